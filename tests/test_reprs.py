"""Issue 28: every public result reads well in a terminal and a notebook — a repr of at most ~15 lines
that never dumps an array, and an HTML view for the ones that hold a table.

The walk covers every class in ``geardesign.__all__`` and in the modules it exposes (``gd.chain``,
``gd.key``, ``gd.motor``, ...) that is a :class:`geardesign.results.Result`: a new public result must get
an example below or the coverage test fails.
"""
from __future__ import annotations

import inspect

import pytest

import geardesign as gd
from geardesign.results import Result

MAX_LINES = 15
MAX_LINE_CHARS = 400          # one long line is a sentence, not a dump


def _examples():
    pair = gd.GearPair(8, 17, 26, 0.898, 0.517)
    ring_pair = gd.GearPair(2, 20, 60, 0.3, 0.6, internal=True)
    drive = gd.Drive(motor=gd.motor.select(4, 1450), stages=[gd.GearStage(3, z1=17, z2=58), gd.ChainStage(z1=13, z2=37)],
                     shafts=[gd.Shaft(40, 60, at=1)])
    return {
        "Geometry": pair.geometry(),
        "Geometry (arrays)": gd.pair_geometry(1, [17, 18, 19], 26, 0.0, 0.5),
        "checks table": pair.checks(),
        "ToothProfile": gd.tooth_profile(8, 17, 0.898),
        "RingProfile": gd.pair_profiles(ring_pair)[1],
        "pair_profiles": gd.pair_profiles(pair),
        "ShiftResult": gd.optimize_shifts(17, 26),
        "ShiftResult (failed)": gd.optimize_shifts(5, 5),
        "Region": gd.feasible_region(17, 26),
        "TeethSelection": gd.select_teeth(1.5, m=8, z1_range=(14, 20)),
        "PlanetarySet": gd.PlanetarySet(1.75, 21, 43, 108, 3, x_sun=0.438, x_planet=0.0426, x_ring=0.0),
        "PlanetaryShiftResult": gd.optimize_planetary_shifts(21, 43, 108, 3, m=1.75),
        "PlanetaryTeethSelection": gd.select_planetary_teeth(5.0, 3, m=2, ratio_tol=0.02, z_sun_range=(12, 16)),
        "ChainDesign": gd.chain.design(torque_nm=380, n1_rpm=120, ratio=1, z1=13),
        "KeySelection": gd.key.select(60, 503, 50),
        "KeyCapacity": gd.key.capacity(60, 32, 300, 120),
        "MotorSelection": gd.motor.select(4, 1450),
        "Drive": drive,
        "DriveAnalysis": drive.analyse(),
        "GearStage": gd.GearStage(3),
        "StrengthResult": pair.strength(gd.Load(torque_nm=900, n_rpm=1000), "42CrMo4", face_width_mm=60),
        "LifeResult": pair.life(gd.LoadSpectrum.from_bins([900, 450], 1000, share=[0.2, 0.8], duration_h=20000),
                                "42CrMo4", face_width_mm=60),
        "ToothMeasurements": gd.tooth_measurements(8, 17, 0.898),
        "Backlash": pair.backlash(-0.1, -0.12, 0.05),
        "FlankTolerances": gd.flank_tolerances(8, 17, 7, face_width_mm=60),
        "MeshForces": pair.forces(400.0),
        "ChainPull": gd.chain_pull(380, 31.75, 13, 120, 3.8, 1270.0),
        "BearingCheck": gd.check_bearing("6208", 3200, 1800, 650),
        "BearingSelection": gd.select_bearing(["62", "63"], 40, 3200, 1800, 650, life_h=20000),
        **_shaft_examples(),
        **_engine_examples(),
    }


def _engine_examples():
    mech = gd.SliderCrank(70, 250, rod_cg_mm=75, piston_mass_kg=2.5, rod_mass_kg=4.7, cylinder_bore_mm=100)
    engine = gd.Engine(mech, gd.IndicatorDiagram.otto(70, 250, 6.0, peak_pressure_mpa=3.2), 1700, cylinders=2,
                       mechanical_efficiency=0.8, flywheel_inertia_kg_m2=1.0)
    return {"JointForces": gd.joint_forces(mech, [0.0, 90.0, 300.0], 1700, 5000.0),
            "EngineTorque": engine.analyse(720)}


