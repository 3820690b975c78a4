"""Both gears of a pair, generated and put in mesh: gear 1 about the origin, gear 2 about (0, a_w),
a tooth of gear 1 and a space of gear 2 on the line of centres (+y), so the teeth touch on both
flanks (zero backlash). ``roll_deg`` turns gear 1 by that angle and gear 2 the matching −roll·z1/z2.
"""
from __future__ import annotations

import math

from ..errors import GearDesignError
from ..validate import one_number, require_range
from .export import gear_outline, turned, write_outlines
from .tooth import tooth_profile

__all__ = ["pair_profiles", "pair_outlines", "export_profiles"]

ROLL_RANGE_DEG = (-3600.0, 3600.0)


def _require_pair(pair):
    if not hasattr(pair, "_geo") or not hasattr(pair, "z1"):
        raise GearDesignError(f"pair must be a GearPair, got {type(pair).__name__}")
    return pair


def pair_profiles(pair, points: int = 200) -> tuple:
    """The generated tooth profiles of both gears of a :class:`~geardesign.gears.pair.GearPair`, each
    cut at the pair's tip circle (so with the pair's tip shortening) and with the pair's rack."""
    pair = _require_pair(pair)
    geo = pair._geo
    return tuple(tooth_profile(pair.m, z, x, rack=pair.rack, tip_diameter_mm=float(geo[f"da{k}"]), points=points)
                 for k, z, x in ((1, pair.z1, pair.x1), (2, pair.z2, pair.x2)))


def pair_outlines(pair, roll_deg: float = 0.0, points: int = 200) -> list:
    """Both gears of a :class:`~geardesign.gears.pair.GearPair`, generated with the pair's tip circles,
    in mesh: ``[("gear1", x_mm, y_mm), ("gear2", x_mm, y_mm)]``, each closed."""
    pair = _require_pair(pair)
    roll = math.radians(one_number("roll_deg", require_range("roll_deg", roll_deg, *ROLL_RANGE_DEG, unit="°")))
    geo = pair._geo
    p1, p2 = pair_profiles(pair, points)
    x1, y1 = turned(*gear_outline(p1), -roll)
    x2, y2 = turned(*gear_outline(p2), math.pi + math.pi / pair.z2 + roll * pair.z1 / pair.z2)
    return [("gear1", x1, y1), ("gear2", x2, y2 + float(geo["a_w"]))]


def export_profiles(pair, path, overwrite: bool = False, roll_deg: float = 0.0, points: int = 200):
    """Both gears of a pair in mesh into one SVG, DXF or CSV file (by the suffix), in mm: two closed
    outlines named gear1 and gear2 (SVG path ids, DXF layers, the CSV's ``outline`` column).

    Returns the path written; an existing file is replaced only with ``overwrite``.
    """
    outlines = pair_outlines(pair, roll_deg, points)
    title = (f"m = {pair.m:g} mm, z1/z2 = {pair.z1}/{pair.z2}, x1/x2 = {pair.x1:.6g}/{pair.x2:.6g}, "
             f"a_w = {float(pair._geo['a_w']):.6g} mm (gear 1 about the origin, gear 2 about (0, a_w))")
    return write_outlines(outlines, path, overwrite, title, pair.m / 50)
