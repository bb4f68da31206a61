"""Display helpers shared by the book's pages (run from book/, so ``import bookdisplay`` works).

They only format what the package returns. The pages type their equations for the reader as labelled
``{math}`` blocks, each checked against the package's expression by :func:`textbook` in a hidden cell;
:func:`compact` writes derivatives of the fields as subscripts (u_xx for d^2u/dx^2) for those checks, and
:func:`show` / :func:`grouped` still render an expression as SymPy prints it, with long sums broken over
lines. A table is Markdown built from numbers the page computed.

The book's conventions live here too, defined once: the colour of each quantity in every figure
(:data:`COLOURS`), the drop heights of the experiment (:data:`DROP_HEIGHTS`), and how a caption names the chain
it shows, its stiffness source and its striker (:func:`chain_note`, :func:`striker_note`, :data:`STRIKER`).
"""

from __future__ import annotations

import random
import re

import sympy as sp
from IPython.display import Markdown, Math, display

__all__ = [
    "COLOURS",
    "DROP_HEIGHTS",
    "FORCE_MAP",
    "HIGH_DROP",
    "LOW_DROP",
    "STRIKER",
    "STRIKER_WORDS",
    "chain_note",
    "compact",
    "grouped",
    "show",
    "stiffness_words",
    "striker_note",
    "table",
    "textbook",
]

#: One colour per quantity across the book (Matplotlib colours).  Sensors and models keep theirs in every
#: chapter; the paper's own numbers are always black markers.
COLOURS = {
    "ring 6": "#1f77b4",  # the sensor nearer the impact
    "ring 12": "#ff7f0e",  # the sensor further up
    "dual-spring": "#2ca02c",
    "power-law": "#d62728",
    "rings that bend": "#444444",
    "paper": "black",
    "theory": "#1f77b4",  # a closed form of the package
    "numerics": "#9467bd",  # boundary elements, lattice points
    "kinetic": "#8c564b",
    "contact": "#e377c2",
    "bending": "#17becf",
    "gravity": "#bcbd22",
    # the three rings of the paper's Table I
    "R/r = 9": "#1f77b4",
    "R/r = 6": "#ff7f0e",
    "R/r = 5.5": "#2ca02c",
    # other aspect ratios of the paper (finite elements, Table II)
    "R/r = 3.1": "#8c564b",
    "R/r = 4": "#7f7f7f",
    "R/r = 8": "#bcbd22",
    "R/r = 10": "#17becf",
    # disorder (chapter "Disorder"): the ordered chain, the ensembles by the size of their spread, the two
    # estimates of the mean speed, and the chain without gravity beside the hanging one
    "ordered": "black",
    "spread 1": "#fdae6b",
    "spread 2": "#f16913",
    "spread 3": "#a63603",
    "effective-medium": "#3182bd",
    "harmonic-mean": "#31a354",
    "hanging": "#756bb1",
    "no gravity": "#a63603",
    # sheets of interlinked rings (the sheets chapter)
    "square sheet": "#a63603",
    "triangular sheet": "#08519c",
    "longitudinal": "#31a354",
    "transverse": "#756bb1",
}

#: The colour map of the forces of a sheet's links (the sheets chapter): pale where a link carries little,
#: dark where it carries most, so that the lattice fades into the page and the pulse stands out.
FORCE_MAP = "magma_r"

#: Drop heights used by every chapter, m; the paper does not give its own.  ``LOW_DROP`` and ``HIGH_DROP``
#: stand for the low- and high-amplitude experiments of the paper's Fig. 1 d and e.
DROP_HEIGHTS = (2e-3, 10e-3, 50e-3, 0.2, 0.5)
LOW_DROP, HIGH_DROP = 2e-3, 50e-3

