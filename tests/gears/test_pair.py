"""GearPair: bad input raises GearDesignError naming the input, its value and the allowed range;
the inverse from a centre distance; the housing check of proposed shifts (expected a_w from
the involute relations in mpmath, tests/mp_formulas.py)."""
import mpmath as mp
import pytest

import geardesign as gd

from tests.mp_formulas import a_w as _a_w


@pytest.mark.parametrize("kwargs,words", [
    (dict(m=0, z1=17, z2=26), ["m (module)", "0", "> 0"]),
    (dict(m=-1, z1=17, z2=26), ["m (module)", "-1"]),
    (dict(m=2, z1=2, z2=26), ["z1", "in [3, 100000]", "2"]),
    (dict(m=2, z1=17.5, z2=26), ["z1", "whole number", "17.5"]),
    (dict(m=2, z1=17, z2=26, x1=float("nan")), ["x1", "finite", "nan"]),
    (dict(m=float("inf"), z1=17, z2=26), ["m (module)", "finite"]),
    (dict(m=2, z1=17, z2=26, x1=-3, x2=-3), ["x1 + x2", "-6", "> -0.88"]),
    (dict(m=2, z1=40, z2=40, x1=-2.5, x2=2.6), ["x1 = -2.5", "tip circle", "base circle"]),
])
def test_bad_pair_input(kwargs, words):
    with pytest.raises(gd.GearDesignError) as info:
        gd.GearPair(**kwargs)
    assert isinstance(info.value, ValueError)
    for w in words:
        assert w in str(info.value), (w, str(info.value))


def test_center_distance_too_small():
    with pytest.raises(gd.GearDesignError, match="a_w = 40 mm is too small"):
        gd.GearPair.from_center_distance(2, 17, 34, 40.0)


def test_housing_check_of_proposed_shifts():
    # seed 000's shifts 0.898/0.517 give a_w = 181.60 mm; a 180 mm housing needs a smaller x-sum
    t = gd.GearPair(8, 17, 26, 0.898, 0.517).checks(housing_a_w=180).set_index("check")
    row = t.loc["center_distance"]
    assert row["value"] == pytest.approx(float(_a_w(8, 17, 26, 1.415)), rel=1e-13)
    assert not row["ok"]
    need = mp.findroot(lambda xs: _a_w(8, 17, 26, xs) - 180, mp.mpf(1))
    assert f"needs x1 + x2 = {float(need):.6g}" in row["label"]
    ok = gd.GearPair(8, 17, 26, 0.6, float(need) - 0.6).checks(housing_a_w=180).set_index("check")
    assert ok.loc["center_distance", "ok"]


def test_a_pair_whose_tips_do_not_overlap_is_refused_by_name():
    """z1 = z2 = 5, x1 = x2 = 2 on a 15° rack with tip shortening: the tips exist but the path of
    contact is negative. Independently, in mpmath: ρ_a1 + ρ_a2 < a_w sin α_w with the tips shortened
    by Δy·m (GOST 16532-70), so the tip circles do not overlap along the line of action."""
    mp.mp.dps = 40
    m, z, x, al = 1, 5, mp.mpf(2), mp.radians(15)
    a_w = _a_w(m, z, z, 2 * x, alpha_deg=15)
    aw = mp.acos(m * z * mp.cos(al) / a_w)          # a_w cos α_w = a cos α, a = m z (z1 = z2)
    dy = 2 * x - (a_w - m * z) / m
    r_a = m * z / mp.mpf(2) + (1 + x - dy) * m
    rho_a = mp.sqrt(r_a ** 2 - (m * z / mp.mpf(2) * mp.cos(al)) ** 2)
    assert 2 * rho_a < a_w * mp.sin(aw)
    with pytest.raises(gd.GearDesignError, match="do not mesh.*tip circles do not overlap.*x1 \\+ x2 = 4"):
        gd.GearPair(1, 5, 5, 2.0, 2.0, rack=gd.BasicRack(alpha_deg=15.0))


@pytest.mark.parametrize("a_w", [1e308, 1e9])
def test_from_center_distance_refuses_an_a_w_no_shifts_reach_without_a_warning(a_w):
    """Found by the fuzzing (tests/fuzzcases.py): a_w = 1e308 overflowed inv α_w ('overflow encountered in
    multiply') before the x-sum was refused. The largest a_w is that of x1 + x2 = 20 (|x| <= 10):
    ISO 21771 eq. (62), cos α_w = a cos α / a_w with inv α_w = inv α + 2 x_Σ tan α / z_Σ."""
    import math
    import warnings
    from scipy.optimize import brentq
    inv = lambda t: math.tan(t) - t
    target = inv(math.radians(20)) + 2 * 20 * math.tan(math.radians(20)) / 43
    alpha_w = brentq(lambda t: inv(t) - target, 0.1, 1.5)
    a_max = 43 / 2 * math.cos(math.radians(20)) / math.cos(alpha_w)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(gd.GearDesignError, match=rf"too large: it must be < {a_max:.6g} mm"):
            gd.GearPair.from_center_distance(1.0, 17, 26, a_w, x1=0.5)
