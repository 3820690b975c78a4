"""The optimiser's result object (geardesign.shifts.result.ShiftResult): JSON round trip, the x-sum
of external and internal pairs (ISO 21771: x_Σ = x1 + x2, internal x2 − x1), its table and its text."""
import json
import math

import numpy as np
import pytest

import geardesign as gd
from geardesign.shifts.result import ShiftResult


def _made(**kw):
    args = dict(x1=0.25, x2=-0.125, fun=0.125, objective="max_x_sum", success=True, message="converged",
                method="exact", tol=1e-9, nit=7, time_s=0.001, margins={"undercut1": 0.0, "tip_thickness2": 0.3},
                active=["undercut1"], sensitivity={"undercut1": -1.5}, z1=17, z2=26, m=2.0, a_w=43.3,
                eps_alpha=math.nan)
    args.update(kw)
    return ShiftResult(**args)


def test_to_json_round_trips_to_dict_with_nan_as_null():
    r = _made()
    d = json.loads(r.to_json())
    assert d == r.to_dict()
    assert d["eps_alpha"] is None and d["x_sum_fixed"] is None
    assert d["status"] == "success" and _made(success=False).to_dict()["status"] == "failed"
    assert d["x1"] == 0.25 and d["margins"] == {"undercut1": 0.0, "tip_thickness2": 0.3}
    assert d["active"] == ["undercut1"] and d["z1"] == 17


def test_x_sum_external_and_internal():
    assert _made().x_sum == 0.25 + -0.125
    assert _made(internal=True).x_sum == -0.125 - 0.25
    np.testing.assert_array_equal(_made().x, [0.25, -0.125])


def test_to_frame_has_one_row_per_check_and_both_corner_sides():
    r = _made(sensitivity_sides={"undercut1": {"raised": -2.0, "lowered": -1.0}})
    f = r.to_frame()
    assert f["check"].tolist() == ["undercut1", "tip_thickness2"]
    assert f["active"].tolist() == [True, False]
    assert f["sensitivity"].tolist() == [-1.5, 0.0]
    assert f["sensitivity_raised"].tolist() == [-2.0, 0.0] and f["sensitivity_lowered"].tolist() == [-1.0, 0.0]
    assert "undercut1 -2 if raised / -1 if lowered (corner)" in repr(r)


def test_a_real_optimum_round_trips():
    r = gd.optimize_shifts(17, 26)
    d = json.loads(r.to_json())
    assert d["x1"] == r.x1 and d["x2"] == r.x2 and d["fun"] == r.fun
    assert set(d["margins"]) == set(r.to_frame()["check"])
    assert d["x1"] + d["x2"] == pytest.approx(r.x_sum)
