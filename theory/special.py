"""Carlson's symmetric elliptic integrals as SymPy functions that print to SciPy.

The elliptical Hertz contact is written by Johnson with the complete elliptic
integrals K(m) and E(m) (parameter m = e^2).  Its two key combinations,
(K - E)/m and (E/(1 - m) - K)/m, are 0/0 at the circular contact m = 0, so code
evaluating them literally loses every digit there.  With Carlson's integrals
(DLMF 19.25.1)

    K(m) = R_F(0, 1 - m, 1),
    K(m) - E(m) = m/3 R_D(0, 1 - m, 1),
    E(m)/(1 - m) - K(m) = m/3 R_D(0, 1, 1 - m),

the factor m cancels symbolically and the generated code is accurate for every
m in [0, 1).  :func:`to_carlson` performs that rewrite; the tests check the three
identities against mpmath.
"""

from __future__ import annotations

from ._codegen import sp

__all__ = ["carlson_rf", "carlson_rd", "to_carlson"]


def _carlson_class(name: str, scipy_name: str, mpmath_name: str):
    """A SymPy Function printing to ``scipy.special.<scipy_name>``, evaluating with mpmath."""

    def _numpycode(self, printer):
        args = ", ".join(printer.doprint(arg) for arg in self.args)
        return f"{printer._module_format('scipy.special.' + scipy_name)}({args})"

    def _eval_evalf(self, prec):
        import mpmath
        from mpmath.libmp import prec_to_dps

        if not all(arg.is_number for arg in self.args):
            return None
        with mpmath.workprec(prec + 10):
            values = [mpmath.mpf(arg.evalf(prec_to_dps(prec) + 5)) for arg in self.args]
            return sp.Float(getattr(mpmath, mpmath_name)(*values), prec_to_dps(prec))

    return type(
        name,
        (sp.Function,),
        {"nargs": 3, "is_real": True, "_numpycode": _numpycode, "_eval_evalf": _eval_evalf},
    )


_CLASSES: dict = {}


def _cls(name, scipy_name, mpmath_name):
    if name not in _CLASSES:
        _CLASSES[name] = _carlson_class(name, scipy_name, mpmath_name)
    return _CLASSES[name]


def carlson_rf(x, y, z):
    """R_F(x, y, z), Carlson's symmetric integral of the first kind (DLMF 19.16.1)."""
    return _cls("carlson_rf", "elliprf", "elliprf")(x, y, z)


def carlson_rd(x, y, z):
    """R_D(x, y, z), Carlson's symmetric integral of the second kind (DLMF 19.16.5)."""
    return _cls("carlson_rd", "elliprd", "elliprd")(x, y, z)


def to_carlson(expr, m):
    """Rewrite ``elliptic_k(m)`` and ``elliptic_e(m)`` in ``expr`` with Carlson's integrals.

    E(m) is replaced by R_F(0, 1-m, 1) - m/3 R_D(0, 1-m, 1), so that K - E becomes
    m/3 R_D(...) and the factor m cancels on simplification.
    """
    rf = carlson_rf(0, 1 - m, 1)
    rd = carlson_rd(0, 1 - m, 1)
    return expr.subs({sp.elliptic_k(m): rf, sp.elliptic_e(m): rf - m * rd / 3})
