"""Shaft as a beam: closed-form beam formulas (uniform shafts, to 1e-9), an independent unit-load (virtual
work) integration for stepped shafts, statics of random cases (hypothesis), critical-speed bounds."""
import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from scipy.integrate import quad

import geardesign as gd
from geardesign.drives.shaft_beam import E_STEEL_MPA, ShaftLoad, ShaftModel, analyse_shaft, second_moment_mm4
from geardesign.errors import GearDesignError


def test_simply_supported_intermediate_load_closed_form():
    """Budynas & Nisbett, Shigley's MED 10th ed., Table A-9-6 (simple supports, intermediate load):
    R1 = F b/l, y = F b x (x² + b² − l²)/(6 E I l) for x <= a, θ at x = 0: F b (b² − l²)/(6 E I l)."""
    F, l, a, d = 2500.0, 300.0, 110.0, 35.0
    b = l - a
    EI = E_STEEL_MPA * float(second_moment_mm4(d))
    an = analyse_shaft(ShaftModel([(l, d)], [0.0, l], [ShaftLoad(a, fy_n=-F)]))
    assert an.reactions["Ry_n"].tolist() == pytest.approx([F * b / l, F * a / l], rel=1e-12)
    xs = np.array([0.0, 30.0, 70.0, a])
    got = an.deflection_at(xs)
    np.testing.assert_allclose(got["wy_mm"], F * b * xs * (xs ** 2 + b ** 2 - l ** 2) / (6 * EI * l),
                               rtol=1e-9, atol=1e-15)
    assert float(got["thy_rad"].iloc[0]) == pytest.approx(F * b * (b ** 2 - l ** 2) / (6 * EI * l), rel=1e-9)
    x2 = np.array([150.0, 250.0])       # x > a: the formula mirrored (a <-> b, x -> l − x)
    np.testing.assert_allclose(an.deflection_at(x2)["wy_mm"],
                               F * a * (l - x2) * ((l - x2) ** 2 + a ** 2 - l ** 2) / (6 * EI * l), rtol=1e-9)
    M = an.diagrams.set_index("x_mm")["Mz_nm"]
    assert M.loc[a].abs().max() == pytest.approx(F * a * b / l / 1000, rel=1e-12)


def test_overhang_closed_form():
    """Shigley Table A-9-10 (overhanging beam, load at the overhang end): R1 = −F a/l, R2 = F(l + a)/l,
    y at the tip = −F a² (l + a)/(3 E I)."""
    F, l, a, d = 1200.0, 250.0, 80.0, 30.0
    EI = E_STEEL_MPA * float(second_moment_mm4(d))
    an = analyse_shaft(ShaftModel([(l + a, d)], [0.0, l], [ShaftLoad(l + a, fz_n=-F)]))
    assert an.reactions["Rz_n"].tolist() == pytest.approx([-F * a / l, F * (l + a) / l], rel=1e-12)
    tip = an.deflection_at(l + a)["wz_mm"].iloc[0]
    assert tip == pytest.approx(-F * a ** 2 * (l + a) / (3 * EI), rel=1e-9)


def test_three_supports_uniform_closed_form():
    """Continuous beam on three equal spans supports, load at mid first span: by superposition of
    Table A-9-6 (an independent small computation here): the middle reaction from w = 0 there."""
    F, L, d = 1000.0, 400.0, 40.0
    a = 100.0
    an = analyse_shaft(ShaftModel([(L, d)], [0.0, L / 2, L], [ShaftLoad(a, fy_n=-F)]))
    EI = E_STEEL_MPA * float(second_moment_mm4(d))

    def y_ss(x, P, at):     # deflection of the simple span 0..L under P at `at` (Table A-9-6), + up
        b = L - at
        if x <= at:
            return P * b * x * (x ** 2 + b ** 2 - L ** 2) / (6 * EI * L)
        return P * at * (L - x) * ((L - x) ** 2 + at ** 2 - L ** 2) / (6 * EI * L)

    # w(L/2) = y_ss(L/2; −F at a) + R_mid · y_ss(L/2; unit at L/2) = 0
    R_mid = -y_ss(L / 2, -F, a) / y_ss(L / 2, 1.0, L / 2)
    assert an.reactions["Ry_n"].iloc[1] == pytest.approx(R_mid, rel=1e-9)
    assert an.reactions["Ry_n"].sum() == pytest.approx(F, rel=1e-12)


