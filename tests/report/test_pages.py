"""The calculation report and the interactive contour, opened in a real (headless) Chromium.

The report's geometry table is read back from the rendered page and compared with KHK's published
example (12/24 teeth, m 3, x 0.6/0.36; tests/data/gear_examples.csv, E1_KHK_ext_12_24, from KHK's
"Calculation of Gears" as quoted in bolsover/UtilitiesForAlibre's unit tests)."""
import csv
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

import geardesign as gd
from geardesign.cli import main
from geardesign.errors import GearDesignError
from geardesign.shifts.contour_html import contour_figure

from .browser import dump_dom, print_pages, tables

pytestmark = pytest.mark.slow   # clusters, browsers, notebooks: seconds each (CONTRIBUTING.md)

DATA = Path(__file__).resolve().parents[1] / "data" / "gear_examples.csv"


def _khk():
    rows = [r for r in csv.DictReader(DATA.open()) if r["example_id"] == "E1_KHK_ext_12_24" and r["published_value"]]
    return {(r["parameter"], r["member"]): float(r["published_value"]) for r in rows}


@pytest.fixture(scope="module")
def khk_report(tmp_path_factory):
    path = tmp_path_factory.mktemp("report") / "khk.html"
    gd.pair_report(gd.GearPair(3, 12, 24, 0.6, 0.36), path)      # GearPair.report (deprecated) alike
    return path


def test_report_is_self_contained_and_printable(khk_report):
    page = khk_report.read_text(encoding="utf-8")
    # nothing fetched from outside: no script, stylesheet or picture by URL
    assert not re.search(r'(src|href)="(https?:)?//', page)
    assert "@media print" in page and "@page" in page
    assert page.count('src="data:image/png;base64,') == 2      # the contour and the mesh drawing


def test_report_in_browser_matches_khk(khk_report):
    dom = dump_dom(khk_report)
    # the verdict comes before every table
    assert dom.index('class="verdict') < dom.index("<table")
    assert "Every check holds" in dom               # KHK's pair: ε_α 1.202 >= 1.2, tips 0.42 m, 0.74 m
    checks, inputs, geometry = tables(dom)
    assert checks[0][:3] == ["verdict", "check", "what it asks"]
    assert {r[1] for r in checks[1:]} >= {"contact_ratio", "undercut1", "tip_thickness2"}
    assert geometry[0] == ["quantity", "symbol", "unit", "gear 1", "gear 2"]
    by_symbol = {r[1]: r for r in geometry[1:]}
    pub = _khk()
    # symbol on the page -> (published parameter, tolerance: the page's rounding + the source's)
    for sym, name, tol in (("db", "d_b", 1e-3), ("dw", "d_w", 1e-3), ("da", "d_a", 1e-3), ("df", "d_f", 1e-3),
                           ("d", "d", 1e-3)):
        row = by_symbol[sym]
        assert abs(float(row[3]) - pub[(name, "1")]) <= tol, (sym, row)
        assert abs(float(row[4]) - pub[(name, "2")]) <= tol, (sym, row)
    for sym, name, tol in (("aw", "a_w", 1e-4), ("αw", "alpha_w_deg", 1e-4), ("y", "y_centre_distance_mod_coeff", 1e-4),
                           ("εα", "eps_alpha", 1e-3)):
        row = by_symbol[sym]
        assert row[3] == row[4], row            # one value across both gear columns
        assert abs(float(row[3]) - pub[(name, "pair")]) <= tol, (sym, row)
    # both pictures are in the rendered page
    assert len(re.findall(r'<img alt="[^"]+" src="data:image/png;base64,', dom)) == 2


def test_report_prints_on_two_pages(khk_report, tmp_path):
    # A4: the calculation (verdict, checks, inputs, geometry) on one page, the pictures on the next
    assert print_pages(khk_report, tmp_path / "khk.pdf") == 2


def test_failing_pair_report_says_so_first(tmp_path):
    path = gd.pair_report(gd.GearPair(8, 17, 26, 0.898, 0.517), tmp_path / "engine.html", housing_a_w=180)
    page = path.read_text(encoding="utf-8")
    verdict = re.search(r'<div class="verdict fail">(.*?)</div>', page).group(1)
    # seed 000's engine pair: ε_α 1.153 < 1.2, and its a_w 181.60 mm is not the housing's 180 mm
    assert "contact_ratio (value 1.1532, limit 1.2)" in verdict and "center_distance" in verdict
    first_rows = re.findall(r"<tr class=\"failrow\"><td class=\"mark\">FAILS</td><td>(\w+)</td>", page)
    assert set(first_rows) == {"contact_ratio", "center_distance"}
    with pytest.raises(GearDesignError, match="exists: give --overwrite"):
        gd.pair_report(gd.GearPair(8, 17, 26, 0.898, 0.517), tmp_path / "engine.html")
    with pytest.raises(GearDesignError, match=r"must end in \.html"):
        gd.pair_report(gd.GearPair(8, 17, 26), tmp_path / "engine.pdf")


