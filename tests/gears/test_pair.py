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
