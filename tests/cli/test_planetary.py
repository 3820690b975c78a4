"""geardesign planetary: optimise, check given shifts, search tooth counts; one line for bad input."""
import json

import pytest

from geardesign.cli import main


def test_optimum_json_is_coaxial(capsys):
    code = main(["planetary", "--module", "1.75", "--planets", "3", "--z-sun", "21", "--z-planet", "43",
                 "--z-ring", "108", "--objective", "max_eps_alpha", "--json"])
    out = json.loads(capsys.readouterr().out)
    assert code == 0 and out["status"] == "success"
    assert abs(out["a_w"] - out["a_w_planet_ring"]) < 1e-9


def test_given_shifts_name_the_failing_check(capsys):
    # LECAD's printed shifts: coaxial, but the ring's tip reaches the planet's fillet (ρ_p < ρ_l)
    code = main(["planetary", "--module", "1.75", "--planets", "3", "--z-sun", "21", "--z-planet", "43",
                 "--z-ring", "108", "--x-sun", "0.438", "--x-planet", "0.0426", "--x-ring", "0"])
    out = capsys.readouterr().out
    assert code == 1 and "FAILS: planet-ring:interference_planet" in out


def test_teeth_search_and_files(tmp_path, capsys):
    plot, drawing = tmp_path / "r.png", tmp_path / "s.png"
    assert main(["planetary", "--module", "2", "--planets", "3", "--ratio", "5", "--z-sun-range", "18:21"]) == 0
    assert "candidates" in capsys.readouterr().out
    assert main(["planetary", "--module", "2", "--planets", "3", "--z-sun", "18", "--z-planet", "27", "--z-ring",
                 "72", "--plot", str(plot), "--drawing", str(drawing)]) == 0
    assert plot.stat().st_size > 10_000 and drawing.stat().st_size > 10_000
    capsys.readouterr()
    # an existing file is not replaced without --overwrite
    assert main(["planetary", "--module", "2", "--planets", "3", "--z-sun", "18", "--z-planet", "27", "--z-ring",
                 "72", "--plot", str(plot)]) == 2
    assert "overwrite" in capsys.readouterr().err


@pytest.mark.parametrize("argv, words", [
    (["--z-sun", "20"], "--z-planet, --z-ring needed"),
    (["--z-sun", "20", "--z-planet", "30", "--z-ring", "30"], "--z-ring must exceed --z-planet"),
    (["--z-sun", "20", "--z-planet", "25", "--z-ring", "72", "--x-sun", "0.1"], "--x-sun and --x-planet go together"),
    (["--ratio", "0.5"], "ratio = 0.5"),
    (["--ratio", "5", "--z-sun-range", "a:b"], "--z-sun-range"),
])
def test_bad_input_is_one_line(argv, words, capsys):
    assert main(["planetary", "--module", "2", "--planets", "3", *argv]) == 2
    err = capsys.readouterr().err.strip()
    assert words in err and len(err.splitlines()) == 1


def test_plot_and_drawing_with_ratio_are_refused_and_nothing_written(tmp_path, capsys):
    """Issue 29 §3.10: --ratio with --plot/--drawing exited 0 and wrote neither file."""
    rc = main(["planetary", "--ratio", "5", "--module", "2", "--planets", "3", "--plot", str(tmp_path / "r.png"),
               "--drawing", str(tmp_path / "s.png")])
    err = capsys.readouterr().err
    assert rc == 2 and err.count("\n") == 1 and "--z-sun" in err and "--ratio" in err
    assert list(tmp_path.iterdir()) == []


def test_given_shifts_write_both_plot_and_drawing(tmp_path, capsys):
    rc = main(["planetary", "--module", "1.75", "--planets", "3", "--z-sun", "21", "--z-planet", "43", "--z-ring",
               "108", "--x-sun", "0.438", "--x-planet", "0.0426", "--plot", str(tmp_path / "r.png"),
               "--drawing", str(tmp_path / "s.png")])
    assert rc in (0, 1)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r.png", "s.png"]
    assert all((tmp_path / n).read_bytes()[:4] == b"\x89PNG" for n in ("r.png", "s.png"))


