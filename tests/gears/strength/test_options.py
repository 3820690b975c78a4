"""The numeric options of pair_strength (geardesign.gears.strength.options): each checked by name against its
range before any work, pairs (one value per gear) as pairs, and the pinion shaft of ISO 6336-1 eq. (44)."""
import inspect

import pytest

from geardesign.errors import GearDesignError
from geardesign.gears.strength import defaults as d
from geardesign.gears.strength.options import SHAFT_RANGES, TIP_RELIEF_RANGE_UM, shaft_option, validate_options

GOOD = dict(accuracy_grade=7, nu40=220.0, Rz_flank_um=6.0, Rz_root_um=10.0, K_gamma=1.0, root_method="B",
            S_Hmin=1.0, S_Fmin=1.4, cycles_per_rev=(1, 1), rim_mm=(None, None), bore_ratio=(0.0, 0.0),
            tip_relief_um=None)


def test_good_options_come_back_checked():
    grade, nu40, rz, rz_root, k_gamma, method, s_min, cpr, rim, bore, c_a = validate_options(**GOOD)
    assert (grade, nu40, rz, rz_root, k_gamma, method, s_min) == (7.0, 220.0, 6.0, 10.0, 1.0, "B", (1.0, 1.4))
    assert (cpr, rim, bore, c_a) == ((1.0, 1.0), (None, None), (0.0, 0.0), None)


@pytest.mark.parametrize("name, value, words", [
    ("accuracy_grade", 13, "accuracy_grade"), ("nu40", 0.0, "nu40"), ("Rz_root_um", d.RZ_ROOT_MAX_UM * 2, "Rz_root_um"),
    ("root_method", "A", "root_method must be 'B'"), ("S_Hmin", 0.1, "S_Hmin"), ("S_Fmin", 20, "S_Fmin"),
    ("cycles_per_rev", 3, "cycles_per_rev must be a pair"), ("cycles_per_rev", (1, 0), "cycles_per_rev"),
    ("rim_mm", (5.0,), "rim_mm must be a pair"), ("bore_ratio", (0.0, 1.0), "bore_ratio"),
    ("bore_ratio", (True, 0.0), "bore_ratio must be a number"),
    ("tip_relief_um", TIP_RELIEF_RANGE_UM[1] * 2, "tip_relief_um"), ("tip_relief_um", True, "tip_relief_um"),
])
def test_each_bad_option_is_refused_by_name(name, value, words):
    with pytest.raises(GearDesignError, match=words):
        validate_options(**{**GOOD, name: value})


def test_the_shaft_option():
    assert shaft_option(None) == {}
    got = shaft_option({"K_prime": 0.48, "l_mm": 300, "s_mm": 30, "d_sh_mm": 60})   # K′ of ISO 6336-1 Fig. 13
    assert got == {"K_prime": 0.48, "l_mm": 300.0, "s_mm": 30.0, "d_sh_mm": 60.0}
    assert set(SHAFT_RANGES) == {"K_prime", "l_mm", "s_mm", "d_sh_mm"}
    for bad, words in (([1, 2], "shaft must be a dict"), ({"K": 1}, "unknown key 'K'"), ({"l_mm": 0}, "l_mm"),
                       ({"K_prime": True}, "K_prime")):
        with pytest.raises(GearDesignError, match=words):
            shaft_option(bad)


def test_the_options_grouped_in_one_object_give_the_same_result():
    from geardesign.gears.strength import Load, StrengthOptions, pair_strength
    from geardesign.gears.strength.options import GROUPED

    loose = dict(accuracy_grade=6, nu40=320.0, Rz_flank_um=4.0, K_gamma=1.1, tip_relief_um=20.0,
                 bore_ratio=(0.3, 0.5), S_Fmin=1.5, cycles_per_rev=(1, 3), rim_mm=(None, 12.0))
    design = dict(load=Load(torque_nm=200, n_rpm=1000, life_h=20_000), material1="42CrMo4", face_width_mm=30)
    one = pair_strength(3, 20, 40, 0.2, 0.1, **design, options=StrengthOptions(**loose))
    with pytest.warns(DeprecationWarning, match=r"options=StrengthOptions\(accuracy_grade=\.\.\., nu40="):
        many = pair_strength(3, 20, 40, 0.2, 0.1, **design, **loose)   # the old way, for one release
    for key in ("S_H1", "S_H2", "S_F1", "S_F2", "K_v", "Z_L1", "Y_B2"):
        assert float(one[key]) == float(many[key])
    assert set(GROUPED) == set(StrengthOptions.__dataclass_fields__)
    with pytest.raises(GearDesignError, match="not both: nu40"):
        pair_strength(3, 20, 40, 0.2, 0.1, **design, options=StrengthOptions(**loose), nu40=100.0)
    with pytest.raises(GearDesignError, match="options must be a geardesign StrengthOptions"):
        pair_strength(3, 20, 40, 0.2, 0.1, **design, options=loose)
    with pytest.raises(GearDesignError, match="nu40"):
        StrengthOptions(nu40=-1.0)          # refused by name when made, before any work


def test_pair_strength_takes_its_options_one_way():
    """Issue 36 §4: pair_strength took its 18 options as keywords beside options=StrengthOptions (two ways to say
    one thing). Its signature now has options= alone; the keywords one by one still work for one release with a
    DeprecationWarning (geardesign.renamed.grouped_keywords), and the package's own callers (a pair's strength,
    the strength checks of the solvers, a planetary set) pass options= and warn nothing."""
    import warnings

    import geardesign as gd
    from geardesign.gears.strength import Load, StrengthOptions, pair_strength
    from geardesign.gears.strength.options import GROUPED
    from geardesign.gears.strength.planetary_meshes import planetary_strength

    params = inspect.signature(pair_strength).parameters
    assert not set(GROUPED) & set(params) and "options" in params
    design = dict(load=Load(torque_nm=200, n_rpm=1000, life_h=20_000), material1="42CrMo4", face_width_mm=30)
    with pytest.raises(GearDesignError, match="not both: nu40"):
        pair_strength(3, 20, 40, 0.2, 0.1, **design, options=StrengthOptions(), nu40=100.0)
    load = design["load"]
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)
        pair = gd.GearPair(3, 20, 40, 0.2, 0.1, face_width_mm=30)
        r = pair.strength(load, "42CrMo4", nu40=320.0, accuracy_grade=6)
        assert r.S_H1 == float(pair_strength(3, 20, 40, 0.2, 0.1, **design, options=StrengthOptions(
            nu40=320.0, accuracy_grade=6))["S_H1"])
        t = pair.checks(load=load, material="42CrMo4", strength={"nu40": 320.0, "accuracy_grade": 6})
        assert float(t.set_index("check").loc["contact_strength", "value"]) == pytest.approx(min(r.S_H1, r.S_H2),
                                                                                           rel=1e-12)
        s = gd.PlanetarySet.coaxial(2, 20, 31, 82, 3)
        planetary_strength(s, Load(torque_nm=100, n_rpm=1500, life_h=10000), "18CrNiMo7-6", face_width_mm=25,
                              K_gamma=1.1, nu40=320.0)
