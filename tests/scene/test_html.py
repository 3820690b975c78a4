"""The one-page HTML reports (geardesign.scene.html) without a browser (tests/report/test_pages.py opens them in
Chromium): seed 000's engine pair 17/26, m = 8, x = 0.898/0.517 fails the contact ratio (ε_α = 1.1532 < 1.2, the
course work's own shifts; recomputed in tests/test_geometry_golden.py), so the verdict comes first and says so;
every geometry value shown is the pair's; the file is written whole, self-contained, and not replaced."""
import re

import pytest

import geardesign as gd
from geardesign.errors import GearDesignError


@pytest.fixture(scope="module")
def engine_pair():
    return gd.GearPair(m=8, z1=17, z2=26, x1=0.898, x2=0.517)


def test_the_verdict_comes_first_and_names_the_failing_check(engine_pair, tmp_path):
    path = gd.pair_report(engine_pair, tmp_path / "pair.html")
    html = path.read_text(encoding="utf-8")
    body = html[html.index("<body"):]
    verdict = re.search(r'class="verdict[^"]*"[^>]*>(.*?)</', body, flags=re.S)
    assert verdict and "contact_ratio" in verdict.group(1) and "fail" in verdict.group(0).lower()
    assert body.index("verdict") < body.index("contact_ratio")
    g = engine_pair.geometry()
    assert f"{g.a_w:.4f}" in html or f"{g.a_w:.3f}" in html          # the pair's own a_w
    assert "<script src=\"http" not in html and "<link rel=\"stylesheet\" href=\"http" not in html   # offline


def test_a_passing_pair_and_the_refusals(tmp_path):
    ok = gd.GearPair(m=3, z1=12, z2=24, x1=0.6, x2=0.36)       # KHK's example: ε_α = 1.202 >= 1.2
    html = gd.pair_report(ok, tmp_path / "ok.html").read_text(encoding="utf-8")
    assert re.search(r'class="verdict ok"', html)
    with pytest.raises(GearDesignError, match="exists"):
        gd.pair_report(ok, tmp_path / "ok.html")
    assert gd.pair_report(ok, tmp_path / "ok.html", overwrite=True).exists()
    with pytest.raises(GearDesignError):
        gd.pair_report(ok, tmp_path / "ok.txt")


def test_a_worm_stage_section_shows_its_numbers_rounded_not_the_floats_sixteen_digits():
    # seed 002's brake stand with its worm computed (studies/scenes/seed002_worm_drive.toml): the worm stage's
    # section printed "efficiency 0.9222413..., gamma_m_deg 17.744671..." to the float's last digit. γ_m of z1 = 4,
    # q = 12.5 is atan(z1/q) (DIN 3975), computed here
    import math

    from geardesign.scene.html import drive_report_html

    drive = gd.Drive(power_kw=4, n_in_rpm=1500, stages=[gd.WormStage(4, 12.5, 4, 50, a=125, efficiency=0.87,
                                                                       name="gear motor")])
    page = drive_report_html(drive.analyse(), pictures=False)
    section = page[page.index("Stage 1, 'gear motor'"):]
    section = section[:section.index("</p>", section.index("<p>", section.index("</p>") + 1))]
    gamma = math.degrees(math.atan(4 / 12.5))
    assert f"gamma_m_deg {gamma:.6g}" in section
    assert not re.search(r"\d\.\d{8,}", section)                     # no 16-digit float left
