"""ISO 6336-6 service life: Miner's sums against the S-N formulas written here, the chain's own life factors,
ISO 6336-6:2019 Annex C (tests/data/iso6336_6_annexC.md) and the part-load case of issue 38."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings, strategies as st

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears.spectrum import LoadSpectrum
from geardesign.gears.strength import Load, Material, pair_strength
from geardesign.gears.strength.service_life import (cycles_to_failure, life_curve, miner_damage, pair_life,
                                                    safety_for_damage, torque_exponent)

DATA = Path(__file__).resolve().parents[2] / "data"
PAIR = gd.GearPair(4, 20, 60, 0.3, 0.1, face_width_mm=40)


def _life(spec, **kw):
    return pair_life(np.float64(PAIR.m), PAIR.z1, PAIR.z2, PAIR.x1, PAIR.x2, spectrum=spec, material1="42CrMo4",
                     face_width_mm=40.0, **kw)


def _chain(T, n=1000.0, life_h=None, **kw):
    return pair_strength(PAIR.m, PAIR.z1, PAIR.z2, PAIR.x1, PAIR.x2, load=Load(torque_nm=T, n_rpm=n, life_h=life_h),
                         material1="42CrMo4", face_width_mm=40.0, **kw)


def _contact_N(r):
    """N of ISO 6336-2:2019 Table 2 for St/V/GGG/GTS/Eh/IF without pitting, written out: Z_NT = 1.6 up to 1e5,
    1.0 at 5e7, 0.85 at 1e10, straight in log-log: N = 5e7·r^(−k) with k = ln(500)/ln 1.6 above the knee,
    5e7·r^(−k2), k2 = ln(200)/ln(1/0.85), below it."""
    if r >= 1.0:
        return 5e7 * r ** (-math.log(500.0) / math.log(1.6))
    return 5e7 * r ** (-math.log(200.0) / math.log(1 / 0.85)) if r > 0.85 else math.inf


def _root_N(r):
    """N of ISO 6336-3:2019 clause 12 for V (through-hardened): Y_NT = 2.5 up to 1e4, 1.0 at 3e6, 0.85 at 1e10."""
    if r >= 1.0:
        return 3e6 * r ** (-math.log(300.0) / math.log(2.5))
    return 3e6 * r ** (-math.log(1e10 / 3e6) / math.log(1 / 0.85)) if r > 0.85 else math.inf


def test_one_bin_miner_sum_is_required_over_endured_cycles():
    """D of a one-bin spectrum = n/N with n = 60·n1·L and N from the S-N formula written above, at the chain's
    stress and stress limit (life factor 1) for that torque."""
    T, n1, L = 300.0, 1000.0, 20000.0
    out = _life(LoadSpectrum.from_bins([T], n1, time_h=[L]))
    ch = _chain(T, n1)
    r_H1 = ch["sigma_H1"] / ch["sigma_HG1"]
    r_F1 = ch["sigma_F1"] / ch["sigma_FG1"]
    assert 1.0 < r_H1 < 1.6      # on the finite-life line
    assert out["D_H1"] == pytest.approx(60 * n1 * L / _contact_N(r_H1), rel=1e-11)
    r_H2 = ch["sigma_H2"] / ch["sigma_HG2"]
    assert out["D_H2"] == pytest.approx(60 * n1 / 3 * L / _contact_N(r_H2), rel=1e-11)
    expect_F1 = 60 * n1 * L / _root_N(r_F1)
    assert out["D_F1"] == pytest.approx(expect_F1, rel=1e-11, abs=1e-300)
    assert out["life_h_H1"] == pytest.approx(L / out["D_H1"], rel=1e-14)


def test_the_life_at_d_equal_one_is_where_the_chains_own_life_factor_gives_s_h_equal_one():
    """Two routes to one number: the hours pair_life finds for D = 1 make the chain's S_H (with its Z_NT of those
    hours and S_Hmin = 1) exactly 1."""
    out = _life(LoadSpectrum.from_bins([300.0], 1000.0, time_h=[1.0]))
    L = out["life_h_H1"]
    ch = _chain(300.0, 1000.0, life_h=L, S_Hmin=1.0)
    assert ch["S_H1"] == pytest.approx(1.0, rel=1e-11)


def test_safety_for_the_required_life_is_the_stress_factor_that_makes_d_one():
    out = _life(LoadSpectrum.from_bins([300.0, 150.0], 1000.0, time_h=[4000.0, 16000.0]))
    ch = [_chain(T) for T in (300.0, 150.0)]
    S = out["S_H1"]
    D = sum(60 * 1000 * t / _contact_N(S * c["sigma_H1"] / c["sigma_HG1"]) for c, t in zip(ch, (4000.0, 16000.0)))
    assert D == pytest.approx(1.0, rel=1e-9)


def test_safety_solver_closed_forms():
    assert safety_for_damage(lambda s: 0.5 * s ** 4) == pytest.approx(2 ** 0.25, rel=1e-12)
    assert safety_for_damage(lambda s: (3.0 * s ** 7, 7.0)) == pytest.approx(3 ** (-1 / 7), rel=1e-12)
    # a kinked damage: a second power law from S = 1.5 on
    f = lambda s: 0.2 * s ** 3 + (0.1 * ((s / 1.5) ** 12 - 1.0) if s > 1.5 else 0.0)  # noqa: E731
    S = safety_for_damage(f)
    assert f(S) == pytest.approx(1.0, rel=1e-9)
    # a damage that jumps over 1 (a bin crossing the end of a horizontal S-N curve): the jump
    assert safety_for_damage(lambda s: 0.5 if s < 1.5 else 2.0) == pytest.approx(1.5, rel=1e-9)
    assert safety_for_damage(lambda s: 1e-30 * s) == 1e3           # beyond the bracket: its end
    assert miner_damage([1e6, 2e6], [1e7, 4e7]) == pytest.approx(0.15, rel=1e-15)


def test_sn_curve_variants_beyond_the_knee():
    pts = life_curve("H", "Eh")
    k = math.log(500.0) / math.log(1.6)
    r = 0.9          # below the knee (f = 1 at 5e7)
    assert float(cycles_to_failure(r, pts, "elementary")) == pytest.approx(5e7 * r ** -k, rel=1e-12)
    assert float(cycles_to_failure(r, pts, "haibach")) == pytest.approx(5e7 * r ** -(2 * k - 1), rel=1e-12)
    assert float(cycles_to_failure(r, pts, "original")) == math.inf
    assert float(cycles_to_failure(r, pts, "iso")) == pytest.approx(_contact_N(r), rel=1e-12)
    assert float(cycles_to_failure(0.8, pts, "iso")) == math.inf
    # above the knee the variants agree
    for v in ("iso", "original", "elementary", "haibach"):
        assert float(cycles_to_failure(1.2, pts, v)) == pytest.approx(_contact_N(1.2), rel=1e-12)
    with pytest.raises(GearDesignError, match="sn_curve"):
        cycles_to_failure(1.0, pts, "miner")


@pytest.mark.parametrize("variant", ["iso", "original", "elementary", "haibach"])
def test_a_stress_not_rated_endures_no_counted_cycles(variant):
    """A NaN ratio (the chain's stress where a caller's unvalidated geometry has no root section) is NaN cycles in
    every variant, so its damage is NaN (the check fails as undefined), never the infinite life of a stress below
    the endurance limit: before the fix (fuzz planetary_spectrum) NaN fell past every point onto the horizontal
    tail, D = 0. The ratios around it keep their values (_contact_N)."""
    pts = life_curve("H", "Eh")
    N = cycles_to_failure(np.array([1.2, np.nan, 0.8]), pts, variant)
    assert math.isnan(N[1]) and N[0] == pytest.approx(_contact_N(1.2), rel=1e-12)
    assert N[2] == math.inf if variant in ("iso", "original") else N[2] > 5e7


def test_torque_exponents_of_annex_a():
    # the stress exponents of the finite-life lines, in torque (contact halves them)
    assert torque_exponent("H", "Eh") == pytest.approx(math.log(500) / math.log(1.6) / 2, rel=1e-14)
    assert torque_exponent("F", "Eh") == pytest.approx(math.log(3000) / math.log(2.5), rel=1e-14)
    assert torque_exponent("F", "V") == pytest.approx(math.log(300) / math.log(2.5), rel=1e-14)


@given(torques=st.lists(st.floats(50.0, 400.0), min_size=1, max_size=4), which=st.integers(0, 3),
       factor=st.floats(1.01, 1.5))
@settings(max_examples=15, deadline=None)
def test_damage_rises_with_every_torque_level(torques, which, factor):
    which %= len(torques)
    hours = [1000.0 * (i + 1) for i in range(len(torques))]
    base = _life(LoadSpectrum.from_bins(torques, 1000.0, time_h=hours), sn_curve="elementary")
    up = list(torques)
    up[which] *= factor
    more = _life(LoadSpectrum.from_bins(up, 1000.0, time_h=hours), sn_curve="elementary")
    for mode in ("H1", "H2", "F1", "F2"):
        assert more["D_" + mode] > base["D_" + mode]


def test_each_bin_has_its_own_load_dependent_factors():
    """Issue 38: GearPair(6, 27, 72, 0.52, 0.03, b = 67.6) at 4547 rpm has S_F1 4.1355 at 400 N·m and 4.1415 at
    800 N·m (K_v falls steeply with the load below ~100 N/mm): the spectrum's bins carry their own K_v, K_Hβ,
    K_Hα, so its 400 N·m bin is rated at 400 N·m's factors, not at the rated torque's scaled down."""
    p = gd.GearPair(6, 27, 72, 0.52, 0.03, face_width_mm=67.6)
    single = {T: p.strength(Load(torque_nm=T, n_rpm=4547), "42CrMo4") for T in (400.0, 800.0)}
    assert single[400.0].S_F1 < single[800.0].S_F1            # the part load is the weaker case
    spec = LoadSpectrum.from_bins([400.0, 800.0], 4547, time_h=[1000.0, 1000.0])
    out = pair_life(np.float64(p.m), p.z1, p.z2, p.x1, p.x2, spectrum=spec, material1="42CrMo4",
                    face_width_mm=67.6, geometry=p._geo, bins=True, sn_curve="elementary")
    kv = out["bin_K_v"]
    assert kv[0] > kv[1]
    assert kv[0] == pytest.approx(single[400.0].factors.set_index("symbol").loc["K_v", "value"], rel=1e-12)
    assert out["bin_sigma_F1"][0] == pytest.approx(single[400.0].sigma_F1, rel=1e-12)
    # the damage with the rated bin's factors scaled to 400 N·m (σ_F ∝ T) would be smaller: per-bin factors matter
    scaled = out["bin_sigma_F1"][1] / 2.0
    assert out["bin_sigma_F1"][0] > scaled * 1.0005
    pts = life_curve("F", "V")
    ref = out["bin_sigma_FG1"]
    n = out["n1"]
    d_scaled = n[0] / cycles_to_failure(scaled / ref[0], pts, "elementary") + n[1] / out["N_F1"][1]
    assert out["D_F1"] > d_scaled


def test_alternating_bending_needs_the_mean_stress_factor():
    spec = LoadSpectrum.from_bins([300.0, -300.0], 1000.0, time_h=[10000.0, 10000.0])
    with pytest.raises(GearDesignError, match="mean_stress_factor"):
        _life(spec)
    with pytest.raises(GearDesignError, match="mean_stress_factor must be in"):
        _life(spec, mean_stress_factor=1.5)
    out = _life(spec, mean_stress_factor=0.7)
    ch = _chain(300.0)
    # each flank: one bin; the root's limit times Y_M = 0.7 (its tooth bends both ways)
    r = ch["sigma_F1"] / (0.7 * ch["sigma_FG1"])
    assert out["D_F1"] == pytest.approx(60 * 1000 * 10000 / _root_N(r), rel=1e-11)
    # pitting: each flank its own damage; both flanks alike here, so one flank's sum
    assert out["D_H1"] == pytest.approx(60 * 1000 * 10000 / _contact_N(ch["sigma_H1"] / ch["sigma_HG1"]), rel=1e-11)


def test_a_per_tooth_spectrum_rates_the_most_loaded_tooth():
    phi = np.linspace(0.0, 720.0, 721)
    T = 150.0 + 200.0 * np.exp(-(phi / 4.0) ** 2) + 200.0 * np.exp(-((phi - 720.0) / 4.0) ** 2)
    spec = LoadSpectrum.from_curve(T, angle_deg=phi, n_rpm=1000, teeth=(20, 60), levels=200)
    out = _life(spec, life_h=20000.0, sn_curve="elementary")
    # tooth 0 of gear 1 meets the 350 N·m peak once per 720° and 150 N·m once: its Miner sum is the largest
    hours = 20000.0
    cycles_per_tooth = 1000 / 2 * 60 * hours          # one mesh of each tooth per crank cycle at each of φ, φ+360
    ch = {Tq: _chain(Tq) for Tq in (350.0, 150.0)}
    pts = life_curve("H", "V")
    expect = sum(cycles_per_tooth / float(cycles_to_failure(ch[Tq]["sigma_H1"] / ch[Tq]["sigma_HG1"], pts,
                                                            "elementary")) for Tq in (350.0, 150.0))
    assert out["D_H1"] == pytest.approx(expect, rel=2e-3)     # the classes' ends: 0.5 % of the range


def test_arrays_of_designs_are_the_designs_one_by_one():
    spec = LoadSpectrum.from_bins([300.0, 150.0], 1000.0, time_h=[4000.0, 16000.0])
    x1 = np.array([0.1, 0.3, 0.5])
    out = pair_life(4.0, 20, 60, x1, 0.1, spectrum=spec, material1="42CrMo4", face_width_mm=40.0)
    for i, x in enumerate(x1):
        one = pair_life(np.float64(4.0), 20, 60, float(x), 0.1, spectrum=spec, material1="42CrMo4",
                        face_width_mm=40.0)
        for mode in ("H1", "H2", "F1", "F2"):
            assert out["D_" + mode][i] == pytest.approx(one["D_" + mode], rel=1e-12, abs=1e-300)


@pytest.mark.parametrize("kwargs, words", [
    (dict(spectrum="x"), "spectrum must be a geardesign LoadSpectrum"),
    (dict(sn_curve="miner"), "sn_curve"),
    (dict(life_h=-1.0), "life_h must be in"),
    (dict(root=False), "root=False"),
])
def test_bad_inputs_are_refused(kwargs, words):
    args = dict(spectrum=LoadSpectrum.from_bins([300.0], 1000.0, time_h=[1.0]))
    args.update(kwargs)
    with pytest.raises(GearDesignError) as e:
        pair_life(np.float64(4.0), 20, 60, 0.3, 0.1, material1="42CrMo4", face_width_mm=40.0, **args)
    assert words in str(e.value)


# ---- ISO 6336-6:2019 Annex C (tests/data/iso6336_6_annexC.md) ----------------------------------------------

def _figure():
    return pd.read_csv(DATA / "iso6336_6_annexC_fig_c1.csv")


def test_annex_c_sn_curve_is_the_z_nt_line_of_part_2():
    f = _figure()
    N, s = f["N_SN"].to_numpy(), f["sigma_SN"].to_numpy()
    knee = float(np.interp(math.log(5e7), np.log(N), s))
    pts = life_curve("H", "Eh")
    from geardesign.gears.strength.life import contact_life_factor

    for n_at in (1e3, 1e5, 1e6, 1e7, 1e8, 1e9, 9e9):
        digitised = float(np.interp(math.log(n_at), np.log(N), s)) / knee
        assert digitised == pytest.approx(float(contact_life_factor(n_at, "Eh")), rel=0.01)
    assert pts[0] == (1e5, 1.6)


def test_annex_c_miner_safety_of_the_figures_spectrum():
    """Figure C.1's stress spectrum (digitised stairs) on its S-N curve (the Z_NT line at the digitised knee level)
    reaches D = 1 at the factor between the figure's two spectra, 2353/1842."""
    f = _figure()
    knee = float(np.interp(math.log(5e7), np.log(f["N_SN"]), f["sigma_SN"]))
    pts = life_curve("H", "Eh")

    def stairs(col):
        N, s = f["N_" + col].to_numpy(), f["sigma_" + col].to_numpy()
        N, s = N[N > 0], s[N > 0]
        dN = np.diff(N)
        return dN[dN > 0], s[:-1][dN > 0]

    n, sigma = stairs("H2")
    S = safety_for_damage(lambda k: float(np.sum(n / cycles_to_failure(k * sigma / knee, pts))))
    ratio = f["sigma_H1"].max() / f["sigma_H2"].max()
    assert S == pytest.approx(ratio, rel=0.01)
    n1, sigma1 = stairs("H1")
    assert float(np.sum(n1 / cycles_to_failure(sigma1 / knee, pts))) == pytest.approx(1.0, abs=0.1)


