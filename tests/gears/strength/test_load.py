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
