"""Defects of the load-capacity surfaces (ISO 6336) found by fuzzing them (tests/fuzzstrength.py,
``python tools/fuzz.py --targets strength_pair,pair_strength,strength_solvers,strength_planetary,
strength_cli,strength_drive --cases 1500 --seed 7 --seconds 1500``, and the strength_report target):
one minimal reproducer per failure class, each stating the project's rule (a result with finite numbers, or one GearDesignError naming the
input, its value and its range; no warning escaping a call). Each was marked ``xfail(strict=True)`` until
the package was fixed; all are fixed now and hold as plain tests.
"""
import math
import warnings

import numpy as np
import pytest

import geardesign as gd
from geardesign.gears.strength import Load, material, pair_strength

LOAD = Load(torque_nm=100, n_rpm=1000)


def _pair():
    return gd.GearPair(4, 20, 60, 0.0, 0.0, face_width_mm=40)


def test_an_empty_material_name_is_refused():
    # material("") returns 18CrNiMo7-6 (the catalog's first row) instead of refusing the name; a name
    # with a space or in lower case is refused, and pair_strength(material1="") refuses it too
    with pytest.raises(gd.GearDesignError, match="material"):
        material("")


@pytest.mark.parametrize("name", [["42CrMo4"], {"a": 1}])
def test_a_material_name_of_a_wrong_type_is_refused(name):
    with pytest.raises(gd.GearDesignError, match="material"):     # now TypeError: unhashable type
        material(name)


@pytest.mark.parametrize("option, value", [("cycles_per_rev", 3), ("cycles_per_rev", (2,)),
                                           ("cycles_per_rev", (1, 1, 1)), ("rim_mm", 30.0), ("rim_mm", True),
                                           ("bore_ratio", 0.5)])
def test_pair_valued_options_must_be_pairs(option, value):
    # now: TypeError ('int' object is not iterable / not subscriptable), IndexError (tuple index out of
    # range; invalid index to scalar variable), or (1, 1, 1) accepted with its third value dropped
    with pytest.raises(gd.GearDesignError, match=option):
        _pair().strength(LOAD, "42CrMo4", **{option: value})


@pytest.mark.parametrize("value", [1e308, float("nan"), float("inf"), "a", -1.0, True, np.array([1.0])])
def test_the_tip_relief_is_validated(value):
    # now: 1e308 and NaN give ValueError (min() of an empty sequence, in the result's governing check),
    # inf gives NaN safeties with RuntimeWarnings, "a" a numpy UFuncTypeError, array([1.]) a ValueError
    # (cannot broadcast a non-scalar to a scalar array), -1 and True answer
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(gd.GearDesignError, match="tip_relief_um"):
            _pair().strength(LOAD, "42CrMo4", tip_relief_um=value)


@pytest.mark.parametrize("z1, z2, x1, x2", [(5, 300, 0.0, 0.0), (21, 59, -1.205, 1.518)])
def test_an_undercut_pinion_gets_a_contact_safety_or_a_clear_refusal(z1, z2, x1, x2):
    # GearPair accepts the pair (it exists and meshes); strength() returns S_H1 = NaN (Z_B: sqrt of a
    # negative in contact.py) with a RuntimeWarning, and the result's repr prints "nan"
    pair = gd.GearPair(4, z1, z2, x1, x2, face_width_mm=40)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            r = pair.strength(LOAD, "42CrMo4")
        except gd.GearDesignError:
            return
    assert all(math.isfinite(v) for v in (r.S_H1, r.S_H2, r.S_F1, r.S_F2, r.sigma_H1))


def test_pair_strength_arrays_hold_no_nan_without_a_given_geometry():
    # the docstring: only with geometry= (unvalidated) may a design give NaN; these two were NaN (Z_B's root of a
    # negative): now the first such design is refused by name, the factor named, with no warning on the way
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(gd.GearDesignError, match=r"design m=4, z1=5, z2=300, x1=0.0, x2=0.0: Z_B is not finite"):
            pair_strength(4, 5, 300, np.array([0.0, 0.5]), 0.0, load=LOAD, material1="42CrMo4", face_width_mm=40)
        out = pair_strength(4, 20, 60, np.array([0.0, 0.5]), 0.0, load=LOAD, material1="42CrMo4", face_width_mm=40)
    assert np.isfinite(out["S_H1"]).all() and np.isfinite(out["Z_B"]).all()


