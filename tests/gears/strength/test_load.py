"""The load case (geardesign.gears.strength.load.Load): P = T·2πn/60 both ways, ISO/TR 6336-30:2017 example 1's
9000 N·m at 360 rpm, and each bad input refused by name with its range."""
import math

import pytest

from geardesign.errors import GearDesignError
from geardesign.gears.strength.load import Load


def test_torque_and_power_both_ways():
    t = Load(torque_nm=9000, n_rpm=360, life_h=50_000)          # ISO/TR 6336-30 example 1's pinion
    assert t.power_kw == pytest.approx(9000 * 2 * math.pi * 360 / 60 / 1000, rel=1e-15)
    assert t.given == "torque" and t.omega == pytest.approx(2 * math.pi * 360 / 60, rel=1e-15)
    p = Load(power_kw=t.power_kw, n_rpm=360)
    assert p.given == "power" and p.torque_nm == pytest.approx(9000, rel=1e-14)
    assert (t.on_gear, t.application_factor, t.life_h) == (1, 1.0, 50_000.0)


@pytest.mark.parametrize("kw, words", [
    (dict(torque_nm=1, power_kw=1, n_rpm=1), "not both"),
    (dict(n_rpm=1000), "one is needed"),
    (dict(torque_nm=100), "n_rpm"),
    (dict(torque_nm=-5, n_rpm=1000), "torque_nm"),
    (dict(torque_nm=float("nan"), n_rpm=1000), "torque_nm"),
    (dict(torque_nm=100, n_rpm=0), "n_rpm"),
    (dict(power_kw=1e5, n_rpm=1e-300), "power_kw and n_rpm"),
    (dict(torque_nm=100, n_rpm=1000, on_gear=3), "on_gear"),
    (dict(torque_nm=100, n_rpm=1000, on_gear=True), "on_gear"),
    (dict(torque_nm=100, n_rpm=1000, application_factor=0.5), "application_factor"),
    (dict(torque_nm=100, n_rpm=1000, life_h=0), "life_h"),
])
def test_bad_inputs_are_refused_by_name(kw, words):
    with pytest.raises(GearDesignError, match=words):
        Load(**kw)


import geardesign as gd  # noqa: E402  (the hint tests below)


@pytest.mark.parametrize("kwargs, hint", [
    (dict(torque=100, n_rpm=1000), "torque_nm=100"),
    (dict(power=5.0, n_rpm=1000), "power_kw=5.0"),
    (dict(torque_nm=100, speed=1000), "n_rpm=1000"),
    (dict(torque_nm=100, n_rpm=1000, K_A=1.25), "application_factor=1.25"),
])
def test_a_slip_of_a_keyword_is_refused_with_the_right_name(kwargs, hint):
    # issue 36 §1.6: gd.Load(torque=100) was a bare TypeError
    with pytest.raises(gd.GearDesignError, match="Load has no argument") as err:
        gd.Load(**kwargs)
    assert hint in str(err.value) and "its arguments are application_factor" in str(err.value)


def test_an_unknown_keyword_without_a_hint_lists_the_arguments():
    with pytest.raises(gd.GearDesignError, match=r"Load has no argument 'colour'; its arguments are "):
        gd.Load(torque_nm=100, n_rpm=1000, colour="red")
    with pytest.raises(gd.GearDesignError, match="takes at most 6 arguments"):
        gd.Load(1, None, 1000, 1, 1.0, None, 7)


def test_the_right_keywords_still_make_a_load():
    # P = T·2πn/60: 100 N·m at 1000 rpm is 10.472 kW
    assert gd.Load(torque_nm=100, n_rpm=1000).power_kw == pytest.approx(100 * 2 * 3.141592653589793 * 1000 / 60e3,
                                                                       rel=1e-15)
    assert gd.Load(100, None, 1000).torque_nm == 100.0


# --- a load per design (issue 35 §5: a drive search checks many flows into a stage in one strength call)

@pytest.mark.parametrize("life_h", [None, 20000.0])
def test_per_design_load_equals_one_load_each(life_h):
    # bit for bit at endurance; with a life, Z_NT and Y_NT take the logarithm of each design's own cycles (numpy's
    # on an array, the float path's on a number): to 1e-14
    import numpy as np
    from geardesign.gears.strength import Load, pair_strength

    T = np.array([300.0, 500.0, 900.0, 40.0])
    n = np.array([1400.0, 900.0, 500.0, 3000.0])
    m, z1, z2 = np.array([3.0, 4.0, 5.0, 2.0]), np.array([20, 21, 22, 30]), np.array([80, 70, 60, 31])
    x1, x2, b = np.array([0.2, 0.1, 0.0, 0.4]), np.array([0.1, 0.0, 0.3, -0.2]), np.array([40.0, 50.0, 60.0, 20.0])
    both = pair_strength(m, z1, z2, x1, x2, load=Load.per_design(T, n, life_h=life_h), material1="42CrMo4",
                         face_width_mm=b)
    for i in range(T.size):
        j = slice(i, i + 1)      # one design as an array: the same (array) path of the chain
        one = pair_strength(m[j], z1[j], z2[j], x1[j], x2[j], load=Load(torque_nm=T[i], n_rpm=n[i], life_h=life_h),
                            material1="42CrMo4", face_width_mm=b[j])
        for k in ("S_H1", "S_H2", "S_F1", "S_F2", "K_v", "K_Hbeta", "Z_NT1", "sigma_H1", "sigma_F2"):
            got, want = float(np.ravel(both[k])[i]), float(np.ravel(one[k])[0])
            assert got == want if life_h is None else got == pytest.approx(want, rel=1e-14), k


def test_per_design_load_validates_each_element():
    from geardesign.gears.strength import Load

    with pytest.raises(GearDesignError, match="torque_nm"):
        Load.per_design([100.0, -1.0], [1000.0, 1000.0])
    with pytest.raises(GearDesignError, match="n_rpm"):
        Load.per_design([100.0, 1.0], [1000.0, float("nan")])
    L = Load.per_design([400.0, 800.0], [1000.0, 500.0])
    assert L == L and L != Load.per_design([400.0, 800.0], [1000.0, 500.0])   # one object: a memo's key
    assert L.power_kw.tolist() == pytest.approx([400 * 1000 * math.pi / 30e3] * 2, rel=1e-15)
