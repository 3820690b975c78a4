"""geardesign.drives.shafting_analysis: the drive's shafts, bearings, efficiencies and K_Hβ from the shafts.

Independent checks written here: statics of a shaft on two bearings (every load balanced, 1e-9), the beam's
closed-form deflection under a point load (Gere & Goodno, *Mechanics of Materials*, Table H-2 case 5:
w = F·b·x·(L² − b² − x²)/(6·L·E·I) for x <= a) for the mesh misalignment f_sh, K_Hβ of ISO 6336-1:2019
eq. (40) with F_βx = 1.33·f_sh + f_ma (ISO 6336-1:2006 7.6.2.1) and y_β = 320/σ_Hlim·F_βx (7.6.3, through
hardened steel below 5 m/s), the power flow with the computed efficiencies; and that a too-thin seat or a
short-lived bearing fails the design naming its check.
"""
import math

import numpy as np
import pytest

import geardesign as gd
from geardesign.drives.shaft_beam import E_STEEL_MPA, ShaftLoad, ShaftModel, analyse_shaft
from geardesign.drives.shafting import DriveShaft, Shafting
from geardesign.drives.shafting_analysis import (G_STEEL_MPA, element_loads, mesh_misalignment_um,
                                                  two_support_reactions)
from geardesign.errors import GearDesignError
from geardesign.gears.strength import material


def _two_stage(shafting=None, n_in=960.0, **kw):
    return gd.Drive(power_kw=11, n_in_rpm=n_in, stages=[
        gd.GearStage(3, 20, 80, material="42CrMo4", face_width_mm=45, name="fast", beta_deg=12, **kw),
        gd.GearStage(4, 21, 84, material="42CrMo4", face_width_mm=65, name="slow")],
        shafting=Shafting() if shafting is None else shafting)


@pytest.fixture(scope="module")
def two_stage():
    return _two_stage().analyse()


# ---------------------------------------------------------------------------------------------- statics

def test_reactions_balance_random_loads():
    rng = np.random.default_rng(7)
    for _ in range(200):
        m = int(rng.integers(1, 6))
        xa, xb = sorted(rng.uniform(0, 500, 2))
        x = rng.uniform(0, 600, m)
        fy, fz, fx, y = (rng.normal(0, 5000, m) for _ in range(4))
        r = two_support_reactions(x, fy, fz, fx, y, xa, xb)
        scale = 1 + np.abs(np.concatenate([fy, fz, fx])).max() * 600
        # Σ F = 0 in y and z, Σ F_x = 0 with A locating
        assert abs(fy.sum() + r["Ay"] + r["By"]) <= 1e-9 * scale
        assert abs(fz.sum() + r["Az"] + r["Bz"]) <= 1e-9 * scale
        assert abs(fx.sum() + r["Ax"]) <= 1e-9 * scale
        # Σ M about B (not the point the function takes moments about): x-y plane with the axial couples −y·fx
        assert abs((fy * (x - xb)).sum() + r["Ay"] * (xa - xb) - (y * fx).sum()) <= 1e-9 * scale
        assert abs((fz * (x - xb)).sum() + r["Az"] * (xa - xb)) <= 1e-9 * scale


def test_reactions_agree_with_the_beam(two_stage):
    # the beam of shaft_beam (its own linear system) gives the bearing loads the statics give
    bearings = two_stage.table("bearings")
    for k, a in two_stage.shafting["analyses"].items():
        R = a.reactions
        got = bearings[bearings["shaft"] == k]
        np.testing.assert_allclose(got["F_r_n"].to_numpy(), R["R_n"].to_numpy(), rtol=1e-9)
        if got["bearing_type"].iloc[0] != "tapered_roller":     # a tapered pair shares it: test_tapered_pair_loads
            assert got["F_a_n"].iloc[0] == pytest.approx(abs(R["Rx_n"].iloc[0]), rel=1e-9, abs=1e-9)


def test_element_loads_action_reaction_and_torque_balance(two_stage):
    d = two_stage.drive
    T = two_stage.flow["torque_nm"].to_numpy()
    els = element_loads(d, list(two_stage.stages), T)
    for name in ("fast", "slow"):
        on = [e for es in els.values() for e in es if e.name == name]
        p, w = (next(e for e in on if e.kind == kind) for kind in ("pinion", "wheel"))
        assert (p.fy + w.fy, p.fz + w.fz, p.fx + w.fx) == pytest.approx((0, 0, 0), abs=1e-9)
        st = next(s for s in two_stage.stages if s["stage"].name == name)
        geo = st["pair"].geometry()
        # the operating pitch circle's F_t = 2000·T1/d_w1 and F_r = F_t·tan α_wt (gears/forces.py's convention)
        F_t = 2000 * st["flow"].torque_in_nm / geo.dw1
        assert abs(p.fz) == pytest.approx(F_t, rel=1e-12)
        assert abs(p.fy) == pytest.approx(F_t * math.tan(math.radians(geo.alpha_w_deg)), rel=1e-12)
    for k, es in els.items():
        assert abs(sum(e.torque_nm for e in es)) <= 1e-9 * max(T)


# ------------------------------------------------------------------------------------------- f_sh, K_Hβ

def _point_deflection(F, a, L, x, EI):
    """Simply supported beam, point load F at a: deflection at x (Gere & Goodno Table H-2 case 5)."""
    b = L - a
    if x <= a:
        return F * b * x * (L * L - b * b - x * x) / (6 * L * EI)
    xr, ar = L - x, b
    return F * a * xr * (L * L - a * a - xr * xr) / (6 * L * EI)


