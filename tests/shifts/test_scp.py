"""Sequential convex programming (geardesign.shifts.scp.solve_convex) on stand-in problems with
analytic optima (tests/shifts/toy_problems.py): max x1 + x2 on a disc of radius r is (r/√2, r/√2)
(Lagrange: ∇(x1 + x2) = λ∇(x1² + x2²)), on a triangle the vertex set by its hypotenuse and the window."""
import math

import numpy as np
import pytest

from geardesign.shifts.scp import solve_convex
from tests.shifts.toy_problems import Disk, Triangle


# starts inside the disc, as the grid gives them (a start whose linearised margin cannot reach 0 within the
# first trust radius makes the subproblem infeasible and the solver stop where it started)
@pytest.mark.parametrize("r, start", [(1.0, (0.0, 0.0)), (0.6, (-0.3, 0.1)), (2.0, (1.0, -1.0))])
def test_disc_optimum(r, start):
    v, nit, lam_m, _ = solve_convex(Disk(r), np.array(start, dtype=float), (-1.5, 3.0), tol=1e-8)
    np.testing.assert_allclose(v, [r / math.sqrt(2), r / math.sqrt(2)], atol=1e-6)
    assert nit >= 1
    # the margin (r² − |x|²)/(2r) has gradient −x/r = −(1, 1)/√2 at the optimum; the multiplier that
    # balances the objective's (1, 1) against it is √2
    assert lam_m[0] == pytest.approx(math.sqrt(2), rel=1e-4)


def test_window_edge_bounds_the_optimum():
    # x1, x2 >= 0 and x1 + x2 <= 10: the hypotenuse lies outside the window [-1.5, 3]², so the
    # window's corner (3, 3) is the optimum
    v, _, _, _ = solve_convex(Triangle(0.0, 10.0), np.array([0.5, 0.5]), (-1.5, 3.0), tol=1e-8)
    np.testing.assert_allclose(v, [3.0, 3.0], atol=1e-7)


def test_convex_solves_with_the_radial_assembly_check():
    """Issue 29 §3.4: the radial-assembly gradient (central differences) stepped over the domain edge
    of its arcsines and handed NaN to cvxpy ("Parameter value must be real"); exact solved it."""
    import geardesign as gd
    kw = dict(internal=True, checks={"radial_assembly": True})
    ref = gd.optimize_shifts(30, 90, method="exact", **kw)
    r = gd.optimize_shifts(30, 90, method="convex", **kw)
    assert r.success and ref.success
    assert (r.x1, r.x2) == pytest.approx((ref.x1, ref.x2), abs=1e-6)


@pytest.mark.parametrize("z1, z2, kw", [
    (10, 23, dict(internal=True, objective="max_margin", checks={"eps_alpha_min": None})),
    (11, 33, dict(internal=True, beta_deg=15.0, objective="max_margin")),
])
def test_convex_subproblems_are_solved_accurately_and_quietly(z1, z2, kw):
    """Issue 29 §3.13: Clarabel was asked for a 1e-12 gap it cannot reach on these subproblems, and
    cvxpy warned "Solution may be inaccurate" beside a plain success. The optimum value agrees with
    exact's (the x2 of a max_margin optimum may slide along a flat ridge, so the value is compared)."""
    import warnings
    import geardesign as gd
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = gd.optimize_shifts(z1, z2, method="convex", **kw)
    ref = gd.optimize_shifts(z1, z2, method="exact", **kw)
    assert r.success and "inaccurate" not in r.message
    assert r.fun == pytest.approx(ref.fun, abs=1e-9)


def test_an_inaccurate_subproblem_is_said_in_the_message(monkeypatch):
    """Where the solver still calls a subproblem inaccurate, the result says so (not a plain success)."""
    import cvxpy as cp
    import geardesign as gd
    solve = cp.Problem.solve

    def inaccurate(self, *a, **k):
        out = solve(self, *a, **k)
        self._status = "optimal_inaccurate"
        return out
    monkeypatch.setattr(cp.Problem, "solve", inaccurate)
    monkeypatch.setattr(cp.Problem, "status", property(lambda self: getattr(self, "_status", None)))
    r = gd.optimize_shifts(17, 26, method="convex")
    assert "solved only inaccurately" in r.message