#: How a lattice is struck, in the words of a caption, for each ``striker_mass`` of the chain constructors: the
#: dropped ring is ring 0 of the chain, with the inertial mass m_eff of every lattice ring (the paper's convention,
#: Sec. III.B, and the default) or, as a rigid ring in free fall, its own mass m0.
STRIKER_WORDS = {
    "m_eff": "striker: the dropped ring, of inertial mass $m_{\\mathrm{eff}}$ like every lattice ring (the paper's "
    "convention)",
    "m0": "striker: the dropped ring as a rigid body, of its full mass $m_0$",
}


def striker_note(striker="m_eff") -> str:
    """The striker of a chain in a caption's words: ``striker`` is a ``striker_mass`` ("m_eff", "m0", kg) or a Chain,
    read from its ``striker_mass`` field (None: the paper's convention; ring 0's weight mass: m0)."""
    if hasattr(striker, "striker_mass"):
        chain, striker = striker, striker.striker_mass
        if striker is None:
            striker = "m_eff"
        elif striker == chain.profile("m_gravity")[0]:
            striker = "m0"
    if isinstance(striker, str):
        return STRIKER_WORDS[striker]
    return f"striker: the dropped ring, of inertial mass {striker * 1e3:.3g} g"


#: Every lattice of the book is struck as the paper's, unless its caption says otherwise.
STRIKER = striker_note("m_eff")


def stiffness_words(model: str, stiffness: str, aspect_ratio: float = 9.0) -> str:
    """Where ``paper_chain(model, stiffness=...)`` takes its stiffness from, as Markdown for a caption.

    The words are the package's (:func:`ringchain.numerics.jobs.paper.stiffness_note`), with the symbols set as math.
    """
    from ringchain.numerics.jobs.paper import stiffness_note

    note = stiffness_note(model, stiffness, aspect_ratio).replace("N/mm^n", "N/mm@UNITS@")
    note = re.sub(r"\b(K_c|K_b|K|n)\b", r"$\1$", note)
    return note.replace("@UNITS@", "$^n$")


def chain_note(model: str, stiffness: str, aspect_ratio: float = 9.0, *, striker=True, striker_mass="m_eff") -> str:
    """The chain of ``paper_chain(model, stiffness=..., striker_mass=...)`` in words: model, stiffness source and
    striker (:func:`striker_note`).

    ``striker=False`` leaves the striker out (a caption naming several chains adds :data:`STRIKER` once).
    """
    words = f"{model} chain, stiffness: {stiffness_words(model, stiffness, aspect_ratio)}"
    return f"{words}; {striker_note(striker_mass)}" if striker else words


def textbook(label: str, typed, derived, *, samples: int = 6) -> None:
    """Fail the build unless ``typed`` (the page's typed form, in SymPy) equals the package's ``derived``.

    The two must be the same expression, or their difference must vanish in a proof by SymPy (the cheap
    ones first, :func:`sympy.simplify` last: see :func:`_proved_equal`), or, where
    every one of these gives up on an identity, the two must agree to 1e-25 (relative; the evaluation
    carries 40 digits) at ``samples`` seeded random points with every symbol in (0.1, 1.1) (the book's
    symbols are positive; angles stay below pi/2).
    """
    typed, derived = sp.sympify(typed), sp.sympify(derived)
    if isinstance(typed, sp.MatrixBase):
        if typed.shape != derived.shape:
            raise AssertionError(f"{label}: a {typed.shape} matrix typed for a {derived.shape} one")
        for i, (a, b) in enumerate(zip(typed, derived, strict=True)):
            textbook(f"{label}[{i}]", a, b, samples=samples)
        return
    if typed == derived or _proved_equal(typed - derived):
        return
    rng = random.Random(label)
    symbols = sorted(typed.free_symbols | derived.free_symbols, key=str)
    for _ in range(samples):
        point = {s: sp.Rational(rng.randint(100, 1100), 1000) for s in symbols}
        a, b = (e.subs(point).evalf(40) for e in (typed, derived))
        # Compared at 40 digits (as complex numbers the values would round to 16, and 1e-25 would mean 1e-16).
        gap = sp.Abs(a - b).evalf(40)
        size = max(sp.Abs(a).evalf(40), sp.Abs(b).evalf(40), sp.Float("1e-300", 40))
        if not gap <= sp.Float("1e-25", 40) * size:
            raise AssertionError(f"{label}: the typed equation differs from the package's: {typed} != {derived}")


