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
