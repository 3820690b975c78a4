"""Optimal shifts: the three methods against an independent brute-force reference.

The reference (written here) uses no gradients and no solver: a dense grid over the window,
then repeated zooming grids around the best feasible node, with the exact margins of
geardesign.gears.checks (the geometry under them is tested against mpmath in test_extremes.py).
"""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import geardesign as gd
from geardesign import checks as ck
from geardesign.gears.geometry import mesh_geometry
from geardesign.gears.mesh import Mesh


def reference_optimum(z1, z2, fun, checks=None, sense=+1, lo=-1.5, hi=3.0, n=41, levels=34, mesh=None):
    """Nested zooming grids: for every x1 node, the best feasible x2 (inner zoom, all x1 nodes
    at once); then zoom in x1 around the best of those. The value of the inner problem is a
    smooth function of x1, so the outer zoom converges even when the optimum slides along a
    curved boundary (where a plain 2-D zoom stalls at ~√(grid step))."""
    mesh = Mesh(z1, z2, gd.BasicRack(), True) if mesh is None else mesh
    cs = ck.resolve_checks(checks, internal=mesh.internal)

    def scores(X1, X2):
        geo = mesh_geometry(mesh, 1.0, X1, X2)
        ok = np.ones(X1.shape, bool)
        for c in cs:
            ok &= np.nan_to_num(c.margin(geo), nan=-1.0) >= 0
        return np.where(ok, sense * fun(geo), -np.inf)

    def inner(x1):
        # best x2 for each x1: a dense first look, then zoom around each row's best node
        c2 = np.full(x1.shape, (lo + hi) / 2)
        half = np.full(x1.shape, (hi - lo) / 2)
        for level in range(levels):
            X2 = c2[:, None] + half[:, None] * np.linspace(-1, 1, 12 * n if level == 0 else n)[None, :]
            X2 = np.clip(X2, lo, hi)     # the zoom stays inside the window
            X1 = np.broadcast_to(x1[:, None], X2.shape)
            s = scores(X1, X2)
            j = np.argmax(s, axis=1)
            c2 = X2[np.arange(len(x1)), j]
            half = half * (0.05 if level == 0 else 0.35)
        return c2, scores(x1, c2)

    c1, half1 = (lo + hi) / 2, (hi - lo) / 2
    for level in range(levels):
        x1 = np.clip(c1 + half1 * np.linspace(-1, 1, 12 * n if level == 0 else n), lo, hi)
        x2, s = inner(x1)
        i = int(np.argmax(s))
        assert np.isfinite(s[i]), "reference found no feasible point"
        c1, best = x1[i], (x1[i], x2[i], s[i])
        half1 *= 0.05 if level == 0 else 0.35
    return best


PAIRS = [(17, 26), (12, 24), (10, 40), (30, 90), (20, 20), (14, 60), (25, 31), (40, 120)]


@pytest.mark.parametrize("z1,z2", PAIRS)
def test_max_x_sum_matches_reference(z1, z2):
    ref = reference_optimum(z1, z2, lambda g: g["_x1"] + g["_x2"])
    r = gd.optimize_shifts(z1, z2, "max_x_sum", method="exact")
    assert r.success
    assert abs(r.x1 - ref[0]) < 1e-6 and abs(r.x2 - ref[1]) < 1e-6
    assert r.fun >= ref[2] - 1e-9           # never worse than the reference


@pytest.mark.slow
@pytest.mark.parametrize("z1,z2", PAIRS[:5])
def test_max_eps_alpha_matches_reference(z1, z2):
    ref = reference_optimum(z1, z2, lambda g: g["eps_alpha"])
    r = gd.optimize_shifts(z1, z2, "max_eps_alpha", method="exact")
    assert abs(r.x1 - ref[0]) < 1e-6 and abs(r.x2 - ref[1]) < 1e-6


@pytest.mark.slow
@pytest.mark.parametrize("z1,z2", [(17, 26), (12, 24), (30, 90)])
def test_balanced_sliding_matches_reference(z1, z2):
    ref = reference_optimum(z1, z2, lambda g: np.maximum(abs(g["sliding1_root"]), abs(g["sliding2_root"])), sense=-1)
    r = gd.optimize_shifts(z1, z2, "balanced_sliding", method="exact")
    assert abs(r.x1 - ref[0]) < 1e-6 and abs(r.x2 - ref[1]) < 1e-6


