"""The involute function inv(α) = tan α − α and its inverse, exact to a few ulp.

All functions take and return radians (or the dimensionless tangent), broadcast over numpy
arrays, and return a Python float when every argument is a scalar.

Why not just ``tan(a) - a``: for small angles the two terms cancel (inv α ≈ α³/3), so the
plain difference loses ~log10(3/α²) digits. t − atan t (t = tan α) is therefore taken from a
tabled node c <= |t| and the short step |t| − c (the tangent subtraction formula, no
cancellation) below |t| = 8, the plain difference above, where it keeps all but ~3ε/t² of its
digits (each within 1e-15 relative of a 40-digit value, tested on −10 … 10). The table itself comes from the half-angle form
(:func:`_t_minus_atan`), which needs no table and ~55 array operations.
"""
from __future__ import annotations

import math

import numpy as np

from ..errors import GearDesignError

__all__ = ["inv", "inv_from_tan", "inv_inverse", "tan_from_inv"]

# s - atan(s) = s^3 * sum_k (-1)^k s^(2k) / (2k + 3); after three half-angle steps |s| <= tan(π/16)
# = 0.199, where 13 terms reach 1e-19.
_SERIES_COEF = tuple((-1.0) ** k / (2 * k + 3) for k in range(13))
_SERIES_HORNER = _SERIES_COEF[-2::-1]


def _scalar_out(value, *inputs):
    return float(value) if all(np.ndim(x) == 0 for x in inputs) else value


def _t_minus_atan(t, sqrt=np.sqrt):
    """t − atan t with no cancellation for any t (an array, or a float with ``sqrt=math.sqrt``).

    With the half-angle tangent s = t/(1 + √(1 + t²)) (atan t = 2 atan s),
    t − atan t = t³/(1 + √(1 + t²))² + 2 (s − atan s): both terms have the sign of t, so
    nothing cancels. Three steps bring |s| below tan(π/16), where the Taylor series of
    s − atan s converges fast.
    """
    acc = 0.0
    scale = 1.0
    s = t
    for _ in range(3):
        r = 1.0 + sqrt(1.0 + s * s)
        acc = acc + scale * (s * s * s) / (r * r)
        s = s / r
        scale *= 2.0
    s2 = s * s
    ser = _SERIES_COEF[-1]
    for c in _SERIES_HORNER:
        ser = ser * s2 + c
    return acc + scale * ser * s2 * s


# From the node c = ⌊32|t|⌋/32 below |t| < TABLE_T, whose c − atan c is tabled,
# t − atan t = (c − atan c) + c t u + (u − atan u), u = Δt/(1 + c t) < 1/32, Δt = t − c (exact):
# atan t − atan c = atan u is the tangent subtraction formula, the three terms have one sign (no
# cancellation), and u − atan u is six terms of its series (|u| < 1/32: 2e-19 relative). One path
# for every t below TABLE_T, no masks; above it the plain difference keeps all but ~3ε/t² of its
# digits. ~25 array operations where the half-angle form takes ~55.
_NODES_PER_UNIT = 32
TABLE_T = 8.0
_STEP_COEF = _SERIES_COEF[:6]
_STEP_HORNER = _STEP_COEF[-2::-1]
_NODE_INV = tuple(_t_minus_atan(k / _NODES_PER_UNIT, math.sqrt) if k else 0.0
                  for k in range(int(TABLE_T * _NODES_PER_UNIT)))
_NODE_INV_ARRAY = np.array(_NODE_INV)


def _from_node(a, k, node_inv):
    """a − atan a (0 <= a < TABLE_T) from its node k = ⌊32 a⌋ (node_inv its tabled value); arrays or floats."""
    c = k * (1.0 / _NODES_PER_UNIT)
    ca = c * a
    u = (a - c) / (1.0 + ca)
    u2 = u * u
    ser = _STEP_COEF[-1]
    for coef in _STEP_HORNER:
        ser = ser * u2 + coef
    return node_inv + ca * u + ser * u2 * u


def t_minus_atan_float(t: float) -> float:
    """:func:`t_minus_atan` for one Python float (the float path of the optimisers calls it ~5 times
    a design).

    >>> abs(t_minus_atan_float(0.7) - (0.7 - math.atan(0.7))) < 1e-16
    True
    """
    a = abs(t)
    if not a < TABLE_T:           # the plain difference (NaN and inf too)
        return t - math.atan(t)
    k = int(a * _NODES_PER_UNIT)
    v = _from_node(a, k, _NODE_INV[k])
    return v if t > 0 else -v


def t_minus_atan(t: np.ndarray) -> np.ndarray:
    """t − atan t for an array: the tabled node and its step (:func:`_from_node`) below TABLE_T,
    the plain difference above (and for NaN)."""
    t0 = np.asarray(t, dtype=float)
    t = t0.reshape(-1)
    if t.size == 0:
        return t0.copy()
    a = np.abs(t)
    beyond = not a.max() < TABLE_T   # NaN too
    if beyond:
        inside = a < TABLE_T
        a = np.where(inside, a, 0.0)
    k = (a * _NODES_PER_UNIT).astype(np.intp)
    out = _from_node(a, k, _NODE_INV_ARRAY.take(k))
    if beyond:
        with np.errstate(invalid="ignore"):
            out = np.where(inside, out, np.abs(t) - np.arctan(np.abs(t)))
    return np.copysign(out, t).reshape(t0.shape)


