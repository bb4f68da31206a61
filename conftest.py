"""Test session setup shared by tests/ and the doctests of the package.

The generated-code cache (and Numba's compiled kernels) is pointed at a fresh directory, so every test
session runs each derivation from the current source instead of trusting a cache from earlier.
"""

import os
import tempfile

# One fresh directory per session: made by the pytest process, inherited by its xdist workers (they share
# the compiled kernels), never by a later session.
if "PYTEST_XDIST_WORKER" not in os.environ:
    os.environ["RINGCHAIN_CACHE_DIR"] = tempfile.mkdtemp(prefix="ringchain-test-cache-")
os.environ.setdefault("MPLBACKEND", "Agg")

# Property tests are derandomized (STYLE.md: seeded randomness only): every run, here and in CI,
# draws the same examples, so a failure reproduces and a green run stays green.  Tests that set
# their own hypothesis settings inherit this profile for what they leave out.
from hypothesis import settings

settings.register_profile("ringchain", derandomize=True, database=None)
settings.load_profile("ringchain")
