"""The manufactured state of a pair (issue 35 §4): its checks with the teeth thinned by their allowances and the
housing within its allowance, written out by hand here; the GOST 1643-81 allowances it assumes."""
from __future__ import annotations

import math

import pytest

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears.manufactured import ShopAllowances, manufactured_margins, shop_allowances


def test_zero_allowances_give_the_nominal_margins_by_another_formula():
    """At zero allowances the manufactured margins (ε_α and ρ_p from the tip radii and a' sin α'_wt, the
    involute thickness at the tip) equal the geometry's own (computed without cancellation another way)."""
    zero = ShopAllowances(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, "B", 0.0, "")
    for args, kw in (((3, 20, 61, 0.3, 0.2), {}), ((2.5, 17, 40, 0.5, -0.1), {"beta_deg": 12.0}),
                     ((4, 13, 90, 0.6, 0.4), {})):
        pair = gd.GearPair(*args, **kw)
        table = pair.checks(jamming=False)
        got = manufactured_margins(pair, table, zero)
        for name, margin in zip(table["check"], table["margin"]):
            assert got[name] == pytest.approx(float(margin), abs=1e-11), name


def test_the_manufactured_state_by_hand():
    """20/61 m 3, x 0.3/0.2, allowances A_sni = −0.2 mm, a' = a_w ± 0.05 mm: the margins written out."""
    pair = gd.GearPair(3, 20, 61, 0.3, 0.2)
    g = pair.geometry()
    table = pair.checks(jamming=False)
    allow = ShopAllowances(-0.05, 0.05, -0.1, -0.1, -0.2, -0.2, "B", 0.0, "")
    got = manufactured_margins(pair, table, allow)
    ra1, ra2, rb1, rb2 = g.da1 / 2, g.da2 / 2, g.db1 / 2, g.db2 / 2
    a_hi = g.a_w + 0.05
    w = math.acos((rb1 + rb2) / a_hi)
    pbt = math.pi * 3 * math.cos(math.radians(20))
    eps = (math.sqrt(ra1**2 - rb1**2) + math.sqrt(ra2**2 - rb2**2) - a_hi * math.sin(w)) / pbt
    assert got["contact_ratio"] == pytest.approx(eps - 1.2, abs=1e-12)
    x_e = 0.3 - 0.2 / (2 * 3 * math.tan(math.radians(20)))
    assert got["undercut1"] == pytest.approx(x_e - g.x_min1, abs=1e-12)
    # tip thickness: s_a = d_a (s/d + inv α − inv α_a) with s thinned by 0.2 mm
    d1 = 60.0
    s = 3 * (math.pi / 2 + 2 * 0.3 * math.tan(math.radians(20))) - 0.2
    aa = math.acos(rb1 / ra1)
    inv = lambda t: math.tan(t) - t
    sa = g.da1 * (s / d1 + inv(math.radians(20)) - inv(aa))
    assert got["tip_thickness1"] == pytest.approx(sa / 3 - 0.25, abs=1e-12)
    a_lo = g.a_w - 0.05
    w = math.acos((rb1 + rb2) / a_lo)
    rho_p1 = a_lo * math.sin(w) - math.sqrt(ra2**2 - rb2**2)
    assert got["interference1"] == pytest.approx((rho_p1 - max(g.rho_l1, 0)) / 3, abs=1e-12)


def test_shop_allowances_follow_gost1643_and_leave_its_least_backlash():
    pair = gd.GearPair(3, 20, 61, 0.3, 0.2)           # a_w 124.6 mm: GOST 1643 interval 80-125 mm
    a = shop_allowances(pair)
    assert a.jn_min_mm == pytest.approx(0.140)       # mating type B: 140 µm (Table 13)
    from geardesign.gears.backlash import pair_backlash

    b = pair_backlash(pair, a.a_sne1, a.a_sne2, (a.a_ai, a.a_ae))      # the least backlash they leave
    assert b.jbn_min == pytest.approx(0.140, abs=1e-9)
    assert a.a_sni1 == pytest.approx(2 * a.a_sne1) and a.a_sne1 < 0
    with pytest.raises(GearDesignError, match="mating_type"):
        shop_allowances(pair, "Z")


def test_given_allowances_are_taken_and_bad_ones_refused_by_name():
    pair = gd.GearPair(3, 20, 61, 0.3, 0.2)
    a = shop_allowances(pair, center_distance_allowance_mm=0.03, thickness_tolerance_mm=(0.05, 0.06))
    assert (a.a_ai, a.a_ae) == (-0.03, 0.03)                      # one number f: ±f, as pair_backlash reads it
    assert a.a_sne1 - a.a_sni1 == pytest.approx(0.05, abs=1e-15) and a.a_sne2 - a.a_sni2 == pytest.approx(0.06, abs=1e-15)
    with pytest.raises(GearDesignError, match="thickness_tolerance_mm must be in"):
        shop_allowances(pair, thickness_tolerance_mm=(-1, 0))
    with pytest.raises(GearDesignError, match="center_distance_allowance_mm"):
        shop_allowances(pair, center_distance_allowance_mm="wide")
