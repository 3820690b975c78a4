"""The ways the ring checks reach the cutter–ring mesh give one answer: a grid of one pair computes it once
per distinct x2 and without its derivatives (geardesign/gears/checks/ring.py), one design computes it in
Python floats, a caller may hand in the ring's tip angle from the geometry; each equals the plain
elementwise computation of :func:`geardesign.gears.ring.cutting_mesh` from r_a2."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

import geardesign as gd
from geardesign.gears.checks import make_checks
from geardesign.gears.distinct import distinct_codes, exact_sum_nodes
from geardesign.gears.geometry import mesh_geometry, mesh_geometry_float
from geardesign.gears.ring import ShaperCutter, cutting_mesh, cutting_mesh_slopes
from geardesign.shifts.nodes import grid_points
from geardesign.shifts.problem import Problem

from tests.strategies import SETTINGS

ALPHA, TAN_N = math.radians(20.0), math.tan(math.radians(20.0))


@pytest.mark.parametrize("n", [8, 31])
def test_distinct_codes_of_a_grid_and_of_scattered_values(n):
    g = exact_sum_nodes(-1.5, 3.0, n)
    X1, X2 = np.meshgrid(g, g, indexing="ij")
    for v in (X2.ravel(), X1.ravel() + X2.ravel(), X2.ravel() - X1.ravel()):
        found = distinct_codes(v)
        if v.size < 64:
            assert found is None
            continue
        codes, first = found
        assert np.array_equal(v[first][codes], v) and len(first) == len(np.unique(v))
    rng = np.random.default_rng(1)
    assert distinct_codes(rng.random(500)) is None                    # nothing repeats
    v = rng.choice(rng.random(7), size=300)                          # few values, in no grid's order
    codes, first = distinct_codes(v)
    assert np.array_equal(v[first][codes], v) and len(first) == len(np.unique(v))


@SETTINGS
@given(z2=st.integers(20, 400), x2=st.floats(-1.0, 3.0), m=st.floats(0.3, 30.0), beta=st.floats(0.0, 40.0),
       z0=st.none() | st.integers(8, 60), x0=st.floats(-0.3, 0.3))
def test_slopes_added_later_and_the_tip_angle_handed_in_change_nothing(z2, x2, m, beta, z0, x0):
    cutter = ShaperCutter(z0=z0, x0=x0)
    cb = math.cos(math.radians(beta))
    alpha_t = math.atan(TAN_N / cb)
    geo = mesh_geometry_float(gd.Mesh(max(z2 - 30, 5), z2, beta_deg=beta, internal=True), m, 0.0, x2, False)
    r_a2 = geo["_ra2"]
    assume(math.isfinite(geo["_t_a2"]))
    full = cutting_mesh(m, z2, x2, r_a2, cutter, alpha_t, TAN_N, cb)
    later = cutting_mesh_slopes(cutting_mesh(m, z2, x2, r_a2, cutter, alpha_t, TAN_N, cb, slopes=False),
                                m, z2, r_a2, cutter, alpha_t, TAN_N, cb)
    assert _same(full, later)
    handed = cutting_mesh(m, z2, x2, r_a2, cutter, alpha_t, TAN_N, cb, tip=(geo["_t_a2"], geo["_inv_a2"]))
    for a, b in zip(full, handed):                 # the geometry's tip angle: the same to rounding
        assert a == pytest.approx(b, rel=1e-12, abs=1e-12, nan_ok=True)
    arrays = cutting_mesh(m, z2, np.array([x2, x2]), np.array([r_a2, r_a2]), cutter, alpha_t, TAN_N, cb)
    for a, b in zip(full, arrays):                 # Python floats and numpy agree
        assert np.allclose(b, a, rtol=1e-13, atol=1e-13, equal_nan=True)


def _same(a, b) -> bool:
    return all((x is None and y is None) or np.array_equal(x, y, equal_nan=True) for x, y in zip(a, b))


@pytest.mark.parametrize("z1, z2, beta, cutter", [(17, 74, 0.0, None), (29, 96, 15.0, None),
                                                  (20, 60, 30.0, ShaperCutter(z0=21, x0=0.1))])
def test_a_grid_of_one_pair_gives_each_node_its_own_margins_and_gradients(z1, z2, beta, cutter):
    mesh = gd.Mesh(z1, z2, beta_deg=beta, internal=True)
    checks = make_checks(internal=True, cutter=cutter)
    prob = Problem(mesh, checks, m=2.5)
    V = grid_points(prob, 31, (-1.5, 3.0))
    x1, x2 = prob.xy(V)
    P, M = prob.evaluate(V, grads=False)                            # x2 repeats: once per column
    geo = prob.geo_then(x1, x2, lambda g: g)                         # one pair's grid, as the solvers see it
    assert np.array_equal(prob.margins(geo), M)
    G = prob.margin_gradients(geo)                                   # the slopes added after the margins
    assert np.allclose(G, prob.margin_gradients(mesh_geometry(mesh, 2.5, x1, x2, full=False)), rtol=1e-12,
                       atol=1e-12, equal_nan=True)                  # the plain elementwise path
    rng = np.random.default_rng(0)
    for i in rng.choice(V.shape[0], 40, replace=False):
        one = mesh_geometry_float(mesh, 2.5, float(x1[i]), float(x2[i]), False)
        for k, c in enumerate(checks):
            want, slope = float(c.margin(one)), c.gradient(one)
            got = M[k, i]
            if not math.isfinite(want):
                assert got == -math.inf
                continue
            assert got == pytest.approx(want, rel=1e-12, abs=1e-12), (c.name, V[i])
            if slope is not None and all(map(math.isfinite, slope)):
                assert G[k, :, i] == pytest.approx(slope, rel=1e-10, abs=1e-12), (c.name, V[i])
