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


# issue 35 §8: at their default size the diagrams overlapped labels ("u 3.52, η 0.98u 3.385, η 0.98") and a
# chain's sprocket covered the gear motor's box. Measured by the renderer: no label's box touches another's, no
# label sits on a wheel, no wheel on a box.
def _gear_gear_chain():
    return gd.Drive(power_kw=15, n_in_rpm=1460, stages=[
        gd.GearStage(3, 21, 74, 0.4, 0.6, face_width_mm=60, name="stage 1"),
        gd.GearStage(4, 22, 75, 0.4, 0.6, face_width_mm=80, name="stage 2"),
        gd.ChainStage(catalog="gost13568", z1=17, z2=34, name="chain")],
        shafts=[gd.Shaft(40, 60, at=1, name="intermediate"), gd.Shaft(60, 80, at=2, name="output"),
                gd.Shaft(70, 90, at=3, name="conveyor")])


def _three_gears():
    return gd.Drive(power_kw=15, n_in_rpm=1460, stages=[
        gd.GearStage(2.5, 20, 70, 0.4, 0.6, face_width_mm=45, name="s1"),
        gd.GearStage(3, 21, 68, 0.4, 0.6, face_width_mm=60, name="s2"),
        gd.GearStage(5, 22, 65, 0.4, 0.6, face_width_mm=80, name="s3")],
        shafts=[gd.Shaft(40, 60, at=1, name="s1 out"), gd.Shaft(60, 80, at=2, name="s2 out"),
                gd.Shaft(90, 110, at=3, name="out")])


def _motor_chain():
    return gd.Drive(power_kw=4, n_in_rpm=1500, stages=[
        gd.GivenStage(12.5, 0.87, "gear motor"), gd.ChainStage(catalog="gost13568", z1=13, z2=13),
        gd.GivenStage(2, 0.95, "belt drive with a longer name")], shafts=[gd.Shaft(60, 50, at=1), gd.Shaft(60, 50, at=2)])


def _extents(ax):
    from matplotlib.patches import FancyBboxPatch

    fig = ax.figure
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    texts = [t for t in [*ax.texts, ax.title] if t.get_text()]
    boxes = [p.get_window_extent(r) for p in ax.patches if isinstance(p, FancyBboxPatch)]
    wheels = [p.get_window_extent(r) for p in ax.patches if isinstance(p, Circle)]
    return [(t.get_text(), t.get_window_extent(r)) for t in texts], boxes, wheels


@pytest.mark.parametrize("make", [_gear_gear_chain, _three_gears, _motor_chain])
def test_no_label_overlaps_at_the_default_size(make):
    import matplotlib.pyplot as plt

    an = make().analyse()
    ax = plot_drive(an)
    try:
        labels, boxes, wheels = _extents(ax)
    finally:
        plt.close(ax.figure)
    assert len(labels) >= 3 * len(an.stages) + 2
    touching = [(a, b) for i, (a, ea) in enumerate(labels) for b, eb in labels[i + 1:] if ea.overlaps(eb)]
    assert not touching, touching
    inside = [t for t, e in labels if any(b.contains((e.x0 + e.x1) / 2, (e.y0 + e.y1) / 2) for b in boxes)]
    # a box's text stays in its box (a long name is wrapped)
    assert all(any(b.x0 <= e.x0 and e.x1 <= b.x1 and b.y0 <= e.y0 and e.y1 <= b.y1 for b in boxes)
               for t, e in labels if t in inside)
    free = [(t, e) for t, e in labels if t not in inside]
    assert not [(t, w) for t, e in free for w in wheels if e.overlaps(w)]
    assert not [(b, w) for b in boxes for w in wheels if b.overlaps(w)]
    # the figure holds its content (nothing cut at the edges)
    fig_box = ax.figure.bbox
    assert all(fig_box.x0 <= e.x0 and e.x1 <= fig_box.x1 and fig_box.y0 <= e.y0 and e.y1 <= fig_box.y1 for _, e in labels)


def test_layout_plot_draws_every_shaft_gear_and_bearing(tmp_path):
    # the top view of a drive with shafting: a rectangle per section, per gear (tip diameter × face width, at its
    # plane), per hub, two per bearing (above and below the shaft), at the sizes of the analysis' tables
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Rectangle

    import geardesign as gd

    an = gd.Drive(power_kw=11, n_in_rpm=960, shafting=gd.Shafting(), stages=[
        gd.GearStage(3, 20, 80, 0.3, 0.1, material="42CrMo4-IF", face_width_mm=45, name="fast"),
        gd.GearStage(4, 21, 84, 0.3, 0.1, material="42CrMo4-IF", face_width_mm=65, name="slow")]).analyse()
    ax = an.plot_layout()
    rects = [p for p in ax.patches if isinstance(p, Rectangle)]
    sections = sum(len(a.model.sections) for a in an.shafting["analyses"].values())
    hubs = sum(1 for es in an.shafting["elements"].values() for e in es if e.width_mm is None)
    assert len(rects) == sections + 4 + hubs + 2 * len(an.table("bearings"))
    widths = sorted(round(p.get_width(), 9) for p in rects)
    for st in an.stages:        # each gear at its face width and tip diameter
        geo = st["pair"].geometry()
        for da in (geo.da1, geo.da2):
            assert any(abs(p.get_width() - st["stage"].width_mm) < 1e-9 and abs(p.get_height() - da) < 1e-9
                       for p in rects)
    for _, b in an.table("bearings").iterrows():
        assert widths.count(round(b["B_mm"], 9)) >= 2
    path = tmp_path / "layout.png"
    ax.figure.savefig(path)
    plt.close(ax.figure)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(gd.GearDesignError, match="shafting"):
        gd.Drive(power_kw=11, n_in_rpm=960, stages=[gd.GearStage(3, 20, 80, face_width_mm=45)]).analyse().plot_layout()
