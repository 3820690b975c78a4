"""Strength shown wherever a stage is shown (issue 35 §6): the pair report names what σ_HP is computed from,
its mesh picture's title agrees with its verdict; the drive's text, JSON and report show every gear stage's
material, S_H, S_F, σ_H, σ_F, the governing check and the factor table."""
import math
import re

import pytest

import geardesign as gd

from .browser import dump_dom, tables

CASE = {"load": gd.Load(torque_nm=400, n_rpm=1000, life_h=20000), "material": "42CrMo4",
        "strength": {"accuracy_grade": 6, "nu40": 100.0, "Rz_flank_um": 3.0}}


def _by_head(found, head):
    return next(t for t in found if t[0] == head)


@pytest.fixture(scope="module")
def loaded(tmp_path_factory):
    pair = gd.GearPair(4, 20, 60, 0.3, 0.1, face_width_mm=40)
    path = gd.pair_report(pair, tmp_path_factory.mktemp("strength") / "pair.html", **CASE)
    return pair, tables(dump_dom(path))


def test_the_pair_report_names_what_sigma_hp_is_computed_from(loaded):
    _, found = loaded
    inputs = {r[0]: r for r in _by_head(found, ["input", "symbol", "unit", "gear 1", "gear 2"])[1:]}
    assert inputs["material"][3:] == ["42CrMo4", "42CrMo4"]
    assert inputs["accuracy grade (ISO 1328-1:1995)"][3] == "6"
    assert float(inputs["lubricant viscosity at 40 °C"][3]) == 100.0
    assert float(inputs["flank roughness (mean of both flanks)"][3]) == 3.0
    # the catalog row of 42CrMo4 (catalogs/materials: ISO 6336-5 V, through-hardened alloy steel)
    mat = gd.material("42CrMo4")
    assert float(inputs["contact endurance limit"][3]) == pytest.approx(mat.sigma_Hlim_mpa)
    assert float(inputs["bending endurance limit"][4]) == pytest.approx(mat.sigma_Flim_mpa)
    # a reader computes σ_HP from the page alone: ISO 6336-2:2019 eq. (3), σ_HP = σ_Hlim Z_NT Z_L Z_v Z_R Z_W Z_X / S_Hmin
    f = {(r[0], r[1]): float(r[2]) for r in _by_head(found, ["symbol", "gear", "value", "clause"])[1:]}
    s_hmin = float(inputs["minimum safety factors"][3].split(",")[0])
    hp1 = (float(inputs["contact endurance limit"][3]) * f[("Z_NT", "1")] * f[("Z_L", "1")] * f[("Z_v", "1")]
           * f[("Z_R", "1")] * f[("Z_W", "1")] * f[("Z_X", "0")] / s_hmin)
    summary = {r[0]: r for r in _by_head(found, ["", "gear 1", "gear 2", "minimum"])[1:]}
    assert hp1 == pytest.approx(float(summary["σHP, MPa"][1]), rel=5e-4)


def test_the_pair_reports_mesh_title_agrees_with_its_verdict(tmp_path, monkeypatch):
    # issue 35 §6: the mesh picture said "every check holds" (the default geometric limits) under a FAILS verdict
    from geardesign.profiles import drawing

    titles = []
    real = drawing.plot_mesh

    def spy(*a, **k):
        ax = real(*a, **k)
        titles.append(ax.get_title())
        return ax

    monkeypatch.setattr(drawing, "plot_mesh", spy)
    pair = gd.GearPair(4, 20, 60, 0.3, 0.1, face_width_mm=40)
    page = gd.pair_report(pair, tmp_path / "p.html", **CASE).read_text(encoding="utf-8")
    assert '<div class="verdict fail">' in page
    assert "FAILS contact_strength" in titles[-1] and "every check holds" not in titles[-1]
    # and a pair that holds under its report's limits says so
    ok = gd.GearPair(3, 17, 26, 0.5, 0.5)
    page = gd.pair_report(ok, tmp_path / "ok.html").read_text(encoding="utf-8")
    assert "<div class=\"verdict ok\">" in page
    assert "every check holds" in titles[-1] and "FAILS" not in titles[-1]
