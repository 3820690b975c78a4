"""A gear stage sized by its service life (issue 38 item 4: ``GearStage(spectrum=...)``).

Every figure is re-derived here without the drive: the stage's torque by hand from the power flow (T = P/ω), its
spectrum from the duty cycle's factors by hand, the damage by ``GearPair.life`` / ``pair_life`` on the stage's own
pair, and the sizing's minimality by a grid of modules and widths written in this file (the ISO 54 series, b = ψ·d1
for ψ = 0.2 … 1.0 in steps of 0.05, at least 3 circular pitches: docs/drive_train.md)."""
import math

import numpy as np
import pytest

import geardesign as gd
from geardesign.catalogs.tables import module_series
from geardesign.errors import GearDesignError
from geardesign.gears.strength.service_life import pair_life

P_KW, N_IN, Z1, Z2, MAT, LIFE = 7.5, 1450.0, 20, 71, "42CrMo4", 20000.0
T_IN = 1000 * P_KW / (2 * math.pi * N_IN / 60)          # 49.39 N·m on the pinion of the drive's only stage
DUTY = ([2.2, 1.0, 0.5], [0.005, 0.3, 0.695])           # overload 2.2·T_n for 100 h, the nominal, half load


def _analysed(spectrum, power_kw=P_KW, m=None, **kw):
    st = gd.GearStage(m, Z1, Z2, material=MAT, life_h=kw.pop("life_h", LIFE), spectrum=spectrum, **kw)
    return gd.Drive(stages=[st], n_in_rpm=N_IN, power_kw=power_kw).analyse()


def _by_hand(q, share, torque_nm=T_IN):
    return gd.LoadSpectrum.from_bins(np.asarray(q) * torque_nm, N_IN, share=share, duration_h=LIFE)


def _grid(m, z1=Z1):
    """The widths the sizing tries at module m (docs/drive_train.md), narrowest first."""
    psi = np.arange(0.2, 1.0 + 1e-9, 0.05)
    return np.unique(np.maximum(np.ceil(psi * m * z1 - 1e-9), np.ceil(3 * math.pi * m - 1e-9)))


def _damage(m, x1, x2, widths, spectrum):
    D = pair_life(np.full(widths.shape, m), Z1, Z2, x1, x2, spectrum=spectrum, material1=MAT, face_width_mm=widths,
                  life_h=LIFE)
    return np.max([D[k] for k in ("D_H1", "D_H2", "D_F1", "D_F2")], axis=0)


@pytest.mark.parametrize("single_load", [False, True])
def test_a_stage_sized_by_its_spectrum_lives_its_hours_and_no_smaller_one_does(single_load):
    a = _analysed(gd.DutyCycle(*DUTY), single_load=single_load, center_distance="free")
    s = a.stages[0]["summary"]
    m, b, x1, x2 = s["m"], s["face_width_mm"], s["x1"], s["x2"]
    spec = _by_hand(*DUTY)
    r = gd.GearPair(m, Z1, Z2, x1, x2, face_width_mm=b).life(spec, MAT)     # the stage's pair, its loads
    assert r.ok and r.required_life_h == LIFE
    got = a.stages[0]["life"]
    for mode in ("H1", "H2", "F1", "F2"):
        assert getattr(got, "D_" + mode) == pytest.approx(getattr(r, "D_" + mode), rel=1e-12)
    margins = {c: v for _, c, v in a.checks[["item", "check", "margin"]].itertuples(index=False)}
    assert margins["pitting_damage1"] == pytest.approx(1 - r.D_H1, rel=1e-12, abs=1e-12)
    assert margins["root_damage2"] == pytest.approx(1 - r.D_F2, rel=1e-12, abs=1e-12)
    assert s["damage"] == pytest.approx(r.governing[1], rel=1e-12) and s["life_h"] == pytest.approx(r.life_h)
    assert ("contact_strength" in margins) == single_load
    if single_load:
        return
    # spectrum alone: the damage governs, so every narrower width at m and every width of the next smaller
    # module fail it (the shifts of a free housing do not depend on the module: every geometric check is in m)
    assert a.limiting.endswith("_damage1") or a.limiting.endswith("_damage2")
    widths = _grid(m)
    assert np.all(_damage(m, x1, x2, widths[widths < b], spec) > 1.0)
    smaller = max(v for v in module_series() if v < m)
    assert np.all(_damage(smaller, x1, x2, _grid(smaller), spec) > 1.0)


@pytest.mark.parametrize("single_load, housing", [(False, "free"), (True, "free"), (False, None)])
def test_a_heavier_spectrum_never_gives_a_smaller_stage(single_load, housing):
    rng = np.random.default_rng(38)
    for _ in range(2):
        q = np.sort(rng.uniform(0.3, 2.5, 3))[::-1]
        share = rng.dirichlet(np.ones(3))
        sizes = []
        for k in (0.6, 1.0, 1.5, 2.2):
            a = _analysed(gd.DutyCycle(k * q, share), single_load=single_load, center_distance=housing)
            s = a.stages[0]["summary"]
            assert a.stages[0]["life"].ok
            sizes.append((s["m"], s["face_width_mm"]))
        assert sizes == sorted(sizes), (q, share, sizes)