@pytest.fixture(scope="module")
def engine_contour(tmp_path_factory):
    path = tmp_path_factory.mktemp("contour") / "c.html"
    reg = gd.feasible_region(17, 26, m=8)
    opt = gd.optimize_shifts(17, 26, m=8, a_w=180)
    reg.to_html(path, optimum=opt, proposed=(0.898, 0.517), x_sum=opt.x_sum_fixed)
    return reg, opt, path


def test_contour_page_in_browser(engine_contour):
    reg, opt, path = engine_contour
    page = path.read_text(encoding="utf-8")
    assert not re.search(r'<script[^>]+src="', page)          # plotly.js inside: works offline
    dom = dump_dom(path)
    assert dom.count('class="main-svg"') >= 2                 # plotly drew its SVG layers
    legend = [html_unescape(t) for t in re.findall(r'class="legendtext"[^>]*>(.*?)</text>', dom)]
    curves = set(reg.limiting_checks()) | {"contact_ratio", "tip_thickness1", "interference1"}
    for name in curves & set(reg.checks):
        assert any(t.startswith(f"{name}: ") for t in legend), (name, legend)
    assert "contact_ratio: ε_α ≥ 1.2" in legend and "tip_thickness2: s_a2/m ≥ 0.25" in legend
    assert any(t.startswith("a_w = 180 mm") for t in legend)
    assert any(t.startswith("proposed (0.898, 0.517): fails") for t in legend)
    assert any(t.startswith("optimum (") for t in legend)
    assert "m = 8 mm" in html_unescape(re.search(r'class="gtitle"[^>]*>(.*?)</text>', dom).group(1))


def html_unescape(s: str) -> str:
    import html
    return html.unescape(re.sub(r"<[^>]+>", "", s))


def test_contour_hover_is_every_margin_at_the_node(engine_contour):
    # the hover grid's numbers against GearPair's own checks at the same (x1, x2): the float path of
    # one pair, not the grid's array path
    reg, _, _ = engine_contour
    fig = contour_figure(reg, n=41)
    hover = fig.data[0]
    g = np.asarray(hover.x)
    names = reg.checks
    assert all(f"{n}: " in hover.hovertemplate for n in names)
    assert "ε_α = " in hover.hovertemplate and "a_w, mm = " in hover.hovertemplate
    for i, j in ((20, 25), (30, 18), (24, 30)):
        x1, x2 = float(g[j]), float(g[i])          # row i is x2, column j is x1
        table = gd.GearPair(8, 17, 26, x1, x2).checks(jamming=False).set_index("check")
        cell = hover.customdata[i][j]
        for k, n in enumerate(names):
            assert cell[k] == pytest.approx(round(float(table.loc[n, "margin"]), 4), abs=1.5e-4), (n, x1, x2)
        geo = gd.GearPair(8, 17, 26, x1, x2).geometry()
        eps, sa1, sa2, a_w = cell[len(names):]
        assert eps == pytest.approx(geo.eps_alpha, abs=1e-4) and a_w == pytest.approx(geo.a_w, abs=1e-4)
        assert sa1 == pytest.approx(geo.sa1 / 8, abs=1e-4) and sa2 == pytest.approx(geo.sa2 / 8, abs=1e-4)
        ok = all(table.loc[n, "ok"] for n in names)
        assert hover.text[i][j] == ("every check holds" if ok else "fails")
    # one legend entry per check curve, each in its own group (a click hides the curve and its ticks)
    groups = [t.legendgroup for t in fig.data if t.showlegend is not False and t.legendgroup in names]
    assert len(groups) == len(set(groups)) >= 4


def test_planetary_contour_names_sun_and_planet(tmp_path):
    reg = gd.planetary_region(21, 43, 108, 3, 1.75, n=81, method="grid")
    fig = contour_figure(reg, n=31)
    assert "ε_α sun-planet" in fig.data[0].hovertemplate and "x_ring" in fig.data[0].hovertemplate
    assert "m = 1.75 mm" in fig.layout.title.text


