"""Issue 14's proof that the drawing checks the checks: interference simulated on generated gears.

The mate's tip corners (taken from the mate's generated profile) are carried through the mesh at the
operating centre distance, over four pitches of roll, into the frame of the gear under test; each
position is tested against that gear's generated material with the cutter's material test (a point is
material when no rack position ever reaches it — :mod:`geardesign.profiles.tooth`, no involute
formula). The analytic check ``interference1``/``interference2`` (ρ_p >= ρ_l) must fail exactly when a
corner enters the material, over a sweep of shifts within ±0.002·m and ±0.02·m of the boundary.
Non-undercut gears only: on an undercut gear the cutter has removed the involute's foot, and a tip
that starts contact there loses contact instead of entering material.
"""

import numpy as np
import pytest
from scipy.optimize import brentq

import geardesign as gd
from geardesign.gears.geometry import undercut_x_min
from geardesign.profiles.tooth import _Cutter

ROLLS = 1500          # positions over four pitches of the gear under test
TOUCH_MM = 1e-9       # deeper than this (m = 1 mm) counts as entering


def deepest_entry_mm(pair, gear):
    """How deep (mm) the mate's tip corners ever reach into ``gear``'s generated material (0: never)."""
    geo = pair._geo
    own, mate = (1, 2) if gear == 1 else (2, 1)
    z_own, z_mate = getattr(pair, f"z{own}"), getattr(pair, f"z{mate}")
    profile = gd.tooth_profile(pair.m, z_mate, getattr(pair, f"x{mate}"), rack=pair.rack,
                               tip_diameter_mm=float(geo[f"da{mate}"]), points=50)
    flank = profile.segment == "involute"
    cx, cy = profile.x_mm[flank][-1], profile.y_mm[flank][-1]      # the corner of a tooth on +y
    turns = 2 * np.pi * np.arange(z_mate) / z_mate
    corners = np.concatenate([np.column_stack([np.cos(turns) * sx * cx - np.sin(turns) * cy,
                                               np.sin(turns) * sx * cx + np.cos(turns) * cy]) for sx in (1, -1)])
    # the gear under test turns by −φ about the origin, the mate by π + π/z_mate + φ z_own/z_mate about
    # (0, a_w) (the placement of geardesign.profiles.mesh, with the gear under test as gear 1)
    pitch = 2 * np.pi / z_own
    phi = np.linspace(-2 * pitch, 2 * pitch, ROLLS)[:, None]
    t = np.pi + np.pi / z_mate + phi * z_own / z_mate
    mx = np.cos(t) * corners[:, 0] - np.sin(t) * corners[:, 1]
    my = np.sin(t) * corners[:, 0] + np.cos(t) * corners[:, 1] + float(geo["a_w"])
    gx, gy = np.cos(phi) * mx - np.sin(phi) * my, np.sin(phi) * mx + np.cos(phi) * my
    r = np.hypot(gx, gy)
    near = r < float(geo[f"da{own}"]) / 2
    # polar angle in the generation frame (a space centred on +y), folded onto one flank
    eta = np.pi / z_own - np.arctan2(gx[near], gy[near])
    eta = np.abs(np.mod(eta + np.pi / z_own, pitch) - np.pi / z_own)
    if not near.any():
        return 0.0
    cutter = _Cutter.of(pair.m, z_own, getattr(pair, f"x{own}"), pair.rack)
    return max(0.0, -float(cutter.max_depth(r[near], eta).min()))


def _margin(z1, z2, x1, x2, name):
    table = gd.GearPair(1.0, z1, z2, x1, x2).checks().set_index("check")
    return float(table.loc[name, "margin"])


CASES = [(12, 60, 1), (14, 40, 1), (10, 30, 1), (60, 12, 2)]


@pytest.mark.slow
@pytest.mark.parametrize("z1, z2, gear", CASES)
@pytest.mark.parametrize("target", [-0.02, -0.002, 0.002, 0.02])
def test_the_mates_tip_enters_the_fillet_exactly_when_interference_fails(z1, z2, gear, target):
    """Gear under test 0.05 above its undercut limit; the mate's shift chosen so the interference
    margin is ``target`` (in m); the simulated tip path enters the generated material iff margin < 0."""
    name = f"interference{gear}"
    own_x = float(undercut_x_min(z1 if gear == 1 else z2)) + 0.05
    if gear == 1:
        x1, x2 = own_x, brentq(lambda v: _margin(z1, z2, own_x, v, name) - target, -1.2, 0.5, xtol=1e-14)
    else:
        x1, x2 = brentq(lambda v: _margin(z1, z2, v, own_x, name) - target, -1.2, 0.5, xtol=1e-14), own_x
    pair = gd.GearPair(1.0, z1, z2, x1, x2)
    assert _margin(z1, z2, x1, x2, name) == pytest.approx(target, abs=1e-9)
    depth = deepest_entry_mm(pair, gear)
    assert (depth > TOUCH_MM) == (target < 0), (depth, target)
    if target < 0:   # the tip's way into the fillet deepens with the shortfall
        assert depth > 1e-7 * (abs(target) / 0.002) ** 2