def test_stepped_shaft_against_unit_load_integration():
    """A stepped shaft: the deflection at each load by the unit-load method, δ = ∫ M m / (E I) dx with
    scipy.integrate.quad over the sections (an independent method and implementation)."""
    sections = [(40.0, 30.0), (60.0, 40.0), (120.0, 50.0), (50.0, 40.0), (30.0, 30.0)]
    supports = [20.0, 250.0]
    loads = [ShaftLoad(80.0, fy_n=-4000.0), ShaftLoad(180.0, fy_n=2500.0), ShaftLoad(285.0, fy_n=-900.0)]
    an = analyse_shaft(ShaftModel(sections, supports, loads))
    ends = np.concatenate([[0.0], np.cumsum([s[0] for s in sections])])
    s1, s2 = supports

    def EI(x):
        i = min(np.searchsorted(ends, x, side="right") - 1, len(sections) - 1)
        return E_STEEL_MPA * math.pi * sections[i][1] ** 4 / 64

    def moment(x, forces):      # left-part moment, reactions of a simply supported beam with overhangs
        tot = sum(f for _, f in forces)
        mom = sum(f * (p - s1) for p, f in forces)
        R2 = -mom / (s2 - s1)
        R1 = -tot - R2
        allf = list(forces) + [(s1, R1), (s2, R2)]
        return sum(f * (x - p) for p, f in allf if p < x)

    applied = [(ld.x_mm, ld.fy_n) for ld in loads]
    brk = sorted(set(ends) | {s1, s2} | {p for p, _ in applied})
    for xq in (80.0, 180.0, 130.0):
        unit = [(xq, 1.0)]
        # virtual work: δ(xq) = ∫ M(x) m(x) / EI dx — then w(xq) on the support line
        integral = sum(quad(lambda x, unit=unit: moment(x, applied) * moment(x, unit) / EI(x), lo, hi, epsabs=0,
                            epsrel=1e-12, limit=200)[0] for lo, hi in zip(brk[:-1], brk[1:]))
        got = float(an.deflection_at(xq)["wy_mm"].iloc[0])
        assert got == pytest.approx(integral, rel=1e-9)


loads_st = st.lists(st.tuples(st.floats(0, 1), st.floats(-5e3, 5e3), st.floats(-5e3, 5e3), st.floats(-2e3, 2e3),
                              st.floats(-80, 80)), min_size=1, max_size=6)


@settings(max_examples=40, deadline=None)
@given(loads_st, st.integers(2, 4), st.lists(st.floats(15, 60), min_size=1, max_size=4))
def test_reactions_balance_every_load(raw, n_sup, diameters):
    L = 400.0
    sections = [(L / len(diameters), d) for d in diameters]
    supports = list(np.linspace(10.0, 390.0, n_sup))
    loads = [ShaftLoad(u * L, fy_n=fy, fz_n=fz, fx_n=fx, y_mm=r) for u, fy, fz, fx, r in raw]
    an = analyse_shaft(ShaftModel(sections, supports, loads), points=40)
    R = an.reactions
    fy = sum(ld.fy_n for ld in loads)
    fz = sum(ld.fz_n for ld in loads)
    scale = 1 + sum(abs(ld.fy_n) + abs(ld.fz_n) + abs(ld.fx_n) for ld in loads)
    assert abs(R["Ry_n"].sum() + fy) <= 1e-9 * scale
    assert abs(R["Rz_n"].sum() + fz) <= 1e-9 * scale
    assert abs(R["Rx_n"].sum() + sum(ld.fx_n for ld in loads)) <= 1e-9 * scale
    # moments about x = 0 in the x-y plane: Σ F x + Σ couples (−y Fx) ... all forces incl. reactions
    mom = (sum(ld.fy_n * ld.x_mm for ld in loads) + (R["Ry_n"] * R["x_mm"]).sum()
           + sum(-ld.y_mm * ld.fx_n for ld in loads))
    assert abs(mom) <= 1e-9 * scale * L * 10
    # the deflection vanishes at every support
    w = an.deflection_at(R["x_mm"].to_numpy())
    assert np.abs(w["w_mm"]).max() <= 1e-9 * max(an.max_deflection_mm, 1e-30) + 1e-15
    # and the moment closes at both ends
    d = an.diagrams
    assert abs(d["M_nm"].iloc[-1]) <= 1e-9 * scale * L / 1000 and abs(d["M_nm"].iloc[0]) == 0.0


