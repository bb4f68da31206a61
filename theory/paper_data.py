"""Numbers reported in the paper, as data (units as printed there, with SI helpers).

Only measured or simulated values the paper reports live here -- never a formula.
Tables I and II give K in N/mm^n; convert with :func:`ringchain.theory.n_per_mm_to_si`.
"""

from __future__ import annotations

__all__ = [
    "TABLE_I",
    "TABLE_II",
    "FE_EXPONENTS",
    "TABLE_II_ASPECT_RATIO",
    "TUBE_RADIUS",
    "CHAIN_RINGS",
    "SENSOR_RINGS",
    "ARRIVAL_TIMES_AS_PRINTED",
    "EQUATION_NUMBERS",
]

#: Tube radius of all the paper's rings, m (Fig. 2 caption).
TUBE_RADIUS = 2.5e-3

#: Table I: aspect ratio R/r -> (K in N/mm^n, n, m_eff/m0); K, n from quasi-static tests,
#: m_eff/m0 from fitting the dynamics.  Contact angle 90 degrees.
TABLE_I = {
    9.0: (2284.0, 1.11, 0.37),
    6.0: (5044.0, 1.24, 0.35),
    5.5: (17700.0, 1.29, 0.35),
}

#: Table II: contact angle in degrees -> (K in N/mm^n, n, m_eff/m0).
TABLE_II = {
    90.0: (2284.0, 1.11, 0.37),
    60.0: (2605.0, 1.13, 0.34),
    30.0: (4030.0, 1.18, 0.33),
}

#: Aspect ratio of the Table II rings.  Sec. IV.B says R = 20 mm, r = 2.5 mm (R/r = 8), the
#: Fig. 3 caption says R/r = 9, and Table II's 90-degree row repeats Table I's R/r = 9 row;
#: we take 9 and note the conflict.
TABLE_II_ASPECT_RATIO = 9.0

#: Finite-element (Abaqus) exponents quoted in Sec. IV.A: R/r -> n.
FE_EXPONENTS = {3.1: 1.418, 4.0: 1.32, 10.0: 1.07}

#: The experiment (Sec. III.A): 20 rings; sensors in rings 6 and 12 counted from the impact.
CHAIN_RINGS = 20
SENSOR_RINGS = (6, 12)

#: Arrival times at the downstream sensor, as printed in Sec. III.A (the paper says "s";
#: see the book's notes on the paper for why they cannot be seconds).
ARRIVAL_TIMES_AS_PRINTED = {"low amplitude": 0.426, "high amplitude": 0.348}

#: The paper's printed equation numbers by the label in its LaTeX source (revtex numbers the main
#: text 1-8 and each appendix A1..., B1...).  Code and book cite the printed numbers.
EQUATION_NUMBERS = {
    "eq:Fc": "1",
    "eq:Fb": "2",
    "eq:dxF": "3",
    "eq:Fdx": "4",
    "eq: dual-spring": "5-6",
    "eq: power law": "7",
    "eq:vsfm": "8",
    "eq:one": "A1",
    "eq:whole": "A2",
    "subeq:1": "A2a",
    "subeq:2": "A2b",
    "eq:three": "A3",
    "eq:disp_expansion": "B1-B3",
    "6": "B6",
    "7": "B7",
    "15": "B15",
    "17": "B17",
    "18": "B18",
    "19": "B19",
    "21": "B21",
}
