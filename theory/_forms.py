"""Numeric forms of derived expressions: what the generated code should compute, in which order.

:func:`sympy.lambdify` prints an expression as SymPy stores it.  Two habits of that form
cost array passes (each about as long as a hand-written NumPy operation on the whole
array) without changing the value:

- differences are stored with a negative leading term, ``(-R + 2*r)/(-R + r)``, which
  prints as a negation and an addition per difference;
- the factors of a product are printed in SymPy's order, so an array factor can come
  first and turn every later scalar factor into an array multiplication.

:func:`positive_differences` flips the signs of differences in pairs (the value is
unchanged), and :func:`split_product` separates a product into the factor that depends on
given symbols (typically the arrays, such as the geometry or the force) and the rest
(typically scalars, such as the material or the chain), so that the numeric function
multiplies the two once, after each is evaluated on its own arguments.

Shared by several derivations, on the symbolic side: :func:`tidy_powers` and :func:`merge_powers`
merge the powers of positive bases (the first also cancels exponents and factors the bases of powers
of sums: :mod:`.solitary`, :mod:`.prestressed`; the second only expands, flattens and combines:
:mod:`.disorder`, :mod:`.attenuation`), :func:`power_root` solves a power of x equal to another for x > 0
(:mod:`.solitary`, :mod:`.pulse`), and :func:`sum_of_squares` writes a variance of two
correlated terms in a form that rounding cannot make negative (:mod:`.disorder`, :mod:`.scattering`).
"""

from __future__ import annotations

import numpy as np

from ._codegen import sp

__all__ = [
    "positive_differences",
    "split_product",
    "log_monomial",
    "power_law",
    "power_law_value",
    "tidy_powers",
    "merge_powers",
    "power_root",
    "sum_of_squares",
]


def _leading_negative(add) -> bool:
    """Whether the term of ``add`` printed first has a negative coefficient."""
    coefficient, _ = add.as_ordered_terms()[0].as_coeff_Mul()
    return bool(coefficient.is_negative)


def _difference(factor):
    """The sum inside ``factor`` if its sign can be flipped (a sum, or a sum to an odd power)."""
    if factor.is_Add:
        return factor
    if factor.is_Pow and factor.base.is_Add and factor.exp.is_integer and factor.exp.is_odd:
        return factor.base
    return None


def _flip(factor):
    if factor.is_Add:
        return -factor
    return sp.Pow(-factor.base, factor.exp)


def _fix_mul(product):
    factors = list(product.args)
    sums = {i: _difference(factor) for i, factor in enumerate(factors)}
    sums = {i: add for i, add in sums.items() if add is not None}
    flip = [i for i, add in sums.items() if _leading_negative(add)]
    # Partners: sums printed positive both ways round (2*x - 1 <-> 1 - 2*x), and a negative number.
    partners = [i for i, add in sums.items() if i not in flip and not _leading_negative(-add)]
    sign = [i for i, factor in enumerate(factors) if factor.is_Number and factor.is_negative]
    if len(flip) % 2 and sign:
        factors[sign[0]] = -factors[sign[0]]
    elif len(flip) % 2 and partners:
        flip.append(partners[0])
    elif len(flip) % 2:
        flip.pop()
    elif sign and partners:  # -R*(2*x - 1) -> R*(1 - 2*x): a difference instead of a negation
        factors[sign[0]] = -factors[sign[0]]
        flip.append(partners[0])
    for i in flip:
        factors[i] = _flip(factors[i])
    rebuilt = sp.Mul(*factors)
    if sp.cancel(sp.together(rebuilt - product)) != 0:  # pragma: no cover - a check of the rewrite itself
        raise RuntimeError(f"sign rewrite changed {product}")
    return rebuilt


def _is_reciprocal_root(power) -> bool:
    return bool(power.is_Pow and not power.base.is_Atom and power.exp.is_Rational and power.exp.is_negative)


def positive_differences(expr):
    """``expr`` with the differences in each product printed with a positive leading term.

    Signs are flipped in pairs (or against a negative numeric coefficient), so the value is
    unchanged: ``(-R + 2*r)/(-R + r)`` becomes ``(R - 2*r)/(R - r)``; and a negative
    fractional power of a quotient is taken of the inverted quotient, ``1/sqrt((R - 2*r)/(R - r))``
    -> ``sqrt((R - r)/(R - 2*r))``, one division fewer.
    """
    if isinstance(expr, tuple):
        return tuple(positive_differences(e) for e in expr)
    expr = expr.replace(lambda e: e.is_Mul, _fix_mul)
    return expr.replace(lambda e: _is_reciprocal_root(e) and not e.exp.is_integer, lambda e: sp.Pow(1 / e.base, -e.exp))


def split_product(expr, *symbols):
    """``(rest, part)`` with ``expr = rest * part``: ``part`` holds every factor depending on ``symbols``.

    Raises ``RuntimeError`` if ``expr`` is not such a product (the rest would still depend
    on the symbols).  Both factors are returned in :func:`positive_differences` form.
    """
    rest, part = expr.as_independent(*symbols, as_Add=False)
    if rest.has(*symbols) or sp.simplify(rest * part - expr) != 0:  # pragma: no cover - derivation check
        raise RuntimeError(f"{expr} does not separate into factors with and without {symbols}")
    return positive_differences(rest), positive_differences(part)