def test_f_sh_and_K_Hbeta_method_C_from_uniform_shafts():
    # a spur stage on two uniform shafts, the gears off centre at 0.35 L: f_sh by the closed-form beam
    L, a, b_face, d1, d2 = 240.0, 84.0, 50.0, 40.0, 55.0
    lay = (DriveShaft(0, [(L, d1)], [0.0, L], {"g": a, "coupling": 0.0}),
           DriveShaft(1, [(L, d2)], [0.0, L], {"g": a, "coupling": L}))
    drive = gd.Drive(power_kw=7.5, n_in_rpm=700, stages=[gd.GearStage(3, 22, 77, 0.2, 0.1, material="42CrMo4",
                                                                         face_width_mm=b_face, name="g")],
                     shafting=Shafting(layout=lay))
    r = drive.analyse()
    st = r.stages[0]
    geo = st["pair"].geometry()
    T1 = st["flow"].torque_in_nm
    F_t = 2000 * T1 / geo.dw1
    F = F_t / math.cos(math.radians(geo.alpha_w_deg))           # the transverse tooth force (β = 0)
    EI1, EI2 = E_STEEL_MPA * math.pi * d1 ** 4 / 64, E_STEEL_MPA * math.pi * d2 ** 4 / 64
    ends = (a - b_face / 2, a + b_face / 2)
    # pinion and wheel pushed apart along the tooth force: the relative deflection is the sum of the two
    delta = [_point_deflection(F, a, L, x, EI1) + _point_deflection(F, a, L, x, EI2) for x in ends]
    twist = geo.dw1 / 2 * T1 * 1000 * b_face / (2 * G_STEEL_MPA * math.pi * geo.dw1 ** 4 / 32)
    # the torque comes in from the coupling at x = 0, left of the gear: the far (right) end lags, along the force
    f_nominal = 1000 * abs(delta[1] - delta[0] + twist)
    mm = r.table("mesh_misalignment").iloc[0]
    assert mm["f_sh_nominal_um"] == pytest.approx(f_nominal, rel=1e-9)
    # K_Hβ by method C (ISO 6336-1:2019 eq. (40); F_βx, y_β of the 2006 edition) from the f_sh it was given
    res = st["strength"]
    fac = res.factors.set_index("symbol")
    K_v, c_gb, f_ma, F_beta = (float(fac.loc[s, "value"]) for s in ("K_v", "c_gamma_beta", "f_ma", "F_beta"))
    f_sh = f_nominal * 1.0 * K_v                                 # K_A = 1
    assert float(fac.loc["f_sh", "value"]) == pytest.approx(f_sh, rel=1e-9)
    w_m = 2000 * T1 / geo.d1 * K_v / b_face                      # F_m/b, F_t on the reference circle (eq. (1))
    F_bx = max(1.33 * f_sh + f_ma, 0.005 * w_m, 0.5 * F_beta)
    v = math.pi * geo.d1 * 700 / 60000
    assert v < 5
    sigma_Hlim = material("42CrMo4").sigma_Hlim_mpa
    y_b = min(320 / sigma_Hlim * F_bx, 25600 / sigma_Hlim, F_bx)
    ratio = c_gb * (F_bx - y_b) / w_m
    K_Hb = 1 + ratio / 2 if ratio <= 2 else math.sqrt(2 * ratio)
    assert mm["K_Hbeta"] == pytest.approx(K_Hb, rel=1e-9)
    assert float(fac.loc["K_Hbeta", "value"]) == pytest.approx(K_Hb, rel=1e-9)


def test_mesh_misalignment_is_a_difference_along_the_force():
    w = [[0.001, 0.0], [0.004, 0.0]]                 # the pinion tilts 3 µm in y over the face
    assert mesh_misalignment_um(w, [[0, 0], [0, 0]], (1.0, 0.0), 30, 0.0, 40, 60) == pytest.approx(3.0)
    assert mesh_misalignment_um(w, [[0, 0], [0, 0]], (0.0, 1.0), 30, 0.0, 40, 60) == pytest.approx(0.0)
    assert mesh_misalignment_um(w, w, (1.0, 0.0), 30, 0.0, 40, 60) == pytest.approx(0.0)


def test_user_given_f_sh_wins():
    r = _two_stage(strength={"factors": {"f_sh": 7.0}}).analyse()
    mm = r.table("mesh_misalignment").set_index("stage")
    assert mm.loc["fast", "source"] == "given by the user"
    fac = next(s for s in r.stages if s["stage"].name == "fast")["strength"].factors.set_index("symbol")
    assert float(fac.loc["f_sh", "value"]) == 7.0


def test_f_sh_from_the_shafts_is_said_to_be_theirs(two_stage):
    # the chain takes the shafts' f_sh as a given factor: its result said "given: f_sh", "f_sh given, not computed"
    # and cited eq. (44) for it, though the user gave nothing
    mm = two_stage.table("mesh_misalignment").set_index("stage")
    for stage in two_stage.stages:
        res = stage["strength"]
        assert mm.loc[stage["stage"].name, "source"] == "shafts"
        assert "f_sh" not in res.given and not any("f_sh given" in n for n in res.notes)
        assert any("from the shafts" in n for n in res.notes)
        clause = res.factors.set_index("symbol").loc["f_sh", "clause"]
        assert "from the shafts" in clause and float(res.factors.set_index("symbol").loc["f_sh", "value"]) == \
            pytest.approx(mm.loc[stage["stage"].name, "f_sh_um"], rel=1e-12)
    user = _two_stage(strength={"factors": {"f_sh": 7.0}}).analyse()
    res = next(s for s in user.stages if s["stage"].name == "fast")["strength"]
    assert "f_sh" in res.given and "f_sh given, not computed" in res.notes     # the user's own stays given
    assert res.factors.set_index("symbol").loc["f_sh", "clause"] == "given by the caller, not computed"


def test_a_shaft_on_two_nu_bearings_is_not_said_to_locate():
    # an NU bearing's inner ring has no ribs: SKF 17000 example C.3 (tests/data/bearing_life_examples.csv,
    # skf_c3_non_locating) calls its NU 311 the non-locating bearing; the table said "locating A, floating B"
    drive = gd.Drive(power_kw=15, n_in_rpm=1450, stages=[gd.GearStage(4, 23, 117, 0.3, -0.3, material="42CrMo4",
                                                                       face_width_mm=40, name="g")],
                     shafting=Shafting(bearing_type="cylindrical_roller"))
    bearings = drive.analyse().table("bearings")
    assert set(bearings["bearing_type"]) == {"cylindrical_roller"}
    assert not any(bearings["mounting"].str.contains("locating A")) and all(bearings["mounting"].str.startswith("NU pair"))
    ball = gd.Drive(power_kw=15, n_in_rpm=1450, stages=drive.stages, shafting=Shafting(bearing_type="deep_groove"))
    assert set(ball.analyse().table("bearings")["mounting"]) == {"locating A, floating B"}


# ------------------------------------------------------------------------------------------- efficiency

