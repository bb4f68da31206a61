"""The book's equation check (book/bookdisplay.py, ``textbook``): a page's typed equation must equal the package's.

Every typed form of the book passes through ``textbook``, and a wrong one stops the build; these tests hold it to
both halves of that: identities pass, whichever of its proofs (or its numeric fallback) settles them, and pairs
that differ, by a little or a lot, are refused.  The expected answers are mathematics, not the package.
"""

import importlib.util
from pathlib import Path

import pytest
import sympy as sp

BOOK = Path(__file__).resolve().parents[2] / "book"

x, y, n = sp.symbols("x y n", positive=True)


@pytest.fixture(scope="module")
def textbook():
    spec = importlib.util.spec_from_file_location("bookdisplay", BOOK / "bookdisplay.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.textbook


IDENTITIES = {
    "the same expression": (x**n / (1 + x), x**n / (1 + x)),
    "expanded": ((x + y) ** 2, x**2 + 2 * x * y + y**2),
    "over one denominator": (1 / x + 1 / y, (x + y) / (x * y)),
    "a half angle": (sp.cos(y), 2 * sp.cos(y / 2) ** 2 - 1),
    "Beta as Gammas": (sp.beta(x + 1, y), sp.gamma(x + 1) * sp.gamma(y) / sp.gamma(x + y + 1)),
    "the numeric fallback only (Min as Abs)": (sp.Min(x, y), (x + y - sp.Abs(x - y)) / 2),
    "a matrix": (sp.Matrix([[x * (x + 1), 1 / x + 1]]), sp.Matrix([[x**2 + x, (x + 1) / x]])),
}


@pytest.mark.parametrize("label", IDENTITIES)
def test_an_identity_passes(textbook, label):
    typed, derived = IDENTITIES[label]
    textbook(label, typed, derived)  # raises AssertionError if refused


DIFFERENT = {
    "a sign": (x - y, y - x),
    "a square of a sum against a sum of squares": ((x + y) ** 2, x**2 + y**2),
    "a factor 2 in a half angle": (sp.cos(y), 2 * sp.cos(y / 2) ** 2),
    "Min against Max": (sp.Min(x, y), sp.Max(x, y)),
    # 1e-20 apart: above the check's 1e-25 at 40 digits (in double precision, as it once compared, this passed).
    "1e-20 apart": (sp.Min(x, y), (x + y - sp.Abs(x - y)) / 2 * (1 + sp.Rational(1, 10**20))),
    "a matrix entry": (sp.Matrix([[x, y]]), sp.Matrix([[x, 2 * y]])),
    "a matrix's shape": (sp.Matrix([[x, y]]), sp.Matrix([[x], [y]])),
}


@pytest.mark.parametrize("label", DIFFERENT)
def test_a_different_pair_is_refused(textbook, label):
    typed, derived = DIFFERENT[label]
    with pytest.raises(AssertionError, match=r"differs|matrix typed"):
        textbook(label, typed, derived)