def log_monomial(expr):
    """log(expr) for a monomial in positive quantities, expanded: sum of exponent * log(base).

    Evaluating exp of this sum (instead of the product of powers) keeps intermediate
    results in range when the result is: a product such as F_m^p K^q/m can overflow on
    the way to a representable speed.
    """
    logarithm = sp.expand(sp.expand_log(sp.log(positive_differences(expr)), force=True))
    if logarithm.has(sp.exp, sp.I):  # pragma: no cover - derivation check
        raise RuntimeError(f"{expr} is not a monomial of positive factors")
    return logarithm


def power_law(expr, variable):
    """``(log C, p)`` with ``expr = C variable^p``, C and p free of the variable (log C by :func:`log_monomial`).

    The numeric code evaluates :func:`power_law_value`: for an array of the variable and scalar
    parameters that is four array operations, with no intermediate overflow.
    """
    rest, part = expr.as_independent(variable, as_Add=False)
    base, exponent = sp.powsimp(sp.powdenest(part, force=True), force=True).as_base_exp()
    if base != variable or exponent.has(variable):  # pragma: no cover - derivation check
        raise RuntimeError(f"{expr} is not a power of {variable}")
    return log_monomial(rest), sp.factor(exponent)


def power_law_value(log_coefficient, exponent, variable):
    """C variable^p evaluated as exp(log C + p log(variable)), variable > 0 (NumPy; broadcasts)."""
    value = np.log(variable)
    if isinstance(value, np.ndarray) and value.shape == np.broadcast_shapes(
        value.shape, np.shape(exponent), np.shape(log_coefficient)
    ):
        value *= exponent
        value += log_coefficient
        return np.exp(value, out=value)
    return np.exp(log_coefficient + exponent * value)


def tidy_powers(expr):
    """Merge powers and cancel their exponents (every base positive); the bases of powers of sums factored."""
    expr = expr.replace(lambda e: e.is_Pow and e.base.is_Add, lambda e: sp.Pow(sp.factor(e.base), e.exp))
    expr = sp.expand_power_base(sp.powdenest(sp.expand_power_base(expr, force=True), force=True), force=True)
    expr = sp.powsimp(expr, combine="exp", force=True)
    expr = expr.replace(
        lambda e: e.is_Pow and bool(e.exp.free_symbols), lambda e: sp.Pow(e.base, sp.factor(sp.cancel(e.exp)))
    )
    return sp.powsimp(expr, combine="exp", force=True)


def merge_powers(expr):
    """Powers of positive bases merged (the bases expanded, nested powers flattened, equal bases combined)."""
    return sp.powsimp(sp.powdenest(sp.expand_power_base(expr, force=True), force=True), force=True)


def power_root(equation, x):
    """x > 0 from ``equation``, c_1 x^e_1 = c_2 x^e_2, each side a monomial in x (checked): (c_2/c_1)^(1/(e_1 - e_2)).

    Powers of products are split first, (c x)^e = c^e x^e (every base positive); the numeric
    factor common to the terms of a sum is taken out of c_2/c_1 (``factor_terms``), the form
    ``solve`` gives (:mod:`.solitary`, :mod:`.pulse`: a few ms instead of 0.5 s).
    """
    sides = []
    for side in (equation.lhs, equation.rhs):
        side = side.replace(
            lambda e: e.is_Pow and e.base.is_Mul and e.base.has(x),
            lambda e: sp.Mul(*(sp.Pow(factor, e.exp) for factor in e.base.as_independent(x, as_Add=False))),
        )
        coefficient, power = side.as_independent(x, as_Add=False)
        base, exponent = power.as_base_exp()
        if coefficient.has(x) or (power != 1 and base != x):  # pragma: no cover - derivation check
            raise RuntimeError(f"{side} is not a monomial in {x}")
        sides.append((coefficient, exponent if power != 1 else sp.S.Zero))
    (first, e_first), (second, e_second) = sides
    difference = sp.cancel(e_first - e_second)
    if difference == 0:
        raise RuntimeError(f"{equation} has the same power of {x} on both sides")
    return sp.factor_terms(second / first) ** (1 / difference)


def sum_of_squares(variance, first, second, correlation):
    """``variance`` = first^2 + second^2 + 2 c first second (checked) in a form that stays non-negative.

    (1+c)/2 (first+second)^2 + (1-c)/2 (first-second)^2.

    Both terms are non-negative for |c| <= 1, so rounding never makes the value negative.
    """
    if sp.simplify(variance - (first**2 + second**2 + 2 * correlation * first * second)) != 0:  # pragma: no cover
        raise RuntimeError(f"{variance} is not the variance of two correlated terms")
    return (1 + correlation) / 2 * (first + second) ** 2 + (1 - correlation) / 2 * (first - second) ** 2
