"""Files of runs: written whole or not at all, refused when incomplete, and describing their run fully."""

import signal

import numpy as np
import pytest
import xarray as xr
from ringchain.numerics import DataError, Sheet, read_sheet_run, simulate, write_csv, write_traces
from ringchain.numerics.engine._files import replacing, write_text
from ringchain.numerics.layouts.sheet_runs import sheet_run_options
from ringchain.theory import Ring

RING = Ring.from_aspect_ratio(9.0)


@pytest.fixture(scope="module")
def small_run():
    sheet = Sheet.square(4, 3, RING, pretension=(1.0, 2.0), m_eff_ratio=0.5, gamma=0.01, struck=[1])
    return simulate(sheet, 2e-4, impact_velocity=0.3, n_samples=11)


def _interrupt_after_some_bytes(monkeypatch, cls, method):
    """Make ``cls.method(path, ...)`` write a part of a file to ``path``, then be interrupted (Ctrl-C)."""

    def partial(self, path, *args, **kwargs):
        with open(path, "wb") as handle:
            handle.write(b"\x89HDF\r\n\x1a\n" + bytes(100))  # a file begun, as h5py begins it
        raise KeyboardInterrupt

    monkeypatch.setattr(cls, method, partial)


def test_an_interrupted_netcdf_write_leaves_the_previous_file_intact(tmp_path, monkeypatch, small_run):
    path = tmp_path / "run.nc"
    small_run.to_netcdf(path)
    before = path.read_bytes()
    _interrupt_after_some_bytes(monkeypatch, xr.Dataset, "to_netcdf")
    with pytest.raises(KeyboardInterrupt):
        small_run.to_netcdf(path)
    assert path.read_bytes() == before  # the previous good file, byte for byte
    assert [p.name for p in tmp_path.iterdir()] == ["run.nc"]  # no temporary file left behind
    assert np.array_equal(read_sheet_run(path)["link_force"].values, small_run.link_force)


def test_a_sigint_inside_a_text_write_leaves_the_previous_file_intact(tmp_path, monkeypatch):
    path = tmp_path / "sweep.csv"
    write_csv([{"a": 1.0}], path)
    before = path.read_text()

    class Interrupted:
        """A file that writes three characters, then receives SIGINT (Ctrl-C) from the terminal."""

        def __init__(self, *args, **kwargs):
            self.file = open(*args, **kwargs)  # closed in __exit__

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            self.file.close()

        def write(self, text):
            self.file.write(text[:3])
            self.file.flush()
            signal.raise_signal(signal.SIGINT)

    monkeypatch.setattr("ringchain.numerics.engine._files.open", Interrupted, raising=False)
    with pytest.raises(KeyboardInterrupt):
        write_csv([{"a": 2.0}], path)
    assert path.read_text() == before and [p.name for p in tmp_path.iterdir()] == ["sweep.csv"]


def test_write_traces_goes_through_a_temporary_name(tmp_path, monkeypatch):
    seen = []
    import ringchain.numerics.engine._files as files

    original = files.replacing

    def watched(path):
        seen.append(path)
        return original(path)

    monkeypatch.setattr("ringchain.numerics.engine.traces.replacing", watched)
    from ringchain.numerics import Chain

    chain = Chain.power_law(8, K=1e9, n=1.5, m=0.01, a=0.02, support="free")
    sim = simulate(chain, 1e-4, impact_velocity=0.1, gravity=False, n_samples=11)
    write_traces(tmp_path / "run.csv", sim, [2, 4])
    assert seen == [tmp_path / "run.csv"] and (tmp_path / "run.csv").read_text().startswith("t_s,")


def test_a_writer_that_fails_leaves_nothing_new(tmp_path):
    target = tmp_path / "new.png"
    with pytest.raises(RuntimeError), replacing(target) as tmp:
        tmp.write_bytes(b"half")
        raise RuntimeError("disk full")
    assert list(tmp_path.iterdir()) == []
    write_text(target.with_suffix(".txt"), "whole")
    assert (tmp_path / "new.txt").read_text() == "whole"


def test_a_truncated_or_foreign_file_is_refused_naming_it(tmp_path, small_run):
    path = tmp_path / "run.nc"
    small_run.to_netcdf(path)
    data = path.read_bytes()
    (tmp_path / "cut.nc").write_bytes(data[: len(data) // 2])  # what a write killed midway left before
    with pytest.raises(DataError, match=r"cut\.nc: not a sheet's run"):
        read_sheet_run(tmp_path / "cut.nc")
    (tmp_path / "run.csv").write_text("t_s,a\n0,1\n")
    with pytest.raises(DataError, match=r"run\.csv: not a sheet's run"):
        read_sheet_run(tmp_path / "run.csv")
    dataset = read_sheet_run(path).drop_vars(["link_force", "energy_contact"])
    dataset.to_netcdf(tmp_path / "part.nc", engine="h5netcdf")
    with pytest.raises(DataError, match=r"part\.nc: an incomplete sheet's run: link_force, energy_contact missing"):
        read_sheet_run(tmp_path / "part.nc")
    dataset = read_sheet_run(path)
    dataset["link_force"][:] = np.nan
    dataset.to_netcdf(tmp_path / "nan.nc", engine="h5netcdf")
    with pytest.raises(DataError, match=r"nan\.nc: an incomplete sheet's run: link_force holds no number"):
        read_sheet_run(tmp_path / "nan.nc")
    xr.Dataset({"a": ("x", [1.0])}).to_netcdf(tmp_path / "other.nc", engine="h5netcdf")
    with pytest.raises(DataError, match=r"other\.nc: not a sheet's run written by ringchain"):
        read_sheet_run(tmp_path / "other.nc")


@pytest.mark.parametrize(
    ("build", "impact"),
    [
        (lambda: Sheet.square(4, 3, RING, pretension=(1.0, 2.0), m_eff_ratio=0.5, gamma=0.01, struck=[1]),
         {"impact_velocity": 0.3}),
        (lambda: Sheet.square(4, 3, RING, hanging=True, m_eff_ratio=0.37), {"drop_height": 0.01}),
        (lambda: Sheet.triangular(4, 3, RING, pretension=(1.0, 2.0, 2.0), boundary="periodic", struck=[1],
                                  impact_direction=-np.pi / 2, angle=(1.2, 1.5, 1.5)), {"impact_velocity": 0.2}),
        (lambda: Sheet.from_links([[0, 0], [RING.spacing, 0]], [[0, 1], [1, -1]], RING, struck=[0],
                                  anchors=[[0, 0], [2 * RING.spacing, 0]], impact_direction=np.pi), {
             "impact_velocity": 0.2}),
    ],
)  # fmt: skip
def test_a_file_rebuilds_its_sheet_and_runs_again_to_the_same_numbers(tmp_path, build, impact):
    sheet = build()
    run = simulate(sheet, 2e-4, n_samples=21, **impact)
    run.to_netcdf(tmp_path / "run.nc")
    data = read_sheet_run(tmp_path / "run.nc")
    again = Sheet.from_run(data)
    assert np.array_equal(again.K, sheet.K) and np.array_equal(again.struck_sites, sheet.struck_sites)
    assert again.ring == sheet.ring and data.attrs["R_m"] == RING.R and data.attrs["material"] == "stainless"
    rerun = simulate(again, **sheet_run_options(tmp_path / "run.nc"))
    # The same network, impact and integrator settings: the same arithmetic, bit for bit.
    assert np.array_equal(rerun.link_force, run.link_force)
    assert np.array_equal(rerun.energy().total, run.energy().total)
