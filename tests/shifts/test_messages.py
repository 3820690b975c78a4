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


def test_root_sliding_at_the_base_circle_is_said_as_minus_infinity():
    """17/26 at its max_eps_alpha optimum: undercut1 and interference1 active, so the pinion's contact starts at its
    base circle, where its rolling speed is 0 (ρ1 = 0 on the geometry, to rounding) and ϑ1 = −∞; the message said
    "+8.9e+15" or so, a number with a sign rounding chose."""
    r = gd.optimize_shifts(17, 26, objective="max_eps_alpha")
    assert {"undercut1", "interference1"} <= set(r.active)
    g = gd.pair_geometry(1, 17, 26, r.x1, r.x2)
    assert abs(float(g.sliding1_root)) > 1e9
    assert "ϑ1 = -∞ (the contact starts at the base circle)" in r.message and "e+15" not in r.message


def test_select_teeth_says_why_the_largest_pair_wins():
    sel = gd.select_teeth(1.5, m=8, z1_range=(14, 24))
    best = sel.best
    exact = sel.feasible[(sel.feasible["ratio_error"].abs() < 1e-12)]
    assert int(best["z1"] + best["z2"]) == int((exact["z1"] + exact["z2"]).max())
    assert "largest pair in the range wins" in sel.choice and "a_w=" in sel.choice
    fixed = gd.select_teeth(1.5, m=8, a_w=180)
    assert "largest pair" not in fixed.choice


@pytest.mark.parametrize("m, z1, z2, torque, material", [
    (3, 32, 106, 50, "C45"),                 # ends on SLSQP's point (no KKT point near it)
    (4, 32, 106, 50, "C45"),                 # SLSQP, then the Newton polish
    (2, 30, 64, 200, "18CrNiMo7-6"),         # the KKT system from a grid node
])
def test_the_accuracy_line_says_what_the_message_says(m, z1, z2, torque, material):
    # issue 36 §1.11: "converged (SLSQP; active-set polish not applicable)" was printed with "accuracy: KKT point
    # solved by Newton: x to ~1e-12": the accuracy of the method's table, not of the point returned
    ck = dict(load=gd.Load(torque_nm=torque, n_rpm=1000), material=material, face_width_mm=20)
    r = gd.optimize_shifts(z1, z2, m=m, objective="max_min_safety", checks=ck)
    assert r.success
    polished = "Newton" in r.message
    assert ("Newton" in r.accuracy) == polished, (r.message, r.accuracy)
    if not polished:
        assert "not applicable" in r.message and r.accuracy.startswith("SLSQP's point")
    assert f"repr: {r!r}".count("Newton") == 2 * polished


def _holds_together(m, z1, z2, x_sum, checks, names, n=1801):
    """The largest smallest margin of ``names`` along the line x1 + x2 = x_sum in the window [-1.5, 3], by
    GearPair.checks (the route a user re-checks a design by), on n points."""
    import numpy as np

    best = -np.inf
    for x1 in np.linspace(-1.5, 3.0, n):
        if not -1.5 <= x_sum - x1 <= 3.0:
            continue
        try:
            t = gd.GearPair(m, z1, z2, float(x1), float(x_sum - x1)).checks(**checks).set_index("check")["margin"]
        except gd.GearDesignError:
            continue
        best = max(best, min(float(t[c]) for c in names))
    return best


def test_a_conflict_names_checks_that_cannot_hold_together_and_says_which_fail_at_the_point():
    # issue 36 §1.11: "conflict: interference1, contact_strength" was listed beside interference1 at +0.1503: true
    # (they cannot hold together) but read as a contradiction. The line says which fail at the point shown
    ck = dict(load=gd.Load(torque_nm=100, n_rpm=1000), material="42CrMo4", face_width_mm=60)
    r = gd.optimize_shifts(17, 71, m=4, a_w=175, checks=ck)
    assert not r.success and len(r.conflict) >= 2
    assert _holds_together(4, 17, 71, r.x1 + r.x2, ck, r.conflict) < 0      # a genuine conflict on the a_w line
    fail = [c for c in r.conflict if r.margins[c] < 0]
    hold = [c for c in r.conflict if r.margins[c] >= 0]
    assert fail and hold                      # the case of the issue: one of them holds at the point shown
    line = next(s for s in repr(r).splitlines() if s.strip().startswith("conflict:"))
    assert f"here {', '.join(fail)} fail" in line and f"{', '.join(hold)} hold" in line
    assert "no shifts hold them all at once" in r.message
    # and the point is no optimum: the accuracy line does not claim a KKT point
    assert "Newton" not in r.accuracy and r.accuracy.startswith("no feasible point, so no optimum")
