"""Load capacity as checks and objectives over the shifts (issue 26 §3).

The checks' margins come from the vectorised chain on the solver's geometry (mesh_geometry, unvalidated);
the reference here is the one-pair path, GearPair.strength, which computes its own validated geometry
(pair_geometry) and is tested against published examples in tests/gears/strength/. Their gradients are
compared with central differences of that reference; the optima with the contact check or the balanced
split active are compared with the definitions (S_H = S_Hmin, S_F1 = S_F2)."""
import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears.checks import make_checks
from geardesign.gears.strength import Load

MATERIAL = "18CrNiMo7-6"
LOAD = Load(torque_nm=400, n_rpm=1000, life_h=20000)
CASE = {"load": LOAD, "material": MATERIAL, "face_width_mm": 40.0}


def _reference(x1, x2, load=LOAD, m=4.0, z1=20, z2=60):
    return gd.GearPair(m, z1, z2, x1, x2, face_width_mm=40.0).strength(load, material=MATERIAL)


def test_strength_checks_are_built_only_with_a_load():
    names = [c.name for c in make_checks(**CASE)]
    assert names[-3:] == ["contact_strength", "root_strength1", "root_strength2"]
    assert "contact_strength" not in [c.name for c in make_checks()]


@pytest.mark.parametrize("kw, match", [
    ({"material": MATERIAL}, "material given without a load"),
    ({"load": LOAD}, "need material="),
    ({"load": "400 Nm", "material": MATERIAL}, "load must be a geardesign Load"),
    ({"load": LOAD, "material": "unobtainium"}, "unobtainium"),
    ({"load": LOAD, "material": MATERIAL, "S_Hmin": 50.0}, "S_Hmin must be"),
])
def test_strength_checks_refuse_incomplete_load_cases(kw, match):
    with pytest.raises(GearDesignError, match=match):
        make_checks(**kw)


@settings(max_examples=15, deadline=None)
@given(x1=st.floats(0.0, 0.8), x2=st.floats(0.0, 0.8))
def test_margins_equal_the_one_pair_chain(x1, x2):
    pair = gd.GearPair(4.0, 20, 60, x1, x2, face_width_mm=40.0)
    table = pair.checks(**CASE).set_index("check")
    ref = _reference(x1, x2)
    assert math.isclose(table.loc["contact_strength", "value"], min(ref.S_H1, ref.S_H2), rel_tol=1e-9)
    assert math.isclose(table.loc["root_strength1", "value"], ref.S_F1, rel_tol=1e-9)
    assert math.isclose(table.loc["root_strength2", "value"], ref.S_F2, rel_tol=1e-9)
    assert math.isclose(table.loc["root_strength1", "margin"], ref.S_F1 / 1.4 - 1.0, rel_tol=1e-9, abs_tol=1e-12)


def test_gradients_match_differences_of_the_reference():
    x1, x2, h = 0.3, 0.25, 1e-5
    checks = {c.name: c for c in make_checks(**CASE)}
    from geardesign.gears.geometry import mesh_geometry_float
    from geardesign.gears.mesh import Mesh
    geo = mesh_geometry_float(Mesh(20, 60), 4.0, x1, x2)
    for name, attr in (("contact_strength", None), ("root_strength1", "S_F1"), ("root_strength2", "S_F2")):
        def value(a, b):
            r = _reference(a, b)
            return (min(r.S_H1, r.S_H2) if attr is None else getattr(r, attr)) / checks[name].limit
        d1 = (value(x1 + h, x2) - value(x1 - h, x2)) / (2 * h)
        d2 = (value(x1, x2 + h) - value(x1, x2 - h)) / (2 * h)
        g1, g2 = checks[name].gradient(geo)
        assert g1 == pytest.approx(d1, rel=1e-5, abs=1e-7) and g2 == pytest.approx(d2, rel=1e-5, abs=1e-7)


def test_contact_strength_limits_the_x_sum_under_a_heavy_load():
    """At 600 N·m the pitting limit stops the x-sum with the contact ratio: the optimum sits on S_H = S_Hmin."""
    heavy = {**CASE, "load": Load(torque_nm=600, n_rpm=1000, life_h=20000)}
    r = gd.optimize_shifts(20, 60, m=4, checks=heavy)
    assert r.success and "contact_strength" in r.active
    ref = _reference(r.x1, r.x2, load=heavy["load"])
    assert min(ref.S_H1, ref.S_H2) == pytest.approx(1.0, abs=1e-8)
    light = gd.optimize_shifts(20, 60, m=4, checks=CASE)          # at 400 N·m it does not bind
    assert "contact_strength" not in light.active and light.x1 + light.x2 > r.x1 + r.x2


def test_max_min_safety_is_the_smallest_ratio_at_its_optimum():
    heavy = {**CASE, "load": Load(torque_nm=600, n_rpm=1000, life_h=20000)}
    r = gd.optimize_shifts(20, 60, m=4, objective="max_min_safety", checks=heavy)
    assert r.success
    ref = _reference(r.x1, r.x2, load=heavy["load"])
    smallest = min(min(ref.S_H1, ref.S_H2) / 1.0, ref.S_F1 / 1.4, ref.S_F2 / 1.4)
    assert r.fun == pytest.approx(smallest, rel=1e-9)


def test_an_overload_names_the_strength_check_in_the_conflict():
    over = {**CASE, "load": Load(torque_nm=800, n_rpm=1000, life_h=20000)}
    r = gd.optimize_shifts(20, 60, m=4, checks=over)
    assert not r.success and "contact_strength" in r.conflict


