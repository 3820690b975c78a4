"""The interactive contour (geardesign.shifts.contour_html) without a browser (tests/report/test_pages.py opens it
in Chromium): each check's zero curve in its registry colour, the feasible region, the marks, the hover grid's
margins equal to the problem's own at a node, and the file written whole, offline, not replaced."""
import numpy as np
import pytest

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.shifts.contour_html import contour_figure, write_contour_html
from geardesign.shifts.looks import check_style


@pytest.fixture(scope="module")
def region():
    return gd.feasible_region(17, 26, method="grid", n=81)


def test_the_figure(region):
    r = gd.optimize_shifts(17, 26)
    fig = contour_figure(region, optimum=r, proposed=(0.898, 0.517), n=41)
    names = [t.name for t in fig.data]
    assert "feasible region" in names
    for check in region.problem.checks:
        curves = [t for t in fig.data if t.name == check.name]
        if curves:                                   # a check whose zero curve crosses the window
            assert curves[0].line.color.lower() in _hexes(check_style(check.name)[0])
    assert "Blocking contour" in fig.layout.title.text
    assert fig.layout.xaxis.range == (-1.5, 3.0)


def _hexes(colour):
    from matplotlib.colors import to_hex
    return {to_hex(colour).lower(), str(colour).lower()}


def test_hover_margins_are_the_problems(region):
    fig = contour_figure(region, n=21)
    hover = fig.data[0]
    g = np.linspace(-1.5, 3.0, 21)
    i, j = 7, 5                                   # the node x1 = g[j], x2 = g[i] (row-major: [x2, x1])
    geo = region.problem.geo(np.array([g[j]]), np.array([g[i]]))
    want = region.problem.margins(geo)[:, 0]
    got = np.array(hover.customdata[i][j][:len(want)], dtype=float)
    assert np.allclose(got, np.round(want, 4), atol=1e-12, equal_nan=True)
    held = bool((want >= 0).all())
    assert (hover.text[i][j] == "every check holds") == held


def test_the_file_is_whole_offline_and_not_replaced(region, tmp_path):
    path = write_contour_html(region, tmp_path / "contour.html", n=21)
    html = path.read_text(encoding="utf-8")
    assert "plotly" in html and "<script src=\"http" not in html     # plotly.js inside: works offline
    with pytest.raises(GearDesignError, match="exists"):
        write_contour_html(region, path, n=21)
    with pytest.raises(GearDesignError, match="region must be"):
        contour_figure("not a region")