def test_cli_report_and_html(tmp_path, capsys):
    rep, page = tmp_path / "pair.html", tmp_path / "contour.html"
    assert main(["pair", "-m", "8", "--z1", "17", "--z2", "26", "--x1", "0.898", "--x2", "0.517", "--report",
                 str(rep), "--json"]) in (0, 1)
    out = capsys.readouterr()
    json.loads(out.out)                       # the JSON stays pure; the note goes to stderr
    assert "report written" in out.err and "FAILS" in rep.read_text(encoding="utf-8")
    assert main(["shift", "--z1", "17", "--z2", "26", "-m", "8", "--center-distance", "180", "--html", str(page)]) == 0
    assert page.stat().st_size > 1_000_000 and "plotly" in page.read_text(encoding="utf-8")[:5_000_000]
    assert main(["shift", "--z1", "17", "--z2", "26", "--html", str(page)]) == 2
    assert "exists" in capsys.readouterr().err


def test_bad_inputs_name_themselves(tmp_path):
    reg = gd.feasible_region(17, 26, method="grid", n=41)
    with pytest.raises(GearDesignError, match="n must be"):
        reg.to_html(tmp_path / "x.html", n=5)
    with pytest.raises(GearDesignError, match="must end in .html"):
        reg.to_html(tmp_path / "x.png")
    with pytest.raises(GearDesignError, match="GearPair"):
        gd.pair_report("17/26", tmp_path / "x.html")
    assert not list(tmp_path.iterdir())
    assert math.isfinite(reg.area)


def test_contour_hover_in_browser(tmp_path):
    # plotly's own hover call at (0.5, 0.5), as a pointer there would; the label is read from the DOM
    reg = gd.feasible_region(17, 26, m=8)
    path = reg.to_html(tmp_path / "c.html", n=61)
    hovered = tmp_path / "hovered.html"
    hovered.write_text(path.read_text(encoding="utf-8").replace("</body>", (
        "<script>Plotly.Fx.hover(document.querySelector('.plotly-graph-div'), {xval: 0.5, yval: 0.5}, 'xy');"
        "</script></body>")), encoding="utf-8")
    dom = dump_dom(hovered)
    start = dom.index('<g class="hovertext"')
    label = html_unescape(dom[start:dom.index("</g>", dom.index("</text>", start))])
    assert "x1 = 0.5250, x2 = 0.5250" in label and "every check holds" in label   # the node nearest 0.5
    table = gd.GearPair(8, 17, 26, 0.525, 0.525).checks(jamming=False).set_index("check")
    for name in reg.checks:
        assert f"{name}: " in label
        assert f"margin {float(table.loc[name, 'margin']):+.4f}" in label, name
    geo = gd.GearPair(8, 17, 26, 0.525, 0.525).geometry()
    assert f"ε_α = {geo.eps_alpha:.4g}" in label and f"a_w, mm = {geo.a_w:.4g}" in label


def test_drive_report_in_browser(tmp_path, capsys):
    # seed 002's brake stand: 4 kW at 1500 rpm, a gear motor u = 12.5, η = 0.87, then a chain u = 1, η 0.96
    scene = Path(__file__).resolve().parents[2] / "studies" / "scenes" / "seed002_drive.toml"
    path = tmp_path / "drive.html"
    assert main(["drive", str(scene), "--report", str(path)]) == 0
    assert "report written" in capsys.readouterr().err
    dom = dump_dom(path)
    assert dom.index('class="verdict ok"') < dom.index("<table")
    found = tables(dom)
    checks = next(t for t in found if t[0] == ["verdict", "item", "check", "margin"])
    flow = next(t for t in found if t[0][:2] == ["shaft", "after"])
    stages = next(t for t in found if t[0][:2] == ["stage", "kind"])
    keys = next(t for t in found if t[0][:2] == ["name", "at"])
    margins = [float(r[3]) for r in checks[1:]]
    assert margins == sorted(margins) and all(r[0] == "holds" for r in checks[1:])
    # the power flow against T = P/ω through the stages (independent of the library)
    t0 = 4000 / (2 * math.pi * 1500 / 60)
    by_shaft = {r[0]: r for r in flow[1:]}
    assert float(by_shaft["0"][3]) == pytest.approx(t0, rel=1e-4)
    assert float(by_shaft["1"][2]) == pytest.approx(120) and float(by_shaft["1"][3]) == pytest.approx(t0 * 12.5 * 0.87, rel=1e-4)
    assert float(by_shaft["2"][3]) == pytest.approx(t0 * 12.5 * 0.87 * 0.96, rel=1e-4)
    assert [r[0] for r in stages[1:]] == ["gear motor", "chain"]
    assert keys[0][:2] == ["name", "at"] and len(keys) == 3
    assert re.search(r'<img alt="drive diagram" src="data:image/png;base64,', dom)
    with pytest.raises(GearDesignError, match="Drive, DriveAnalysis or DriveOptimum"):
        gd.drive_report(gd.GearPair(8, 17, 26), tmp_path / "x.html")