@pytest.mark.parametrize("method", ["exact", "grid"])
def test_a_pitting_limit_the_geometry_cannot_meet_is_named_alone(method):
    """20/60, m = 4, 40 mm of 42CrMo4 at 200 N·m: S_H rises with x_Σ until ε_α reaches 1 (the chain's range),
    and stays below S_Hmin = 1 there; the answer names contact_strength alone, and the reference chain agrees
    that S_H < 1 at the most central point returned."""
    case = {"load": Load(torque_nm=200, n_rpm=1000, life_h=20000), "material": "42CrMo4", "face_width_mm": 40}
    r = gd.optimize_shifts(20, 60, m=4, method=method, checks=case)
    assert not r.success and r.conflict == ["contact_strength"]
    ref = gd.GearPair(4.0, 20, 60, r.x1, r.x2, face_width_mm=40.0).strength(case["load"], material="42CrMo4")
    assert min(ref.S_H1, ref.S_H2) < 1.0


def test_an_overloaded_ring_pair_names_its_conflict():
    """20/70 internal at 1500 N·m: the search grids hold designs the chain refuses (a root notch parameter q_s
    below its range, where the geometry fails anyway); they fail the check instead of stopping the solve, and
    the answer names the root strength of the ring, which the reference chain confirms below S_Fmin."""
    over = {**CASE, "load": Load(torque_nm=1500, n_rpm=1000, life_h=20000)}
    for method in ("exact", "grid"):
        r = gd.optimize_shifts(20, 70, m=4, internal=True, method=method, checks=over)
        assert not r.success and r.conflict == ["root_strength2"]
        ref = gd.GearPair(4.0, 20, 70, r.x1, r.x2, internal=True, face_width_mm=40.0).strength(over["load"],
                                                                                              material=MATERIAL)
        assert ref.S_F2 < 1.4


def test_balanced_root_strength_equalises_the_gears_on_a_fixed_centre_distance():
    m, z1, z2 = 4.0, 20, 60
    a_w = gd.GearPair(m, z1, z2, 0.3, 0.2).geometry().a_w
    r = gd.optimize_shifts(z1, z2, m=m, a_w=a_w, objective="balanced_root_strength",
                           checks={**CASE, "eps_alpha_min": 1.1})
    assert r.success
    ref = _reference(r.x1, r.x2)
    if not r.active:          # no check stops the split: the two root safeties are equal
        assert ref.S_F1 == pytest.approx(ref.S_F2, rel=1e-9)
    assert r.x1 + r.x2 == pytest.approx(0.5, abs=1e-9)


@pytest.mark.slow
@pytest.mark.parametrize("method", ["exact", "convex", "grid"])
def test_strength_objectives_run_on_every_method(method):
    r = gd.optimize_shifts(20, 60, m=4, objective="max_min_safety", method=method, checks=CASE)
    assert r.success and np.isfinite(r.fun)


def test_strength_objective_without_a_load_says_so():
    with pytest.raises(GearDesignError, match="needs a load"):
        gd.optimize_shifts(20, 60, m=4, objective="balanced_root_strength")


def test_region_draws_the_strength_curves():
    import matplotlib
    matplotlib.use("Agg")
    heavy = {**CASE, "load": Load(torque_nm=700, n_rpm=1000, life_h=20000)}
    region = gd.feasible_region(20, 60, m=4, checks=heavy)
    assert "contact_strength" in region.boundary["check"].unique()
    ax = region.plot()
    assert any("contact_strength" in t.get_text() for t in ax.get_legend().get_texts())
    matplotlib.pyplot.close(ax.figure)


def test_the_solvers_quadratic_model_of_the_chain_matches_it():
    """The model the solvers walk on (StrengthSpec.model): at its anchor the chain's own values and gradients,
    nearby a second-order Taylor polynomial (error of third order at 1e-3 away: far below the first-order one's)."""
    from geardesign.gears.geometry import mesh_geometry_float
    from geardesign.gears.mesh import Mesh
    spec = make_checks(**CASE)[-1].spec
    at = mesh_geometry_float(Mesh(20, 60), 4.0, 0.3, 0.25)
    model, exact = spec.model(at), spec.safety(mesh_geometry_float(Mesh(20, 60), 4.0, 0.3, 0.25), gradients=True)
    assert model.safety(at) == exact
    d = 1e-3
    near = mesh_geometry_float(Mesh(20, 60), 4.0, 0.3 + d, 0.25 - d)
    truth = spec.safety(near)
    for name in ("S_H", "S_F1", "S_F2"):
        linear = exact[name] + (exact["d" + name][0] - exact["d" + name][1]) * d
        error = abs(model.safety(near)[name] - truth[name])
        assert error < 1e-8 and error < abs(linear - truth[name]) / 10


def test_a_load_per_design_goes_with_its_designs_when_the_chain_refuses_some():
    """Fuzzing (strength_drive) found 'ValueError: operands could not be broadcast together with shapes (272,)
    (136,)' from a drive sizing a stage of a V material without yield_mpa: the chain refused the call, the halves
    it then tried took the whole per-design load. Now the refusal itself, by name."""
    mat = gd.material("V_alloy", hardness=360.0)
    with pytest.raises(GearDesignError, match="needs yield_mpa"):
        gd.Drive(power_kw=2.0, n_in_rpm=950.0, stages=[gd.GearStage(material=mat, m=None)]).optimize(2.81)
