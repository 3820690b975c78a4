"""DIN 743 safety: the exam cases with printed safeties (tests/data/din743_exam_cases.md), the factor formulas
against hand arithmetic, a thicker shaft never less safe (hypothesis), the least diameter (the command: tests/cli/test_shaft.py)."""
import math

import pytest
from hypothesis import given, settings, strategies as st

from geardesign.drives import din743
from geardesign.drives.din743 import Notch, ShaftNotch, din743_safety, least_diameter_mm, shaft_safety
from geardesign.drives.shaft_beam import ShaftLoad, ShaftModel, analyse_shaft
from geardesign.errors import GearDesignError


def test_exam_2024W_1_shoulder_load_case_1():
    """MEL1 2024W task 1 (tests/data/din743_exam_cases.md): S_D = 2.373, S_F = 1.464."""
    r = din743_safety("50CrMo4", Notch("shoulder", r_mm=4.0), d_mm=84.0, D_mm=100.0, d_eff_mm=100.0, Rz_um=10.0,
                      load_case=1, F_zdm=443341.5553, F_zdmax=443341.5553, M_bm=23275.43165, M_ba=2909.428956,
                      M_bmax=26184.86061, T_m=13965.25899, T_max=13965.25899)
    assert round(r.S_D, 3) == 2.373
    assert round(r.S_F, 3) == 1.464


def test_exam_2024W_2_key_seat_load_case_2():
    """MEL1 2024W task 2: S_D = 1.472, S_F = 2.568."""
    r = din743_safety("C50", Notch("key"), d_mm=60.0, d_eff_mm=80.0, Rz_um=25.0, hard_surface=True,
                      M_ba=1402.294, T_m=1336.902, M_bmax=1.8 * 1402.294, T_max=1.8 * 1336.902)
    assert round(r.S_D, 3) == 1.472
    assert round(r.S_F, 3) == 2.568


def test_key_seat_by_hand():
    """The key-seat chain by hand (DIN 743-2 Table 1, eqs. (10), (16), (17); DIN 743-1 eqs. (6), (7)) for a
    pure reversed bending: S_D = σ_bWK/σ_ba."""
    d = 40.0
    r = din743_safety("42CrMo4", Notch("key"), d_mm=d, d_eff_mm=16.0, M_ba=300.0)
    sB = 1100.0                                          # K1 = 1 at d_eff = d_B = 16 mm
    beta = 3.0 * (sB / 1000) ** 0.38                     # at d_BK = 40 = d: K3 ratio 1
    K2 = 1 - 0.2 * math.log10(d / 7.5) / math.log10(20)
    K = beta / K2                                        # K_F = 1 for key seats, K_V = 1
    sigma_bWK = 0.5 * sB / K
    sigma_ba = 300e3 / (math.pi * d ** 3 / 32)
    assert r.S_D == pytest.approx(sigma_bWK / sigma_ba, rel=1e-12)
    # static: σ_bFK = K1S K2F γF σ_S = 1 · 1.2 · 1 · 900
    assert r.S_F == pytest.approx(1.2 * 900.0 / sigma_ba, rel=1e-12)


@settings(max_examples=60, deadline=None)
@given(st.floats(15, 120), st.floats(1.01, 1.6), st.sampled_from(["smooth", "key", "press_fit", "shoulder"]),
       st.floats(0, 2000), st.floats(0, 3000), st.floats(0, 50000), st.sampled_from([1, 2]))
def test_thicker_is_never_less_safe(d, grow, kind, M, T, N, case):
    notch = Notch(kind, r_mm=1.5 if kind == "shoulder" else None)

    def s(dd):
        kw = dict(D_mm=dd * 1.2) if kind == "shoulder" else {}
        r = din743_safety("C45", notch, d_mm=dd, d_eff_mm=200.0, M_ba=M, T_m=T, F_zdm=N, load_case=case, **kw)
        return r.S_D, r.S_F

    (a_d, a_f), (b_d, b_f) = s(d), s(d * grow)
    assert b_d >= a_d * (1 - 1e-12) and b_f >= a_f * (1 - 1e-12)