def test_optimum_on_the_window_edge_matches_reference():
    """With ε_α >= 1.0 alone, 40/120 runs into the window (x2 = 3): a vertex of the window's
    edge and the contact ratio, which the exact method solves like any other vertex."""
    checks = (ck.ContactRatio(limit=1.0),)
    ref = reference_optimum(40, 120, lambda g: g["_x1"] + g["_x2"], checks=checks)
    r = gd.optimize_shifts(40, 120, "max_x_sum", checks=checks)
    assert r.success and "grid node" in r.message
    assert abs(r.x2 - 3.0) < 1e-12 and r.active == ["contact_ratio"]
    assert abs(r.x1 - ref[0]) < 1e-6 and abs(r.x2 - ref[1]) < 1e-6


def test_custom_check_with_difference_gradients_matches_reference():
    """A user's check (no analytic gradient: central differences) limiting the centre distance."""
    a_w_max = ck.CustomCheck(name="a_w_max", func=lambda g: g["a_w"], limit=22.2, sense="<=")
    checks = ck.make_checks(extra=(a_w_max,))
    ref = reference_optimum(17, 26, lambda g: g["eps_alpha"], checks=checks)
    r = gd.optimize_shifts(17, 26, "max_eps_alpha", checks=checks)
    assert r.success
    assert abs(r.x1 - ref[0]) < 1e-6 and abs(r.x2 - ref[1]) < 1e-6


@pytest.mark.parametrize("z1,z2", PAIRS[:5] + [(8, 40)])
@pytest.mark.parametrize("objective", ["max_x_sum", "max_eps_alpha", "balanced_sliding",
                                       "min_specific_pressure", "max_margin"])
def test_three_methods_agree_within_their_tolerance(z1, z2, objective):
    exact = gd.optimize_shifts(z1, z2, objective, method="exact")
    convex = gd.optimize_shifts(z1, z2, objective, method="convex", tol=1e-7)
    grid = gd.optimize_shifts(z1, z2, objective, method="grid", tol=0.01)
    assert exact.success and convex.success and grid.success
    for r in (exact, convex, grid):
        # every returned point satisfies the exact checks to within its tolerance
        assert min(r.margins.values()) >= -r.tol
    # the convex answer agrees with exact within its tolerance (1e-7) in x
    assert abs(convex.fun - exact.fun) <= 1e-7 * max(1.0, abs(exact.fun))
    assert np.hypot(convex.x1 - exact.x1, convex.x2 - exact.x2) < 1e-7
    # the grid answer: its objective is within one grid step's worth of the optimum
    assert exact.objective == grid.objective
    if objective != "max_margin":
        sign = 1 if objective.startswith("max") else -1
        assert sign * (exact.fun - grid.fun) >= -1e-9


def test_seed000_shifts_are_outside_and_eps_is_why():
    # Seed 000 took x 0.898/0.517 from Kudryavtsev's tables; with GOST tip shortening ε_α = 1.153.
    pair = gd.GearPair(8, 17, 26, 0.898, 0.517)
    failing = pair.checks().query("not ok")["check"].tolist()
    assert failing == ["contact_ratio"]
    r = gd.optimize_shifts(17, 26, "max_x_sum", m=8)
    assert r.success and min(r.margins.values()) >= -1e-9
    assert r.active == ["contact_ratio"]                # ε_α = 1.2 is what limits the x-sum
    assert r.x1 + r.x2 < 0.898 + 0.517
    # at m = 8 the optimum holds every check (ε_α = 1.2 to the last ulp)
    assert (gd.GearPair(8, 17, 26, r.x1, r.x2).checks()["margin"] >= -1e-12).all()


