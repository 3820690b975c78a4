"""What a shift result tells beyond its numbers (issue 28): the grid's achieved spacing when a finer
tolerance was asked for, a pointer to balanced_sliding when the roots slide unevenly, and why
select_teeth's first row is first."""
import pytest

import geardesign as gd
from geardesign.shifts.grid import GRID_N_MAX, nodes_for
from geardesign.shifts.optimize import SLIDING_IMBALANCE


def test_grid_states_the_spacing_it_achieved():
    r = gd.optimize_shifts(17, 26, method="grid", tol=1e-4)
    n = nodes_for(1e-4, 4.5, 2, None)                       # the window [-1.5, 3] is 4.5 wide
    spacing = 4.5 / (n - 1)
    assert n <= GRID_N_MAX and spacing > 2e-4
    assert "tol 0.0001 asked" in r.message and f"{spacing:.3g}" in r.message
    assert r.tol == pytest.approx(spacing / 2)
    plain = gd.optimize_shifts(17, 26, method="grid", tol=0.05)
    assert "asked" not in plain.message


def test_max_x_sum_points_to_balanced_sliding():
    """17/26 at its max_x_sum optimum: root sliding −1.87 against −0.74 (issue 28's figures)."""
    r = gd.optimize_shifts(17, 26)
    g = gd.pair_geometry(1, 17, 26, r.x1, r.x2)
    s1, s2 = abs(float(g.sliding1_root)), abs(float(g.sliding2_root))
    assert max(s1, s2) > SLIDING_IMBALANCE * min(s1, s2)
    assert "balanced_sliding" in r.message
    b = gd.optimize_shifts(17, 26, objective="balanced_sliding")
    gb = gd.pair_geometry(1, 17, 26, b.x1, b.x2)
    assert "root sliding" not in b.message
    assert abs(float(gb.sliding1_root)) == pytest.approx(abs(float(gb.sliding2_root)), rel=1e-6)


def test_select_teeth_says_why_the_largest_pair_wins():
    sel = gd.select_teeth(1.5, m=8, z1_range=(14, 24))
    best = sel.best
    exact = sel.feasible[(sel.feasible["ratio_error"].abs() < 1e-12)]
    assert int(best["z1"] + best["z2"]) == int((exact["z1"] + exact["z2"]).max())
    assert "largest pair in the range wins" in sel.choice and "a_w=" in sel.choice
    fixed = gd.select_teeth(1.5, m=8, a_w=180)
    assert "largest pair" not in fixed.choice