@pytest.mark.parametrize("x1, x2", [(np.zeros(3), np.zeros(4)), (0.0, [[1], [2, 3]])])
def test_pair_strength_refuses_mismatched_or_ragged_arrays(x1, x2):
    # now numpy's ValueError (shape mismatch; setting an array element with a sequence) from the chain's
    # geometry; pair_geometry refuses both cleanly ("x2 must be a number, got [[1], [2, 3]]")
    with pytest.raises(gd.GearDesignError, match="x1|x2|shape"):
        pair_strength(4, 20, 60, x1, x2, load=LOAD, material1="42CrMo4", face_width_mm=40)


def test_an_unknown_strength_option_is_refused():
    # in a checks dict's "strength" (as in every solver) and in GearPair.strength(**options): now a
    # TypeError (pair_strength() got an unexpected keyword argument 'bogus')
    with pytest.raises(gd.GearDesignError, match="bogus"):
        _pair().checks(load=LOAD, material="42CrMo4", face_width_mm=40, strength={"bogus": 1})


def test_a_torque_from_power_and_speed_is_held_to_the_torque_range():
    # torque_nm=1e10 is refused ("torque_nm must be in (0, 1e+09] N·m"), but 1e6 kW at 1e-6 rpm
    # (9.5e15 N·m) is taken: S_H = 0.000, sigma_F of 1e11 MPa, and on the command line NaN checks
    with pytest.raises(gd.GearDesignError, match="power_kw|n_rpm|torque"):
        Load(power_kw=1e6, n_rpm=1e-6)


@pytest.mark.parametrize("kw, name", [(dict(rim_mm=(1.0, 1.0)), "rim_mm"), ({}, "face_width")])
def test_a_refusal_names_the_input_given(kw, name):
    # rim_mm=(1, 1): "s_R_over_h_t must be in (0.5, 1e+06], got 0.111"; a face width of 1e4 mm on a
    # 45° helix: "eps_beta must be in [0, 50], got 562.7" (neither names what the caller gave)
    pair = gd.GearPair(4, 20, 60, 0.0, 0.0, beta_deg=45 if name == "face_width" else 0.0,
                       face_width_mm=1e4 if name == "face_width" else 40)
    with pytest.raises(gd.GearDesignError, match=name):
        pair.strength(LOAD, "42CrMo4", **kw)


def test_the_result_repr_keeps_its_columns_apart():
    # a valid extreme load (1e9 N·m, the top of torque_nm's range, on a module-4 pair):
    # "sigma_F  461890345.3437006678.1  MPa"
    r = _pair().strength(Load(torque_nm=1e9, n_rpm=1000), "42CrMo4")
    row = next(line for line in repr(r).splitlines() if line.strip().startswith("sigma_F "))
    assert len(row.split()) >= 4, row


@pytest.mark.parametrize("m, z1, z2, x2, width, load", [(4, 20, 60, 0.0, 40, LOAD),
                                                        (0.1, 22, 112, -0.337, 2.3, Load(torque_nm=400, n_rpm=1e-6))])
