"""The single-design float path of the shift problem agrees with the vectorised array path.

The local solvers evaluate one design at a time in Python floats (:meth:`Problem.evaluate_point`)
because a one-element numpy call costs ~20× more. Both run the same formulas on different
backends; these tests hold them together. The analytic gradients of the objective pieces are
held against central differences.
"""
from __future__ import annotations

import numpy as np
from hypothesis import assume, given
from hypothesis import strategies as st

from geardesign.gears.checks import CustomCheck, make_checks
from geardesign.gears.geometry import mesh_geometry_float
from geardesign.gears.mesh import Mesh
from geardesign.shifts.objectives import OBJECTIVES
from geardesign.shifts.problem import Problem

from tests.strategies import SETTINGS, designs


@SETTINGS
@given(z1=st.integers(8, 150), z2=st.integers(8, 300), x1=st.floats(-0.5, 1.5), x2=st.floats(-0.5, 1.5),
       objective=st.sampled_from(sorted(o for o in OBJECTIVES if not OBJECTIVES[o].needs_load)), fixed=st.booleans())
def test_evaluate_point_equals_evaluate(z1, z2, x1, x2, objective, fixed):
    """The float path gives the checks as smooth parts: the smallest part of each check is its
    margin, and that part's gradient is the check's gradient."""
    extra = (CustomCheck(name="a_w_max", func=lambda g: g["a_w"], limit=1e4, sense="<="),)
    prob = Problem(Mesh(z1, z2), checks=make_checks(extra=extra), objective=objective,
                   x_sum=(x1 + x2) if fixed else None)
    v = np.array([x1] if fixed else [x1, x2])
    P, M, GP, GM = (a[..., 0] for a in prob.evaluate(v[None, :]))
    fP, fM, fGP, fGM = prob.evaluate_point(v)
    assume(np.isfinite(M).all())
    # finite differences (custom check, max_margin pieces) agree to their own precision
    if objective == "max_margin":   # pieces per part there: the same smallest piece
        assert abs(fP.min() - P.min()) <= 1e-7 * max(1.0, abs(P.min()))
    else:
        assert np.allclose(fP, P, rtol=1e-7, atol=1e-7) and np.allclose(fGP, GP, rtol=1e-7, atol=1e-7)
    part_check = np.array(prob.part_check)
    for i in range(len(prob.checks)):
        parts = np.flatnonzero(part_check == i)
        j = parts[np.argmin(fM[parts])]
        assert abs(fM[j] - M[i]) <= 1e-12 * max(1.0, abs(M[i])), (prob.names[i], fM[parts], M[i])
        gap = np.sort(fM[parts])[1] - fM[j] if parts.size > 1 else np.inf
        # a custom check's gradient is a central difference (step 1e-6) on each path: the paths' values
        # agree to ~1e-14 relative, which the difference amplifies to ~1e-14·|margin|/1e-6
        tol = 1e-8 * max(1.0, abs(M[i])) if isinstance(prob.checks[i], CustomCheck) else 1e-7
        if gap > 1e-9:   # off the kink, the gradient is that part's
            assert np.allclose(fGM[j], GM[i], rtol=1e-7, atol=tol), (prob.names[i], fGM[j], GM[i])


@SETTINGS
@given(designs())
def test_piece_gradients_match_central_differences(d):
    """Analytic gradients of the pieces (specific sliding, ε_α, specific pressure)."""
    g = d["geo"]
    assume(min(abs(g.rho_p1), abs(g.rho_p2)) > 1e-3 * d["m"])
    assume(min(abs(g.sliding1_root), abs(g.sliding2_root)) > 1e-6)
    h = 1e-6
    for objective in ("balanced_sliding", "max_eps_alpha", "min_specific_pressure"):
        prob = Problem(Mesh(d["z1"], d["z2"], d["rack"], d["ts"]), objective=objective, m=d["m"])
        geo = mesh_geometry_float(Mesh(d["z1"], d["z2"], d["rack"], d["ts"]), d["m"], d["x1"], d["x2"])
        an = np.array(prob._piece_gradient_values(geo), dtype=float)
        for j, (dx1, dx2) in enumerate(((h, 0.0), (0.0, h))):
            up = np.array(prob._piece_values(prob.geo(d["x1"] + dx1, d["x2"] + dx2)), dtype=float)
            dn = np.array(prob._piece_values(prob.geo(d["x1"] - dx1, d["x2"] - dx2)), dtype=float)
            fd = (up - dn) / (2 * h)
            scale = np.maximum(1.0, np.abs(fd))
            # conditioning of the difference: the pieces are O(|piece|), the step 1e-6
            tol = 1e-6 * scale + 1e-9 * np.abs(up) / h
            assert (np.abs(an[:, j] - fd) <= tol).all(), (objective, j, an[:, j], fd)


