"""Roller-chain formulas (geardesign.drives.chain.formulas). Every number is recomputed by hand here (formula
written out) or taken from a cited source: seed 002 (the brake test stand course work) and Bhandari's worked
examples (both in docs/references.md), or the catalog tables."""
import math

import pytest

from geardesign import chain
from tests.drives.chain import SEED


def test_seed002_pitch_estimate():
    # seed 002, 1.9.5: t >= 28·cbrt(T1·K/([p]·z1·m·K_m)), T in N·m: 36.23 mm (m = 1) and 30.35 mm (m = 2, K_m = 0.85)
    one = 28 * (380 * 2.1484 / (29 * 13 * 1 * 1)) ** (1 / 3)
    two = 28 * (380 * 2.1484 / (29 * 13 * 2 * 0.85)) ** (1 / 3)
    assert round(one, 2) == 36.23 and round(two, 2) == 30.35
    assert chain.pitch_estimate_mm(380, 13, 29, 2.1484, 1.0) == pytest.approx(one)
    assert chain.pitch_estimate_mm(380, 13, 29, 2.1484, 1.7) == pytest.approx(two)
    r = chain.design(**SEED)
    assert r.pitch_estimate_mm[1] == pytest.approx(28 * (380 * 2.148 / (29 * 13)) ** (1 / 3))


def test_bhandari_14_1_safety_factor():
    # Bhandari Ex. 14.1: 12A, z1 = 17, n1 = 1000, Q = 31 100 N, rating 14.32 kW -> fs = 11.722224
    v = 17 * 19.05 * 1000 / 60000
    fs = chain.safety_factor(31100, 14320 / v, 1.0, 0.0, v, 0.0)
    assert fs == pytest.approx(11.722224, abs=1e-6)


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
