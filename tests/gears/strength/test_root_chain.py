"""The root stresses and their limit (geardesign.gears.strength.root_chain, ISO 6336-3:2019 eq. (1)-(5)) from the
factors a KISSsoft 03/2017 report of the NREL 5 MW gearbox prints for stage 3's pinion, against the stresses
it prints (tests/data/iso6336_root_kisssoft.md)."""
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from geardesign.gears.strength import root_chain as rc

DATA = Path(__file__).parents[2] / "data"
PRINTED = pd.read_csv(DATA / "iso6336_root_kisssoft_printed.csv").query("case == 's3_gear1'").set_index("quantity")
FACTORS = pd.read_csv(DATA / "iso6336_root_kisssoft_factors.csv").query("report == 'stage_03' and gear == 'gear 1'")
CASE = pd.read_csv(DATA / "iso6336_root_kisssoft_cases.csv").set_index("case").loc["s3_gear1"]


def _factor(q):
    return float(FACTORS.set_index("quantity").loc[q, "value"])


def test_nominal_root_stress_of_the_nrel_stage_3_pinion():
    form = float(PRINTED.loc["Y_F", "value"]) * float(PRINTED.loc["Y_S", "value"]) * _factor("Y_beta")   # Y_B = Y_DT = 1
    got = rc.nominal_root_stress(float(CASE["F_t_N"]), float(CASE["b_mm"]), float(CASE["m_n"]), form)
    # Y_F and Y_S are printed to 2 decimals (±0.4 % and ±0.2 %): the printed σ_F0 within their rounding
    assert float(got) == pytest.approx(float(PRINTED.loc["sigma_F0", "value"]), rel=6e-3)


def test_root_stress_limit_of_the_nrel_stage_3_pinion():
    # σ_FG = σ_Flim Y_ST Y_NT Y_δrelT Y_RrelT Y_X with σ_Flim = 430 MPa (the report's Eh material), Y_ST = 2
    got = rc.root_stress_limit(430.0, _factor("Y_NT"), _factor("Y_deltarelT"), _factor("Y_RrelT"), _factor("Y_X"))
    printed = float(FACTORS.set_index("quantity").loc["sigma_FG", "value"])
    assert float(got) == pytest.approx(printed, rel=5e-4)     # the factors are printed to 3 decimals


def test_loaded_stress_is_the_nominal_times_the_load_factors():
    f_t, b, m_n, form = np.array([1e4, 2e5]), np.array([50.0, 360.0]), 4.0, 2.2 * 1.9
    k = dict(K_A=1.25, K_gamma=1.1, K_v=1.05, K_Fbeta=1.2, K_Falpha=1.1)
    want = f_t / (b * m_n) * form * 1.25 * 1.1 * 1.05 * 1.2 * 1.1
    assert np.allclose(rc.root_stress(f_t, b, m_n, form, *k.values()), want, rtol=1e-15, atol=0)
    assert rc.Y_ST == 2.0     # the reference test gear's stress correction factor (ISO 6336-3:2019 clause 9)
