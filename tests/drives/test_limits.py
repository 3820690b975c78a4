"""The drive's limits (geardesign.drives.limits), one place each: the search and the inputs refuse what lies
beyond them, by name, before any work."""
import pytest

import geardesign as gd
from geardesign.drives import limits as lim
from geardesign.errors import GearDesignError


def _stage():
    return gd.GivenStage(2.0, 0.97)


def test_the_objectives_are_the_drives():
    d = gd.Drive(power_kw=1, n_in_rpm=1500, stages=[gd.GearStage(m=2, z1_range=(17, 20), z2_max=60)])
    for objective in lim.OBJECTIVES:
        assert d.optimize(total_ratio=2.0, ratio_tol=0.05, objective=objective).objective == objective
    with pytest.raises(GearDesignError, match="objective"):
        d.optimize(total_ratio=2.0, objective="cheapest")


@pytest.mark.parametrize("make, words", [
    (lambda: gd.Drive(power_kw=1, n_in_rpm=1500, stages=[_stage()] * (lim.STAGES_MAX + 1)), "stages"),
    (lambda: gd.Drive(power_kw=1, n_in_rpm=lim.SPEED_RANGE_RPM[1] * 2, stages=[_stage()]), "n_in_rpm"),
    (lambda: gd.Drive(power_kw=lim.POWER_RANGE_KW[1] * 2, n_in_rpm=1500, stages=[_stage()]), "power_kw"),
    (lambda: gd.Drive(power_kw=1, n_in_rpm=1500, stages=[_stage()]).optimize(
        total_ratio=lim.TOTAL_RATIO_RANGE[1] * 2), "total_ratio"),
    (lambda: gd.Drive(power_kw=1, n_in_rpm=1500, stages=[_stage()]).optimize(
        total_ratio=2.0, ratio_tol=lim.RATIO_TOL_RANGE[1] + 0.1), "ratio_tol"),
    (lambda: gd.Drive(power_kw=1, n_in_rpm=1500, stages=[_stage()]).optimize(
        total_ratio=2.0, top=lim.TOP_MAX + 1), "top"),
])
def test_beyond_a_limit_is_refused_by_name(make, words):
    with pytest.raises(GearDesignError, match=words):
        make()
