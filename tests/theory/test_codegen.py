"""Lazy derivation and the on-disk cache of generated code."""

import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest
import sympy as sp
from ringchain.theory import _codegen, contact, longwave, ring, series, solitary
from ringchain.theory._codegen import Derived

ALL_DERIVED = [
    obj
    for module in (contact, ring, series, longwave, solitary)
    for obj in vars(module).values()
    if isinstance(obj, Derived)
]

# A physical sample point for every argument name a derivation uses (SI units). ``m`` is the
# contact ellipse's squared eccentricity in contact.py and a ring mass (kg) in the wave modules;
# 0.3 is admissible for both.
SAMPLE = {
    "R": 0.02, "r": 0.0025, "theta": 1.2, "m": 0.3, "A": 50.0, "E": 193e9, "nu": 0.29,
    "F": 10.0, "K_c": 7.5e9, "K_b": 3.3e6,
    "F_m": 20.0, "F_0": 2.0, "K": 8.7e6, "n": 1.11, "a": 0.04, "v_max": -0.3, "x": 0.05,
}  # fmt: skip


@pytest.mark.parametrize("derived", ALL_DERIVED, ids=lambda d: d.name)
def test_generated_code_equals_evalf(derived):
    args, expr = derived.expression()
    values = [SAMPLE[str(a)] for a in args]
    got = np.asarray(derived(*values), dtype=float)
    target = sp.Matrix([expr]) if isinstance(expr, tuple) else expr
    expected = np.asarray(sp.N(target, 20, subs=dict(zip(args, values, strict=True))), dtype=float)
    # The generated code evaluates the same expression in double precision: 1e-12.
    assert np.allclose(got.ravel(), expected.ravel(), rtol=1e-12)


def _run(code, cache):
    env = {**os.environ, "RINGCHAIN_CACHE_DIR": str(cache)}
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
    first = _run(code, tmp_path).split()
    assert first[1] == "True"  # cold: derived with SymPy ...
    assert any(p.name.startswith("contact._stiffness_elliptical-") for p in tmp_path.iterdir())
    second = _run(code, tmp_path).split()
    assert second[1] == "False"  # ... warm: loaded from the cache without SymPy
    assert first[0] == second[0]  # bit-identical


def test_cache_key_follows_source(tmp_path, monkeypatch):
    monkeypatch.setenv("RINGCHAIN_CACHE_DIR", str(tmp_path))
    d = Derived(lambda: ((sp.Symbol("x"),), sp.Symbol("x") ** 2), name="probe")
    assert d.cache_path.name == f"probe-{_codegen.source_key()}.py"
    d.cache_path.parent.mkdir(parents=True, exist_ok=True)
    d.cache_path.write_text("def _lambdifygenerated(x):\n    return x + 1\n")
    assert d(2.0) == 3.0  # a cache entry under the current key is trusted ...
    monkeypatch.setattr(_codegen, "source_key", lambda: "changed")
    fresh = Derived(d.build, name="probe")
    assert fresh(2.0) == 4.0  # ... a change of source means a new key and a fresh derivation


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