def inv_from_tan(t):
    """Involute function from the tangent of the angle: inv α = t − atan t, t = tan α.

    Used inside geometry, where tan α is what the geometry gives (tan α_a = √(r_a² − r_b²)/r_b),
    so no arccos of a number near 1 is ever taken.

    >>> round(inv_from_tan(np.tan(np.radians(20.0))), 12)
    0.014904383867
    """
    if type(t) is float:   # one number: without numpy's per-call cost
        return t_minus_atan_float(t)
    t = np.asarray(t, dtype=float)
    return _scalar_out(t_minus_atan(t), t)


def inv(alpha):
    """Involute function inv α = tan α − α, α in radians (ISO 21771:2007, eq. for inv α).

    Accurate to a few ulp for all α in [0, π/2), including α → 0 where inv α ≈ α³/3.

    >>> round(inv(np.radians(20.0)), 12)   # handbook value inv 20° = 0.014904
    0.014904383867
    >>> f"{inv(1e-6):.12e}"                # α³/3 + 2α⁵/15 (50-digit: 3.333333333334666e-19)
    '3.333333333335e-19'
    """
    if type(alpha) is float:   # one number: without numpy's per-call cost
        return t_minus_atan_float(math.tan(alpha))
    alpha = np.asarray(alpha, dtype=float)
    out = t_minus_atan(np.tan(alpha))
    return _scalar_out(out, alpha)


def tan_from_inv(v, *, validate: bool = True, polish: bool = True):
    """tan α of the angle whose involute is v (v > 0); the workhorse behind :func:`inv_inverse`.

    Newton's method on g(t) = t − atan t − v, which is convex and increasing for t > 0.
    The start t0 = s(1 + s²/5), s = (3v)^(1/3), is the series inverse for small v and
    t0 = w − 1/w, w = v + π/2 the asymptote for large v; three steps on the plain
    difference and a last one on the cancellation-free series reach 1 ulp for
    1e-12 <= v <= 10 (checked against 50-digit mpmath in the tests). Without ``polish`` the last
    step is left to the caller (as in :func:`_tan_from_inv_float`).
    """
    v_in = np.asarray(v, dtype=float)
    v = np.atleast_1d(v_in)
    if validate:
        bad = ~(v > 0) | ~np.isfinite(v)
        if bad.any():
            raise GearDesignError(
                f"involute value must be finite and > 0, got {v[bad][0]!r}")
    s = np.cbrt(3.0 * v)
    t = s * (1.0 + s * s / 5.0)
    if not v.max(initial=0.0) < 0.5:   # large involutes (and NaN): the asymptote start where needed
        w = v + np.pi / 2
        t = np.where(v < 0.5, t, w - 1.0 / w)
    for _ in range(3):
        t2 = t * t
        t = t - (t - np.arctan(t) - v) * (1.0 + t2) / t2
    if polish:
        t2 = t * t
        t = t - (t_minus_atan(t) - v) * (1.0 + t2) / t2
    return _scalar_out(t.reshape(v_in.shape), v_in)


def _tan_from_inv_float(v: float, polish: bool = True) -> float:
    """:func:`tan_from_inv` for one Python float (the single-design fast path of the optimisers).

    The same start and the same Newton steps; raises ValueError unless v > 0. Without
    ``polish`` the last, cancellation-free step is left to the caller (the operating angle
    refines tan α_w − tan α itself, which supersedes it).
    """
    if not v > 0.0:
        raise ValueError(f"involute value must be > 0, got {v!r}")
    if v < 0.5:
        s = (3.0 * v) ** (1.0 / 3.0)
        t = s * (1.0 + s * s / 5.0)
    else:
        w = v + math.pi / 2
        t = w - 1.0 / w
    for _ in range(3):
        t2 = t * t
        t = t - (t - math.atan(t) - v) * (1.0 + t2) / t2
    if not polish:
        return t
    t2 = t * t
    return t - (t_minus_atan_float(t) - v) * (1.0 + t2) / t2


def inv_inverse(v):
    """The angle α in radians (0 < α < π/2) with inv α = v, for v > 0.

    >>> round(float(np.degrees(inv_inverse(0.014904383867))), 9)
    20.0
    >>> v = inv(np.radians(20.0)) + 2 * 0.96 * np.tan(np.radians(20.0)) / 36  # KHK 12/24, x 0.6/0.36
    >>> round(float(np.degrees(inv_inverse(v))), 4)                           # KHK: α_w = 26.0886°
    26.0886
    """
    t = tan_from_inv(v)
    return _scalar_out(np.arctan(t), np.asarray(v))
