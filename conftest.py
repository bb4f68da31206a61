"""Test session setup shared by tests/ and the doctests of the package.

The generated-code cache is pointed at a fresh directory, so every test session runs
each derivation from the current source instead of trusting a cache from earlier.
"""

import os
import tempfile

os.environ["RINGCHAIN_CACHE_DIR"] = tempfile.mkdtemp(prefix="ringchain-test-cache-")
os.environ.setdefault("MPLBACKEND", "Agg")
