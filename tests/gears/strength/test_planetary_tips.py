"""planetary_strength on the tips a set actually has (issue 36): the sun and planet shortened by the sun-planet
mesh's k·m, or given diameters, against the KISSsoft reports of the NREL 5 MW planetary stages
(tests/data/planetary_tips_kisssoft.csv); the unshortened tips stay the default."""
from pathlib import Path

import pandas as pd
import pytest

from geardesign.errors import GearDesignError
from geardesign.gears.planetary import PlanetarySet
from geardesign.gears.strength import Load, pair_strength, planetary_strength
from geardesign.gears.strength.planetary_meshes import _contact_ratio, set_tips

ROWS = pd.read_csv(Path(__file__).resolve().parents[2] / "data" / "planetary_tips_kisssoft.csv").to_dict("records")
LOAD = Load(torque_nm=3.0e5, n_rpm=100, life_h=10_000)


def set_of(r):
    return PlanetarySet(r["m_n"], r["z_sun"], r["z_planet"], r["z_ring"], 3, r["x_sun"], r["x_planet"], r["x_ring_gost"])


def eps(res):
    return float(res["sun-planet"]._chain["eps_alpha"]), float(res["planet-ring"]._chain["eps_alpha"])


@pytest.mark.parametrize("r", ROWS, ids=[r["stage"] for r in ROWS])
def test_contact_ratio_from_tips_is_the_geometrys(r):
    s = set_of(r)
    for tag in ("sun-planet", "planet-ring"):
        g = s._geo[tag]
        assert _contact_ratio(g, g["da1"], g["da2"], tag == "planet-ring") == pytest.approx(g["eps_alpha"], rel=1e-12)


@pytest.mark.parametrize("r", ROWS, ids=[r["stage"] for r in ROWS])
def test_shortened_tips_are_the_reports(r):
    tips = set_tips(set_of(r), "shortened")
    # the report's shifts are printed to 4 decimals: 2 m_n (|dx| + |dk|) <= 2·45·1e-4 = 0.009 mm of rounding
    for gear in ("sun", "planet", "ring"):
        assert tips[gear] == pytest.approx(r[f"da_{gear}_mm"], abs=0.01), gear


@pytest.mark.parametrize("r", ROWS, ids=[r["stage"] for r in ROWS])
def test_contact_ratios_with_the_reports_tips_match_it(r):
    s = set_of(r)
    given = {g: r[f"da_{g}_mm"] for g in ("sun", "planet", "ring")}
    for tips in (given, "shortened"):
        sp, pr = eps(planetary_strength(s, LOAD, "18CrNiMo7-6", face_width_mm=100, tips=tips))
        assert abs(sp - r["eps_alpha_sun_planet"]) <= 0.0005 + 2e-4      # printed to 3 decimals; shift rounding
        assert abs(pr - r["eps_alpha_planet_ring"]) <= 0.0005 + 2e-4
    # the unshortened tips overstate the sun-planet mesh's contact ratio by 0.27 (stage 1)
    sp0, _ = eps(planetary_strength(s, LOAD, "18CrNiMo7-6", face_width_mm=100))
    assert sp0 > r["eps_alpha_sun_planet"] + 0.1


def test_unshortened_stays_the_default_and_is_the_old_result():
    s = set_of(ROWS[0])
    res = planetary_strength(s, LOAD, "18CrNiMo7-6", face_width_mm=100)
    old = pair_strength(s.m, s.z_sun, s.z_planet, s.x_sun, s.x_planet, load=Load(torque_nm=1.0e5, n_rpm=100 * (1 - 19 / 75),
                                                                              life_h=10_000),
                        material1="18CrNiMo7-6", face_width_mm=100, tip_shortening=False, cycles_per_rev=(3, 1))
    assert res["sun-planet"].S_H1 == pytest.approx(float(old["S_H1"]), rel=1e-12)
    assert res["sun-planet"].S_F1 == pytest.approx(float(old["S_F1"]), rel=1e-12)
    same = planetary_strength(s, LOAD, "18CrNiMo7-6", face_width_mm=100, tips="unshortened")
    assert same["planet-ring"].S_F2 == res["planet-ring"].S_F2


def test_shortened_tips_change_the_strength():
    s = set_of(ROWS[0])
    a = planetary_strength(s, LOAD, "18CrNiMo7-6", face_width_mm=100)
    b = planetary_strength(s, LOAD, "18CrNiMo7-6", face_width_mm=100, tips="shortened")
    assert b["sun-planet"].S_H1 < a["sun-planet"].S_H1      # a shorter path of contact: Z_eps up


@pytest.mark.parametrize("bad, word", [("short", "tips"), ({"moon": 900.0}, "tips"), ({}, "tips"),
                                       ({"sun": -1.0}, "tips\\['sun'\\]"), ({"sun": 500.0}, "base circle"),
                                       ({"ring": 3000.0}, "root circle"), ({"planet": float("nan")}, "tips")])
def test_bad_tips_are_refused_by_name(bad, word):
    with pytest.raises(GearDesignError, match=word):
        planetary_strength(set_of(ROWS[0]), LOAD, "18CrNiMo7-6", face_width_mm=100, tips=bad)
