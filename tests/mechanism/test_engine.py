"""An engine's torque over the cycle: the cylinders shifted by their phases, only the harmonic orders an even-firing
engine keeps (FFT), the mean equal to the indicated work over the cycle, the inertia torque's zero mean, the
journal torques of seed 004, the curve a load spectrum reads, and inputs refused by name."""
import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.errors import GearDesignError
from geardesign.mechanism.engine import Engine, EngineTorque, TorqueCurve, engine_torque
from geardesign.mechanism.pressure import IndicatorDiagram, gas_force, otto_pressure, piston_area
from geardesign.mechanism.slider_crank import SliderCrank

MECH = SliderCrank(45, 150, rod_cg_mm=45, piston_mass_kg=0.6, rod_mass_kg=0.7, rod_inertia_kg_m2=0.003,
                   crank_mass_kg=2.0, crank_cg_mm=10, cylinder_bore_mm=86)
OTTO = dict(compression_ratio=10.0, intake_pressure_mpa=0.095, exhaust_pressure_mpa=0.11, peak_pressure_mpa=7.0,
            polytropic_compression=1.36, polytropic_expansion=1.26)


def _diagram(points=7200, strokes=4):
    return IndicatorDiagram.otto(45, 150, OTTO["compression_ratio"], points=points, strokes=strokes,
                                 **{k: v for k, v in OTTO.items() if k != "compression_ratio"})


def four(**kw):
    return Engine(MECH, _diagram(), 3000, cylinders=4, throws_deg=(0, 180, 180, 0), firing_order=(1, 3, 4, 2), **kw)


def test_cylinders_are_one_curve_shifted_by_their_phases():
    res = four().analyse(720)
    e = res.engine
    for c in range(4):
        np.testing.assert_allclose(res.cylinder_torque_nm[c], e.cylinder_torque(res.crank_angle_deg - e.phases[c]),
                                   rtol=0, atol=1e-9 * np.abs(res.torque_nm).max())
    np.testing.assert_allclose(res.torque_nm, res.cylinder_torque_nm.sum(axis=0), rtol=1e-15)
    # phases off the sampling grid take the other path (each cylinder evaluated at its own angles): the same curve
    off = Engine(MECH, _diagram(), 3000, cylinders=4, phases_deg=(0.0, 540.0, 180.0, 360.0)).analyse(719)
    np.testing.assert_allclose(off.torque_nm, four().cylinder_torque(off.crank_angle_deg[None, :] - np.array(
        [0, 540, 180, 360])[:, None]).sum(axis=0), rtol=0, atol=1e-9 * np.abs(off.torque_nm).max())


@pytest.mark.parametrize("cylinders, strokes", [(4, 4), (6, 4), (3, 4), (2, 2), (3, 2)])
def test_even_firing_keeps_only_its_harmonic_orders(cylinders, strokes):
    """n identical cylinders firing every cycle/n: the summed torque's Fourier series keeps only the harmonics of
    the cycle that are multiples of n — orders (per crank turn) multiples of n/2 for a four-stroke engine, of n for a
    two-stroke one (Den Hartog, Mechanical Vibrations, §5.8; Kolchin & Demidov §11)."""
    points = 1440
    e = Engine(MECH, _diagram(strokes=strokes), 3000, cylinders=cylinders)
    res = e.analyse(points)
    spectrum = np.abs(np.fft.rfft(res.torque_nm)) / points
    h = np.arange(spectrum.size)
    kept = h % cylinders == 0
    assert spectrum[~kept].max() < 1e-9 * spectrum.max()
    per_turn = h / (strokes / 2)                 # harmonic h of the cycle is order h/(cycle/360) per crank turn
    assert np.all(np.mod(per_turn[kept], cylinders / (strokes / 2)) == 0)
    assert spectrum[cylinders] > 1e-3 * spectrum[0]           # the firing order itself is there


def test_mean_torque_is_the_indicated_work_over_the_cycle():
    """With the exact pressure at every sample (a table of the curve at the sampling angles), the mean torque is
    ∮p dV/(4π) per cylinder; the weights and inertia forces add nothing over the cycle."""
    points = 14400
    phi = np.arange(points) * (720 / points)
    p = otto_pressure(phi, 45, 150, **OTTO)
    res = Engine(MECH, IndicatorDiagram(phi, p), 3000, cylinders=4, firing_order=(1, 3, 4, 2)).analyse(points)
    vc = 90 / (OTTO["compression_ratio"] - 1)
    va = vc + 90
    pa, pr, pz = OTTO["intake_pressure_mpa"], OTTO["exhaust_pressure_mpa"], OTTO["peak_pressure_mpa"]
    n1, n2 = OTTO["polytropic_compression"], OTTO["polytropic_expansion"]
    pc, pb = pa * (va / vc) ** n1, pz * (vc / va) ** n2
    work = (pz * vc - pb * va) / (n2 - 1) - (pc * vc - pa * va) / (n1 - 1) + (pa - pr) * (va - vc)   # MPa·mm
    mean = 4 * work * float(piston_area(86)) / 1000 / (4 * math.pi)
    assert res.mean_torque_nm == pytest.approx(mean, rel=1e-6)
    assert abs(res.inertia_torque_nm.mean()) < 1e-9 * np.abs(res.inertia_torque_nm).max()
    assert res.gas_torque_nm.mean() == pytest.approx(mean, rel=1e-6)
    assert res.power_kw == pytest.approx(res.mean_torque_nm * 100 * math.pi / 1000, rel=1e-12)


