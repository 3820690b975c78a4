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
