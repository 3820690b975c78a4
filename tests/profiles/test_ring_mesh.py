"""Internal pairs in mesh (issue 14 with issue 12): the line-of-action points and diagrams against the pair
geometry, the pinion and the generated ring touching without overlap, the annulus exported, and KHK's
internal example (m 3, z 16/24, x 0/0.5; tests/data/internal_helical_examples.csv) drawn as it is cut."""
import math

import matplotlib
import numpy as np
import pytest
from matplotlib.path import Path

import geardesign as gd
from geardesign.profiles.drawing import contact_points, line_of_action_diagrams
from geardesign.profiles.export import outline_area_mm2
from geardesign.profiles.mesh import pair_outlines, placed

from .test_mesh import _centroid, _read

matplotlib.use("Agg")

# (m, z1, z2, x1, x2, beta_deg)
PAIRS = [(2.0, 20, 60, 0.3, 0.6, 0.0), (3.0, 16, 24, 0.0, 0.5, 0.0), (2.5, 17, 71, 0.5, 0.8, 20.0),
         (4.0, 25, 90, 0.0, 0.3, 0.0)]


def _pair(m, z1, z2, x1, x2, beta):
    return gd.GearPair(m, z1, z2, x1, x2, beta_deg=beta, internal=True)


@pytest.mark.parametrize("m, z1, z2, x1, x2, beta", PAIRS)
def test_internal_line_of_action_points_match_the_geometry(m, z1, z2, x1, x2, beta):
    """N1 and N2 on one side of P, N1N2 = a_w sin α_w, A on the ring's tip circle, E on the pinion's,
    A–E the geometry's g_α; N1A the pinion's ρ at the start of contact (KHK: −0.029 mm, the data file)."""
    pair = _pair(m, z1, z2, x1, x2, beta)
    g = pair.geometry()
    c = contact_points(pair._geo)
    o2 = np.array([0.0, -g.a_w])
    assert np.linalg.norm(c["N1"]) == pytest.approx(g.db1 / 2, abs=1e-9 * m)
    assert np.linalg.norm(c["N2"] - o2) == pytest.approx(g.db2 / 2, abs=1e-9 * m)
    assert np.linalg.norm(c["N2"] - c["N1"]) == pytest.approx(g.a_w * math.sin(math.radians(g.alpha_w_deg)), abs=1e-9 * m)
    assert c["s_N2"] < 0 < c["s_P"]                        # N2, N1, P in this order
    assert np.linalg.norm(c["A"] - o2) == pytest.approx(g.da2 / 2, abs=1e-9 * m)
    assert np.linalg.norm(c["E"]) == pytest.approx(g.da1 / 2, abs=1e-9 * m)
    assert c["s_E"] - c["s_A"] == pytest.approx(g.g_alpha, abs=1e-9 * m)
    assert c["s_A"] == pytest.approx(g.rho_p1, abs=1e-9 * m)
    for k in ("A", "E", "P"):                              # on the line through N1 and N2
        d1, d2 = c[k] - c["N1"], c["N2"] - c["N1"]
        assert abs(d1[0] * d2[1] - d1[1] * d2[0]) <= 1e-9 * m * np.linalg.norm(d2)
    if (m, z1, z2) == (3.0, 16, 24):
        assert c["s_A"] == pytest.approx(-0.0290945278, abs=1e-9)


@pytest.mark.parametrize("m, z1, z2, x1, x2, beta", PAIRS)
def test_internal_diagrams_end_and_pitch_values_are_the_geometry_s(m, z1, z2, x1, x2, beta):
    pair = _pair(m, z1, z2, x1, x2, beta)
    g = pair.geometry()
    d0 = line_of_action_diagrams(pair._geo, n=10)
    d = line_of_action_diagrams(pair._geo, s_mm=[d0["s_A"], d0["s_P"], d0["s_E"]])
    assert d["sliding1"][0] == pytest.approx(g.sliding1_root, rel=1e-9)
    assert d["sliding2"][0] == pytest.approx(g.sliding2_tip, rel=1e-9)
    assert d["sliding1"][2] == pytest.approx(g.sliding1_tip, rel=1e-9)
    assert d["sliding2"][2] == pytest.approx(g.sliding2_root, rel=1e-9)
    assert abs(d["sliding1"][1]) < 1e-12 and abs(d["sliding2"][1]) < 1e-12
    assert d["pressure"][1] == pytest.approx(g.spec_pressure_pitch, rel=1e-12)
    import matplotlib.pyplot as plt
    plt.close(gd.plot_diagrams(pair)[0].figure)


