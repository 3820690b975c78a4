"""A StrengthResult names its inputs (issue 35 §6: a report must let a reader compute σ_HP and σ_FP again)."""
import math

import pytest

import geardesign as gd
from geardesign.gears.strength import Load, strength


def _factor(r, symbol, gear):
    f = r.factors
    return float(f.loc[(f["symbol"] == symbol) & (f["gear"] == gear), "value"].iloc[0])


@pytest.mark.parametrize("grade, nu40, rz", [(7, 220.0, 6.0), (5, 100.0, 3.0)])
def test_the_case_reproduces_the_permissible_stresses(grade, nu40, rz):
    pair = gd.GearPair(4, 20, 60, 0.3, 0.1, face_width_mm=40)
    r = strength(pair, Load(torque_nm=400, n_rpm=1000, life_h=20000), "42CrMo4", material2="16MnCr5",
                 accuracy_grade=grade, nu40=nu40, Rz_flank_um=rz)
    c = r.case
    assert (c["material1"], c["material2"], c["accuracy_grade"], c["nu40_mm2_s"], c["Rz_flank_um"]) == \
        ("42CrMo4", "16MnCr5", grade, nu40, rz)
    for k in (1, 2):
        # ISO 6336-2:2019 eq. (3)/(4): σ_HP = σ_Hlim Z_NT (Z_L Z_v Z_R) Z_W Z_X / S_Hmin
        hp = (c[f"sigma_Hlim{k}_mpa"] * _factor(r, "Z_NT", k) * _factor(r, "Z_L", k) * _factor(r, "Z_v", k)
              * _factor(r, "Z_R", k) * _factor(r, "Z_W", k) * _factor(r, "Z_X", 0) / r.S_Hmin)
        assert math.isclose(hp, getattr(r, f"sigma_HP{k}"), rel_tol=1e-12)
        # ISO 6336-3:2019 eq. (3)/(4): σ_FP = σ_Flim Y_ST Y_NT Y_δrelT Y_RrelT Y_X / S_Fmin
        fp = (c[f"sigma_Flim{k}_mpa"] * 2.0 * _factor(r, "Y_NT", k) * _factor(r, "Y_deltarelT", k)
              * _factor(r, "Y_RrelT", k) * _factor(r, "Y_X", k) / r.S_Fmin)
        assert math.isclose(fp, getattr(r, f"sigma_FP{k}"), rel_tol=1e-12)
    assert r.to_dict()["case"] == c


def test_the_case_reads_options_grouped_in_one_object():
    # the strength options may come grouped in one object (pair_strength's options=); the case reads them there
    from types import SimpleNamespace

    from geardesign.gears.strength.chain import strength_case

    c = strength_case("42CrMo4", options=SimpleNamespace(accuracy_grade=5, nu40=320.0, Rz_flank_um=2.0, Rz_root_um=8.0))
    assert (c["accuracy_grade"], c["nu40_mm2_s"], c["Rz_flank_um"], c["Rz_root_um"]) == (5, 320.0, 2.0, 8.0)
    assert strength_case("42CrMo4", accuracy_grade=8)["accuracy_grade"] == 8
