"""An infeasible pair names a conflicting set of checks, and that set alone admits no point."""
import numpy as np

import geardesign as gd
from geardesign import checks as ck
from geardesign.gears.geometry import mesh_geometry
from geardesign.gears.mesh import Mesh


def test_infeasible_pair_names_conflict():
    r = gd.optimize_shifts(5, 5, method="exact")
    assert not r.success
    assert r.conflict, r.message
    assert "conflict" in r.message
    # the named set really is infeasible on its own: no node of a fine grid satisfies it
    sub = [c for c in ck.make_checks() if c.name in r.conflict]
    g = np.linspace(-1.5, 3.0, 401)
    X1, X2 = np.meshgrid(g, g)
    geo = mesh_geometry(Mesh(5, 5, gd.BasicRack(), True), 1.0, X1, X2)
    ok = np.ones(X1.shape, bool)
    for c in sub:
        ok &= np.nan_to_num(c.margin(geo), nan=-1) >= 0
    assert not ok.any()


def test_a_window_a_grid_node_holds_names_no_conflict_without_searching_every_subset():
    """30/50/129 × 3 (carrier fixed) under three load cases on the sun: 34 checks. The solver's start nodes hold no
    design that passes them all, but a node of the conflict search's 161 × 161 grid does (worst margin +0.0115 at
    x = (0.80625, 0.39375), re-checked here by PlanetarySet.checks). The search tried every subset by size before
    finding that none conflicts: 34 choose 4 and beyond (fuzz planetary_spectrum: minutes). Now it answers []
    at once, and the message says no conflict was shown instead of 'every check passes somewhere, but not all
    together'."""
    from geardesign.shifts.conflict import smallest_conflict
    from geardesign.shifts.planetary import _problem

    spectra = [gd.LoadSpectrum.from_bins([-4862.147164729698, 15375.241292, -14492.558961, -4933.422703, -856.603053,
                                          1798.369825, 716.876691, -693.55472],
                                         [4327.45, 8108.87, 1977.63, 8089.72, 7065.34, 1253.26, 2670.3, 6844.12],
                                         time_h=[0.544, 0.269, 1359.255, 6.995, 11095.745, 0.001, 0.001, 0.001]),
               gd.LoadSpectrum.from_bins([-2753.835932, 14221.094914], 7777.7, share=[0.5, 0.5], duration_h=1.0),
               gd.LoadSpectrum.from_bins([6053.760386131065, 0.0, 4212.960781, 0.0, 106.554198, 187.699467,
                                          552.544107, 4609.021298], 0.001,
                                         time_h=[0.605, 254.604, 0.001, 1.941, 1458.734, 0.001, 878.226, 0.001])]
    checks = {"material": "31CrMoV9", "face_width_mm": 100.0, "mean_stress_factor": 0.7, "sn_curve": "original",
              "spectrum": spectra}
    table = gd.PlanetarySet.coaxial(5.0, 30, 50, 129, 3, 0.80625, 0.39375, arrangement="carrier_fixed").checks(checks)
    assert table["ok"].all() and table["margin"].min() >= 0.0
    prob = _problem(30, 50, 129, 3, 5.0, "max_life", checks, None, 0.0, None, None, (-1.5, 1.5),
                    arrangement="carrier_fixed")
    assert smallest_conflict(prob, (-1.5, 1.5)) == []
    r = gd.optimize_planetary_shifts(30, 50, 129, 3, 5.0, checks=checks, objective="max_life",
                                     arrangement="carrier_fixed")
    assert r.success or ("no set of them is shown to conflict" in r.message and r.conflict == [])


def test_past_its_budget_the_search_names_an_irreducible_conflict(monkeypatch):
    """With the subsets by size cut off at once (SUBSETS_MAX 0), 5/5's conflict is found by deletion: the set it
    names admits no node of a fine grid (as the first test checks the smallest one), and leaving out any one of
    its checks admits some node: no check of it can be left out."""
    from geardesign.shifts import conflict
    from geardesign.shifts.problem import Problem

    monkeypatch.setattr(conflict, "SUBSETS_MAX", 0)
    prob = Problem(Mesh(5, 5, gd.BasicRack(), True), None, "max_x_sum", 1.0)
    names = conflict.smallest_conflict(prob, (-1.5, 3.0))
    assert names
    g = np.linspace(-1.5, 3.0, 401)
    X1, X2 = np.meshgrid(g, g)
    geo = mesh_geometry(Mesh(5, 5, gd.BasicRack(), True), 1.0, X1, X2)
    held = {c.name: np.nan_to_num(c.margin(geo), nan=-1) >= 0 for c in ck.make_checks() if c.name in names}
    assert set(held) == set(names)
    assert not np.logical_and.reduce(list(held.values())).any()
    for left_out in names:
        assert np.logical_and.reduce([v for k, v in held.items() if k != left_out] or [np.ones_like(X1, bool)]).any()
