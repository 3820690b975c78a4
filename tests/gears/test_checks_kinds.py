"""The checks of helical and internal pairs: analytic gradients equal central differences of the
margins (hypothesis, tests/strategies.kinds), the ring pair's check list, and the conditions each
check restates, computed here from the geometry fields."""
from __future__ import annotations

import math

import mpmath as mp
import pytest
from hypothesis import assume, given

import geardesign as gd
from geardesign.gears.checks import CutterInterference, RingInterference, make_checks
from geardesign.gears.geometry import mesh_geometry
from geardesign.shifts.objectives import OBJECTIVES

from tests.strategies import SETTINGS, kinds


def _fd(d, func, h=1e-5):
    """Central differences with one Richardson step (error O(h⁴)): near a pole (the specific sliding as
    ρ_p -> 0, 1/ρ_p) a plain central difference at 1e-6 is off by ~1e-6 relative."""
    def central(h):
        out = []
        for dx in ((h, 0.0), (0.0, h)):
            up = mesh_geometry(d["mesh"], d["m"], d["x1"] + dx[0], d["x2"] + dx[1])
            dn = mesh_geometry(d["mesh"], d["m"], d["x1"] - dx[0], d["x2"] - dx[1])
            out.append(float(func(up) - func(dn)) / (2.0 * h))
        return out
    coarse, fine = central(h), central(h / 2.0)
    return [(4.0 * f - c) / 3.0 for f, c in zip(fine, coarse)]


@pytest.mark.slow
@SETTINGS
@given(kinds())
def test_check_gradients_match_central_differences(d):
    g = d["geo"]
    assume(abs(g.rho_l1) > 1e-4 * d["m"] and (d["internal"] or abs(g.rho_l2) > 1e-4 * d["m"]))
    geo = mesh_geometry(d["mesh"], d["m"], d["x1"], d["x2"])
    for check in make_checks(internal=d["internal"], eps_gamma_min=1.0 if d["face"] else None,
                             radial_assembly=True):
        if math.isnan(float(check.margin(geo))):   # undefined here: a failing row (next test), no slope
            continue
        an = [float(v) for v in check.gradient(geo)]
        fd = _fd(d, check.margin)
        for j in (0, 1):
            assert abs(an[j] - fd[j]) <= 1e-6 * max(1.0, abs(fd[j])), (check.name, j + 1, an[j], fd[j], d["internal"])


def test_an_undefined_check_fails_and_says_so():
    """A ring shift so negative that the cutter–ring mesh has no operating angle: with the default
    100 mm cutter at m = 1 (z0 = min(100, z2 − 18) = 43, x0 = 0) on a ring of 61 teeth, β = 8°,
    inv α_w0 = inv α_t + 2 (x2 − x0) tan α_n / (z2 − z0) < 0 (GOST 19274-73, computed here). The
    checks that need that mesh are undefined: the table reports them failing (margin −inf) with
    the reason, not a 0 that reads like a check at its limit."""
    x2, z0 = -0.738, 43
    alpha_t = math.atan(math.tan(math.radians(20.0)) / math.cos(math.radians(8.0)))
    assert math.tan(alpha_t) - alpha_t + 2 * (x2 - 0.0) * math.tan(math.radians(20.0)) / (61 - z0) < 0
    table = gd.GearPair(1.0, 5, 61, -0.738, x2, beta_deg=8.0, internal=True).checks().set_index("check")
    for name in ("interference2", "cutter_interference"):
        row = table.loc[name]
        assert row["margin"] == -math.inf and not row["ok"] and "undefined for this design" in row["label"]
    assert table.loc["tip_thickness1", "margin"] > 0          # the rest are evaluated as usual


