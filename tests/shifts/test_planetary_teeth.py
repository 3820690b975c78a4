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
