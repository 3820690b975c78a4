"""Jupyter views: regions, optima, profiles and drives show their text and their picture inline."""
import base64
import io
import re

import matplotlib
import pytest

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402

import geardesign as gd  # noqa: E402
from geardesign.inline import TEXT_LINES_MAX, html_view  # noqa: E402


def _picture(view: str):
    """The inline PNG of a view, decoded: (height, width) in pixels."""
    uri = re.search(r"src='data:image/png;base64,([A-Za-z0-9+/=]+)'", view)
    assert uri, view[:300]
    return mpimg.imread(io.BytesIO(base64.b64decode(uri.group(1))), format="png").shape[:2]


@pytest.mark.parametrize("make", [
    lambda: gd.feasible_region(17, 26, m=8, method="grid", n=61),
    lambda: gd.optimize_shifts(17, 26, m=8),
    lambda: gd.optimize_planetary_shifts(21, 43, 108, 3, 1.75),
    lambda: gd.tooth_profile(8, 17, 0.898, points=40),
    lambda: gd.ring_profile(2, 60, 0.2, points=40),
], ids=["region", "optimum", "planetary optimum", "profile", "ring"])
def test_results_show_a_picture(make):
    obj = make()
    view = obj._repr_html_()
    h, w = _picture(view)
    assert h > 200 and w > 300
    first = repr(obj).splitlines()[0]
    assert first[:40].replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;") in view
    assert "no picture" not in view


def test_optimum_picture_marks_the_active_check():
    r = gd.optimize_shifts(17, 26, m=8)     # max x1 + x2: ε_α = 1.2 is the one active check
    ax = r.plot_margins()
    labels = [t.get_text() for t in ax.get_yticklabels()]
    assert "contact_ratio (active)" in labels and sum("(active)" in t for t in labels) == len(r.active) == 1
    # only the active check's bar is outlined
    edges = [p.get_edgecolor()[3] for p in ax.patches]
    assert edges == [1.0 if n in r.active else 0.0 for n in r.margins]


def test_drive_analysis_shows_its_diagram():
    from pathlib import Path

    from geardesign.scene import load_scene
    from geardesign.scene.drive import compute_drive

    scene = Path(__file__).resolve().parents[1] / "studies" / "scenes" / "seed002_drive.toml"
    *_, analysis = compute_drive(load_scene(scene).sections["drive"])
    view = analysis._repr_html_()
    assert _picture(view)[1] > 300 and "DriveAnalysis" in view


def test_drive_optimum_shows_the_best_diagram():
    drive = gd.Drive(n_in_rpm=1450, power_kw=4.0, stages=[gd.GearStage(3), gd.GivenStage(2.0, 0.95)])
    opt = drive.optimize(total_ratio=6, ratio_tol=0.03)
    assert opt.best is not None
    view = opt._repr_html_()
    assert _picture(view)[1] > 300 and "DriveOptimum" in view


def test_a_failing_picture_leaves_the_text():
    def broken(ax):
        raise ValueError("no geometry")
    view = html_view("Result(ok)", broken)
    assert "Result(ok)" in view and "no picture: no geometry" in view


def test_long_text_is_cut():
    view = html_view("\n".join(f"line {k}" for k in range(100)))
    assert f"line {TEXT_LINES_MAX - 1}" in view and f"line {TEXT_LINES_MAX}<" not in view and "80 more lines" in view
