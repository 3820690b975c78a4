"""A bought unit as a drive stage (geardesign.drives.stage_kinds.given): seed 002's worm gear motor (4 kW at
1500 rpm, u = 12.5, η = 0.87; its n = 1500/12.5 = 120 rpm) checked against a rated output torque, the margin
1 − T_out/[T] computed here by hand."""
import math

import numpy as np
import pytest

import geardesign as gd
from geardesign.drives.stage_kinds import kind_of
from geardesign.drives.stage_kinds.given import GivenKind

T_OUT = 4000 / (1500 * math.pi / 30) * 12.5 * 0.87      # 276.930 N·m on the gear motor's output


def test_the_kind_of_a_given_stage():
    kind = kind_of(gd.GivenStage(12.5, 0.87))
    assert isinstance(kind, GivenKind) and kind.name == "given" and kind.colour == "#d9d9d9"
    assert kind.ratio_span(gd.GivenStage(12.5, 0.87)) == (12.5, 12.5)


def test_the_rated_torque_margin_by_hand():
    stage = gd.GivenStage(12.5, 0.87, "gear motor", rated_output_torque_nm=300.0)
    a = gd.Drive(power_kw=4, n_in_rpm=1500, stages=[stage]).analyse()
    assert a.flow["torque_nm"].iloc[-1] == pytest.approx(T_OUT, rel=1e-14)
    got = a.checks.set_index("check").loc["rated_torque", "margin"]
    assert got == pytest.approx(1 - T_OUT / 300.0, rel=1e-13)
    assert a.success
    over = gd.Drive(power_kw=4, n_in_rpm=1500,
                    stages=[gd.GivenStage(12.5, 0.87, rated_output_torque_nm=250.0)]).analyse()
    assert not over.success and over.checks.set_index("check").loc["rated_torque", "margin"] == pytest.approx(
        1 - T_OUT / 250.0, rel=1e-13)


def test_a_batch_of_designs_and_a_unit_without_a_rating():
    stage = gd.GivenStage(12.5, 0.87, rated_output_torque_nm=300.0)
    torques = np.array([100.0, 300.0, 450.0])
    assert np.allclose(stage.margins(torques)["rated_torque"], 1 - torques / 300.0, rtol=1e-15, atol=0)
    assert gd.GivenStage(12.5, 0.87).margins(torques) == {}
