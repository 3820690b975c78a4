"""Gear stages by the load they carry, with the ISO 6336 model (geardesign.gears.strength): a stage with a
material gets contact and root strength checks at the torque and speed the drive's flow brings it (worked
by hand here: T = P/ω·∏u·η upstream), each equal to the pair's own StrengthResult (GearPair.strength) at
that load; a given module too small fails naming the check; a stage without a module takes the smallest
ISO 54 module, and at it the narrowest face width b = ⌈ψ_d·d1⌉ (ψ_d = 0.2 … 1.0 by 0.05, the documented
range), that holds every check — the next smaller module at every width and the next narrower width are
shown to fail, by the pair's own StrengthResult."""
import math

import numpy as np
import pytest

import geardesign as gd
from geardesign.gears.strength import Load
from geardesign.shifts.optimize import optimize_shifts

# ISO 54:1996 modules 1 … 8 mm, series I and II
ISO54 = (1, 1.125, 1.25, 1.375, 1.5, 1.75, 2, 2.25, 2.5, 2.75, 3, 3.5, 4, 4.5, 5, 5.5, 6, 7, 8)
PSI = np.round(np.arange(0.2, 1.0 + 1e-9, 0.05), 10)


def _grid_widths(m, z1, beta_deg=0.0):
    """The documented widths at module m: b = ψ_d·d1 rounded up, none below three circular pitches (3·π·m)."""
    return np.maximum(np.ceil(PSI * m * z1 / math.cos(math.radians(beta_deg)) - 1e-9), math.ceil(3 * math.pi * m - 1e-9))


def _omega(n_rpm):
    return 2 * math.pi * n_rpm / 60


def _margins(res):
    return {"contact_strength": min(res.S_H1, res.S_H2) / res.S_Hmin - 1, "root_strength1": res.S_F1 / res.S_Fmin - 1,
            "root_strength2": res.S_F2 / res.S_Fmin - 1}


def _pair_margins(m, b, x1, x2, torque_nm, n_rpm, z1=20, z2=60, material="42CrMo4"):
    pair = gd.GearPair(m, z1, z2, x1, x2, face_width_mm=b)
    return _margins(pair.strength(Load(torque_nm=torque_nm, n_rpm=n_rpm), material))


def test_the_checks_table_gains_the_strength_checks_at_the_stages_own_load():
    d = gd.Drive(power_kw=7.5, n_in_rpm=1450, stages=[gd.GivenStage(2, 0.95, "belt"),
                                                      gd.GearStage(4, z1=20, z2=60, face_width_mm=40, material="42CrMo4")])
    a = d.analyse()
    t_in = 7500 / _omega(1450) * 2 * 0.95                 # 93.82 N·m into the pair at 725 rpm
    s = a.stages[1]["summary"]
    want = _pair_margins(4, 40, s["x1"], s["x2"], t_in, 725)
    got = a.checks[a.checks["item"] == "gear"].set_index("check")["margin"]
    for name, v in want.items():
        assert got[name] == pytest.approx(v, rel=1e-12)
    kept = _margins(a.stages[1]["strength"])         # the StrengthResult (factor table) kept in the analysis
    assert kept == pytest.approx(want, rel=1e-12)


def test_a_given_module_that_cannot_carry_the_load_fails_naming_the_check():
    stage = gd.GearStage(1.5, z1=20, z2=60, material="42CrMo4")
    a = gd.Drive(power_kw=7.5, n_in_rpm=1450, stages=[stage]).analyse()
    t_in = 7500 / _omega(1450)                             # 49.39 N·m on the pinion
    s = a.stages[0]["summary"]
    want = _pair_margins(1.5, 4 * math.pi * 1.5, s["x1"], s["x2"], t_in, 1450)   # the mass model's b = 4πm
    assert want["contact_strength"] < 0
    assert not a.success
    assert f"gear: contact_strength ({want['contact_strength']:+.3f})" in a.message
    r = gd.Drive(power_kw=7.5, n_in_rpm=1450, stages=[gd.GearStage(1.5, z1_range=(20, 20), ratio_range=(3, 3),
                                                                    material="42CrMo4")]).optimize(3, 0.0)
    assert not r.success
    assert "fails contact_strength" in r.conflict[0]


