"""The table of shift solvers (geardesign.shifts.methods): its three built-in methods, a method added and taken
away, refusals, and each method's answer within its stated accuracy of the exact one (which tests/shifts/
test_optimize.py holds against a brute-force reference)."""
import pytest

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.shifts import grid
from geardesign.shifts.methods import ACCURACY, DEFAULT_TOL, METHOD_TABLE, METHODS, Method, register_method


def test_the_built_in_methods():
    assert METHODS[:3] == ["grid", "convex", "exact"]
    assert (DEFAULT_TOL["grid"], DEFAULT_TOL["convex"], DEFAULT_TOL["exact"]) == (1e-2, 1e-7, 1e-9)
    assert all("{tol:g}" in ACCURACY[m] or "1e-12" in ACCURACY[m] for m in METHODS[:3])
    assert set(METHOD_TABLE) >= set(METHODS[:3])


def test_each_method_within_its_accuracy_of_the_exact_optimum():
    exact = gd.optimize_shifts(17, 26, method="exact")
    convex = gd.optimize_shifts(17, 26, method="convex")
    coarse = gd.optimize_shifts(17, 26, method="grid")
    assert exact.success and convex.success and coarse.success
    assert abs(convex.x1 - exact.x1) < 1e-5 and abs(convex.x2 - exact.x2) < 1e-5
    assert abs(coarse.fun - exact.fun) <= 2 * DEFAULT_TOL["grid"] and coarse.fun <= exact.fun + 1e-12
    assert exact.margins["contact_ratio"] == pytest.approx(0.0, abs=1e-9)    # the active check is on its limit


def test_a_method_added_and_taken_away():
    register_method(Method("grid51", 0.05, "best node of a 51 x 51 grid",
                           lambda prob, bounds, tol, grid_n, start: grid.solve(prob, bounds, tol, 51)))
    try:
        r = gd.optimize_shifts(17, 26, method="grid51")
        assert r.method == "grid51" and r.success and DEFAULT_TOL["grid51"] == 0.05
        with pytest.raises(GearDesignError, match="exists already"):
            register_method(METHOD_TABLE["grid51"])
    finally:
        METHODS.remove("grid51")
        METHOD_TABLE.pop("grid51")
    with pytest.raises(GearDesignError, match="method"):
        gd.optimize_shifts(17, 26, method="grid51")


def test_only_a_method_registers():
    with pytest.raises(GearDesignError, match="register_method takes"):
        register_method(lambda *a: None)
