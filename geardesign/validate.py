"""Input validators shared by every layer: each raises a :class:`~geardesign.errors.GearDesignError`
that names the input, the value it got and the range it allows."""
from __future__ import annotations

import numbers
import sys

import numpy as np

from .errors import GearDesignError

__all__ = [
    "require_finite", "require_positive", "require_range", "require_int", "require_count", "one_number",
    "ndim", "require_choice", "require_bool", "broadcast_inputs", "require_axes",
    "require_callable", "hint_unknown_arguments",
]


def _show(value) -> str:
    try:
        arr = np.asarray(value)
    except Exception:   # ragged lists and the like
        return _short(value)
    if arr.ndim == 0:
        return _short(value.item() if hasattr(value, "item") else value)
    return f"array of shape {arr.shape}"


def _first_bad(arr: np.ndarray, bad: np.ndarray) -> str:
    if arr.ndim == 0:
        return repr(arr.item())
    idx = tuple(int(i) for i in np.argwhere(bad)[0])
    return f"{arr[idx].item()!r} (at index {idx if len(idx) > 1 else idx[0]})"


def require_finite(name: str, value) -> np.ndarray:
    """Return ``value`` as a float array; raise if any element is NaN or infinite."""
    if isinstance(value, (str, bytes, bool, np.bool_)):
        raise GearDesignError(f"{name} must be a number, got {_short(value)}")
    try:
        arr = np.asarray(value, dtype=float)
    except OverflowError:
        raise GearDesignError(f"{name} must be finite, got {_show(value)}") from None
    except (TypeError, ValueError):
        raise GearDesignError(f"{name} must be a number, got {_show(value)}") from None
    bad = ~np.isfinite(arr)
    if bad.any():
        raise GearDesignError(f"{name} must be finite, got {_first_bad(arr, bad)}")
    return arr


_FLOAT_MAX = sys.float_info.max


def _plain(value):
    """``value`` as a finite float when it is one plain number (a Python int or float, or the 0-d float
    array a validator returns), else None: the common case, checked without numpy (~1 µs instead of ~4)."""
    t = type(value)
    if t is float or t is int:
        return float(value) if -_FLOAT_MAX <= value <= _FLOAT_MAX else None
    if t is np.ndarray and value.ndim == 0 and value.dtype == np.float64:
        v = float(value)
        return v if -_FLOAT_MAX <= v <= _FLOAT_MAX else None
    return None


def require_positive(name: str, value, unit: str = "") -> np.ndarray:
    """Finite and strictly positive."""
    v = _plain(value)
    if v is not None and v > 0:
        return np.asarray(v)
    arr = require_finite(name, value)
    bad = arr <= 0
    if bad.any():
        u = f" {unit}" if unit else ""
        raise GearDesignError(f"{name} must be > 0{u}, got {_first_bad(arr, bad)}")
    return arr


def require_range(name: str, value, lo: float, hi: float, *, lo_open=False, hi_open=False,
                  unit: str = "") -> np.ndarray:
    """Finite and inside [lo, hi] (or the open ends asked for)."""
    v = _plain(value)
    if v is not None and (lo < v if lo_open else lo <= v) and (v < hi if hi_open else v <= hi):
        return np.asarray(v)
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


def require_int(name: str, value, minimum: int, maximum: int | None = None) -> np.ndarray:
    """Whole numbers (an int, or a float with no fractional part) in [minimum, maximum].

    ``maximum`` defaults to 10**15 so that every accepted value is exact in int64 and a float
    such as 1e308 is refused by name instead of wrapping around.
    """
    hi = _INT_MAX if maximum is None else int(maximum)
    rng = f"in [{minimum}, {hi:.6g}]"
    if isinstance(value, (bool, np.bool_)) or isinstance(value, (str, bytes)):
        raise GearDesignError(f"{name} must be a whole number {rng}, got {value!r}")
    if isinstance(value, numbers.Integral):
        v = int(value)
        if not minimum <= v <= hi:
            raise GearDesignError(f"{name} must be a whole number {rng}, got {_short(v)}")
        return np.asarray(v, dtype=np.int64)
    farr = require_finite(name, value)
    frac = farr != np.round(farr)
    if frac.any():
        raise GearDesignError(f"{name} must be a whole number {rng}, got {_first_bad(farr, frac)}")
    bad = (farr < minimum) | (farr > hi)
    if bad.any():
        raise GearDesignError(f"{name} must be a whole number {rng}, got {_first_bad(farr, bad)}")
    return farr.astype(np.int64)


def one_number(name: str, arr) -> float:
    """The single number a validator returned, as a float; an array (a list given where one
    number belongs) is refused by name."""
    if np.ndim(arr) != 0:
        raise GearDesignError(f"{name} must be one number, got {_show(arr)}")
    return float(arr)


