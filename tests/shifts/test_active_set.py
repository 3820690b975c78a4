"""The small dense algebra of one active set (geardesign.shifts.active_set) against numpy.linalg:
solve_small against numpy.linalg.solve, the rows' layout written out, and the multipliers against a
least-squares solve of the stationarity condition built here."""
import numpy as np
import pytest

from geardesign.shifts.active_set import active_rows, multipliers, solve_small


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_solve_small_matches_numpy_on_random_systems(n):
    rng = np.random.default_rng(11 + n)
    for _ in range(200):
        A = rng.standard_normal((n, n))
        b = rng.standard_normal(n)
        if np.linalg.cond(A) > 1e8:
            continue
        ours = np.array(solve_small(A.tolist(), b.tolist()))
        np.testing.assert_allclose(ours, np.linalg.solve(A, b), rtol=1e-9, atol=1e-12 * np.abs(ours).max())


def test_solve_small_pivots_on_a_zero_leading_entry():
    # without row exchanges the first pivot would be 0: [[0, 1], [1, 0]] x = [2, 3] -> x = (3, 2)
    assert solve_small([[0.0, 1.0], [1.0, 0.0]], [2.0, 3.0]) == [3.0, 2.0]


def test_solve_small_leaves_its_arguments_alone_and_refuses_singular():
    A, b = [[2.0, 1.0], [1.0, 3.0]], [1.0, 2.0]
    solve_small(A, b)
    assert A == [[2.0, 1.0], [1.0, 3.0]] and b == [1.0, 2.0]
    with pytest.raises(np.linalg.LinAlgError):
        solve_small([[1.0, 2.0], [2.0, 4.0]], [1.0, 2.0])


@pytest.mark.parametrize("order", [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)])
def test_solve_small_three_rows_pivot_in_every_order(order):
    # a permuted identity (each pivot search meets zeros first), scaled rows: x is exact
    A = [[0.0, 0.0, 0.0] for _ in range(3)]
    for row, col in enumerate(order):
        A[row][col] = 2.0 ** (row + 1)
    b = [2.0 ** (row + 1) * (col + 1) for row, col in enumerate(order)]
    assert solve_small(A, b) == [1.0, 2.0, 3.0]


@pytest.mark.parametrize("A", [[[1.0, 2.0, 3.0], [2.0, 4.0, 6.0], [0.0, 1.0, 1.0]],
                               [[1.0, 2.0, 3.0], [0.0, 1.0, 1.0], [1.0, 3.0, 4.0]],
                               [[0.0, 1.0, 2.0], [0.0, 3.0, 1.0], [0.0, 1.0, 5.0]]])
def test_solve_small_refuses_singular_three_row_systems(A):
    with pytest.raises(np.linalg.LinAlgError):
        solve_small(A, [1.0, 2.0, 3.0])


def test_active_rows_are_piece_minus_t_then_margins():
    GP = np.array([[1.0, 2.0], [3.0, 4.0]])
    GM = np.array([[5.0, 6.0], [7.0, 8.0], [9.0, 10.0]])
    assert active_rows(GP, GM, [1], [0, 2]) == [[3.0, 4.0, -1.0], [5.0, 6.0, 0.0], [9.0, 10.0, 0.0]]


class _Linear:
    """A stand-in problem with constant gradients (only what multipliers reads)."""
    nvar = 2

    def __init__(self, GP, GM):
        self.GP, self.GM = np.asarray(GP, float), np.asarray(GM, float)

    def __call__(self, v):
        return None, None, self.GP, self.GM


def test_multipliers_solve_the_stationarity_condition():
    # e_t + Σ λ_j ∇c_j = 0 in w = (x1, x2, t), ∇(piece − t) = (g, −1), ∇margin = (g, 0):
    # an exact solution exists here, so least squares (numpy) must reproduce it
    rng = np.random.default_rng(5)
    for _ in range(50):
        GP = rng.standard_normal((2, 2))
        GM = rng.standard_normal((1, 2))
        ev = _Linear(GP, GM)
        lam_p, lam_m = multipliers(ev, np.zeros(3), [0, 1], [0], ev)
        R = np.array([[*GP[0], -1.0], [*GP[1], -1.0], [*GM[0], 0.0]])
        ref, *_ = np.linalg.lstsq(R.T, -np.array([0.0, 0.0, 1.0]), rcond=None)
        np.testing.assert_allclose(np.concatenate([lam_p, lam_m]), ref, rtol=1e-7, atol=1e-9)
        np.testing.assert_allclose(R.T @ np.concatenate([lam_p, lam_m]) + [0, 0, 1], 0, atol=1e-9)
