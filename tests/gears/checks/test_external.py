"""The checks of an external pair (geardesign.gears.checks.external) on KHK's worked example (z 12/24, m 3,
x 0.6/0.36: ε_α = 1.202, KHK Technical Data, the worked example pair_geometry's doctest cites) and each check's
value and limit computed here from the textbook formulas (ISO 21771:2007, GOST 16532-70)."""
import math

import pytest

import geardesign as gd
from geardesign.gears.checks import CenterDistance, ContactRatio, make_checks

ALPHA = math.radians(20.0)


def inv(a):
    return math.tan(a) - a


@pytest.fixture(scope="module")
def khk():
    pair = gd.GearPair(3, 12, 24, 0.6, 0.36)
    return pair, pair.geometry(), pair.checks().set_index("check")


def test_contact_ratio_is_the_printed_eps_alpha_against_its_limit(khk):
    _, _, t = khk
    assert t.loc["contact_ratio", "value"] == pytest.approx(1.202, abs=5e-4)      # KHK prints 1.202
    assert t.loc["contact_ratio", "margin"] == pytest.approx(t.loc["contact_ratio", "value"] - 1.2, abs=1e-15)


def test_undercut_limit_is_the_classic_x_min(khk):
    _, _, t = khk
    # x_min = h_a* − z sin²α / 2 (GOST 16532-70; the rack's fillet moves the limit by its h_l* − h_a*, 3e-5 here)
    for gear, z, x in ((1, 12, 0.6), (2, 24, 0.36)):
        row = t.loc[f"undercut{gear}"]
        assert row.value == x and row.limit == pytest.approx(1 - z * math.sin(ALPHA) ** 2 / 2, abs=5e-5)


def test_tip_thickness_is_the_involute_formula(khk):
    pair, g, t = khk
    for gear, z, x, da in ((1, 12, 0.6, g.da1), (2, 24, 0.36, g.da2)):
        db = 3 * z * math.cos(ALPHA)
        alpha_a = math.acos(db / da)
        # s_a = d_a (π/(2z) + 2 x tan α / z + inv α − inv α_a) (ISO 21771:2007, spur)
        s_a = da * (math.pi / (2 * z) + 2 * x * math.tan(ALPHA) / z + inv(ALPHA) - inv(alpha_a))
        row = t.loc[f"tip_thickness{gear}"]
        assert row.value == pytest.approx(s_a / 3, rel=1e-12) and row.limit == 0.25


def test_jamming_limit_is_the_distance_to_the_mates_interference_point(khk):
    _, g, t = khk
    # O2N1 = sqrt(r_b2² + (a_w sin α_w)²): N2N1 = a_w sin α_w along the line of action
    aw, alpha_w = g.a_w, math.radians(g.alpha_w_deg)
    rb1, rb2 = g.db1 / 2, g.db2 / 2
    assert t.loc["jamming1", "limit"] == pytest.approx(math.hypot(rb2, aw * math.sin(alpha_w)) / 3, rel=1e-12)
    assert t.loc["jamming1", "value"] == pytest.approx(g.da2 / 2 / 3, rel=1e-14)
    assert t.loc["jamming2", "limit"] == pytest.approx(math.hypot(rb1, aw * math.sin(alpha_w)) / 3, rel=1e-12)


def test_options_change_the_limits_and_the_center_distance_check():
    checks = {c.name: c for c in make_checks(sa_min=0.4, eps_alpha_min=1.1, undercut=False)}
    assert "undercut1" not in checks and checks["tip_thickness1"].limit == 0.4
    assert isinstance(checks["contact_ratio"], ContactRatio) and checks["contact_ratio"].limit == 1.1
    c = CenterDistance(limit=56.5, tol_mm=0.01)
    geo = {"a_w": 56.495, "_m": 3.0, "_sgn": 1}
    assert c.margin(geo) == pytest.approx((0.01 - 0.005) / 3.0, rel=1e-12)     # (tol − |a_w − a|)/m
