"""Seed 000's engine end to end (issue 38 §5, examples/seed000_engine_gear.toml): the engine's torque counted on
its gear pair per tooth and flank, the pair's ISO 6336-6 life against the chain written out step by step, the
max_life shifts against the seed's and a brute-force grid, and the [gear.spectrum] keys of an engine's spectrum."""
from pathlib import Path

import numpy as np
import pytest

from geardesign.errors import GearDesignError

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "seed000_engine.toml"


def _scene(tmp_path, text):
    path = tmp_path / "e.toml"
    path.write_text(text, encoding="utf-8")
    return path


GEAR_EXAMPLE = EXAMPLE.parent / "seed000_engine_gear.toml"


def _toml(path):
    import tomllib

    return tomllib.loads(path.read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def seed_gear():
    from geardesign.scene.engine_gear import engine_gear
    from geardesign.scene.load import load_scene

    return engine_gear(load_scene(GEAR_EXAMPLE))


def test_the_end_to_end_example_drives_seed000s_pair_with_seed000s_engine():
    raw = _toml(GEAR_EXAMPLE)
    assert raw["engine"] == _toml(EXAMPLE)["engine"]          # the same engine as the engine example, table for table
    g = raw["gear"]
    assert (g["module"], g["z1"], g["z2"], g["x1"], g["x2"]) == (8, 17, 26, 0.898, 0.517)   # seed 000 §6.1


def test_the_life_is_the_chain_computed_step_by_step(seed_gear):
    """mechanism -> LoadSpectrum.from_curve -> pair.life, written out here, gives the scene's numbers."""
    import geardesign as gd

    mech = gd.SliderCrank(70, 250, rod_cg_mm=75, piston_mass_kg=2.5, rod_mass_kg=4.7, rod_inertia_kg_m2=0.0617,
                          crank_mass_kg=10.5, crank_cg_mm=25, cylinder_bore_mm=100)
    diagram = gd.IndicatorDiagram.otto(70, 250, 6.0, peak_pressure_mpa=3.2, intake_pressure_mpa=0.09,
                                       exhaust_pressure_mpa=0.11, polytropic_compression=1.35,
                                       polytropic_expansion=1.25)
    engine = gd.Engine(mech, diagram, 1700, cylinders=2, phases_deg=(0, 540), mechanical_efficiency=0.8,
                       flywheel_inertia_kg_m2=1.0)
    angle, torque, n = gd.engine_torque(engine, 720)
    spec = gd.LoadSpectrum.from_curve(torque, angle_deg=angle, n_rpm=n, teeth=(17, 26), period_deg=720, levels=48)
    # the run after which the same teeth meet the same crank angle again: 720/(360/17) = 34 meshes a cycle,
    # lcm(34, 17, 26) = 442 meshes, 442·(360/17)° at 6·1700 °/s
    assert spec.meshes.sum() == 442 and spec.duration_h * 3600 == pytest.approx(442 * (360 / 17) / (6 * 1700), rel=1e-12)
    assert spec.reverses and spec.torque_nm.max() <= torque.max() and spec.torque_nm.min() >= torque.min()
    life = gd.GearPair(8, 17, 26, 0.898, 0.517, face_width_mm=56).life(spec, "40Cr", life_h=5000,
                                                                       mean_stress_factor=0.7)
    got = seed_gear.life["given"]
    for mode in ("H1", "H2", "F1", "F2"):
        assert getattr(got, "D_" + mode) == pytest.approx(getattr(life, "D_" + mode), rel=1e-12, abs=1e-300)
        assert getattr(got, "S_" + mode) == pytest.approx(getattr(life, "S_" + mode), rel=1e-9)
    np.testing.assert_array_equal(seed_gear.spectrum.torque_nm, spec.torque_nm)
    # by hand: mesh j is at j·(360/17)° (mod 720) on pinion tooth j mod 17; the largest bin (its class counted at
    # the end farthest from zero) is the largest torque a mesh meets, on the tooth that meets it
    j = np.arange(442)
    met = np.interp(j * 360 / 17 % 720, angle, torque)
    top = int(np.argmax(spec.torque_nm))
    assert spec.torque_nm[top] == pytest.approx(met.max(), rel=1e-12)
    assert int(spec.tooth1[top]) in set((j[np.isclose(met, met.max(), rtol=1e-12)] % 17).tolist())


def test_the_optimal_shifts_live_longest(seed_gear):
    """max_life's optimum lives at least as long as the seed's shifts and as every feasible node of a grid (the
    geometric checks and D <= 10 checked node by node, the life by pair_life)."""
    import geardesign as gd

    opt, given, best = seed_gear.optimum, seed_gear.life["given"], seed_gear.life["optimum"]
    assert opt.success and opt.objective == "max_life"
    assert best.life_h >= given.life_h                       # 3517 h against 1945 h
    assert opt.fun == pytest.approx(np.log(best.life_h / 5000.0), rel=1e-9)    # fun = ln(L/L_req)
    spec = seed_gear.spectrum
    grid = np.linspace(-0.5, 1.5, 21)
    X1, X2 = (v.ravel() for v in np.meshgrid(grid, grid))
    ok = np.array([bool(gd.GearPair(8, 17, 26, a, b).checks(eps_alpha_min=1.2, sa_min=0.25)["ok"].all())
                   if _builds(a, b) else False for a, b in zip(X1, X2)])
    assert ok.sum() > 20
    out = gd.pair_life(8.0, 17, 26, X1[ok], X2[ok], spectrum=spec, material1="40Cr", face_width_mm=56.0,
                       life_h=5000.0, mean_stress_factor=0.7)
    D = np.max([out[f"D_{m}"] for m in ("H1", "H2", "F1", "F2")], axis=0)
    assert np.all(5000.0 / D <= best.life_h * (1 + 1e-9))


def _builds(x1, x2) -> bool:
    import geardesign as gd
    from geardesign.errors import GearDesignError

    try:
        gd.GearPair(8, 17, 26, x1, x2).geometry()
        return True
    except GearDesignError:
        return False


@pytest.mark.parametrize("change, expected", [
    (("life_h = 5000 ", ""), "[gear.spectrum] life_h: missing; the [engine]'s spectrum is one run"),
    (("life_h = 5000 ", "n_rpm = 1700\nlife_h = 5000 "), "[gear.spectrum] n_rpm: not used with the [engine]'s"),
    (("material = \"40Cr\"", "material = \"40Cr\"\nlevels = 0"), "[gear.spectrum] levels: expected a whole number"),
])
def test_a_bad_engine_spectrum_is_refused_by_key(tmp_path, change, expected):
    from geardesign.scene.load import load_scene

    text = GEAR_EXAMPLE.read_text(encoding="utf-8")
    assert change[0] in text
    path = _scene(tmp_path, text.replace(change[0], change[1]))
    with pytest.raises(GearDesignError) as exc:
        load_scene(path)
    assert str(exc.value).startswith(str(path)) and expected in str(exc.value), str(exc.value)


def test_a_spectrum_without_file_needs_an_engine(tmp_path):
    from geardesign.scene.load import load_scene

    path = _scene(tmp_path, "[gear]\nmodule = 8\nz1 = 17\nz2 = 26\nface_width_mm = 56\n[gear.spectrum]\n"
                            "material = '40Cr'\nlife_h = 5000\n")
    with pytest.raises(GearDesignError, match=r"\[gear.spectrum\] file: missing; give a spectrum file, or an "
                                              r"\[engine\]"):
        load_scene(path)
