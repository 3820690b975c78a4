"""Load factors (geardesign.gears.strength.factors, ISO 6336-1:2019), each from its formula with the printed
inputs of ISO/TR 6336-30:2017 example 1 against the printed result (tests/data/iso6336_tr30_example1.md), and
the closed forms written out here."""
import math
from pathlib import Path

import pandas as pd
import pytest

from geardesign.gears.strength import factors as kf

TR30 = pd.read_csv(Path(__file__).parents[2] / "data" / "iso6336_tr30_example1.csv").set_index("quantity")
D1 = 8 * 17 / math.cos(math.radians(15.8))      # the pinion's reference diameter, m_n z / cos β = 141.3401 mm


def printed(q):
    return pytest.approx(float(TR30.loc[q, "value"]), rel=float(TR30.loc[q, "rel_tol"]))


def test_force_and_speed_of_the_tr30_example():
    assert D1 == pytest.approx(141.3401, abs=1e-4)
    assert float(kf.tangential_load(9000, D1)) == printed("F_t")           # F_t = 2000 T/d
    assert float(kf.pitch_line_velocity(D1, 360)) == printed("v")          # v = π d n / 60 000


def test_stiffness_of_the_tr30_example():
    c_th = kf.theoretical_single_stiffness(float(TR30.loc["z_n1", "value"]), float(TR30.loc["z_n2", "value"]),
                                           0.145, 0.0)
    assert float(c_th) == printed("c_th")
    # profile D of ISO 53: h_fP = 1.4 m_n; C_B = 1 + 0.5 (1.2 − h_fP/m_n) for α_n = 20° (ISO 6336-1:2019, C_B)
    assert float(kf.basic_rack_factor(1.4)) == pytest.approx(1 + 0.5 * (1.2 - 1.4), rel=1e-15)
    c_prime = kf.single_stiffness(float(TR30.loc["c_th", "value"]), 0.9, 15.8, 1273.5)
    assert float(c_prime) == printed("c_prime")
    c_ga, c_gb = kf.mesh_stiffness(float(TR30.loc["c_prime", "value"]), 1.54908)
    assert float(c_ga) == printed("c_gamma_alpha") and float(c_gb) == printed("c_gamma_beta")
    # c_γα = c′ (0.75 ε_α + 0.25), c_γβ = 0.85 c_γα (ISO 6336-1:2019, mesh stiffness)
    assert float(c_ga) == pytest.approx(12.37047 * (0.75 * 1.54908 + 0.25), rel=1e-14)
    assert float(c_gb) == pytest.approx(0.85 * float(c_ga), rel=1e-14)


def test_resonance_closed_forms():
    # n_E1 = 30 000/(π z1) sqrt(c_γα/m_red); N = n1/n_E1 (ISO 6336-1:2019 eq. (28), (29))
    assert float(kf.resonance_speed(20, 20.0, 0.02786)) == pytest.approx(30_000 / (math.pi * 20) * math.sqrt(20 / 0.02786),
                                                                         rel=1e-14)
    assert float(kf.resonance_ratio(360, 7200)) == 0.05
    # m_red = (π/8)(d_m1/d_b1)² d_m1² / (1/ρ1 + 1/(ρ2 u²)) for solid steel gears (eq. (30))
    rho = 7.83e-6
    want = math.pi / 8 * (100 / 93.97) ** 2 * 100 ** 2 / (1 / rho + 1 / (rho * 4))
    assert float(kf.reduced_mass(100.0, 93.97, 2.0, rho1=rho, rho2=rho)) == pytest.approx(want, rel=1e-14)


def test_dynamic_factor_is_one_plus_nk_below_resonance():
    # subcritical: K_v = N K + 1 with K = C_v1 B_p + C_v2 B_f + C_v3 B_k (ISO 6336-1:2019 eq. (33))
    cv = kf.dynamic_coefficients(2.6)
    N, bp, bf, bk = 0.05, 0.0311, 0.0543, 0.04
    k = float(cv[0]) * bp + float(cv[1]) * bf + float(cv[2]) * bk
    assert float(kf.dynamic_factor(N, 2.6, bp, bf, bk, 1273.5)) == pytest.approx(N * k + 1, rel=1e-14)
    # ISO 6336-1:2019 Table 7 for 1 < ε_γ <= 2: C_v1 = 0.32, C_v2 = 0.34, C_v3 = 0.23
    assert [round(float(c), 2) for c in kf.dynamic_coefficients(1.5)[:3]] == [0.32, 0.34, 0.23]
