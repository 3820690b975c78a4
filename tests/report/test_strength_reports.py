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


# A reducer: two spur stages in 42CrMo4 and a roller chain, keys on three shafts, 15 kW at 1460 rpm (the conveyor
# job of issue 35, with its tooth counts fixed). Every figure below is computed here by hand or through
# GearPair.strength at the stage's own torque, never read back from the drive.
P_KW, N_IN = 15.0, 1460.0
STAGES = [(3, 21, 74, 0.4, 0.6, 60.0), (4, 22, 75, 0.4, 0.6, 80.0)]
SCENE = f"""
title = "two gear stages and a chain"
[drive]
power_kw = {P_KW}
n_in_rpm = {N_IN}
""" + "".join(f"""
[[drive.stage]]
kind = "gear"
name = "stage {i}"
module = {m}
z1 = {z1}
z2 = {z2}
x1 = {x1}
x2 = {x2}
face_width_mm = {b}
material = "42CrMo4"
""" for i, (m, z1, z2, x1, x2, b) in enumerate(STAGES, start=1)) + """
[[drive.stage]]
kind = "chain"
name = "chain"
z1 = 17
z2 = 34
""" + "".join(f"""
[[drive.shaft]]
at = {at}
name = "{name}"
d_mm = {d}
hub_length_mm = {l}
""" for at, name, d, l in ((1, "intermediate", 40, 60), (2, "output", 60, 80), (3, "conveyor", 70, 90)))


def _hand_strength():
    """Each gear stage's StrengthResult by GearPair.strength at the torque the power flow brings it (T = P/ω,
    T_k = T_{k-1} u η with η = 0.98, the GearStage default)."""
    torque, speed, out = P_KW * 1000 / (2 * math.pi * N_IN / 60), N_IN, []
    for m, z1, z2, x1, x2, b in STAGES:
        pair = gd.GearPair(m, z1, z2, x1, x2, face_width_mm=b)
        out.append(pair.strength(gd.Load(torque_nm=torque, n_rpm=speed), "42CrMo4"))
        torque, speed = torque * z2 / z1 * 0.98, speed * z1 / z2
    return out


def _span_mm(m, z, x, k, alpha_deg=20.0):
    """Base tangent length over k teeth, ISO 21771:2007 eq. (93): W_k = m cos α [(k − 0.5) π + z inv α + 2 x tan α]."""
    a = math.radians(alpha_deg)
    return m * math.cos(a) * ((k - 0.5) * math.pi + z * (math.tan(a) - a) + 2 * x * math.tan(a))


@pytest.fixture(scope="module")
def reducer(tmp_path_factory):
    folder = tmp_path_factory.mktemp("reducer")
    scene = folder / "reducer.toml"
    scene.write_text(SCENE, encoding="utf-8")
    return scene