def test_least_diameter_reaches_s_min():
    d = least_diameter_mm("42CrMo4", Notch("key"), M_ba=500.0, T_m=800.0)
    at = din743_safety("42CrMo4", Notch("key"), d_mm=d, M_ba=500.0, T_m=800.0)
    below = din743_safety("42CrMo4", Notch("key"), d_mm=d - 0.01, M_ba=500.0, T_m=800.0)
    assert min(at.S_D, at.S_F) >= 1.2 > min(below.S_D, below.S_F)


def _shaft():
    return ShaftModel([(40.0, 35.0), (40.0, 40.0), (120.0, 45.0), (40.0, 40.0), (40.0, 35.0)], [20.0, 260.0],
                      [ShaftLoad(140.0, fy_n=-3000.0, fz_n=1100.0, fx_n=800.0, y_mm=60.0, torque_nm=120.0),
                       ShaftLoad(280.0, fz_n=-1500.0, torque_nm=-120.0)])


def test_shaft_safety_and_least_scale():
    an = analyse_shaft(_shaft())
    notches = [ShaftNotch(140.0, Notch("key")), ShaftNotch(80.0, Notch("shoulder", r_mm=1.6))]
    s = shaft_safety(an, notches, "42CrMo4")
    row = s.table.iloc[0]
    assert row["d_mm"] == 45.0 and row["T_nm"] == pytest.approx(120.0)
    # the moment there is the diagram's resultant at x = 140
    assert row["M_nm"] == pytest.approx(an.diagrams.loc[an.diagrams["x_mm"] == 140.0, "M_nm"].max())
    k = din743.least_shaft_scale(_shaft(), notches, "42CrMo4")
    m = _shaft().with_diameters(k)
    sn = [ShaftNotch(140.0, Notch("key")), ShaftNotch(80.0, Notch("shoulder", r_mm=1.6 * k))]
    t = shaft_safety(analyse_shaft(m), sn, "42CrMo4").table
    assert (t[["S_D", "S_F"]].min(axis=1).min()) == pytest.approx(1.2, rel=2e-3)


def test_bad_inputs():
    with pytest.raises(GearDesignError, match="material"):
        din743_safety("unobtainium", d_mm=40.0)
    with pytest.raises(GearDesignError, match="beta_sigma"):
        Notch("given")
    with pytest.raises(GearDesignError, match="d/D <= 0.98"):
        din743_safety("C45", Notch("shoulder", r_mm=1.0), d_mm=40.0, D_mm=40.5)


def test_material_as_a_dict_is_checked():
    mine = {"kind": "quenched_tempered", "sigma_B_mpa": 700.0, "sigma_S_mpa": 490.0, "d_B_mm": 16.0}
    assert din743_safety(mine, d_mm=40, M_ba=100).S_D == din743_safety("C45", d_mm=40, M_ba=100).S_D
    with pytest.raises(GearDesignError, match="d_B_mm"):
        din743_safety({"kind": "quenched_tempered", "sigma_B_mpa": 700.0, "sigma_S_mpa": 490.0}, d_mm=40)
    with pytest.raises(GearDesignError, match="sigma_S_mpa must be below"):
        din743_safety({**mine, "sigma_S_mpa": 800.0}, d_mm=40)


def test_least_diameter_of_a_shoulder_keeps_its_shape():
    d = least_diameter_mm("C45", Notch("shoulder", r_mm=1.0), D_over_d=1.2, r_over_d=0.05, M_ba=400.0, T_m=300.0)
    at = din743_safety("C45", Notch("shoulder", r_mm=0.05 * d), d_mm=d, D_mm=1.2 * d, M_ba=400.0, T_m=300.0)
    assert min(at.S_D, at.S_F) == pytest.approx(1.2, abs=1e-3)
    with pytest.raises(GearDesignError, match="D_over_d and r_over_d"):
        least_diameter_mm("C45", Notch("shoulder", r_mm=1.0), M_ba=400.0)


