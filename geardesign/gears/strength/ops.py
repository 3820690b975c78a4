"""The arithmetic the strength formulas are written in: one source for two kinds of input. One design in
Python floats runs on :mod:`math` (~10x faster than numpy on 0-d arrays); arrays of designs on numpy.
Each formula picks its operations with :func:`ops_of` from its inputs, so the chain of one pair and the
vectorised chain evaluate the same expressions."""
from __future__ import annotations

import contextlib
import functools
import math

import numpy as np

from ...validate import require_range

__all__ = ["FloatOps", "ArrayOps", "MixedOps", "ops_of", "checked", "once", "per_load_case"]


def _any(a):
    return a.any() if type(a) is np.ndarray else np.any(a)


def _all(a):
    return a.all() if type(a) is np.ndarray else np.all(a)


def _clip(a, lo, hi):
    return np.minimum(np.maximum(a, lo), hi)     # np.clip's values, without its Python wrapper (small batches)


class ArrayOps:
    """numpy functions for arrays of designs (any input numpy accepts: lists, ints, 0-d arrays)."""
    sin, cos, tan, sqrt, cbrt, arccos, exp, exp2, log = np.sin, np.cos, np.tan, np.sqrt, np.cbrt, np.arccos, \
        np.exp, np.exp2, np.log
    radians, degrees, abs, maximum, minimum, where = np.radians, np.degrees, np.abs, np.maximum, np.minimum, np.where
    any, all, clip, interp = staticmethod(_any), staticmethod(_all), staticmethod(_clip), staticmethod(np.interp)
    errstate = np.errstate

    @staticmethod
    def asarray(v):
        return np.asarray(v, dtype=float)

    @staticmethod
    def like(a, v):
        return np.full(np.shape(a), v)


_NO_CONTEXT = contextlib.nullcontext()     # reusable: it holds nothing


def _where(cond, a, b):
    return a if cond else b


def _interp(x, xs, ys):
    """numpy.interp of one number (its arithmetic: the end values outside, slope·(x − x_j) + y_j inside)."""
    if x <= xs[0]:
        return ys[0]
    for j in range(1, len(xs)):
        if x < xs[j]:
            return (ys[j] - ys[j - 1]) / (xs[j] - xs[j - 1]) * (x - xs[j - 1]) + ys[j - 1]
    return ys[-1]


class FloatOps:
    """:mod:`math` functions for one design in Python floats: the same formulas as :class:`ArrayOps`."""
    sin, cos, tan, sqrt, cbrt, arccos, exp, exp2, log = math.sin, math.cos, math.tan, math.sqrt, math.cbrt, \
        math.acos, math.exp, staticmethod(lambda v: 2.0 ** v), math.log
    radians, degrees, abs, maximum, minimum = math.radians, math.degrees, abs, max, min
    where, interp = staticmethod(_where), staticmethod(_interp)
    any = all = staticmethod(bool)
    errstate = staticmethod(lambda **kw: _NO_CONTEXT)    # math raises instead of warning

    @staticmethod
    def clip(v, lo, hi):
        return min(max(v, lo), hi)

    asarray = float          # of a Python float: itself (a builtin call, no Python frame)

    @staticmethod
    def like(a, v):
        return v


def _mixed(f_float, f_array):
    """One argument: ``f_float`` of a Python float, ``f_array`` of anything else."""
    return staticmethod(lambda v: f_float(v) if type(v) is float else f_array(v))


def _mixed2(f_float, f_array):
    """Two arguments: ``f_float`` of two Python floats, ``f_array`` where either is anything else."""
    return staticmethod(lambda a, b: f_float(a, b) if type(a) is float and type(b) is float else f_array(a, b))