def test_annex_c_whole_chain_pitting_safety_of_the_pinion():
    """The example's pair under Table 4 over 30 years: the pinion's pitting safety within 3 % of Figure C.1's
    2353/1842 (the inputs the transcription lacks: tests/data/iso6336_6_annexC.md)."""
    t = pd.read_csv(DATA / "iso6336_6_annexC_table4.csv")
    mat = Material("case-hardened (Annex C)", "Eh", 206000, 0.3, 700, "HV", 1500.0, 500.0, "MQ", "ISO 6336-6 Annex C")
    rack = gd.BasicRack(alpha_deg=25, ha=1.0, c=0.4, rho_f=0.2)
    pair = gd.GearPair(8.467, 17, 60, 0.172, 0.0015, rack=rack, beta_deg=15.5, face_width_mm=152.4)
    assert pair.geometry().a_w == pytest.approx(339.727, abs=0.02)
    spec = LoadSpectrum.from_bins(t["Torque_Max_Nm"], 35.2, time_h=t["time_h"])
    r = pair.life(spec, mat, life_h=30 * 365.25 * 24, accuracy_grade=6, tip_relief_um=70, bore_ratio=(0.5, 0.5))
    f = _figure()
    assert r.S_H1 == pytest.approx(f["sigma_H1"].max() / f["sigma_H2"].max(), rel=0.03)
    # the top bin's contact stress is the figure's top level to 3 %, its cycles summing to the figure's 6.0e5
    top = r.bins.iloc[0]
    assert top["sigma_H1"] == pytest.approx(f["sigma_H2"].max(), rel=0.03)
    assert r.bins["n1"].sum() == pytest.approx(6.0e5, rel=0.01)