def test_critical_speed_uniform_shaft_bounds():
    """Uniform simply supported shaft: ω = (π/L)²·√(EI/μ) (Shigley 10th ed. eq. (7-22)); Rayleigh is an
    upper and Dunkerley a lower estimate, Rayleigh within 0.1 % for the static deflection curve."""
    L, d = 1000.0, 40.0
    an = analyse_shaft(ShaftModel([(L, d)], [0.0, L]), points=1000)
    EI = E_STEEL_MPA * float(second_moment_mm4(d))        # N·mm²
    mu = 7850e-9 * math.pi * d ** 2 / 4                   # kg/mm
    omega = (math.pi / L) ** 2 * math.sqrt(EI / (mu * 1e-3))
    n_exact = omega * 30 / math.pi
    assert an.critical_speed_dunkerley_rpm < n_exact < an.critical_speed_rpm
    assert an.critical_speed_rpm / n_exact - 1 < 1e-3


def test_bad_inputs_are_named():
    with pytest.raises(GearDesignError, match="supports_mm"):
        ShaftModel([(100.0, 30.0)], [0.0])
    with pytest.raises(GearDesignError, match="loads\\[0\\].x_mm"):
        ShaftModel([(100.0, 30.0)], [0.0, 100.0], [ShaftLoad(150.0, fy_n=1.0)])
    with pytest.raises(GearDesignError, match="torques on the shaft must balance"):
        ShaftModel([(100.0, 30.0)], [0.0, 100.0], [ShaftLoad(50.0, torque_nm=10.0)])
    with pytest.raises(GearDesignError, match="bore_mm"):
        ShaftModel([(100.0, 30.0, 30.0)], [0.0, 100.0])
    assert gd.ShaftModel is ShaftModel


IN, LBF = 25.4, 4.4482216152605
E_30MPSI = 30e6 * LBF / IN ** 2        # N/mm²


def test_shigley_problem_7_8_printed_slopes():
    """tests/data/shigley_shaft_examples.md, item 1: slopes 0.0002823 (left), 4.342e-4 (right), 0.000304
    (gear) rad, printed to 4 and 3 digits."""
    model = ShaftModel([(11 * IN, 1.875 * IN)], [0.0, 11 * IN], [ShaftLoad(9 * IN, fy_n=-1449 * LBF)], E_mpa=E_30MPSI)
    th = analyse_shaft(model).deflection_at([0.0, 11 * IN, 9 * IN])["th_rad"].tolist()
    assert th[0] == pytest.approx(0.0002823, abs=0.5e-7)
    assert th[1] == pytest.approx(4.342e-4, abs=0.5e-7)
    assert th[2] == pytest.approx(0.000304, abs=0.5e-6)


