"""The entries of generated code shipped in ``theory/_shipped`` are the derivations' own output.

They spare a fresh checkout the derivations (theory/_codegen.py, "Shipped entries"); they are a cache, so
each is derived again here and compared byte for byte with what the generator writes today.
"""

from __future__ import annotations

import pytest
import ringchain.theory  # noqa: F401  (every derivation registered)
from ringchain.theory import _codegen

NAMES = sorted(_codegen.REGISTRY)


def test_every_derivation_is_shipped_for_these_sources():
    missing = [name for name in NAMES if not _codegen.shipped_path(name).is_file()]
    assert not missing, f"not shipped for these sources (run python -m ringchain.theory._codegen): {missing}"
    current = {_codegen.shipped_path(name) for name in NAMES}
    others = [path.name for path, _ in _codegen._cache_files(_codegen.SHIPPED_DIR) if path not in current]
    assert not others, f"entries of other sources or of no derivation: {others}"


@pytest.mark.parametrize("name", NAMES)
def test_a_shipped_entry_is_its_derivation(name):
    path = _codegen.shipped_path(name)
    args, expr = _codegen.REGISTRY[name].expression()
    fresh = _codegen._entry(name, args, expr, _codegen.generate_source(args, expr))
    if _codegen._read_entry(path, name) is not None:  # written under this installation's SymPy and NumPy
        assert path.read_bytes() == fresh
    else:  # refused, and only because the versions differ (then it is never read: the derivation runs)
        versions = ", ".join(f"{dist} {version}" for dist, version in _codegen._versions())
        assert versions not in path.read_text()


def test_a_fresh_cache_reads_the_shipped_entry_and_derives_nothing(tmp_path, monkeypatch):
    monkeypatch.setenv("RINGCHAIN_CACHE_DIR", str(tmp_path))
    name = "solitary._speed"
    shipped = _codegen.REGISTRY[name]
    usable = _codegen._read_entry(_codegen.shipped_path(name), name) is not None  # same SymPy and NumPy
    derive, calls = shipped._derive_and_store, []
    monkeypatch.setattr(shipped, "_derive_and_store", lambda path: calls.append(path) or derive(path))
    loaded = shipped._load()
    assert calls == ([] if usable else [shipped.cache_path])
    args, expr = shipped.expression()
    fresh = _codegen._compile(_codegen.generate_source(args, expr), name)
    values = (2.0e9, 1.5, 0.01, 0.05)  # K (SI units of n = 1.5), n, a (m), m (kg)
    assert loaded(*values) == fresh(*values)  # the same generated code