@pytest.mark.parametrize("sn_curve", ["iso", "original", "elementary", "haibach"])
def test_safety_factors_of_all_modes_at_once_are_each_modes_own(sn_curve):
    """pair_life solves the four safety factors together; each equals the one-row solver's S on the damage sum
    written from cycles_to_failure (per flank, a reversing spectrum with Y_M)."""
    spec = LoadSpectrum.from_bins([300.0, 200.0, -150.0, 80.0], 1000.0, time_h=[500.0, 3000.0, 2000.0, 9000.0])
    out = pair_life(np.float64(4.0), 20, 60, 0.3, 0.1, spectrum=spec, material1="42CrMo4", face_width_mm=40.0,
                    sn_curve=sn_curve, mean_stress_factor=0.8, bins=True)
    for mode in ("H1", "H2", "F1", "F2"):
        g = int(mode[1])
        r, n = out["ratio"][mode], out[f"n{g}"]
        flank = spec.torque_nm[out["bin_index"]] < 0

        def D(S, r=r, n=n, mode=mode):
            d = n / cycles_to_failure(S * r, out["curves"][mode], sn_curve)
            return max(d[~flank].sum(), d[flank].sum())

        S = out["S_" + mode]
        assert S == pytest.approx(safety_for_damage(D), rel=1e-8)
        # D reaches 1 at S (or jumps over it there: a bin crossing a horizontal curve's knee or end)
        assert D(S * (1 - 1e-7)) < 1.0 <= D(S * (1 + 1e-7))