def test_key_seat_torsion_by_hand():
    """Alternating torsion alone (the exam cases have no torsion amplitude): S_D = τ_tWK/τ_ta with
    β_τ = 0.56·β_σ + 0.1 (DIN 743-2 Table 1), K_τ = β_τ/K_2, τ_tWK = 0.3·σ_B/K_τ; d = d_BK = 40 mm, d_eff = 16 mm."""
    d, T = 40.0, 400.0
    r = din743_safety("34CrNiMo6", Notch("key"), d_mm=d, d_eff_mm=16.0, T_a=T)
    sB = 1200.0
    beta_t = 0.56 * 3.0 * (sB / 1000) ** 0.38 + 0.1
    K2 = 1 - 0.2 * math.log10(d / 7.5) / math.log10(20)
    tau_WK = 0.3 * sB / (beta_t / K2)
    tau_a = T * 1000 / (math.pi * d ** 3 / 16)
    assert r.S_D == pytest.approx(tau_WK / tau_a, rel=1e-12)


def test_notch_between_nodes_takes_the_exact_moment():
    """Simply supported, F at a: M(x) = F (l − a) x / l left of the load (Shigley Table A-9-6); the key seat at
    an x that is no node of the diagrams gets that moment, and the stress σ_ba = 32 M/(π d³)."""
    F, span, a, d = 5000.0, 300.0, 200.0, 40.0
    an = analyse_shaft(ShaftModel([(span, d)], [0.0, span], [ShaftLoad(a, fy_n=-F)]), points=10)
    x = 123.456
    s = shaft_safety(an, [ShaftNotch(x, Notch("key"))], "C45")
    assert s.table["M_nm"].iloc[0] == pytest.approx(F * (span - a) * x / span / 1000, rel=1e-12)


def test_hollow_shaft_stress_and_deflection():
    """A bore lowers I to π(d⁴ − d_i⁴)/64 (deflection F L³/(48 E I), Shigley Table A-9-5) and raises the stress."""
    F, L, d, di = 2000.0, 400.0, 50.0, 30.0
    an = analyse_shaft(ShaftModel([(L, d, di)], [0.0, L], [ShaftLoad(L / 2, fz_n=F)]))
    I_mm4 = math.pi * (d ** 4 - di ** 4) / 64
    assert an.max_deflection_mm == pytest.approx(F * L ** 3 / (48 * 210000.0 * I_mm4), rel=1e-9)
    solid = din743_safety("C45", d_mm=d, M_ba=100.0)
    hollow = din743_safety("C45", d_mm=d, bore_mm=di, M_ba=100.0)
    assert hollow.S_D < solid.S_D


def test_press_fit_and_given_notch_by_hand():
    """Press fit at d = d_BK = 40 mm (DIN 743-2 Table 1: β_σ = 2.7·(σ_B/1000)^0.43, K_F = 1) and a notch whose β
    the user gives: S_D = σ_bWK/σ_ba with K = β/K_2 (+ 1/K_F − 1 for the given notch, R_z = 1: K_F = 1)."""
    d, M = 40.0, 250.0
    K2 = 1 - 0.2 * math.log10(d / 7.5) / math.log10(20)
    sigma_ba = M * 1000 / (math.pi * d ** 3 / 32)
    r = din743_safety("42CrMo4", Notch("press_fit"), d_mm=d, d_eff_mm=16.0, M_ba=M)
    beta = 2.7 * 1.1 ** 0.43
    assert r.S_D == pytest.approx(0.5 * 1100 / (beta / K2) / sigma_ba, rel=1e-12)
    g = din743_safety("42CrMo4", Notch("given", beta_sigma=2.2, beta_tau=1.6), d_mm=d, d_eff_mm=16.0, Rz_um=1.0,
                      M_ba=M)
    assert g.S_D == pytest.approx(0.5 * 1100 / (2.2 / K2) / sigma_ba, rel=1e-12)