def test_shigley_example_7_5_equivalent_loads():
    """tests/data/shigley_shaft_examples.md, item 2: w_1c = 35·δ11/δcc = 17.1 lbf, w_2c = 55·δ22/δcc = 46.1 lbf
    (influence coefficients from unit loads on the model)."""
    L = 31 * IN

    def delta(at, of):
        m = ShaftModel([(L, IN)], [0.0, L], [ShaftLoad(of, fy_n=-1.0)], E_mpa=E_30MPSI)
        return -analyse_shaft(m, points=20).deflection_at(at)["wy_mm"].iloc[0]

    x1, x2, xc = 7 * IN, 20 * IN, L / 2
    dcc = delta(xc, xc)
    assert 35 * delta(x1, x1) / dcc == pytest.approx(17.1, abs=0.05)
    assert 55 * delta(x2, x2) / dcc == pytest.approx(46.1, abs=0.05)
    assert 6 * E_30MPSI * float(second_moment_mm4(IN)) * L / (LBF * IN ** 3) == pytest.approx(0.2739e9, rel=2e-4)


@pytest.mark.parametrize("sections", [-1e308, 40, None])
def test_sections_that_are_no_list_are_refused_by_name(sections):
    """Fuzzing found "TypeError: 'float' object is not iterable" for sections=-1e308."""
    with pytest.raises(GearDesignError, match=r"sections must be a list of \(length_mm, d_mm\[, bore_mm\]\)"):
        ShaftModel(sections=sections, supports_mm=[10.0, 50.0])


@pytest.mark.parametrize("field, value", [("fz_n", ()), ("fy_n", [1.0, 2.0]), ("x_mm", [10.0]), ("mass_kg", [])])
def test_a_load_value_that_is_not_one_number_is_refused_by_name(field, value):
    """Fuzzing found 'ValueError: setting an array element with a sequence' from analyse_shaft for fz_n=()."""
    load = dict(x_mm=20.0, fy_n=100.0) | {field: value}
    with pytest.raises(GearDesignError, match=rf"loads\[0\]\.{field} must be one number"):
        ShaftModel(sections=[(40.0, 30.0)], supports_mm=[0.0, 40.0], loads=[ShaftLoad(**load)])


def _printed(example):
    """tests/data/shigley_shaft_printed.csv: the printed figures of one example, {(quantity, x_in): value}."""
    import csv
    from pathlib import Path

    with open(Path(__file__).parents[1] / "data" / "shigley_shaft_printed.csv", encoding="utf-8") as f:
        rows = [r for r in csv.DictReader(f) if r["example"] == example]
    out = {}
    for r in rows:
        out.setdefault((r["quantity"], float(r["x_in"]) if r["x_in"] else None), []).append(float(r["value"]))
    return out


def _example_4_7():
    # the book's model: only the step at D (AB taken as 1.5 in and EF as 1.75 in); supports at the shaft's two
    # ends (the length as the sum of its sections, so the right support is exactly on it)
    secs = [(8.5 * IN, 1.5 * IN), (11.5 * IN, 1.75 * IN)]
    L = secs[0][0] + secs[1][0]
    return analyse_shaft(ShaftModel(secs, [0.0, L], [ShaftLoad(8 * IN, fy_n=-600 * LBF)], E_mpa=E_30MPSI))


def test_shigley_example_4_7_reactions_moments_and_m_over_i():
    """tests/data/shigley_shaft_examples.md, item 3 (Shigley 9th ed. Example 4-7): R1 = 360, R2 = 240 lbf; M = 2880
    lbf·in at C and 2760 at D; M/I = 11 106.6 and 5 994.8 lbf/in³ either side of D (the book's I rounded to 0.2485 and
    0.4604 in⁴: to its printed digits with those, to 3e-5 with ours)."""
    p = _printed("4-7")
    an = _example_4_7()
    assert (an.reactions["Ry_n"] / LBF).tolist() == pytest.approx([p[("R1", 0.0)][0], p[("R2", 20.0)][0]], abs=1e-9)
    d = an.diagrams
    for x in (8.0, 8.5):
        rows = d[np.isclose(d["x_mm"], x * IN)]
        assert (rows["Mz_nm"] * 1000 / (LBF * IN)).to_numpy() == pytest.approx(p[("M", x)][0], abs=1e-9)
    rows = d[np.isclose(d["x_mm"], 8.5 * IN)]          # left and right limits at the step D
    I_in4 = second_moment_mm4(rows["d_mm"].to_numpy()) / IN ** 4
    assert I_in4 == pytest.approx([p[("I_BC", None)][0], p[("I_DE", None)][0]], abs=0.5e-4)
    M_lbf_in = rows["Mz_nm"].to_numpy() * 1000 / (LBF * IN)
    assert M_lbf_in / np.round(I_in4, 4) == pytest.approx(p[("M_over_I", 8.5)], abs=0.05)
    assert M_lbf_in / I_in4 == pytest.approx(p[("M_over_I", 8.5)], rel=3e-5)


