"""Pair geometry: vectorised input (an error names the bad index; scalar in, float out; arrays
broadcast), and the single-design float path against the vectorised array path.

The local solvers evaluate one design at a time in Python floats (:func:`mesh_geometry_float`)
because a one-element numpy call costs ~20× more. Both run the same formulas
(:func:`geardesign.gears.geometry._formulas`) on different backends; these tests hold them
together, so that the golden and mpmath tests of the array path cover the float path too.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears.geometry import REPORT_FIELDS, mesh_geometry, mesh_geometry_float
from geardesign.gears.mesh import Mesh

from tests.strategies import SETTINGS, designs


def test_vectorised_error_names_index():
    with pytest.raises(gd.GearDesignError, match="index 2"):
        gd.pair_geometry(1.0, 20, 30, np.array([0.0, 0.1, -40.0]), 0.0)


def test_scalar_in_scalar_out_and_broadcast():
    g = gd.pair_geometry(2.0, 17, 34, 0.0, 0.0)
    assert isinstance(g.a_w, float)
    ga = gd.pair_geometry(2.0, np.array([17, 18]), np.array([[34], [40], [50]]), 0.1, 0.2)
    assert ga.a_w.shape == (3, 2)
    assert ga.to_frame().shape[0] == 6


@SETTINGS
@given(designs())
def test_pair_geometry_of_single_numbers_is_the_array_paths(d):
    """Single plain numbers take the float path (issue 36 §3: 7.6x GearPair(...).geometry() on one-element arrays);
    the values are the array path's, ``fields`` keeps its meaning."""
    one = gd.pair_geometry(d["m"], d["z1"], d["z2"], d["x1"], d["x2"], d["rack"], d["ts"])
    arr = gd.pair_geometry(np.array([d["m"]]), d["z1"], d["z2"], d["x1"], d["x2"], d["rack"], d["ts"])
    assert one.names == arr.names
    for k in one.names:
        assert isinstance(one[k], float), k
        v = float(arr[k][0])
        flt = mesh_geometry_float(Mesh(d["z1"], d["z2"], d["rack"], d["ts"]), d["m"], d["x1"], d["x2"])
        assert abs(one[k] - v) <= 1e-13 * max(1.0, abs(v)) * _conditioning(k, flt), k
    some = gd.pair_geometry(d["m"], d["z1"], d["z2"], d["x1"], d["x2"], d["rack"], d["ts"], fields=["a_w", "sa1"])
    assert some.names == ["a_w", "sa1"] and some.a_w == one.a_w and some.eps_alpha is None


def test_pair_geometry_of_single_numbers_refuses_and_returns_as_the_array_path():
    """A design whose geometry does not exist is refused by name; gears whose tips do not reach across the
    line of action are returned with g_alpha <= 0 (the regions need them), as on the array path."""
    with pytest.raises(GearDesignError, match="too negative"):
        gd.pair_geometry(1.0, 10, 10, -2.0, -2.0)
    with pytest.raises(GearDesignError, match="tip circle of gear 1"):
        gd.pair_geometry(1.0, 10, 40, -1.5, 3.0)
    apart = gd.pair_geometry(1.0, 5, 5, 3, 3)
    arr = gd.pair_geometry(np.array([1.0]), 5, 5, 3, 3)
    assert apart.g_alpha == pytest.approx(float(arr.g_alpha[0]), rel=1e-12) and apart.g_alpha <= 0


@SETTINGS
@given(designs())
def test_float_core_equals_array_core(d):
    mesh = Mesh(d["z1"], d["z2"], d["rack"], d["ts"])
    arr, flt = mesh_geometry(mesh, d["m"], d["x1"], d["x2"]), mesh_geometry_float(mesh, d["m"], d["x1"], d["x2"])
    assert arr.keys() == flt.keys()
    assert arr["_mesh"] is flt["_mesh"] is mesh            # the one non-number: what the geometry is of
    for k, v in arr.items():
        if k == "_mesh":
            continue
        v = float(v)
        assert isinstance(flt[k], float), k
        assert abs(flt[k] - v) <= 1e-13 * max(1.0, abs(v)) * _conditioning(k, flt), (k, flt[k], v)


