"""The paper module: one source of stiffness for both models, the tables and figures of ``ringchain paper``."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from ringchain import numerics
from ringchain.numerics import paper
from ringchain.numerics.cli import main
from ringchain.theory import fit_power_law, n_per_mm_to_si, paper_data

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def test_the_experiment_lives_in_the_paper_module_and_stays_importable():
    from ringchain.numerics.solve import PaperExperiment, paper_experiment

    assert paper_experiment is paper.paper_experiment is numerics.paper_experiment
    assert PaperExperiment is paper.PaperExperiment


@pytest.mark.parametrize(
    "row", [*(("Table I", k, v) for k, v in paper_data.TABLE_I.items()),
            *(("Table II", k, v) for k, v in paper_data.TABLE_II.items())],
)  # fmt: skip
def test_series_stiffness_reduces_to_the_measured_power_law(row):
    """The springs found for each measured (K, n) of Tables I and II, fitted again by the theory's
    own least squares (Eq. 4, theory.fit_power_law), give that K and n back."""
    _, _, (K_mm, n, _) = row
    K = float(n_per_mm_to_si(K_mm, n=n))
    K_c, K_b = paper.series_stiffness_for_power_law(K, n)
    K_fit, n_fit = fit_power_law(K_c=K_c, K_b=K_b)
    # The root finder stops at 1e-13 in ln F*; n depends smoothly on it.
    assert float(n_fit) == pytest.approx(n, rel=1e-9)
    assert float(K_fit) == pytest.approx(K, rel=1e-9)
    # Springs of a steel ring of this size: K_b of 1e6-1e8 N/m (Eq. 2 gives 3.3e6 at R/r = 9),
    # K_c of 1e9-1e10 N/m^1.5 (Eq. 1 gives 7.5e9).
    assert 1e6 < K_b < 1e8 and 1e9 < K_c < 1e11


@settings(max_examples=40, deadline=None)
@given(K=st.floats(1e4, 1e10), n=st.floats(1.02, 1.48), window=st.sampled_from([(1.0, 100.0), (0.1, 10.0)]))
def test_series_stiffness_round_trips_over_the_admissible_range(K, n, window):
    K_c, K_b = paper.series_stiffness_for_power_law(K, n, *window)
    assert np.isfinite(K_c) and np.isfinite(K_b)
    K_fit, n_fit = fit_power_law(K_c=K_c, K_b=K_b, F_min=window[0], F_max=window[1])
    assert float(n_fit) == pytest.approx(n, rel=1e-8)  # root finding to 1e-13 in ln F*
    assert float(K_fit) == pytest.approx(K, rel=1e-7)  # K ~ K_b^n: the error in n times ln(delta)


@pytest.mark.parametrize(
    ("args", "message"),
    [((4.9e6, 1.5), r"n must lie in \(1, 1.5\)"), ((4.9e6, 1.0), r"n must lie in \(1, 1.5\)"),
     ((-1.0, 1.2), "K must be positive"), ((4.9e6, 1.2, 10.0, 1.0), "F_min < F_max")],
)  # fmt: skip
def test_series_stiffness_refuses_what_no_series_law_gives(args, message):
    with pytest.raises(ValueError, match=message):
        paper.series_stiffness_for_power_law(*args)


def test_experiment_table_names_each_models_source_of_stiffness():
    runs = paper.experiment_runs(0.05, stiffness="theory")
    table = paper.experiment_table(runs)
    assert table.headers[-1] == "stiffness"
    assert [row[0] for row in table.rows] == ["dual-spring", "power-law"]
    assert [row[-1] for row in table.rows] == ["theory", "theory"]
    assert "stiffness of the dual-spring chain: theory: K_c of Eq. (1), K_b of Eq. (2)" in table.notes
    assert "stiffness of the power-law chain: theory: K, n fitted to Eqs. (1)-(3) over 1-100 N" in table.notes
    lines = str(table).splitlines()
    assert lines[0] == table.title
    assert len({len(line) for line in lines[1:4]}) == 1  # header and rows right-aligned to one width


def test_the_paper_job_prints_the_stiffness_it_used(capsys, tmp_path):
    assert main(["paper", "--stiffness", "theory", "--out", str(tmp_path / "figures")]) == 0
    out = capsys.readouterr().out
    rows = [line.split() for line in out.splitlines() if line.strip().startswith(("dual-spring", "power-law"))]
    assert [row[-1] for row in rows] == ["theory", "theory"]
    assert "stiffness of the power-law chain: theory" in out
    figures = sorted((tmp_path / "figures").glob("*.png"))
    assert len(figures) == 5 and all(path.read_bytes()[:8] == PNG_MAGIC for path in figures)
    assert main(["paper", "--stiffness", "fitted", "--out", str(tmp_path)]) == 2  # argparse's choices


def test_tables_are_plain_data_the_book_can_show():
    static = paper.static_table()
    row = next(row for row in static.rows if row[0] == "9.0")
    assert row[6:9] == ("2284", "1.11", "Table I")  # the paper's K, n beside the theory
    speeds = paper.speed_table(forces=[10.0])
    assert speeds.headers[-1] == "V_s(10 N) (m/s)" and len(speeds.rows) == len(paper_data.TABLE_I) + len(
        paper_data.TABLE_II)  # fmt: skip


def test_the_angle_table_takes_each_contact_from_contact_at_angle():
    # Issue 24, item 3: one choice between the Hertz ellipse and the numerical contact, shared with `ringchain ring`.
    from ringchain.numerics import contact_at_angle
    from ringchain.theory import STAINLESS_STEEL_304, Ring

    table = paper.angle_table()
    ring = Ring.from_aspect_ratio(paper_data.TABLE_II_ASPECT_RATIO, r=paper_data.TUBE_RADIUS)
    rows = {row[0]: row for row in table.rows}
    for angle_deg, method in ((90.0, "Hertz"), (60.0, "Hertz"), (30.0, "BEM, 2 patches")):
        contact = contact_at_angle(ring.R, ring.r, STAINLESS_STEEL_304.E, STAINLESS_STEEL_304.nu,
                                   math.radians(angle_deg), K_b=ring.K_b)  # fmt: skip
        row = rows[f"{angle_deg:.0f}"]
        assert row[1] == method
        assert float(row[2]) == pytest.approx(contact.K_c, rel=5e-5)  # printed to 5 figures
        assert float(row[5]) == pytest.approx(contact.n, abs=5e-4)  # 3 decimals
    assert any("above 55.84 deg" in note for note in table.notes)  # the handover for 1-100 N