def test_shigley_example_4_7_deflection_curve():
    """Item 3's deflections: the book's M/I, eq. (2), integrated twice with y = 0 at both bearings (the closed form
    below, exact for its printed coefficients) bounds the deflection by the half-unit of each printed coefficient; the
    beam's lies inside at every x. The book's eq. (4) rounds 1448.7/6 = 241.45 up to 241.5, which moves the deflection
    by 0.04-0.11 %: against eq. (4) as printed, 0.15 %. Both the book and the beam ignore shear deformation."""
    p = _printed("4-7")
    xs = np.arange(0.5, 20.0, 0.5)                       # the book's ½-in steps
    got = _example_4_7().deflection_at(xs * IN)["wy_mm"].to_numpy() / IN

    def ramp(v, n):
        return np.where(v > 0, v, 0.0) ** n

    def basis(x):           # double integrals of x, <x−8>¹, <x−8.5>⁰, <x−8.5>¹ with y(0) = y(20) = 0
        terms = [lambda x: x ** 3 / 6, lambda x: ramp(x - 8, 3) / 6, lambda x: ramp(x - 8.5, 2) / 2,
                 lambda x: ramp(x - 8.5, 3) / 6]
        return np.array([t(x) - t(20.0) * x / 20.0 for t in terms])

    c = np.array([p[(k, None)][0] for k in ("eq2_x", "eq2_x8", "eq2_x85_0", "eq2_x85_1")])
    G = basis(xs)
    E_psi = 30e6
    mid, half = c @ G / E_psi, 0.05 * np.abs(G).sum(axis=0) / E_psi
    assert np.all(np.abs(got - mid) <= half)
    c4 = [p[(k, None)][0] for k in ("eq4_x3", "eq4_x8_3", "eq4_x85_2", "eq4_x85_3")]

    def eq4(x, C1):
        return c4[0] * x ** 3 + c4[1] * ramp(x - 8, 3) + c4[2] * ramp(x - 8.5, 2) + c4[3] * ramp(x - 8.5, 3) + C1 * x

    C1 = -eq4(20.0, 0.0) / 20.0                          # y(20) = 0 (C2 = 0 from y(0) = 0)
    np.testing.assert_allclose(got, eq4(xs, C1) / E_psi, rtol=1.5e-3)


