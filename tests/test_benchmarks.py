"""The benchmarks' plain references compute what the library computes, so that the speed ratios they
print compare like with like: bench_geometry's straight-line numpy margins (textbook forms, written
independently in the benchmark) against the library's seven default margins."""
import sys
from pathlib import Path

import numpy as np
import pytest

import geardesign as gd
from geardesign import checks
from geardesign.gears.geometry import mesh_geometry
from geardesign.gears.mesh import Mesh

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_geometry import designs, plain_blocked, plain_margins  # noqa: E402


def test_plain_margins_of_bench_geometry_are_the_librarys():
    z1, z2, x1, x2 = designs(5000, seed=5)
    cs = gd.make_checks()
    ours = checks.margins(mesh_geometry(Mesh(z1, z2, gd.BasicRack(), True), 1.0, x1, x2, False), cs)
    plain = plain_margins(z1.astype(float), z2.astype(float), x1, x2)
    assert [c.name for c in cs] == ["undercut1", "undercut2", "interference1", "interference2",
                                    "tip_thickness1", "tip_thickness2", "contact_ratio"]
    for c, p in zip(cs, plain):
        np.testing.assert_allclose(ours[c.name], p, rtol=0, atol=1e-9, err_msg=c.name)


def test_blocked_plain_margins_are_the_plain_margins():
    """The blocked plain version (bench_geometry's ceiling of a numpy kernel) computes the same values,
    across block boundaries."""
    z1, z2, x1, x2 = designs(40_000, seed=6)
    z1, z2 = z1.astype(float), z2.astype(float)
    np.testing.assert_array_equal(plain_blocked(z1, z2, x1, x2), np.array(plain_margins(z1, z2, x1, x2)))


def test_margin_bound_witness_beats_the_max_margin_solution():
    """bench_drive_margin_bound's witness: a node of the window where the smallest raw check margin, re-checked
    by GearPair.checks (another path than the vectorised problem), is the witness's value and lies well above the
    smallest raw margin at the max_margin shift solution of the same pair (its Chebyshev centre of the
    normalised margins): a bound valid over the window cannot come near the solved value."""
    from bench_drive_margin_bound import witness

    value, x1, x2 = witness(25, 116, 3.0)
    table = gd.GearPair(3.0, 25, 116, x1, x2).checks(jamming=False)   # the drive stage's checks
    assert abs(table["margin"].astype(float).min() - value) <= 1e-9
    solved = gd.optimize_shifts(25, 116, "max_margin", m=3.0)
    assert value > min(solved.margins.values()) + 0.05


def test_bench_worm_reference_computes_the_librarys_quantities():
    """bench_worm's plain reference (a few of a worm pair's quantities) is the library's, for one design and an
    array of them, so its ratios compare like with like."""
    from bench_worm import plain_worm, plain_worm_arrays

    import math

    from geardesign.gears.worm.geometry import worm_geometry, worm_geometry_float

    names = ["gamma_m_deg", "d_a1", "d_f1", "d_a2", "d_f2", "a", "eps_alpha"]
    g = worm_geometry_float(5.0, 2, 25, 10.0, 0.1)
    ref = plain_worm(5.0, 2, 25, 10.0, 0.1)
    ref = (math.degrees(ref[0]),) + tuple(ref[1:])
    for n, v in zip(names, ref):
        assert g[n] == pytest.approx(v, rel=1e-14), n
    args = [np.array(v) for v in ([2.0, 4.0], [1.0, 4.0], [30.0, 61.0], [8.0, 12.5], [-0.3, 0.4])]
    ga = worm_geometry(*args)
    ra = plain_worm_arrays(*args)
    ra = (np.degrees(ra[0]),) + tuple(ra[1:])
    for n, v in zip(names, ra):
        np.testing.assert_allclose(ga[n], v, rtol=1e-14, err_msg=n)
