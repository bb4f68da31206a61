"""Lazy derivation and the on-disk cache of generated code."""

import hashlib
import os
import stat
import subprocess
import sys
import textwrap

import numpy as np
import pytest
import sympy as sp
from ringchain.theory import _codegen, contact, elliptical, gap, longwave, prestressed, ring, series, solitary
from ringchain.theory._codegen import Derived

ALL_DERIVED = [
    obj
    for module in (contact, elliptical, gap, ring, series, longwave, solitary, prestressed)
    for obj in vars(module).values()
    if isinstance(obj, Derived)
]

# A physical sample point for every argument name a derivation uses (SI units). ``m`` is the
# contact ellipse's squared eccentricity in contact.py and elliptical.py and a ring mass (kg) in the wave modules;
# 0.3 is admissible for both.
SAMPLE = {
    "R": 0.02, "r": 0.0025, "theta": 1.2, "m": 0.3, "A": 50.0, "E": 193e9, "nu": 0.29,
    "F": 10.0, "K_c": 7.5e9, "K_b": 3.3e6,
    "F_m": 20.0, "F_0": 2.0, "K": 8.7e6, "n": 1.11, "a": 0.04, "v_max": -0.3, "x": 0.05,
    "X": 0.01, "Y": 0.002, "Z": 0.015, "y": 4e-4, "delta_c": 2e-6, "P": 10.0, "m_1": 0.7,
    "R_1": 0.0225, "r_1": 0.0025, "R_2": 0.015, "r_2": 0.002, "E_1": 193e9, "nu_1": 0.29, "E_2": 100e9, "nu_2": 0.34,
}  # fmt: skip
# Where a derivation needs other values: the exact torus gap at points over both tubes (x is a position
# near the contact, not along the chain), the two contact points below theta_min.
OVERRIDES = {"gap._gap": {"x": 5e-4}, "gap._patches": {"theta": 0.5}}


@pytest.mark.parametrize("derived", ALL_DERIVED, ids=lambda d: d.name)
def test_generated_code_equals_evalf(derived):
    args, expr = derived.expression()
    sample = {**SAMPLE, **OVERRIDES.get(derived.name, {})}
    values = [sample[str(a)] for a in args]
    got = np.asarray(derived(*values), dtype=float)
    target = sp.Matrix([expr]) if isinstance(expr, tuple) else expr
    expected = np.asarray(sp.N(target, 20, subs=dict(zip(args, values, strict=True))), dtype=float)
    # The generated code evaluates the same expression in double precision: 1e-12.
    assert np.allclose(got.ravel(), expected.ravel(), rtol=1e-12)


def _run(code, cache, env=None):
    env = {**(os.environ if env is None else env), "RINGCHAIN_CACHE_DIR": str(cache)}
    command = [sys.executable, "-c", textwrap.dedent(code)]
    return subprocess.run(command, env=env, capture_output=True, text=True, check=True).stdout


def test_import_does_not_import_sympy(tmp_path):
    out = _run("import sys, ringchain.theory, ringchain.numerics; print('sympy' in sys.modules)", tmp_path)
    assert out.strip() == "False"


def test_disk_cache_round_trip(tmp_path):
    code = """
        import sys
        from ringchain.theory import hertz_stiffness
        print(repr(float(hertz_stiffness(22.5e-3, 2.5e-3, 193e9, 0.29, 1.3))), 'sympy' in sys.modules)
    """
    # Cold: the package's shipped entry where it was written under this SymPy and NumPy (theory/_shipped,
    # tests/theory/test_shipped.py), else derived with SymPy and stored ...
    name = "elliptical._stiffness_elliptical"
    shipped = _codegen._read_entry(_codegen.shipped_path(name), name) is not None
    first = _run(code, tmp_path).split()
    assert first[1] == str(not shipped)
    assert any(p.name.startswith(f"{name}-") for p in tmp_path.iterdir()) != shipped
    second = _run(code, tmp_path).split()
    assert second[1] == "False"  # ... warm: loaded without SymPy
    assert first[0] == second[0]  # bit-identical


def test_a_derivation_is_stored_and_read_back_without_sympy(tmp_path):
    # The disk cache's own round trip, whatever is shipped: a derivation the package does not ship.
    code = """
        import sympy as sp
        from ringchain.theory import _codegen
        x = sp.Symbol("x")
        print(repr(float(_codegen.Derived(lambda: ((x,), sp.sqrt(x) / 3), name="probe.root")(2.0))))
    """
    first = _run(code, tmp_path).split()
    assert any(p.name.startswith("probe.root-") for p in tmp_path.iterdir())
    warm = """
        import sys
        from ringchain.theory import _codegen
        print(repr(float(_codegen.Derived(lambda: 1 / 0, name="probe.root")(2.0))), 'sympy' in sys.modules)
    """
    second = _run(warm, tmp_path).split()  # a derivation that would fail: the value comes from the disk
    assert second == [first[0], "False"]
    assert float(first[0]) == pytest.approx(2.0**0.5 / 3, rel=1e-15)  # sqrt(2)/3 to rounding


def _square(name="probe"):
    x = sp.Symbol("x")
    return Derived(lambda: ((x,), x**2), name=name)


def _underivable(name="probe"):
    """A Derived that can only load its code from the disk cache (deriving raises)."""

    def build():
        raise AssertionError("derived although a valid cache entry exists")

    return Derived(build, name=name)