def test_a_grid_of_one_pair_gives_each_designs_own_margins_and_pieces():
    """Problem.evaluate without gradients on one pair's grid (its tooth-count fields then numbers, its
    operating angle once per x-sum diagonal, or once on a fixed-a_w line) gives every node bit for bit
    what the node gets evaluated alone, with the tooth counts as arrays (the general path)."""
    from geardesign.gears.geometry import mesh_geometry
    from geardesign.shifts.nodes import grid_points

    for mesh, objective, x_sum in ((Mesh(17, 26, None, True), "max_x_sum", None),
                                   (Mesh(20, 60, None, True, 0.0, True), "balanced_sliding", None),
                                   (Mesh(14, 41, None, True, 15.0, False, 20.0), "min_specific_pressure", None),
                                   (Mesh(17, 26, None, True), "balanced_sliding", 0.7)):
        prob = Problem(mesh, None, objective, 2.0, x_sum=x_sum)
        V = grid_points(prob, 31 if x_sum is None else 41, (-1.5, 3.0))
        P, M = prob.evaluate(V, grads=False)
        x1, x2 = prob.xy(V)
        for i in range(0, V.shape[0], 29):
            one = mesh.unchecked(np.array([mesh.z1]), np.array([mesh.z2]))
            geo = mesh_geometry(one, np.array([2.0]), x1[i:i + 1], x2[i:i + 1], prob.full)
            np.testing.assert_array_equal(M[:, i], prob.margins(geo)[:, 0])
            np.testing.assert_array_equal(P[:, i], prob.pieces(geo)[:, 0])


def test_central_differences_turn_one_sided_at_a_domain_edge():
    """A check that exists only on one side of a line (an arcsine's argument reaching 1, as the
    radial-assembly margin): within the difference step of the edge the gradient comes from the side
    where it exists, never NaN (issue 29 §3.4). Here margin = 2 x1 + 3 x2 for x1 >= 0.3, else NaN."""
    import numpy as np
    import pytest
    from geardesign.gears.checks import CustomCheck
    from geardesign.gears.mesh import Mesh
    from geardesign.shifts.problem import Problem

    def func(geo):
        x1, x2 = np.asarray(geo["_x1"], float), np.asarray(geo["_x2"], float)
        return np.where(x1 >= 0.3, 2.0 * x1 + 3.0 * x2, np.nan)

    prob = Problem(Mesh(17, 26), [CustomCheck(name="edge", func=func, limit=0.0)], "max_x_sum")
    for x1 in (0.3 + 2e-7, 0.3 + 5e-7, 0.5):
        _, (_, _, _, GM) = prob.evaluate_design(x1, 0.2)
        k = prob.names.index("edge")
        assert GM[k] == pytest.approx([2.0, 3.0], rel=1e-6)


def test_a_flat_holding_margin_is_far_from_its_boundary():
    """Regression: a check that holds with no gradient (a root damage sum of 0 wherever the stress stays below the
    S-N curve's end) had distance −inf, so max_margin with the damage checks stopped with "no finite result"; it
    is FLAT_DISTANCE away (the other checks decide), and the optimum is the max_margin of the checks that move."""
    import geardesign as gd
    from geardesign.shifts.problem import FLAT_DISTANCE, _normalise

    P = _normalise(np.array([0.5, 1.0, -0.2, 0.0]), np.array([[1.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0]]))
    assert P.tolist() == [0.5, FLAT_DISTANCE, -np.inf, -np.inf]
    spec = gd.LoadSpectrum.from_bins([120, 90, 60], 1000, time_h=[2000, 8000, 10000])
    r = gd.optimize_shifts(20, 60, m=4, checks={"spectrum": spec, "material": "42CrMo4", "face_width_mm": 40.0},
                           objective="max_margin")
    assert r.success and r.margins["root_damage1"] == 1.0 and r.margins["root_damage2"] == 1.0
    assert r.fun < FLAT_DISTANCE and min(r.margins.values()) > 0
