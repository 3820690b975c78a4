"""A drive's optimum and the analysis of the same design agree (issue 36 §1.9).

The report: a generated drive (GearStage(3, z1_range=(19, 20), z2_max=120, beta_deg=15, face_width_mm=20) and
GivenStage(5.103, 0.87, rated_output_torque_nm=50)) optimised for ``max_margin`` gave best.min_margin +0.21775,
and ``Drive(stages=<the best's stages>).analyse()`` gave 0. The best's own stages (``best.drive.stages``: tooth
counts *and* shifts fixed) re-analyse to the same margins whatever objective ``analyse`` is given; the 0 is what
the best's tooth counts give with their shifts left free, re-solved by ``analyse``'s default objective
(``min_size``: the smallest pair, at a vertex of the region where a margin is 0), another design. Re-solving them
for the optimum's own objective gives its shifts and margins back.
"""
import dataclasses

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import geardesign as gd


@st.composite
def small_drives(draw):
    z1 = draw(st.integers(14, 24))
    gear = dict(m=draw(st.sampled_from([2.0, 3.0])), z1_range=(z1, z1 + draw(st.integers(0, 2))),
                z2_max=draw(st.sampled_from([60, 120])), beta_deg=draw(st.sampled_from([0.0, 15.0, 25.0])),
                face_width_mm=draw(st.sampled_from([None, 8.0, 20.0])),
                checks=draw(st.sampled_from([None, {"eps_alpha_min": 1.1}, {"sa_min": 0.3}])))
    given_stage = dict(ratio=draw(st.sampled_from([2.0, 3.55, 5.103])), efficiency=draw(st.sampled_from([0.87, 0.95])),
                       rated_output_torque_nm=draw(st.sampled_from([None, 50.0, 200.0])))
    stages = [gd.GearStage(**gear), gd.GivenStage(**given_stage)]
    if draw(st.booleans()):
        stages.reverse()
    load = draw(st.sampled_from([dict(power_kw=0.3), dict(power_kw=1.0), dict(output_torque_nm=40.0)]))
    return (stages, dict(n_in_rpm=draw(st.sampled_from([960.0, 1450.0, 2900.0])), **load),
            round(draw(st.floats(4.0, 20.0)), 3), draw(st.sampled_from(["min_size", "min_mass", "max_margin"])))


def _margins(analysis):
    return list(zip(analysis.checks["item"], analysis.checks["check"], analysis.checks["margin"]))


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(small_drives())
def test_the_best_design_re_analysed_gives_its_margins(case):
    stages, inputs, u, objective = case
    try:
        opt = gd.Drive(stages=stages, **inputs).optimize(u, objective=objective, top=3)
    except gd.GearDesignError:
        return                                 # a ratio the stages cannot make: refused, nothing to compare
    best = opt.best
    if best is None:
        return
    assert opt.table["min_margin"].iloc[0] == best.min_margin
    again = gd.Drive(stages=best.drive.stages, **inputs).analyse()        # default objective: shifts are fixed
    assert _margins(again) == _margins(best) and again.min_margin == best.min_margin
    # the tooth counts with free shifts, re-solved for the optimum's own objective: the same design again
    free = [dataclasses.replace(s, x1=None, x2=None) if isinstance(s, gd.GearStage) else s for s in best.drive.stages]
    resolved = gd.Drive(stages=free, **inputs).analyse(objective)
    assert _margins(resolved) == _margins(best)


def test_the_reported_drive():
    # the case of the report, at a load and ratio where the best is limited by its gear (not the given stage)
    stages = [gd.GearStage(3, z1_range=(19, 20), z2_max=120, beta_deg=15.0, face_width_mm=20),
              gd.GivenStage(5.103, 0.87, rated_output_torque_nm=50)]
    inputs = dict(n_in_rpm=1450.0, power_kw=0.3)
    best = gd.Drive(stages=stages, **inputs).optimize(6.0, objective="max_margin").best
    assert best.min_margin > 0.2
    assert gd.Drive(stages=best.drive.stages, **inputs).analyse().min_margin == best.min_margin
    # what gave 0: the shifts left free and solved for min_size, analyse's default (another design)
    free = [dataclasses.replace(best.drive.stages[0], x1=None, x2=None), best.drive.stages[1]]
    assert gd.Drive(stages=free, **inputs).analyse().min_margin == 0.0
    assert gd.Drive(stages=free, **inputs).analyse("max_margin").min_margin == best.min_margin
