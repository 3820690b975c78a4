"""Roller-chain candidates, operating factors, catalogs and input checks
(geardesign.drives.chain.candidates). Every number is recomputed by hand here (formula written out) or taken
from a cited source: seed 002 (the brake test stand course work) and Bhandari's worked examples (both in
docs/references.md), or the catalog tables."""
import math

import pytest

from geardesign import chain
from geardesign.catalogs import load_catalog
from geardesign.errors import GearDesignError
from tests.drives.chain import SEED


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
