"""One result base: every job's result has a status and gives JSON without NaN."""
import json

import pytest

import geardesign as gd


def test_results_share_status_and_json():
    ok = gd.optimize_shifts(17, 26)
    bad = gd.optimize_shifts(5, 5, checks={"sa_min": 0.6})   # undercut and tip thickness cannot both hold at z = 5
    assert ok.status == "success" and bad.status == "failed" and bad.conflict
    for res in (ok, bad, gd.feasible_region(17, 26), gd.key.select(60, 503, 50)):
        text = res.to_json()
        assert "NaN" not in text and json.loads(text)["status"] in ("success", "failed")
    cap = gd.key.capacity(60, 32, 300, 120)       # seed 002: 300·60·4·14/2000 = 504 N·m
    assert cap.torque_nm == cap["torque_nm"] == pytest.approx(504.0) and cap.governing == "crushing"