@pytest.mark.slow
@SETTINGS
@given(kinds())
def test_objective_gradients_match_central_differences(d):
    g = d["geo"]
    assume(min(abs(g.rho_p1), abs(g.rho_p2)) > 1e-3 * d["m"])
    geo = mesh_geometry(d["mesh"], d["m"], d["x1"], d["x2"])
    for name in ("min_specific_pressure", "max_eps_alpha", "balanced_sliding"):
        obj = OBJECTIVES[name]
        for k, grad in enumerate(obj.piece_gradients(geo)):
            fd = _fd(d, lambda gg: obj.pieces(gg)[k])
            for j in (0, 1):
                assert abs(float(grad[j]) - fd[j]) <= 1e-6 * max(1.0, abs(fd[j])), (name, k, j, grad, fd)


def _shaper_form_radius(m, z2, x2, z0, x0=0.0, ha0=1.25, alpha_deg=20.0):
    """ρ_F2 = ρ_a0 + a_w0 sin α_w0 of a ring cut by a sharp-tipped shaper (docs/research/internal_helical.md
    §3), in 50-digit arithmetic: inv α_w0 = inv α + 2 (x2 − x0) tan α/(z2 − z0) solved by findroot."""
    mp.mp.dps = 50
    a = mp.radians(alpha_deg)
    inv_w0 = mp.tan(a) - a + 2 * (x2 - x0) * mp.tan(a) / (z2 - z0)
    aw = mp.findroot(lambda t: mp.tan(t) - t - inv_w0, a)
    a_w0 = m * (z2 - z0) * mp.cos(a) / (2 * mp.cos(aw))
    r_a0, r_b0 = m * z0 / mp.mpf(2) + (ha0 + x0) * m, m * z0 / mp.mpf(2) * mp.cos(a)
    return float(mp.sqrt(r_a0 ** 2 - r_b0 ** 2) + a_w0 * mp.sin(aw))


def test_large_shaper_cuts_the_ring_like_its_rack():
    """A shaper of many teeth tends to the rack of the same sharp tip (ρ_f = 0, h_l* = h_a0* = 1.25):
    the interference check's form limit then tends to the rack-equivalent ρ_l2 of the geometry."""
    rack = gd.BasicRack(rho_f=0.0)
    for z0 in (100, 200, 400):     # the gap closes like 1/z0 (in modules: ~35/z0 here)
        z2 = 2 * z0
        geo = mesh_geometry(gd.Mesh(60, z2, rack, internal=True), 1.0, 0.0, 0.4)
        form = float(RingInterference(cutter=gd.ShaperCutter(z0=z0)).limit_value(geo))
        assert form == pytest.approx(_shaper_form_radius(1.0, z2, 0.4, z0), rel=1e-12)
        assert 0.0 < float(geo["rho_l2"]) - form < 50.0 / z0


def test_ring_pair_check_list_and_what_each_restates():
    """KHK's internal pair 16/24 (x 0/0.5): every check computed again from the geometry fields."""
    pair = gd.pair_geometry(3, 16, 24, 0.0, 0.5, internal=True, tip_shortening=False)
    geo = mesh_geometry(gd.Mesh(16, 24, internal=True, tip_shortening=False), 3.0, 0.0, 0.5)
    checks = {c.name: c for c in make_checks(internal=True)}
    assert list(checks) == ["undercut1", "interference1", "interference2", "ring_tip", "tip_interference",
                            "cutter_trimming", "cutter_interference", "tip_thickness1", "tip_thickness2",
                            "contact_ratio"]
    m = 3.0
    want = {
        "undercut1": 0.0 - pair.x_min1,
        "interference1": (pair.rho_p1 - max(pair.rho_l1, 0.0)) / m,
        "interference2": (_shaper_form_radius(m, 24, 0.5, z0=8) - pair.rho_p2) / m,   # default cutter: 8 teeth
        "ring_tip": (pair.da2 - pair.db2) / 2 / m,
        "tip_thickness1": pair.sa1 / m - 0.25, "tip_thickness2": pair.sa2 / m - 0.25,
        "contact_ratio": pair.eps_alpha - 1.2,
    }
    del checks["tip_interference"], checks["cutter_trimming"]     # tests/gears/test_ring.py
    del checks["cutter_interference"]                              # test_cutter_interference_is_khk_5_4 below
    for name, value in want.items():
        assert float(checks[name].margin(geo)) == pytest.approx(value, rel=1e-12, abs=1e-14), name
    # the ring's path of contact ends where the pinion's tip circle crosses N1N2: ρ_p2 = N1N2 + ρ_a1
    n1n2 = pair.a_w * math.sin(math.radians(pair.alpha_w_deg))
    assert pair.rho_p2 == pytest.approx(n1n2 + math.sqrt((pair.da1 / 2) ** 2 - (pair.db1 / 2) ** 2), rel=1e-13)