def test_computed_efficiencies_in_the_power_flow():
    oil = gd.Lubricant(220, 19)
    sh = Shafting(lubricant=oil)
    r = gd.Drive(power_kw=11, n_in_rpm=960, stages=[
        gd.GearStage(3, 20, 80, material="42CrMo4", face_width_mm=45, name="fast"),
        gd.GearStage(4, 21, 84, material="42CrMo4", face_width_mm=65, name="slow", efficiency=0.95)],
        shafting=sh).analyse()
    eff = r.table("efficiency").set_index("stage")
    assert eff.loc["fast", "source"] == "computed" and eff.loc["slow", "source"] == "given"
    assert eff.loc["slow", "efficiency"] == 0.95                     # a given efficiency wins
    assert 0.97 < eff.loc["fast", "efficiency"] < 1.0
    # the flow: T_k = T_{k−1}·u_k·η_k with the computed η (its fixed point to 1e-6)
    T = r.flow["torque_nm"].to_numpy()
    assert T[1] == pytest.approx(T[0] * 4 * eff.loc["fast", "efficiency"], rel=1e-5)
    assert T[2] == pytest.approx(T[1] * 4 * 0.95, rel=1e-12)
    P = r.flow["power_kw"].to_numpy()
    assert r.overall_efficiency == pytest.approx(P[-1] / P[0], rel=1e-12)
    assert r.heat_kw == pytest.approx(P[0] - P[-1], rel=1e-12)
    # the stage's losses: mesh + bearings (both shafts' bearings charged once: shaft 0 and 1 to fast, 2 to slow)
    assert eff.loc["fast", "loss_w"] == pytest.approx(eff.loc["fast", "mesh_loss_w"] + eff.loc["fast", "bearing_loss_w"])


def test_without_lubricant_efficiencies_stay(two_stage):
    eff = two_stage.table("efficiency")
    assert (eff["efficiency"] == 0.98).all() and (eff["source"] == "default").all()


# ------------------------------------------------------------------------------------ checks that fail

def test_checks_appear(two_stage):
    c = two_stage.checks
    items = set(c["item"])
    bearings = two_stage.table("bearings").set_index("name")
    # the checks table names the bearing chosen: "bearing 0A 32006 X"
    assert set(bearings.index) == {f"bearing {k}{t} {bearings.loc[bearings['shaft'] == k, 'designation'].iloc[0]}"
                                   for k in (0, 1, 2) for t in "AB"}
    assert {"shaft 0", "shaft 1", "shaft 2", "key 1 slow"} | set(bearings.index) <= items
    item_1b = next(n for n in bearings.index if n.startswith("bearing 1B"))
    assert set(c.loc[c["item"] == item_1b, "check"]) >= {"life", "static_safety", "speed"}
    # the bearings reach the required life, the seats S_min, the keys sit on the seat diameters
    assert (two_stage.table("bearings")["L10h"] >= 20_000).all()
    assert (two_stage.table("sections")[["S_D", "S_F"]].min(axis=1) >= 1.2).all()
    shafts = two_stage.table("shafts").set_index("shaft")
    keys = two_stage.table("seat_keys").set_index("name")
    assert keys.loc["key 1 slow", "d_mm"] == shafts.loc[1, "d_gear_mm"]
    assert shafts.loc[1, "d_bearing_mm"] == float(bearings.loc[item_1b, "bore_mm"])


def test_too_thin_shaft_fails_by_name():
    lay = (DriveShaft(1, [(40.0, 14.0), (170.0, 16.0), (40.0, 14.0)], [20.0, 230.0],
                      {"fast": 72.5, "slow": 152.5}, bearings=("6202", "6202")),)
    r = _two_stage(Shafting(layout=lay)).analyse()
    assert not r.success
    bad = r.checks[~r.checks["ok"]]
    assert ("shaft 1", "safety key slow") in set(zip(bad["item"], bad["check"]))
    assert "shaft 1: safety key slow" in r.message


def test_short_bearing_life_fails_by_name():
    lay = (DriveShaft(0, [(260.0, 30.0)], [70.0, 250.0], {"fast": 112.5, "coupling": 0.0},
                      bearings=("6206", "6206")),)
    r = _two_stage(Shafting(layout=lay, life_h=200_000)).analyse()
    bad = r.checks[~r.checks["ok"]]
    assert ("bearing 0A 6206", "life") in set(zip(bad["item"], bad["check"]))
    assert "bearing 0A 6206: life" in r.message


def test_thicker_shaft_is_never_less_safe():
    least = []
    for d in (20.0, 25.0, 30.0, 40.0, 55.0):
        lay = (DriveShaft(1, [(250.0, d)], [20.0, 230.0], {"fast": 72.5, "slow": 152.5}),)
        r = _two_stage(Shafting(layout=lay)).analyse()
        least.append(float(r.table("shafts").set_index("shaft").loc[1, "least_safety"]))
    assert all(b >= a for a, b in zip(least, least[1:]))


def test_given_layout_names_what_it_misses():
    lay = (DriveShaft(1, [(250.0, 40.0)], [20.0, 230.0], {"fast": 72.5}),)
    with pytest.raises(GearDesignError, match="'slow'"):
        _two_stage(Shafting(layout=lay)).analyse()


def test_json_has_the_tables(two_stage):
    out = two_stage.to_dict()
    for k in ("shafts", "bearings", "sections", "seat_keys", "efficiency", "mesh_misalignment"):
        assert k in out
    assert math.isfinite(out["overall_efficiency"])
    with pytest.raises(GearDesignError, match="table must be one of"):
        two_stage.table("nope")


def test_beam_path_agrees_with_analyse_shaft(two_stage):
    from geardesign.drives.shafting_analysis import shaft_deflections

    for k, a in two_stage.shafting["analyses"].items():
        xq = np.linspace(0.0, a.model.length_mm, 7)
        R, w = shaft_deflections(a.model, xq)
        ref = a.deflection_at(xq)
        scale = np.abs(ref[["wy_mm", "wz_mm"]].to_numpy()).max()
        np.testing.assert_allclose(w.T, ref[["wy_mm", "wz_mm"]].to_numpy(), rtol=0, atol=1e-10 * scale)
        np.testing.assert_allclose(R[0], a.reactions["Ry_n"].to_numpy(), rtol=1e-10, atol=1e-8)
        np.testing.assert_allclose(R[1], a.reactions["Rz_n"].to_numpy(), rtol=1e-10, atol=1e-8)