def test_a_stage_without_module_takes_the_smallest_module_and_width_that_carry_the_load():
    t_in = 7500 / _omega(1450)
    # a free housing: every module is a candidate (with a standard one, a module whose pair reaches no standard a_w
    # in the x-sum window is passed over whatever its strength: test_a_sized_stage_sits_on_a_standard_...)
    a = gd.Drive(power_kw=7.5, n_in_rpm=1450, stages=[gd.GearStage(z1=20, z2=60, material="42CrMo4", center_distance="free",
                                                                   shift_bounds=(-1.5, 3.0), mating_type="none")]).analyse()
    s = a.stages[0]["summary"]
    m, b = s["m"], s["face_width_mm"]
    assert a.success and m in ISO54
    assert b in _grid_widths(m, 20)
    assert min(_pair_margins(m, b, s["x1"], s["x2"], t_in, 1450).values()) >= -1e-9
    narrower = [w for w in _grid_widths(m, 20) if w < b]
    if narrower:     # the next narrower width of the range fails
        assert min(_pair_margins(m, max(narrower), s["x1"], s["x2"], t_in, 1450).values()) < 0
    assert m > ISO54[0]
    smaller = ISO54[ISO54.index(m) - 1]           # no width of the range holds at the next smaller module
    for w in _grid_widths(smaller, 20):
        assert min(_pair_margins(smaller, w, s["x1"], s["x2"], t_in, 1450).values()) < 0


def test_the_search_sizes_every_design_at_its_own_load():
    stages = [gd.GearStage(3, z1_range=(17, 17), ratio_range=(2, 3), name="g1"),
              gd.GearStage(None, z1_range=(17, 17), ratio_range=(2, 3), material="42CrMo4", name="g2")]
    r = gd.Drive(power_kw=7.5, n_in_rpm=1450, stages=stages).optimize(6.25, 0.03, "min_mass", top=4)
    assert r.success
    ok = r.table[r.table["feasible"]]
    for _, row in ok.iterrows():
        t_in = 7500 / _omega(1450) * row["g1.ratio"] * 0.98
        n_in = 1450 / row["g1.ratio"]
        got = _pair_margins(row["g2.m"], row["g2.face_width_mm"], row["g2.x1"], row["g2.x2"], t_in, n_in, 17,
                            int(row["g2.z2"]))
        assert min(got.values()) >= -1e-9
    best = r.best.checks.set_index(["item", "check"])["margin"]
    assert {"contact_strength", "root_strength1", "root_strength2"} <= set(best["g2"].index)


def test_an_unknown_material_is_refused_when_the_stage_is_built():
    from geardesign.errors import GearDesignError

    with pytest.raises(GearDesignError, match="material must be a name of the catalog.*'unobtainium'"):
        gd.GearStage(3, material="unobtainium")


def test_a_drive_whose_gear_cannot_carry_the_load_names_the_strength_checks():
    """The closest failing design may be one stopped by a chain check before its gears were solved; the
    message then also names what the closest design evaluated in full fails: here the m = 1.5 mm pair's
    strength (its contact safety at 20 kW is far below S_Hmin, by the pair's own StrengthResult)."""
    stages = [gd.GearStage(1.5, z1_range=(17, 18), ratio_range=(2, 3), material="42CrMo4"),
              gd.ChainStage(catalog="gost13568", strands=(1,), ratio_range=(2, 3))]
    r = gd.Drive(power_kw=20, n_in_rpm=1480, stages=stages).optimize(total_ratio=6)
    assert not r.success
    assert r.message.endswith("of the designs evaluated in full, the closest fails stage 'gear': fails "
                              "contact_strength, root_strength1, root_strength2")
    # every tooth pair of the window is far from carrying 20 kW at 1480 rpm with m = 1.5 mm (z2 from 34 to 54
    # spans its ratios 2 ... 3): both safety factors stay below their minimums with the shifts the stage takes
    t_in = 20_000 / _omega(1480)
    for z2 in (34, 54):
        o = optimize_shifts(17, z2, "max_x_sum", None, "exact", m=1.5)
        res = gd.GearPair(1.5, 17, z2, o.x1, o.x2, face_width_mm=4 * math.pi * 1.5).strength(
            Load(torque_nm=t_in, n_rpm=1480), "42CrMo4")
        assert max(res.S_H1, res.S_H2) < res.S_Hmin and max(res.S_F1, res.S_F2) < res.S_Fmin


def test_the_stage_load_case_takes_its_life_and_application_factor():
    """GearStage(life_h=, application_factor=): the strength checks are the pair's StrengthResult under
    Load(..., life_h, application_factor) at the stage's own torque and speed."""
    stage = gd.GearStage(4, z1=20, z2=60, face_width_mm=40, material="42CrMo4", life_h=5000, application_factor=1.5)
    a = gd.Drive(power_kw=7.5, n_in_rpm=1450, stages=[gd.GivenStage(2, 0.95, "belt"), stage]).analyse()
    s = a.stages[1]["summary"]
    pair = gd.GearPair(4, 20, 60, s["x1"], s["x2"], face_width_mm=40)
    t_in = 7500 / _omega(1450) * 2 * 0.95
    want = _margins(pair.strength(Load(torque_nm=t_in, n_rpm=725, life_h=5000, application_factor=1.5), "42CrMo4"))
    got = a.checks[a.checks["item"] == "gear"].set_index("check")["margin"]
    assert {k: got[k] for k in want} == pytest.approx(want, rel=1e-12)
    endurance = _margins(pair.strength(Load(torque_nm=t_in, n_rpm=725), "42CrMo4"))
    assert want["contact_strength"] != pytest.approx(endurance["contact_strength"], rel=1e-3)   # K_A and life count