def test_helical_tip_thickness_is_normal_and_eps_gamma_adds_eps_beta():
    """s_an = s_at cos β_a with tan β_a = tan β d_a/d (ISO 21771 (54)-(55)), ε_γ = ε_α + b sin β/(π m_n)."""
    g = gd.pair_geometry(3.5, 31, 30, 0.3, 0.35, beta_deg=21.0, face_width_mm=50.0)
    beta_a = math.atan(math.tan(math.radians(21.0)) * g.da1 / g.d1)
    assert g.san1 == pytest.approx(g.sa1 * math.cos(beta_a), rel=1e-14)
    assert g.eps_gamma == pytest.approx(g.eps_alpha + 50.0 * math.sin(math.radians(21.0)) / (math.pi * 3.5), rel=1e-14)
    geo = mesh_geometry(gd.Mesh(31, 30, beta_deg=21.0, face_width_mm=50.0), 3.5, 0.3, 0.35)
    tip = {c.name: c for c in make_checks(eps_gamma_min=2.5)}
    assert float(tip["tip_thickness1"].margin(geo)) == pytest.approx(g.san1 / 3.5 - 0.25, rel=1e-13)
    assert float(tip["total_contact_ratio"].margin(geo)) == pytest.approx(g.eps_gamma - 2.5, rel=1e-13)
    assert math.isnan(gd.pair_geometry(3.5, 31, 30, 0.3, 0.35, beta_deg=21.0).eps_beta)


def test_undercut_limit_of_a_helical_gear_is_the_exact_transverse_one():
    """x_min = h_l* − z sin²α_t/(2 cos β); the virtual-gear rule h_l* − z_n sin²α_n/2 is close only
    for small β (here within 2 % of z sin²α_n/2 at β = 15°)."""
    z, beta = 14, 15.0
    a_n = math.radians(20.0)
    a_t = math.atan(math.tan(a_n) / math.cos(math.radians(beta)))
    g = gd.pair_geometry(2.0, z, 40, 0.2, 0.0, beta_deg=beta)
    assert g.x_min1 == pytest.approx(gd.BasicRack().h_limit - z * math.sin(a_t) ** 2 / (2 * math.cos(math.radians(beta))),
                                     rel=1e-14)
    virtual = gd.BasicRack().h_limit - g.z_n1 * math.sin(a_n) ** 2 / 2
    assert abs(virtual - g.x_min1) < 0.02 * z * math.sin(a_n) ** 2 / 2


@SETTINGS
@given(kinds())
def test_center_distance_round_trip(d):
    """from_center_distance(a_w of the pair, x1) gives back x2, for both kinds (x_Σ = x2 − x1 for a ring)."""
    g = d["geo"]
    assume(g.g_alpha > 0)
    p = gd.GearPair.from_center_distance(d["m"], d["z1"], d["z2"], g.a_w, x1=d["x1"], rack=d["rack"],
                                         tip_shortening=d["ts"], beta_deg=d["beta"], internal=d["internal"],
                                         face_width_mm=d["face"])
    zs = d["z2"] - d["z1"] if d["internal"] else d["z1"] + d["z2"]
    assert abs(p.x2 - d["x2"]) <= 1e-11 * max(1.0, zs / 50), (p.x2, d["x2"])
    assert abs(p.geometry().a_w - g.a_w) <= 1e-12 * g.a_w


