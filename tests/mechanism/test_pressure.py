"""The indicator diagram and the gas force: interpolation, CSV, the parametric polytropic cycle, and the mean gas
torque against the cycle's indicated work written in closed form here."""
import math

import numpy as np
import pytest

from geardesign.errors import GearDesignError
from geardesign.mechanism.kinetostatics import piston_force_torque
from geardesign.mechanism.pressure import (ATMOSPHERE_MPA, IndicatorDiagram, cycle_volume, gas_force, otto_pressure,
                                           piston_area)


def test_gas_force_is_pressure_over_the_crankcase_times_the_area():
    assert float(gas_force(ATMOSPHERE_MPA, 90)) == 0.0
    assert float(gas_force(2.0, 100, crankcase_pressure_mpa=0.0)) == pytest.approx(2.0 * math.pi * 2500, rel=1e-15)
    assert float(piston_area(80)) == pytest.approx(math.pi * 1600, rel=1e-15)


def test_diagram_reads_periodically_and_linearly():
    d = IndicatorDiagram([0, 90, 360, 600], [1.0, 3.0, 2.0, 0.5])
    np.testing.assert_allclose(d.pressure([45, 90, 225, 660, 720, -30]), [2.0, 3.0, 2.5, 0.75, 1.0, 0.875])
    two = IndicatorDiagram([0, 180], [4.0, 0.2], strokes=2)
    assert two.cycle_deg == 360 and float(two.pressure(270)) == pytest.approx(2.1)
    assert "2 points, 2-stroke" in repr(two)


@pytest.mark.parametrize("kw, match", [
    (dict(crank_angle_deg=[0, 0, 10], pressure_mpa=[1, 1, 1]), "must increase strictly"),
    (dict(crank_angle_deg=[0, 720], pressure_mpa=[1, 1]), "inside one cycle \\[0, 720\\)"),
    (dict(crank_angle_deg=[0, 10], pressure_mpa=[1, -1]), "pressure_mpa must be in \\[0, 100\\]"),
    (dict(crank_angle_deg=[0, 10, 20], pressure_mpa=[1, 1]), "one value each per point"),
    (dict(crank_angle_deg=[0], pressure_mpa=[1]), "at least 2 points"),
    (dict(crank_angle_deg=[0, 10], pressure_mpa=[1, 1], strokes=3), "strokes must be 2 or 4"),
])
def test_bad_diagrams_are_refused_by_name(kw, match):
    with pytest.raises(GearDesignError, match=match):
        IndicatorDiagram(**kw)


def test_diagram_from_csv(tmp_path):
    path = tmp_path / "p.csv"
    path.write_text("crank_angle_deg,pressure_mpa\n0,0.1\n360,5.0\n540,0.4\n", encoding="utf-8")
    d = IndicatorDiagram.from_csv(path)
    assert float(d.pressure(450)) == pytest.approx(2.7) and d.source == str(path)
    bad = tmp_path / "bad.csv"
    bad.write_text("angle,p\n0,1\n", encoding="utf-8")
    with pytest.raises(GearDesignError, match="expected the columns crank_angle_deg, pressure_mpa"):
        IndicatorDiagram.from_csv(bad)
    bad.write_text("crank_angle_deg,pressure_mpa\n0,x\n", encoding="utf-8")
    with pytest.raises(GearDesignError, match="needs a number"):
        IndicatorDiagram.from_csv(bad)
    with pytest.raises(GearDesignError, match="cannot be read"):
        IndicatorDiagram.from_csv(tmp_path / "none.csv")


def _otto_work(eps, pa, pr, pz, n1, n2, stroke):
    """∮p dV per unit piston area (MPa·mm) of the polytropic four-stroke cycle, integrated by hand:
    (p_z V_c − p_b V_a)/(n₂ − 1) − (p_c V_c − p_a V_a)/(n₁ − 1) + (p_a − p_r)(V_a − V_c)."""
    vc = stroke / (eps - 1)
    va = vc + stroke
    pc = pa * (va / vc) ** n1
    pb = pz * (vc / va) ** n2
    return (pz * vc - pb * va) / (n2 - 1) - (pc * vc - pa * va) / (n1 - 1) + (pa - pr) * (va - vc)


