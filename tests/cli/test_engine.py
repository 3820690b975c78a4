"""`geardesign engine`: the torque summary of the example scene (seed 000's engine), the CSV and plot written whole and
never over an existing file, --json, errors naming the option or the scene's key."""
import csv
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from geardesign.cli import main
from geardesign.scene.engine import load_engine

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "seed000_engine.toml"


def test_summary_of_the_example(capsys):
    assert main(["engine", str(EXAMPLE)]) == 0
    out = capsys.readouterr().out
    res = load_engine(EXAMPLE).engine.analyse(720)
    assert out.splitlines()[0].startswith("OK: seed 000 engine: two cylinders at 1700 rpm: the engine does work")
    assert f"M_i = {res.mean_torque_nm:.6g} N·m" in out and "unevenness μ" in out
    assert "the torque reverses at " + ", ".join(f"{a:.1f}" for a in res.reversal_angles_deg) in out.replace("\n  ", " ")


def test_csv_and_plot_are_written_and_never_silently_replaced(tmp_path, capsys):
    table, png = tmp_path / "torque.csv", tmp_path / "torque.png"
    assert main(["engine", str(EXAMPLE), "--csv", str(table), "--plot", str(png), "--points", "360"]) == 0
    capsys.readouterr()
    with open(table, encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    res = load_engine(EXAMPLE).engine.analyse(360)
    assert len(rows) == 360 and float(rows[1]["crank_angle_deg"]) == 2.0
    np.testing.assert_allclose([float(r["torque_nm"]) for r in rows], res.torque_nm, rtol=1e-9, atol=1e-9)
    assert png.stat().st_size > 10_000
    before = table.read_bytes()
    assert main(["engine", str(EXAMPLE), "--csv", str(table)]) == 2
    assert "--csv" in capsys.readouterr().err and table.read_bytes() == before
    # a bad plot path stops the command before anything is written, the CSV included
    other = tmp_path / "other.csv"
    assert main(["engine", str(EXAMPLE), "--csv", str(other), "--plot", str(tmp_path / "t.txt")]) == 2
    assert "--plot" in capsys.readouterr().err and not other.exists()
    assert main(["engine", str(EXAMPLE), "--csv", str(table), "--overwrite", "--points", "720"]) == 0
    assert table.read_bytes() != before


def test_json(capsys):
    assert main(["engine", str(EXAMPLE), "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["ok"] is True and d["cylinders"] == 2 and d["phases_deg"] == [0.0, 540.0] and d["points"] == 720
    assert d["effective_torque_nm"] == pytest.approx(0.8 * d["mean_torque_nm"])


@pytest.mark.parametrize("extra, text", [
    (["--points", "3"], "--points must be a whole number in [8, 100000], got 3"),
])
def test_bad_options_are_named(extra, text, capsys):
    assert main(["engine", str(EXAMPLE), *extra]) == 2
    err = capsys.readouterr().err.strip()
    assert err == f"geardesign engine: error: {text}"


def test_a_bad_scene_names_the_key(tmp_path, capsys):
    scene = tmp_path / "e.toml"
    scene.write_text(EXAMPLE.read_text(encoding="utf-8").replace("rod_length_mm = 250", "rod_length_mm = 60"),
                     encoding="utf-8")
    assert main(["engine", str(scene)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"{scene}: [engine.mechanism]: rod_length_mm must exceed" in err[0]


def test_a_missing_scene_is_one_line_in_a_subprocess(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "geardesign", "engine", str(tmp_path / "none.toml")],
                          capture_output=True, text=True)
    assert proc.returncode == 2 and proc.stderr.count("\n") == 1 and "Traceback" not in proc.stderr


# ---- the engine's gear end to end (issue 38 §5) ----------------------------------------------------------------
GEAR_EXAMPLE = EXAMPLE.parent / "seed000_engine_gear.toml"


def _variant(tmp_path, *changes):
    text = GEAR_EXAMPLE.read_text(encoding="utf-8")
    for old, new in changes:
        assert old in text
        text = text.replace(old, new)
    path = tmp_path / "g.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_the_seed_gear_prints_spectrum_life_and_shifts_and_fails(capsys):
    """Exit 1: the seed's shifts fail eps_alpha >= 1.2 and no shifts give 40Cr's pinion 5000 h."""
    from geardesign.scene.engine_gear import engine_gear
    from geardesign.scene.load import load_scene

    assert main(["engine", str(GEAR_EXAMPLE)]) == 1
    out = capsys.readouterr().out
    g = engine_gear(load_scene(GEAR_EXAMPLE))
    best, given = g.life["optimum"], g.life["given"]
    first = out.replace("\n  ", " ").splitlines()[0]
    assert first.startswith("FAILS: seed 000 engine and its gear pair") and "the given shifts fail contact_ratio" in first
    assert f"at the best shifts the gear's life is {best.life_h:.4g} h < 5000 h (pitting, gear 1)" in first
    flat = out.replace("\n  ", " ")
    assert "the torque reverses at" in flat and "LoadSpectrum(442 bins, per tooth" in flat and "coast flank" in out
    assert f"life at the given shifts x1 = 0.8980, x2 = 0.5170 (they fail contact_ratio): {given.life_h:.4g} h" in flat
    assert f"optimal shifts: x1 = {g.optimum.x1:.6f}, x2 = {g.optimum.x2:.6f} (max_life" in flat
    assert out.count("pitting  gear 1  D = ") == 2


def test_a_gear_that_reaches_its_life_passes(tmp_path, capsys):
    path = _variant(tmp_path, ("x1 = 0.898 ", "#"), ("x2 = 0.517", "#"), ("life_h = 5000", "life_h = 3000"))
    assert main(["engine", str(path), "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["ok"] is True and d["failures"] == [] and list(d["life"]) == ["optimum"]
    life = d["life"]["optimum"]
    assert life["ok"] and life["life_h"] >= 3000 and life["required_life_h"] == 3000
    assert [r["mode"] for r in life["damage"]] == ["pitting", "pitting", "root", "root"]
    assert d["optimum"]["objective"] == "max_life" and d["spectrum"]["reverses"] is True


@pytest.mark.parametrize("changes, text", [
    ((("[gear.spectrum]", "[gear.notspectrum]"),), "notspectrum: unknown key"),
    ((("life_h = 5000 ", ""),), "[gear.spectrum] life_h: missing"),
    ((("material = \"40Cr\"", "material = \"40Cr\"\nfile = \"s.csv\""),), "[gear.spectrum] file"),
])
def test_a_bad_gear_table_is_one_line_naming_the_key(tmp_path, capsys, changes, text):
    if changes[0][1] == "material = \"40Cr\"\nfile = \"s.csv\"":
        (tmp_path / "s.csv").write_text("torque_nm,n_rpm,time_h\n100,1700,10\n", encoding="utf-8")
    path = _variant(tmp_path, *changes)
    assert main(["engine", str(path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and text in err[0] and str(path) in err[0], err


def test_without_a_spectrum_table_the_key_is_named(tmp_path, capsys):
    path = _variant(tmp_path, ("[gear.spectrum] ", "[gear.load]"), ("material = \"40Cr\" ", "material = \"40Cr\"\n"
                                                                                          "n_rpm = 1700\ntorque_nm = 90 "),
                    ("life_h = 5000 ", ""), ("mean_stress_factor = 0.7 ", ""), ("objective = \"max_life\"", ""))
    assert main(["engine", str(path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "[gear] spectrum: missing; the engine's gear needs [gear.spectrum]" in err[0], err


def test_html_report_of_the_engines_gear(tmp_path, capsys):
    page = tmp_path / "r.html"
    assert main(["engine", str(GEAR_EXAMPLE), "--html", str(page)]) == 1
    assert f"wrote {page} (the engine's gear report)" in capsys.readouterr().out
    text = page.read_text(encoding="utf-8")
    for part in ("The engine's torque over the cycle", "Load spectrum on the gear (ISO 6336-6)",
                 "Service life at the scene's shifts", "Service life at the optimal shifts (max_life)",
                 "<th>mode</th><th>gear</th><th>D</th><th>life_h</th><th>S</th><th>ok</th>", "Optimal shifts of 17/26"):
        assert part in text, part
    # torque, histogram, two S-N diagrams, each inline: the page fetches nothing
    assert text.count('src="data:image/png;base64,') == 4 and 'src="http' not in text
    before = page.read_bytes()
    assert main(["engine", str(GEAR_EXAMPLE), "--html", str(page)]) == 2      # never over a file unasked
    assert "--html" in capsys.readouterr().err and page.read_bytes() == before
    assert main(["engine", str(EXAMPLE), "--html", str(tmp_path / "e.html")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--html is the report of the engine's gear: the scene has no [gear]" in err[0]
    assert not (tmp_path / "e.html").exists()


def test_points_count_the_gears_spectrum_too(capsys):
    """--points samples the curve the spectrum is counted from as well (360 points: every 2°)."""
    import geardesign as gd
    from geardesign.scene.engine import load_engine

    assert main(["engine", str(GEAR_EXAMPLE), "--points", "360", "--json"]) == 1
    d = json.loads(capsys.readouterr().out)
    angle, torque, n = gd.engine_torque(load_engine(GEAR_EXAMPLE).engine, 360)
    spec = gd.LoadSpectrum.from_curve(torque, angle_deg=angle, n_rpm=n, teeth=(17, 26), period_deg=720)
    assert d["engine"]["points"] == 360
    assert d["spectrum"]["max_torque_nm"] == pytest.approx(float(spec.torque_nm.max()), rel=1e-12)
    assert d["spectrum"]["min_torque_nm"] == pytest.approx(float(spec.torque_nm.min()), rel=1e-12)