def test_round_groove_by_hand():
    """Round groove (DIN 743-2 Table 2, bending: A = 0.2, B = 2.75, C = 0; G' = 2(1 + φ)/r with φ = 1/(4√(t/r) + 2)
    for d/D > 0.67; n = 1 + √G'·10^−(0.33 + σ_S(d)/712)): β = α/n."""
    d, D, r = 45.0, 50.0, 1.0
    t = (D - d) / 2
    alpha = 1 + 1 / math.sqrt(0.2 * r / t + 2 * 2.75 * r / d * (1 + 2 * r / d) ** 2)
    assert din743.stress_concentration("groove", d, D, r, "bending") == pytest.approx(alpha, rel=1e-14)
    phi = 1 / (4 * math.sqrt(t / r) + 2)
    n = 1 + math.sqrt(2 * (1 + phi) / r) * 10 ** -(0.33 + 490.0 / 712)     # C45, d_eff = 16: σ_S(d) = 490
    res = din743_safety("C45", Notch("groove", r_mm=r, t_mm=t), d_mm=d, d_eff_mm=16.0, M_ba=100.0)
    beta_b = res.factors.set_index("symbol").loc["beta", "bending"]
    assert beta_b == pytest.approx(alpha / n, rel=1e-12)


def test_one_pass_over_a_shaft_equals_one_section_at_a_time():
    """shaft_safety runs the chain over all sections at once (mixed kinds: key seat, press fit, shoulder, groove,
    smooth, given β); each row must equal din743_safety of that section alone, with the loads read here from the
    diagrams at x (their larger limit at a node), to 1e-12, on random shafts and options."""
    import numpy as np

    rng = np.random.default_rng(743)
    for k in range(25):
        secs = [(60.0, 40.0), (90.0, 52.0), (60.0, 40.0), (40.0, 34.0)]
        loads = [ShaftLoad(105.0, fy_n=float(rng.normal(0, 4000)), fz_n=float(rng.normal(0, 4000)),
                           fx_n=float(rng.normal(0, 900)), y_mm=60.0, torque_nm=200.0),
                 ShaftLoad(230.0, fy_n=float(rng.normal(0, 500)), torque_nm=-200.0)]
        an = analyse_shaft(ShaftModel(secs, [30.0, 180.0], loads), points=30)
        notches = [ShaftNotch(105.0, Notch("key", keys=int(rng.integers(1, 3)))),
                   ShaftNotch(60.0, Notch("shoulder", r_mm=float(rng.uniform(0.8, 3.0)))),
                   ShaftNotch(150.0, Notch("shoulder", r_mm=1.2)),
                   ShaftNotch(210.0, Notch("shoulder", r_mm=1.0)),
                   ShaftNotch(230.0, Notch("press_fit")),
                   ShaftNotch(80.0, Notch("groove", r_mm=1.0, t_mm=1.5)),
                   ShaftNotch(125.0, Notch("smooth")),
                   ShaftNotch(40.0, Notch("given", beta_sigma=2.1, beta_tau=1.6, alpha_sigma=2.4))]
        opts = dict(peak_factor=float(rng.uniform(1, 2.5)), torque_amplitude=float(rng.uniform(0, 0.5)),
                    hard_surface=bool(k % 3 == 0), load_case=1 + k % 2, Rz_um=float(rng.uniform(1, 25)))
        s = shaft_safety(an, notches, ["C45", "42CrMo4", "16MnCr5"][k % 3], **opts)
        d = an.diagrams
        for row, sn in zip(s.table.itertuples(), notches):
            at = d[d["x_mm"] == sn.x_mm]
            if len(at):
                M, T = at["M_nm"].max(), at["T_nm"].abs().max()
                N = at["N_n"].to_numpy()[np.argmax(np.abs(at["N_n"].to_numpy()))]
            else:
                M, T, N = (np.interp(sn.x_mm, d["x_mm"], d[c]) for c in ("M_nm", "T_nm", "N_n"))
                T = abs(T)
            dl, dr = an.model.diameter_at(sn.x_mm, "left")[0], an.model.diameter_at(sn.x_mm, "right")[0]
            kind = sn.notch.kind
            dd = dr - 2 * sn.notch.t_mm if kind == "groove" else min(dl, dr)
            D = max(dl, dr) if kind == "shoulder" else (dr if kind == "groove" else None)
            one = din743_safety(["C45", "42CrMo4", "16MnCr5"][k % 3], sn.notch, d_mm=dd, D_mm=D, d_eff_mm=52.0,
                                Rz_um=opts["Rz_um"], hard_surface=opts["hard_surface"], load_case=opts["load_case"],
                                F_zdm=N, M_ba=M, T_m=T, T_a=opts["torque_amplitude"] * T,
                                F_zdmax=opts["peak_factor"] * abs(N), M_bmax=opts["peak_factor"] * M,
                                T_max=opts["peak_factor"] * T * (1 + opts["torque_amplitude"]))
            assert row.S_D == pytest.approx(one.S_D, rel=1e-12) and row.S_F == pytest.approx(one.S_F, rel=1e-12)
            assert s.results[row.Index].factors.equals(one.factors)