def _conditioning(name, geo):
    """The specific sliding at a root divides by ρ_p, a difference of two lengths of size
    r_b tan α_w: one ulp there moves it by ~ε·r_b tan α_w/|ρ_p| relative (the allowance of
    tests/test_extremes.py::_conditioning), which exceeds 1e-13 near an interference point."""
    if name not in ("sliding1_root", "sliding2_root"):
        return 1.0
    j = name[7]
    big = geo[f"db{j}"] / 2.0 * geo["_t_w"]
    return max(1.0, 16 * 2.0 ** -52 * big / abs(geo[f"rho_p{j}"]) / 1e-13)


def test_float_core_gives_nan_where_the_design_does_not_exist():
    """x-sum too negative for an operating angle: NaN on both paths, never an exception."""
    from geardesign.gears.rack import BasicRack
    arr = mesh_geometry(Mesh(10, 10, BasicRack(), True), 1.0, -2.0, -2.0)
    flt = mesh_geometry_float(Mesh(10, 10, BasicRack(), True), 1.0, -2.0, -2.0)
    assert math.isnan(flt["a_w"]) and np.isnan(arr["a_w"])


def test_geometry_blocks_equal_one_pass():
    """Large inputs go through in blocks; the values are those of small calls (same formulas)."""
    rng = np.random.default_rng(3)
    n = 70_000                       # more than one block of 65 536
    z1 = rng.integers(12, 60, n)
    z2 = rng.integers(20, 150, n)
    x1, x2 = rng.uniform(-0.3, 0.9, n), rng.uniform(-0.3, 0.9, n)
    big = mesh_geometry(Mesh(z1, z2), 1.0, x1, x2)
    for i in (0, 65_535, 65_536, n - 1):
        one = mesh_geometry_float(Mesh(int(z1[i]), int(z2[i])), 1.0, x1[i], x2[i])
        for k in ("a_w", "eps_alpha", "sa1", "rho_p2", "o2n1"):
            assert big[k][i] == pytest.approx(one[k], rel=1e-13, abs=1e-13)

def test_pair_geometry_fields_on_demand():
    """KHK worked example (12/24, m = 3, x = 0.6/0.36): a_w = 56.4999 mm, ε_α = 1.202."""
    g = gd.pair_geometry(3, 12, 24, 0.6, 0.36, fields=["a_w", "eps_alpha"])
    assert g.names == ["a_w", "eps_alpha"]
    assert round(g.a_w, 4) == 56.4999 and round(g.eps_alpha, 3) == 1.202
    assert g.sw1 is None and list(g.to_frame()["quantity"]) == ["a_w", "eps_alpha"]
    full = gd.pair_geometry(3, 12, 24, 0.6, 0.36)
    assert REPORT_FIELDS <= set(full.names)
    with pytest.raises(GearDesignError, match="fields must be names of GEOMETRY_FIELDS.*'a_ww'"):
        gd.pair_geometry(3, 12, 24, 0.6, 0.36, fields=["a_ww"])


def test_grid_geometry_is_each_designs_own():
    """A design's fields do not depend on its neighbours: on a grid (where the operating angle is
    computed once per x-sum, nodes that do not exist included) every field equals the design's
    own one-element evaluation bit for bit."""
    import numpy as np

    from geardesign.gears.geometry import exact_sum_nodes, mesh_geometry
    from geardesign.gears.mesh import Mesh

    g = exact_sum_nodes(-1.5, 3.0, 31)
    X1, X2 = (a.ravel() for a in np.meshgrid(g, g, indexing="ij"))
    for mesh in (Mesh(12, 12, None, True), Mesh(20, 60, None, True, 0.0, True)):
        grid = mesh_geometry(mesh, 2.0, X1, X2, full=False)
        assert np.isnan(grid["a_w"]).any() and np.isfinite(grid["a_w"]).any()   # both kinds of node
        for i in range(0, X1.size, 37):
            one = mesh_geometry(mesh, 2.0, X1[i:i + 1], X2[i:i + 1], full=False)
            for k in ("a_w", "sa1", "eps_alpha", "rho_p1", "_t_w"):
                np.testing.assert_array_equal(grid[k][i:i + 1], one[k])


