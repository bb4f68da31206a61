"""Input checks shared by every public numeric function.

Each check converts its input to a float array (so functions broadcast) and raises a
:class:`ValueError` that names the parameter and says what is wrong with it.  The checks
cost two reductions (min and max) per array, so validating 10^5 points is cheap beside
the arithmetic that follows; values in messages are printed with every digit that
matters (``2.9999999999999996``, never a rounded ``3``).
"""

from __future__ import annotations

import math
import numbers

import numpy as np

__all__ = [
    "as_array",
    "as_float",
    "positive",
    "nonnegative",
    "in_range",
    "boolean",
    "flag",
    "integer",
    "count",
    "choice",
    "broadcast_shape",
    "finite_result",
    "show",
    "distinct",
    "compact_wave_exponent",
    "compact_wave_chain",
    "torus_radii",
    "spreads",
    "exponent_between",
    "finite_array_result",
    "rings",
]


def as_array(name: str, value) -> np.ndarray:
    """``value`` as a float array, unchecked beyond its type (a TypeError for non-numbers)."""
    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a real number or an array of them, got {value!r}") from None


def _bounds(array: np.ndarray):
    """(min, max) of a non-empty array; NaN anywhere makes both NaN."""
    if array.size == 1:
        value = array.item()
        return value, value
    return array.min(), array.max()


def as_float(name: str, value) -> np.ndarray:
    """``value`` as a float array; rejects non-numeric and non-finite entries."""
    array = as_array(name, value)
    if array.size:
        lo, hi = _bounds(array)
        if not (lo > -np.inf and hi < np.inf):  # False for NaN too
            raise ValueError(f"{name} must be finite, got {_show_bad(array, value)}")
    return array


def _checked(name: str, value, ok, requirement: str, unit: str) -> np.ndarray:
    array = as_array(name, value)
    if array.size:
        lo, hi = _bounds(array)
        if not (hi < np.inf and lo > -np.inf and ok(lo, hi)):
            if not np.all(np.isfinite(array)):
                raise ValueError(f"{name} must be finite, got {_show_bad(array, value)}")
            raise ValueError(f"{name} must be {requirement}{_in(unit)}, got {show(array)}")
    return array


def positive(name: str, value, unit: str = "") -> np.ndarray:
    """``value`` > 0 (and finite) everywhere."""
    return _checked(name, value, lambda lo, hi: lo > 0, "positive", unit)


def nonnegative(name: str, value, unit: str = "") -> np.ndarray:
    """``value`` >= 0 (and finite) everywhere."""
    return _checked(name, value, lambda lo, hi: lo >= 0, "non-negative", unit)


def in_range(name: str, value, low: float, high: float, *, closed_low=False, closed_high=True) -> np.ndarray:
    """``low < value <= high`` (bounds open or closed as asked) everywhere; finite."""
    array = as_float(name, value)
    if array.size:
        lo, hi = _bounds(array)
        above = lo >= low if closed_low else lo > low
        below = hi <= high if closed_high else hi < high
        if not (above and below):
            left = "[" if closed_low else "("
            right = "]" if closed_high else ")"
            raise ValueError(f"{name} must lie in {left}{low:g}, {high:g}{right}, got {show(array)}")
    return array


def boolean(name: str, value) -> bool:
    """``value`` if it is ``True`` or ``False`` (NumPy booleans included); a string such as
    ``"no"`` would be truthy, so anything else is refused."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise TypeError(f"{name} must be True or False, got {value!r}")


def flag(name: str, value) -> bool:
    """``value`` as a bool: True or False only (a string such as "no" is refused, not read as true); ValueError."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise ValueError(f"{name} must be True or False, got {value!r}")