def test_many_designs_run_in_chunks_with_the_same_answers(monkeypatch):
    from geardesign.gears.strength import service_life as sl

    spec = LoadSpectrum.from_bins([300.0, 150.0, 75.0], 1000.0, time_h=[4000.0, 16000.0, 1.0])
    x1 = np.linspace(0.1, 0.5, 7).reshape(7, 1)
    x2 = np.array([0.0, 0.1])
    whole = pair_life(4.0, 20, 60, x1, x2, spectrum=spec, material1="42CrMo4", face_width_mm=40.0)
    monkeypatch.setattr(sl, "_ELEMENTS", 7)            # 2 designs (of 3 bins) a chunk
    parts = pair_life(4.0, 20, 60, x1, x2, spectrum=spec, material1="42CrMo4", face_width_mm=40.0)
    for mode in ("H1", "H2", "F1", "F2"):
        assert parts["D_" + mode].shape == (7, 2)
        assert np.allclose(parts["D_" + mode], whole["D_" + mode], rtol=1e-12, atol=0)


def test_grouped_max_is_the_largest_group_sum():
    """Regression (the per-tooth spectra of an engine: a matrix product over 442 bins cost ~10 ms a call): the
    largest sum over the bins of one group, infinite where a bin of the group endures no cycle."""
    from geardesign.gears.strength.service_life import _grouped_max

    rng = np.random.default_rng(7)
    d = rng.random((4, 30))
    groups = rng.integers(0, 6, 30)
    d[2, 5] = np.inf
    expected = [max(d[i, groups == g].sum() for g in set(groups.tolist())) for i in range(4)]
    np.testing.assert_allclose(_grouped_max(d, groups), expected, rtol=1e-13)
    assert _grouped_max(d, groups)[2] == np.inf
    assert _grouped_max(d[0], np.zeros(30, dtype=np.int64)) == pytest.approx(d[0].sum(), rel=1e-13)


