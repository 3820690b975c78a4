"""The load a pair carries (geardesign.gears.strength.load): its arguments refused by name."""
import pytest

import geardesign as gd


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