@pytest.mark.parametrize("kw, words", [({"life_h": -1.0}, "life_h"), ({"application_factor": 0.5}, "application_factor"),
                                       ({"application_factor": "x"}, "application_factor")])
def test_a_bad_stage_load_case_is_refused_by_name(kw, words):
    from geardesign.errors import GearDesignError

    with pytest.raises(GearDesignError, match=words):
        gd.GearStage(3, material="42CrMo4", **kw)


def test_the_searchs_sized_geometry_is_the_pairs_own_at_the_chosen_module():
    """With a free housing the search solves a sized spur stage's shifts once (at m = 1: every geometric check
    is a margin in module units) and scales the lengths: the table's shifts and centre distance equal those of
    optimize_shifts and GearPair at the chosen module and width."""
    stages = [gd.GearStage(None, z1_range=(19, 19), ratio_range=(3, 3.2), material="42CrMo4", center_distance="free",
                           shift_bounds=(-1.5, 3.0), mating_type="none")]
    r = gd.Drive(power_kw=11, n_in_rpm=1460, stages=stages).optimize(3.1, 0.03, top=3)
    assert r.success
    for _, row in r.table[r.table["feasible"]].iterrows():
        m, b, z2 = row["gear.m"], row["gear.face_width_mm"], int(row["gear.z2"])
        o = optimize_shifts(19, z2, "max_x_sum", None, "exact", m=m, face_width_mm=b)
        assert (row["gear.x1"], row["gear.x2"]) == pytest.approx((o.x1, o.x2), abs=1e-12)
        geo = gd.GearPair(m, 19, z2, o.x1, o.x2, face_width_mm=b).geometry()
        assert row["gear.a_w_mm"] == pytest.approx(geo.a_w, rel=1e-12)


def test_a_sized_stage_sits_on_a_standard_center_distance_with_shifts_a_shop_can_cut():
    """Issue 35 §2-4: a stage sized by its load (defaults) puts a_w on GOST 2185-66, its shifts split the x-sum
    that a_w fixes (balanced specific sliding, optimize_shifts' rule for a fixed x-sum) within |x| <= 1.2, and
    every check holds at the manufactured state (teeth thinned by their GOST 1643 B allowances, the housing at
    either end of its centre-distance allowance)."""
    from geardesign.catalogs import center_distance_series
    from geardesign.gears.manufactured import manufactured_margins, shop_allowances

    stages = [gd.GearStage(None, z1_range=(17, 21), ratio_range=(3, 3.3), material="42CrMo4")]
    r = gd.Drive(power_kw=11, n_in_rpm=1460, stages=stages).optimize(3.15, 0.05, top=4)
    assert r.success
    series = center_distance_series((1, 2))
    for _, row in r.table[r.table["feasible"]].iterrows():
        m, z1, z2, a_w = row["gear.m"], int(row["gear.z1"]), int(row["gear.z2"]), row["gear.a_w_mm"]
        assert np.min(np.abs(series - a_w)) < 1e-9 * a_w                 # a standard a_w, to rounding
        assert -1.2 <= row["gear.x1"] <= 1.2 and -1.2 <= row["gear.x2"] <= 1.2
        o = optimize_shifts(z1, z2, "balanced_sliding", None, "exact", m=m, a_w=float(np.round(a_w)),
                            bounds=(-1.2, 1.2))
        assert (row["gear.x1"], row["gear.x2"]) == pytest.approx((o.x1, o.x2), abs=1e-9)
        pair = gd.GearPair(m, z1, z2, o.x1, o.x2)
        table = pair.checks(jamming=False)
        shop = manufactured_margins(pair, table, shop_allowances(pair))
        assert min(shop.values()) >= -1e-9                                # holds on the shop floor
        # and the allowances really thin the teeth: every moved margin is below its nominal one
        nominal = dict(zip(table["check"], table["margin"]))
        assert shop["tip_thickness1"] < nominal["tip_thickness1"] and shop["contact_ratio"] < nominal["contact_ratio"]
    best = r.best                                   # the rank-1 design analysed again, fixed
    assert best.success and best.min_margin == pytest.approx(r.table["min_margin"].iloc[0], abs=1e-9)
    assert any(k.endswith("_manufactured") for k in best.checks["check"])
    stage = best.drive.stages[0]
    assert stage.center_distance == pytest.approx(r.table["gear.a_w_mm"].iloc[0], rel=1e-9)


