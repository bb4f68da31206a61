"""The paper module: one source of stiffness for both models, the tables and figures of ``ringchain paper``."""

import math

import pytest
from ringchain import numerics
from ringchain.numerics.cli.commands import main
from ringchain.numerics.jobs import paper
from ringchain.theory import paper_data

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def test_the_experiment_and_its_chain_live_in_the_paper_module():
    assert numerics.paper_experiment is paper.paper_experiment and numerics.PaperExperiment is paper.PaperExperiment
    assert numerics.paper_chain is paper.paper_chain


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
