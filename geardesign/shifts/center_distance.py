"""A housing's centre distance on the shift plane: the a_w a pair can reach, and the x-sum it fixes."""
from __future__ import annotations

from ..errors import GearDesignError
from ..gears.geometry import center_distance_from_x_sum, min_center_distance, x_sum_from_center_distance
from ..gears.involute import inv
from ..validate import one_number, require_positive
from .problem import DEFAULT_BOUNDS, Problem

__all__ = ["reachable_center_distance", "x_sum_for_housing"]


def _kind(prob: Problem) -> dict:
    return dict(beta_deg=prob.mesh.beta_deg, internal=prob.mesh.internal)


def x_sum_window(prob: Problem, bounds=DEFAULT_BOUNDS) -> tuple[float, float]:
    """The x_Σ that x1, x2 within ``bounds`` reach: [2 lo, 2 hi] for x1 + x2, [lo − hi, hi − lo]
    for a ring pair's x2 − x1."""
    lo, hi = bounds
    return (lo - hi, hi - lo) if prob.mesh.internal else (2 * lo, 2 * hi)


def reachable_center_distance(prob: Problem, bounds=DEFAULT_BOUNDS) -> tuple[float, float]:
    """(a_w min, a_w max) in mm that x_Σ within ``bounds`` can give this pair (see
    :func:`x_sum_window`), above the x_Σ where inv α_w = 0 (a_w = a cos α_t)."""
    xs_lo, xs_hi = x_sum_window(prob, bounds)
    sc = prob.mesh.section
    zs = prob.z2 - prob.z1 if prob.mesh.internal else prob.z1 + prob.z2
    xs_zero = -zs * inv(sc.alpha_t) / (2.0 * sc.tan_n)
    a_cos = float(min_center_distance(prob.m, prob.z1, prob.z2, prob.rack, **_kind(prob)))
    a_lo = a_cos if xs_lo <= xs_zero else center_distance_from_x_sum(prob.m, prob.z1, prob.z2, xs_lo, prob.rack,
                                                                     **_kind(prob))
    a_hi = center_distance_from_x_sum(prob.m, prob.z1, prob.z2, xs_hi, prob.rack,
                                      **_kind(prob)) if xs_hi > xs_zero else a_cos
    return float(a_lo), float(a_hi)


def x_sum_for_housing(prob: Problem, a_w, bounds=DEFAULT_BOUNDS) -> float:
    """The x-sum of a housing centre distance ``a_w`` (mm), or one line naming the range of a_w
    this pair, module, rack and window can reach."""
    a_w = one_number("a_w (center distance)", require_positive("a_w (center distance)", a_w, unit="mm"))
    a_lo, a_hi = reachable_center_distance(prob, bounds)
    r = prob.rack
    where = (f"for m = {prob.m:g} mm, z1/z2 = {prob.z1}/{prob.z2}, rack {r.alpha_deg:g} deg, "
             f"x1, x2 in [{bounds[0]:g}, {bounds[1]:g}]")
    if not a_lo < a_w <= a_hi:
        raise GearDesignError(f"a_w (center distance) = {a_w:.10g} mm is out of reach: it must be in "
                              f"({a_lo:.8g}, {a_hi:.8g}] mm {where}")
    x_sum = float(x_sum_from_center_distance(prob.m, prob.z1, prob.z2, a_w, prob.rack, **_kind(prob)))
    # inside its window the fixed-x_Σ line meets the square of x1, x2
    xs_lo, xs_hi = x_sum_window(prob, bounds)
    return min(max(x_sum, xs_lo), xs_hi)