def test_cut_on_shaft_rule_and_body_in_the_default_shaft():
    from geardesign.drives.shafting_analysis import cut_on_shaft

    # rim over the keyway (d_f − d)/2 − 0.05·d against 2.5·m, written out
    for d_f, m, d in ((54.3, 3.0, 35.0), (54.3, 3.0, 45.0), (200.0, 4.0, 60.0)):
        assert cut_on_shaft(d_f, m, d) == ((d_f - d) / 2 - 0.05 * d < 2.5 * m)
    # a default shaft whose pinion is cut on it: the pinion body (its root diameter over its face width) is a section,
    # it has no key, and its sides are checked as shoulders
    r = _two_stage(Shafting(bearing_series="63")).analyse()
    keys = set(r.table("seat_keys")["name"])
    sections = r.table("sections")
    shaft0 = r.table("shafts").set_index("shaft").loc[0]
    pinion = next(s for s in r.stages if s["stage"].name == "fast")["pair"].geometry()
    if cut_on_shaft(pinion.df1, 3.0, shaft0["d_gear_mm"]):
        assert "key 0 fast" not in keys
        assert sections["section"].str.startswith("gear body").any()
    else:
        assert "key 0 fast" in keys


def test_stiff_shafts_meet_the_iso_estimate():
    # Shafting(stiff=True): every gear pair's f_sh from its default shafts at most ISO 6336-1 eq. (44)'s
    from geardesign.drives.shafting_analysis import iso_f_sh_um

    d = gd.Drive(power_kw=4, n_in_rpm=1450, shafting=Shafting(stiff=True), stages=[
        gd.GearStage(2.5, 22, 88, material="42CrMo4", face_width_mm=30, name="g")])
    r = d.analyse()
    st = r.stages[0]
    mm = r.table("mesh_misalignment").iloc[0]
    assert mm["f_sh_nominal_um"] <= iso_f_sh_um(st["stage"], st["pair"], st["flow"].torque_in_nm) * (1 + 1e-12)


def test_a_bought_unit_feeds_the_gear_shaft_through_its_end():
    # a belt (given stage) drives the pinion's shaft: its pulley is the overhung element bringing the torque in
    d = gd.Drive(power_kw=7.5, n_in_rpm=1450, shafting=Shafting(), stages=[
        gd.GivenStage(2, 0.95, "belt"), gd.GearStage(3, 20, 60, material="42CrMo4", face_width_mm=40, name="g")])
    r = d.analyse()
    els = r.shafting["elements"]
    assert sorted(els) == [1, 2]                       # the motor shaft 0 carries no gear: not on the drive's shafts
    belt = next(e for e in els[1] if e.name == "belt")
    T = r.flow["torque_nm"].to_numpy()
    assert belt.side == "left" and abs(belt.torque_nm) == pytest.approx(T[1], rel=1e-12)
    assert next(e for e in els[2] if e.name == "coupling").side == "right"


# ---------------------------------------------------------------------------------------------- the search

def _small_search(**kw):
    return gd.Drive(power_kw=4, n_in_rpm=1450, shafting=Shafting(**kw), stages=[
        gd.GearStage(3, z1_range=(18, 20), ratio_range=(3.2, 3.8), material="42CrMo4", face_width_mm=30)])


def test_search_returns_its_best_on_shafts_and_bearings():
    r = _small_search().optimize(total_ratio=3.5, ratio_tol=0.05, top=3)
    assert r.success and r.best.shafting is not None and r.best.success
    ranked = r.table[r.table["rank"].notna()]
    assert ranked["shafts"].iloc[0] == "holds"
    assert "shaft 1" in set(r.best.checks["item"])
    assert r.best.checks["item"].str.match(r"bearing 0A \S").any()


def test_search_whose_ranked_designs_fail_on_their_bearings_says_so():
    # the input shaft drawn on 6204 bearings, a life of 10^6 h: every ranked design fails on its bearings
    lay = (DriveShaft(0, [(200.0, 20.0)], (20.0, 180.0), {"gear": 60.0, "coupling": 0.0}, bearings=("6204", "6204")),)
    r = _small_search(life_h=1e6, layout=lay).optimize(total_ratio=3.5, ratio_tol=0.05, top=2)
    assert not r.success and r.best is None
    assert "fail with their shafts" in r.message
    assert any("life" in c for c in r.conflict)
    ranked = r.table[r.table["rank"].notna()]
    assert ranked["shafts"].head(2).str.startswith("fails").all()


def test_gear_deflections_are_the_beams(two_stage):
    # each gear's deflection and slope: the beam's at the gear's place (shaft_beam.ShaftAnalysis.deflection_at)
    t = two_stage.table("gear_deflections")
    assert len(t) == 4
    for _, g in t.iterrows():
        d = two_stage.shafting["analyses"][g["shaft"]].deflection_at([g["x_mm"]]).iloc[0]
        assert g["w_mm"] == pytest.approx(d["w_mm"], rel=1e-12) and g["slope_rad"] == pytest.approx(d["th_rad"], rel=1e-9)


def test_a_drawn_shaft_must_carry_a_gear():
    d = gd.Drive(power_kw=4, n_in_rpm=1450, shafting=Shafting(layout=(
        DriveShaft(2, [(200.0, 40.0)], (20.0, 180.0), {"chain": 10.0}),)), stages=[
        gd.GearStage(3, 20, 60, material="42CrMo4", face_width_mm=30, name="g"), gd.ChainStage(z1=17, z2=34)])
    with pytest.raises(GearDesignError, match="shaft 2 carries no gear"):
        d.analyse()


def test_thicker_drawn_shaft_never_less_safe_property(two_stage):
    # random diameters of the intermediate shaft, its loads those of the two-stage drive: the least DIN 743 safety
    # of every checked section never falls as every diameter grows
    from hypothesis import given, settings, strategies as st

    from geardesign.drives.shafting_analysis import _given_geometry, _least, _safety

    els = two_stage.shafting["elements"][1]
    sh = two_stage.drive.shafting

    def least(d):
        ds = DriveShaft(1, [(40.0, d), (170.0, d + 5), (40.0, d)], (20.0, 230.0), {"fast": 72.5, "slow": 152.5})
        return _least(_safety(_given_geometry(ds, els), els, sh, sh._material)[0].table)

    @settings(max_examples=12, deadline=None)
    @given(st.floats(18.0, 90.0), st.floats(0.5, 20.0))
    def check(d, step):
        assert least(d + step) >= least(d) * (1 - 1e-12)

    check()


