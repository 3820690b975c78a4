"""The grid method (geardesign.shifts.grid) on stand-in problems with analytic answers
(tests/shifts/toy_problems.py): node counts from the tolerance, the best node within one spacing of
the known optimum, and the thin-region fallback to the incentre."""
import math

import numpy as np
import pytest

from geardesign.shifts import grid
from tests.shifts.toy_problems import Disk, Triangle


def test_nodes_for_the_tolerance():
    assert grid.nodes_for(0.01, 4.5, 2, None) == math.ceil(4.5 / 0.02) + 1
    assert grid.nodes_for(1.0, 4.5, 2, None) == 11                     # at least 11
    assert grid.nodes_for(1e-9, 4.5, 2, None) == 1001                  # capped per axis in the plane
    assert grid.nodes_for(1e-9, 4.5, 1, None) == 200_001               # a fixed-a_w line: capped longer
    assert grid.nodes_for(0.01, 4.5, 2, 17) == 17                      # a given count wins


@pytest.mark.parametrize("r", [1.0, 0.55])
def test_grid_optimum_within_one_spacing(r):
    out = grid.solve(Disk(r), (-1.5, 3.0), tol=0.01)
    h = 4.5 / (grid.nodes_for(0.01, 4.5, 2, None) - 1)
    assert out.success and out.tol == pytest.approx(max(h / 2, 0.01))
    x1, x2 = out.v
    assert x1 * x1 + x2 * x2 <= r * r
    # the best node's x1 + x2 is within one diagonal step of the optimum r·√2
    assert r * math.sqrt(2) - 2 * h <= x1 + x2 <= r * math.sqrt(2)


def test_thin_region_falls_back_to_its_most_central_point():
    prob = Triangle(0.31, 0.67)
    out = grid.solve(prob, (-1.5, 3.0), tol=0.075)         # 31 nodes, spacing 0.15: none inside
    rho = prob.inradius()
    assert out.success and "thinner than the grid" in out.message
    np.testing.assert_allclose(out.v, [0.31 + rho, 0.31 + rho], atol=1e-7)
