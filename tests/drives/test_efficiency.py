"""A stage's efficiency (geardesign.drives.efficiency): the properties issue 37 asks for (the bearing friction it
adds: tests/drives/test_bearing_friction.py)."""
from __future__ import annotations

import itertools

import pytest

from geardesign.drives.efficiency import BearingLoad, stage_efficiency
from geardesign.errors import GearDesignError
from geardesign.gears.efficiency import Lubricant
from geardesign.gears.pair import GearPair
from geardesign.gears.strength import Load


PAIR = GearPair(3.0, 21, 64, 0.3, 0.2, face_width_mm=40)     # an ordinary reducer stage, u ≈ 3


def _stage(torque_nm, oil, t=60.0, **kw):
    force = 2000.0 * torque_nm / PAIR.geometry().dw1          # tangential force, shared by the two bearings
    bearings = [BearingLoad("6307", 1, force / 2), BearingLoad("6307", 1, force / 2),
                BearingLoad("6310", 2, force / 2), BearingLoad("6310", 2, force / 2)]
    return stage_efficiency(PAIR, Load(torque_nm=torque_nm, n_rpm=1450), oil, t, bearings=bearings, **kw)


OILS = [Lubricant(32, 5.4), Lubricant(100, 11.1), Lubricant(320, 24), Lubricant(680, 40)]


def test_efficiency_falls_as_the_oil_thickens_at_low_load():
    eta = [_stage(10.0, oil).efficiency for oil in OILS]
    assert all(a > b for a, b in itertools.pairwise(eta)), eta


def test_a_larger_load_raises_the_load_dependent_loss():
    losses = [_stage(t, OILS[1]).mesh_loss_w for t in (20.0, 100.0, 400.0)]
    assert losses[0] < losses[1] < losses[2]
    # μ_mZ ∝ (F/b)^0.2 at fixed speed: P_VZP ∝ T^1.2
    assert losses[2] / losses[1] == pytest.approx(4.0 ** 1.2, rel=1e-9)


def test_mesh_efficiency_of_a_usual_spur_pair_is_about_0_99():
    r = _stage(400.0, OILS[1], Ra_um=0.5)
    assert 0.985 < r.mesh_efficiency < 0.995
    assert r.efficiency < r.mesh_efficiency
    assert r.loss_w == pytest.approx(r.mesh_loss_w + r.no_load_loss_w + r.bearing_loss_w, rel=1e-15)
    assert r.heat_w == r.loss_w
    assert r.to_frame()["power_w"].sum() == pytest.approx(r.loss_w, rel=1e-12)


def test_a_given_no_load_loss_is_counted_and_the_load_may_be_on_gear_2():
    base = _stage(100.0, OILS[1])
    more = _stage(100.0, OILS[1], no_load_loss_w=50.0)
    assert more.loss_w - base.loss_w == pytest.approx(50.0, rel=1e-12)
    on2 = stage_efficiency(PAIR, Load(torque_nm=100.0 * 64 / 21, n_rpm=1450 * 21 / 64, on_gear=2), OILS[1], 60.0)
    alone = stage_efficiency(PAIR, Load(torque_nm=100.0, n_rpm=1450), OILS[1], 60.0)
    assert on2.efficiency == pytest.approx(alone.efficiency, rel=1e-12)


def test_stage_efficiency_bad_inputs():
    with pytest.raises(GearDesignError, match="load"):
        stage_efficiency(PAIR, 100.0, OILS[1], 60.0)
    with pytest.raises(GearDesignError, match="lubricant"):
        stage_efficiency(PAIR, Load(torque_nm=100.0, n_rpm=1450), 68, 60.0)
    with pytest.raises(GearDesignError, match="shaft"):
        BearingLoad("6307", 3, 100.0)
    with pytest.raises(GearDesignError, match="no_load_loss_w"):
        _stage(100.0, OILS[1], no_load_loss_w=-1.0)


@pytest.mark.parametrize("bearings", [__import__("numpy").array(100.0), 5, "6307"])
def test_bearings_that_are_no_list_are_refused_by_name(bearings):
    """Fuzzing found 'TypeError: iteration over a 0-d array' for bearings=np.array(100.0)."""
    with pytest.raises(GearDesignError, match="bearings must be a list of BearingLoad items"):
        stage_efficiency(PAIR, Load(power_kw=15, n_rpm=1450), Lubricant(100, 11.1), 60.0, bearings=bearings)


@pytest.mark.parametrize("lubrication", [__import__("numpy").array([]), ["oil_bath"], "water"])
def test_a_lubrication_that_is_no_name_is_refused_by_name(lubrication):
    """Fuzzing found 'TypeError: unhashable type' for lubrication=np.array([])."""
    with pytest.raises(GearDesignError, match="lubrication must be one of"):
        stage_efficiency(PAIR, Load(power_kw=15, n_rpm=1450), Lubricant(100, 11.1), 60.0, lubrication=lubrication)


def test_losses_reaching_the_input_power_are_refused_by_name():
    # fuzzing: 5e-324 kW through a stage with bearings gave efficiency −inf; the stage does not run at such a load
    pair = GearPair(1.0, 21, 26, 0.3, 0.2, face_width_mm=40.0)
    with pytest.raises(GearDesignError, match=r"losses .* reach its input power"):
        stage_efficiency(pair, Load(power_kw=5e-324, n_rpm=10000.0), Lubricant(680.0, 40.0), 20.0,
                         bearings=[BearingLoad("6307", 1, 100.0, 0.0)])
    with pytest.raises(GearDesignError, match=r"losses .* reach its input power"):
        stage_efficiency(pair, Load(power_kw=0.001, n_rpm=1000.0), Lubricant(680.0, 40.0), 20.0, no_load_loss_w=2.0)
