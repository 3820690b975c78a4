"""Every margin of a chain candidate (geardesign.drives.chain.checks), recomputed here by hand for seed 002's
two-strand 2PR-31,75-177 on z1 = z2 = 13 at 120 rpm with K_e = 2.148 (its sections 1.9.3-1.9.5), from the
formulas of Chernavsky's course design (F_t = P/v with the chain's mean speed v = z1 p n1/60 000, p = F_t K_e/(A m_eff), s = Q/(K_d F_t + q v² +
9.81 k_f q a), w = 4 z1 n1/(60 W)) and the catalogs' rows ([p] interpolated in speed, [s], n1_max, [w])."""
import math

import pytest

from geardesign.drives import chain

T1 = 4000 / (1500 * math.pi / 30) * 12.5 * 0.87        # seed 002's torque on the small sprocket, N·m


@pytest.fixture(scope="module")
def row():
    r = chain.design(torque_nm=T1, n1_rpm=120, ratio=1, z1=13, k_e=2.148)
    return r.candidates.set_index("designation").loc["2PR-31,75-177"]


def test_force_and_speed(row):
    d1 = 31.75 / math.sin(math.pi / 13)
    assert row.sprocket1_pitch_diameter_mm == pytest.approx(d1, rel=1e-14)
    v = 13 * 31.75 * 120 / 60_000
    assert row.speed_m_s == pytest.approx(v, rel=1e-12)
    assert row.force_n == pytest.approx(T1 * 2 * math.pi * 120 / 60 / v, rel=1e-12)     # F_t = P/v


def test_hinge_pressure_margin(row):
    p = row.force_n * 2.148 / (row.hinge_area_mm2 * 2 * 0.85)       # m_eff = 2 strands × K_m 0.85 = 1.7
    assert row.pressure_mpa == pytest.approx(p, rel=1e-14)
    allowable = 35 + (120 - 50) / (200 - 50) * (29 - 35)             # [p] at 31.75 mm: 35 MPa at 50, 29 at 200 rpm
    assert row.allowable_pressure_mpa == pytest.approx(allowable, rel=1e-14)
    assert row.margin_pressure == pytest.approx(1 - p / allowable, rel=1e-13)


def test_safety_margin(row):
    q, v, a_m = row.mass_kg_m, row.speed_m_s, row.center_distance_mm / 1000
    s = 177_000 / (1.0 * row.force_n + q * v ** 2 + 9.81 * 6.0 * q * a_m)    # K_d = 1: K_e given as one number
    assert row.safety_factor == pytest.approx(s, rel=1e-13)
    assert row.margin_safety == pytest.approx(s / row.allowable_safety_factor - 1, rel=1e-13)


def test_speed_and_impact_margins(row):
    assert row.margin_speed == pytest.approx(1 - 120 / row.n1_max_rpm, rel=1e-14)
    w = 4 * 13 * 120 / (60 * row.links)
    assert row.impacts_per_s == pytest.approx(w, rel=1e-14)
    assert row.margin_impacts == pytest.approx(1 - w / row.allowable_impacts_per_s, rel=1e-14)


def test_the_limiting_check_is_the_smallest_margin(row):
    margins = {k: row[f"margin_{k}"] for k in ("pressure", "safety", "speed", "impacts")}
    assert row.limiting_check == min(margins, key=margins.get)
    assert row.min_margin == pytest.approx(min(margins.values()), rel=1e-15)
    assert row.feasible == (row.min_margin >= 0)
