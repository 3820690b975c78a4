"""The chain's pull on its shafts (geardesign.drives.chain.pull): F_B = F_t + 2 F_f along the line of centres
(Chernavsky; vunivere.ru/work4181/page2), the branch tensions, written out here on seed 002's drive."""
from __future__ import annotations

import math

import pytest

from geardesign.drives.chain import chain_pull
from geardesign.drives.chain.pull import centrifugal_tension_n, sag_factor, sag_tension_n, shaft_load_n, working_pull_n
from geardesign.errors import GearDesignError


def test_seed_002_drive_by_hand():
    """Seed 002: T1 = 380 N·m, z1 = 13, t = 31.75 mm, n1 = 120 rpm; chain of q = 3.8 kg/m at a = 1270 mm,
    horizontal. d = t/sin(180°/z), F_t = 2T/d, v = z t n/60000, F_v = q v², F_f = 9.81·6·q·a."""
    p = chain_pull(380, 31.75, 13, 120, 3.8, 1270.0)
    d = 31.75 / math.sin(math.pi / 13)
    F_t = 2000 * 380 / d
    v = 13 * 31.75 * 120 / 60000
    F_f = 9.81 * 6 * 3.8 * 1.27
    assert p.working_pull_n == pytest.approx(F_t, rel=1e-12)
    assert p.speed_m_s == pytest.approx(v, rel=1e-12)
    assert p.centrifugal_n == pytest.approx(3.8 * v * v, rel=1e-12)
    assert p.sag_n == pytest.approx(F_f, rel=1e-12)
    assert p.tight_branch_n == pytest.approx(F_t + 3.8 * v * v + F_f, rel=1e-12)
    assert p.slack_branch_n == pytest.approx(3.8 * v * v + F_f, rel=1e-12)
    assert p.shaft_load_n == pytest.approx(F_t + 2 * F_f, rel=1e-12)
    assert p.shaft1_load_n == pytest.approx((F_t + 2 * F_f, 0.0)) and p.shaft2_load_n == pytest.approx((-(F_t + 2 * F_f), 0.0))


def test_direction_and_sag_factor_from_the_layout():
    up = chain_pull(380, 31.75, 13, 120, 3.8, 1270.0, incline_deg=40.0)
    assert up.k_f == 1.5 and up.direction1 == pytest.approx((math.cos(math.radians(40)), math.sin(math.radians(40))))
    vertical = chain_pull(380, 31.75, 13, 120, 3.8, 1270.0, incline_deg=90.0)
    assert vertical.k_f == 1.0 and vertical.direction1 == pytest.approx((0.0, 1.0))
    assert float(sag_factor(20)) == pytest.approx(6.0 - 4.5 * 20 / 40)
    given = chain_pull(380, 31.75, 13, 120, 3.8, 1270.0, incline_deg=90.0, k_f=6.0)
    assert given.sag_n == pytest.approx(9.81 * 6 * 3.8 * 1.27)


def test_formulas_and_bad_inputs():
    assert float(working_pull_n(100, 200)) == 1000.0
    assert float(centrifugal_tension_n(2.0, 3.0)) == 18.0
    assert float(sag_tension_n(2.0, 500.0, 1.0)) == pytest.approx(9.81)
    assert float(shaft_load_n(1000.0, 50.0)) == 1100.0
    for kwargs, name in ((dict(torque_nm=-1), "torque_nm"), (dict(z1=3), "z1"), (dict(incline_deg=120), "incline_deg"),
                         (dict(center_distance_mm=0), "center_distance_mm")):
        args = dict(torque_nm=380, pitch_mm=31.75, z1=13, n1_rpm=120, mass_kg_m=3.8, center_distance_mm=1270.0)
        args.update(kwargs)
        with pytest.raises(GearDesignError, match=name):
            chain_pull(**args)