@pytest.mark.parametrize("supports", [(10.0, 230.0), (0.0, 120.0, 240.0)])
def test_beam_deflections_on_two_and_three_supports(supports):
    # the lean beam against shaft_beam.analyse_shaft (its own linear system), a stepped shaft, forces and a couple
    from geardesign.drives.shafting_analysis import beam_deflections

    secs = [(60.0, 30.0), (120.0, 40.0, 10.0), (60.0, 30.0)]
    loads = [ShaftLoad(50.0, fy_n=-2000.0, fz_n=800.0), ShaftLoad(170.0, fy_n=1500.0, fx_n=900.0, y_mm=40.0),
             ShaftLoad(235.0, fz_n=-600.0)]
    a = analyse_shaft(ShaftModel(secs, supports, loads))
    xq = np.linspace(0.0, 240.0, 9)
    R, w = beam_deflections(secs, supports, [ld.x_mm for ld in loads], [ld.fy_n for ld in loads],
                            [ld.fz_n for ld in loads], [-ld.y_mm * ld.fx_n for ld in loads], [0.0] * 3, xq)
    ref = a.deflection_at(xq)
    scale = np.abs(ref[["wy_mm", "wz_mm"]].to_numpy()).max()
    np.testing.assert_allclose(w.T, ref[["wy_mm", "wz_mm"]].to_numpy(), rtol=0, atol=1e-10 * scale)
    np.testing.assert_allclose(R[0], a.reactions["Ry_n"].to_numpy(), rtol=1e-10, atol=1e-8)
    np.testing.assert_allclose(R[1], a.reactions["Rz_n"].to_numpy(), rtol=1e-10, atol=1e-8)


# ------------------------------------------------------------------------------- tapered roller pairs

def _table7(fr_a, fr_b, Y_a, Y_b, ka):
    """SKF 17000/1 EN Table 7 (p. 682), written out: two tapered roller bearings adjusted against each other, the
    external axial force ka > 0 toward B (cases 1a-1c), < 0 toward A (cases 2a-2c)."""
    ia, ib = 0.5 * fr_a / Y_a, 0.5 * fr_b / Y_b
    if ka >= 0:
        return (ia, ia + ka) if ia + ka >= ib else (ib - ka, ib)
    k = -ka
    return (ib + k, ib) if ib + k >= ia else (ia, ia - k)


def _iso281_roller_life_h(row, fr, fa, n_rpm):
    """ISO 281 L10h of a tapered roller bearing from its catalog row: P = Fr (Fa/Fr <= e) or 0.4·Fr + Y·Fa,
    L10 = (C/P)^(10/3) (SKF 17000/1 EN pp. 88, 680)."""
    P = fr if fa <= row["e"] * fr else 0.4 * fr + row["Y"] * fa
    return 1e6 / (60.0 * n_rpm) * (1000.0 * row["C_kn"] / P) ** (10.0 / 3.0)


@pytest.fixture(scope="module")
def tapered_catalog():
    import pandas as pd
    from pathlib import Path

    return pd.read_csv(Path(gd.__file__).resolve().parents[1] / "catalogs" / "bearings_tapered_roller.csv",
                       dtype={"series": str}).set_index("designation")


def _check_pair(r, k, tapered_catalog, arrangement="X"):
    """The tapered pair of shaft k re-checked: its axial loads by Table 7 from the elements' axial forces, each
    bearing's L10h by ISO 281 from the catalog row."""
    b = r.table("bearings")
    mine = b[b["shaft"] == k].reset_index(drop=True)
    row = tapered_catalog.loc[mine["designation"].iloc[0]]
    fx = sum(e.fx for e in r.shafting["elements"][k])           # the axial force on the shaft, +x (toward B)
    ka = fx if arrangement == "X" else -fx
    fa = _table7(mine["F_r_n"][0], mine["F_r_n"][1], row["Y"], row["Y"], ka)
    for i in (0, 1):
        assert mine["F_a_n"][i] == pytest.approx(fa[i], rel=1e-12, abs=1e-9)
        life = _iso281_roller_life_h(row, mine["F_r_n"][i], fa[i], mine["n_rpm"][i])
        assert mine["L10h"][i] == pytest.approx(life, rel=1e-9)
        assert mine["ok"][i] == (life >= 20_000)
    return mine


def test_table7_written_out_agrees_with_the_library():
    from geardesign.drives.bearing import tapered_axial_loads

    rng = np.random.default_rng(3)
    for _ in range(200):
        fr_a, fr_b = rng.uniform(1, 1e4, 2)
        Y_a, Y_b = rng.uniform(1.3, 2.1, 2)
        ka = rng.normal(0, 3000)
        got = [float(v) for v in tapered_axial_loads(fr_a, fr_b, Y_a, Y_b, ka)]
        assert got == pytest.approx(_table7(fr_a, fr_b, Y_a, Y_b, ka), rel=1e-12)


def test_helical_input_shaft_deep_groove_fails_tapered_pair_holds(tapered_catalog):
    # the helical fast stage's input shaft drawn with 30 mm seats: no deep groove bearing of bore 30 (6206, 6306)
    # reaches 20 000 h under its radial and axial load (gd.check_bearing one by one); "auto" then takes a pair of
    # tapered roller bearings of bore 30, which holds
    lay = (DriveShaft(0, [(260.0, 30.0)], [70.0, 250.0], {"fast": 112.5, "coupling": 0.0}),)
    deep = _two_stage(Shafting(layout=lay, bearing_type={0: "deep_groove"})).analyse()
    b = deep.table("bearings")
    a = b[b["shaft"] == 0].iloc[0]
    assert a["bearing_type"] == "deep_groove_ball" and not a["ok"]
    for name in ("6206", "6306"):
        assert not gd.check_bearing(name, a["F_r_n"], a["F_a_n"], a["n_rpm"], life_h=20_000).ok
    bad = deep.checks[~deep.checks["ok"]]
    assert (f"bearing 0A {a['designation']}", "life") in set(zip(bad["item"], bad["check"]))

    auto = _two_stage(Shafting(layout=lay)).analyse()
    mine = _check_pair(auto, 0, tapered_catalog)
    assert (mine["bearing_type"] == "tapered_roller").all() and mine["ok"].all()
    assert mine["bore_mm"].iloc[0] == 30.0 and mine["mounting"].iloc[0] == "tapered pair (X)"
    shafts = auto.table("shafts").set_index("shaft")
    assert shafts.loc[0, "bearings"] == f"{mine['designation'][0]}/{mine['designation'][0]}"
    assert not auto.checks["item"].str.startswith("bearing 0").pipe(lambda s: auto.checks.loc[s, "ok"]).eq(False).any()
    # the smallest outside diameter of the tapered rows of bore 30 that holds under the pair's loads
    for des, row in tapered_catalog[(tapered_catalog["d_mm"] == 30) & (tapered_catalog["D_mm"] < mine["D_mm"][0])].iterrows():
        fa = _table7(mine["F_r_n"][0], mine["F_r_n"][1], row["Y"], row["Y"],
                     sum(e.fx for e in auto.shafting["elements"][0]))
        lives = [_iso281_roller_life_h(row, mine["F_r_n"][i], fa[i], mine["n_rpm"][i]) for i in (0, 1)]
        assert min(lives) < 20_000, des


