"""The operating angle once per distinct x-sum: a grid of (x1, x2) takes ~2n x-sums over n² nodes, so the
vectorised geometry computes it per diagonal (exact when the nodes' sums are exact, :func:`exact_sum_nodes`)
or per hashed distinct value of a large batch that repeats itself; a ring's cutter mesh once per distinct x2
(:func:`distinct_codes`)."""
from __future__ import annotations

import functools
import math

import numpy as np

__all__ = ["per_distinct", "distinct_codes", "exact_sum_nodes"]


_PROBE = 1024   # values looked at before deduplicating: a grid block repeats its x-sums within them
# Below this many values the hashing costs more than it saves (a 31 × 31 start grid: 200 µs
# against 70 µs for every value's own operating angle); smaller grids are recognised by their shape
_DEDUPE_MIN = 4096
_SHAPED_MIN = 64


@functools.lru_cache(maxsize=8)
def _grid_patterns(n: int) -> tuple:
    """For an n × n grid flattened row by row: the index of each node's x-sum diagonal (i + j), of its
    x-difference diagonal (j − i + n − 1) and of its column j (x2 of a grid whose x2 runs along the rows),
    each with the node that carries its value first."""
    i, j = np.divmod(np.arange(n * n), n)
    first_sum = np.concatenate((np.arange(n), np.arange(2, n + 1) * n - 1))      # row 0, then column n − 1
    first_diff = np.concatenate((np.arange(n - 1, 0, -1) * n, np.arange(n)))   # column 0 upwards, then row 0
    return (i + j, first_sum), (j - i + n - 1, first_diff), (j, np.arange(n))


def _grid_codes(v):
    """(codes, first) with flat[first][codes] == flat (flat = v flattened) when v is constant or a flattened
    square grid constant along its diagonals, anti-diagonals (the x-sums of :func:`exact_sum_nodes` grids, an
    external or an internal pair's) or columns, else None."""
    flat = v.reshape(-1)
    if flat[0] == flat[-1] and (flat == flat[0]).all():   # a fixed-x_Σ line
        return np.zeros(flat.size, dtype=np.intp), np.zeros(1, dtype=np.intp)
    n = math.isqrt(flat.size)
    if n * n == flat.size:
        for codes, first in _grid_patterns(n):
            if (flat[first][codes] == flat).all():
                return codes, first
    return None


def distinct_codes(v):
    """(codes, first) with flat[first][codes] == flat (flat = v flattened, ``first`` the index of each
    distinct value's first node) when v repeats its values enough to gain from computing once per value:
    a square grid's diagonals or columns (:func:`_grid_codes`), else by sorting when a probe of v repeats
    itself; None otherwise (or for fewer than 64 values)."""
    if v.size < _SHAPED_MIN:
        return None
    found = _grid_codes(v)
    if found is not None:
        return found
    flat = v.reshape(-1)
    probe = flat[:_PROBE]
    if 4 * np.unique(probe).size > probe.size:
        return None
    _, first, codes = np.unique(flat, return_index=True, return_inverse=True)
    return (codes.reshape(-1), first) if 4 * first.size <= flat.size else None


def per_distinct(func, v):
    """func(v) for an array v, evaluated once per distinct value when v repeats a lot: on a
    grid of (x1, x2) the operating angle depends on x1 + x2 alone, which takes ~2n of n² values
    (bitwise equal only when the nodes' sums are exact: :func:`exact_sum_nodes`). Each value gets
    exactly what it would get alone, whatever its neighbours."""
    if _SHAPED_MIN <= v.size < _DEDUPE_MIN:
        found = _grid_codes(v)
        if found is not None:
            codes, first = found
            return tuple(r[codes].reshape(v.shape) for r in func(v.reshape(-1)[first]))
    elif v.size >= _DEDUPE_MIN:
        probe = v.reshape(-1)[:_PROBE]   # a grid repeats its x-sums at once; scattered designs do not,
        if 4 * np.unique(probe).size <= probe.size:   # and then the deduplication would be wasted
            import pandas as pd     # factorize hashes (O(n)); np.unique sorts, 4x slower here

            codes, distinct = pd.factorize(v.reshape(-1), use_na_sentinel=False)   # NaN a value too
            if 4 * distinct.size <= v.size:
                return tuple(r[codes].reshape(v.shape) for r in func(np.asarray(distinct, dtype=float)))
    return func(v)


def exact_sum_nodes(lo: float, hi: float, n: int) -> np.ndarray:
    """``n`` nodes in [lo, hi], the ends within n·2⁻⁴⁰ of lo and hi, on multiples of 2⁻⁴⁰, so that every sum and
    difference of two nodes is exact: the x-sums of a grid's nodes are then bitwise equal along
    each diagonal, and the operating angle is computed once per diagonal (:func:`per_distinct`).

    >>> g = exact_sum_nodes(-1.5, 3.0, 41)
    >>> bool(g[1] + g[3] == g[2] + g[2]), bool(abs(g[-1] - 3.0) < 1e-10)
    (True, True)
    """
    unit = 2.0 ** -40
    first = math.ceil(lo / unit) * unit
    step = math.floor((hi - first) / max(n - 1, 1) / unit) * unit
    return first + step * np.arange(n)
