"""Roller-chain drive design. Every number is recomputed by hand here (formula written out) or
taken from a cited source: seed 002 (the brake test stand course work) and Bhandari's worked examples
(both in docs/references.md), or the catalog tables."""
import json
import math

import numpy as np
import pytest

from geardesign import chain, sprocket
from geardesign.catalogs import load_catalog
from geardesign.errors import GearDesignError

SEED = dict(torque_nm=380, n1_rpm=120, ratio=1, z1=13, k_e=2.148, allowable_pressure_mpa=29, strands=(1, 2))


def test_seed002_pitch_estimate():
    # seed 002, 1.9.5: t >= 28·cbrt(T1·K/([p]·z1·m·K_m)), T in N·m: 36.23 mm (m = 1) and 30.35 mm (m = 2, K_m = 0.85)
    one = 28 * (380 * 2.1484 / (29 * 13 * 1 * 1)) ** (1 / 3)
    two = 28 * (380 * 2.1484 / (29 * 13 * 2 * 0.85)) ** (1 / 3)
    assert round(one, 2) == 36.23 and round(two, 2) == 30.35
    assert chain.pitch_estimate_mm(380, 13, 29, 2.1484, 1.0) == pytest.approx(one)
    assert chain.pitch_estimate_mm(380, 13, 29, 2.1484, 1.7) == pytest.approx(two)
    r = chain.design(**SEED)
    assert r.pitch_estimate_mm[1] == pytest.approx(28 * (380 * 2.148 / (29 * 13)) ** (1 / 3))


def test_seed002_k_e_from_conditions():
    # seed 002, 1.9.3: K = Kd·Kk·Kc·Kp/Kz with Kk = 1.1·1.25·1·1.5 = 2.0625 and Kz = 0.96 -> 2.148
    c = chain.Conditions(k_reg=1.1, k_a=1.25, k_lub=1.5)
    assert c.k_e == pytest.approx(1.1 * 1.25 * 1.5)
    assert c.k_e / (1 + 0.01 * (13 - 17)) == pytest.approx(2.1484, abs=1e-4)
    named = chain.Conditions.from_mapping({"k_lub": "irregular", "k_reg": "idler", "k_a": "below_25_pitches"})
    assert named.k_e == pytest.approx(c.k_e)


def test_seed002_two_strand_chain_recomputed():
    # 2PR-31.75 (GOST 13568): A = 260 mm2 per strand (GOST 13568-75), two strands m·K_m = 1.7.
    # v = z1·t·n1/60000; F = P/v with P = T·2π·n/60; p = F·K_e/(A·1.7)
    v = 13 * 31.75 * 120 / 60000
    force = 380 * 2 * math.pi * 120 / 60 / v
    p = force * 2.148 / (260 * 1.7)
    r = chain.design(**SEED)
    row = r.candidates[r.candidates["designation"] == "2PR-31,75-177"].iloc[0]
    assert row["speed_m_s"] == pytest.approx(v)
    assert row["force_n"] == pytest.approx(force)
    assert row["pressure_mpa"] == pytest.approx(p)
    assert row["margin_pressure"] == pytest.approx(1 - p / 29)
    assert p < 29 and row["feasible"]
    single = r.candidates[r.candidates["designation"] == "PR-31,75-89"].iloc[0]
    assert single["pressure_mpa"] == pytest.approx(force * 2.148 / 260) and not single["feasible"]


def test_seed002_choice_by_objective():
    # The seed picks the smallest pitch that passes: 31.75 mm with two strands (its estimate
    # 30.35 mm) against 38.1 mm with one (estimate 36.23 mm). That is the smallest-sprocket choice.
    small = chain.design(**SEED, objective="min_sprocket_diameter")
    assert small.best["designation"] == "2PR-31,75-177"
    # Lightest per metre: PR-38.1 (5.5 kg/m) beats 2PR-31.75 (7.3 kg/m, GOST 13568-75 masses);
    # its pressure F·K_e/A with A = 395 mm2 and v = 13·38.1·120/60000 stays under 29 MPa
    light = chain.design(**SEED)
    assert light.best["designation"] == "PR-38,1-127"
    v = 13 * 38.1 * 120 / 60000
    assert 380 * 2 * math.pi * 2 / v * 2.148 / 395 < 29


def test_seed002_sprocket_geometry():
    # seed 002, 1.9.6: d = t/sin(180/z) = 132.67, De = t(0.5 + ctg(180/z)) = 144.69, Di = d - 2(0.5025·d1 + 0.05) = 113.43
    r = chain.design(**SEED, objective="min_sprocket_diameter")
    b = r.best
    assert b["sprocket1_pitch_diameter_mm"] == pytest.approx(132.67, abs=0.005)
    assert b["sprocket1_tip_diameter_mm"] == pytest.approx(144.69, abs=0.005)
    assert b["sprocket1_root_diameter_mm"] == pytest.approx(113.43, abs=0.015)