def test_fields_asked_for_equal_the_full_result_and_are_validated_alike():
    """pair_geometry(fields=...) stores only those fields (and what the validation reads) block by
    block: the values are the full call's, bit for bit, over more than one block, and a design that
    does not exist is refused by name as without ``fields``."""
    import numpy as np

    from geardesign.gears.geometry import BLOCK

    rng = np.random.default_rng(3)
    n = BLOCK + 1000
    z1, z2 = rng.integers(12, 60, n), rng.integers(20, 150, n)
    x1, x2 = rng.uniform(-0.3, 0.9, n), rng.uniform(-0.3, 0.9, n)
    some = gd.pair_geometry(2.0, z1, z2, x1, x2, fields=["a_w", "sa1", "eps_alpha", "d_l1"])
    every = gd.pair_geometry(2.0, z1, z2, x1, x2)
    assert some.names == ["a_w", "sa1", "eps_alpha", "d_l1"] and some.da1 is None
    for k in some.names:
        np.testing.assert_array_equal(getattr(some, k), getattr(every, k))
    no_contact = gd.pair_geometry(2.0, z1, z2, x1, x2, fields=["a_w", "sa2", "df1"])
    for k in no_contact.names:
        np.testing.assert_array_equal(getattr(no_contact, k), getattr(every, k))
    x1[-1] = -3.0
    with pytest.raises(gd.GearDesignError, match=f"index {n - 1}"):
        gd.pair_geometry(2.0, z1, z2, x1, x2, fields=["a_w"])


def test_path_of_contact_left_out_when_no_field_needs_it():
    """mesh_geometry(contact=False) computes no field of the path of contact (CONTACT_FIELDS) and
    every other field as with it; pair_geometry asks for it only when a field needs it."""
    import numpy as np

    from geardesign.gears.geometry import CONTACT_FIELDS
    from geardesign.gears.mesh import Mesh

    mesh = Mesh(np.array([17, 20]), np.array([26, 60]), None, True, 0.0, False)
    lean = mesh_geometry(mesh, 2.0, np.array([0.3, 0.1]), np.array([0.2, 0.5]), full=False, contact=False)
    with_path = mesh_geometry(mesh, 2.0, np.array([0.3, 0.1]), np.array([0.2, 0.5]), full=False)
    assert CONTACT_FIELDS.isdisjoint(lean) and CONTACT_FIELDS <= set(with_path)
    assert set(with_path) - set(lean) == CONTACT_FIELDS
    for k in lean:
        np.testing.assert_array_equal(lean[k], with_path[k])
    # KHK 12/24 (x 0.6/0.36): a_w = 56.4999 mm without the path; 5/5 at x = 2 on a 15° rack, whose tips do
    # not overlap along the line of action (shown in mpmath in tests/gears/test_pair.py), only GearPair refuses
    assert round(gd.pair_geometry(3, 12, 24, 0.6, 0.36, fields=["a_w"]).a_w, 4) == 56.4999
    rack15 = gd.BasicRack(alpha_deg=15.0)
    assert gd.pair_geometry(1, 5, 5, 2.0, 2.0, rack=rack15, fields=["a_w"]).names == ["a_w"]
    assert gd.pair_geometry(1, 5, 5, 2.0, 2.0, rack=rack15, fields=["eps_alpha"]).eps_alpha < 0


def test_fields_of_one_pair_are_full_arrays_like_the_full_result():
    """One pair over an array of shifts (its tooth-count fields computed once, as numbers): the fields asked
    for still come back as writeable arrays of the designs' shape, equal to the full call's bit for bit."""
    import numpy as np

    x1 = np.linspace(0.0, 0.6, 7)
    some = gd.pair_geometry(2.0, 17, 26, x1, 0.3, fields=["d1", "db2", "a_w", "sa1"])
    every = gd.pair_geometry(2.0, 17, 26, x1, 0.3)
    for k in some.names:
        v = getattr(some, k)
        assert v.shape == x1.shape and v.flags.writeable
        np.testing.assert_array_equal(v, getattr(every, k))
