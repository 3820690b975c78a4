"""A drive's results (geardesign.drives.drive_results): seed 002's brake stand (4 kW at 1500 rpm, a gear motor
u = 12.5, η = 0.87, then a chain u = 1, η = 0.96) analysed — the flow, the smallest margin and its check, the JSON
form, a short repr — and an optimum whose best design is the analysis of its first row."""
import json
import math

import matplotlib
import pytest

import geardesign as gd

matplotlib.use("Agg")


def _seed002(**kw):
    return gd.Drive(power_kw=4, n_in_rpm=1500, stages=[gd.GivenStage(12.5, 0.87, "gear motor"),
                                                       gd.ChainStage(z1=13, z2=13, k_e=2.148, **kw)])


@pytest.fixture(scope="module")
def analysis():
    return _seed002(designation="2PR-31,75-177").analyse()


def test_the_analysis(analysis):
    t1 = 4000 / (1500 * math.pi / 30) * 12.5 * 0.87              # on the gear motor's output, by hand
    assert analysis.flow["torque_nm"].iloc[1] == pytest.approx(t1, rel=1e-14)
    assert analysis.total_ratio == pytest.approx(12.5, rel=1e-15)
    smallest = analysis.checks.loc[analysis.checks["margin"].idxmin()]
    assert analysis.min_margin == pytest.approx(smallest.margin, rel=1e-15) and smallest.check in analysis.limiting
    assert analysis.success == bool((analysis.checks["margin"] >= 0).all())


def test_the_json_form_and_the_repr(analysis):
    data = json.loads(json.dumps(analysis.to_dict()))
    assert data["total_ratio"] == pytest.approx(12.5) and len(data["flow"]) == 3
    assert len(repr(analysis).splitlines()) <= 20
    assert "<" in analysis._repr_html_()
    assert analysis.plot() is not None


def test_the_optimums_best_is_the_analysis_of_its_first_row():
    opt = _seed002().optimize(total_ratio=12.5, ratio_tol=0.0, objective="min_mass")
    assert opt.success and opt.objective == "min_mass" and opt.best is not None
    assert opt.best.min_margin == pytest.approx(opt.table.iloc[0]["min_margin"], rel=1e-12, abs=1e-12)
    assert opt.n_candidates >= len(opt.table) >= 1
    assert json.loads(json.dumps(opt.to_dict()))["objective"] == "min_mass"