def test_auto_on_a_default_shaft_and_the_rule(two_stage, tapered_catalog):
    # the default shafts: "auto" keeps a radial bearing on the seat when one holds, else a tapered pair on it
    from geardesign.drives.bearing import bearing_catalog

    radial = bearing_catalog(["62", "63", "NU2", "NU3"])
    b = two_stage.table("bearings")
    for k in (0, 1, 2):
        mine = b[b["shaft"] == k].reset_index(drop=True)
        n, bore = mine["n_rpm"][0], mine["bore_mm"][0]
        fa = abs(sum(e.fx for e in two_stage.shafting["elements"][k]))     # a radial bearing A locates: all of it
        at_seat = radial[radial["d_mm"] == bore]
        holds = {row["designation"]: gd.check_bearing(row["designation"], mine["F_r_n"][0], fa, n, life_h=20_000).ok
                 and gd.check_bearing(row["designation"], mine["F_r_n"][1], 0.0, n, life_h=20_000).ok
                 for _, row in at_seat.iterrows()}
        if mine["bearing_type"][0] == "tapered_roller":
            assert not any(holds.values())         # no radial bearing on this seat holds
            _check_pair(two_stage, k, tapered_catalog)
        else:                                      # the smallest radial one of this bore that holds
            assert holds[mine["designation"][0]]
            assert mine["D_mm"][0] == min(at_seat.set_index("designation").loc[[d for d, ok in holds.items() if ok],
                                                                              "D_mm"])
    assert set(two_stage.table("bearings")["bearing_type"]) >= {"tapered_roller"}


def test_o_arrangement_swaps_which_bearing_takes_the_axial_force(tapered_catalog):
    lay = (DriveShaft(0, [(260.0, 30.0)], [70.0, 250.0], {"fast": 112.5, "coupling": 0.0}),)
    r = _two_stage(Shafting(layout=lay, bearing_type={0: "tapered"}, arrangement="O")).analyse()
    _check_pair(r, 0, tapered_catalog, arrangement="O")
    assert r.table("shafts").set_index("shaft").loc[0, "mounting"] == "tapered pair (O)"


def test_given_tapered_bearings_are_a_pair(tapered_catalog):
    lay = (DriveShaft(0, [(260.0, 30.0)], [70.0, 250.0], {"fast": 112.5, "coupling": 0.0},
                      bearings=("30206", "30206")),)
    r = _two_stage(Shafting(layout=lay)).analyse()
    _check_pair(r, 0, tapered_catalog)
    mixed = (DriveShaft(0, [(260.0, 30.0)], [70.0, 250.0], {"fast": 112.5, "coupling": 0.0},
                        bearings=("30206", "6206")),)
    with pytest.raises(GearDesignError, match="tapered roller bearing is mounted against another"):
        _two_stage(Shafting(layout=mixed)).analyse()


# ------------------------------------------------------------------- the search re-sizes for the shafts' K_Hβ

def test_search_resizes_a_stage_that_fails_with_its_shafts_k_hbeta():
    # the input shaft drawn slender (30 mm, 360 mm between its bearings, the pinion 90 mm from A): the search's
    # first design, sized with ISO 6336-1 eq. (44)'s f_sh, fails its contact strength with the f_sh of its shafts
    # (and only that); the search sizes the stage again and returns a design that holds, as Drive.analyse() finds
    lay = (DriveShaft(0, [(400.0, 30.0)], (20.0, 380.0), {"g": 110.0, "coupling": 0.0}),)
    d = gd.Drive(power_kw=4, n_in_rpm=1450, shafting=Shafting(layout=lay), stages=[
        gd.GearStage(None, material="42CrMo4", name="g", z1_range=(18, 20), ratio_range=(3.2, 3.8))])
    r = d.optimize(total_ratio=3.5, ratio_tol=0.05, top=1)
    first = r.table[r.table["rank"] == 1].iloc[0]
    # rank 1 as the search sized it, analysed on its shafts: fails its contact strength alone, with K_Hβ from f_sh
    as_sized = gd.Drive(power_kw=4, n_in_rpm=1450, shafting=Shafting(layout=lay), stages=[
        gd.GearStage(first["g.m"], int(first["g.z1"]), int(first["g.z2"]), first["g.x1"], first["g.x2"],
                     material="42CrMo4", name="g", face_width_mm=first["g.face_width_mm"])]).analyse()
    bad = as_sized.checks[~as_sized.checks["ok"]]
    assert list(zip(bad["item"], bad["check"])) == [("g", "contact_strength")]
    mm = as_sized.table("mesh_misalignment").iloc[0]
    assert mm["source"] == "shafts" and mm["K_Hbeta"] > mm["K_Hbeta_default"]
    # the search's answer: the same teeth, a larger size, every check holding on the shafts
    assert r.success and r.best.success and "re-sized" in r.message and first["shafts"].startswith("holds re-sized")
    again = r.best.drive.analyse()
    assert again.success and again.min_margin == pytest.approx(r.best.min_margin, rel=1e-9, abs=1e-12)
    st = again.drive.stages[0]
    assert (st.z1, st.z2) == (int(first["g.z1"]), int(first["g.z2"]))
    assert (st.m, st.width_mm) > (first["g.m"], first["g.face_width_mm"])
    assert again.table("mesh_misalignment").iloc[0]["source"] == "shafts"