def _penetration(pair, roll_deg, points=200, profiles=None):
    """(how deep pinion points lie in the ring's material, how deep ring points lie in the pinion, the
    closest approach; mm), and the ring points inside the pinion (ring-centred radii)."""
    profiles = gd.pair_profiles(pair, points) if profiles is None else profiles
    out = {n: np.column_stack([x, y]) for n, x, y in placed(pair, *profiles, math.radians(roll_deg))}
    g1, bore = out["gear1"], out["gear2"]
    a_w = pair.geometry().a_w

    def depth(pts, poly):
        """Distance of each point to the polyline: to the two segments at its nearest vertex (the
        outlines are dense enough that the nearest segment is one of them)."""
        from scipy.spatial import cKDTree

        if not len(pts):
            return np.zeros(0)
        j = np.clip(cKDTree(poly).query(pts)[1], 1, len(poly) - 2)
        best = np.full(len(pts), np.inf)
        for a, b in ((poly[j - 1], poly[j]), (poly[j], poly[j + 1])):
            ab = b - a
            t = np.clip(((pts - a) * ab).sum(1) / np.maximum((ab * ab).sum(1), 1e-300), 0.0, 1.0)
            best = np.minimum(best, np.hypot(*(a + t[:, None] * ab - pts).T))
        return best

    # only teeth within 12 modules of the pitch point can meet
    near = np.hypot(g1[:, 0], g1[:, 1] - float(pair._geo["dw1"]) / 2) < 12 * pair.m
    near2 = np.hypot(bore[:, 0], bore[:, 1] - float(pair._geo["dw1"]) / 2) < 12 * pair.m
    p_in_ring = g1[near & ~Path(bore).contains_points(g1)]
    r_in_pin = bore[near2][Path(g1).contains_points(bore[near2])]
    d1 = depth(p_in_ring, bore).max(initial=0.0)
    d2 = depth(r_in_pin, g1).max(initial=0.0)
    gap = depth(g1[near][::5], bore).min()
    return d1, d2, gap, np.hypot(r_in_pin[:, 0], r_in_pin[:, 1] + a_w)


@pytest.mark.slow
@pytest.mark.parametrize("m, z1, z2, x1, x2, beta", [PAIRS[0], PAIRS[2]])
@pytest.mark.parametrize("roll_deg", [0.0, 5.0])
def test_pinion_and_generated_ring_touch_without_overlap(m, z1, z2, x1, x2, beta, roll_deg):
    """Zero backlash at a_w: pinion and ring (pairs passing every check) come within 1e-2·m and neither
    enters the other by more than the outlines' chords (1e-5·m at 200 points a segment)."""
    pair = _pair(m, z1, z2, x1, x2, beta)
    assert pair.ok()
    d1, d2, gap, _ = _penetration(pair, roll_deg)
    assert d1 <= 1e-5 * m and d2 <= 1e-5 * m
    assert gap < 1e-2 * m


@pytest.mark.slow
@pytest.mark.parametrize("x2, fails", [(0.3, True), (0.6, False)])
def test_ring_tip_runs_into_the_pinion_fillet_exactly_when_interference1_fails(x2, fails):
    """4 mm, 25/90, x1 = 0: with x2 = 0.3 the ring's tip meets the pinion below its form circle
    (interference1's margin −0.085), and over one pinion pitch of roll the generated teeth overlap
    by more than 1e-4·m; with x2 = 0.6 (margin +0.154, every check passes) they never do."""
    pair = _pair(4.0, 25, 90, 0.0, x2, 0.0)
    checks = pair.checks()
    assert (not bool(checks.set_index("check").loc["interference1", "ok"])) == fails
    profiles = gd.pair_profiles(pair, 120)
    deepest = max(max(_penetration(pair, roll, profiles=profiles)[:2]) for roll in np.linspace(0.0, 360.0 / 25, 13))
    assert (deepest > 1e-4 * 4.0) == fails


@pytest.mark.slow
def test_khk_internal_example_drawn_as_cut():
    """KHK's 16/24 example, its ring cut by the default cutter for a 24-tooth ring (8 teeth): the ring's
    tip circle lies past that cutter's interference point N0, so the cutter trims the ring's tips
    (cutting_interference; tests/profiles/test_ring.py sweeps the cutter to confirm the shape): the
    generated tip thickness is below the geometry's s_a2 (2.62 mm, KHK's involute value)."""
    pair = _pair(3.0, 16, 24, 0.0, 0.5, 0.0)
    _, ring = gd.pair_profiles(pair)
    assert ring.z0 == 8 and ring.cutting_interference
    assert ring.tip_thickness_mm < pair.geometry().sa2 - 0.1
    ax = gd.plot_mesh(pair)
    assert "a_w = 13.1683 mm" in ax.get_title() and "z0 = 8" in ax.get_title()
    import matplotlib.pyplot as plt
    plt.close(ax.figure)


@pytest.mark.parametrize("suffix", [".svg", ".dxf", ".csv"])
def test_internal_pair_export_reopens_as_pinion_and_annulus(tmp_path, suffix):
    pair = _pair(2.0, 20, 60, 0.3, 0.6, 0.0)
    path = gd.export_profiles(pair, tmp_path / f"gears{suffix}", points=60, roll_deg=2.0)
    read = _read(path)
    assert sorted(read) == ["gear1", "gear2", "gear2_rim"]
    placed = {n: (x, y) for n, x, y in pair_outlines(pair, 2.0, points=60)}
    a_w = pair.geometry().a_w
    for name, centre in (("gear1", (0.0, 0.0)), ("gear2", (0.0, -a_w)), ("gear2_rim", (0.0, -a_w))):
        x, y = read[name]
        assert (x[0], y[0]) == (x[-1], y[-1])
        assert outline_area_mm2(x, y) == pytest.approx(outline_area_mm2(*placed[name]), rel=1e-9)
        assert np.allclose(_centroid(x, y), centre, atol=1e-9 * a_w)
    assert outline_area_mm2(*read["gear2_rim"]) > outline_area_mm2(*read["gear2"])
