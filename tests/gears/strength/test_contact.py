"""Contact-stress factors (geardesign.gears.strength.contact, ISO 6336-2:2019), each from its formula with the
printed inputs of ISO/TR 6336-30:2017 example 1 against the printed result (tests/data/iso6336_tr30_example1.md),
and the closed forms written out here."""
import math
from pathlib import Path

import pandas as pd
import pytest

from geardesign.gears.strength import contact as zc

TR30 = pd.read_csv(Path(__file__).parents[2] / "data" / "iso6336_tr30_example1.csv").set_index("quantity")


def printed(q):
    return pytest.approx(float(TR30.loc[q, "value"]), rel=float(TR30.loc[q, "rel_tol"]))


def test_zone_factor_closed_form():
    # Z_H = sqrt(2 cos β_b cos α_wt / (cos² α_t sin α_wt)) (ISO 6336-2:2019 eq. (9)); a spur pair at α = 20°
    assert float(zc.zone_factor(0, 20, 20)) == pytest.approx(math.sqrt(2 / (math.cos(math.radians(20)) *
                                                                          math.sin(math.radians(20)))), rel=1e-14)
    b, t, w = 14.8, 20.7, 23.1
    r = math.radians
    want = math.sqrt(2 * math.cos(r(b)) * math.cos(r(w)) / (math.cos(r(t)) ** 2 * math.sin(r(w))))
    assert float(zc.zone_factor(b, t, w)) == pytest.approx(want, rel=1e-14)


def test_elasticity_factor_of_steel_on_steel():
    assert float(zc.elasticity_factor(206000, 0.3, 206000, 0.3)) == printed("Z_E")
    # Z_E = sqrt(1 / (π ((1 − ν1²)/E1 + (1 − ν2²)/E2))) (ISO 6336-2:2019 eq. (10)): steel on grey iron
    want = math.sqrt(1 / (math.pi * ((1 - 0.3 ** 2) / 206000 + (1 - 0.3 ** 2) / 118000)))
    assert float(zc.elasticity_factor(206000, 0.3, 118000, 0.3)) == pytest.approx(want, rel=1e-14)


def test_factors_of_the_tr30_example():
    assert float(zc.helix_angle_factor(15.8)) == printed("Z_beta")
    assert float(zc.contact_ratio_factor(1.54908, 1.0835)) == printed("Z_eps")
    assert float(zc.lubricant_factor(320, 1500)) == printed("Z_L1")
    assert float(zc.velocity_factor(2.6642, 1500)) == printed("Z_v1")


def test_stresses_of_the_tr30_example():
    v = {q: float(TR30.loc[q, "value"]) for q in TR30.index}
    sigma_h0 = zc.nominal_contact_stress(v["F_t"], 141.3401, 100.0, 103 / 17, v["Z_H"], v["Z_E"], v["Z_eps"],
                                         v["Z_beta"])
    assert float(sigma_h0) == pytest.approx(v["sigma_H0"], rel=1e-3)     # Z_eps printed as 0.803 (0.80346)
    sigma_h = zc.contact_stress(v["sigma_H0"], v["Z_B"], 1.0, 1.0, v["K_v"], v["K_Hbeta"], v["K_Halpha"])
    assert float(sigma_h) == pytest.approx(v["sigma_H1"], rel=2e-4)      # K_v printed as 1.003
    limit = zc.contact_stress_limit(1500, v["Z_NT1"], v["Z_L1"], v["Z_v1"], v["Z_R1"], v["Z_W1"])
    assert float(limit) == pytest.approx(v["sigma_HG1"], rel=1e-3)      # Z_NT1 printed as 0.91
    assert float(limit) / float(sigma_h) == pytest.approx(v["S_H1"], rel=2e-3)


def test_work_hardening_is_one_unless_it_applies():
    assert float(zc.work_hardening_factor(300, False)) == 1.0
    # ISO 6336-2:2006 eq. (29): Z_W = 1.2 − (HB − 130)/1700 for 130 <= HB <= 470, 1.2 below, 1.0 above
    assert float(zc.work_hardening_factor(300, True)) == pytest.approx(1.2 - (300 - 130) / 1700, rel=1e-12)
    assert float(zc.work_hardening_factor(100, True)) == pytest.approx(1.2, rel=1e-12)
    assert float(zc.work_hardening_factor(500, True)) == pytest.approx(1.0, rel=1e-12)
