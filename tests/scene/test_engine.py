"""The [engine] table of a scene: every key checked by name before anything runs, the three kinds of indicator
diagram, and the example scene of seed 000's engine."""
from pathlib import Path

import numpy as np
import pytest

from geardesign.errors import GearDesignError
from geardesign.mechanism.engine import Engine
from geardesign.scene.engine import engine_schema, load_engine

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "seed000_engine.toml"
BASE = """title = "t"
[engine]
n_rpm = 2000
cylinders = 2
[engine.mechanism]
crank_radius_mm = 40
rod_length_mm = 140
cylinder_bore_mm = 80
"""
OTTO = "[engine.pressure]\nkind = 'otto'\ncompression_ratio = 9.0\npeak_pressure_mpa = 6.0\n"


def _scene(tmp_path, text):
    path = tmp_path / "e.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_the_example_is_seed000s_engine():
    s = load_engine(EXAMPLE)
    m = s.engine.mechanism
    assert (m.crank_radius_mm, m.rod_length_mm, m.rod_cg_mm, m.rod_mass_kg, m.crank_mass_kg, m.crank_cg_mm) == \
        (70, 250, 75, 4.7, 10.5, 25)                        # seed 000 §5: r, L_CB, L_CS, 46.06 N / 9.8, m_k, e_k
    assert s.engine.n_rpm == 1700 and s.engine.cylinders == 2 and s.points == 720
    res = s.engine.analyse(s.points)
    # the assumed diagram aims at the seed's 15.6 kW at 177.9 rad/s: T1 = 87.68 N·m (§7.10)
    assert res.effective_torque_nm == pytest.approx(87.68, rel=0.03)
    # in kind, seed §5.3.2: while cylinder 1 draws in and cylinder 2 compresses, the engine receives energy
    first = (res.crank_angle_deg > 0) & (res.crank_angle_deg < 90)
    assert np.all(res.torque_nm[first] < 0)


def test_the_three_diagrams(tmp_path):
    otto = load_engine(_scene(tmp_path, BASE + OTTO))
    assert isinstance(otto.engine, Engine) and otto.engine.diagram.source == "otto_pressure"
    table = load_engine(_scene(tmp_path, BASE + "[engine.pressure]\nkind = 'table'\ncrank_angle_deg = [0, 360, 540]\n"
                                                 "pressure_mpa = [0.1, 4.0, 0.3]\n"))
    assert float(table.engine.diagram.pressure(450)) == pytest.approx(2.15)
    (tmp_path / "p.csv").write_text("crank_angle_deg,pressure_mpa\n0,0.1\n360,4.0\n540,0.3\n", encoding="utf-8")
    from_csv = load_engine(_scene(tmp_path, BASE + "[engine.pressure]\nkind = 'csv'\ncsv = 'p.csv'\n"))
    np.testing.assert_array_equal(from_csv.engine.analyse(72).torque_nm, table.engine.analyse(72).torque_nm)


@pytest.mark.parametrize("text, expected", [
    (BASE.replace("n_rpm = 2000", "n_rpm = -1") + OTTO, "[engine] n_rpm: expected a number in (0, 100000]"),
    (BASE + OTTO + "[engine.extra]\n", "[engine] extra: unknown key"),
    (BASE.replace("cylinder_bore_mm = 80\n", "") + OTTO, "[engine.mechanism] cylinder_bore_mm: missing"),
    (BASE, "[engine] pressure: missing; expected a table [engine.pressure]"),
    (BASE + "[engine.pressure]\nkind = 'otto'\ncompression_ratio = 9.0\n", "[engine.pressure] peak_pressure_mpa: missing"),
    (BASE + OTTO + "csv = 'x.csv'\n", "[engine.pressure] csv: not used by kind = 'otto'"),
    (BASE + "[engine.pressure]\nkind = 'csv'\ncsv = 'none.csv'\n", "[engine.pressure] csv: the indicator diagram"),
    (BASE.replace("cylinders = 2", "cylinders = 2\nstrokes = 3") + OTTO, "[engine] strokes: expected 2 or 4"),
    (BASE.replace("cylinders = 2", "cylinders = 2\nphases_deg = [0]") + OTTO, "one phase per cylinder (2)"),
    (BASE.replace("rod_length_mm = 140", "rod_length_mm = 30") + OTTO, "[engine.mechanism]: rod_length_mm must"),
    (BASE + OTTO.replace("6.0", "1.0"), "[engine.pressure]: peak_pressure_mpa must exceed the end of compression"),
    ("[gear]\nmodule = 8\n", "top level: expected an [engine] section"),
    ("[engine\n", "not a valid TOML file"),
])
def test_bad_scenes_are_refused_by_file_and_key(tmp_path, text, expected):
    path = _scene(tmp_path, text)
    with pytest.raises(GearDesignError) as exc:
        load_engine(path)
    assert str(exc.value).startswith(str(path)) and expected in str(exc.value), str(exc.value)


def test_schema_ranges_come_from_the_library():
    from geardesign.mechanism.cylinders import CYLINDERS_MAX

    s = engine_schema()
    assert s["cylinders"].hi == CYLINDERS_MAX and s["mechanism"]["cylinder_bore_mm"].required


def test_v_banks_from_the_scene(tmp_path):
    text = BASE.replace("cylinders = 2", "cylinders = 2\nthrows_deg = [0, 90]\nfiring_order = [1, 2]\n"
                                         "axis_tilts_deg = [-45, 45]") + OTTO
    e = load_engine(_scene(tmp_path, text)).engine
    assert e.phases.tolist() == [0.0, 90.0] and e.axis_tilts_deg == (-45.0, 45.0)