@pytest.mark.parametrize("m, match", [({"a": 1}, r"m must be a number, got \{'a': 1\}"),
                                      ([[1], [2, 3]], r"m must be a number, got \[\[1\], \[2, 3\]\]"),
                                      ([4.0, 5.0, 6.0], "do not broadcast")])
def test_pair_life_refuses_designs_without_a_shape_by_name(m, match):
    """Fuzzing found TypeError / ValueError tracebacks for a dict or a ragged list as the module (read for its
    shape before any check) and for designs whose shapes do not broadcast."""
    spec = LoadSpectrum.from_bins([241.0], 1000.0, time_h=[100.0])
    with pytest.raises(GearDesignError, match=match):
        pair_life(m, [20, 21], 80, 0.3, 0.1, spectrum=spec, material1="42CrMo4", face_width_mm=20.0)


def test_pair_life_refuses_an_empty_list_of_teeth_by_name():
    """Fuzzing found 'ValueError: zero-size array to reduction operation maximum' for z1=[]."""
    spec = LoadSpectrum.from_bins([241.0], 1000.0, time_h=[100.0])
    with pytest.raises(GearDesignError, match="z1 and z2 must each give a tooth count, got 0 and 1 values"):
        pair_life(20.0, [], 26, 0.3, 0.1, spectrum=spec, material1="42CrMo4", face_width_mm=40.0)


