"""The generated tooth profile against the analytic geometry: two independent models of one gear.

The profile comes from simulating the rack cutter (law of gearing, no involute formula); the
geometry from ISO 21771 formulas. Each test compares a quantity both give."""
import math

import numpy as np
import pytest

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears.geometry import undercut_x_min
from geardesign.profiles.tooth import tooth_profile

CASES = [(8.0, 17, 0.898, gd.BasicRack()), (3.0, 12, 0.6, gd.BasicRack()), (2.0, 30, -0.2, gd.BasicRack()),
         (1.0, 60, 0.0, gd.BasicRack()), (0.5, 25, 0.3, gd.BasicRack(alpha_deg=25.0, ha=1.0, c=0.25, rho_f=0.3)),
         (5.0, 40, -0.1, gd.BasicRack(alpha_deg=14.5, ha=1.0, c=0.25, rho_f=0.2))]


def _involute_angle(r_mm, m, z, x, alpha):
    """Polar angle of the right flank from the tooth's centre line, written out here:
    s/d + inv α − inv α_y with cos α_y = r_b/r (the textbook involute of the base circle)."""
    r_b = m * z / 2 * math.cos(alpha)
    a_y = np.arccos(r_b / r_mm)
    return math.pi / (2 * z) + 2 * x * math.tan(alpha) / z + (math.tan(alpha) - alpha) - (np.tan(a_y) - a_y)


@pytest.mark.parametrize("m, z, x, rack", CASES)
def test_generated_flank_is_the_involute(m, z, x, rack):
    p = tooth_profile(m, z, x, rack=rack, points=300)
    sel = p.segment == "involute"
    r = np.hypot(p.x_mm[sel], p.y_mm[sel])
    eta = np.arctan2(p.x_mm[sel], p.y_mm[sel])
    assert np.max(np.abs(eta - _involute_angle(r, m, z, x, rack.alpha)) * r) <= 1e-9 * m


@pytest.mark.parametrize("m, z, x, rack", CASES)
def test_tip_thickness_form_and_root_circles_match_the_geometry(m, z, x, rack):
    p = tooth_profile(m, z, x, rack=rack)
    g = gd.pair_geometry(m, z, 200, x, 0.0, rack=rack, tip_shortening=False)
    assert p.tip_thickness_mm == pytest.approx(g.sa1, abs=1e-9 * m)
    assert 2 * p.r_form_mm == pytest.approx(g.d_l1, abs=1e-6 * m)
    root = p.segment == "root"
    assert np.hypot(p.x_mm[root], p.y_mm[root]) == pytest.approx(g.df1 / 2, abs=1e-9 * m)


def test_outline_is_symmetric_and_spans_one_pitch():
    p = tooth_profile(8, 17, 0.898)
    xs, ys = p.outline()
    assert np.arctan2(xs[-1], ys[-1]) == pytest.approx(math.pi / 17, abs=1e-12)
    assert np.allclose(xs, -xs[::-1], atol=1e-12) and np.allclose(ys, ys[::-1], atol=1e-12)
    assert list(p.to_frame().columns) == ["x_mm", "y_mm", "segment"]


@pytest.mark.slow
@pytest.mark.parametrize("z", [8, 10, 12, 14, 17, 25, 40])
def test_profile_is_undercut_exactly_below_the_undercut_limit(z):
    """Material test: the cutter removes involute just above the base circle exactly where the
    undercut check's x_min (h_l* − z sin²α/2) says, over a sweep of x around it."""
    x_min = float(undercut_x_min(z))
    for dx in (-0.2, -0.01, -1e-3, 1e-3, 0.01, 0.2):
        assert tooth_profile(2, z, x_min + dx, points=60).undercut == (dx < 0), dx


@pytest.mark.parametrize("m, z, x", [(2.0, 10, 0.0), (2.0, 8, -0.2), (1.0, 14, -0.3)])
def test_undercut_profile_keeps_the_involute_above_the_cut_and_less_below(m, z, x):
    p = tooth_profile(m, z, x, points=120)
    alpha = math.radians(20.0)
    r_b = m * z / 2 * math.cos(alpha)
    assert p.undercut and p.r_form_mm > r_b
    inv = p.segment == "involute"
    r = np.hypot(p.x_mm[inv], p.y_mm[inv])
    assert np.max(np.abs(np.arctan2(p.x_mm[inv], p.y_mm[inv]) - _involute_angle(r, m, z, x, alpha)) * r) <= 1e-9 * m
    cut = (p.segment == "fillet") & (np.hypot(p.x_mm, p.y_mm) > r_b)
    rc = np.hypot(p.x_mm[cut], p.y_mm[cut])
    # where the cutter reaches above the base circle the tooth is thinner than the involute
    assert np.all(np.arctan2(p.x_mm[cut], p.y_mm[cut]) <= _involute_angle(rc, m, z, x, alpha) + 1e-12)
    g = gd.pair_geometry(m, z, 200, x, 0.0, tip_shortening=False)
    assert p.tip_thickness_mm == pytest.approx(g.sa1, abs=1e-9 * m)


def test_inputs_refused_by_name():
    with pytest.raises(GearDesignError, match=r"points must be a whole number in \[8, 20000\]"):
        tooth_profile(2, 20, 0.0, points=10**9)
    with pytest.raises(GearDesignError, match="tip circle .* inside the base circle"):
        tooth_profile(2, 20, 0.0, tip_diameter_mm=30.0)
