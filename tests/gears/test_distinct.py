"""Computing once per distinct value (geardesign.gears.distinct): the result is each value's own result, bit for
bit, whatever the array's layout (a grid's diagonals, a large repeating batch, scattered values, NaN), and a
grid's nodes whose sums are exact."""
import numpy as np
import pytest

from geardesign.gears.distinct import distinct_codes, exact_sum_nodes, per_distinct


def _func(v):
    calls.append(v.size)
    return np.tan(v) - v, np.sqrt(np.abs(v)) * 3.0


calls = []


def _alone(v):
    flat = v.reshape(-1)
    out = [np.array([_func(np.array([x]))[k][0] for x in flat]).reshape(v.shape) for k in range(2)]
    return tuple(out)


@pytest.mark.parametrize("make", [
    lambda: np.add.outer(exact_sum_nodes(-1.5, 3.0, 41), exact_sum_nodes(-1.5, 3.0, 41)),   # a grid's x-sums
    lambda: np.tile(np.linspace(-0.5, 1.0, 50), 200),                                          # a batch repeating
    lambda: np.random.default_rng(1).uniform(-1, 2, 5000),                                     # scattered
    lambda: np.where(np.arange(6000) % 7 == 0, np.nan, np.arange(6000) % 40 * 0.05),           # with NaN
])
def test_each_value_gets_its_own_result(make):
    v = make()
    got = per_distinct(_func, v)
    want = _alone(v)
    for g, w in zip(got, want):
        assert g.shape == v.shape
        assert np.array_equal(g, w, equal_nan=True)


def test_a_grid_is_computed_once_per_diagonal():
    g = exact_sum_nodes(-1.5, 3.0, 41)
    v = np.add.outer(g, g)
    calls.clear()
    per_distinct(_func, v)
    assert calls == [2 * 41 - 1]                      # 81 distinct sums of 1681 nodes
    codes, first = distinct_codes(v)
    assert np.array_equal(v.reshape(-1)[first][codes], v.reshape(-1))


def test_exact_sum_nodes():
    g = exact_sum_nodes(-1.5, 3.0, 41)
    assert abs(g[0] + 1.5) <= 41 * 2.0 ** -40 and abs(g[-1] - 3.0) <= 41 * 2.0 ** -40
    s = np.add.outer(g, g)
    for k in range(-40, 41):                          # every diagonal holds one value, bit for bit
        assert np.unique(np.diagonal(s[:, ::-1], k)).size == 1
    assert distinct_codes(np.arange(10.0)) is None    # too few values to gain anything
