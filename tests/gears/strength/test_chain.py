"""Properties of the chain (scaling with the load at fixed factors, symmetry, given factors), the result object,
and every refusal with its message."""
import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign import GearPair
from geardesign.errors import GearDesignError
from geardesign.gears.planetary import PlanetarySet
from geardesign.gears.strength import (GIVEN_FACTORS, Load, Material, StrengthResult, material, material_names,
                                       pair_strength, planetary_strength, strength)
from geardesign.gears.strength.defaults import S_FMIN, S_HMIN

FIXED = {"K_v": 1.05, "K_Hbeta": 1.2, "K_Fbeta": 1.15, "K_Halpha": 1.1, "K_Falpha": 1.1, "Z_NT1": 1.0, "Z_NT2": 1.0}


def _pair(torque, **kw):
    opts = dict(load=Load(torque_nm=torque, n_rpm=900), material1="42CrMo4", face_width_mm=30, factors=FIXED)
    opts.update(kw)
    return pair_strength(3, 19, 47, 0.3, 0.1, **opts)


@settings(max_examples=40, deadline=None)
@given(st.floats(1.0, 1e4), st.floats(1.01, 50.0))
def test_contact_stress_grows_with_the_root_of_the_load(torque, k):
    a, b = _pair(torque), _pair(torque * k)
    for key in ("sigma_H0", "sigma_H1", "sigma_H2"):
        assert float(b[key]) / float(a[key]) == pytest.approx(math.sqrt(k), rel=1e-12)
    assert float(b["F_t"]) / float(a["F_t"]) == pytest.approx(k, rel=1e-12)


@settings(max_examples=40, deadline=None)
@given(st.floats(1.0, 1e4), st.floats(1.01, 50.0), st.sampled_from(["B", "C"]))
def test_root_stress_is_proportional_to_the_load(torque, k, method):
    a, b = _pair(torque, root_method=method), _pair(torque * k, root_method=method)
    for key in ("sigma_F1", "sigma_F2"):
        assert float(b[key]) / float(a[key]) == pytest.approx(k, rel=1e-12)
    assert float(b["S_F1"]) * k == pytest.approx(float(a["S_F1"]), rel=1e-12)


@pytest.mark.parametrize("tip_shortening", [True, False])
def test_root_form_falls_as_the_shift_grows(tip_shortening):
    """Y_Fa·Y_Sa (tip load) of an external gear falls as its shift grows. (With method B in a pair the load
    point follows ε_α: as x1 grows ε_α falls, the outer point of single contact moves towards the tip and
    Y_F·Y_S can rise again, e.g. 25/25 with shortened tips between x1 = 0.3 and 0.8: not a property.)"""
    x = np.linspace(-0.2, 1.0, 13)
    out = pair_strength(3, 25, 25, x, 0.0, load=Load(torque_nm=100, n_rpm=900), material1="42CrMo4",
                        face_width_mm=30, root_method="C", tip_shortening=tip_shortening)
    ys = np.asarray(out["Y_Fa1"]) * np.asarray(out["Y_Sa1"])
    assert np.all(np.diff(ys) < 0)


def test_identical_gears_give_identical_values():
    out = pair_strength(2.5, 30, 30, 0.2, 0.2, load=Load(torque_nm=200, n_rpm=1000, life_h=1e4), material1="C45",
                        face_width_mm=25)
    for a, b in (("S_H1", "S_H2"), ("sigma_H1", "sigma_H2"), ("Z_B", "Z_D"), ("Z_NT1", "Z_NT2"), ("Z_R1", "Z_R2"),
                 ("Y_F1", "Y_F2"), ("Y_S1", "Y_S2"), ("sigma_F1", "sigma_F2"), ("S_F1", "S_F2")):
        assert float(out[a]) == pytest.approx(float(out[b]), rel=1e-12), (a, b)