@pytest.mark.parametrize("kw, match", [(dict(Rz_um=__import__("numpy").array([])), "Rz_um must be one number"),
                                       (dict(Rz_um=[6.3, 6.3]), "Rz_um must be one number"),
                                       (dict(peak_factor=[1.0, 2.0]), "peak_factor must be one number"),
                                       (dict(torque_amplitude=[0.1]), "torque_amplitude must be one number"),
                                       (dict(K_V=[1.0, 1.1]), "K_V must be one number"),
                                       (dict(d_eff_mm=[45.0, 50.0]), "d_eff_mm must be one number")])
def test_shaft_safety_takes_one_number_per_shaft(kw, match):
    """Fuzzing found 'ValueError: operands could not be broadcast together with shapes (0,) (2,)' for Rz_um=[]."""
    an = analyse_shaft(_shaft())
    notches = [ShaftNotch(140.0, Notch("key")), ShaftNotch(80.0, Notch("shoulder", r_mm=1.6))]
    with pytest.raises(GearDesignError, match=match):
        shaft_safety(an, notches, "42CrMo4", **kw)


def test_a_groove_through_a_hollow_shafts_wall_and_array_inputs_are_refused_by_name():
    """A groove of depth t on a tube of bore b with d − 2t <= b left no section (d² − b² < 0: a negative area and
    section moduli) yet gave safeties (S_D 0.197, S_F 1.85 here); fuzzing found a notch position as an empty array
    (TypeError) and load_case as an array (ValueError, 'truth value of an array is ambiguous')."""
    model = ShaftModel(sections=[(50.0, 3.0, 2.9), (50.0, 3.0, 2.9)], supports_mm=[0.0, 100.0],
                          loads=[ShaftLoad(x_mm=50.0, fy_n=-10.0, torque_nm=1.0), ShaftLoad(x_mm=100.0,
                                                                                                  torque_nm=-1.0)])
    a = analyse_shaft(model)
    with pytest.raises(GearDesignError, match=r"cuts through the wall: root d − 2t = 2\.8 mm <= bore 2\.9 mm"):
        shaft_safety(a, [ShaftNotch(40.0, Notch("groove", r_mm=0.01, t_mm=0.1))], "42CrMo4")
    with pytest.raises(GearDesignError, match=r"notches\[0\]\.x_mm must be"):
        shaft_safety(a, [ShaftNotch([], Notch("key"))], "42CrMo4")
    with pytest.raises(GearDesignError, match="load_case must be 1 .* or 2"):
        shaft_safety(a, [ShaftNotch(40.0, Notch("key"))], "42CrMo4", load_case=[1.0, math.nan])
    assert shaft_safety(a, [ShaftNotch(40.0, Notch("key"))], "42CrMo4", load_case=1).table["S_D"].iloc[0] > 0


def test_a_notch_takes_one_number_per_size():
    """Fuzzing found 'ValueError: setting an array element with a sequence' from shaft_safety for a groove of radius
    array([1.]): each size of a Notch is one number, refused by name otherwise."""
    with pytest.raises(GearDesignError, match="r_mm must be one number"):
        Notch("groove", r_mm=[1.0], t_mm=2.0)
    with pytest.raises(GearDesignError, match="t_mm must be one number"):
        Notch("groove", r_mm=1.0, t_mm=[1.0, 2.0])
    with pytest.raises(GearDesignError, match="beta_sigma must be one number"):
        Notch("given", beta_sigma=[2.0], beta_tau=1.5)
    assert Notch("groove", r_mm=1, t_mm=2).r_mm == 1.0
