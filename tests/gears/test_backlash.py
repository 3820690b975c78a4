"""Backlash (geardesign.gears.backlash): published examples, the free turn of generated gears, properties,
the GOST 1643-81 table, errors."""
import csv
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq, minimize_scalar

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears.backlash import (allowances_for_backlash, backlash_from_shifts, gost1643_jn_min,
                                       pair_backlash, x_sum_for_backlash)
from geardesign.gears.measurement_formulas import generating_shift
from geardesign.profiles.tooth import _Cutter, transverse_rack

DATA = Path(__file__).parent.parent / "data" / "backlash_examples.csv"


def examples():
    with DATA.open(encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


@pytest.mark.parametrize("row", [r for r in examples() if r["quantity"] == "x_sum_generating"],
                         ids=lambda r: r["example_id"])
def test_generating_shift_sum_for_a_backlash_published(row):
    got = x_sum_for_backlash(float(row["m_n"]), int(row["z1"]), int(row["z2"]), float(row["a_w_mm"]),
                             float(row["backlash_mm"]), row["kind"], beta_deg=float(row["beta_deg"]))
    assert round(got, int(row["digits"])) == float(row["published_value"])


def test_drivetrainhub_shift_reduction_and_the_two_kinds():
    row = [r for r in examples() if r["quantity"] == "x_mod_backlash"][0]
    zero = x_sum_for_backlash(2.5, 47, 50, 122.0, 0.0)
    with_j = x_sum_for_backlash(2.5, 47, 50, 122.0, 0.1, "jt")
    assert round(with_j - zero, 3) == float(row["published_value"])
    # circular (tan) and normal (sin) readings of one number differ by cos α_n exactly
    jn = x_sum_for_backlash(2.5, 47, 50, 122.0, 0.1, "jn") - zero
    jbn = x_sum_for_backlash(2.5, 47, 50, 122.0, 0.1, "jbn") - zero
    assert jn / jbn == pytest.approx(math.cos(math.radians(20)), rel=1e-12)


# --- the free turn of the generated gears ---------------------------------------------------------------------


def _flank(m_t, z, x_t, rack_t, d_a):
    cut = _Cutter.of(m_t, z, x_t, rack_t)
    lo = min(cut.s_form(), cut.r * math.sin(cut.alpha))
    hi = float(cut.s_at_radius(d_a / 2.0))
    return cut, (min(lo, hi), max(lo, hi))


def free_turn(pair, x1e, x2e, a_mm):
    """Half the angle gear 1 turns, gear 2 held, until its generated right flank touches gear 2's generated flank
    (the gears placed as geardesign.profiles.mesh.placed puts them: a tooth of gear 1 and a space of gear 2 on
    the line of centres, so the turn is the same both ways). The touch: the deepest point of gear 1's flank in
    gear 2's tooth (polar angle against the generated flank's at that radius) reaches zero."""
    rack_t, cb = transverse_rack(pair.rack, pair.beta_deg)
    geo = pair.geometry()
    c1, b1 = _flank(pair.m / cb, pair.z1, x1e * cb, rack_t, geo.da1)
    c2, _ = _flank(pair.m / cb, pair.z2, x2e * cb, rack_t, geo.da2)
    r_lo2, r_hi2 = math.hypot(*np.ravel(c2.flank(np.array([min(c2.s_form(), c2.r * math.sin(c2.alpha))])))), geo.da2 / 2
    centre = math.pi - math.pi / pair.z2        # gear 2's tooth right of the space, from +y toward +x

    def depth(theta):
        c, s = math.cos(theta), math.sin(theta)

        def inside(u):
            px, py = np.ravel(c1.flank(np.array([u])))
            qx, qy = c * px + s * py, -s * px + c * py - a_mm        # turned clockwise, from gear 2's centre
            r2 = math.hypot(qx, qy)
            if not r_lo2 < r2 < r_hi2:
                return -1.0
            fx, fy = np.ravel(c2.flank(c2.s_at_radius(np.array([r2]))))
            return r2 * (math.atan2(fx, fy) - abs(math.atan2(qx, qy) - centre))
        r = minimize_scalar(lambda u: -inside(u), bounds=b1, method="bounded", options={"xatol": 1e-14})
        return -r.fun

    return brentq(depth, 0.0, 0.05, xtol=1e-16, rtol=1e-15)   # backlash turns are thousandths of a radian


@pytest.mark.parametrize("pair, a1, a2, da", [
    (gd.GearPair(3, 12, 24, 0.6, 0.36), -0.05, -0.08, 0.0),
    (gd.GearPair(2, 17, 40, 0.2, -0.1), -0.03, -0.03, 0.04),
    (gd.GearPair(2.5, 21, 33, 0.3, 0.1, beta_deg=15), -0.04, -0.06, -0.02),
])
def test_backlash_equals_the_free_turn_of_the_generated_gears(pair, a1, a2, da):
    x1e, x2e = generating_shift(pair.x1, a1, pair.m, pair.rack.alpha), generating_shift(pair.x2, a2, pair.m, pair.rack.alpha)
    a = float(pair.geometry().a_w) + da
    theta = free_turn(pair, x1e, x2e, a)
    j = backlash_from_shifts(pair.m, pair.z1, pair.z2, x1e, x2e, a, pair.rack, pair.beta_deg)
    r_b1 = float(pair.geometry().db1) / 2
    assert abs(2 * theta * r_b1 - j["jbt"]) < 1e-9 * pair.m
    # the pair's own least backlash is this one when its allowances and centre distance are these
    b = pair_backlash(pair, a1, a2, (da, da + 0.01))
    assert abs(b.jbt_min - j["jbt"]) < 1e-12


# --- properties -----------------------------------------------------------------------------------------------

pairs = st.tuples(st.floats(0.5, 10), st.integers(12, 60), st.integers(12, 120), st.floats(-0.3, 0.8),
                  st.floats(-0.3, 0.8), st.sampled_from([0.0, 12.0, 30.0]), st.booleans())


def _pair(p):
    m, z1, z2, x1, x2, beta, internal = p
    if internal:
        z2 = z1 + 12 + z2
    try:
        return gd.GearPair(m, z1, z2, x1, x2, beta_deg=beta, internal=internal)
    except GearDesignError:
        return None


@settings(max_examples=60, deadline=None)
@given(pairs)
def test_zero_allowances_give_zero_backlash_at_the_nominal_centre_distance(p):
    pair = _pair(p)
    if pair is None:
        return
    b = pair.backlash()
    for k in ("jt", "jbt", "jbn", "jn", "jr"):
        assert abs(getattr(b, k + "_min")) < 1e-9 * pair.m and abs(getattr(b, k + "_max")) < 1e-9 * pair.m


@settings(max_examples=60, deadline=None)
@given(pairs, st.floats(0.0, 0.1), st.floats(0.0, 0.1), st.floats(0.0, 0.05))
def test_backlash_grows_with_thinner_teeth_and_the_first_order_rule_holds(p, t1, t2, f):
    pair = _pair(p)
    if pair is None:
        return
    m = pair.m
    b = pair.backlash((-t1 * m, -2 * t1 * m), (-t2 * m, -2 * t2 * m), f * m)
    assert b.jbn_max >= b.jbn_min
    # thickness only: j_bn = −(A_sn1 + A_sn2) cos α_n exactly
    thick = pair.backlash(-t1 * m, -t2 * m, 0.0)
    assert abs(thick.jbn_min - (t1 + t2) * m * math.cos(pair.rack.alpha)) < 1e-10 * m
    assert abs(thick.jn_min - (t1 + t2) * m) < 1e-10 * m


def test_internal_pair_backlash_closes_as_the_centre_distance_grows():
    p = gd.GearPair(2, 20, 60, 0.3, 0.6, internal=True)
    x1, x2 = p.x1, p.x2
    a = float(p.geometry().a_w)
    assert backlash_from_shifts(2, 20, 60, x1, x2, a + 0.01, internal=True)["jbn"] < 0
    assert backlash_from_shifts(2, 20, 60, x1, x2, a - 0.01, internal=True)["jbn"] > 0


def test_allowances_for_a_wanted_backlash_round_trip():
    p = gd.GearPair(2.5, 21, 33, 0.3, 0.1, beta_deg=15)
    a = allowances_for_backlash(p, 0.08, 0.03, share1=0.3, thickness_tolerance_mm=(0.04, 0.05))
    assert a["backlash"].jbn_min == pytest.approx(0.08, abs=1e-12)
    assert a["a_sne1"] / a["a_sne2"] == pytest.approx(0.3 / 0.7)


# --- GOST 1643-81 ---------------------------------------------------------------------------------------------

# ISO 286-1 IT7, IT8, IT9 rows (µm) for nominal sizes 50-80, 80-120, 120-180, 180-250, 250-315, 315-400, 400-500 mm,
# as tabulated in public ISO 286 code (find_string/search: "ISO 286 Standard Tolerance Database", IT_GRADES); IT10,
# IT11 from ISO 286-1:2010 Table 1
IT = {"E": [30, 35, 40, 46, 52, 57, 63], "D": [46, 54, 63, 72, 81, 89, 97], "C": [74, 87, 100, 115, 130, 140, 155],
      "B": [120, 140, 160, 185, 210, 230, 250], "A": [190, 220, 250, 290, 320, 360, 400]}


@pytest.mark.parametrize("kind", list(IT))
def test_gost1643_least_backlash_is_the_it_grade_of_the_centre_distance(kind):
    a = [80, 125, 180, 250, 315, 400, 500]
    assert [round(v * 1000) for v in gost1643_jn_min(kind, a)] == IT[kind]
    assert gost1643_jn_min("H", 999) == 0.0


@pytest.mark.parametrize("call, word", [
    (lambda: gost1643_jn_min("F", 100), "mating_type"), (lambda: gost1643_jn_min("C", 4000), "a_w"),
    (lambda: x_sum_for_backlash(2, 20, 30, 60, 0.1, "j"), "kind"),
    (lambda: pair_backlash(gd.GearPair(2, 20, 30), (-0.2, -0.1)), "A_sni"),
    (lambda: pair_backlash(gd.GearPair(2, 20, 30), 0.0, 0.0, 5.0), "center_distance_allowance_mm"),
    (lambda: pair_backlash(gd.GearPair(2, 20, 30), "x"), "thickness_allowance1_mm"),
    (lambda: allowances_for_backlash(gd.GearPair(2, 20, 30), -0.1), "jbn_min_mm"),
    (lambda: backlash_from_shifts(2, 20, 30, 0, 0, 40.0), "a_mm"),
    (lambda: backlash_from_shifts(2, 20, 30, 0, 0, 5e-324), "a_mm"),
    (lambda: x_sum_for_backlash(2, 20, 30, 40.0, 0.1), "a_w"), (lambda: x_sum_for_backlash(2, 20, 30, 51, -0.1), "backlash_mm"),
    (lambda: x_sum_for_backlash(2, 2, 30, 51, 0.1), "z1"),
    (lambda: gd.GearPair(3, 12, 24).measurements(gear=True), "gear"),
])
def test_bad_input_is_one_clear_error(call, word):
    with pytest.raises(GearDesignError, match=word):
        call()


def ring_free_turn(pair, x1e, x2e, a_mm):
    """free_turn for an internal pair: the ring (ring_profile's shaper-cutter envelope) about (0, −a), a space on
    +y (as geardesign.profiles.mesh.placed puts it); gear 1's right flank meets the left flank of the ring tooth
    at π/z2. The ring flank's polar angle at a radius is found on the envelope by its cutter roll."""
    from geardesign.gears.ring import ShaperCutter
    from geardesign.profiles import ring as ring_mod

    rack = pair.rack
    geo = pair.geometry()
    c1, b1 = _flank(pair.m, pair.z1, x1e, rack, geo.da1)
    cut, t_a0, *_ = ring_mod._cutter_in_place(pair.m, pair.z2, x2e, geo.da2 / 2, ShaperCutter(), rack, rack.alpha,
                                              pair.m, 1.0)

    def ring_point(u):
        return np.ravel(ring_mod._mirror(pair.z2, *cut.envelope(*cut.flank(np.array([u])))))

    r_tip2, r_root2 = float(np.hypot(*ring_point(t_a0 * (1 - 1e-12)))), float(np.hypot(*ring_point(1e-9)))
    lo_r, hi_r = sorted((r_tip2, r_root2))

    def eta(r):
        u = brentq(lambda u: math.hypot(*ring_point(u)) - r, 1e-9, t_a0 * (1 - 1e-12), xtol=1e-15, rtol=1e-15)
        px, py = ring_point(u)
        return math.atan2(px, py)

    centre = math.pi / pair.z2

    def depth(theta):
        c, s = math.cos(theta), math.sin(theta)

        def inside(u):
            px, py = np.ravel(c1.flank(np.array([u])))
            qx, qy = c * px + s * py, -s * px + c * py + a_mm
            r2 = math.hypot(qx, qy)
            if not lo_r < r2 < hi_r:
                return -1.0
            return r2 * (eta(r2) - abs(math.atan2(qx, qy) - centre))
        r = minimize_scalar(lambda u: -inside(u), bounds=b1, method="bounded", options={"xatol": 1e-13})
        return -r.fun

    return brentq(depth, 0.0, 0.05, xtol=1e-16, rtol=1e-15)


def test_ring_pair_backlash_equals_the_free_turn_of_the_generated_gears():
    pair = gd.GearPair(2, 20, 60, 0.3, 0.6, internal=True)
    x1e = generating_shift(pair.x1, -0.04, pair.m, pair.rack.alpha)
    x2e = generating_shift(pair.x2, -0.05, pair.m, pair.rack.alpha, internal=True)
    a = float(pair.geometry().a_w) - 0.01
    theta = ring_free_turn(pair, x1e, x2e, a)
    j = backlash_from_shifts(pair.m, 20, 60, x1e, x2e, a, pair.rack, internal=True)
    assert abs(2 * theta * float(pair.geometry().db1) / 2 - j["jbt"]) < 1e-9 * pair.m


def _printed(quantity):
    rows = {r["quantity"]: r for r in csv.DictReader(
        (Path(__file__).parent.parent / "data" / "backlash_nrel_stage3_kisssoft.csv").open(encoding="utf-8"))}
    return tuple(float(v) for v in rows[quantity]["value"].split("/"))


def test_nrel_stage3_backlash_names_against_the_kisssoft_report():
    """docs/strength.md maps our backlash names onto a KISSsoft report's (issue 36 §2): checked here on the printed
    section 6 of the NREL 5 MW stage 3 report (tests/data/iso6336_nrel_stage3_kisssoft.md, "Backlash")."""
    mn, z1, z2, x1, x2, beta = 14.0, 24, 95, 0.48, 0.6691, 10.0
    A1, A2, Aa = _printed("A_sn1"), _printed("A_sn2"), _printed("A_a")
    b = gd.GearPair(mn, z1, z2, x1, x2, beta_deg=beta).backlash(A1, A2, (Aa[1], Aa[0]))
    # [jtw] is our jt, to the printed digits
    assert (round(b.jt_max, 3), round(b.jt_min, 3)) == _printed("j_tw")
    # [jnw] is jtw cos α_n cos β (DIN 3967's normal backlash; the printed jtw's 3 decimals are too few to carry it
    # to jnw's last digit, so our unrounded jt); our jbn (j_wt cos α'_wt cos β_b) is another quantity
    cos_n_b = math.cos(math.radians(20)) * math.cos(math.radians(beta))
    assert (round(b.jt_max * cos_n_b, 3), round(b.jt_min * cos_n_b, 3)) == _printed("j_nw")
    assert abs(b.jbn_max - _printed("j_nw")[0]) > 0.005
    # [jrw] is the exact closing of the centre distance: the zero-backlash centre distance of the thinned teeth,
    # written out here (ISO 21771 involute function), reproduces the printed aControl and jrw
    an = math.radians(20.0)
    at = math.atan(math.tan(an) / math.cos(math.radians(beta)))

    def inv(a):
        return math.tan(a) - a

    a_ref = mn * (z1 + z2) / (2 * math.cos(math.radians(beta)))

    def zero_backlash_centre(x_sum):
        alpha = brentq(lambda t: inv(t) - inv(at) - 2 * x_sum * math.tan(an) / (z1 + z2), 1e-6, 1.4, xtol=1e-15)
        return a_ref * math.cos(at) / math.cos(alpha)

    a_w = zero_backlash_centre(x1 + x2)
    a_control = [zero_backlash_centre(x1 + x2 + (s1 + s2) / (2 * mn * math.tan(an))) for s1, s2 in zip(A1, A2)]
    assert tuple(round(a, 3) for a in a_control) == _printed("a_control")
    jr_exact = (a_w + Aa[0] - a_control[1], a_w + Aa[1] - a_control[0])     # largest: thinnest teeth, A_a max
    assert tuple(round(j, 3) for j in jr_exact) == _printed("j_rw")
    # our jr is ISO/TR 10064-2's first-order j_wt/(2 tan α'_wt): within 2 µm of the exact one, not equal to it
    assert b.jr_max == pytest.approx(max(jr_exact), abs=2e-3) and round(b.jr_max, 3) != _printed("j_rw")[0]
    assert b.jr_min == pytest.approx(min(jr_exact), abs=2e-3)
