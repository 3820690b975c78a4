"""WormPair: every bad input refused by name with its value and range; the pair for a centre distance reproduces
it; the result's ways out (dict, JSON, table, summary); the exact x2 optimisation against its own definition (the
undercut limit in closed form, a dense scan of the smallest margin)."""
import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import geardesign as gd
from geardesign.gears.rack import BasicRack
from geardesign.gears.worm.geometry import WORM_FIELDS, worm_geometry
from geardesign.gears.worm.pair import WormGeometry, WormPair, WormShiftResult


@pytest.mark.parametrize("kwargs,words", [
    (dict(m_x=0, z1=1, z2=40, q=10), ["m_x", "> 0", "0"]),
    (dict(m_x=float("nan"), z1=1, z2=40, q=10), ["m_x", "finite"]),
    (dict(m_x=2, z1=0, z2=40, q=10), ["z1", "[1, 10]", "0"]),
    (dict(m_x=2, z1=11, z2=40, q=10), ["z1", "[1, 10]", "11"]),
    (dict(m_x=2, z1=1.5, z2=40, q=10), ["z1", "whole number", "1.5"]),
    (dict(m_x=2, z1=1, z2=2, q=10), ["z2", "2"]),
    (dict(m_x=2, z1=1, z2=40, q=2.5), ["q", "(2.5, 100]", "2.5"]),
    (dict(m_x=2, z1=1, z2=40, q=10, x2=11), ["x2", "[-10, 10]", "11"]),
    (dict(m_x=2, z1=1, z2=40, q=10, flank_form="ZX"), ["flank_form", "ZA", "'ZX'"]),
    (dict(m_x=2, z1=1, z2=40, q=10, rack="standard"), ["rack", "BasicRack", "'standard'"]),
    (dict(m_x=2, z1=1, z2=40, q=10, worm_length_mm=-1), ["worm_length_mm", "-1"]),
    (dict(m_x=[2, 3], z1=1, z2=40, q=10), ["m_x", "single number", "worm_geometry"]),
    (dict(m_x=2, z1=1, z2=20, q=10, x2=-3), ["x2 = -3", "too small"]),
    (dict(m_x=2, z1=1, z2=20, q=10, x2=6), ["x2 = 6", "too large", "does not mesh"]),
    (dict(m=2, z1=1, z2=40, q=10), ["no argument 'm'", "m_x=2"]),
    (dict(m_x=2, z1=1, z2=40, q=10, a=100), ["from_center_distance"]),
])
def test_bad_input_is_refused_by_name(kwargs, words):
    with pytest.raises(gd.GearDesignError) as info:
        WormPair(**kwargs)
    for w in words:
        assert w in str(info.value), (w, str(info.value))


def test_rack_parameters_are_settable_like_the_spur_pair():
    rack = BasicRack(alpha_deg=15.0, ha=0.9, c=0.2, rho_f=0.2)
    g = WormPair(5, 1, 40, 10, rack=rack, flank_form="ZN").geometry()
    assert g.alpha_n_deg == 15.0 and g.d_a1 == pytest.approx(5 * (10 + 1.8)) and g.d_f1 == pytest.approx(5 * (10 - 2.2))


@settings(max_examples=150, deadline=None)
@given(m_x=st.sampled_from([1.6, 2.5, 4.0, 6.3, 10.0]), z1=st.integers(1, 4), z2=st.integers(26, 80),
       q=st.sampled_from([8.0, 10.0, 12.5, 16.0]), x2=st.floats(-0.7, 0.7))
def test_from_center_distance_reproduces_it(m_x, z1, z2, q, x2):
    a = m_x * (q + z2 + 2 * x2) / 2
    p = WormPair.from_center_distance(a, m_x, z1, z2, q)
    assert p.geometry().a == pytest.approx(a, rel=1e-14, abs=1e-12)
    assert p.x2 == pytest.approx(x2, abs=1e-12)


def test_from_center_distance_out_of_reach_names_the_range():
    with pytest.raises(gd.GearDesignError, match=r"a \(center distance\) must be in \[30, 70\] mm for m_x = 2"):
        WormPair.from_center_distance(500, 2, 1, 40, 10)


def test_geometry_result_ways_out():
    g = WormPair(3, 2, 30, 44 / 3).geometry()
    assert isinstance(g, WormGeometry) and g.status == "success"
    d = g.to_dict()
    assert list(d)[1:-1] == list(WORM_FIELDS) and d["flank_form"] == "ZA"
    assert json.loads(g.to_json())["a"] == 67.0
    t = g.table()
    assert len(t) == len(WORM_FIELDS) and list(t.columns) == ["quantity", "symbol", "value", "unit", "field"]
    assert "a = 67 mm" in g.summary() and "z1/z2 = 2/30" in repr(g)
    with pytest.raises(AttributeError):
        g.no_such_field


def test_checks_table_and_ok():
    p = WormPair(3, 2, 30, 44 / 3)
    t = p.checks()
    assert list(t.columns) == ["check", "margin", "ok", "value", "limit", "label"]
    assert p.ok() and not p.ok(eps_alpha_min=2.5)


