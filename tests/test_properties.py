"""Property tests (hypothesis) of the pair geometry: exact invariants, no numbers from geardesign.

Issue #2, "Property tests": s_w1 + s_w2 = p_w at zero backlash; clearance = c*·m with tip
shortening; ε_α from the path of contact equals ε_α from the tip angles; from_center_distance
round-trips. Also: analytic check gradients = central differences of the margins, d_w1/d_w2 =
z1/z2 and d_w1 + d_w2 = 2 a_w, the undercut margin has the sign of ρ_l, and swapping the two
gears swaps the per-gear fields.

Random valid designs (tests/strategies.py): z1, z2 in 5..400, x1, x2 in −0.8..2.5, m 0.5..20 mm,
α 14.5..30°; designs whose geometry does not exist (geardesign raises GearDesignError) are rejected
with ``assume``. Reproducible: derandomize=True.
"""
from __future__ import annotations

import math

import numpy as np
from hypothesis import assume, given

import geardesign as gd
from geardesign.gears.checks import make_checks
from geardesign.gears.geometry import mesh_geometry
from geardesign.gears.mesh import Mesh

from tests.strategies import SETTINGS, designs

PER_GEAR = [("d1", "d2"), ("db1", "db2"), ("dw1", "dw2"), ("da1", "da2"), ("df1", "df2"), ("s1", "s2"),
            ("sw1", "sw2"), ("sa1", "sa2"), ("alpha_a1_deg", "alpha_a2_deg"), ("clearance1", "clearance2"),
            ("x_min1", "x_min2"), ("rho_l1", "rho_l2"), ("rho_p1", "rho_p2"), ("d_l1", "d_l2"),
            ("d_p1", "d_p2"), ("o2n1", "o1n2"), ("sliding1_root", "sliding2_root"),
            ("sliding1_tip", "sliding2_tip"), ("san1", "san2"), ("z_n1", "z_n2")]


def close(a, b, tol, scale=0.0):
    return abs(a - b) <= tol * max(abs(a), abs(b), scale)


@SETTINGS
@given(designs())
def test_operating_tooth_thicknesses_fill_the_pitch(d):
    """Zero backlash: s_w1 + s_w2 = p_w = π d_w1 / z1."""
    g = d["geo"]
    assert close(g.sw1 + g.sw2, g.p_w, 1e-12), (g.sw1 + g.sw2, g.p_w)
    assert close(g.p_w, math.pi * g.dw2 / d["z2"], 1e-12)


@SETTINGS
@given(designs())
def test_clearance(d):
    """With shortening the tip clearance is c*·m on both sides; without it c*·m − Δy·m."""
    g, m = d["geo"], d["m"]
    want = d["rack"].c * m - (0.0 if d["ts"] else g.dy * m)
    tol = 1e-12 * m * (d["z1"] + d["z2"])
    assert abs(g.clearance1 - want) <= tol, (g.clearance1, want)
    assert abs(g.clearance2 - want) <= tol, (g.clearance2, want)


@SETTINGS
@given(designs())
def test_contact_ratio_from_tip_angles(d):
    """ε_α = g_α/p_b = [z1(tan α_a1 − tan α_w) + z2(tan α_a2 − tan α_w)]/(2π)."""
    g = d["geo"]
    tw = math.tan(math.radians(g.alpha_w_deg))
    eps = (d["z1"] * (math.tan(math.radians(g.alpha_a1_deg)) - tw)
           + d["z2"] * (math.tan(math.radians(g.alpha_a2_deg)) - tw)) / (2.0 * math.pi)
    assert close(g.eps_alpha, eps, 1e-11), (g.eps_alpha, eps)
    assert close(g.eps_alpha, g.g_alpha / g.p_b, 1e-14)


@SETTINGS
@given(designs())
def test_from_center_distance_round_trip(d):
    g = d["geo"]
    assume(g.eps_alpha > 0)   # a GearPair refuses tips that do not overlap (tests/gears/test_pair.py); this is for pairs that mesh
    p = gd.GearPair.from_center_distance(d["m"], d["z1"], d["z2"], g.a_w, x1=d["x1"], rack=d["rack"],
                                         tip_shortening=d["ts"])
    assert p.x1 == d["x1"]
    assert abs(p.x2 - d["x2"]) <= 1e-12 * (d["z1"] + d["z2"]), (p.x2, d["x2"])
    assert close(p.geometry().a_w, g.a_w, 1e-12)