def test_seed002_link_count_slip():
    # The seed counts links with l = (3a + π·d)/t (a three-sided loop around its layout), 30 links,
    # a = 178.57 mm. For the two-sprocket drive the tool designs, L = 2a/t + (z1 + z2)/2 + 0:
    seed_links = (3 * 180 + 3.14 * 132.67) / 31.75
    assert seed_links == pytest.approx(30.13, abs=0.005)  # the seed prints 30.14, a rounding slip; either way 30
    two_sprocket = 2 * 180 / 31.75 + 13
    assert sprocket.link_count(180, 31.75, 13, 13) == pytest.approx(two_sprocket)
    assert sprocket.even_links(two_sprocket) == 24
    # z1 = z2: a = t·(L - z)/2 exactly
    assert sprocket.center_distance_for_links_mm(24, 31.75, 13, 13) == pytest.approx(31.75 * 11 / 2)
    r = chain.design(**SEED, center_distance_mm=180, objective="min_sprocket_diameter")
    assert r.best["links"] == 24 and r.best["center_distance_mm"] == pytest.approx(174.625)


def test_bhandari_14_3_links_and_centre_distance():
    # Bhandari Ex. 14.3: p = 12.7, z1 = 21, z2 = 63, a = 500 -> Ln = 121.875 -> 122, a = 500.804717 mm; chain 08A
    r = chain.design(power_kw=5, n1_rpm=1400, ratio=3, z1=21, k_e=1.3, catalog="iso606a", strands=(1,),
                     center_distance_mm=500, method="power_rating")
    row = r.candidates[r.candidates["designation"] == "08A"].iloc[0]
    assert row["links"] == 122
    assert row["center_distance_mm"] == pytest.approx(500.804717, abs=1e-6)
    assert r.best["designation"] == "08A"


def test_bhandari_14_4_diameters_and_distance():
    # Bhandari Ex. 14.4: 12B, z = 17/34: D1 = 103.673741, D2 = 206.462975, Ln = 105.683 -> 106 at a = 40p,
    # a = 763.496160 mm after a 0.2 % sag allowance
    assert sprocket.pitch_diameter_mm(19.05, 17) == pytest.approx(103.673741, abs=1e-6)
    assert sprocket.pitch_diameter_mm(19.05, 34) == pytest.approx(206.462975, abs=1e-6)
    assert sprocket.link_count(40 * 19.05, 19.05, 17, 34) == pytest.approx(105.683, abs=1e-3)
    assert sprocket.center_distance_for_links_mm(106, 19.05, 17, 34) * 0.998 == pytest.approx(763.496160, abs=1e-5)


def test_bhandari_14_1_safety_factor():
    # Bhandari Ex. 14.1: 12A, z1 = 17, n1 = 1000, Q = 31 100 N, rating 14.32 kW -> fs = 11.722224
    v = 17 * 19.05 * 1000 / 60000
    fs = chain.safety_factor(31100, 14320 / v, 1.0, 0.0, v, 0.0)
    assert fs == pytest.approx(11.722224, abs=1e-6)


def test_bhandari_14_2_design_power_with_strand_factor():
    # Bhandari Ex. 14.2: 30 kW, η = 0.9, Ks = 1.4, four strands K1 = 3.3: required rating 11.454545 kW
    factors = load_catalog("chain_strand_factors").set_index("strands")
    assert 30 * 0.9 * 1.4 / factors.loc[4, "power_strand_factor"] == pytest.approx(11.454545, abs=1e-6)


def test_power_rating_uses_ansi_formulas():
    # ANSI link-plate HP = 0.004·N^1.08·n^0.9·p^(3-0.07p), roller-bushing HP = 1000·17·N^1.5·p^0.8/n^1.5 (p in inches)
    r = chain.design(power_kw=5, n1_rpm=1400, ratio=3, z1=21, k_e=1.3, catalog="iso606a", strands=(1, 2),
                     method="power_rating")
    row = r.candidates[r.candidates["designation"] == "10A-2"].iloc[0]
    p = 0.625
    plate = 0.004 * 21 ** 1.08 * 1400 ** 0.9 * p ** (3 - 0.07 * p)
    roller = 1000 * 17 * 21 ** 1.5 * p ** 0.8 / 1400 ** 1.5
    assert row["rated_power_kw"] == pytest.approx(min(plate, roller) * 0.745699872 * 1.7)
    assert row["design_power_kw"] == pytest.approx(5 * 1.3)