def test_pair_cli_takes_helical_and_internal(capsys):
    import json

    from geardesign.cli import main
    # KHK's 16/24 ring pair with x1 = 0 undercuts its pinion: a failing design, exit 1
    assert main(["pair", "--module", "3", "--z1", "16", "--z2", "24", "--x2", "0.5", "--internal",
                 "--no-tip-shortening", "--json"]) == 1
    out = json.loads(capsys.readouterr().out)
    assert out["input"]["internal"] is True and round(out["geometry"]["a_w"], 4) == 13.1683
    assert [c["check"] for c in out["checks"]][:4] == ["undercut1", "interference1", "interference2", "ring_tip"]
    assert main(["pair", "--module", "3.5", "--z1", "31", "--z2", "30", "--beta", "21", "--center-distance",
                 "116.5", "--face-width", "50", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert abs(out["geometry"]["a_w"] - 116.5) < 1e-9 and round(out["geometry"]["alpha_t_deg"], 10) == 21.2990642859
    assert main(["pair", "--module", "3", "--z1", "20", "--z2", "30", "--beta", "50"]) == 2
    assert "--beta must be in [0, 45]" in capsys.readouterr().err      # the option, not the keyword (issue 35 §7)


@pytest.mark.parametrize("m, z2, x2, z0", [(3.0, 24, 0.5, 8), (2.0, 40, 0.0, 20), (2.0, 40, 0.0, 30),
                                          (2.0, 50, -0.2, 25), (2.0, 30, 0.8, 10)])
def test_cutter_interference_is_khk_5_4(m, z2, x2, z0):
    """KHK eq. (5-4) with the cutter as the pinion, z0/z2 >= 1 − tan α_a2/tan α_w0, written out here in
    50 digits: margin·m = r_b2 tan α_a2 − (r_b2 − r_b0) tan α_w0, inv α_w0 = inv α + 2 x2 tan α/(z2 − z0)."""
    mp.mp.dps = 50
    a = mp.radians(20)
    inv = lambda t: mp.tan(t) - t   # noqa: E731
    aw0 = mp.findroot(lambda t: inv(t) - (inv(a) + 2 * mp.mpf(x2) * mp.tan(a) / (z2 - z0)), mp.mpf("0.5"))
    r_b2, r_b0 = m * z2 * mp.cos(a) / 2, m * z0 * mp.cos(a) / 2
    r_a2 = m * z2 / 2 - m * (1 - mp.mpf(x2))                    # the ring's tip, d_a2 = d2 − 2m(h_a* − x2)
    want = (mp.sqrt(r_a2 ** 2 - r_b2 ** 2) - (r_b2 - r_b0) * mp.tan(aw0)) / m
    geo = mesh_geometry(gd.Mesh(z2 - 10, z2, internal=True), m, 0.0, x2)
    c = CutterInterference(cutter=gd.ShaperCutter(z0=z0))
    assert float(c.margin(geo)) == pytest.approx(float(want), abs=1e-12)


@pytest.mark.slow
@pytest.mark.parametrize("m, z2, x2, z0", [(3.0, 24, 0.5, 8), (2.0, 40, 0.0, 20), (2.0, 40, 0.0, 30),
                                          (2.0, 50, 0.3, 30), (2.0, 30, 0.8, 10)])
def test_cutter_interference_fails_exactly_where_the_generated_ring_loses_its_tips(m, z2, x2, z0):
    """The ring generated by that cutter (profiles.ring: the envelope of the cutter's flank and tip,
    a material test over every cutter position) keeps the geometry's tip thickness s_a2 exactly when
    the check holds, and comes out thinner at the tip when it fails."""
    cutter = gd.ShaperCutter(z0=z0)
    geo = mesh_geometry(gd.Mesh(z2 - 10, z2, internal=True), m, 0.0, x2)
    margin = float(CutterInterference(cutter=cutter).margin(geo))
    generated = gd.ring_profile(m, z2, x2, cutter=cutter).tip_thickness_mm
    if margin >= 0:
        assert generated == pytest.approx(float(geo["sa2"]), abs=1e-9 * m)
    else:
        assert generated < float(geo["sa2"]) - 1e-3 * m
