"""Special functions for derivations whose generated code calls SciPy: Carlson's integrals, 2F1, Beta;
and an exponential that SymPy leaves alone.

The elliptical Hertz contact is written by Johnson with the complete elliptic
integrals K(m) and E(m) (parameter m = e^2).  Its two key combinations,
(K - E)/m and (E/(1 - m) - K)/m, are 0/0 at the circular contact m = 0, so code
evaluating them literally loses every digit there.  With Carlson's integrals
(DLMF 19.25.1)

    K(m) = R_F(0, 1 - m, 1),
    K(m) - E(m) = m/3 R_D(0, 1 - m, 1),
    E(m)/(1 - m) - K(m) = m/3 R_D(0, 1, 1 - m),

the factor m cancels symbolically and the generated code is accurate for every
m in [0, 1).  :mod:`.contact` performs that rewrite; the tests check the three
identities against mpmath.
"""

from __future__ import annotations

import functools

from ._codegen import sp

__all__ = ["carlson_rf", "carlson_rd", "hyp2f1", "beta", "exp_of_log", "gauss_legendre"]


def _scipy_function(name: str, scipy_name: str, nargs: int, mpmath_name: str, module="scipy.special", **extra):
    """A SymPy Function of ``nargs`` arguments that prints to ``<module>.<scipy_name>``
    in generated code and evaluates with ``mpmath.<mpmath_name>`` in ``evalf``."""

    def _numpycode(self, printer):
        args = ", ".join(printer.doprint(arg) for arg in self.args)
        return f"{printer._module_format(module + '.' + scipy_name)}({args})"

    def _eval_evalf(self, prec):
        import mpmath
        from mpmath.libmp import prec_to_dps

        if not all(arg.is_number for arg in self.args):
            return None
        with mpmath.workprec(prec + 10):
            values = [mpmath.mpf(arg.evalf(prec_to_dps(prec) + 5)) for arg in self.args]
            return sp.Float(getattr(mpmath, mpmath_name)(*values), prec_to_dps(prec))

    attributes = {"nargs": nargs, "is_real": True, "_numpycode": _numpycode, "_eval_evalf": _eval_evalf}
    return type(name, (sp.Function,), {**attributes, **extra})


_CLASSES: dict = {}


def _cls(name, scipy_name, nargs, mpmath_name, **extra):
    if name not in _CLASSES:
        _CLASSES[name] = _scipy_function(name, scipy_name, nargs, mpmath_name, **extra)
    return _CLASSES[name]


def exp_of_log(x):
    """exp(x), printing to ``numpy.exp``, for x a sum of logarithms that SymPy would otherwise fold back.

    ``sympy.exp(3*log(a) - 2*log(b))`` evaluates to ``a**3/b**2`` at once, and the generated code then
    forms a^3 and b^2, which can overflow although their quotient would not.  This exponential
    keeps the logarithms (``expr.rewrite(sympy.exp)`` gives SymPy's own for symbolic work).
    """

    def _eval_rewrite_as_exp(self, arg, **kwargs):
        return sp.exp(arg)

    return _cls("exp_of_log", "exp", 1, "exp", module="numpy", _eval_rewrite_as_exp=_eval_rewrite_as_exp)(x)


def carlson_rf(x, y, z):
    """R_F(x, y, z), Carlson's symmetric integral of the first kind (DLMF 19.16.1)."""
    return _cls("carlson_rf", "elliprf", 3, "elliprf")(x, y, z)


def carlson_rd(x, y, z):
    """R_D(x, y, z), Carlson's symmetric integral of the second kind (DLMF 19.16.5)."""
    return _cls("carlson_rd", "elliprd", 3, "elliprd")(x, y, z)


def hyp2f1(a, b, c, z):
    """Gauss's 2F1(a, b; c; z) (DLMF 15.2.1), printing to ``scipy.special.hyp2f1``.

    ``expr.rewrite(sympy.hyper)`` gives SymPy's own ``hyper`` for symbolic work
    (e.g. :func:`sympy.hyperexpand`).
    """

    def _eval_rewrite_as_hyper(self, a, b, c, z, **kwargs):
        return sp.hyper([a, b], [c], z)

    return _cls("hyp2f1", "hyp2f1", 4, "hyp2f1", _eval_rewrite_as_hyper=_eval_rewrite_as_hyper)(a, b, c, z)


def beta(x, y):
    """Euler's Beta function B(x, y) = Gamma(x) Gamma(y)/Gamma(x + y) (DLMF 5.12.1), printing to ``scipy.special.beta``.

    SciPy evaluates it without forming the Gamma functions, so it stays finite for large
    arguments (the compact solitary wave as n -> 1, :mod:`.pulse`), where the Gamma
    quotient overflows.  ``expr.rewrite(sympy.gamma)`` gives the Gamma quotient.
    """

    def _eval_rewrite_as_gamma(self, x, y, **kwargs):
        return sp.gamma(x) * sp.gamma(y) / sp.gamma(x + y)

    return _cls("B", "beta", 2, "beta", _eval_rewrite_as_gamma=_eval_rewrite_as_gamma)(x, y)


@functools.cache
def gauss_legendre(order: int = 64):
    """Nodes and weights of the ``order``-point Gauss-Legendre rule on [-1, 1] (computed once per order)."""
    import numpy as np

    return np.polynomial.legendre.leggauss(order)