def _proved_equal(difference) -> bool:
    """Whether SymPy proves ``difference`` zero, by the cheapest proof that succeeds.

    Each step is a proof (a rewriting that preserves the value), tried in order of cost: expanding
    products and powers; bringing everything over one denominator and cancelling (for rational
    functions of any generators: sums, roots, trigonometric functions); the same with trigonometric
    functions written as exponentials (so that cos(x) and cos(x/2)^2 share a generator); Beta functions
    (SymPy's and the package's) written as Gamma quotients with their arguments in lowest terms; last
    the full simplifier, which costs tenths of a second to seconds and succeeds where the others cannot.
    """
    if sp.expand(difference) == 0 or sp.cancel(difference) == 0:
        return True
    if sp.cancel(sp.expand(difference.rewrite(sp.exp))) == 0:
        return True
    if any(hasattr(f, "_eval_rewrite_as_gamma") for f in difference.atoms(sp.Function)):
        in_gamma = difference.rewrite(sp.gamma).replace(
            lambda e: isinstance(e, sp.gamma), lambda e: sp.gamma(sp.cancel(e.args[0]))
        )
        if sp.cancel(sp.expand(in_gamma)) == 0:
            return True
    return sp.simplify(difference) == 0


def compact(expr):
    """``expr`` with u(x, t), xi(x, t), f(tau) and their derivatives written as u, u_x, u_xx, ..."""
    if not isinstance(expr, sp.Basic):
        return expr
    replacements = {}
    for derivative in expr.atoms(sp.Derivative):
        function = derivative.expr
        if isinstance(function, sp.core.function.AppliedUndef):
            name = sp.latex(function.func)
            subscript = "".join(sp.latex(variable) * count for variable, count in derivative.variable_count)
            replacements[derivative] = sp.Symbol(f"{name}_{{{subscript}}}")
    expr = expr.xreplace(replacements)
    functions = {f: sp.Symbol(sp.latex(f.func)) for f in expr.atoms(sp.core.function.AppliedUndef)}
    return expr.xreplace(functions)


def grouped(expr):
    """``compact(expr)`` with its terms grouped by their field factors, each coefficient factored.

    E.g. n^2 u_xx^3/24 - n u_xx^3/8 + ... becomes n (n - 3)/24 u_xx^3 + ...; the value is unchanged.
    """
    expr = sp.expand(compact(expr))
    fields = [s for s in expr.free_symbols if "_{" in s.name or s.name in ("u", "\\xi", "f")]
    groups: dict = {}
    for term in sp.Add.make_args(expr):
        coefficient, part = term.as_independent(*fields, as_Add=False)
        groups[part] = groups.get(part, 0) + coefficient
    return sp.Add(*[sp.factor(c) * part for part, c in groups.items()])


def show(lhs: str, expr, *, per_line: int | None = None) -> None:
    """Display ``lhs = expr``; a sum with more than ``per_line`` terms is broken over several lines."""
    expr = compact(expr)
    terms = sp.Add.make_args(expr) if isinstance(expr, sp.Add) else (expr,)
    if per_line is None or len(terms) <= per_line:
        display(Math(f"{lhs} = {sp.latex(expr)}"))
        return
    lines = []
    for start in range(0, len(terms), per_line):
        chunk = sp.latex(sp.Add(*terms[start : start + per_line], evaluate=False))
        if start and not chunk.startswith("-"):
            chunk = "+ " + chunk
        lines.append(("&= " if start == 0 else "&\\quad ") + chunk)
    display(Math(f"\\begin{{aligned}}{lhs} " + " \\\\\n".join(lines) + "\\end{aligned}"))


def table(header, rows, caption: str | None = None) -> None:
    """A Markdown table (and an optional caption line above it)."""
    lines = [] if caption is None else [caption, ""]
    lines += ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    display(Markdown("\n".join(lines)))
