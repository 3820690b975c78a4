"""The measuring-size formulas (geardesign.gears.measurement_formulas), each against a published worked example
(tests/data/measurement_examples.csv: MachineCalcs' span example, SDP/SI T-81 Tables 10-1 and 10-3) and the
textbook closed forms written out here (ISO 21771:2007 §5.5-5.7, DIN 3960)."""
import math
from pathlib import Path

import pandas as pd
import pytest

from geardesign.gears import measurement_formulas as mf

DATA = pd.read_csv(Path(__file__).parents[1] / "data" / "measurement_examples.csv")
A20 = math.radians(20)


def published(example, quantity):
    row = DATA[(DATA.example_id == example) & (DATA.quantity == quantity)].iloc[0]
    return pytest.approx(row.published_value, abs=0.6 * 10.0 ** -row.digits)    # to the printed digits


def inv(a):
    return math.tan(a) - a


def test_span_of_the_machinecalcs_example():
    w_k = mf.base_tangent_length(2, 20, 0.0, 3, A20, A20)
    assert w_k == published("MC_span_20", "w_k")
    # W_k = m cos α (π (k − 0.5) + z inv α) + 2 x m sin α (ISO 21771:2007 §5.6, spur)
    assert w_k == pytest.approx(2 * math.cos(A20) * (math.pi * 2.5 + 20 * inv(A20)), rel=1e-14)
    assert mf.span_contact_diameter(w_k, 40 * math.cos(A20), 1.0) == published("MC_span_20", "d_wk")


def test_thickness_and_chord_of_sdp_table_10_1():
    s_n = mf.normal_tooth_thickness(10, 0.3, A20)          # m 10, z 12, x 0.3
    assert s_n == published("SDP_T81_10_1", "s_n")
    assert s_n == pytest.approx(10 * (math.pi / 2 + 2 * 0.3 * math.tan(A20)), rel=1e-15)
    assert mf.chordal_thickness(120.0, s_n) == published("SDP_T81_10_1", "s_chord")
    h_a = 10 * (1 + 0.3)
    assert mf.chordal_height(120.0, s_n, h_a) == published("SDP_T81_10_1", "h_chord")


def test_virtual_gear_of_sdp_table_10_3():
    # helical m_n 5, z 16, β 25°, x 0.2: SDP/SI uses z_v = z/cos³β, ISO 21771 z_n = z/(cos²β_b cos β)
    beta = math.radians(25)
    assert 16 / math.cos(beta) ** 3 == published("SDP_T81_10_3", "z_v")
    alpha_t = math.atan(math.tan(A20) / math.cos(beta))
    cos_bb = math.cos(math.atan(math.tan(beta) * math.cos(alpha_t)))
    d_n = mf.virtual_diameter(5, 16, math.cos(beta), cos_bb)
    assert d_n == pytest.approx(5 * 16 / (cos_bb ** 2 * math.cos(beta)), rel=1e-15)
    assert mf.normal_tooth_thickness(5, 0.2, A20) == published("SDP_T81_10_3", "s_n")


@pytest.mark.parametrize("z", [20, 21])
def test_dimension_over_balls_closed_form(z):
    d_m, ball = 2.0 * z + 1.7, 3.5
    want = d_m + ball if z % 2 == 0 else d_m * math.cos(math.pi / (2 * z)) + ball      # DIN 3960 eq. 3.6.6-7
    assert mf.dimension_over_balls(d_m, ball, z) == pytest.approx(want, rel=1e-15)
    assert mf.dimension_over_balls(d_m, ball, z, internal=True) == pytest.approx(want - 2 * ball, rel=1e-15)


def test_generating_shift_of_an_allowance():
    # a thickness allowance A_s moves the generating rack by x_E m = A_s/(2 tan α): x_E = x + A_s/(2 m tan α)
    assert mf.generating_shift(0.1, -0.1, 2.5, A20) == pytest.approx(0.1 - 0.1 / (2 * 2.5 * math.tan(A20)), rel=1e-14)