def test_one_design_in_numbers_is_the_array_call_of_one_design():
    """One design in Python floats (the chain's pair-wide factors on math, the bins' on numpy) against the same
    design as a one-element array (numpy throughout): the damage sums, lives and bins agree to the last few ulps
    (D ∝ σ^13: an ulp of σ is ~13 ulps of D), on a spectrum counted per tooth with both flanks loaded."""
    phi = np.linspace(0, 720, 721)
    T = 300 + 500 * np.exp(-((phi - 20) / 15) ** 2) - 150 * np.exp(-((phi - 380) / 30) ** 2)
    spec = LoadSpectrum.from_curve(T, angle_deg=phi, n_rpm=1700, teeth=(20, 60), levels=24)
    kw = dict(spectrum=spec, material1="42CrMo4", material2="C45", face_width_mm=40.0, sn_curve="haibach",
              mean_stress_factor=0.7, life_h=4000.0, bins=True)
    one = pair_life(4.0, 20, 60, 0.3, 0.1, **kw)
    arr = pair_life(np.array([4.0]), 20, 60, np.array([0.3]), np.array([0.1]), **kw)
    for mode in ("H1", "H2", "F1", "F2"):
        assert one["D_" + mode] > 0
        assert one["D_" + mode] == pytest.approx(float(arr["D_" + mode][0]), rel=1e-13)
        assert one["life_h_" + mode] == pytest.approx(float(arr["life_h_" + mode][0]), rel=1e-13)
        np.testing.assert_allclose(one["N_" + mode], arr["N_" + mode][0], rtol=1e-13)
    for k in ("K_v", "K_Hbeta", "sigma_H1", "sigma_F2", "sigma_FG1"):
        np.testing.assert_allclose(one["bin_" + k], arr["bin_" + k][0], rtol=1e-14)