def test_the_drive_report_is_one_document_for_the_reducer(reducer, tmp_path, capsys):
    from geardesign.cli import main

    path = tmp_path / "reducer.html"
    assert main(["drive", str(reducer), "--report", str(path)]) == 1      # both stages fail contact (S_H < 1)
    page = path.read_text(encoding="utf-8")
    assert page.count("<html") == 1 and not re.search(r'(src|href)="(https?:)?//', page)
    dom = dump_dom(path)
    heads = re.findall(r"<h2[^>]*>(.*?)</h2>", dom)
    assert [h for h in heads if h.startswith("Stage ")] == ["Stage 1, 'stage 1': gear pair", "Stage 2, 'stage 2': gear pair",
                                                          "Stage 3, 'chain': roller chain"]
    assert {"Power flow", "Stages", "Keys", "Diagram"} <= set(heads)
    found = tables(dom)
    hand = _hand_strength()
    # the overview: per gear stage the material, S_H (the smaller), S_F of each gear and the governing check
    overview = {r[0]: r for r in _by_head(found, ["stage", "kind", "u", "η", "design", "material", "SH", "SF1", "SF2",
                                                  "governing (margin)"])[1:]}
    for k, r in enumerate(hand, start=1):
        row = overview[f"stage {k}"]
        assert row[5] == "42CrMo4"
        assert float(row[6]) == pytest.approx(min(r.S_H1, r.S_H2), abs=5e-4 * min(r.S_H1, r.S_H2))
        assert float(row[7]) == pytest.approx(r.S_F1, rel=5e-4) and float(row[8]) == pytest.approx(r.S_F2, rel=5e-4)
        assert row[9].startswith("contact (pitting), gear 1")
    assert overview["chain"][5] == "–"
    # per gear stage: geometry, strength inputs, S and σ per gear, the factor table, both gears' data block
    geometry = [t for t in found if t[0] == ["quantity", "symbol", "unit", "gear 1", "gear 2"]]
    inputs = [t for t in found if t[0] == ["input", "symbol", "unit", "gear 1", "gear 2"]]
    summaries = [t for t in found if t[0] == ["", "gear 1", "gear 2", "minimum"]]
    factors = [t for t in found if t[0] == ["symbol", "gear", "value", "clause"]]
    blocks = [t for t in found if t[0] == ["parameter", "symbol", "gear 1", "gear 2", "unit"]]
    assert len(geometry) == len(inputs) == len(summaries) == len(factors) == len(blocks) == 2
    mat = gd.material("42CrMo4")
    for (m, z1, z2, x1, x2, b), r, g, i, s, f, blk in zip(STAGES, hand, geometry, inputs, summaries, factors, blocks):
        assert [row[3:] for row in g[1:3]] == [[str(z1), str(z2)], [f"{x1:.4f}", f"{x2:.4f}"]]
        rows = {row[0]: row for row in i[1:]}
        assert rows["material"][3:] == ["42CrMo4", "42CrMo4"]
        assert float(rows["contact endurance limit"][3]) == pytest.approx(mat.sigma_Hlim_mpa)
        assert float(rows["bending endurance limit"][3]) == pytest.approx(mat.sigma_Flim_mpa)
        sig = {row[0]: row for row in s[1:]}
        assert float(sig["σH, MPa"][1]) == pytest.approx(r.sigma_H1, rel=5e-4)
        assert float(sig["σF, MPa"][2]) == pytest.approx(r.sigma_F2, rel=5e-4)
        assert len(f) - 1 == len(r.factors)
        block = {row[1]: row for row in blk[1:]}
        for gear, (z, x) in enumerate(((z1, x1), (z2, x2)), start=2):
            k = int(block["k"][gear])
            assert float(block["W_k"][gear].split()[0]) == pytest.approx(_span_mm(m, z, x, k), abs=1e-4)
    chain = {row[0]: row for row in _by_head(found, ["quantity", "symbol", "unit", "value"])[1:]}
    assert chain["sprocket teeth"][3] == "17, 34" and "service factor" in chain
    keys = _by_head(found, ["name", "at", "d_mm", "hub_length_mm", "torque_nm", "key_mm", "n_keys", "crush_mpa",
                            "shear_mpa", "margin_crush", "margin_shear"])
    assert [r[0] for r in keys[1:]] == ["intermediate", "output", "conveyor"]
    assert re.search(r'<img alt="drive diagram" src="data:image/png;base64,', dom)