def test_exchanging_the_gears_exchanges_the_values():
    """Gear 1 and 2 swapped (the load on the same physical gear) swap every per-gear value; the factors whose
    formulas are not symmetric in the two gears (the stiffness regression, m_red) are given."""
    given_ = dict(FIXED, c_prime=14.0, c_gamma_alpha=20.0, c_gamma_beta=17.0)
    kw = dict(material1="42CrMo4", material2="18CrNiMo7-6", face_width_mm=30, factors=given_)
    a = pair_strength(3, 24, 31, 0.4, 0.1, load=Load(torque_nm=150, n_rpm=900, on_gear=1, life_h=5e3), **kw)
    kw.update(material1="18CrNiMo7-6", material2="42CrMo4")
    b = pair_strength(3, 31, 24, 0.1, 0.4, load=Load(torque_nm=150, n_rpm=900, on_gear=2, life_h=5e3), **kw)
    for k1, k2 in (("S_H1", "S_H2"), ("sigma_H1", "sigma_H2"), ("Z_B", "Z_D"), ("Z_W1", "Z_W2"), ("Z_NT1", "Z_NT2"),
                   ("Y_F1", "Y_F2"), ("sigma_F1", "sigma_F2"), ("S_F1", "S_F2")):
        assert float(a[k1]) == pytest.approx(float(b[k2]), rel=1e-12), k1
        assert float(a[k2]) == pytest.approx(float(b[k1]), rel=1e-12), k2
    assert float(a["sigma_H0"]) == pytest.approx(float(b["sigma_H0"]), rel=1e-12)


def test_a_given_factor_is_used_and_reported():
    out = _pair(100.0, factors={"K_Hbeta": 1.16})
    assert float(out["K_Hbeta"]) == 1.16 and out["given"] == ("K_Hbeta",)
    assert float(out["K_Fbeta"]) == pytest.approx(1.16 ** float(out["N_F"]), rel=1e-14)
    r = strength(GearPair(m=3, z1=19, z2=47, x1=0.3, x2=0.1, face_width_mm=30), Load(torque_nm=100, n_rpm=900),
                 material="42CrMo4", factors={"K_Hbeta": 1.16})
    assert r.given == ("K_Hbeta",) and "K_Hbeta given, not computed" in r.notes
    assert r.factors.query("symbol == 'K_Hbeta'").value.iloc[0] == 1.16


def test_torque_and_power_are_one_load():
    a = _pair(0.0 + 9549.296585513721 * 10 / 900)           # 10 kW at 900 rpm
    b = pair_strength(3, 19, 47, 0.3, 0.1, load=Load(power_kw=10, n_rpm=900), material1="42CrMo4",
                      face_width_mm=30, factors=FIXED)
    assert float(a["sigma_H1"]) == pytest.approx(float(b["sigma_H1"]), rel=1e-12)


def test_load_on_the_wheel_is_carried_to_the_pinion():
    a = _pair(100.0)
    b = pair_strength(3, 19, 47, 0.3, 0.1, load=Load(torque_nm=100 * 47 / 19, n_rpm=900 * 19 / 47, on_gear=2),
                      material1="42CrMo4", face_width_mm=30, factors=FIXED)
    assert float(a["F_t"]) == pytest.approx(float(b["F_t"]), rel=1e-12)
    assert float(a["v"]) == pytest.approx(float(b["v"]), rel=1e-12)


def test_stiffness_range_flag():
    inside = _pair(100.0)
    outside = pair_strength(3, 19, 47, 0.1, 0.5, load=Load(torque_nm=100, n_rpm=900), material1="42CrMo4",
                            face_width_mm=30)     # x1 < x2: outside the regression's stated range
    assert not bool(inside["stiffness_out_of_range"]) and bool(outside["stiffness_out_of_range"])


def test_result_object():
    r = strength(GearPair(m=3, z1=19, z2=47, x1=0.3, x2=0.1, face_width_mm=30), Load(torque_nm=50, n_rpm=900),
                 material="18CrNiMo7-6")
    assert isinstance(r, StrengthResult)
    text = repr(r)
    assert len(text.splitlines()) <= 15 and text.splitlines()[0].startswith("StrengthResult")
    assert set(r.factors.columns) == {"symbol", "gear", "value", "clause"}
    assert {"K_v", "K_Hbeta", "K_Halpha", "K_Fbeta", "Z_H", "Z_E", "Z_eps", "Z_beta", "Z_NT", "Z_L", "Z_v",
            "Z_R"} <= set(r.factors.symbol)
    d = json.loads(r.to_json())
    assert d["S_H1"] == pytest.approx(r.S_H1) and "margins" in d
    assert r.margins["contact1"] == pytest.approx(r.S_H1 / S_HMIN - 1)
    assert "<table>" in r._repr_html_()
    assert (S_HMIN, S_FMIN) == (r.S_Hmin, r.S_Fmin)