def test_the_face_load_factor_is_at_least_one(m, z1, z2, x2, width, load):
    # a material of low sigma_Hlim (100 MPa, inside Material's [1, 5000]): y_beta = 320/sigma_Hlim F_betax
    # exceeds F_betax, F_betay < 0 and K_Hbeta = -2.54 (20/60, NaN safeties and three RuntimeWarnings:
    # K_Fbeta = K_Hbeta**N_F) or 0.342 (22/112, finite safeties from K_Hbeta < 1); ISO 6336-1 bounds
    # y_beta and K_Hbeta >= 1. Without yield_mpa the warning escapes before the clean refusal.
    soft = gd.Material(name="soft", kind="V", E_mpa=206000.0, nu=0.3, hardness=280.0, hardness_scale="HV",
                       sigma_Hlim_mpa=100.0, sigma_Flim_mpa=300.0, yield_mpa=700.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = pair_strength(m, z1, z2, 0.0, x2, load=load, material1=soft, face_width_mm=width)
    assert out["K_Hbeta"] >= 1.0 and out["K_Fbeta"] >= 1.0 and np.isfinite(out["S_H1"])


def test_the_strength_checks_agree_with_strength_on_a_pair_with_interference():
    # 20/300 at x1 = -0.2 (slight undercut, interference1 fails): strength() gives S_H1 = 0.740,
    # S_F1 = 3.46, but checks(load=...) gives contact_strength, root_strength1, root_strength2 value NaN,
    # margin -inf (the chain is skipped where rho_p1 <= 0), and `geardesign pair ... --torque` prints
    # "contact_strength (value nan, limit 1)"; perhaps meant (d5b5602: NaN past the root section's range),
    # but then the command prints NaN as a value and the two answers for one pair disagree
    pair = gd.GearPair(4, 20, 300, -0.2, 0.1, face_width_mm=20)
    r = pair.strength(LOAD, "42CrMo4")
    t = pair.checks(load=LOAD, material="42CrMo4", face_width_mm=20).set_index("check")
    assert t.loc["contact_strength", "value"] == pytest.approx(min(r.S_H1, r.S_H2))
    assert t.loc["root_strength1", "value"] == pytest.approx(r.S_F1)


@pytest.mark.parametrize("option, value", [("cycles_per_rev", (2, 1)), ("beta_deg", 10.0)])
def test_planetary_strength_refuses_the_options_it_sets(option, value):
    # now: TypeError (pair_strength() / dict() got multiple values for keyword argument ...); the set
    # fixes the cycles per revolution (a sun among N planets: N) and takes its helix angle from itself
    from geardesign.gears.strength import planetary_strength
    s = gd.PlanetarySet.coaxial(2, 20, 31, 82, 3)
    with pytest.raises(gd.GearDesignError, match=option):
        planetary_strength(s, LOAD, "42CrMo4", face_width_mm=25, **{option: value})


def test_strength_refuses_root_false_by_name():
    # was: KeyError 'S_F1' from the result object (found by the strength-scalar review); the contact side alone
    # is pair_strength's, whose dict then has no root fields
    pair = gd.GearPair(4, 20, 60, 0.3, 0.1, face_width_mm=40)
    with pytest.raises(gd.GearDesignError, match="root=False"):
        pair.strength(LOAD, "42CrMo4", root=False)
    out = pair_strength(4, 20, 60, 0.3, 0.1, load=LOAD, material1="42CrMo4", face_width_mm=40, root=False)
    assert "S_F1" not in out and out["S_H1"] > 0


@pytest.mark.parametrize("shaft, match", [({"B_star": 1.0}, "unknown key 'B_star'"), ({"l_mm": -5.0}, r"shaft\['l_mm'\]"),
                                          ({"d_sh_mm": 0.0}, r"shaft\['d_sh_mm'\]"), ({"K_prime": "a"}, "K_prime"),
                                          ({"K_prime": True}, "K_prime"), (5, "shaft must be a dict")])
def test_pair_strength_refuses_a_bad_shaft_by_name(shaft, match):
    # was: TypeError from shaft_misalignment (an unknown key, a string, not a dict), or a negative bearing span
    # taken silently (found by the strength-scalar2 review)
    with pytest.raises(gd.GearDesignError, match=match):
        pair_strength(4, 20, 60, 0.3, 0.1, load=LOAD, material1="42CrMo4", face_width_mm=40, shaft=shaft)


def test_a_pinion_shaft_offset_raises_f_sh_as_eq_44_says():
    # ISO 6336-1:2006 eq. (44): f_sh = (F_m/b) 0.023 [|1 + K' l s/d1² (d1/d_sh)⁴ − 0.3| + 0.3] (b/d1)²; with
    # K' = 0.48, l = 200, s = 20, d_sh = d1 = 80 mm the bracket is |1 + 0.48·200·20/6400 − 0.3| + 0.3 = 1.3
    plain = pair_strength(4, 20, 60, 0.3, 0.1, load=LOAD, material1="42CrMo4", face_width_mm=40)
    off = pair_strength(4, 20, 60, 0.3, 0.1, load=LOAD, material1="42CrMo4", face_width_mm=40,
                        shaft={"K_prime": 0.48, "l_mm": 200.0, "s_mm": 20.0, "d_sh_mm": 80.0})
    assert off["f_sh"] / plain["f_sh"] == pytest.approx(1.3 / 1.0, rel=1e-12)


@pytest.mark.slow
@pytest.mark.parametrize("width", [np.array(100.0), np.float64(100.0)])
def test_a_pairs_checks_and_report_take_a_width_as_a_0d_array(width, tmp_path):
    # was: TypeError unhashable type 'numpy.ndarray' (the strength checks' spec is hashed), found by
    # tools/fuzz.py --targets strength_report --seed 17; the values are those of the width as a float
    pair = gd.GearPair(4, 20, 60, 0.3, 0.1)
    t = pair.checks(load=LOAD, material="42CrMo4", face_width_mm=width).set_index("check")
    assert t.loc["contact_strength", "value"] == pytest.approx(
        min(pair.strength(LOAD, "42CrMo4", face_width_mm=100.0).S_H1,
            pair.strength(LOAD, "42CrMo4", face_width_mm=100.0).S_H2), rel=1e-12)
    assert gd.pair_report(pair, tmp_path / "r.html", load=LOAD, material="42CrMo4", face_width_mm=width).exists()


@pytest.mark.parametrize("call", ["strength", "checks"])
def test_one_pairs_strength_refuses_several_widths_by_name(call):
    # was: TypeError "only 0-dimensional arrays can be converted" from the result object (strength), unhashable
    # (checks)
    pair = gd.GearPair(4, 20, 60, 0.3, 0.1)
    with pytest.raises(gd.GearDesignError, match="face_width_mm must be one number"):
        if call == "strength":
            pair.strength(LOAD, "42CrMo4", face_width_mm=np.array([100.0]))
        else:
            pair.checks(load=LOAD, material="42CrMo4", face_width_mm=[100.0, 90.0])


FAST = gd.Load(torque_nm=500.0, n_rpm=1450.0, life_h=20_000)   # v = 6.1 m/s: the running-in caps of 5-10 m/s
_GIVEN_VALUES = {"f_pb": 5.0, "f_falpha": 5.0, "F_beta": 10.0, "f_Hbeta": 8.0, "f_sh": 5.0, "f_ma": 5.0, "C_a": 5.0,
                 "c_prime": 14.0, "c_gamma_alpha": 18.0, "c_gamma_beta": 17.0, "Z_E": 189.8}


@pytest.mark.parametrize("mat", ["42CrMo4", "18CrNiMo7-6", "GG"])
def test_every_given_factor_as_a_float_over_arrays_of_designs(mat):
    # was: ValueError "truth value of an array is ambiguous" for factors={'f_pb': 0.0} over an array of wheels
    # (tools/fuzz.py --targets pair_strength --seed 23): a given factor kept as a Python float made the running-in
    # allowance take math's min over the speeds' array. Each factor given as a float gives the values of the same
    # factor given as a numpy number, and each design the values of its own one-design call (the float path).
    material = gd.material("GG", hardness=200, E_mpa=110000, nu=0.28, yield_mpa=250) if mat == "GG" else mat
    from geardesign.gears.strength.chain import GIVEN_FACTORS
    z2 = np.array([40, 60, 80])
    for name in sorted(GIVEN_FACTORS):
        value = _GIVEN_VALUES.get(name, 1.1)
        kw = dict(load=FAST, material1=material, face_width_mm=40.0, beta_deg=15.0)
        a = pair_strength(4.0, 20, z2, 0.2, 0.1, factors={name: value}, **kw)
        b = pair_strength(4.0, 20, z2, 0.2, 0.1, factors={name: np.float64(value)}, **kw)
        for k in ("S_H1", "S_H2", "S_F1", "S_F2"):
            assert np.array_equal(a[k], b[k]), (name, k)
        one = [pair_strength(4.0, 20, int(z), 0.2, 0.1, factors={name: value}, **kw) for z in z2]
        for k in ("S_H1", "S_F2"):
            np.testing.assert_allclose([o[k] for o in one], a[k], rtol=1e-12, err_msg=name)


def test_power_at_a_vanishing_speed_is_refused_by_name():
    # was: ZeroDivisionError (ω = n·π/30 of n = 5e-324 rpm underflows to 0), tools/fuzz.py --targets pair_strength
    # --seed 29; P/ω is then past every torque
    with pytest.raises(gd.GearDesignError, match="power_kw and n_rpm must give a torque"):
        gd.Load(power_kw=1e6, n_rpm=5e-324)
    assert gd.Load(power_kw=75.0, n_rpm=1480.0).torque_nm == pytest.approx(75_000 * 30 / (math.pi * 1480), rel=1e-15)


def test_an_overloaded_pair_ends_infeasible_naming_the_conflict_not_undefined():
    # was: "no finite result ... the pair's geometry or a check is undefined at the point the solver reached"
    # (also from `geardesign pair ... --torque 400 --report`): the least infeasible point lies on ε_α = 1, where the
    # ISO 6336 chain is undefined (its load point needs ε_αn >= 1), so the strength margins there are -inf
    r = gd.optimize_shifts(20, 60, m=4, checks={"load": gd.Load(torque_nm=400, n_rpm=1000), "material": "42CrMo4",
                                                "face_width_mm": 40})
    assert not r.success and "contact_strength" in r.conflict
    assert all(math.isfinite(v) or v == -math.inf for v in r.margins.values())
    assert all(math.isfinite(v) for k, v in r.margins.items() if "strength" not in k)
