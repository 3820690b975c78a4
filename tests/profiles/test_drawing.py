"""The meshing drawing: its line-of-action points against the pair geometry, and the generated teeth
of both gears, put in mesh at the operating centre distance, touch without overlapping."""
import math

import matplotlib
import numpy as np
import pytest

import geardesign as gd
from geardesign.profiles.drawing import contact_points
from geardesign.profiles.mesh import pair_outlines

matplotlib.use("Agg")

PAIRS = [(8.0, 17, 26, 0.898, 0.517), (3.0, 12, 24, 0.6, 0.36), (2.0, 20, 40, 0.0, 0.0)]


@pytest.mark.parametrize("m, z1, z2, x1, x2", PAIRS)
def test_line_of_action_points_match_the_geometry(m, z1, z2, x1, x2):
    pair = gd.GearPair(m, z1, z2, x1, x2)
    g = pair.geometry()
    c = contact_points(pair._geo)
    assert np.linalg.norm(c["E"] - c["A"]) == pytest.approx(g.g_alpha, abs=1e-9 * m)
    assert np.linalg.norm(c["N2"] - c["N1"]) == pytest.approx(g.a_w * math.sin(math.radians(g.alpha_w_deg)),
                                                              abs=1e-9 * m)
    assert np.linalg.norm(c["N1"]) == pytest.approx(g.db1 / 2, abs=1e-9 * m)
    assert np.linalg.norm(c["N2"] - np.array([0.0, g.a_w])) == pytest.approx(g.db2 / 2, abs=1e-9 * m)
    d1, d2 = c["P"] - c["N1"], c["N2"] - c["N1"]
    assert abs(d1[0] * d2[1] - d1[1] * d2[0]) <= 1e-9 * m * np.linalg.norm(d2)   # P on N1N2
    assert np.linalg.norm(c["A"]) < g.da1 / 2 and np.linalg.norm(c["E"]) == pytest.approx(g.da1 / 2, abs=1e-9 * m)


@pytest.mark.slow
@pytest.mark.parametrize("m, z1, z2, x1, x2", PAIRS)
@pytest.mark.parametrize("roll_deg", [0.0, 4.0])
def test_teeth_in_mesh_touch_without_overlap(m, z1, z2, x1, x2, roll_deg):
    """Zero backlash at a_w: the outlines come within 1e-4·m of each other and never cross."""
    from matplotlib.path import Path

    pair = gd.GearPair(m, z1, z2, x1, x2)
    geo = pair._geo
    (_, *g1), (_, *g2) = pair_outlines(pair, roll_deg, points=200)
    a1, a2 = np.column_stack(g1), np.column_stack(g2)
    near = np.linalg.norm(a2 - np.array([0.0, float(geo["dw1"]) / 2]), axis=1) < 3 * m
    inside = Path(a1).contains_points(a2[near], radius=-1e-6 * m)
    assert not inside.any()
    gap = min(np.min(np.linalg.norm(a1 - q, axis=1)) for q in a2[near])
    assert gap < 1e-2 * m


def test_plot_mesh_draws_and_titles():
    ax = gd.plot_mesh(gd.GearPair(8, 17, 26, 0.898, 0.517))
    assert "a_w = 181.602 mm" in ax.get_title() and "ε_α = 1.153" in ax.get_title()
    import matplotlib.pyplot as plt
    plt.close(ax.figure)


@pytest.mark.parametrize("m, z1, z2, x1, x2", PAIRS)
def test_diagrams_end_and_pitch_values_are_the_geometry_s(m, z1, z2, x1, x2):
    """Along N1N2: at A (gear 1's root, gear 2's tip) and E the sliding equals the geometry's end
    values, at P it is zero for both gears and γ equals the pitch-point coefficient."""
    from geardesign.profiles.drawing import line_of_action_diagrams

    pair = gd.GearPair(m, z1, z2, x1, x2)
    g = pair.geometry()
    d0 = line_of_action_diagrams(pair._geo, n=10)
    d = line_of_action_diagrams(pair._geo, s_mm=[d0["s_A"], d0["s_P"], d0["s_E"]])
    assert d["sliding1"][0] == pytest.approx(g.sliding1_root, abs=1e-9)
    assert d["sliding2"][0] == pytest.approx(g.sliding2_tip, abs=1e-9)
    assert d["sliding1"][2] == pytest.approx(g.sliding1_tip, abs=1e-9)
    assert d["sliding2"][2] == pytest.approx(g.sliding2_root, abs=1e-9)
    assert abs(d["sliding1"][1]) < 1e-12 and abs(d["sliding2"][1]) < 1e-12
    assert d["pressure"][1] == pytest.approx(g.spec_pressure_pitch, rel=1e-12)
    axes = gd.plot_diagrams(pair)
    import matplotlib.pyplot as plt
    plt.close(axes[0].figure)