def test_a_helical_stage_with_a_total_contact_ratio_check_is_sized():
    """ε_γ = ε_α + ε_β needs a face width (ε_β = b·sin β/(π·m)), which a stage sized by its load has not
    before it is sized: the pair is solved first at m = 1 with the widest width of the sizing range, and
    each candidate again at its own module and width. The stage chosen holds ε_γ ≥ 1.3 (ε_β by ISO 21771:2007
    eq. (83), ε_β = b·sin β/(π·m_n)) and every strength check, by the pair's own geometry and
    StrengthResult at its own shifts."""
    t_in = 15_000 / _omega(1450)
    stage = gd.GearStage(m=None, material="42CrMo4", beta_deg=15, z1=21, z2=55, checks={"eps_gamma_min": 1.3})
    a = gd.Drive(power_kw=15, n_in_rpm=1450, stages=[stage]).analyse()
    s = a.stages[0]["summary"]
    m, b = s["m"], s["face_width_mm"]
    assert a.success and m in ISO54

    def holds(width):
        o = optimize_shifts(21, 55, "max_x_sum", {"eps_gamma_min": 1.3}, "exact", m=m, beta_deg=15, face_width_mm=width)
        if not o.success:
            return False
        pair = gd.GearPair(m, 21, 55, o.x1, o.x2, beta_deg=15, face_width_mm=width)
        eps_gamma = pair.geometry().eps_alpha + width * math.sin(math.radians(15)) / (math.pi * m)
        res = pair.strength(Load(torque_nm=t_in, n_rpm=1450), "42CrMo4")
        return eps_gamma >= 1.3 - 1e-9 and min(_margins(res).values()) >= -1e-9

    assert b in _grid_widths(m, 21, 15)
    assert holds(b)


def test_strength_margins_at_a_flow_per_design_equal_one_flow_each():
    # issue 35 §5: a search meets most flows into a stage with one new tooth pair each; the sizing checks them all
    # in one call with a torque and speed per design, which must give each design's own margins bit for bit
    import numpy as np
    from geardesign.drives.stage_kinds.gear_strength import strength_margins

    st = gd.GearStage(None, material="42CrMo4", life_h=10000.0)
    M, B = np.array([3.0, 4.0, 5.0]), np.array([40.0, 50.0, 60.0])
    Z1, Z2, X = np.array([20.0, 21.0, 22.0]), np.array([80.0, 70.0, 60.0]), np.array([0.2, 0.1, 0.0])
    T, N = np.array([300.0, 500.0, 900.0]), np.array([1400.0, 900.0, 500.0])
    many = strength_margins(st, M, B, Z1, Z2, X, X, T, N)
    for i in range(3):
        one = strength_margins(st, M[i], B[i], Z1[i], Z2[i], X[i], X[i], T[i], N[i])
        assert {k: float(v[i]) for k, v in many.items()} == {k: float(v) for k, v in one.items()}


def test_a_sized_stage_is_no_narrower_than_three_circular_pitches():
    # issue 35: 19/95 at 15 kW came out m 5.5, b 21 mm (b/m 3.8: b = 0.2·d1); the textbook range of spur face widths
    # is 3p <= b <= 5p (Shigley, Standard Handbook of Machine Design, ch. 9), so b >= 3·π·m
    d = gd.Drive(power_kw=15, n_in_rpm=1460, stages=[gd.GearStage(None, z1=19, z2=95, material="42CrMo4")])
    pair = d.analyse().stages[0]["pair"]
    assert pair.face_width_mm >= 3 * math.pi * pair.m
    assert pair.face_width_mm < 3 * math.pi * pair.m + 1 or pair.face_width_mm > 0.2 * 19 * pair.m   # whole mm


def test_a_sized_stage_in_a_free_housing_holds_at_its_manufactured_state():
    # found by the shafts' work (round 12): the stage's candidates were solved at m = 1 as a stage of given module,
    # i.e. without its shift window and mating type (x2 2.18 on the ε_α boundary), and the best design failed
    # interference2_manufactured and contact_ratio_manufactured when analysed
    st = gd.GearStage(None, material="42CrMo4", center_distance="free")
    r = gd.Drive(power_kw=7.5, n_in_rpm=1450, stages=[st]).optimize(4.0)
    assert r.success
    best = r.best.drive.stages[0]
    lo, hi = st.bounds
    assert lo <= best.x1 <= hi and lo <= best.x2 <= hi
    a = r.best.drive.analyse()
    assert a.success, a.message
    shop = a.checks[a.checks["check"].str.endswith("_manufactured")]
    assert len(shop) >= 2 and (shop["margin"].astype(float) >= 0).all()
