"""Internal pairs through the chain: the contact side written out here from pair_geometry's geometry (ISO
6336-2 with u < 0 in ISO's sign, i.e. (u − 1)/u for the ring's positive count), Z_D = 1, the ring's mass
infinite in m_red, and the ring's root by the form-factor module's internal treatment."""
import math

import pytest

from geardesign.gears.geometry import pair_geometry
from geardesign.gears.strength import Load, pair_strength


@pytest.mark.parametrize("beta", [0.0, 12.0])
def test_internal_contact_side_written_out(beta):
    m, z1, z2, x1, x2, b = 3.0, 20, 71, 0.2, 0.3, 35.0
    out = pair_strength(m, z1, z2, x1, x2, load=Load(torque_nm=250, n_rpm=1200, life_h=1e4), material1="18CrNiMo7-6",
                        face_width_mm=b, beta_deg=beta, internal=True, factors={"K_v": 1.1, "K_Hbeta": 1.2})
    g = pair_geometry(m, z1, z2, x1, x2, beta_deg=beta, internal=True)
    awt = math.acos(g.db1 / g.dw1)
    at = math.atan(math.tan(math.radians(20)) / math.cos(math.radians(beta)))
    bb = math.atan(math.tan(math.radians(beta)) * math.cos(at))
    ZH = math.sqrt(2 * math.cos(bb) * math.cos(awt) / (math.cos(at) ** 2 * math.sin(awt)))
    eb = b * math.sin(math.radians(beta)) / (math.pi * m)
    ebc = min(eb, 1.0)
    Ze = math.sqrt((4 - g.eps_alpha) * (1 - ebc) / 3 + ebc / g.eps_alpha)
    u = z2 / z1
    Ft = 2000 * 250 / g.d1
    s0 = ZH * 189.81170043756651 * Ze / math.sqrt(math.cos(math.radians(beta))) * math.sqrt(Ft / (g.d1 * b) * (u - 1) / u)
    assert float(out["sigma_H0"]) == pytest.approx(s0, rel=1e-12)
    assert float(out["Z_D"]) == 1.0
    dm1 = (g.da1 + g.df1) / 2
    assert float(out["m_red"]) == pytest.approx(math.pi / 8 * (dm1 / g.db1) ** 2 * dm1 ** 2 * 7.83e-6, rel=1e-12)
    assert math.isfinite(float(out["S_F2"])) and float(out["Y_F2"]) > 0


def test_internal_pair_is_less_stressed_than_the_external_one():
    """Same pinion and counts: the concave ring flank gives a larger ρ_red, so a lower σ_H0 (a property of
    (u − 1)/u < (u + 1)/u and of Z_H at the same operating angle)."""
    kw = dict(load=Load(torque_nm=250, n_rpm=1200), material1="18CrNiMo7-6", face_width_mm=35,
              factors={"K_v": 1.1, "K_Hbeta": 1.2, "Z_H": 2.4, "Z_eps": 0.9})
    ext = pair_strength(3.0, 20, 71, 0.0, 0.0, **kw)
    ring = pair_strength(3.0, 20, 71, 0.0, 0.0, internal=True, **kw)
    assert float(ring["sigma_H0"]) / float(ext["sigma_H0"]) == pytest.approx(math.sqrt((71 - 20) / (71 + 20)), rel=1e-12)
