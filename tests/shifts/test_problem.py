"""The single-design float path of the optimisers agrees with the vectorised array path.

The local solvers evaluate one design at a time in Python floats (:func:`_core_float`,
:meth:`Problem.evaluate_point`) because a one-element numpy call costs ~20× more. Both run the
same formulas (:func:`geardesign.gears.geometry._formulas`) on different backends; these tests hold
them together, so that the golden and mpmath tests of the array path cover the float path too.
The analytic gradients of the objective pieces are held against central differences.
"""
from __future__ import annotations

import math

import numpy as np
from hypothesis import assume, given
from hypothesis import strategies as st

from geardesign.gears.checks import CustomCheck, make_checks
from geardesign.gears.geometry import mesh_geometry, mesh_geometry_float
from geardesign.gears.mesh import Mesh
from geardesign.shifts.objectives import OBJECTIVES
from geardesign.shifts.problem import Problem

from test_properties import SETTINGS, designs


@SETTINGS
@given(designs())
def test_float_core_equals_array_core(d):
    mesh = Mesh(d["z1"], d["z2"], d["rack"], d["ts"])
    arr, flt = mesh_geometry(mesh, d["m"], d["x1"], d["x2"]), mesh_geometry_float(mesh, d["m"], d["x1"], d["x2"])
    assert arr.keys() == flt.keys()
    for k, v in arr.items():
        v = float(v)
        assert isinstance(flt[k], float), k
        assert abs(flt[k] - v) <= 1e-13 * max(1.0, abs(v)), (k, flt[k], v)


def test_float_core_gives_nan_where_the_design_does_not_exist():
    """x-sum too negative for an operating angle: NaN on both paths, never an exception."""
    from geardesign.gears.rack import BasicRack
    arr = mesh_geometry(Mesh(10, 10, BasicRack(), True), 1.0, -2.0, -2.0)
    flt = mesh_geometry_float(Mesh(10, 10, BasicRack(), True), 1.0, -2.0, -2.0)
    assert math.isnan(flt["a_w"]) and np.isnan(arr["a_w"])


@SETTINGS
@given(z1=st.integers(8, 150), z2=st.integers(8, 300), x1=st.floats(-0.5, 1.5), x2=st.floats(-0.5, 1.5),
       objective=st.sampled_from(sorted(OBJECTIVES)), fixed=st.booleans())
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
        if gap > 1e-9:   # off the kink, the gradient is that part's
            assert np.allclose(fGM[j], GM[i], rtol=1e-7, atol=1e-7), (prob.names[i], fGM[j], GM[i])


@SETTINGS
@given(designs())
def test_part_gradients_match_central_differences(d):
    """Interference's two parts (above the limit point, above the base circle) are smooth."""
    m, rack, ts = d["m"], d["rack"], d["ts"]
    geo = mesh_geometry_float(Mesh(d["z1"], d["z2"], rack, ts), m, d["x1"], d["x2"])
    h = 1e-6
    for check in make_checks():
        an = np.array(check.part_gradients(geo), dtype=float)
        for j, (dx1, dx2) in enumerate(((h, 0.0), (0.0, h))):
            up = mesh_geometry_float(Mesh(d["z1"], d["z2"], rack, ts), m, d["x1"] + dx1, d["x2"] + dx2)
            dn = mesh_geometry_float(Mesh(d["z1"], d["z2"], rack, ts), m, d["x1"] - dx1, d["x2"] - dx2)
            fd = (np.array(check.part_margins(up)) - np.array(check.part_margins(dn))) / (2 * h)
            assert np.allclose(an[:, j], fd, rtol=1e-6, atol=1e-6), (check.name, j, an[:, j], fd)


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
