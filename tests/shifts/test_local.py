"""Local solves (geardesign.shifts.local) on stand-in problems whose answers are known analytically
(tests/shifts/toy_problems.py): the most central point of a triangle is its incentre, SLSQP's max-min
optimum of x1 + x2 on a disc is (r/√2, r/√2), the window box and the evaluator's window rows."""
import math

import numpy as np
import pytest

from geardesign.shifts.local import Evaluator, MinMargin, central_point, slsqp, window_box
from geardesign.shifts.nodes import grid_points
from tests.shifts.toy_problems import Disk, Triangle


@pytest.mark.parametrize("a, s", [(0.0, 1.0), (0.2, 0.5), (-1.0, 2.5)])
def test_central_point_is_the_incentre(a, s):
    prob = Triangle(a, s)
    V = grid_points(prob, 31, (-1.5, 3.0))
    _, M = prob.evaluate(V, grads=False)
    w = central_point(prob, V, M, (-1.5, 3.0))
    rho = prob.inradius()
    np.testing.assert_allclose(w, [a + rho, a + rho, rho], atol=1e-7)


def test_central_point_of_a_region_thinner_than_the_grid():
    # legs 0.05 between nodes 0.15 apart (…, 0.3, 0.45, …): no node inside, the incentre still found
    prob = Triangle(0.31, 0.67)
    V = grid_points(prob, 31, (-1.5, 3.0))
    _, M = prob.evaluate(V, grads=False)
    assert (M.min(axis=0) < 0).all()
    w = central_point(prob, V, M, (-1.5, 3.0))
    rho = prob.inradius()
    assert rho > 0
    np.testing.assert_allclose(w, [0.31 + rho, 0.31 + rho, rho], atol=1e-7)


@pytest.mark.parametrize("r", [1.0, 0.4])
def test_slsqp_max_x_sum_on_a_disc(r):
    w, nit, ev, ok = slsqp(Disk(r), np.array([0.0, 0.0]), (-1.5, 3.0))
    np.testing.assert_allclose(w, [r / math.sqrt(2), r / math.sqrt(2), r * math.sqrt(2)], atol=1e-7)
    assert nit >= 1 and ev.nfev >= 1 and ev.missing == 0


def test_min_margin_sees_the_margins_as_pieces():
    prob = Triangle(0.0, 1.0)
    P, M, GP, GM = MinMargin(prob).evaluate_point([0.2, 0.3])
    np.testing.assert_allclose(P, [0.2, 0.3, 0.5 / math.sqrt(2)])
    assert M.size == 0 and GM.shape[0] == 0 and GP.shape == (3, 2)


def test_window_box_and_the_evaluators_window_rows():
    lo, hi = window_box(Disk(), (-1.5, 3.0))
    assert lo.tolist() == [-1.5, -1.5] and hi.tolist() == [3.0, 3.0]
    ev = Evaluator(Disk(), window=(lo, hi))
    _, M, _, GM = ev([0.5, -1.0])
    # the disc's margin, then v − lo, then hi − v
    np.testing.assert_allclose(M, [(1 - 0.25 - 1.0) / 2, 2.0, 0.5, 2.5, 4.0])
    np.testing.assert_array_equal(GM[1:], [[1, 0], [0, 1], [-1, 0], [0, -1]])
    ev([0.5, -1.0])
    assert ev.nfev == 1            # the second call at the same point is cached