def require_count(name: str, value, lo: int, hi: int) -> int:
    """One whole number in [lo, hi]: a size (grid nodes, pairs, values) checked before any work."""
    if type(value) is int and lo <= value <= hi:
        return value
    if ndim(value) != 0:
        raise GearDesignError(f"{name} must be one whole number in [{lo}, {hi:.6g}], got {_show(value)}")
    return int(require_int(name, value, lo, hi))


def require_choice(name: str, value, choices) -> str:
    """One of ``choices`` (strings); anything else, a list included, is refused by name."""
    choices = list(choices)
    if not isinstance(value, str) or value not in choices:
        raise GearDesignError(f"{name} must be one of {choices}, got {_short(value)}")
    return value


def require_bool(name: str, value) -> bool:
    """True or False (numpy booleans too); 0/1 and strings are refused."""
    if not isinstance(value, (bool, np.bool_)):
        raise GearDesignError(f"{name} must be True or False, got {_short(value)}")
    return bool(value)


def require_axes(name: str, value, count: int = 1):
    """A matplotlib Axes (``count`` 1) or a sequence of ``count`` of them, as given; anything else
    refused by name (matplotlib is imported only here, when a caller hands axes in)."""
    from matplotlib.axes import Axes
    items = [value] if count == 1 else value
    try:
        ok = len(items) == count and all(isinstance(a, Axes) for a in items)
    except TypeError:
        ok = False
    if not ok:
        want = "a matplotlib Axes" if count == 1 else f"{count} matplotlib Axes"
        raise GearDesignError(f"{name} must be {want} or None, got {_short(value)}")
    return value


def require_callable(name: str, value, allow_none: bool = True):
    """A function (or None where ``allow_none``); anything else refused by name."""
    if (value is None and allow_none) or callable(value):
        return value
    raise GearDesignError(f"{name} must be a function{' or None' if allow_none else ''}, got {_short(value)}")


def broadcast_inputs(**arrays) -> list[np.ndarray]:
    """numpy-broadcast the named arrays; shapes that do not broadcast are refused by name."""
    try:
        return list(np.broadcast_arrays(*arrays.values()))
    except ValueError:
        shapes = ", ".join(f"{k} {np.shape(v)}" for k, v in arrays.items())
        raise GearDesignError(f"input shapes do not broadcast together: {shapes}") from None


_INT_MAX = 10**15


def hint_unknown_arguments(cls, hints: dict, needs: dict | None = None):
    """Wrap the dataclass ``cls``'s ``__init__`` so that an unknown keyword is refused by name: the class's own
    arguments listed, and where ``hints`` holds the name, a hint to the right one (``{value!r}``: what was given),
    in place of Python's bare TypeError. A required argument left out is refused by name too, with what
    ``needs`` says of it (its meaning, unit and range). Returns ``cls``."""
    import dataclasses
    import functools

    init = cls.__init__
    known = [f.name for f in dataclasses.fields(cls) if f.init]
    required = [f.name for f in dataclasses.fields(cls) if f.init and f.default is dataclasses.MISSING
                and f.default_factory is dataclasses.MISSING]
    needs = needs or {}

    @functools.wraps(init)
    def checked_init(self, *args, **kwargs):
        for name in kwargs:
            if name not in known:
                hint = hints.get(name, "").format(value=kwargs[name])
                raise GearDesignError(f"{cls.__name__} has no argument {name!r}" + (f": {hint}" if hint else "")
                                      + f"; its arguments are {', '.join(sorted(known))}")
        if len(args) > len(known):
            raise GearDesignError(f"{cls.__name__} takes at most {len(known)} arguments ({', '.join(known)}), "
                                  f"got {len(args)}")
        missing = [name for name in required[len(args):] if name not in kwargs]
        if missing:
            said = "; ".join(f"{name}: {needs[name]}" if name in needs else name for name in missing)
            raise GearDesignError(f"{cls.__name__} needs {', '.join(missing)} (missing): {said}")
        init(self, *args, **kwargs)

    cls.__init__ = checked_init
    return cls


def _short(value) -> str:
    """repr of a value, cut to 60 characters (a 400-digit integer must not fill the screen)."""
    text = repr(value)
    return text if len(text) <= 60 else text[:40] + f"... ({len(text)} characters)"


def ndim(value) -> int:
    """np.ndim of a user's value; -1 for what numpy cannot shape (ragged lists and the like)."""
    try:
        return int(np.ndim(value))
    except (ValueError, TypeError):
        return -1


def is_scalar(*values) -> bool:
    """True when every value is a Python or numpy scalar (0-d)."""
    return all(np.ndim(v) == 0 for v in values)


