"""Sensitivities of the optimum to the checks' limits, smooth and at corners (one-sided), for
both local methods, against finite differences of re-solved optima."""
import pytest

import geardesign as gd
from geardesign import checks as ck


class _Tightened(ck.Undercut):
    """undercut1 with extra margin ``delta`` required (the limit raised by delta)."""

    def __init__(self, delta):
        super().__init__(gear=1)
        object.__setattr__(self, "delta", delta)

    def margin(self, geo):
        return super().margin(geo) - self.delta

    def part_margins(self, geo):
        return [self.margin(geo)]


def _corner_fun(delta, z1=17, z2=26):
    checks = [_Tightened(delta)] + [c for c in ck.make_checks() if c.name != "undercut1"]
    return gd.optimize_shifts(z1, z2, "max_eps_alpha", checks=checks).fun


@pytest.mark.parametrize("z1,z2", [(17, 26), (10, 40), (20, 60)])
def test_one_sided_sensitivities_at_a_degenerate_corner(z1, z2):
    """At the undercut1/interference1 corner of max_eps_alpha three constraints are active in
    2-D: raising the undercut limit moves the optimum, lowering it does not. Both methods report
    both sides, equal to finite differences of re-solved optima."""
    base = gd.optimize_shifts(z1, z2, "max_eps_alpha")
    if "undercut1" not in base.sensitivity_sides:
        pytest.fail(f"{z1}/{z2}: expected a corner at undercut1, got {base.active}")
    h = 1e-5
    f0 = _corner_fun(0.0, z1, z2)
    raised = (_corner_fun(h, z1, z2) - f0) / h
    lowered = (f0 - _corner_fun(-h, z1, z2)) / h
    for method in ("exact", "convex"):
        r = gd.optimize_shifts(z1, z2, "max_eps_alpha", method=method)
        sides = r.sensitivity_sides["undercut1"]
        assert sides["raised"] == pytest.approx(raised, abs=1e-3), method
        assert sides["lowered"] == pytest.approx(lowered, abs=1e-3), method
    assert abs(lowered) < 1e-6 < abs(raised)


def test_smooth_sensitivity_matches_finite_difference_for_both_methods():
    h = 1e-5
    up = gd.optimize_shifts(30, 90, checks={"eps_alpha_min": 1.2 + h}).fun
    down = gd.optimize_shifts(30, 90, checks={"eps_alpha_min": 1.2 - h}).fun
    fd = (up - down) / (2 * h)
    for method in ("exact", "convex"):
        r = gd.optimize_shifts(30, 90, method=method)
        assert r.sensitivity["contact_ratio"] == pytest.approx(fd, rel=1e-4)
        assert r.sensitivity_sides == {}


def _fun_with(z1, z2, objective, eps_limit=1.2, undercut_delta=0.0, only_contact=False, method="exact"):
    if only_contact:
        checks = [ck.ContactRatio(limit=eps_limit)]
    else:
        checks = [_Tightened(undercut_delta)] + [c for c in ck.make_checks(eps_alpha_min=eps_limit)
                                                 if c.name != "undercut1"]
    return gd.optimize_shifts(z1, z2, objective, checks=checks, method=method)


@pytest.mark.parametrize("case", [
    # a vertex of two checks (undercut1 and contact_ratio both active, multipliers unique)
    dict(z1=10, z2=40, objective="max_x_sum"),
    # the window's edge and one check: 40/120 with only ε_α >= 1 runs to x2 = 3
    dict(z1=40, z2=120, objective="max_x_sum", only_contact=True),
])
def test_sensitivities_at_other_corners_agree_with_finite_differences(case):
    h = 1e-5
    only = case.get("only_contact", False)
    args = (case["z1"], case["z2"], case["objective"])
    fd = {"contact_ratio": (_fun_with(*args, eps_limit=1.0 + h if only else 1.2 + h, only_contact=only).fun
                            - _fun_with(*args, eps_limit=1.0 - h if only else 1.2 - h, only_contact=only).fun) / (2 * h)}
    if not only:
        fd["undercut1"] = (_fun_with(*args, undercut_delta=h).fun - _fun_with(*args, undercut_delta=-h).fun) / (2 * h)
    for method in ("exact", "convex"):
        r = _fun_with(*args, eps_limit=1.0 if only else 1.2, only_contact=only, method=method)
        assert r.sensitivity_sides == {}, method
        for name, value in fd.items():
            assert r.sensitivity[name] == pytest.approx(value, rel=1e-4, abs=1e-6), (method, name)