def test_ratio_is_signed_on_the_command_line_too(capsys):
    # issue 36 §1.8: the carrier-fixed set's ratio is -z_r/z_s, asked and printed with its sign
    args = ["planetary", "-m", "2.5", "--planets", "2", "--ratio-tol", "0.05", "--z-sun-range", "12:12",
            "--nonstandard-max", "0", "--arrangement", "carrier_fixed", "--json"]
    assert main(args + ["--ratio", "12"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "must be < -1" in err[0] and "give -12" in err[0]
    assert main(args + ["--ratio", "-12"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["ok"] and out["table"][0]["ratio"] == -144 / 12
    assert all(row["ratio"] == -row["z_ring"] / row["z_sun"] for row in out["table"])


def test_a_sun_spectrum_gives_the_sets_damage_checks(tmp_path, capsys):
    # --spectrum on the planetary command: the damage checks of both meshes, as the Python set's checks give them
    # for the same spectrum, and the planet's root damage as planetary_life rates it (bent both ways, Y_M 0.7)
    import geardesign as gd
    from geardesign.gears.strength import planetary_life

    csv = tmp_path / "sun.csv"
    csv.write_text("torque_nm,n_rpm,time_h\n450,1500,2000\n300,1500,3000\n200,1500,5000\n", encoding="utf-8")
    args = ["planetary", "-m", "2", "--planets", "3", "--z-sun", "20", "--z-planet", "31", "--z-ring", "82",
            "--x-sun", "0.3", "--x-planet", "0.1", "--spectrum", str(csv), "--material", "18CrNiMo7-6",
            "--face-width", "25"]
    assert main(args + ["--mean-stress-factor", "0.7", "--json"]) == 1     # the sun's flank is worn out
    got = {c["check"]: c["value"] for c in json.loads(capsys.readouterr().out)["checks"]}
    s = gd.PlanetarySet.coaxial(2, 20, 31, 82, 3, 0.3, 0.1)
    spec = gd.LoadSpectrum.from_csv(csv)
    want = s.checks({"spectrum": spec, "material": "18CrNiMo7-6", "face_width_mm": 25.0,
                     "mean_stress_factor": 0.7}).set_index("check")["value"]
    names = [n for n in want.index if "damage" in n]
    assert len(names) == 8 and all(got[n] == pytest.approx(float(want[n]), rel=1e-12) for n in names)
    life = planetary_life(s, spec, "18CrNiMo7-6", face_width_mm=25.0, mean_stress_factor=0.7)
    assert life["D_F_planet"] > 0 and got["sun-planet:root_damage_planet"] == pytest.approx(life["D_F_planet"], rel=1e-12)
    # without Y_M: one line naming the option, exit 2
    assert main(args) == 2
    assert "--mean-stress-factor" in capsys.readouterr().err
    # a reversing spectrum: the planet's damage summed per flank across both meshes, as planetary_life sums it
    csv.write_text("torque_nm,n_rpm,time_h\n450,1500,2000\n-300,1500,3000\n", encoding="utf-8")
    assert main(args + ["--mean-stress-factor", "0.7", "--json"]) == 1     # the sun's flank is worn out
    got = {c["check"]: c["value"] for c in json.loads(capsys.readouterr().out)["checks"]}
    life = planetary_life(s, gd.LoadSpectrum.from_csv(csv), "18CrNiMo7-6", face_width_mm=25.0, mean_stress_factor=0.7)
    assert got["set:pitting_damage_planet"] == pytest.approx(life["D_H_planet"], rel=1e-12) and life["D_H_planet"] > 0


@pytest.mark.parametrize("shifts", [["--x-sun", "0.3", "--x-planet", "0.2"], []])   # given, and the optimum
def test_a_loaded_set_shows_each_meshs_strength(capsys, shifts):
    # with --torque/--material the output gave only the strength checks' margins, never S_H, S_F or the stresses;
    # each mesh's result now follows its checks, and its safety factors are those the checks compared (the sun and
    # the ring 18CrNiMo7-6, the planet 42CrMo4: each mesh's S_H the smaller of its two gears')
    argv = ["planetary", "--module", "2", "--planets", "3", "--z-sun", "24", "--z-planet", "36", "--z-ring", "96",
            "--torque", "60", "--speed", "1450", "--material", "18CrNiMo7-6", "--planet-material", "42CrMo4",
            "--face-width", "25", "--life-h", "20000", "--k-gamma", "1.15", "--sh-min", "1.1", "--accuracy-grade", "6",
            "--factor", "K_Hbeta=1.2", *shifts]
    assert main(argv) == 0
    text = capsys.readouterr().out
    assert main(argv + ["--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    rows = data["checks"] if "checks" in data else [dict(check=k, margin=v) for k, v in data["margins"].items()]
    margin = {r["check"]: r["margin"] for r in rows}
    for mesh in ("sun-planet", "planet-ring"):
        block = text.split(f"strength of the {mesh} mesh")[1].split("strength of the")[0]
        line = {ln.split()[0]: ln.split()[1:] for ln in block.splitlines() if ln.startswith("  S_")}
        s_h, s_f = ([float(v) for v in line[k]] for k in ("S_H", "S_F"))
        assert "(S_Hmin 1.1, S_Fmin 1.4)" in block and "sigma_H" in block
        assert min(s_h) / 1.1 - 1 == pytest.approx(margin[f"{mesh}:contact_strength"], abs=1e-3)
        root = sorted(k for k in margin if k.startswith(f"{mesh}:root_strength"))
        gears = ("sun", "planet") if mesh == "sun-planet" else ("planet", "ring")
        for s, g in zip(s_f, gears):
            assert s / 1.4 - 1 == pytest.approx(margin[f"{mesh}:root_strength_{g}"], abs=1e-3)
        assert len(root) == 2


def test_a_spectrum_without_y_m_names_the_planet_not_a_pairs_gear_2(tmp_path, capsys):
    # the damage check's message said "gear 2's root bends both ways": a planetary set has no gear 2
    csv = tmp_path / "sun.csv"
    csv.write_text("torque_nm,share\n120,0.05\n80,0.95\n", encoding="utf-8")
    argv = ["planetary", "-m", "2", "--planets", "3", "--z-sun", "24", "--z-planet", "36", "--z-ring", "96",
            "--speed", "1450", "--material", "18CrNiMo7-6", "--face-width", "25", "--life-h", "20000",
            "--spectrum", str(csv)]
    for shifts in ([], ["--x-sun", "0.3", "--x-planet", "0.2"]):
        assert main(argv + shifts) == 2
        err = capsys.readouterr().err.strip()
        assert len(err.splitlines()) == 1 and "--mean-stress-factor" in err and "planet's root" in err
        assert "gear 2" not in err
