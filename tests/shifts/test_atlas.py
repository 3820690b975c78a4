"""Shift atlas: many pairs at once, against one-by-one solves."""
import pytest

import geardesign as gd


def test_atlas_agrees_with_one_by_one_solves():
    df = gd.shift_atlas([12, 17, 25], [26, 40, 90])
    assert len(df) == 9
    for _, row in df.iterrows():
        r = gd.optimize_shifts(int(row.z1), int(row.z2))
        assert row.feasible == r.success
        if r.success:
            assert abs(row.x1 - r.x1) < 1e-9 and abs(row.x2 - r.x2) < 1e-9
            # the area estimate is a grid count: close to the traced region's area
            assert row.area == pytest.approx(gd.feasible_region(int(row.z1), int(row.z2)).area, rel=0.03)


def test_atlas_reports_infeasible_pairs():
    df = gd.shift_atlas([5, 6], [5, 6])
    assert not df.feasible.any()
    assert (df.conflict.str.len() > 0).all()


def test_atlas_thin_regions_agree_with_one_by_one_solves():
    """Pairs whose region holds no node of the atlas's grid (8 to 11 pinion teeth: a sliver) start the
    batched Newton from their least infeasible node; each row is still the single-pair optimum."""
    df = gd.shift_atlas([8, 9, 10, 11], [13, 17, 22, 45, 120])
    thin = 0
    for _, row in df.iterrows():
        r = gd.optimize_shifts(int(row.z1), int(row.z2))
        assert row.feasible == r.success
        if r.success:
            assert abs(row.x1 - r.x1) < 1e-9 and abs(row.x2 - r.x2) < 1e-9
            thin += row.area < 0.01
    assert thin >= 3   # the case exercised: regions thinner than the grid


def test_feasible_pairs_with_a_large_wheel_are_settled_in_the_batch(monkeypatch):
    """Only infeasible pairs go one by one (the docstring's promise): pairs with a large wheel, whose optimum
    lies on the window's edge x2 = 3 (issue 36 §3: 36 % of the feasible pairs of z1 12..184 × z2 185..357 went
    one by one), are settled by the batched Newton, each at the single-pair optimum."""
    from geardesign.shifts import atlas

    alone = []
    solve = atlas._row_solved
    monkeypatch.setattr(atlas, "_row_solved", lambda z1, z2, *a: alone.append((z1, z2)) or solve(z1, z2, *a))
    df = gd.shift_atlas([18, 32, 60, 104], [231, 286, 302, 347])
    assert df.feasible.all() and alone == []
    on_edge = 0
    for _, row in df.iterrows():
        r = gd.optimize_shifts(int(row.z1), int(row.z2))
        assert abs(row.x1 - r.x1) < 1e-9 and abs(row.x2 - r.x2) < 1e-9
        on_edge += r.x2 == 3.0
    assert on_edge >= 8      # the case exercised: optima on the window's edge


def test_grid_areas_of_a_disc_an_annulus_and_two_pieces():
    """The atlas's area against plane geometry: a disc (π r²), an annulus (its hole subtracted) and
    two separate squares (added), each grid at once; the error of the interpolated contour ~ h²."""
    import numpy as np
    from geardesign.shifts.atlas import grid_areas

    g = np.linspace(-1.0, 1.0, 201)
    h = g[1] - g[0]
    X1, X2 = np.meshgrid(g, g, indexing="ij")
    r = np.hypot(X1, X2)
    F = np.stack([0.8 - r, np.minimum(0.9 - r, r - 0.4),
                  np.maximum(0.3 - np.maximum(np.abs(X1 - 0.5), np.abs(X2)),
                             0.2 - np.maximum(np.abs(X1 + 0.5), np.abs(X2)))])
    exact = np.array([np.pi * 0.8 ** 2, np.pi * (0.9 ** 2 - 0.4 ** 2), 0.6 ** 2 + 0.4 ** 2])
    assert np.allclose(grid_areas(F, h), exact, rtol=0, atol=5 * h * h)
    assert grid_areas(-np.ones((3, 3)), 1.0) == 0.0 and grid_areas(np.ones((3, 3)), 1.0) == 4.0


@pytest.mark.parametrize("checks", [[], {"eps_alpha_min": None, "sa_min": None}])
def test_atlas_with_checks_dropped_agrees_with_optimize_shifts(checks):
    """Issue 29 §3.11: checks=[] raised IndexError (no check to pair); once meshing (a condition of
    existence, always held) gave the batch a check, its Newton left the window (x2 = 3.53 > 3)."""
    df = gd.shift_atlas([17, 18], [26, 40], checks=checks)
    for row in df.itertuples():
        r = gd.optimize_shifts(row.z1, row.z2, checks=checks)
        assert row.feasible and r.success
        assert -1.5 <= row.x1 <= 3.0 and -1.5 <= row.x2 <= 3.0
        assert row.objective == pytest.approx(r.fun, abs=1e-8)
        gd.GearPair(1, row.z1, row.z2, row.x1, row.x2)     # meshes
