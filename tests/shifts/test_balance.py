"""The exact method's short cut on a fixed-a_w line (geardesign.shifts.balance): equal root sliding where no
check is active, a single check's boundary where one stops the line.

References: the exact method's own active-set search (kkt.py from the 401-node start grid of the line, run here
with the short cut switched off: a different algorithm), and a 20 001-node grid of the line evaluated with
Problem.evaluate (no solver): no feasible node may beat the optimum. Issue 35 §5: a drive sizing gear stages on a
standard housing solves ~600 such lines; the short cut must give the search's answer, not a nearby one.
"""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.gears.checks import FEASIBILITY_TOL
from geardesign.gears.mesh import Mesh
from geardesign.shifts import balance, methods
from geardesign.shifts.optimize import optimize_shifts
from geardesign.gears.center_distance import center_distance_from_x_sum
from geardesign.gears.pair import GearPair
from geardesign.shifts.problem import Problem

REDUCER_WINDOW = (-1.2, 1.2)


def _solve(z1, z2, x_sum, beta_deg):
    a_w = float(center_distance_from_x_sum(1.0, z1, z2, x_sum, beta_deg=beta_deg))
    return optimize_shifts(z1, z2, None, None, "exact", m=1.0, a_w=a_w, beta_deg=beta_deg, face_width_mm=20.0,
                           bounds=REDUCER_WINDOW)


def _without_short_cut(monkeypatch, *args):
    with monkeypatch.context() as mp:
        mp.setattr(balance, "serves", lambda prob: False)
        return _solve(*args)


def _grid_best(z1, z2, x_sum, beta_deg):
    """The best feasible node of a fine grid of the line: (x1, min piece), by Problem.evaluate."""
    a_w = float(center_distance_from_x_sum(1.0, z1, z2, x_sum, beta_deg=beta_deg))
    r = optimize_shifts(z1, z2, None, None, "grid", m=1.0, a_w=a_w, beta_deg=beta_deg, face_width_mm=20.0,
                        bounds=REDUCER_WINDOW)
    prob = Problem(Mesh(z1, z2, beta_deg=beta_deg, face_width_mm=20.0), None, "balanced_sliding", 1.0, r.x1 + r.x2)
    lo, hi = prob.x1_on_line(*REDUCER_WINDOW)
    x = np.linspace(lo, hi, 20001)
    P, M = prob.evaluate(x[:, None], grads=False)
    ok = M.min(axis=0) >= 0
    f = P.min(axis=0)
    return (x[ok][np.argmax(f[ok])], f[ok].max()) if ok.any() else (None, None)


CASES = [(20, 79, 0.2, 0.0),      # an interior crossing: no check active
         (17, 74, 0.1, 0.0),
         (25, 61, 0.55, 10.0)]    # helical


@pytest.mark.parametrize("z1, z2, x_sum, beta", CASES)
def test_interior_crossing_is_equal_sliding(monkeypatch, z1, z2, x_sum, beta):
    r = _solve(z1, z2, x_sum, beta)
    assert r.success and r.message.startswith("converged: equal root sliding")
    geo = GearPair(1.0, z1, z2, r.x1, r.x2, beta_deg=beta, face_width_mm=20.0).geometry()
    assert geo.sliding1_root == pytest.approx(geo.sliding2_root, rel=1e-11)
    assert r.x1 + r.x2 == pytest.approx(x_sum, abs=1e-12)
    ref = _without_short_cut(monkeypatch, z1, z2, x_sum, beta)
    assert (r.x1, r.x2) == pytest.approx((ref.x1, ref.x2), abs=1e-9)
    assert r.active == ref.active == []


def test_a_check_stopping_the_line_is_its_boundary(monkeypatch):
    # 17/74 at x_Σ = −0.45: equal sliding wants x1 below gear 1's interference limit (a 75 kW stage's case)
    r = _solve(17, 74, -0.45, 0.0)
    assert r.success and "stops the fixed-a_w line" in r.message
    name = r.message.split(" stops")[0].removeprefix("converged: ")
    assert r.active == [name] and abs(r.margins[name]) < 1e-9
    ref = _without_short_cut(monkeypatch, 17, 74, -0.45, 0.0)
    assert (r.x1, r.x2) == pytest.approx((ref.x1, ref.x2), abs=1e-9)
    x_best, f_best = _grid_best(17, 74, -0.45, 0.0)
    assert r.x1 == pytest.approx(x_best, abs=2.4 / 20000)


@settings(max_examples=60, deadline=None)
@given(z1=st.integers(12, 45), dz=st.integers(0, 120), x_sum=st.floats(-0.5, 1.0), beta=st.sampled_from([0.0, 12.0]))
def test_short_cut_equals_the_active_set_search(z1, dz, x_sum, beta):
    z2 = z1 + dz
    r = _solve(z1, z2, x_sum, beta)
    orig = balance.serves
    balance.serves = lambda prob: False
    try:
        ref = _solve(z1, z2, x_sum, beta)
    finally:
        balance.serves = orig
    assert r.success == ref.success
    if r.success:
        assert (r.x1, r.x2) == pytest.approx((ref.x1, ref.x2), abs=1e-9)
        assert min(r.margins.values()) >= -FEASIBILITY_TOL


def test_the_short_cut_is_the_exact_methods_own():
    assert methods.METHOD_TABLE["exact"].solve.__module__ == methods.__name__
    assert balance.serves.__doc__ and "fixed-a_w line" in balance.serves.__doc__
