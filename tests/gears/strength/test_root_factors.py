"""ISO 6336-3 root factors besides Y_F, Y_S (geardesign.gears.strength.root_factors).

No published worked example with these factors and their inputs was found in the sources searched (ISO/TR
6336-30's examples are not public; the public implementations seen print none). The formulas of Y_β, Y_B, Y_DT,
Y_δrelT (fatigue, steels), Y_RrelT and Y_X (steels) were read in IACS UR M56 Rev.4 (see
tests/data/iso6336_root_sources.md); each formula is checked here against the standard's own statements: the values it prints at its break points, its continuity where
the lines are meant to meet, the reference test gear (q_s = 2.5, Y_S = Y_ST = 2) where the relative factors
are 1 by definition, the printed power-law exponents of the life factor, and hand evaluations written out.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from geardesign.errors import GearDesignError
from geardesign.gears.strength import root_factors as rf
from geardesign.gears.strength.root_factors import (MATERIAL_KINDS, Y_ST, contact_ratio_factor_Y_eps,
                                                    deep_tooth_factor_Y_DT, helix_factor_Y_beta, life_factor_Y_NT,
                                                    relative_notch_sensitivity_Y_delta_relT,
                                                    relative_surface_factor_Y_RrelT, rim_factor_Y_B,
                                                    size_factor_Y_X)

KINDS = list(MATERIAL_KINDS)
_LIMIT = {"St": 350.0, "V": 700.0, "GGG(perl)": 700.0, "GTS": 700.0, "GG": 200.0, "GGG(ferr)": 200.0}


def test_material_kinds_cover_every_table():
    assert Y_ST == 2.0
    for table in (rf._SLIP_LAYER_MM, rf._SURFACE, rf._SIZE, rf._LIFE):
        listed = [k for group in table for k in group]
        assert sorted(listed) == sorted(KINDS)              # each kind in exactly one group
    assert sorted(list(rf._STATIC_LINEAR) + list(rf._STATIC_STRENGTH)) == sorted(KINDS)


def test_helix_factor():
    # UR M56 Rev.4 §M56.3.5 / ISO 6336-3:2006: 1 − eps_beta beta/120, eps_beta and beta capped at 1 and 30 degrees
    assert float(helix_factor_Y_beta(0.8, 20.0)) == pytest.approx(1 - 0.8 * 20 / 120, rel=1e-15)
    assert float(helix_factor_Y_beta(2.0, 40.0)) == pytest.approx(0.75, rel=1e-15)
    assert float(helix_factor_Y_beta(0.0, 0.0)) == 1.0
    # the opt-in 2019 reading: the same over cos^3 beta (beta capped at 30 degrees there too)
    assert float(helix_factor_Y_beta(0.8, 20.0, edition=2019)) == pytest.approx(
        (1 - 0.8 * 20 / 120) / math.cos(math.radians(20)) ** 3, rel=1e-15)
    assert float(helix_factor_Y_beta(1.0, -15.0)) == float(helix_factor_Y_beta(1.0, 15.0))
    out = helix_factor_Y_beta(np.array([0.2, 1.5]), np.array([[10.0], [25.0]]))
    assert out.shape == (2, 2)


def test_contact_ratio_factor_method_c():
    assert float(contact_ratio_factor_Y_eps(1.0)) == 1.0
    assert float(contact_ratio_factor_Y_eps(2.0)) == pytest.approx(0.625)


def test_deep_tooth_factor_breakpoints():
    e = np.array([1.5, 2.05, 2.06, 2.5, 2.51, 3.0])
    got = deep_tooth_factor_Y_DT(e, 4)
    want = [1.0, 1.0, -0.666 * 2.06 + 2.366, -0.666 * 2.5 + 2.366, 0.7, 0.7]
    np.testing.assert_allclose(got, want, rtol=1e-15)
    assert abs((-0.666 * 2.5 + 2.366) - 0.7) < 0.0011       # the line meets the floor (0.701)
    assert abs((-0.666 * 2.05 + 2.366) - 1.0) < 0.001       # and 1.0 at 2.05 (1.0007)
    np.testing.assert_array_equal(deep_tooth_factor_Y_DT(e, 5), np.ones(6))


def test_rim_factor():
    assert rim_factor_Y_B() == 1.0 and rim_factor_Y_B(internal=True) == 1.0
    assert float(rim_factor_Y_B(1.2)) == 1.0 and float(rim_factor_Y_B(5.0)) == 1.0
    assert float(rim_factor_Y_B(0.6)) == pytest.approx(1.6 * math.log(2.242 / 0.6), rel=1e-15)
    assert 1.6 * math.log(2.242 / 1.2) == pytest.approx(1.0, abs=3e-4)          # continuous at 1.2
    assert float(rim_factor_Y_B(internal=True, s_R_over_mn=2.0)) == pytest.approx(1.15 * math.log(8.324 / 2.0))
    assert 1.15 * math.log(8.324 / 3.5) == pytest.approx(1.0, abs=4e-3)          # continuous at 3.5


@pytest.mark.parametrize("kind", KINDS)
def test_relative_notch_sensitivity_is_one_at_test_gear(kind):
    lim = _LIMIT.get(kind)
    assert float(relative_notch_sensitivity_Y_delta_relT(2.5, kind, limit_mpa=lim)) == pytest.approx(1.0, abs=1e-15)
    assert float(relative_notch_sensitivity_Y_delta_relT(None, kind, static=True, Y_S=Y_ST, limit_mpa=lim)) \
        == pytest.approx(1.0, abs=1e-15)
    q = np.linspace(1.0, 7.9, 30)
    y = relative_notch_sensitivity_Y_delta_relT(q, kind, limit_mpa=lim)
    assert np.all(np.diff(y) > 0)               # a blunter notch (larger q_s) is less sensitive: Y grows


def test_notch_sensitivity_slip_layer_st_400_is_0_0445():
    """The 0.445-for-0.0445 trap: St with sigma_S = 400 MPa, q_s = 1 (chi* = 0.6), written out."""
    want = (1 + math.sqrt(0.0445 * 0.6)) / (1 + math.sqrt(0.0445 * 1.2))
    assert float(relative_notch_sensitivity_Y_delta_relT(1.0, "St", limit_mpa=400.0)) == pytest.approx(want, rel=1e-15)
    assert want == pytest.approx(0.945021, abs=1e-6)
    wrong = (1 + math.sqrt(0.445 * 0.6)) / (1 + math.sqrt(0.445 * 1.2))
    assert abs(want - wrong) > 0.02
    # in between the table entries: linear in the limit (350 MPa: the mean of 0.0833 and 0.0445)
    mid = (1 + math.sqrt(0.0639 * 0.6)) / (1 + math.sqrt(0.0639 * 1.2))
    assert float(relative_notch_sensitivity_Y_delta_relT(1.0, "St", limit_mpa=350.0)) == pytest.approx(mid, rel=1e-14)


def test_notch_sensitivity_static_forms():
    ys = 1.7
    k = 0.93 * (200 / 355.0) ** 0.25
    assert float(relative_notch_sensitivity_Y_delta_relT(None, "St", static=True, Y_S=ys, limit_mpa=355.0)) \
        == pytest.approx((1 + k * (ys - 1)) / (1 + k), rel=1e-15)
    assert float(relative_notch_sensitivity_Y_delta_relT(None, "NT", static=True, Y_S=ys)) == pytest.approx(0.2 * ys + 0.6)
    k = 0.82 * (300 / 650.0) ** 0.25
    assert float(relative_notch_sensitivity_Y_delta_relT(None, "GTS", static=True, Y_S=ys, limit_mpa=650.0)) \
        == pytest.approx((1 + k * (ys - 1)) / (1 + k), rel=1e-15)
    assert float(relative_notch_sensitivity_Y_delta_relT(None, "GG", static=True, Y_S=ys)) == 1.0


def test_surface_factor():
    assert float(relative_surface_factor_Y_RrelT(10.0, "St")) == pytest.approx(5.306 - 4.203 * 11 ** 0.01, rel=1e-15)
    assert float(relative_surface_factor_Y_RrelT(10.0, "NT")) == pytest.approx(4.299 - 3.259 * 11 ** 0.0058, rel=1e-15)
    assert float(relative_surface_factor_Y_RrelT(0.3, "V")) == 1.12
    assert float(relative_surface_factor_Y_RrelT(20.0, "Eh", static=True)) == 1.0
    rz = np.linspace(1.0, 40.0, 50)
    for kind in KINDS:                           # rougher roots are weaker
        assert np.all(np.diff(relative_surface_factor_Y_RrelT(rz, kind)) < 0)
    # St and GG meet their constants at Rz = 1 (to the printed digits); the V/Eh curve is 1.107 there vs 1.120
    assert 5.306 - 4.203 * 2 ** 0.01 == pytest.approx(1.070, abs=4e-3)
    assert 4.299 - 3.259 * 2 ** 0.0058 == pytest.approx(1.025, abs=2e-3)


def test_size_factor_lines_meet_their_ends():
    for kind, floor, m_floor in (("St", 0.85, 30.0), ("Eh", 0.8, 25.0), ("GG", 0.7, 25.0)):
        assert float(size_factor_Y_X(5.0, kind)) == 1.0
        assert float(size_factor_Y_X(5.0 + 1e-9, kind)) == pytest.approx(1.0, abs=1e-9)
        assert float(size_factor_Y_X(m_floor, kind)) == pytest.approx(floor, abs=1e-12)
        assert float(size_factor_Y_X(100.0, kind)) == floor
        assert float(size_factor_Y_X(12.0, kind, static=True)) == 1.0
    assert float(size_factor_Y_X(10.0, "V")) == pytest.approx(1.03 - 0.06)


@pytest.mark.parametrize("kind, n_static, y_static, exponent", [
    ("St", 1e4, 2.5, 0.16), ("V", 1e4, 2.5, 0.16), ("Eh", 1e3, 2.5, 0.115), ("NT", 1e3, 1.6, 0.059),
    ("NV(nitrocar)", 1e3, 1.1, 0.012),
])
def test_life_factor_against_printed_power_laws(kind, n_static, y_static, exponent):
    """ISO 6336-3 prints Y_NT = (3e6/N_L)^e with e rounded to 2-3 digits, and 0.02 above 3e6: the curves
    through the printed corner values agree with them to the rounding of e."""
    assert float(life_factor_Y_NT(n_static / 10, kind)) == y_static
    assert float(life_factor_Y_NT(3e6, kind)) == pytest.approx(1.0, abs=1e-15)
    assert float(life_factor_Y_NT(1e10, kind)) == pytest.approx(0.85, rel=1e-14)
    assert float(life_factor_Y_NT(1e12, kind)) == pytest.approx(0.85, rel=1e-14)
    assert float(life_factor_Y_NT(1e9, kind, optimum=True)) == 1.0
    n = np.geomspace(n_static, 3e6, 20)
    np.testing.assert_allclose(life_factor_Y_NT(n, kind), (3e6 / n) ** exponent, rtol=0.006)
    n = np.geomspace(3e6, 1e10, 20)
    np.testing.assert_allclose(life_factor_Y_NT(n, kind), (3e6 / n) ** 0.02, rtol=0.001)


@pytest.mark.parametrize("call, fragment", [
    (lambda: helix_factor_Y_beta(-0.1, 10.0), "eps_beta must be in [0, 50]"),
    (lambda: helix_factor_Y_beta(0.5, 50.0), "beta_deg must be in [-45, 45]"),
    (lambda: helix_factor_Y_beta(0.5, 10.0, edition=2010), "edition must be one of"),
    (lambda: contact_ratio_factor_Y_eps(0.9), "eps_alpha_n must be in [1, 10]"),
    (lambda: deep_tooth_factor_Y_DT(2.2, 0), "accuracy_grade must be a whole number in [1, 12]"),
    (lambda: deep_tooth_factor_Y_DT(2.2, 4.5), "accuracy_grade must be a whole number"),
    (lambda: rim_factor_Y_B(0.5), "s_R_over_h_t must be in (0.5"),
    (lambda: rim_factor_Y_B(internal=True, s_R_over_mn=1.7), "s_R_over_mn must be in (1.75"),
    (lambda: rim_factor_Y_B(1.0, internal="yes"), "internal must be True or False"),
    (lambda: relative_notch_sensitivity_Y_delta_relT(2.0, "steel"), "material_kind must be one of"),
    (lambda: relative_notch_sensitivity_Y_delta_relT(2.0, "St"), "limit_mpa (the material's strength"),
    (lambda: relative_notch_sensitivity_Y_delta_relT(2.0, "St", limit_mpa=250.0), "limit_mpa must be in [300, 400]"),
    (lambda: relative_notch_sensitivity_Y_delta_relT(2.0, "V", limit_mpa=1200.0), "limit_mpa must be in [500, 1000]"),
    (lambda: relative_notch_sensitivity_Y_delta_relT(-1.0, "Eh"), "q_s must be in [0.1, 50]"),
    (lambda: relative_notch_sensitivity_Y_delta_relT(None, "Eh", static=True), "Y_S must be given"),
    (lambda: relative_notch_sensitivity_Y_delta_relT(None, "V", static=True, Y_S=1.8), "limit_mpa (yield"),
    (lambda: relative_notch_sensitivity_Y_delta_relT(None, "V", static=True, Y_S=1.8, limit_mpa=-5),
     "limit_mpa must be > 0"),
    (lambda: relative_surface_factor_Y_RrelT(45.0, "Eh"), "Rz_um must be in [0, 40]"),
    (lambda: relative_surface_factor_Y_RrelT(float("nan"), "Eh"), "Rz_um must be finite"),
    (lambda: size_factor_Y_X(0.0, "Eh"), "m_n_mm must be in (0, 1000]"),
    (lambda: size_factor_Y_X(3.0, None), "material_kind must be one of"),
    (lambda: life_factor_Y_NT(0.5, "Eh"), "N_L must be in [1, 1e+30]"),
    (lambda: life_factor_Y_NT(1e6, "Eh", optimum=1), "optimum must be True or False"),
])
def test_refusals(call, fragment):
    with pytest.raises(GearDesignError) as err:
        call()
    assert fragment in str(err.value)