class MixedOps:
    """One design in Python floats carrying arrays of load cases (the bins of a load spectrum, whose torque and speed
    are arrays): each operation on :mod:`math` where its operands are Python floats (the design's geometry and the
    factors of the pair alone), on numpy where one is an array (the load-dependent factors and stresses). A
    formula called from the chain picks its own with :func:`ops_of`, by the same rule."""
    sin, cos, tan, sqrt = _mixed(math.sin, np.sin), _mixed(math.cos, np.cos), _mixed(math.tan, np.tan), \
        _mixed(math.sqrt, np.sqrt)
    cbrt, arccos, exp, log = _mixed(math.cbrt, np.cbrt), _mixed(math.acos, np.arccos), _mixed(math.exp, np.exp), \
        _mixed(math.log, np.log)
    exp2 = _mixed(lambda v: 2.0 ** v, np.exp2)
    radians, degrees, abs = _mixed(math.radians, np.radians), _mixed(math.degrees, np.degrees), _mixed(abs, np.abs)
    maximum, minimum = _mixed2(max, np.maximum), _mixed2(min, np.minimum)
    any = staticmethod(lambda a: bool(a) if type(a) is bool else _any(a))
    all = staticmethod(lambda a: bool(a) if type(a) is bool else _all(a))
    errstate = np.errstate          # the arrays' warnings (math raises instead)

    @staticmethod
    def where(cond, a, b):
        return (a if cond else b) if type(cond) is bool else np.where(cond, a, b)

    @staticmethod
    def clip(v, lo, hi):
        return min(max(v, lo), hi) if type(v) is float and type(lo) is float and type(hi) is float else \
            _clip(v, lo, hi)

    @staticmethod
    def interp(x, xs, ys):
        return _interp(x, xs, ys) if type(x) is float else np.interp(x, xs, ys)

    @staticmethod
    def asarray(v):
        return float(v) if type(v) is float or type(v) is int else np.asarray(v, dtype=float)

    @staticmethod
    def like(a, v):
        return v if type(a) is float else np.full(np.shape(a), v)


def ops_of(*values):
    """:class:`FloatOps` when every value is a Python float (the one-design path), else :class:`ArrayOps`.

    >>> ops_of(1.0, 2.0) is FloatOps, ops_of(1.0, [2.0]) is ArrayOps, ops_of(1) is ArrayOps
    (True, True, True)
    """
    for v in values:
        if type(v) is not float:
            return ArrayOps
    return FloatOps


def checked(name, value, lo, hi, *, lo_open=False, hi_open=False, unit=""):
    """``value`` as a Python float when it is a Python float or int inside [lo, hi] (or the open ends asked for:
    the one-design path, no numpy), else :func:`~geardesign.validate.require_range` of it (the same refusal by
    name, and a float array).

    >>> checked("q_s", 2.5, 0.1, 50.0), checked("b", 40.0, 0.0, 1e5, lo_open=True)
    (2.5, 40.0)
    """
    t = type(value)
    if (t is float or t is int) and (lo < value if lo_open else lo <= value) and (
            value < hi if hi_open else value <= hi):
        return float(value)
    if t is np.ndarray and value.dtype == np.float64 and value.size:   # two reductions instead of four passes
        lo_v, hi_v = value.min(), value.max()                          # (NaN propagates: refused below)
        if (lo < lo_v if lo_open else lo <= lo_v) and (hi_v < hi if hi_open else hi_v <= hi):
            return value
    return require_range(name, value, lo, hi, lo_open=lo_open, hi_open=hi_open, unit=unit)


def once(memo: dict, key, compute, *args):
    """``compute(*args)`` the first time ``key`` is asked for, the stored value after: a factor both gears of a pair
    share (one material on both: Z_L, Z_v, Z_R by σ_Hlim, Y_RrelT, Y_X by kind).

    >>> memo = {}
    >>> once(memo, "Z_L", lambda: 1.05), once(memo, "Z_L", lambda: 2.0)
    (1.05, 1.05)
    """
    if key not in memo:
        memo[key] = compute(*args)
    return memo[key]


def per_load_case(factor, N_L, *args):
    """``factor(N_L, *args)``, a life factor (Z_NT, Y_NT) of N_L load cycles: once per load case when N_L is one
    number (the one-design path; the shift solvers and the sizing of a stage vary the design, not the cycles).

    >>> per_load_case(lambda n, k: n * k, 2.0, 3.0), per_load_case(lambda n, k: n * k, 2.0, 3.0)
    (6.0, 6.0)
    """
    return _cached_factor(factor, N_L, *args) if type(N_L) is float else factor(N_L, *args)


@functools.lru_cache(maxsize=1024)
def _cached_factor(factor, N_L, *args):
    return factor(N_L, *args)
