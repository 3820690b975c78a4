"""Helical pairs drawn in the transverse section (issue 14 with issue 12): the generated transverse
tooth has the thicknesses of ISO 21771 (s_t = m_t (π/2 + 2 x_n tan α_n) at the reference circle,
the transverse tip thickness of the 50-digit reference at the tip). Helical rings: tests/profiles/test_ring.py."""
import math

import pytest

import geardesign as gd
from geardesign.profiles.mesh import transverse_rack
from tests.reference_mp import pair_reference


@pytest.mark.parametrize("beta, x", [(10.0, 0.0), (25.0, 0.4), (40.0, -0.2)])
def test_transverse_tooth_has_the_iso_thickness_at_the_reference_circle(beta, x):
    m, z = 3.0, 23
    rack, cb = transverse_rack(gd.BasicRack(), beta)
    m_t = m / cb
    p = gd.tooth_profile(m_t, z, x * cb, rack=rack, tip_diameter_mm=m_t * z)
    s_t = m_t * (math.pi / 2 + 2 * x * math.tan(math.radians(20)))
    assert p.tip_thickness_mm == pytest.approx(s_t, rel=1e-12)


@pytest.mark.parametrize("beta", [8.0, 20.0, 33.0])
def test_mesh_profiles_have_the_reference_tip_thickness(beta):
    pair = gd.GearPair(2.5, 17, 41, 0.35, -0.1, beta_deg=beta)
    ref, why = pair_reference(2.5, 17, 41, 0.35, -0.1, beta_deg=beta)
    assert ref is not None, why
    p1, p2 = gd.pair_profiles(pair)
    assert p1.tip_thickness_mm == pytest.approx(float(ref["sa1"]), rel=1e-10)
    assert p2.tip_thickness_mm == pytest.approx(float(ref["sa2"]), rel=1e-10)