def test_a_re_sized_design_is_compared_with_the_ranks_after_it():
    # re-sizing only grows a design: rank 1 re-sized to m 6 must not be taken while a later rank, smaller as
    # ranked, was never analysed; the message's figures are the returned design's, not the ranked ones
    lay = (DriveShaft(0, [(400.0, 25.0)], (20.0, 380.0), {"g": 110.0, "coupling": 0.0}),)
    d = gd.Drive(power_kw=4, n_in_rpm=1450, shafting=Shafting(layout=lay), stages=[
        gd.GearStage(None, material="42CrMo4", name="g", z1_range=(18, 20), ratio_range=(3.2, 3.8))])
    r = d.optimize(total_ratio=3.5, ratio_tol=0.05, top=6)
    ranked = r.table[r.table["rank"].notna()]
    assert r.success and r.objective == "min_size"
    smaller = ranked[ranked["size_mm2"] < r.best.size_mm2]
    assert len(smaller) > 1 and (smaller["shafts"] != "not analysed").all()
    held_as_ranked = ranked[ranked["shafts"] == "holds"]
    assert (r.best.size_mm2 <= held_as_ranked["size_mm2"]).all()
    assert f"size {r.best.size_mm2:.6g} mm², mass {r.best.mass_kg:.4g} kg" in r.message


def test_a_mesh_tilted_past_the_chain_fails_by_name():
    # a 10 mm input shaft 1.5 m long: f_sh beyond the 10 mm the strength chain takes stopped the analysis with an
    # error (factors['f_sh'] must be in [0, 10000]); now the stage fails its check shaft_misalignment
    lay = (DriveShaft(0, [(1500.0, 10.0)], (20.0, 1480.0), {"g": 400.0, "coupling": 0.0}),)
    r = gd.Drive(power_kw=4, n_in_rpm=1450, shafting=Shafting(layout=lay), stages=[
        gd.GearStage(3, 20, 70, material="42CrMo4", name="g", face_width_mm=30)]).analyse()
    row = r.checks[(r.checks["item"] == "g") & (r.checks["check"] == "shaft_misalignment")].iloc[0]
    mm = r.table("mesh_misalignment").iloc[0]
    assert mm["f_sh_um"] > 1e4 and row["margin"] == pytest.approx(1 - mm["f_sh_um"] / 1e4, rel=1e-12)
    assert not row["ok"] and "g: shaft_misalignment" in r.message


def test_beam_deflections_many_loads_take_the_array_path():
    # past SCALAR_BEAM_MAX a two-support shaft is solved by the array code: the same beam as analyse_shaft
    from geardesign.drives import shafting_analysis as sa

    secs = [(60.0, 30.0), (120.0, 40.0, 10.0), (60.0, 30.0)]
    xs = np.linspace(1.0, 239.0, 70)
    assert len(secs) + xs.size ** 2 > sa.SCALAR_BEAM_MAX
    loads = [ShaftLoad(float(x), fy_n=100.0 * math.sin(x), fz_n=-50.0 * math.cos(x), fx_n=20.0, y_mm=25.0) for x in xs]
    a = analyse_shaft(ShaftModel(secs, (10.0, 230.0), loads))
    xq = np.linspace(0.0, 240.0, 9)
    R, w = sa.beam_deflections(secs, (10.0, 230.0), xs, [ld.fy_n for ld in loads], [ld.fz_n for ld in loads],
                               [-ld.y_mm * ld.fx_n for ld in loads], np.zeros(xs.size), xq)
    ref = a.deflection_at(xq)[["wy_mm", "wz_mm"]].to_numpy()
    np.testing.assert_allclose(w.T, ref, rtol=0, atol=1e-10 * np.abs(ref).max())
    np.testing.assert_allclose(R[0], a.reactions["Ry_n"].to_numpy(), rtol=1e-10)


def test_beam_deflections_plain_float_path_equals_the_array_path():
    # a drive's two-support shaft is solved in plain floats (the speed of the drive's analysis, issue 37): the same
    # beam as the array code to 1e-12 of F·L³/EI on random stepped, bored shafts with forces and couples, loads on
    # section ends and on the supports, queries at the ends; and a scalar query gives a (2,) array
    from hypothesis import assume, given, settings, strategies as st

    from geardesign.drives import shafting_analysis as sa

    @settings(max_examples=150, deadline=None)
    @given(st.data())
    def check(data):
        n = data.draw(st.integers(1, 6))
        secs = [(data.draw(st.floats(5.0, 100.0)), d, data.draw(st.sampled_from([0.0, 0.3, 0.6])) * d)
                for d in (data.draw(st.floats(10.0, 80.0)) for _ in range(n))]
        ends = np.concatenate([[0.0], np.cumsum([s[0] for s in secs])])
        L = float(ends[-1])
        where = st.one_of(st.floats(0.0, L), st.sampled_from(ends.tolist()))
        a, b = sorted(data.draw(st.lists(where, min_size=2, max_size=2, unique=True)))
        assume(b - a >= 1.0)        # (a span of a micrometre: the array code's own rounding dominates)
        m = data.draw(st.integers(0, 6))
        x = data.draw(st.lists(st.one_of(where, st.sampled_from([a, b])), min_size=m, max_size=m))
        f = st.one_of(st.just(0.0), st.floats(-1e4, -1e-3), st.floats(1e-3, 1e4))
        fy, fz, cy, cz = (data.draw(st.lists(f, min_size=m, max_size=m)) for _ in range(4))
        xq = data.draw(st.lists(where, min_size=1, max_size=5)) + [0.0, L]
        R1, w1 = sa.beam_deflections(secs, (a, b), x, fy, fz, cy, cz, xq)
        old = sa.SCALAR_BEAM_MAX
        try:
            sa.SCALAR_BEAM_MAX = -1
            R2, w2 = sa.beam_deflections(secs, (a, b), x, fy, fz, cy, cz, xq)
        finally:
            sa.SCALAR_BEAM_MAX = old
        EI = E_STEEL_MPA * math.pi * min(s[1] ** 4 - s[2] ** 4 for s in secs) / 64.0
        scale = (sum(map(abs, fy + fz)) * L + sum(map(abs, cy + cz))) * L * L / EI
        assert w1.shape == w2.shape == (2, len(xq))
        np.testing.assert_allclose(w1, w2, rtol=0, atol=1e-12 * scale + 1e-300)
        np.testing.assert_allclose(R1, R2, rtol=0, atol=1e-12 * (sum(map(abs, fy + fz)) + sum(map(abs, cy + cz)) / L))

    check()
    R, w = sa.beam_deflections([(200.0, 40.0)], (0.0, 200.0), [100.0], [-1000.0], [0.0], [0.0], [0.0], 100.0)
    assert w.shape == (2,) and R.shape == (2, 2)
    assert w[0] == pytest.approx(-1000 * 200 ** 3 / (48 * E_STEEL_MPA * math.pi * 40 ** 4 / 64), rel=1e-12)