@pytest.mark.parametrize("eps, pz, n1, n2", [(7.0, 4.5, 1.37, 1.25), (16.0, 9.0, 1.35, 1.28), (5.0, 2.0, 1.3, 1.2)])
def test_mean_gas_torque_is_the_indicated_work_over_the_cycle(eps, pz, n1, n2):
    r, l_, bore = 70.0, 250.0, 100.0
    pa, pr = 0.09, 0.115
    phi = np.arange(72000) * 0.01
    p = otto_pressure(phi, r, l_, eps, intake_pressure_mpa=pa, exhaust_pressure_mpa=pr, peak_pressure_mpa=pz,
                      polytropic_compression=n1, polytropic_expansion=n2)
    torque = piston_force_torque(gas_force(p, bore), phi, r, l_)
    work_j = _otto_work(eps, pa, pr, pz, n1, n2, 2 * r) * float(piston_area(bore)) / 1000
    assert torque.mean() == pytest.approx(work_j / (4 * math.pi), rel=1e-6)


def test_otto_pressure_follows_its_polytropes():
    r, l_ = 50.0, 150.0
    phi = np.array([200.0, 300.0, 400.0, 500.0])
    p = otto_pressure(phi, r, l_, 9.0, intake_pressure_mpa=0.1, peak_pressure_mpa=6.0, polytropic_compression=1.35,
                      polytropic_expansion=1.27)
    v = cycle_volume(phi, r, l_, 9.0)
    va, vc = cycle_volume(180.0, r, l_, 9.0), cycle_volume(0.0, r, l_, 9.0)
    np.testing.assert_allclose(p[:2], 0.1 * (va / v[:2]) ** 1.35, rtol=1e-14)
    np.testing.assert_allclose(p[2:], 6.0 * (vc / v[2:]) ** 1.27, rtol=1e-14)
    assert float(vc) == pytest.approx(100 / 8) and float(va) == pytest.approx(100 + 100 / 8)
    two = otto_pressure([90.0, 270.0], r, l_, 9.0, strokes=2, intake_pressure_mpa=0.1, peak_pressure_mpa=6.0)
    v2 = cycle_volume([90.0, 270.0], r, l_, 9.0)      # two-stroke: expansion from firing, compression from BDC
    np.testing.assert_allclose(two, [6.0 * (vc / v2[0]) ** 1.25, 0.1 * (va / v2[1]) ** 1.37], rtol=1e-14)


def test_otto_refuses_a_peak_below_the_end_of_compression():
    with pytest.raises(GearDesignError, match="peak_pressure_mpa must exceed the end of compression"):
        otto_pressure(0, 70, 250, 10.0, intake_pressure_mpa=0.1, peak_pressure_mpa=2.0)
    with pytest.raises(GearDesignError, match="compression_ratio must be in \\(1, 40\\]"):
        otto_pressure(0, 70, 250, 1.0)
    d = IndicatorDiagram.otto(70, 250, 7.0, points=360)
    assert d.crank_angle_deg.size == 360 and d.source == "otto_pressure"


@pytest.mark.parametrize("strokes", [np.array(100.0), np.array([4]), [4], "4"])
def test_strokes_that_are_no_number_are_refused_by_name(strokes):
    """Fuzzing found 'TypeError: unhashable type' for strokes=np.array(100.0) (a dict lookup before any check)."""
    with pytest.raises(GearDesignError, match="strokes must be 2 or 4"):
        IndicatorDiagram.otto(45, 150, 10.0, peak_pressure_mpa=7.0, strokes=strokes)
    with pytest.raises(GearDesignError, match="strokes must be 2 or 4"):
        IndicatorDiagram([0, 180], [0.1, 1.0], strokes)


def test_a_diagram_that_is_no_text_file_is_refused_by_name(tmp_path):
    """Fuzzing found from_csv reading /dev/zero without end (unbounded work) and a UnicodeDecodeError traceback for
    bytes that are not UTF-8: a device, a folder or a larger file is refused before it is read whole."""
    latin = tmp_path / "latin.csv"
    latin.write_bytes(b"crank_angle_deg,pressure_mpa\n0,0.1\n\xe9\n")
    with pytest.raises(GearDesignError, match="indicator diagram .* is not UTF-8 text"):
        IndicatorDiagram.from_csv(latin)
    for path in ("/dev/zero", tmp_path):
        with pytest.raises(GearDesignError, match="is not a regular file"):
            IndicatorDiagram.from_csv(path)
