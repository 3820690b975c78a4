"""The planetary drawing (geardesign.profiles.planetary.plot_planetary) of an unshifted standard set,
whose circles are known by hand (ISO 21771: d = m·z, d_a = m·(z + 2) external, a = m·(z_s + z_p)/2 at
x = 0): the circles drawn are where they must be, the planets on the carrier arm, the neighbour gap
2·a·sin(π/n) − d_a,planet written on it."""
import math

import matplotlib
import numpy as np
import pytest

import geardesign as gd
from geardesign.profiles.planetary import plot_planetary

matplotlib.use("Agg")

M, ZS, ZP, ZR, N = 2.0, 18, 27, 72, 3
A = M * (ZS + ZP) / 2                     # 45 mm


def _circles(ax):
    """(centre x, centre y, radius) of every drawn closed circle, from its points."""
    out = []
    for line in ax.lines:
        x, y = line.get_xdata(), line.get_ydata()
        if len(x) == 361:
            cx, cy = (x.max() + x.min()) / 2, (y.max() + y.min()) / 2
            r = np.hypot(x - cx, y - cy)
            assert np.ptp(r) < 1e-9 * r.max()
            out.append((cx, cy, r[0]))
    return out


@pytest.fixture(scope="module")
def ax():
    import matplotlib.pyplot as plt

    ax = plot_planetary(gd.PlanetarySet(M, ZS, ZP, ZR, N))
    yield ax
    plt.close(ax.figure)


def test_circles_of_sun_and_planets(ax):
    circles = _circles(ax)
    assert len(circles) == 3 * (N + 2) + 1                 # tip, pitch, root of each gear; the carrier
    centred = sorted(r for cx, cy, r in circles if abs(cx) < 1e-9 and abs(cy) < 1e-9)
    for r in (M * (ZS + 2) / 2, M * ZS / 2, A):             # sun tip and pitch, carrier arm
        assert min(abs(c - r) for c in centred) < 1e-9, r
    for k in range(N):
        t = math.radians(90 + 360 * k / N)
        here = [r for cx, cy, r in circles if math.hypot(cx - A * math.cos(t), cy - A * math.sin(t)) < 1e-9]
        assert len(here) == 3
        assert min(abs(r - M * (ZP + 2) / 2) for r in here) < 1e-9      # planet tip
        assert min(abs(r - M * ZP / 2) for r in here) < 1e-9            # planet pitch


def test_neighbour_gap_is_labelled(ax):
    gap = 2 * A * math.sin(math.pi / N) - M * (ZP + 2)      # 77.94 − 58 = 19.94 mm
    assert any(t.get_text().strip() == f"{gap:.3g} mm" for t in ax.texts)


def test_title_names_the_set(ax):
    title = ax.get_title()
    assert "m = 2 mm" in title and f"a_w = {A:.6g} mm" in title
    assert f"ratio {1 + ZR / ZS:.6g}" in title              # ring fixed: u = 1 + z_r/z_s = 5