def test_cache_key_follows_source(tmp_path, monkeypatch):
    monkeypatch.setenv("RINGCHAIN_CACHE_DIR", str(tmp_path))
    d = _square()
    assert d.cache_path.name == f"probe-{_codegen.source_key()}.py"
    assert d(3.0) == 9.0
    assert _underivable()(3.0) == 9.0  # a later process loads the entry under the current key ...
    monkeypatch.setattr(_codegen, "source_key", lambda: "changed")
    with pytest.raises(AssertionError, match="derived although"):
        _underivable()(3.0)  # ... a change of source means a new key and a fresh derivation


def _entry_of_square(tmp_path, monkeypatch) -> bytes:
    monkeypatch.setenv("RINGCHAIN_CACHE_DIR", str(tmp_path))
    d = _square()
    assert d(2.0) == 4.0
    return d.cache_path.read_bytes()


@pytest.mark.parametrize(
    "damage",
    [
        pytest.param(lambda good: good[: len(good) // 2], id="truncated"),  # SyntaxError in today's loader
        pytest.param(lambda good: b"\xff\xfe\x00" + good[3:], id="not-utf8"),  # UnicodeDecodeError
        pytest.param(lambda good: b"x = 1\n", id="no-function"),  # KeyError
        pytest.param(lambda good: b"def _lambdifygenerated(x:\n", id="syntax-error"),
        pytest.param(lambda good: b"", id="empty"),
    ],
)
def test_a_corrupt_entry_is_rebuilt_and_replaced(tmp_path, monkeypatch, damage):
    good = _entry_of_square(tmp_path, monkeypatch)
    path = _square().cache_path
    path.write_bytes(damage(good))
    assert _square()(2.0) == 4.0  # derived again instead of raising ...
    assert path.read_bytes() == good  # ... and the entry rewritten,
    assert _underivable()(5.0) == 25.0  # so that the next process loads it


@pytest.mark.parametrize(
    "wrong",
    [
        pytest.param(lambda good, other: b"def _lambdifygenerated(x):\n    return x + 1\n", id="plain-code"),
        pytest.param(lambda good, other: good.replace(b"x**2", b"x**3"), id="edited-body"),
        pytest.param(lambda good, other: other, id="entry-of-another-derivation"),
    ],
)
def test_a_valid_but_wrong_entry_is_not_trusted(tmp_path, monkeypatch, wrong):
    good = _entry_of_square(tmp_path, monkeypatch)
    x = sp.Symbol("x")
    cube = Derived(lambda: ((x,), x**3), name="cube")
    assert cube(2.0) == 8.0
    path = _square().cache_path
    path.write_bytes(wrong(good, cube.cache_path.read_bytes()))
    assert _square()(2.0) == 4.0
    assert path.read_bytes() == good


def test_entries_record_what_they_were_generated_from(tmp_path, monkeypatch):
    text = _entry_of_square(tmp_path, monkeypatch).decode()
    x = sp.Symbol("x")
    assert "# derivation: probe" in text
    assert f"# source key: {_codegen.source_key()}" in text
    assert f"sympy {sp.__version__}" in text
    assert "# arguments: x" in text
    assert f"# expression sha256: {hashlib.sha256(sp.srepr(x**2).encode()).hexdigest()}" in text


@pytest.mark.parametrize(("umask", "mode"), [(0o022, 0o644), (0o002, 0o664), (0o077, 0o600)], ids=["022", "002", "077"])
def test_entries_are_created_as_open_would_create_them_under_the_umask(tmp_path, monkeypatch, umask, mode):
    """Group-readable under the usual umasks (a cache shared by a group works); private if the umask says so."""
    monkeypatch.setenv("RINGCHAIN_CACHE_DIR", str(tmp_path / "cache"))
    old = os.umask(umask)
    try:
        d = _square()
        assert d(2.0) == 4.0
    finally:
        os.umask(old)
    assert stat.S_IMODE(d.cache_path.stat().st_mode) == mode
    assert stat.S_IMODE(d.cache_path.parent.stat().st_mode) == 0o777 & ~umask


def test_a_full_disk_leaves_no_temporary_file_and_still_computes(tmp_path):
    # The file-size limit makes every write past 8 bytes fail (EFBIG), as a full disk does (ENOSPC).
    code = """
        import resource, signal, sympy
        from ringchain.theory._codegen import Derived
        x = sympy.Symbol("x")
        d = Derived(lambda: ((x,), x**2 + 2 * x + 1), name="full")
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (8, 8))
        print(d(2.0))
    """
    env = {**os.environ, "PYTHONDONTWRITEBYTECODE": "1"}
    out = _run(code, tmp_path, env=env)
    assert float(out) == 9.0
    assert list(tmp_path.iterdir()) == []


def test_disabled_cache(monkeypatch):
    monkeypatch.setenv("RINGCHAIN_CACHE_DIR", "")
    d = Derived(lambda: ((sp.Symbol("x"),), 3 * sp.Symbol("x")), name="nocache")
    assert d.cache_path is None and d(2.0) == 6.0


def test_unwritable_cache_is_not_an_error(tmp_path, monkeypatch):
    blocker = tmp_path / "file"
    blocker.write_text("")
    monkeypatch.setenv("RINGCHAIN_CACHE_DIR", str(blocker / "sub"))  # a directory under a file
    d = Derived(lambda: ((sp.Symbol("x"),), sp.Symbol("x") - 1), name="ro")
    assert d(2.0) == 1.0