def test_planetary_meshes_share_the_torque():
    s = PlanetarySet.coaxial(2, 20, 31, 82, 3)
    one = planetary_strength(s, Load(torque_nm=90, n_rpm=1500), "18CrNiMo7-6", face_width_mm=25,
                             factors={"K_v": 1.0, "K_Hbeta": 1.0, "K_Halpha": 1.0})
    direct = pair_strength(2, 20, 31, s.x_sun, s.x_planet, load=Load(torque_nm=30, n_rpm=1500 * (1 - 20 / 102)),
                           material1="18CrNiMo7-6", face_width_mm=25, tip_shortening=False,
                           factors={"K_v": 1.0, "K_Hbeta": 1.0, "K_Halpha": 1.0})
    assert one["sun-planet"].sigma_H0 == pytest.approx(float(direct["sigma_H0"]), rel=1e-12)
    k = planetary_strength(s, Load(torque_nm=90, n_rpm=1500), "18CrNiMo7-6", face_width_mm=25, K_gamma=1.21,
                           factors={"K_v": 1.0, "K_Hbeta": 1.0, "K_Halpha": 1.0})
    assert k["planet-ring"].sigma_H1 == pytest.approx(one["planet-ring"].sigma_H1 * 1.1, rel=1e-12)


@pytest.mark.parametrize("kwargs, message", [
    (dict(torque_nm=1, power_kw=1, n_rpm=1), "give either torque_nm or power_kw, not both"),
    (dict(n_rpm=1), "give either torque_nm or power_kw, one is needed"),
    (dict(torque_nm=1), "n_rpm (the speed of the gear the load is given on) is needed"),
    (dict(torque_nm=-5, n_rpm=1), "torque_nm must be in (0, 1e+09] N·m, got -5"),
    (dict(torque_nm=5, n_rpm=1, on_gear=3), "on_gear must be 1 or 2"),
    (dict(torque_nm=5, n_rpm=1, application_factor=0.5), "application_factor must be in [1, 10], got 0.5"),
    (dict(torque_nm=5, n_rpm=1, life_h=0), "life_h must be in (0, 1e+07] h, got 0"),
])
def test_load_refusals(kwargs, message):
    with pytest.raises(GearDesignError) as e:
        Load(**kwargs)
    assert message in str(e.value)


@pytest.mark.parametrize("kwargs, message", [
    (dict(material1="unobtainium"), "material must be a name of the catalog or an ISO 6336-5 group"),
    (dict(material1=3), "material1 must be a geardesign Material or a material name, got int"),
    (dict(face_width_mm=0), "face_width_mm must be in [0.001, 100000] mm, got 0"),
    (dict(accuracy_grade=13), "accuracy_grade must be in [0, 12], got 13"),
    (dict(nu40=0.5), "nu40 must be in [1, 10000] mm²/s, got 0.5"),
    (dict(Rz_flank_um=0.0), "Rz_flank_um must be in [0.01, 100] µm, got 0.0"),
    (dict(K_gamma=0.9), "K_gamma must be in [1, 3], got 0.9"),
    (dict(root_method="A"), "root_method must be 'B'"),
    (dict(factors={"K_Hbeta": -1}), "factors['K_Hbeta'] must be in [0.01, 100], got -1"),
    (dict(factors={"K_Q": 1}), "factors: unknown factor 'K_Q'"),
    (dict(factors=[1]), "factors must be a dict"),
    (dict(Rz_root_um=50), "Rz_root_um must be in [0.01, 40] µm, got 50"),
    (dict(material1=material("V_alloy", hardness=300)), "needs yield_mpa for the relative notch sensitivity"),
    (dict(load=5), "load must be a geardesign Load, got int"),
    (dict(S_Hmin=0.1), "S_Hmin must be in [0.5, 10], got 0.1"),
])
def test_chain_refusals(kwargs, message):
    opts = dict(load=Load(torque_nm=100, n_rpm=900), material1="42CrMo4", face_width_mm=30)
    opts.update(kwargs)
    with pytest.raises(GearDesignError) as e:
        pair_strength(3, 19, 47, 0.3, 0.1, **opts)
    assert message in str(e.value)


