"""The drive diagram (geardesign.drives.diagram.plot_drive): a gear motor then a gear pair, 4 kW in at
1500 rpm. The shaft labels carry the power flow worked by hand here (T = P/ω, T_out = T_in·u·η,
n_out = n_in/u), and the pair's two circles touch with radii in the ratio of the teeth."""
import math

import matplotlib
import pytest
from matplotlib.patches import Circle

import geardesign as gd
from geardesign.drives.diagram import plot_drive

matplotlib.use("Agg")


@pytest.fixture(scope="module")
def ax():
    import matplotlib.pyplot as plt

    drive = gd.Drive(power_kw=4, n_in_rpm=1500,
                     stages=[gd.GivenStage(12.5, 0.87, "gear motor"), gd.GearStage(2, z1=20, z2=50, efficiency=0.97)])
    ax = plot_drive(drive.analyse())
    yield ax
    plt.close(ax.figure)


def test_shaft_labels_carry_the_hand_power_flow(ax):
    t0 = 4000 / (2 * math.pi * 1500 / 60)          # 25.46 N·m
    t1 = t0 * 12.5 * 0.87                          # 276.9 N·m at 120 rpm
    t2 = t1 * 50 / 20 * 0.97                       # 671.6 N·m at 48 rpm
    texts = [t.get_text() for t in ax.texts]
    for k, (n, t) in enumerate([(1500, t0), (120, t1), (48, t2)]):
        assert f"shaft {k}\n{n:.4g} rpm\n{t:.4g} N·m" in texts
    assert "input\n4 kW" in texts


def test_gear_pair_circles_touch_in_the_tooth_ratio(ax):
    circles = [p for p in ax.patches if isinstance(p, Circle)]
    assert len(circles) == 2
    (c1, c2) = sorted(circles, key=lambda c: c.center[0])
    assert c2.radius / c1.radius == pytest.approx(50 / 20, rel=1e-12)
    assert c2.center[0] - c1.center[0] == pytest.approx(c1.radius + c2.radius, rel=1e-12)