def _shaft_examples():
    model = gd.ShaftModel([(40, 35), (160, 45), (40, 35)], [20, 220],
                          [gd.ShaftLoad(120, fy_n=-3000, torque_nm=100), gd.ShaftLoad(240, fz_n=500, torque_nm=-100)])
    a = gd.analyse_shaft(model)
    return {"ShaftAnalysis": a, "ShaftSafety": gd.shaft_safety(a, [gd.ShaftNotch(120, gd.Notch("key"))], "C45"),
            "Din743Result": gd.din743_safety("C45", gd.Notch("key"), d_mm=45, M_ba=300, T_m=100)}


def _scene_path():
    from pathlib import Path

    return Path(__file__).resolve().parents[1] / "studies" / "scenes" / "seed002_chain.toml"


@pytest.fixture(scope="module")
def examples():
    return _examples()


def _public_result_classes():
    found = {}
    for name in gd.__all__:
        obj = getattr(gd, name)
        members = [obj] if inspect.isclass(obj) else [m for _, m in inspect.getmembers(obj, inspect.isclass)
                                                       if m.__module__.startswith(getattr(obj, "__name__", "-"))]
        for cls in members:
            if issubclass(cls, Result) and cls is not Result and not cls.__name__.startswith("_"):
                found[cls.__name__] = cls
    return found


def test_every_public_result_has_an_example(examples):
    covered = {type(v).__name__ for v in examples.values()}
    missing = set(_public_result_classes()) - covered - {"RankedTable", "SceneReport"}
    assert not missing, f"add an example of {sorted(missing)} to tests/test_reprs.py"


def test_scene_report_repr(tmp_path):
    from geardesign.scene import run_scene

    rep = run_scene(_scene_path(), tmp_path / "out")
    text = repr(rep)
    assert len(text.splitlines()) <= MAX_LINES and "FAILS" not in text.splitlines()[0]


@pytest.mark.parametrize("name", [
    "Geometry", "Geometry (arrays)", "checks table", "ToothProfile", "RingProfile", "pair_profiles", "ShiftResult",
    "ShiftResult (failed)", "Region", "TeethSelection", "PlanetarySet", "PlanetaryShiftResult",
    "PlanetaryTeethSelection", "ChainDesign", "KeySelection", "KeyCapacity", "MotorSelection", "Drive",
    "DriveAnalysis", "GearStage", "MeshForces", "ChainPull", "BearingCheck", "BearingSelection", "ShaftAnalysis",
    "ShaftSafety", "Din743Result", "JointForces", "EngineTorque"])
def test_repr_is_short_and_never_an_array_dump(name, examples):
    text = repr(examples[name])
    lines = text.splitlines()
    assert len(lines) <= MAX_LINES, f"{name}: {len(lines)} lines"
    assert max(map(len, lines)) <= MAX_LINE_CHARS, f"{name}: a line of {max(map(len, lines))} characters"
    assert "array([" not in text and "dtype:" not in text, f"{name} dumps an array or a Series"


@pytest.mark.parametrize("name", ["Geometry", "ShiftResult", "TeethSelection", "ChainDesign", "KeySelection",
                                  "DriveAnalysis", "PlanetaryShiftResult", "checks table", "BearingSelection",
                                  "ShaftAnalysis", "ShaftSafety", "Din743Result", "JointForces", "EngineTorque"])
def test_tabular_results_have_an_html_view(name, examples):
    html = examples[name]._repr_html_()
    assert "<table" in html and "array([" not in html
    assert len(html) < 60_000


def test_unshortened_tip_is_said_loudly():
    """Seed 000's pinion: d + 2(h_a* + x)m = 136 + 2·1.898·8 = 166.368 mm unshortened; the pair's tip is
    shorter by 2Δy·m (GOST 16532-70), and pair_profiles cuts it there without the warning."""
    alone = gd.tooth_profile(8, 17, 0.898)
    assert alone.tip_diameter_mm == pytest.approx(136 + 2 * 1.898 * 8, rel=1e-12)
    assert "NOT shortened" in repr(alone) and "pair_profiles" in repr(alone)
    pair = gd.GearPair(8, 17, 26, 0.898, 0.517)
    pinion, _ = gd.pair_profiles(pair)
    g = pair.geometry()
    assert pinion.tip_diameter_mm == pytest.approx(136 + 2 * (1.898 - g.dy) * 8, rel=1e-12)
    assert "NOT shortened" not in repr(pinion)
    given = gd.tooth_profile(8, 17, 0.898, tip_diameter_mm=g.da1)
    assert "NOT shortened" not in repr(given)


def test_geometry_is_subscriptable_and_names_a_wrong_field():
    g = gd.GearPair(8, 17, 26, 0.898, 0.517).geometry()
    assert g["eps_alpha"] == g.eps_alpha and g["a_w"] == g.a_w
    with pytest.raises(KeyError, match="eps_alpha"):
        g["epsilon"]
