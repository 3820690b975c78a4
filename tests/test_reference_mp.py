"""The 50-digit reference itself against published worked examples, before it judges the library.

E9 (tests/data/gear_examples.csv): the ISO 21771:2007 helical spreadsheet (m_n 3.5, z 31/30, β 21°,
a_w 116.5 mm given, so x1 + x2 = 0.651877131252): α_t, a, α_wt, inv α_t, inv α_wt to the digits printed.
"""
from pathlib import Path

import mpmath as mp
import pandas as pd
import pytest

from tests.reference_mp import inv, pair_reference

DATA = pd.read_csv(Path(__file__).parent / "data" / "gear_examples.csv")
E9 = DATA[DATA.example_id == "E9_ISO21771_helical_31_30"]


def _digits(text) -> int:
    text = str(text)
    return len(text.split(".")[1]) if "." in text else 0


@pytest.mark.parametrize("parameter, published", [(r.parameter, r.published_value) for r in E9.itertuples()
                                                  if r.parameter != "x_sum_generating_with_backlash"])
def test_helical_reference_reproduces_the_iso_21771_example(parameter, published):
    x_sum = float(E9[E9.parameter == "x_sum"].published_value.iloc[0])
    fields, _ = pair_reference(3.5, 31, 30, x_sum / 2, x_sum / 2, beta_deg=21.0)
    value = {"alpha_t_deg": fields["alpha_t_deg"], "a_ref": fields["a"], "alpha_wt_deg": fields["alpha_w_deg"],
             "inv_alpha_wt": fields["inv_alpha_w"], "inv_alpha_t": inv(mp.radians(fields["alpha_t_deg"])),
             "x_sum": mp.mpf(x_sum) if abs(fields["a_w"] - mp.mpf("116.5")) < 1e-9 else mp.nan}[parameter]
    assert abs(float(value) - float(published)) <= 0.5 * 10.0 ** -_digits(published) + 1e-15, (parameter, value)


def test_beta_zero_is_the_spur_reference():
    spur, _ = pair_reference(8, 17, 26, 0.898, 0.517)
    helix0, _ = pair_reference(8, 17, 26, 0.898, 0.517, beta_deg=0.0, face_width_mm=60)
    for name, v in spur.items():
        assert abs(helix0[name] - v) <= mp.mpf(10) ** -45 * max(1, abs(v)), name
    assert helix0["eps_beta"] == 0 and helix0["z_n1"] == 17 and helix0["san1"] == spur["sa1"]
