"""Objectives: a registry of objects, a user's own, and those of the x-sum alone refused when a centre
distance fixes the x-sum."""
import numpy as np
import pytest

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears.geometry import mesh_geometry
from geardesign.gears.mesh import Mesh
from geardesign.shifts.objectives import OBJECTIVES, CustomObjective


@pytest.mark.parametrize("objective", ["max_x_sum", "min_specific_pressure"])
def test_objectives_of_the_x_sum_alone_are_refused_on_a_fixed_center_distance(objective):
    with pytest.raises(gd.GearDesignError, match="depends on x1 \\+ x2 alone"):
        gd.optimize_shifts(12, 31, objective=objective, a_w=55, m=2.5)


def test_custom_objective_equals_the_builtin_it_restates():
    """Two routes to one optimum: a CustomObjective of x1 + x2 (numeric gradients) and max_x_sum."""
    mine = gd.optimize_shifts(17, 26, objective=CustomObjective("x_sum", lambda g: g["_x1"] + g["_x2"]))
    ref = gd.optimize_shifts(17, 26, objective="max_x_sum")
    assert mine.success and mine.objective == "x_sum"
    assert mine.x1 == pytest.approx(ref.x1, abs=1e-7) and mine.x2 == pytest.approx(ref.x2, abs=1e-7)

def test_custom_objective_beats_every_feasible_grid_node():
    """Minimum tip diameter d_a1 against a brute-force 401 x 401 grid of the same checks."""
    r = gd.optimize_shifts(17, 26, m=8, objective=CustomObjective("min_da1", lambda g: g["da1"], "min"))
    g = np.linspace(-1.5, 3.0, 401)
    X1, X2 = np.meshgrid(g, g)
    geo = mesh_geometry(Mesh(17, 26), 8.0, X1, X2)
    ok = np.ones(X1.shape, bool)
    for c in gd.make_checks():
        with np.errstate(invalid="ignore"):
            ok &= np.nan_to_num(c.margin(geo), nan=-1.0) >= 0
    assert r.success and min(r.margins.values()) >= -1e-9
    assert r.fun <= geo["da1"][ok].min() + 1e-9

def test_objective_registry_and_refusals():
    assert set(OBJECTIVES) == {"max_x_sum", "max_eps_alpha", "balanced_sliding", "min_specific_pressure", "max_margin",
                               "balanced_root_strength", "max_min_safety", "max_life"}
    with pytest.raises(GearDesignError, match="objective must be one of"):
        gd.optimize_shifts(17, 26, objective="fastest")
    with pytest.raises(GearDesignError, match="sense must be 'max' or 'min'"):
        CustomObjective("x", lambda g: g["a"], sense="up")


def test_max_life_needs_a_spectrum():
    with pytest.raises(GearDesignError, match="objective 'max_life' needs a load spectrum: give the checks spectrum="):
        gd.optimize_shifts(20, 60, objective="max_life")


def test_max_life_is_the_longest_life_of_a_spectrum():
    """A one-bin spectrum (docs/life.md's pair): fun = ln(L/L_req) with L = L_req/max D of pair_life at the optimum,
    and no feasible node of a grid lives longer."""
    spec = gd.LoadSpectrum.from_bins([120.0], 1000, time_h=[20000.0])
    case = {"spectrum": spec, "material": "42CrMo4", "face_width_mm": 40.0, "damage_max": 10.0}
    res = gd.optimize_shifts(20, 60, m=4, checks=case, objective="max_life")
    assert res.success
    D = gd.pair_life(4.0, 20, 60, res.x1, res.x2, spectrum=spec, material1="42CrMo4", face_width_mm=40.0)
    worst = max(D[f"D_{m}"] for m in ("H1", "H2", "F1", "F2"))
    assert res.fun == pytest.approx(-np.log(worst), rel=1e-9)
    grid = np.linspace(-0.4, 1.6, 21)
    X1, X2 = (v.ravel() for v in np.meshgrid(grid, grid))
    ok = np.array([_holds(a, b) for a, b in zip(X1, X2)])
    out = gd.pair_life(4.0, 20, 60, X1[ok], X2[ok], spectrum=spec, material1="42CrMo4", face_width_mm=40.0)
    nodes = np.max([out[f"D_{m}"] for m in ("H1", "H2", "F1", "F2")], axis=0)
    assert ok.sum() > 20 and np.all(-np.log(nodes) <= res.fun + 1e-9)


def test_max_life_where_no_gear_takes_damage_says_the_life_is_unlimited():
    """A spectrum below every S-N curve's endurance (pair_life: D = 0 for both gears and modes at the optimum): fun
    is the cap −ln 1e-300, which ranks nothing; the message says so (a pair and a set). A spectrum that does damage
    does not get the note."""
    light = gd.LoadSpectrum.from_bins([20.0, 10.0], 1500, time_h=[2000.0, 3000.0])
    res = gd.optimize_shifts(20, 60, m=4, checks={"spectrum": light, "material": "18CrNiMo7-6", "face_width_mm": 40.0},
                             objective="max_life")
    D = gd.pair_life(4.0, 20, 60, res.x1, res.x2, spectrum=light, material1="18CrNiMo7-6", face_width_mm=40.0)
    assert all(D[f"D_{m}"] == 0 for m in ("H1", "H2", "F1", "F2"))
    assert res.fun == pytest.approx(-np.log(1e-300), rel=1e-12) and "life is unlimited" in res.message
    s = gd.optimize_planetary_shifts(20, 31, 82, 3, 2, objective="max_life", checks={
        "spectrum": light, "material": "18CrNiMo7-6", "face_width_mm": 40.0, "mean_stress_factor": 0.7})
    assert "life is unlimited" in s.message
    heavy = gd.LoadSpectrum.from_bins([120.0], 1000, time_h=[20000.0])
    res = gd.optimize_shifts(20, 60, m=4, objective="max_life", checks={
        "spectrum": heavy, "material": "42CrMo4", "face_width_mm": 40.0, "damage_max": 10.0})
    assert res.fun < 50 and "unlimited" not in res.message


def _holds(x1, x2) -> bool:
    """The default checks (a subset of the nodes the optimiser may reach: the table adds jamming)."""
    try:
        return bool(gd.GearPair(4, 20, 60, x1, x2).checks()["ok"].all())
    except GearDesignError:
        return False