def test_limits_change_the_answer():
    base = gd.optimize_shifts(30, 90, "max_x_sum")
    hard = gd.optimize_shifts(30, 90, "max_x_sum", checks={"sa_min": 0.4})
    assert hard.margins["tip_thickness1"] >= -1e-9 and hard.margins["tip_thickness2"] >= -1e-9
    loose = gd.optimize_shifts(30, 90, "max_x_sum", checks={"eps_alpha_min": 1.1})
    assert loose.fun >= base.fun - 1e-12
    # sensitivity of the optimum to the active ε limit matches a finite difference
    if "contact_ratio" in base.active:
        h = 1e-4
        up = gd.optimize_shifts(30, 90, "max_x_sum", checks={"eps_alpha_min": 1.2 + h})
        fd = (up.fun - base.fun) / h
        assert base.sensitivity["contact_ratio"] == pytest.approx(fd, rel=1e-3)


def test_bad_arguments():
    with pytest.raises(gd.GearDesignError, match="objective must be one of"):
        gd.optimize_shifts(17, 26, "max_fun")
    with pytest.raises(gd.GearDesignError, match="method must be one of"):
        gd.optimize_shifts(17, 26, method="magic")
    with pytest.raises(gd.GearDesignError, match=r"a_w \(center distance\) = 10 mm is out of reach: it must be in \(20\.2033"):
        gd.optimize_shifts(17, 26, a_w=10, m=1)


def test_margins_at_the_optimum_show_zero_not_rounding():
    r = gd.optimize_shifts(17, 26)
    assert r.margins["contact_ratio"] == 0.0
    assert "-2.7" not in repr(r) and "e-16" not in repr(r)


@settings(max_examples=12, deadline=None, derandomize=True)
@given(z1=st.integers(10, 40), dz=st.integers(0, 80),
       objective=st.sampled_from(["max_x_sum", "max_eps_alpha", "balanced_sliding"]),
       method=st.sampled_from(["exact", "convex"]))
def test_no_feasible_neighbour_is_better(z1, dz, objective, method):
    """Property: the returned point holds every check to within tol, and no feasible point
    in a small neighbourhood beats it by more than the tolerance (sign by the objective's sense)."""
    z2 = z1 + dz
    r = gd.optimize_shifts(z1, z2, objective, method=method)
    if not r.success:
        assert r.conflict
        return
    assert min(r.margins.values()) >= -r.tol
    cs = ck.make_checks()
    rng = np.random.default_rng(z1 * 1000 + z2)
    for radius in (1e-2, 1e-4):
        pts = np.array([r.x1, r.x2]) + rng.uniform(-radius, radius, (400, 2))
        geo = mesh_geometry(Mesh(z1, z2, gd.BasicRack(), True), 1.0, pts[:, 0], pts[:, 1])
        ok = np.all([np.nan_to_num(c.margin(geo), nan=-1) >= 0 for c in cs], axis=0)
        if objective == "max_x_sum":
            f = geo["_x1"] + geo["_x2"]
        elif objective == "max_eps_alpha":
            f = geo["eps_alpha"]
        else:
            f = -np.maximum(abs(geo["sliding1_root"]), abs(geo["sliding2_root"]))
        fun = r.fun if objective != "balanced_sliding" else -r.fun
        assert (f[ok] <= fun + 1e-9).all()


# --- issue 29 §3: defects found by generated input ------------------------------------------

@pytest.mark.parametrize("method", ["exact", "convex", "grid"])
@pytest.mark.parametrize("z1, z2, kind, checks", [
    (25, 26, dict(internal=True), {"eps_alpha_min": None}),      # issue 29 §3.1: returned eps_alpha -0.419
    (17, 26, {}, []),                                             # every check dropped
    (30, 90, dict(internal=True), {"eps_alpha_min": None, "sa_min": None}),
    (12, 14, dict(beta_deg=20.0), {"eps_alpha_min": None, "undercut": False}),
])
def test_a_solution_always_meshes_whatever_checks_are_dropped(z1, z2, kind, checks, method):
    """Meshing is a condition of existence: GearPair (which refuses gears whose tips do not overlap
    along the line of action) must accept every design a solver calls a success."""
    r = gd.optimize_shifts(z1, z2, checks=checks, method=method, **kind)
    assert r.success, r.message
    pair = gd.GearPair(1, z1, z2, r.x1, r.x2, **kind)      # raises "the gears do not mesh" otherwise
    assert pair.geometry().g_alpha > 0 and r.eps_alpha > 0
