"""`geardesign mesh`: every output written and readable, the line-of-action figures agree with the pair
geometry, outputs are checked before any work (existing file, repeated path) with one-line errors."""
import json
import subprocess
import sys

import pytest

import geardesign as gd
from geardesign.cli import main

ENGINE = ["mesh", "--module", "8", "--z1", "17", "--z2", "26", "--x1", "0.898", "--x2", "0.517"]


def test_mesh_writes_every_output(tmp_path, capsys):
    files = {flag: tmp_path / name for flag, name in
             (("--plot", "mesh.png"), ("--diagrams", "diag.png"), ("--svg", "g.svg"), ("--dxf", "g.dxf"),
              ("--csv", "g.csv"))}
    argv = ENGINE + [a for flag, path in files.items() for a in (flag, str(path))] + ["--json"]
    assert main(argv) == 1      # the engine pair fails contact_ratio; the files are written either way
    out = json.loads(capsys.readouterr().out)
    assert out["ok"] is False and out["failing_checks"] == ["contact_ratio"]
    for path in files.values():
        assert path.stat().st_size > 1000
    for png in (files["--plot"], files["--diagrams"]):
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    g = gd.GearPair(8, 17, 26, 0.898, 0.517).geometry()
    line = out["line_of_action_mm"]
    assert line["active_A_to_E"] == pytest.approx(g.g_alpha, rel=1e-12)
    assert line["base_pitch"] == pytest.approx(g.p_b, rel=1e-12)
    assert line["double_contact_each_end"] == pytest.approx((g.eps_alpha - 1) * g.p_b, rel=1e-9)
    assert line["N1A"] < line["N1P"] < line["N1E"] < line["N1N2"]
    assert out["a_w_mm"] == pytest.approx(g.a_w, rel=1e-15)


def test_mesh_checks_outputs_before_work(tmp_path):
    (tmp_path / "g.svg").write_text("keep me")
    for extra, words in ((["--svg", str(tmp_path / "g.svg")], ["--svg", "exists", "--overwrite"]),
                         (["--svg", str(tmp_path / "a.svg"), "--plot", str(tmp_path / "a.svg")], ["must end in .png"]),
                         (["--dxf", str(tmp_path / "d.dxf"), "--z1", "2"], ["z1", "[3, 100000]"])):
        proc = subprocess.run([sys.executable, "-m", "geardesign", *ENGINE, *extra], capture_output=True, text=True)
        assert proc.returncode == 2
        lines = proc.stderr.strip().splitlines()
        assert len(lines) == 1, proc.stderr
        assert all(w in lines[0] for w in words), lines[0]
    assert (tmp_path / "g.svg").read_text() == "keep me"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["g.svg"]


def test_mesh_refuses_one_file_for_two_outputs(tmp_path, capsys):
    assert main(ENGINE + ["--svg", str(tmp_path / "a.svg"), "--plot", str(tmp_path / "m.png"),
                          "--diagrams", str(tmp_path / "m.png")]) == 2
    assert "also given to --plot" in capsys.readouterr().err


def test_mesh_draws_and_exports_an_internal_pair(tmp_path, capsys):
    """--internal: the ring pair 20/60 drawn and exported (the DXF holds the pinion, the ring's toothed bore
    and its rim); --cutter-teeth picks the shaper that generates the ring; cutter options need --internal."""
    import ezdxf

    ring = ["mesh", "--module", "2", "--z1", "20", "--z2", "60", "--x1", "0.3", "--x2", "0.6", "--internal"]
    files = {flag: tmp_path / name for flag, name in (("--plot", "m.png"), ("--diagrams", "d.png"), ("--dxf", "g.dxf"))}
    argv = ring + ["--cutter-teeth", "30"] + [a for flag, path in files.items() for a in (flag, str(path))] + ["--json"]
    assert main(argv) == 0
    out = json.loads(capsys.readouterr().out)
    g = gd.GearPair(2, 20, 60, 0.3, 0.6, internal=True).geometry()
    assert out["internal"] is True
    assert out["line_of_action_mm"]["active_A_to_E"] == pytest.approx(g.g_alpha, rel=1e-12)
    lo, pts = out["line_of_action_mm"], out["points_mm"]
    import math
    # N1 and N2 on one side of P: P–N2 = N1N2 + N1P
    assert math.dist(pts["P"], pts["N2"]) == pytest.approx(lo["N1N2"] + lo["N1P"], rel=1e-12)
    layers = sorted(e.dxf.layer for e in ezdxf.readfile(files["--dxf"]).modelspace().query("LWPOLYLINE"))
    assert layers == ["gear1", "gear2", "gear2_rim"]
    assert main(["mesh", "--module", "2", "--z1", "20", "--z2", "60", "--cutter-teeth", "30",
                 "--svg", str(tmp_path / "x.svg")]) == 2
    assert "give --internal" in capsys.readouterr().err
    assert not (tmp_path / "x.svg").exists()


def test_a_250_character_output_name_is_written(tmp_path, capsys):
    """Issue 29 §3.8: --csv <250-character name> printed a traceback, exited 1 and left a.png written."""
    csv = tmp_path / ("c" * 246 + ".csv")
    rc = main(["mesh", "--module", "2", "--z1", "20", "--z2", "40", "--plot", str(tmp_path / "a.png"),
               "--csv", str(csv)])
    assert rc == 0 and csv.read_text().startswith("outline")
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(["a.png", csv.name])


def test_a_late_failure_leaves_none_of_the_commands_files(tmp_path, capsys, monkeypatch):
    """One command's outputs are all or nothing: the plot is not left behind when an export fails."""
    import geardesign.profiles.mesh as pm

    def broken(*a, **k):
        raise gd.GearDesignError("--dxf: cannot write (No space left on device)")
    monkeypatch.setattr(pm, "export_profiles", broken)
    rc = main(["mesh", "--module", "2", "--z1", "17", "--z2", "26", "--plot", str(tmp_path / "a.png"),
               "--diagrams", str(tmp_path / "d.png"), "--dxf", str(tmp_path / "g.dxf")])
    assert rc == 2 and "No space left" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []
