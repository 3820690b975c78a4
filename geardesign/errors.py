"""The one exception family of geardesign and the input validators that raise it.

Every message names the input, the value it got and the range it allows, so that a
user (or the command line, which prints the message as one line) knows what to change.
"""
from __future__ import annotations

import numbers

import numpy as np

__all__ = [
    "GearDesignError",
    "CatalogError",
    "require_finite",
    "require_positive",
    "require_range",
    "require_int",
]


class GearDesignError(ValueError):
    """Bad input to geardesign: names the input, its value and the allowed range."""


class CatalogError(GearDesignError):
    """A catalog file that is missing, malformed or inconsistent (names file, row and column)."""


def _show(value) -> str:
    arr = np.asarray(value)
    if arr.ndim == 0:
        return repr(value.item() if hasattr(value, "item") else value)
    return f"array of shape {arr.shape}"


def _first_bad(arr: np.ndarray, bad: np.ndarray) -> str:
    if arr.ndim == 0:
        return repr(arr.item())
    idx = tuple(int(i) for i in np.argwhere(bad)[0])
    return f"{arr[idx].item()!r} (at index {idx if len(idx) > 1 else idx[0]})"


def require_finite(name: str, value) -> np.ndarray:
    """Return ``value`` as a float array; raise if any element is NaN or infinite."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise GearDesignError(f"{name} must be a number, got {_show(value)}") from None
    bad = ~np.isfinite(arr)
    if bad.any():
        raise GearDesignError(f"{name} must be finite, got {_first_bad(arr, bad)}")
    return arr


def require_positive(name: str, value, unit: str = "") -> np.ndarray:
    """Finite and strictly positive."""
    arr = require_finite(name, value)
    bad = arr <= 0
    if bad.any():
        u = f" {unit}" if unit else ""
        raise GearDesignError(f"{name} must be > 0{u}, got {_first_bad(arr, bad)}")
    return arr


def require_range(name: str, value, lo: float, hi: float, *, lo_open=False, hi_open=False,
                  unit: str = "") -> np.ndarray:
    """Finite and inside [lo, hi] (or the open ends asked for)."""
    arr = require_finite(name, value)
    bad = (arr <= lo) if lo_open else (arr < lo)
    bad |= (arr >= hi) if hi_open else (arr > hi)
    if bad.any():
        left = "(" if lo_open else "["
        right = ")" if hi_open else "]"
        u = f" {unit}" if unit else ""
        raise GearDesignError(
            f"{name} must be in {left}{lo:g}, {hi:g}{right}{u}, got {_first_bad(arr, bad)}")
    return arr


def require_int(name: str, value, minimum: int) -> np.ndarray:
    """Whole numbers (an int, or a float with no fractional part) >= minimum."""
    if isinstance(value, bool):
        raise GearDesignError(f"{name} must be a whole number >= {minimum}, got {value!r}")
    if isinstance(value, numbers.Integral):
        arr = np.asarray(value, dtype=np.int64)
    else:
        farr = require_finite(name, value)
        frac = farr != np.round(farr)
        if frac.any():
            raise GearDesignError(
                f"{name} must be a whole number >= {minimum}, got {_first_bad(farr, frac)}")
        arr = farr.astype(np.int64)
    bad = arr < minimum
    if bad.any():
        raise GearDesignError(f"{name} must be a whole number >= {minimum}, got {_first_bad(arr, bad)}")
    return arr


def is_scalar(*values) -> bool:
    """True when every value is a Python or numpy scalar (0-d)."""
    return all(np.ndim(v) == 0 for v in values)