def test_shigley_example_7_2_reactions_and_moments_in_two_planes():
    """tests/data/shigley_shaft_examples.md, item 4 (Shigley 9th ed. Example 7-2): the countershaft's reactions in
    both planes to the printed 0.1 lbf and its moments at G, I, J, K to the printed lbf·in (x-z plane: our My,
    x-y plane: our Mz; the tangential forces W₂₃ᵗ = +540 lbf and W₅₄ᵗ = −2431 lbf along z, the radial ones −197 and
    −885 lbf along y). On two bearings the diameters do not change reactions and moments: the sections here are
    any, with steps at I and K (so that they are nodes of the diagrams)."""
    p = _printed("7-2")
    secs = [(7.5 * IN, 1.625 * IN), (1.0 * IN, 2.0 * IN), (2.0 * IN, 1.625 * IN), (1.0 * IN, 1.0 * IN)]
    loads = [ShaftLoad(2.75 * IN, fy_n=-197 * LBF, fz_n=540 * LBF),
             ShaftLoad(8.5 * IN, fy_n=-885 * LBF, fz_n=-2431 * LBF)]
    an = analyse_shaft(ShaftModel(secs, [0.75 * IN, 10.75 * IN], loads, E_mpa=E_30MPSI))
    R = an.reactions / LBF
    assert R["Rz_n"].tolist() == pytest.approx([p[("R_Az", 0.75)][0], p[("R_Bz", 10.75)][0]], abs=0.05)
    assert R["Ry_n"].tolist() == pytest.approx([p[("R_Ay", 0.75)][0], p[("R_By", 10.75)][0]], abs=0.05)
    d = an.diagrams
    to_lbf_in = 1000 / (LBF * IN)
    for x in (2.75, 7.5, 8.5, 9.5):
        rows = d[np.isclose(d["x_mm"], x * IN)]
        for col, q in (("My_nm", "M_xz"), ("Mz_nm", "M_xy")):
            assert rows[col].to_numpy() * to_lbf_in == pytest.approx(p[(q, x)][0], abs=0.5), (x, q)
        # the book's totals are √(M_xz² + M_xy²) of its rounded components ("at J, √(3996² + 1632²) = 4316"): so to
        # the printed digit from ours rounded as the book rounds them, to 1 lbf·in from ours as they are
        M_xz, M_xy = (np.round(rows[c].to_numpy() * to_lbf_in) for c in ("My_nm", "Mz_nm"))
        assert np.hypot(M_xz, M_xy) == pytest.approx(p[("M_tot", x)][0], abs=0.5), x
        assert rows["M_nm"].to_numpy() * to_lbf_in == pytest.approx(p[("M_tot", x)][0], abs=1.0), x


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.floats(0, 1), st.floats(-5e3, 5e3)), min_size=1, max_size=8),
       st.floats(0.0, 0.45), st.floats(0.55, 1.0))
def test_two_support_reactions_closed_form(raw, ua, ub):
    """Statics of a simply supported shaft (overhangs allowed) with point loads, closed form written here:
    R_B = −Σ F_i (x_i − a)/(b − a), R_A = −Σ F_i − R_B (forces and reactions +y), to 1e-9."""
    L = 300.0
    a, b = ua * L, ub * L
    loads = [ShaftLoad(u * L, fy_n=f) for u, f in raw]
    R = analyse_shaft(ShaftModel([(L, 40.0)], [a, b], loads), points=20).reactions["Ry_n"].to_numpy()
    Rb = -sum(ld.fy_n * (ld.x_mm - a) for ld in loads) / (b - a)
    Ra = -sum(ld.fy_n for ld in loads) - Rb
    scale = 1.0 + sum(abs(ld.fy_n) for ld in loads) * L / (b - a)
    assert abs(R[0] - Ra) <= 1e-9 * scale and abs(R[1] - Rb) <= 1e-9 * scale


def test_a_support_at_the_end_of_a_shaft_in_inches_is_on_it():
    """Found transcribing Shigley's Example 4-7: sections of 8.5 and 11.5 in sum to 507.99999999999994 mm, and a
    bearing and a load at 20 in (508.00000000000006 mm) were refused as off the shaft. Within 1e-9 of its length
    beyond an end, a position is that end; further, still refused by name."""
    m = ShaftModel([(8.5 * IN, 1.5 * IN), (11.5 * IN, 1.75 * IN)], [0.0, 20 * IN],
                   [ShaftLoad(8 * IN, fy_n=-600.0), ShaftLoad(20 * IN, fz_n=10.0)])
    assert m.supports_mm[1] == m.length_mm and m.loads[1].x_mm == m.length_mm
    assert analyse_shaft(m).reactions["Ry_n"].sum() == pytest.approx(600.0, rel=1e-12)
    with pytest.raises(GearDesignError, match="supports_mm must lie on the shaft"):
        ShaftModel([(100.0, 30.0)], [0.0, 100.001])
    with pytest.raises(GearDesignError, match=r"loads\[0\].x_mm must be in"):
        ShaftModel([(100.0, 30.0)], [0.0, 100.0], [ShaftLoad(-0.001, fy_n=1.0)])