def integer(name: str, value) -> int:
    """``value`` as an int: a whole number (2 or 2.0), not a bool, a string or 2.7 (ValueError naming it)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} must be an integer, got {value!r}")
    if not math.isfinite(value) or int(value) != value:
        raise ValueError(f"{name} must be an integer, got {value!r}")
    return int(value)


def count(name: str, value, minimum: int) -> int:
    """An integer of at least ``minimum`` (ValueError naming it)."""
    value = integer(name, value)
    if value < minimum:
        raise ValueError(f"{name} must be at least {minimum}, got {value}")
    return value


def choice(name: str, value, options):
    """``value`` if it is one of ``options`` (ValueError listing them)."""
    if not isinstance(value, str | int | float) or value not in options:
        raise ValueError(f"{name} must be one of {tuple(options)}, got {value!r}")
    return value


def broadcast_shape(**arrays) -> tuple:
    """The common shape of the named arrays; a ValueError naming the two that clash otherwise."""
    shapes = {name: np.shape(array) for name, array in arrays.items()}
    distinct = {shape for shape in shapes.values() if shape != ()}
    if len(distinct) <= 1:  # numbers and one shape: nothing to check
        return distinct.pop() if distinct else ()
    try:
        return np.broadcast_shapes(*shapes.values())
    except ValueError:
        pass
    names = list(shapes)
    for i, first in enumerate(names):
        for second in names[i + 1 :]:
            try:
                np.broadcast_shapes(shapes[first], shapes[second])
            except ValueError:
                raise ValueError(
                    f"{first} (shape {shapes[first]}) and {second} (shape {shapes[second]}) cannot be broadcast "
                    "together: give arrays of equal shape, or shapes that NumPy broadcasting combines"
                ) from None
    described = ", ".join(f"{name} {shape}" for name, shape in shapes.items())
    raise ValueError(f"the shapes {described} cannot be broadcast together")


def finite_result(value, what: str, inputs: str):
    """``value`` if every entry is finite; else a ValueError saying that ``what`` is beyond
    double precision for these ``inputs`` (a description of the arguments involved)."""
    array = np.asarray(value)
    if array.size == 1:
        total = array.item()
    else:
        # One reduction: a sum is finite when every entry is (it could overflow only for entries
        # within a factor array.size of the largest double, which the exact check then clears).
        with np.errstate(over="ignore", invalid="ignore"):
            total = np.sum(array)
    if array.size and not np.isfinite(total) and not np.all(np.isfinite(array)):
        raise ValueError(
            f"{what} is not representable in double precision (it overflows or is undefined) for these "
            f"{inputs}; they lie far outside any physical range"
        )
    return value


def distinct(x: float, limit: float) -> str:
    """``x`` with the fewest significant digits (at least 4) that do not print it as ``limit``."""
    for digits in range(4, 18):
        text = f"{x:.{digits}g}"
        if x == limit or text != f"{limit:.{digits}g}":
            return text
    return repr(x)


def compact_wave_exponent(n):
    """n as a float array, > 1: the power-law chain has a compact solitary wave (with the reason in the error)."""
    try:
        return in_range("n", n, 1.0, np.inf)
    except ValueError as error:
        raise ValueError(
            f"{error}: the power-law chain has a compact solitary wave only for n > 1 "
            "(its profile |sin|^(2/(n-1)) needs n > 1; n = 1 is the linear chain, where pulses disperse)"
        ) from None


def compact_wave_chain(K, n, a, m=None):
    """K (N/m^n), n (> 1), a (m) and, if given, m (kg) of a power-law chain with a compact wave, checked."""
    out = [positive("K", K, "N/m^n"), compact_wave_exponent(n), positive("a", a, "m")]
    if m is not None:
        out.append(positive("m", m, "kg"))
    return out


def torus_radii(R, r):
    """R, r as float arrays with 0 < 2 r < R, finite; a ValueError naming the problem otherwise.

    The usual case (r one number) costs two reductions over R.
    """
    r = positive("r", r, "m")
    R = as_array("R", R)
    broadcast_shape(R=R, r=r)
    if R.size and r.size == 1:
        lo, hi = R.min(), R.max()
        fine = bool(hi < np.inf and 0.5 * lo > r.reshape(()))  # False for NaN too; 0.5 R is exact
    else:
        fine = False
    if not fine:
        R = positive("R", R, "m")
        if not np.all(0.5 * R > r):
            with np.errstate(all="ignore"):
                ratio = np.min(R / r)
            raise ValueError(
                "R must exceed 2 r: for R <= 2 r the relative curvature of two interlocked tori is not "
                f"positive and Hertz contact does not apply (got R/r = {show(ratio)})"
            )
    return R, r


def spreads(sigma_K, sigma_m, correlation):
    """Two relative spreads (>= 0) and their correlation (in [-1, 1]) of a disordered chain, as float arrays."""
    sigma_K = nonnegative("sigma_K", sigma_K)
    sigma_m = nonnegative("sigma_m", sigma_m)
    correlation = in_range("correlation", correlation, -1.0, 1.0, closed_low=True, closed_high=True)
    return sigma_K, sigma_m, correlation


def exponent_between(n, low=1.0, high=np.inf):
    """n in (low, high) for low 1 (the compact wave) or 0 (any power law), with what the bounds mean."""
    try:
        return in_range("n", n, low, high, closed_high=False)
    except ValueError as error:
        reason = {
            1.0: "the compact solitary wave exists only for n > 1 (n = 1 is the linear chain)",
            0.0: "the contact law F = K delta^n needs n > 0",
        }[low]
        if high < np.inf:
            reason += f"; its strain profile has an infinite mean square wavenumber (a cusp) for n >= {high:g}"
        raise ValueError(f"{error}: {reason}") from None


def finite_array_result(value, what: str, inputs: str):
    """``value`` as a float array (computed quietly), checked by :func:`finite_result`."""
    with np.errstate(all="ignore"):
        array = np.asarray(value, dtype=float)
    return finite_result(array, what, inputs)


def rings(name, value, unit):
    """Per-ring values: positive, finite, at least one ring on the last axis (a number is one ring)."""
    array = positive(name, value, unit)
    if array.ndim == 0:
        array = array[None]
    if array.shape[-1] == 0:
        raise ValueError(f"{name} must hold at least one ring: its last axis (the rings) is empty")
    return array


def show(array) -> str:
    """A value for a message: the shortest repr that round-trips (no misleading rounding)."""
    array = np.asarray(array, dtype=float)
    if array.size == 1:
        return repr(float(array.reshape(())))
    return f"an array with min {float(np.nanmin(array))!r} and max {float(np.nanmax(array))!r}"


def _show_bad(array: np.ndarray, value) -> str:
    if array.size == 1:
        return repr(float(array.reshape(())))
    bad = array[~np.isfinite(array)]
    return f"an array containing {float(bad[0])!r}"


def _in(unit: str) -> str:
    return f" (in {unit})" if unit else ""