def test_allowable_pressure_interpolates_and_never_extrapolates():
    # table (catalogs/chain_allowable_pressure.csv): 31.75-38.1 mm group: 35 MPa at 50 rpm, 29 at 200, 15 at 1200
    assert chain.allowable_pressure_mpa(38.1, 80) == (pytest.approx(35 + (29 - 35) * 30 / 150), 0)
    value, status = chain.allowable_pressure_mpa(31.75, 1500)
    assert math.isnan(value) and status == 1
    r = chain.design(torque_nm=50, n1_rpm=900, ratio=2, z1=21, strands=(1,))
    high = r.candidates[r.candidates["pitch_mm"] == 44.45]
    # 44.45-50.8 group stops at 800 rpm -> no [p] data; the 44.45 pitch also exceeds its 600 rpm limit
    assert high["allowable_pressure_mpa"].isna().all() and not high["feasible"].any()
    assert any("above the [p] table" in n for n in r.notes)
    slow = chain.design(torque_nm=380, n1_rpm=30, ratio=1, z1=13, strands=(1,))
    assert any("below the [p] table" in n for n in slow.notes)
    assert slow.candidates["allowable_pressure_mpa"].max() == 35.0


def test_free_z1_follows_the_rule():
    # z1 = 29 - 2u: u = 1 -> 27; candidates are the odd counts 13..27
    r = chain.design(torque_nm=380, n1_rpm=120, ratio=1, k_e=2.148, allowable_pressure_mpa=29)
    assert sorted(r.candidates["z1"].unique()) == list(range(13, 28, 2))
    assert chain.recommended_z1(1) == 27 and chain.recommended_z1(2.5) == 25 and chain.recommended_z1(9) == 13


def test_no_candidate_says_what_stops_each_family():
    r = chain.design(torque_nm=20000, n1_rpm=120, ratio=1, z1=13, k_e=2.148, allowable_pressure_mpa=29, strands=(1, 2))
    assert not r.success and r.best is None
    assert "no candidate passes" in r.message
    assert set(r.blocking["designation"]) == set(r.candidates["designation"])
    assert (r.blocking["limiting_check"] == "pressure").all() and (r.blocking["min_margin"] < 0).all()


def test_result_object():
    r = chain.design(**SEED)
    text = repr(r)
    assert "PR-38,1-127" in text and "margins" in text
    d = r.to_dict()
    json.dumps(d)
    assert d["best"]["designation"] == "PR-38,1-127" and d["n_candidates"] == len(r.to_frame())
    for col in ("designation", "pitch_mm", "strands", "z1", "z2", "links", "center_distance_mm", "speed_m_s",
                "force_n", "pressure_mpa", "allowable_pressure_mpa", "safety_factor", "allowable_safety_factor",
                "mass_kg_m", "feasible"):
        assert col in r.candidates.columns
    # links are even and the centre distance is exact for them
    c = r.candidates
    assert (c["links"] % 2 == 0).all()
    np.testing.assert_allclose(sprocket.link_count(c["center_distance_mm"], c["pitch_mm"], c["z1"], c["z2"]), c["links"])


def test_catalogs_all_run():
    for cat in ("gost13568", "iso606", "iso606a", "iso606b", "ansi_b29"):
        r = chain.design(power_kw=4, n1_rpm=200, ratio=2, catalog=cat, strands=(1, 2, 3)
                         if cat != "ansi_b29" else (1,))
        assert len(r.candidates) > 0


@pytest.mark.parametrize("kwargs, match", [
    (dict(torque_nm=-380), r"torque_nm must be in \[0.001, 1e\+07\] N·m, got -380"),
    (dict(torque_nm=380, power_kw=3), "exactly one of torque_nm or power_kw"),
    (dict(torque_nm=380, catalog="din8187"), "catalog must be one of"),
    (dict(torque_nm=380, objective="cheap"), "objective must be one of"),
    (dict(torque_nm=380, ratio=0.5), r"ratio must be in \[1, 10\]"),
    (dict(torque_nm=380, ratio=10, z1=13), "z2_max"),
    (dict(torque_nm=380, strands=(5,)), "strands"),
    (dict(torque_nm=380, n1_rpm=5000), "above the maximum speed of every chain"),
    (dict(torque_nm=380, k_e=2, conditions={"k_d": 1.2}), "not both"),
    (dict(torque_nm=380, conditions={"k_lub": "greasy"}), "conditions"),
])
def test_bad_input(kwargs, match):
    args = dict(n1_rpm=120, ratio=1)
    args.update(kwargs)
    with pytest.raises(GearDesignError, match=match):
        chain.design(**args)