@pytest.mark.parametrize("housing", ["free", None])
def test_one_bin_at_the_rated_load_for_the_rated_life_sizes_as_the_single_load(housing):
    # ISO 6336-6: one bin at T for L_h hours has D = N_L/N(σ) on the S-N curve the chain's Z_NT (ISO 6336-2 Table
    # 2) and Y_NT (ISO 6336-3 clause 12) are read from, so D <= 1 is S_H >= 1 and S_F >= 1: the two sizings coincide
    # at S_Hmin = S_Fmin = 1
    limits = {"S_Hmin": 1.0, "S_Fmin": 1.0}
    rated = _analysed(None, strength=limits, center_distance=housing)
    life = _analysed(gd.DutyCycle([1.0], [1.0]), single_load=False, strength=limits, center_distance=housing)
    s1, s2 = rated.stages[0]["summary"], life.stages[0]["summary"]
    assert (s1["m"], s1["face_width_mm"], s1["x1"]) == (s2["m"], s2["face_width_mm"], s2["x1"])
    res, r = rated.stages[0]["strength"], life.stages[0]["life"]
    assert r.S_H1 == pytest.approx(res.S_H1, rel=1e-6) and r.S_H2 == pytest.approx(res.S_H2, rel=1e-6)
    assert r.S_F1 == pytest.approx(res.S_F1, rel=1e-6)
    # with the default S_Fmin = 1.4 the single load keeps a 40 % root reserve that D <= 1 does not ask for: the
    # spectrum's sizing is never the larger
    rated = _analysed(None, center_distance=housing).stages[0]["summary"]
    life = _analysed(gd.DutyCycle([1.0], [1.0]), single_load=False, center_distance=housing).stages[0]["summary"]
    assert (life["m"], life["face_width_mm"]) <= (rated["m"], rated["face_width_mm"])


def test_a_load_spectrum_is_the_pinions_loads_whatever_the_flow():
    spec = _by_hand(*DUTY)
    lives = [_analysed(spec, power_kw=p, m=4, face_width_mm=50, life_h=None).stages[0]["life"] for p in (3.0, 7.5)]
    assert lives[0].D_H1 == lives[1].D_H1 and lives[0].required_life_h == spec.duration_h
    duty = [_analysed(gd.DutyCycle(*DUTY), power_kw=p, m=4, face_width_mm=50).stages[0]["life"] for p in (3.0, 7.5)]
    assert duty[0].D_H1 < duty[1].D_H1         # a duty cycle follows the flow


def test_the_search_sizes_by_life_and_its_best_reanalyses():
    def best(k):
        st = gd.GearStage(None, material=MAT, life_h=LIFE, spectrum=gd.DutyCycle(k * np.array(DUTY[0]), DUTY[1]),
                          z1_range=(19, 21), z2_max=80, center_distance="free")
        return gd.Drive(stages=[st], n_in_rpm=N_IN, power_kw=P_KW).optimize(3.5, 0.03, "min_mass", top=3)

    light, heavy = best(1.0), best(2.0)
    for opt in (light, heavy):
        assert opt.success
        again = gd.Drive(stages=opt.best.drive.stages, n_in_rpm=N_IN, power_kw=P_KW).analyse("min_mass")
        assert again.success and again.mass_kg == pytest.approx(opt.best.mass_kg, rel=1e-12)
        assert "pitting_damage1" in set(again.checks["check"]) and again.stages[0]["life"].ok
    assert heavy.best.mass_kg >= light.best.mass_kg


@pytest.mark.parametrize("kw, words", [
    (dict(spectrum=gd.DutyCycle([1.0], [1.0]), life_h=1000), "needs a material"),
    (dict(spectrum=gd.DutyCycle([1.0], [1.0]), material=MAT), "needs life_h"),
    (dict(spectrum=gd.DutyCycle([1.0, -0.5], [0.5, 0.5]), material=MAT, life_h=1e3), "mean_stress_factor"),
    (dict(spectrum=[1.0], material=MAT), "DutyCycle"),
    (dict(single_load=False, material=MAT), "needs a spectrum"),
    (dict(single_load="no", material=MAT), "single_load"),
    (dict(sn_curve="linear", material=MAT), "sn_curve"),
    (dict(mean_stress_factor=0.1, material=MAT), "mean_stress_factor"),
    (dict(spectrum=gd.LoadSpectrum.from_curve([1.0, 1.0], angle_deg=[0, 360], n_rpm=600, teeth=(20, 40)),
          material=MAT), "per tooth"),
])
def test_a_bad_life_case_is_refused_by_name(kw, words):
    with pytest.raises(GearDesignError, match=words):
        gd.GearStage(3, **kw)


def test_one_duty_cycle_loads_each_stage_at_its_own_nominal():
    # two fixed stages: the second's nominal is T_0·u_1·η_1 at n_0/u_1 (the power flow by hand), its bins the
    # factors times that, over the same required life
    q, share = [1.8, 1.0, 0.3], [0.1, 0.6, 0.3]
    duty = gd.DutyCycle(q, share, speed_factor=[1.0, 1.0, 0.5])
    stages = [gd.GearStage(3, 20, 60, material=MAT, life_h=LIFE, spectrum=duty, face_width_mm=40, name="fast"),
              gd.GearStage(5, 19, 57, material=MAT, life_h=LIFE, spectrum=duty, face_width_mm=70, name="slow")]
    an = gd.Drive(stages=stages, n_in_rpm=N_IN, power_kw=P_KW).analyse()
    for k, (T, n) in enumerate([(T_IN, N_IN), (T_IN * 3 * 0.98, N_IN / 3)]):
        s = an.stages[k]["summary"]
        spec = gd.LoadSpectrum.from_bins(np.array(q) * T, np.array([1.0, 1.0, 0.5]) * n, share=share, duration_h=LIFE)
        want = gd.GearPair(s["m"], s["z1"], s["z2"], s["x1"], s["x2"], face_width_mm=s["face_width_mm"]).life(spec, MAT)
        got = an.stages[k]["life"]
        assert [getattr(got, "D_" + m) for m in ("H1", "H2", "F1", "F2")] == pytest.approx(
            [getattr(want, "D_" + m) for m in ("H1", "H2", "F1", "F2")], rel=1e-12)
