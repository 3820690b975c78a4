"""The chain against ISO/TR 6336-30:2017 example 1, every printed quantity to its printed digits (the
data, its source and the reasons for the three small differences: tests/data/iso6336_tr30_example1.md)."""
import math
from pathlib import Path

import pandas as pd
import pytest

from geardesign.gears.geometry import x_sum_from_center_distance
from geardesign.gears.rack import BasicRack
from geardesign.gears.strength import Load, material, pair_strength
from geardesign.gears.strength import contact as zc
from geardesign.gears.strength import factors as kf
from geardesign.gears.strength.life import contact_life_factor, load_cycles

DATA = pd.read_csv(Path(__file__).parents[2] / "data" / "iso6336_tr30_example1.csv")
RACK_D = BasicRack(ha=1.0, c=0.4, rho_f=0.39)       # ISO 53 profile D: h_fP = 1.4 m_n, ρ_fP = 0.39 m_n
X1 = x_sum_from_center_distance(8, 17, 103, 500.0, rack=RACK_D, beta_deg=15.8)   # a_w = 500 mm, x2 = 0


def _example(**extra):
    opts = dict(load=Load(torque_nm=9000, n_rpm=360, life_h=50_000), material1=material("18CrNiMo7-6"),
                face_width_mm=100, beta_deg=15.8, rack=RACK_D, accuracy_grade=5, nu40=320, Rz_flank_um=6.0,
                tip_relief_um=70, bore_ratio=(0.5, 0.5), tip_shortening=False, S_Hmin=1.0)
    opts.update(extra)
    return pair_strength(8, 17, 103, X1, 0.0, **opts)


@pytest.fixture(scope="module")
def given_kv():
    return _example(factors={"K_Hbeta": 1.16, "K_v": 1.003})


@pytest.fixture(scope="module")
def computed_kv():
    return _example(factors={"K_Hbeta": 1.16})


@pytest.mark.parametrize("row", list(DATA.itertuples()), ids=lambda r: f"{r.quantity}")
def test_printed_value(row, given_kv, computed_kv):
    out = computed_kv if row.quantity in ("K_v", "c_gamma_alpha", "c_gamma_beta") else given_kv
    assert float(out[row.quantity]) == pytest.approx(row.value, rel=row.rel_tol, abs=1e-12)


def test_material_is_the_examples():
    m = material("18CrNiMo7-6")
    assert m.sigma_Hlim_mpa == 1500.0 and m.kind == "Eh"


def test_formula_level_values():
    """The factors the example prints, each from its own formula with the example's printed inputs."""
    assert kf.theoretical_single_stiffness(18.905, 114.543, 0.145, 0.0) == pytest.approx(17.85584, rel=2e-5)
    assert kf.single_stiffness(17.85584, kf.basic_rack_factor(1.4), 15.8, 1273.5) == pytest.approx(12.37047, rel=2e-6)
    c_ga, c_gb = kf.mesh_stiffness(12.37047, (17.46485 / 12.37047 - 0.25) / 0.75)
    assert (c_ga, c_gb) == (pytest.approx(17.46485, rel=1e-9), pytest.approx(14.84512, rel=1e-6))
    assert zc.contact_ratio_factor(1.5491, 1.08) == pytest.approx(0.803, abs=5e-4)
    assert zc.helix_angle_factor(15.8) == pytest.approx(1.01944, abs=5e-6)
    assert zc.lubricant_factor(320, 1500) == pytest.approx(1.04739, abs=5e-6)
    assert zc.velocity_factor(2.664, 1500) == pytest.approx(0.96911, abs=5e-6)
    assert load_cycles(360, 50_000) == 1.08e9
    assert contact_life_factor(1.08e9, "Eh") == pytest.approx(0.91, abs=5e-4)
    assert contact_life_factor(360 * 17 / 103 * 60 * 50_000, "Eh") == pytest.approx(0.962, abs=5e-4)
    assert zc.contact_stress_limit(1500, 0.9100545, 1.04739, 0.96911, 0.96599, 1.0) == pytest.approx(1338.48, rel=1e-5)
    assert zc.contact_safety(1338.48050, 1301.35343) == pytest.approx(1.02853, abs=5e-6)
    assert zc.contact_safety(1414.52551, 1301.35343) == pytest.approx(1.08696, abs=5e-6)


def test_edition_of_Z_beta_is_2019():
    # ISO 6336-2:2006 had Z_beta = sqrt(cos beta) = 0.98093 here; the example prints 1.01944
    assert zc.helix_angle_factor(15.8) != pytest.approx(math.sqrt(math.cos(math.radians(15.8))), rel=1e-3)


CROSS = pd.read_csv(Path(__file__).parents[2] / "data" / "iso6336_din3990_crosscheck.csv")


@pytest.fixture(scope="module")
def din3990():
    from geardesign.gears.strength import Material
    steel = Material("case-hardened", "Eh", 206000, 0.3, 700, "HV", 1500, 430)
    return pair_strength(4, 19, 104, 0.5, 0.15, load=Load(power_kw=55, n_rpm=980, application_factor=1.75),
                         material1=steel, face_width_mm=48.64, rack=BasicRack(ha=1.0, c=0.25, rho_f=0.25),
                         tip_shortening=False, root_method="C", Rz_flank_um=5.0,
                         factors={"K_v": 1.0278576187783273, "K_Hbeta": 1.1064272863295082,
                                  "K_Fbeta": 1.0864854433487987, "K_Halpha": 1.0, "K_Falpha": 1.0, "Z_E": 189.8})


@pytest.mark.parametrize("row", list(CROSS.itertuples()), ids=lambda r: r.quantity)
def test_din3990_program_crosscheck(row, din3990):
    assert float(din3990[row.quantity]) == pytest.approx(row.value, rel=row.rel_tol)
