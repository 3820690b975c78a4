"""Optimal shifts of helical and internal pairs: the three methods against the brute-force reference
of tests/shifts/test_optimize.py (no gradients, no solver), a housing centre distance fixing
x_Σ = x2 − x1 of a ring pair, and the region and its conflicts for both kinds."""
import numpy as np
import pytest

import geardesign as gd
from geardesign.gears.mesh import Mesh
from tests.shifts.test_optimize import reference_optimum

KINDS = [  # (z1, z2, kind)
    (17, 26, dict(beta_deg=20.0)), (12, 40, dict(beta_deg=35.0)), (20, 60, dict(internal=True)),
    (16, 40, dict(internal=True, beta_deg=15.0)), (30, 90, dict(internal=True)),
]


@pytest.mark.slow
@pytest.mark.parametrize("z1, z2, kind", KINDS)
@pytest.mark.parametrize("objective, fun, sense", [
    ("max_x_sum", lambda g: g["_x2"] + g["_sgn"] * g["_x1"], +1),
    ("max_eps_alpha", lambda g: g["eps_alpha"], +1),
])
def test_exact_matches_the_brute_force_reference(z1, z2, kind, objective, fun, sense):
    mesh = Mesh(z1, z2, beta_deg=kind.get("beta_deg", 0.0), internal=kind.get("internal", False))
    x1, x2, best = reference_optimum(z1, z2, fun, sense=sense, mesh=mesh)
    r = gd.optimize_shifts(z1, z2, objective=objective, **kind)
    assert r.success
    assert sense * r.fun >= best - 1e-9                      # no feasible point the reference found is better
    assert abs(sense * r.fun - best) <= 1e-7
    if objective == "max_eps_alpha":                         # a strict optimum: the point itself agrees
        assert np.hypot(r.x1 - x1, r.x2 - x2) <= 1e-5


@pytest.mark.parametrize("z1, z2, kind", KINDS)
def test_the_three_methods_agree(z1, z2, kind):
    exact = gd.optimize_shifts(z1, z2, method="exact", **kind)
    convex = gd.optimize_shifts(z1, z2, method="convex", **kind)
    grid = gd.optimize_shifts(z1, z2, method="grid", **kind)
    assert abs(exact.fun - convex.fun) <= 1e-6 and abs(exact.fun - grid.fun) <= 0.03


def test_a_housing_fixes_x2_minus_x1_of_a_ring_pair():
    r = gd.optimize_shifts(20, 60, internal=True, a_w=41.0, m=2.0)
    assert r.success and abs(r.a_w - 41.0) <= 1e-9
    xs = gd.x_sum_from_center_distance(2.0, 20, 60, 41.0, internal=True)
    assert abs((r.x2 - r.x1) - xs) <= 1e-12
    g = gd.pair_geometry(2.0, 20, 60, r.x1, r.x2, internal=True)
    assert abs(g.sliding1_root - g.sliding2_root) <= 1e-7    # balanced sliding, the default on a fixed a_w
    with pytest.raises(gd.GearDesignError, match="out of reach"):
        gd.optimize_shifts(20, 60, internal=True, a_w=10.0, m=2.0)


def test_region_of_a_ring_pair_holds_its_optimum_and_an_infeasible_one_names_conflicts():
    reg = gd.feasible_region(20, 60, internal=True)
    r = gd.optimize_shifts(20, 60, internal=True)
    assert reg.feasible and reg.contains(r.x1 + 1e-6, r.x2 - 1e-3)
    tight = gd.optimize_shifts(20, 22, internal=True, checks={"eps_alpha_min": 2.2})
    assert not tight.success and "contact_ratio" in tight.conflict
    assert set(tight.conflict) <= {c.name for c in gd.make_checks(internal=True, eps_alpha_min=2.2)}
