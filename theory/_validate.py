"""Input checks shared by every public numeric function.

Each check converts its input to a float array (so functions broadcast) and raises a
:class:`ValueError` that names the parameter and says what is wrong with it.
"""

from __future__ import annotations

import numpy as np

__all__ = ["as_float", "positive", "nonnegative", "in_range"]


def as_float(name: str, value) -> np.ndarray:
    """``value`` as a float array; rejects non-numeric and non-finite entries."""
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a real number or an array of them, got {value!r}") from None
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name} must be finite, got {value!r}")
    return array


def positive(name: str, value, unit: str = "") -> np.ndarray:
    """``value`` > 0 everywhere."""
    array = as_float(name, value)
    if np.any(array <= 0):
        raise ValueError(f"{name} must be positive{_in(unit)}, got {_show(array)}")
    return array


def nonnegative(name: str, value, unit: str = "") -> np.ndarray:
    """``value`` >= 0 everywhere."""
    array = as_float(name, value)
    if np.any(array < 0):
        raise ValueError(f"{name} must be non-negative{_in(unit)}, got {_show(array)}")
    return array


def in_range(name: str, value, low: float, high: float, *, closed_low=False, closed_high=True) -> np.ndarray:
    """``low < value <= high`` (bounds open or closed as asked) everywhere."""
    array = as_float(name, value)
    above = array >= low if closed_low else array > low
    below = array <= high if closed_high else array < high
    if not np.all(above & below):
        lo = "[" if closed_low else "("
        hi = "]" if closed_high else ")"
        raise ValueError(f"{name} must lie in {lo}{low:g}, {high:g}{hi}, got {_show(array)}")
    return array


def _in(unit: str) -> str:
    return f" (in {unit})" if unit else ""


def _show(array: np.ndarray) -> str:
    return f"{array.item():g}" if array.size == 1 else f"array with min {array.min():g}"