def test_journal_and_crank_pin_torques_and_the_resultant():
    res = four(mechanical_efficiency=0.85).analyse(720)
    np.testing.assert_array_equal(res.journal_torque_nm[0], 0)
    np.testing.assert_allclose(res.journal_torque_nm[-1], res.torque_nm, rtol=1e-14, atol=1e-9)
    np.testing.assert_allclose(res.crank_pin_torque_nm[2], res.cylinder_torque_nm[:2].sum(axis=0)
                               + 0.5 * res.cylinder_torque_nm[2], rtol=1e-14, atol=1e-9)
    assert res.effective_torque_nm == pytest.approx(0.85 * res.mean_torque_nm, rel=1e-15)
    assert res.unevenness == pytest.approx((res.max_torque_nm - res.min_torque_nm) / res.mean_torque_nm)
    table = res.table()
    assert {"torque_nm", "journal5_torque_nm", "crank_pin4_torque_nm", "cylinder3_torque_nm"} <= set(table.columns)


def test_gas_torque_alone_against_the_closed_form():
    """Massless links, no weights: each cylinder's torque is F_g·r·sin(φ + β)/cos β at its own angle."""
    mech = SliderCrank(45, 150, cylinder_bore_mm=86)
    e = Engine(mech, _diagram(), 3000, cylinders=2, phases_deg=(0.0, 360.0), gravity_m_s2=0.0)
    res = e.analyse(720)
    own = res.crank_angle_deg - 360.0
    beta = np.arcsin(0.3 * np.sin(np.radians(own)))
    fg = gas_force(e.diagram.pressure(own), 86)
    closed = fg * 0.045 * np.sin(np.radians(own) + beta) / np.cos(beta)
    np.testing.assert_allclose(res.cylinder_torque_nm[1], closed, rtol=0, atol=1e-9 * np.abs(closed).max())


def test_fluctuation_with_a_flywheel():
    res = four(flywheel_inertia_kg_m2=0.25).analyse(1440)
    w = 100 * math.pi
    assert res.fluctuation == pytest.approx(res.excess_work_j / (0.25 * w * w), rel=1e-12)
    assert four().analyse().fluctuation is None
    # a heavier flywheel, a smoother engine
    assert four(flywheel_inertia_kg_m2=1.0).analyse(1440).fluctuation == pytest.approx(res.fluctuation / 4)


def test_the_curve_a_load_spectrum_reads():
    e = four()
    curve = engine_torque(e, points=720)
    assert isinstance(curve, TorqueCurve)
    angle, torque, n = curve
    assert angle.shape == torque.shape == (720,) and n == 3000.0
    assert angle[0] == 0 and angle[-1] == pytest.approx(719.0)
    np.testing.assert_array_equal(torque, e.analyse(720).torque_nm)
    np.testing.assert_array_equal(e.torque_curve(720).torque_nm, torque)


def test_summary_repr_and_json():
    res = four(mechanical_efficiency=0.8, flywheel_inertia_kg_m2=0.3).analyse()
    text = "\n".join(res.summary())
    assert "4-cylinder 4-stroke engine at 3000 rpm" in text and "unevenness μ" in text and "δ = " in text
    assert repr(res).startswith("EngineTorque(4-cylinder") and len(repr(res).splitlines()) <= 8
    d = json.loads(res.to_json())
    assert d["cylinders"] == 4 and d["phases_deg"] == [0.0, 540.0, 180.0, 360.0] and d["status"] == "success"
    assert isinstance(res, EngineTorque) and "Engine(mechanism=SliderCrank(" in repr(res.engine)


@pytest.mark.parametrize("kw, match", [
    (dict(cylinders=0), "cylinders must be a whole number in \\[1, 24\\]"),
    (dict(cylinders=4, phases_deg=(0, 180)), "one phase per cylinder \\(4\\)"),
    (dict(cylinders=2, phases_deg=(0, 720)), "phases_deg must be in \\[0, 720\\)"),
    (dict(cylinders=2, throws_deg=(0, 180)), "need its firing_order"),
    (dict(cylinders=2, phases_deg=(0, 360), firing_order=(1, 2)), "not both"),
    (dict(n_rpm=0), "n_rpm must be in \\(0, 100000\\] rpm"),
    (dict(mechanical_efficiency=1.2), "mechanical_efficiency must be in \\(0, 1\\]"),
    (dict(flywheel_inertia_kg_m2=0), "flywheel_inertia_kg_m2 must be in \\(0, 100000\\]"),
    (dict(speed_rpm=3000), "the crankshaft's speed is n_rpm"),
    (dict(n_rpm=[1000, 2000]), "n_rpm must be one number"),
    (dict(gravity_m_s2=(9.81, 0)), "gravity_m_s2 must be one number"),
    (dict(name=3), "name must be text"),
    (dict(mechanism="crank"), "mechanism must be a SliderCrank"),
    (dict(diagram=[0, 1]), "diagram must be an IndicatorDiagram"),
])
def test_bad_engines_are_refused_by_name(kw, match):
    args = dict(mechanism=MECH, diagram=_diagram(720), n_rpm=3000) | kw
    with pytest.raises(GearDesignError, match=match):
        Engine(**args)