def _sliding_balance_exists(d, x_sum):
    """Independent scan: is there an x1 with ϑ1,root = ϑ2,root among existing, interference-free splits?"""
    x1 = x_sum / 2.0 + np.linspace(-6.0, 6.0, 2401)
    geo = mesh_geometry(Mesh(d["z1"], d["z2"], d["rack"], d["ts"]), d["m"], x1, x_sum - x1)
    with np.errstate(invalid="ignore"):
        ok = ((geo["da1"] > geo["db1"]) & (geo["da2"] > geo["db2"]) & (geo["df1"] > 0) & (geo["df2"] > 0)
              & (geo["rho_p1"] > 0) & (geo["rho_p2"] > 0))
    diff = geo["sliding1_root"] - geo["sliding2_root"]
    return bool(np.any(ok[:-1] & ok[1:] & (np.sign(diff[:-1]) != np.sign(diff[1:]))))


@SETTINGS
@given(designs())
def test_from_center_distance_balanced_sliding(d):
    """x1=None splits the x-sum so that the specific sliding at both roots is equal."""
    g = d["geo"]
    x_sum = d["x1"] + d["x2"]
    assume(_sliding_balance_exists(d, x_sum))
    p = gd.GearPair.from_center_distance(d["m"], d["z1"], d["z2"], g.a_w, rack=d["rack"], tip_shortening=d["ts"])
    q = p.geometry()
    assert abs(p.x1 + p.x2 - x_sum) <= 1e-12 * (d["z1"] + d["z2"])
    assert abs(q.sliding1_root - q.sliding2_root) <= 1e-9 * max(1.0, abs(q.sliding1_root)), \
        (p.x1, p.x2, q.sliding1_root, q.sliding2_root)


@SETTINGS
@given(designs())
def test_check_gradients_match_central_differences(d):
    m, rack, ts = d["m"], d["rack"], d["ts"]
    g = d["geo"]
    # stay off the kink of Interference's max(ρ_l, 0)
    assume(abs(g.rho_l1) > 1e-4 * m and abs(g.rho_l2) > 1e-4 * m)
    geo = mesh_geometry(Mesh(d["z1"], d["z2"], rack, ts), m, d["x1"], d["x2"])
    h = 1e-6
    for check in make_checks(jamming=True):
        an = [float(v) for v in check.gradient(geo)]
        for j in (0, 1):
            dx = (h, 0.0) if j == 0 else (0.0, h)
            up = mesh_geometry(Mesh(d["z1"], d["z2"], rack, ts), m, d["x1"] + dx[0], d["x2"] + dx[1])
            dn = mesh_geometry(Mesh(d["z1"], d["z2"], rack, ts), m, d["x1"] - dx[0], d["x2"] - dx[1])
            fd = float(check.margin(up) - check.margin(dn)) / (2.0 * h)
            assert abs(an[j] - fd) <= 1e-6 * max(1.0, abs(fd)), (check.name, j + 1, an[j], fd)


@SETTINGS
@given(designs())
def test_pitch_circles_and_undercut_sign(d):
    g = d["geo"]
    assert close(g.dw1 * d["z2"], g.dw2 * d["z1"], 1e-14)
    assert close(g.dw1 + g.dw2, 2.0 * g.a_w, 1e-14)
    geo = mesh_geometry(Mesh(d["z1"], d["z2"], d["rack"], d["ts"]), d["m"], d["x1"], d["x2"])
    for j, check in ((1, make_checks()[0]), (2, make_checks()[1])):
        assert check.name == f"undercut{j}"
        assert np.sign(float(check.margin(geo))) == np.sign(getattr(g, f"rho_l{j}"))


@SETTINGS
@given(designs())
def test_swapping_the_gears_swaps_the_fields(d):
    g = d["geo"]
    s = gd.pair_geometry(d["m"], d["z2"], d["z1"], d["x2"], d["x1"], rack=d["rack"], tip_shortening=d["ts"])
    swapped = {a: b for a, b in PER_GEAR} | {b: a for a, b in PER_GEAR}
    for name in gd.GEOMETRY_FIELDS:
        ours, theirs = getattr(g, name), getattr(s, swapped.get(name, name))
        unit = gd.GEOMETRY_FIELDS[name][0]
        scale = d["m"] if unit == "mm" else 1.0
        assert close(ours, theirs, 1e-12, scale), (name, ours, theirs)