def test_the_drive_text_and_json_show_each_stages_strength(reducer, capsys):
    import json

    from geardesign.cli import main

    hand = _hand_strength()
    assert main(["drive", str(reducer)]) == 1
    text = capsys.readouterr().out
    for k, r in enumerate(hand, start=1):
        part = text[text.index(f"strength of stage 'stage {k}'"):]
        assert "material 42CrMo4 (sigma_Hlim 766.9, sigma_Flim 314.5 MPa)" in part
        assert f"  S_H      {r.S_H1:>10.3f}{r.S_H2:>10.3f}" in part and f"{r.sigma_F1:>10.1f}" in part
        assert "governing: contact, gear 1" in part
        factors = part[part.index(f"factors of stage 'stage {k}'"):].splitlines()
        kv = next(line for line in factors if line.startswith("K_v "))
        assert float(kv.split()[1]) == pytest.approx(float(r.factors.query("symbol == 'K_v'")["value"].iloc[0]), rel=1e-5)
    assert main(["drive", str(reducer), "--json"]) == 1
    stages = json.loads(capsys.readouterr().out)["analysis"]["stages"]
    assert [("strength" in s) for s in stages] == [True, True, False]
    for s, r in zip(stages, hand):
        st = s["strength"]
        assert st["case"]["material1"] == "42CrMo4" and st["case"]["sigma_Hlim1_mpa"] == gd.material("42CrMo4").sigma_Hlim_mpa
        assert st["S_H1"] == pytest.approx(r.S_H1, rel=1e-9) and st["sigma_F2"] == pytest.approx(r.sigma_F2, rel=1e-9)
        assert st["governing"] == "contact1" and len(st["factors"]) == len(r.factors)


def test_the_scene_run_shows_each_stages_strength(reducer, tmp_path, capsys):
    import pandas as pd

    from geardesign.cli import main

    out = tmp_path / "out"
    assert main(["run", str(reducer), "--out", str(out)]) == 1
    text = (out / "report.md").read_text(encoding="utf-8")
    for k, r in enumerate(_hand_strength(), start=1):
        part = text[text.index(f"### Strength of stage 'stage {k}'"):]
        assert "material 42CrMo4 (sigma_Hlim 766.9, sigma_Flim 314.5 MPa)" in part.splitlines()[2]
        assert f"S_H = {r.S_H1:.4g} / {r.S_H2:.4g}" in part and f"σ_F = {r.sigma_F1:.4g} / {r.sigma_F2:.4g} MPa" in part
        factors = pd.read_csv(out / f"drive_strength_stage_{k}.csv")
        assert list(factors.columns) == ["symbol", "gear", "value", "clause"] and len(factors) == len(r.factors)


def test_the_data_block_takes_the_stages_shop_allowances():
    # a stage whose analysis assumed a manufactured state (out["allowances"]: tooth-thickness allowances a_sne/a_sni
    # per gear and a_ai/a_ae of the centre distance, mm) prints its control sizes with them: the span's deviations
    # are the thickness allowances times cos α_n (ISO 21771:2007 eq. (93) differentiated: dW/ds = cos α_n)
    import dataclasses
    from types import SimpleNamespace

    from geardesign.scene.html import drive_report_html

    an = gd.Drive(power_kw=4, n_in_rpm=1450, stages=[gd.GearStage(3, 21, 74, 0.4, 0.6, face_width_mm=40)]).analyse()
    shop = SimpleNamespace(a_ai=-0.032, a_ae=0.032, a_sne1=-0.097, a_sni1=-0.193, a_sne2=-0.110, a_sni2=-0.220,
                           describe=lambda: "mating type B (test)")
    page = drive_report_html(dataclasses.replace(an, stages=(dict(an.stages[0], allowances=shop),)), pictures=False)
    assert "Control sizes with the allowances of the manufactured state the checks assumed: mating type B (test)" in page
    block = {r[1]: r for r in _by_head(tables(page), ["parameter", "symbol", "gear 1", "gear 2", "unit"])[1:]}
    cos_a = math.cos(math.radians(20.0))
    for col, (upper, lower) in ((2, (shop.a_sne1, shop.a_sni1)), (3, (shop.a_sne2, shop.a_sni2))):
        nominal, dev = block["W_k"][col].split(" ", 1)
        hi, lo = (float(v) for v in dev.strip("()").split(" / "))
        assert (hi, lo) == (pytest.approx(upper * cos_a, abs=1e-4), pytest.approx(lower * cos_a, abs=1e-4))
    assert block["a_w"][2].endswith("(+0.0320 / -0.0320)")
    # without a manufactured state the sizes are nominal and say so
    assert "Control sizes: nominal, no tooth-thickness allowance assumed" in drive_report_html(an, pictures=False)
