"""One pair's strength as a result (geardesign.gears.strength.result): ISO/TR 6336-30:2017 example 1 through
from_chain — the safety factors and stresses as printed (tests/data/iso6336_tr30_example1.md), the factor table
with each factor's clause, the notes on given factors, and the JSON form."""
import json
from pathlib import Path

import pandas as pd
import pytest

from geardesign.gears.geometry import x_sum_from_center_distance
from geardesign.gears.rack import BasicRack
from geardesign.gears.strength import Load, material, pair_strength
from geardesign.gears.strength.result import FACTOR_TABLE, StrengthResult, from_chain

TR30 = pd.read_csv(Path(__file__).parents[2] / "data" / "iso6336_tr30_example1.csv").set_index("quantity")
RACK_D = BasicRack(ha=1.0, c=0.4, rho_f=0.39)       # ISO 53 profile D, as the example


@pytest.fixture(scope="module")
def result():
    x1 = x_sum_from_center_distance(8, 17, 103, 500.0, rack=RACK_D, beta_deg=15.8)
    out = pair_strength(8, 17, 103, x1, 0.0, load=Load(torque_nm=9000, n_rpm=360, life_h=50_000),
                        material1=material("18CrNiMo7-6"), face_width_mm=100, beta_deg=15.8, rack=RACK_D,
                        accuracy_grade=5, nu40=320, Rz_flank_um=6.0, tip_relief_um=70, bore_ratio=(0.5, 0.5),
                        tip_shortening=False, S_Hmin=1.0, factors={"K_Hbeta": 1.16, "K_v": 1.003})
    return from_chain(out, title="ISO/TR 6336-30 example 1")


def test_the_printed_safety_factors_and_stresses(result):
    assert isinstance(result, StrengthResult)
    for q in ("S_H1", "S_H2", "sigma_H0", "sigma_H1", "sigma_H2"):
        assert getattr(result, q) == pytest.approx(float(TR30.loc[q, "value"]), rel=float(TR30.loc[q, "rel_tol"]))
    assert result.S_Hmin == 1.0 and result.title == "ISO/TR 6336-30 example 1"


def test_the_factor_table_has_each_factor_with_its_clause(result):
    table = result.factors
    assert list(table.columns) == ["symbol", "gear", "value", "clause"]
    z_e = table[table.symbol == "Z_E"].iloc[0]
    assert z_e.value == pytest.approx(float(TR30.loc["Z_E", "value"]), rel=float(TR30.loc["Z_E", "rel_tol"]))
    assert "6336-2" in z_e.clause
    assert all(isinstance(row[3], str) and row[3] for row in FACTOR_TABLE)


def test_a_given_factor_row_says_it_was_given_not_its_formulas_clause(result):
    # K_Hβ = 1.16 and K_v = 1.003 are the example's given values: their rows cited the clauses they were not from
    fac = result.factors.set_index("symbol")
    assert fac.loc["K_Hbeta", "clause"] == fac.loc["K_v", "clause"] == "given by the caller, not computed"
    assert fac.loc["K_Hbeta", "value"] == 1.16 and "6336-1" in fac.loc["K_Halpha", "clause"]


def test_given_factors_are_noted_and_the_json_form_is_plain(result):
    assert set(result.given) == {"K_Hbeta", "K_v"}
    assert any("K_v given" in n for n in result.notes)
    data = json.loads(json.dumps(result.to_dict()))
    assert data["S_H1"] == pytest.approx(result.S_H1, rel=1e-15)
    assert len(repr(result).splitlines()) <= 15          # a readable repr, not a dump