def test_a_bore_and_the_points_are_asked_for():
    with pytest.raises(GearDesignError, match="cylinder_bore_mm is needed"):
        Engine(SliderCrank(45, 150), _diagram(720), 3000)
    with pytest.raises(GearDesignError, match="points must be a whole number in \\[8, 100000\\]"):
        four().analyse(4)
    with pytest.raises(GearDesignError, match="engine must be an Engine"):
        engine_torque("V8")


@settings(max_examples=25, deadline=None)
@given(n=st.floats(100, 8000), cyl=st.integers(1, 8), points=st.integers(16, 800))
def test_cylinders_sum_to_the_resultant_and_inertia_averages_out(n, cyl, points):
    res = Engine(MECH, _diagram(720), n, cylinders=cyl).analyse(points)
    np.testing.assert_allclose(res.cylinder_torque_nm.sum(axis=0), res.torque_nm, rtol=1e-12,
                               atol=1e-9 * np.abs(res.torque_nm).max())
    np.testing.assert_allclose(res.gas_torque_nm + res.inertia_torque_nm, res.torque_nm, rtol=1e-12,
                               atol=1e-9 * np.abs(res.torque_nm).max())
    assert res.excess_work_j >= 0
    assert np.all((res.reversal_angles_deg >= 0) & (res.reversal_angles_deg < 720))


def test_two_stroke_throws_give_the_firing_order():
    """A two-stroke cylinder fires at each top dead centre: its phase is its throw (the order follows)."""
    e = Engine(MECH, _diagram(720, strokes=2), 3000, cylinders=3, throws_deg=(0, 240, 120))
    assert e.phases.tolist() == [0.0, 240.0, 120.0] and e.cycle_deg == 360.0


def test_seed003_as_a_v_twin_engine():
    """Seed 003's V-twin through the Engine: cylinder 2's bank 80° after cylinder 1 (throws 0, 80; cylinder 2 fires
    80° after cylinder 1), the banks tilted ∓40°, a table diagram giving P3 = 2376 N on piston 1 at 45° after its
    firing and nothing on piston 2: at cylinder 1's cycle angle 405° the engine's torque over r is the lever's F_y."""
    from tests.mechanism.test_kinetostatics import seed003_mechanism

    mech, n, s = seed003_mechanism()
    mech = SliderCrank(**{**{f: getattr(mech, f) for f in mech.__dataclass_fields__}, "cylinder_bore_mm": 76.0})
    p0 = 0.101325
    p3 = p0 + s["P3"] / float(piston_area(76.0))
    diagram = IndicatorDiagram([0, 325, 405, 600], [p0, p0, p3, p0])
    e = Engine(mech, diagram, n, cylinders=2, throws_deg=(0, 80), firing_order=(1, 2), axis_tilts_deg=(-40, 40),
               gravity_m_s2=9.81)
    assert e.phases.tolist() == [0.0, 80.0]
    res = e.analyse(720)
    assert res.torque_nm[405] / 0.044 == pytest.approx(s["F_y_lever"], rel=1e-3)
    np.testing.assert_allclose(res.cylinder_torque_nm[1], e.cylinder_torque(res.crank_angle_deg - 80, cylinder=2),
                               rtol=0, atol=1e-9 * np.abs(res.torque_nm).max())
    upright = Engine(mech, diagram, n, cylinders=2, throws_deg=(0, 80), firing_order=(1, 2), gravity_m_s2=9.81)
    assert not np.allclose(upright.analyse(720).torque_nm, res.torque_nm, rtol=0, atol=1e-6)   # the weights turned
    with pytest.raises(GearDesignError, match="axis_tilts_deg must give one tilt per cylinder"):
        Engine(mech, diagram, n, cylinders=2, axis_tilts_deg=(10,))


def test_no_unevenness_without_work_over_the_cycle():
    """Fuzzing found μ = NaN in the result (and in its JSON) when the mean torque is not positive: a cylinder
    compressing gas it never burns does negative work over the cycle; μ is None then, like the summary says."""
    motored = IndicatorDiagram([0, 180, 350, 360, 370, 540], [0.1, 0.1, 2.0, 0.1, 0.1, 0.1])
    res = Engine(MECH, motored, 3000).analyse(720)
    assert res.mean_torque_nm < 0 and not res.success
    assert res.unevenness is None and json.loads(res.to_json())["unevenness"] is None
    assert "no unevenness" in "\n".join(res.summary())
    res.plot()