def test_cli_planetary_html(tmp_path, capsys):
    page = tmp_path / "set.html"
    args = ["planetary", "--module", "1.75", "--planets", "3", "--z-sun", "21", "--z-planet", "43", "--z-ring", "108"]
    assert main(args + ["--objective", "max_eps_alpha", "--html", str(page)]) == 0
    assert "interactive region written" in capsys.readouterr().out
    dom = dump_dom(page)
    legend = [html_unescape(t) for t in re.findall(r'class="legendtext"[^>]*>(.*?)</text>', dom)]
    assert "planet-ring:contact_ratio: ε_α ≥ 1.2" in legend and "sun-planet:tip_thickness_sun: s_a,sun/m ≥ 0.25" in legend
    r = gd.optimize_planetary_shifts(21, 43, 108, 3, 1.75, objective="max_eps_alpha")
    assert any(t.startswith(f"optimum ({r.x_sun:.3f}, {r.x_planet:.3f})") for t in legend)   # the same optimum
    assert main(args + ["--x-sun", "0", "--x-planet", "0.5", "--html", str(tmp_path / "x.html")]) == 2
    assert "--html draws the region of an optimisation" in capsys.readouterr().err


def test_report_of_a_pair_with_no_feasible_shifts(tmp_path):
    # 6/6 unshifted: both gears undercut. x_min = h − z sin²α/2 with h the height of the rack's straight
    # flank above the reference line, h_a* + c* − ρ_f*(1 − sin α) (GOST 16532-70; the standard rack
    # 1 / 0.25 / 0.38 of GOST 13755): 0.64903
    page = gd.pair_report(gd.GearPair(1, 6, 6), tmp_path / "six.html").read_text(encoding="utf-8")
    alpha = math.radians(20)
    x_min = (1 + 0.25 - 0.38 * (1 - math.sin(alpha))) - 6 * math.sin(alpha) ** 2 / 2
    assert f"undercut1 (value 0, limit {x_min:.5g})" in page
    assert "no feasible optimum" in page and "-0.0" not in page and "-0<" not in page


def test_report_with_a_load_shows_the_strength_and_its_factors(tmp_path):
    # issue 26 §4: the report of a loaded pair carries the strength checks, the ISO 6336 result per gear and the
    # factor table; the page's figures are the StrengthResult's (and 20/60 at 400 N·m fails contact first)
    pair = gd.GearPair(4, 20, 60, 0.3, 0.1, face_width_mm=40)
    case = {"load": gd.Load(torque_nm=400, n_rpm=1000, life_h=20000), "material": "42CrMo4"}
    path = gd.pair_report(pair, tmp_path / "loaded.html", **case)
    res = pair.strength(case["load"], "42CrMo4")
    dom = dump_dom(path)
    verdict = re.search(r'<div class="verdict fail">(.*?)</div>', dom).group(1)
    assert "contact_strength" in verdict
    found = tables(dom)
    checks = found[0]
    summary = next(t for t in found if t[0] == ["", "gear 1", "gear 2", "minimum"])
    factors = next(t for t in found if t[0] == ["symbol", "gear", "value", "clause"])
    assert {"contact_strength", "root_strength1", "root_strength2"} <= {r[1] for r in checks[1:]}
    assert summary[0] == ["", "gear 1", "gear 2", "minimum"]
    rows = {r[0]: r for r in summary[1:]}
    assert float(rows["safety SH (contact)"][1]) == pytest.approx(res.S_H1, abs=5e-4)
    assert float(rows["safety SF (root)"][2]) == pytest.approx(res.S_F2, abs=5e-4)
    assert factors[0] == ["symbol", "gear", "value", "clause"]
    by_symbol = {(r[0], r[1]): r for r in factors[1:]}
    assert float(by_symbol[("Z_H", "0")][2]) == pytest.approx(float(res.factors.query("symbol == 'Z_H'")["value"].iloc[0]),
                                                              rel=1e-5)
    assert len(factors) - 1 == len(res.factors)