def test_material_refusals_and_lines():
    with pytest.raises(GearDesignError, match=r"hardness must be in \[200, 360\] HV for the V_alloy MQ contact"):
        material("42CrMo4", hardness=420)
    with pytest.raises(GearDesignError, match="needs a hardness"):
        material("V_alloy")
    with pytest.raises(GearDesignError, match="is a cast iron: give E_mpa and nu"):
        material("GGG", hardness=250)
    with pytest.raises(GearDesignError, match="quality must be one of"):
        material("42CrMo4", quality="MX")
    with pytest.raises(GearDesignError, match="nu must be in"):
        Material("x", "V", 206000, 0.7, 300, "HV", 700, 300)
    m = material("V_alloy", hardness=250, quality="ME")       # ISO 6336-5 Table 1: 2.213 x + 260, 0.358 x + 231
    assert (m.sigma_Hlim_mpa, m.sigma_Flim_mpa) == (pytest.approx(2.213 * 250 + 260), pytest.approx(0.358 * 250 + 231))
    assert {"42CrMo4", "18CrNiMo7-6", "C45", "40Cr", "40Х", "20CrMnTi", "18ХГТ", "Eh"} <= set(material_names())


def test_every_given_factor_name_is_a_field():
    out = _pair(100.0, factors=None)
    missing = {k for k in GIVEN_FACTORS if k not in out and k not in ("Y_Fa1", "Y_Fa2", "Y_Sa1", "Y_Sa2", "Y_eps")}
    assert not missing, missing


def test_planetary_refusals_and_sun_cycles():
    s = PlanetarySet.coaxial(2, 20, 31, 82, 3)
    with pytest.raises(GearDesignError, match="load must be a geardesign Load given on the sun"):
        planetary_strength(s, Load(torque_nm=90, n_rpm=1500, on_gear=2), "18CrNiMo7-6", face_width_mm=25)
    with pytest.raises(GearDesignError, match="material is needed"):
        planetary_strength(s, Load(torque_nm=90, n_rpm=1500), face_width_mm=25)
    sun_fixed = PlanetarySet.coaxial(2, 20, 31, 82, 3, arrangement="sun_fixed")
    with pytest.raises(GearDesignError, match="arrangement must be 'ring_fixed' or 'carrier_fixed'"):
        planetary_strength(sun_fixed, Load(torque_nm=90, n_rpm=1500), "18CrNiMo7-6", face_width_mm=25)
    r = planetary_strength(s, Load(torque_nm=90, n_rpm=1500, life_h=1000), "18CrNiMo7-6", face_width_mm=25)
    n_rel = 1500 * (1 - 20 / 102)
    z_nt = r["sun-planet"].factors.query("symbol == 'Z_NT' and gear == 1").value.iloc[0]
    from geardesign.gears.strength.life import contact_life_factor
    assert z_nt == pytest.approx(float(contact_life_factor(60 * n_rel * 1000 * 3, "Eh")), rel=1e-12)


def test_contact_only():
    full = _pair(100.0, factors=None)
    contact = _pair(100.0, factors=None, root=False)
    assert "S_F1" not in contact and "Y_F1" not in contact
    for k in ("S_H1", "S_H2", "K_v", "K_Hbeta", "K_Halpha"):
        assert float(contact[k]) == float(full[k])


def test_a_given_factor_that_is_not_needed_is_reported():
    out = _pair(100.0, factors={"K_Hbeta": 1.2, "f_sh": 10.0, "Y_eps": 0.7})
    assert out["given"] == ("K_Hbeta",) and out["given_unused"] == ("Y_eps", "f_sh")
