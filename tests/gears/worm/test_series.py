"""Worm series catalogs (each row with its source) and select_worm: the shift of each candidate is the one its
centre distance fixes, the ranking puts feasible rows first, bad input is refused by name."""
import numpy as np
import pytest

import geardesign as gd
from geardesign.catalogs.tables import load_catalog
from geardesign.gears.worm import series


def test_catalogs_carry_their_source_and_the_printed_rows():
    for name in ("worm_modules", "worm_center_distances"):
        frame = load_catalog(name)
        assert frame["source"].str.len().min() > 40 and set(frame["series"]) == {1, 2}
    # the rows the cited page prints (examum.ru course-design guide)
    assert series.worm_center_distance_series(1).tolist() == [40, 50, 63, 80, 100, 125, 160, 200, 250, 315, 400, 500]
    assert series.worm_module_series(1).tolist() == [1.6, 2, 2.5, 3.15, 4, 5, 6.3, 8, 10, 12.5, 16]
    assert series.worm_module_series((1, 2), 3, 4).tolist() == [3.0, 3.15, 3.5, 4.0]


def test_bad_series_is_refused():
    with pytest.raises(gd.GearDesignError, match="series must be 1, 2 or"):
        series.worm_module_series(3)


def test_select_for_seed_002_gear_motor():
    # seed 002: a worm gear motor of u = 12.5; a standard centre distance of 125 mm (GOST 2144 1st row)
    s = gd.select_worm(12.5, 125, z1=(2, 4))
    t = s.table
    assert len(t) == s.n_candidates and t["feasible"].iloc[0]
    # every row's x2 is the one its a fixes: a = m_x (q + z2 + 2 x2)/2
    assert np.allclose(t["m_x"] * (t["q"] + t["z2"] + 2 * t["x2"]) / 2, 125.0, rtol=1e-14, atol=0)
    assert set(t["u"]) == {12.5}
    # feasible rows first, then |x2| (the default objective), the infeasible ones after
    feas = t["feasible"].to_numpy()
    assert not np.any(~feas[:-1] & feas[1:])
    f = t[t["feasible"]]
    assert np.all(np.diff(f["x2"].abs().to_numpy()) >= -1e-15)
    p = s.pair()
    assert p.ok() and p.geometry().a == pytest.approx(125.0, rel=1e-14)
    assert "candidates feasible" in s.choice


def test_select_without_a_center_distance_optimises_x2():
    s = gd.select_worm(20, m_x=4.0, q=(8, 10), z1=2, objective="max_margin")
    assert s.best is not None and s.a is None
    r = gd.WormPair(4.0, 2, 40, float(s.best["q"])).optimize_x2("max_margin")
    assert float(s.best["x2"]) == pytest.approx(r.x2, abs=1e-12)


@pytest.mark.parametrize("kwargs,words", [
    (dict(), ["needs ratio or z2"]),
    (dict(ratio=12.5), ["needs m_x"]),
    (dict(ratio=0.5, a=100), ["ratio", "[1, 1000]"]),
    (dict(ratio=12.5, a=-1), ["a (center distance)", "(0, 100000] mm", "-1"]),
    (dict(ratio=12.5, a=100, z1=0), ["z1", "[1, 10]"]),
    (dict(ratio=12.5, a=100, objective="fast"), ["objective", "min_abs_x2"]),
    (dict(ratio=12.5, a=100, z1=3, ratio_tol=0.001), ["no z1/z2 within ratio_tol"]),
])
def test_bad_select_input(kwargs, words):
    with pytest.raises(gd.GearDesignError) as info:
        gd.select_worm(**kwargs)
    for w in words:
        assert w in str(info.value), (w, str(info.value))


def test_first_row_modules_rank_before_second_row_ones():
    t = gd.select_worm(12.5, 125, z1=(2, 4)).table
    f = t[t["feasible"]]
    assert np.all(np.diff(f["module_series"].to_numpy()) >= 0)     # equal ratio errors here: the series decides
    assert set(t["module_series"]) <= {1, 2}


@pytest.mark.parametrize("kw, match", [(dict(ratio=[1, 2], m_x=6.3), "ratio must be one number"),
                                       (dict(ratio=12.5, a=[100, 125]), r"a \(center distance\) must be one number"),
                                       (dict(ratio=12.5, a=125, ratio_tol=[0.1]), "ratio_tol must be one number")])
def test_select_worm_refuses_a_list_where_one_number_belongs(kw, match):
    """Fuzzing found 'TypeError: only 0-dimensional arrays can be converted' for select_worm([1, 2], ...)."""
    with pytest.raises(gd.GearDesignError, match=match):
        gd.select_worm(**kw)


@pytest.mark.parametrize("kw, match", [(dict(q=[[1], [2, 3]]), "q must be a number or a flat list of them"),
                                       (dict(q=[[10.0], [12.5, 14.0]]), "q must be a number or a flat list of them"),
                                       (dict(z1=[[1, 2], [2]]), "z1 must be a number or a flat list of them")])
def test_select_worm_refuses_a_ragged_list_by_name(kw, match):
    """Fuzzing found 'ValueError: setting an array element with a sequence' for q=[[1], [2, 3]]."""
    with pytest.raises(gd.GearDesignError, match=match):
        gd.select_worm(12.5, None, m_x=[3.15, 4.0], **kw)


def test_a_centre_distance_beyond_the_lengths_is_refused_by_name():
    """Fuzzing found overflow RuntimeWarnings escaping select_worm(12.5, 1e308): a is checked against (0, 1e5] mm."""
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(gd.GearDesignError, match=r"a \(center distance\) must be in \(0, 100000\] mm, got 1e\+308"):
            gd.select_worm(12.5, 1e308, ratio_tol=0.05)