def test_measurements_for_the_drawing():
    m = WormPair(3, 2, 30, 44 / 3).measurements().set_index("symbol")
    gamma = math.atan(2 / (44 / 3))
    assert m.loc["s_x1", "value"] == pytest.approx(3 * math.pi / 2, rel=1e-15)
    assert m.loc["s_n1", "value"] == pytest.approx(3 * math.pi / 2 * math.cos(gamma), rel=1e-15)
    assert set(m.index) == {"s_x1", "s_n1", "s̄_1", "h̄_a1", "z_v2", "s̄_2", "h̄_a2"}


def test_min_abs_x2_is_the_undercut_limit_when_zero_undercuts():
    p = WormPair(4, 1, 16, 10)                 # x_min2 = 1.25 − 0.38(1 − sin 20°) − 16 sin²20°/2 = 0.0641
    a = math.radians(20)
    x_min = 1.25 - 0.38 * (1 - math.sin(a)) - 16 * math.sin(a) ** 2 / 2
    r = p.optimize_x2()
    assert isinstance(r, WormShiftResult) and r.success and r.method == "exact"
    assert r.x2 == pytest.approx(x_min, abs=1e-13)
    assert "undercut2" in r.active
    assert r.pair().geometry().a == pytest.approx(4 * (10 + 16 + 2 * x_min) / 2, rel=1e-14)


def test_x2_limits_are_where_the_margins_cross_zero():
    p = WormPair(4, 2, 30, 10)
    lo, hi = p.x2_limits(eps_alpha_min=1.5)
    for x2, name in ((lo, "undercut2"), (hi, "contact_ratio")):
        t = p.with_x2(x2).checks(eps_alpha_min=1.5).set_index("check")
        assert abs(float(np.asarray(t.loc[name, "value"])) - float(t.loc[name, "limit"])) < 1e-12


def test_max_margin_beats_a_dense_scan():
    p = WormPair(4, 2, 28, 10)
    r = p.optimize_x2("max_margin", sa_min=0.4)
    xs = np.linspace(-1.0, 1.0, 20001)
    g = worm_geometry(4.0, 2, 28, 10.0, xs)
    cs = gd.checks.make_checks(kind="worm", sa_min=0.4)
    moving = [c for c in cs if c.name in ("undercut2", "tip_thickness2", "contact_ratio", "x2_range")]
    scan = np.min([np.asarray(c.margin(g)) * np.ones_like(xs) for c in moving], axis=0)
    assert r.success and r.fun >= scan.max() - 1e-12 and r.fun <= scan.max() + 1e-4
    assert repr(r).splitlines()[0].startswith("     message:")
    assert list(r.to_frame().columns) == ["check", "margin", "active"]


def test_no_feasible_x2_says_which_checks_conflict():
    r = WormPair(4, 1, 16, 10).optimize_x2(eps_alpha_min=1.9)
    assert not r.success and "contact_ratio" in r.conflict and "no x2 satisfies" in r.message
    assert r.to_dict()["status"] == "failed"


@settings(max_examples=60, deadline=None)
@given(z1=st.integers(1, 4), z2=st.integers(14, 90), q=st.sampled_from([6.3, 8.0, 10.0, 12.5, 16.0, 20.0]),
       eps_min=st.floats(1.0, 1.8), sa_min=st.floats(0.0, 0.45))
def test_the_feasible_x2_interval_and_the_optimum_are_exact(z1, z2, q, eps_min, sa_min):
    p = WormPair(2.5, z1, z2, q)
    limits = dict(eps_alpha_min=eps_min, sa_min=sa_min)
    lo, hi = p.x2_limits(**limits)
    r = p.optimize_x2(**limits)
    xs = np.linspace(-1.0, 1.0, 2001)
    g = worm_geometry(2.5, z1, z2, q, xs, validate=False)
    cs = gd.checks.make_checks(kind="worm", **limits)
    ok = np.all([np.nan_to_num(np.asarray(c.margin(g), float) * np.ones_like(xs), nan=-1.0) >= -1e-12 for c in cs],
                axis=0)
    if not math.isfinite(lo):
        assert not ok.any() and not r.success
        return
    assert r.success and lo - 1e-12 <= r.x2 <= hi + 1e-12
    inside = (xs > lo + 1e-9) & (xs < hi - 1e-9)
    outside = (xs < lo - 1e-9) | (xs > hi + 1e-9)
    assert ok[inside].all() and not ok[outside].any()
    # the x2 nearest 0 in the interval: no scanned feasible x2 is nearer
    assert abs(r.x2) <= np.abs(xs[ok]).min() + 1e-12


def test_from_center_distance_refuses_an_array_of_teeth_by_name():
    """Fuzzing found a TypeError traceback for z2 given as an (empty) array."""
    for z2 in (np.array([]), [30, 31]):
        with pytest.raises(gd.GearDesignError, match="z2 must be one number"):
            WormPair.from_center_distance(67, 3, 2, z2, 44 / 3)