def test_pair_life_takes_a_mesh_too():
    # issue 36 §4: pair_life restated the mesh keywords without taking a Mesh (as pair_strength did before); the
    # mesh's face width is the pair's, and the results are the loose call's bit for bit (spur and helical, one
    # design and arrays, a reversing spectrum with Y_M)
    spec = LoadSpectrum.from_bins([700, -400], 1000, time_h=[2000, 8000])
    for beta in (0.0, 12.0):
        mesh = gd.Mesh(20, 60, beta_deg=beta, face_width_mm=30.0)
        for m, x1 in ((3.0, 0.3), (np.array([2.5, 3.0]), np.array([0.2, 0.4]))):
            loose = pair_life(m, 20, 60, x1, 0.1, spectrum=spec, material1="42CrMo4", face_width_mm=30.0,
                              beta_deg=beta, mean_stress_factor=0.7)
            meshed = pair_life(m, x1=x1, x2=0.1, spectrum=spec, material1="42CrMo4", mesh=mesh,
                               mean_stress_factor=0.7)
            keys = ("D_H1", "D_H2", "D_F1", "D_F2") + (("S_H1", "S_F2") if np.ndim(m) == 0 else ())
            for k in keys:
                assert np.array_equal(np.asarray(meshed[k]), np.asarray(loose[k])), k
            assert np.all(np.asarray(loose["D_F1"]) > 0)


@pytest.mark.parametrize("kw, words", [
    (dict(mesh=gd.Mesh(20, 60)), "face_width_mm .* is needed"),
    (dict(z1=20, z2=60), "face_width_mm .* is needed"),
    (dict(mesh=gd.Mesh(20, 60, face_width_mm=30.0), face_width_mm=30.0), "face_width_mm, not both"),
    (dict(mesh=gd.Mesh(20, 60, face_width_mm=30.0), beta_deg=10.0), "beta_deg, not both"),
    (dict(mesh=gd.Mesh(20, 60, face_width_mm=30.0), z1=20), "z1, not both"),
    (dict(mesh=(20, 60)), "mesh must be a geardesign.Mesh"),
    (dict(face_width_mm=30.0), "z1 and z2"),
])
def test_pair_life_mesh_refusals_name_the_input(kw, words):
    spec = LoadSpectrum.from_bins([120, 60], 1000, time_h=[2000, 8000])
    with pytest.raises(GearDesignError, match=words):
        pair_life(3.0, x1=0.3, x2=0.1, spectrum=spec, material1="42CrMo4", **kw)


def test_an_alternating_gear_bends_both_ways_in_every_bin():
    # an idler or a planet: its teeth meet two mates on opposite flanks, so its root's limit is times Y_M
    # (ISO 6336-3:2019's alternating bending) even under a one-sided spectrum; the other gear is rated one-sided
    spec = LoadSpectrum.from_bins([800.0], 1000.0, time_h=[10000.0])
    with pytest.raises(GearDesignError, match="gear 2's root bends both ways .*mean_stress_factor"):
        _life(spec, alternating=(False, True))
    with pytest.raises(GearDesignError, match="alternating must be two booleans"):
        _life(spec, alternating=True, mean_stress_factor=0.7)
    out = _life(spec, alternating=(False, True), mean_stress_factor=0.7)
    ch = _chain(800.0)
    n2 = 1000 * 60 * 10000 * 20 / 60                  # the wheel's revolutions
    assert out["D_F2"] == pytest.approx(n2 / _root_N(ch["sigma_F2"] / (0.7 * ch["sigma_FG2"])), rel=1e-11)
    assert out["D_F1"] == pytest.approx(60 * 1000 * 10000 / _root_N(ch["sigma_F1"] / ch["sigma_FG1"]), rel=1e-11)
    # σ_F2/σ_FG2 ≈ 0.65 lies below the curve's end (0.85): no damage one-sided, some with the limit times 0.7
    assert out["D_F2"] > 0.0 == _life(spec)["D_F2"]


def test_a_vanishing_speed_gives_an_infinite_life_without_a_warning():
    """Fuzzing found 'RuntimeWarning: overflow encountered in scalar divide' from pair_life for a spectrum at
    n = 5e-324 rpm: a subnormal damage D = n·t/N, whose life t/D is +inf (nothing loads the teeth)."""
    import warnings

    s = gd.LoadSpectrum.from_bins(torque_nm=[665.2], n_rpm=5e-324, time_h=[20000.0])
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        r = pair_life(2.0, 17, 200, 0.3, 0.1, spectrum=s, material1="18CrNiMo7-6", face_width_mm=400.0,
                      mean_stress_factor=1.0)
    assert all(r[f"life_h_{k}"] == np.inf for k in ("H1", "H2", "F1", "F2"))
    assert 0.0 <= r["D_H1"] < 1e-300
