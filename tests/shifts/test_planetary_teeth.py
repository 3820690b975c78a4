"""The planetary tooth-count search (geardesign.shifts.planetary_teeth): every feasible row re-checked with
PlanetarySet.checks, the assembly condition (z_sun + z_ring) divisible by the planet count and the ratio
window written out here; refusals named."""
import pytest

import geardesign as gd


def test_tooth_count_search_rows_check_out():
    sel = gd.select_planetary_teeth(5.0, 3, 2.0, ratio_tol=0.01, z_sun_range=(18, 24))
    assert sel.found
    feas = sel.table[sel.table["feasible"]]
    assert len(feas) >= 3 and (~sel.table["standard"]).any() and sel.table["standard"].any()
    for _, row in feas.iterrows():
        assert abs(row["ratio"] - 5.0) <= 0.01 * 5.0 + 1e-12
        assert (row["z_sun"] + row["z_ring"]) % 3 == 0
        s = gd.PlanetarySet(2.0, int(row["z_sun"]), int(row["z_planet"]), int(row["z_ring"]), 3,
                            row["x_sun"], row["x_planet"], row["x_ring"])
        t = s.checks(coaxiality_tol_mm=1e-9)
        assert (t["margin"] >= -1e-8).all(), t
    bad = sel.table[~sel.table["feasible"]]
    assert (bad["reason"].str.len() > 0).all()
    # ranked: feasible first, then the ratio error
    assert list(sel.table["feasible"]) == sorted(sel.table["feasible"], reverse=True)



@pytest.mark.parametrize("kw, words", [
    (dict(ratio=0.5), "ring_fixed"),
    (dict(ratio=5.0, arrangement="sun_fixed"), "in \\(1, 2\\)"),
    (dict(ratio=5.0, z_sun_range=(40, 12)), "lo <= hi"),
    (dict(ratio=5.0, nonstandard_max=9), "nonstandard_max"),
])
def test_tooth_count_search_refuses_by_name(kw, words):
    with pytest.raises(gd.GearDesignError, match=words):
        gd.select_planetary_teeth(n_planets=3, m=2.0, **kw)


@pytest.mark.parametrize("checks, words", [
    ({"load": gd.Load(torque_nm=50, n_rpm=1000), "material": "42CrMo4", "face_width_mm": float("nan")},
     "face_width_mm must be finite, got nan"),
    ({"load": gd.Load(torque_nm=50, n_rpm=1000), "material": "42CrMo4", "face_width_mm": -1.0},
     "face_width_mm must be in"),
    ({"face_width_mm": 20.0}, "face_width_mm given without a load"),
    ({"neighbour_clearance": float("nan")}, "neighbour_clearance"),
])
def test_a_bad_checks_option_is_refused_not_a_reason_in_every_row(checks, words):
    # issue 36 §1.4: the NaN face width was caught per candidate and reported as "no feasible set among 376"
    with pytest.raises(gd.GearDesignError, match=words):
        gd.select_planetary_teeth(4.99, 4, 2, checks=checks)


def test_a_strength_objective_without_a_load_is_refused_up_front():
    with pytest.raises(gd.GearDesignError, match="objective 'max_min_safety' needs a load"):
        gd.select_planetary_teeth(4.99, 4, 2, objective="max_min_safety")


def test_a_target_ratio_is_signed_as_the_results_are():
    # issue 36 §1.8: +12.0 asked of a carrier-fixed set gave a best ratio of -12.0. A ratio is n_in/n_out, signed
    # (Willis: -z_r/z_s with the carrier held, docs/planetary.md); the magnitude is refused with the signed value
    with pytest.raises(gd.GearDesignError, match=r"must be < -1 \(signed n_in/n_out.*give -12\)"):
        gd.select_planetary_teeth(12.0, 2, m=2.5, ratio_tol=0.05, z_sun_range=(12, 14), arrangement="carrier_fixed")
    sel = gd.select_planetary_teeth(-12.0, 2, m=2.5, ratio_tol=0.05, z_sun_range=(12, 14), nonstandard_max=0,
                                    arrangement="carrier_fixed")
    t = sel.table
    assert len(t) > 0 and (t["ratio"] == -t["z_ring"] / t["z_sun"]).all()
    assert (t["ratio_error"] == (t["ratio"] + 12.0) / 12.0).all() and (t["ratio_error"].abs() <= 0.05 + 1e-12).all()
    # every ring within the tolerance is a candidate: z_r in [11.4, 12.6]·z_s
    want = {(s, r) for s in (12, 13, 14) for r in range(s, 200) if 11.4 * s <= r <= 12.6 * s and (r - s) % 2 == 0}
    assert set(zip(t["z_sun"], t["z_ring"])) == want
    assert sel.best["ratio"] == -12.0
