"""Nodes of the shift plane (geardesign.shifts.nodes): the grid's x-sums exact (checked in rational
arithmetic with fractions.Fraction), its ends at the window's, and the best feasible node against a
brute-force scan written here on a problem with an analytic feasible set (tests/shifts/toy_problems.py)."""
import itertools
from fractions import Fraction

import numpy as np
import pytest

from geardesign.shifts.nodes import START_N, best_feasible, grid_points, grid_starts
from tests.shifts.toy_problems import Disk, Triangle


@pytest.mark.parametrize("lo, hi, n", [(-1.5, 3.0, START_N), (-1.0, 1.0, 7), (-0.3, 2.7, 12), (0.1, 0.2, 101)])
def test_grid_nodes_sum_exactly_and_span_the_window(lo, hi, n):
    V = grid_points(Disk(), n, (lo, hi))
    assert V.shape == (n * n, 2)
    g = V[::n, 0]
    np.testing.assert_array_equal(V[:n, 1], g)          # x1 rows (ij order), x2 the same nodes
    assert lo <= g[0] and g[-1] <= hi
    assert g[0] - lo <= n * 2.0 ** -40 and hi - g[-1] <= n * 2.0 ** -40
    assert np.all(np.diff(g) > 0)
    for a, b in itertools.combinations_with_replacement(g.tolist(), 2):
        assert Fraction(a + b) == Fraction(a) + Fraction(b)
        assert Fraction(a - b) == Fraction(a) - Fraction(b)


def test_equal_sums_are_bitwise_equal_along_each_diagonal():
    n = 41
    V = grid_points(Disk(), n, (-1.5, 3.0))
    s = (V[:, 0] + V[:, 1]).reshape(n, n)
    for k in range(2 * n - 1):       # the anti-diagonal i + j = k has one x-sum
        vals = {s[i, k - i] for i in range(max(0, k - n + 1), min(n, k + 1))}
        assert len(vals) == 1


@pytest.mark.parametrize("prob", [Disk(1.0), Disk(0.37), Triangle(0.1, 1.3)])
def test_best_feasible_is_the_brute_force_best_node(prob):
    V = grid_points(prob, 61, (-1.5, 3.0))
    i, P, M = best_feasible(prob, V)
    best, best_j = -np.inf, None
    for j, (x1, x2) in enumerate(V.tolist()):
        if isinstance(prob, Disk):
            ok = x1 * x1 + x2 * x2 <= prob.r ** 2
        else:
            ok = x1 >= prob.a and x2 >= prob.a and x1 + x2 <= prob.s
        if ok and x1 + x2 > best:
            best, best_j = x1 + x2, j
    assert best_j is not None and i is not None and V[i, 0] + V[i, 1] == best
    assert (M[:, i] >= 0).all()


def test_best_feasible_is_none_on_an_empty_set():
    prob = Triangle(a=1.0, s=1.5)       # x1 >= 1, x2 >= 1, x1 + x2 <= 1.5: empty
    i, _, M = best_feasible(prob, grid_points(prob, 31, (-1.5, 3.0)))
    assert i is None and (M.min(axis=0) < 0).all()


def test_grid_starts_one_per_separate_piece_best_first():
    # two disjoint feasible discs: margins max over the two of (r² − |x − c|²)/(2r)
    class TwoDiscs(Disk):
        centres = np.array([[-1.0, -1.0], [2.0, 2.0]])

        def evaluate(self, V, grads=False):
            V = np.atleast_2d(V)
            d2 = ((V[None, :, :] - self.centres[:, None, :]) ** 2).sum(axis=2)
            return (V[:, 0] + V[:, 1])[None, :], ((0.3 ** 2 - d2) / 0.6).max(axis=0)[None, :]

    n = 31
    V = grid_points(TwoDiscs(), n, (-1.5, 3.0))
    starts, _, _ = grid_starts(TwoDiscs(), V, n)
    assert len(starts) == 2
    near = [int(np.argmin(((TwoDiscs.centres - s) ** 2).sum(axis=1))) for s in starts]
    assert near == [1, 0]          # the upper disc has the larger x1 + x2: first
    for s in starts:
        assert np.min(((TwoDiscs.centres - s) ** 2).sum(axis=1)) <= 0.3 ** 2
    # each piece's ceiling is at least the most x1 + x2 reaches on its disc (c1 + c2 + r√2, exact), and the
    # lower disc's is below the upper disc's best node: its start need not be solved
    ceilings = grid_starts(TwoDiscs(), V, n)[2]
    for c, centre in zip(ceilings, TwoDiscs.centres[[1, 0]]):
        assert c >= centre.sum() + 0.3 * np.sqrt(2)
    assert ceilings[1] < starts[0].sum()

