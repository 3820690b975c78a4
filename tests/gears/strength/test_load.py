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