def test_two_support_reactions_refuse_lists_of_different_lengths():
    with pytest.raises(GearDesignError, match="must be of one length, got 2, 1"):
        two_support_reactions([10.0, 20.0], [1.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0], 0.0, 100.0)


# ------------------------------------------------------------ default shafts stiffened for their gears' K_Hβ

def _conveyor_fixed(power_kw, **shafting):
    # a conveyor reducer's two stages (the search's rank 1 for 15 kW, 1450 rpm, u 24.17), through-hardened 42CrMo4
    return gd.Drive(power_kw=power_kw, n_in_rpm=1450, shafting=Shafting(life_h=20000, **shafting), stages=[
        gd.GearStage(4, 23, 117, 0.338, -0.338, face_width_mm=38, material="42CrMo4", life_h=20000, name="fast"),
        gd.GearStage(6, 21, 96, 0.436, 0.258, face_width_mm=57, material="42CrMo4", life_h=20000, name="slow")])


def test_a_stage_failing_with_its_default_shafts_gets_them_a_bore_step_thicker(monkeypatch):
    """At 8 kW the fast stage holds with ISO 6336-1's default f_sh but fails its contact strength with K_Hβ from its
    shafts as DIN 743 sizes them: a larger gear would not help (F_t/b and f_sh fall together), a stiffer shaft does
    (f_sh ∝ 1/d⁴). The pair's two default shafts go to the next bore of their bearing series and the drive holds;
    without the step (STIFFEN_ROUNDS 0) it fails, named. The stiffened drive is what Shafting(min_bore_mm=...) at
    those bores gives, every margin to the bit."""
    from geardesign.drives import shafting_analysis as sa

    monkeypatch.setattr(sa, "STIFFEN_ROUNDS", 0)
    thin = _conveyor_fixed(8).analyse()
    bad = thin.checks[~thin.checks["ok"]]
    assert list(zip(bad["item"], bad["check"])) == [("fast", "contact_strength")]
    mm = thin.table("mesh_misalignment").set_index("stage").loc["fast"]
    assert mm["source"] == "shafts" and mm["K_Hbeta"] > mm["K_Hbeta_default"]
    monkeypatch.setattr(sa, "STIFFEN_ROUNDS", 2)
    stiff = _conveyor_fixed(8).analyse()
    assert stiff.success
    before = thin.table("shafts").set_index("shaft")["d_bearing_mm"]
    after = stiff.table("shafts").set_index("shaft")
    for k in (0, 1):          # the fast pair's shafts: the seat's next bores of their bearing series (one or two steps)
        bores = sa._seat_bores(Shafting(life_h=20000), k)
        assert after.loc[k, "stiffened"] and after.loc[k, "d_bearing_mm"] in bores[bores.index(before[k]) + 1:][:2]
    assert not after.loc[2, "stiffened"] and after.loc[2, "d_bearing_mm"] == before[2]
    given = _conveyor_fixed(8, min_bore_mm={k: float(after.loc[k, "d_bearing_mm"]) for k in (0, 1)}).analyse()
    assert given.checks["margin"].tolist() == stiff.checks["margin"].tolist()


def test_stiffening_that_does_not_make_the_stage_hold_is_not_kept():
    # at 15 kW two bore steps do not save the fast stage: its shafts stay as DIN 743 sized them, and it fails, named
    r = _conveyor_fixed(15).analyse()
    assert not r.success and ("fast", "contact_strength") in set(zip(r.checks["item"], r.checks["check"]))
    assert not r.table("shafts")["stiffened"].any()


def test_min_bore_is_checked_by_name_and_only_thickens():
    with pytest.raises(GearDesignError, match=r"min_bore_mm\[1\]"):
        Shafting(min_bore_mm={1: -5})
    with pytest.raises(GearDesignError, match="min_bore_mm: a shaft is a whole number"):
        Shafting(min_bore_mm={"a": 30})
    with pytest.raises(GearDesignError, match="min_bore_mm must be a dict"):
        Shafting(min_bore_mm=30)
    free = _conveyor_fixed(4).analyse().table("shafts").set_index("shaft")["d_bearing_mm"]
    held = _conveyor_fixed(4, min_bore_mm={1: 60.0}).analyse().table("shafts").set_index("shaft")
    assert held.loc[1, "d_bearing_mm"] >= 60.0 and held.loc[1, "stiffened"] and free[1] < 60.0


@pytest.mark.slow
def test_a_conveyor_reducer_search_on_shafts_finds_a_design():
    """The new user's conveyor (15 kW, 1450 rpm, u 24.17 ± 4 %, two sized 42CrMo4 stages, min_mass): every ranked
    design failed on its shafts — re-sizing a stage thinned its shafts (a larger gear has smaller forces, DIN 743
    asks less), which tilted the mesh more, and the fast stage ran away from m 4 to m 20. Re-sized designs now keep
    shafts at least as thick as before: a design that holds, and holds again when analysed on its own."""
    d = gd.Drive(power_kw=15, n_in_rpm=1450, shafting=Shafting(life_h=20000), stages=[
        gd.GearStage(None, material="42CrMo4", life_h=20000, name="fast"),
        gd.GearStage(None, material="42CrMo4", life_h=20000, name="slow")])
    r = d.optimize(total_ratio=24.17, ratio_tol=0.04, objective="min_mass")
    assert r.success and r.best.success
    for st in r.best.drive.stages:
        assert st.m <= 8
    again = r.best.drive.analyse("min_mass")
    assert again.success and again.min_margin == pytest.approx(r.best.min_margin, rel=1e-9, abs=1e-12)
