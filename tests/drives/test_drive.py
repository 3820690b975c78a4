"""gd.Drive: the power flow by hand, the seed 002 brake stand rebuilt, the optimiser against an
exhaustive enumeration written here with the standalone functions, and every returned design
re-evaluated on its own."""
import math

import numpy as np
import pytest

import geardesign as gd
from geardesign import chain, key
from geardesign.errors import GearDesignError
from geardesign.shifts.optimize import optimize_shifts


def _omega(n_rpm):
    return 2 * math.pi * n_rpm / 60


# ------------------------------------------------------------------------------ seed 002, by hand

def _seed002(**chain_kw):
    # Seed 002 (brake-stand diploma): 4 kW, 1500 rpm motor; worm gear motor u = 12.5, η = 0.87
    # (section "характеристики двигателя" and n_б = n_дв/u_м.р. = 1500/12.5 = 120 rpm); chain u = 1,
    # z1 = z2 = 13, K_e = 2.148 (its 1.9.3), two-strand 2PR-31.75 (1.9.5); sprocket hubs on d = 60 mm
    # shafts, 50 mm long, keys of steel 45 with [σ]cm = 300 MPa, [τ] = 120 MPa (1.9.6-1.9.7).
    stages = [gd.GivenStage(12.5, 0.87, "gear motor"),
              gd.ChainStage(z1=13, z2=13, k_e=2.148, **chain_kw)]
    shafts = [gd.Shaft(60, 50, 1, "driving sprocket", allowable_crush_mpa=300, allowable_shear_mpa=120),
              gd.Shaft(60, 50, 2, "driven sprocket", allowable_crush_mpa=300, allowable_shear_mpa=120)]
    return gd.Drive(power_kw=4, n_in_rpm=1500, stages=stages, shafts=shafts)


def test_seed002_power_flow_by_hand():
    a = _seed002(designation="2PR-31,75-177").analyse()
    t0 = 4000 / _omega(1500)                       # 25.4648 N·m on the motor shaft
    t1 = t0 * 12.5 * 0.87                          # 276.930 N·m on the gear motor's output
    t2 = t1 * 1 * 0.96                             # 265.852 N·m on the driven sprocket (chain η 0.96)
    assert a.flow["n_rpm"].tolist() == pytest.approx([1500, 120, 120], rel=1e-15)
    assert a.flow["torque_nm"].tolist() == pytest.approx([t0, t1, t2], rel=1e-14)
    assert a.flow["power_kw"].tolist() == pytest.approx([4, 4 * 0.87, 4 * 0.87 * 0.96], rel=1e-14)
    # The seed's own T1 = 380 N·m does not follow from its 4 kW motor: 380 N·m at 120 rpm is
    # 380·ω = 4.78 kW at the gear motor's output, more than the motor gives; the propagated
    # 276.93 N·m is used (its T2 = 190 N·m splits 380 between two roller shafts).
    assert 380 * _omega(120) / 1000 == pytest.approx(4.775, abs=1e-3)


def test_seed002_chain_and_keys_equal_the_standalone_functions():
    a = _seed002(designation="2PR-31,75-177").analyse()
    t1, t2 = a.flow["torque_nm"].iloc[1], a.flow["torque_nm"].iloc[2]
    alone = chain.design(torque_nm=t1, n1_rpm=120, ratio=1, z1=13, k_e=2.148)
    row = alone.candidates.set_index("designation").loc["2PR-31,75-177"]
    got = a.checks[a.checks["item"] == "chain"].set_index("check")["margin"]
    for check in ("pressure", "safety", "speed", "impacts"):
        assert got[check] == pytest.approx(row[f"margin_{check}"], rel=1e-14, abs=1e-15)
    for name, torque in (("driving sprocket", t1), ("driven sprocket", t2)):
        sel = key.select(60, torque, 50, allowable_crush_mpa=300, allowable_shear_mpa=120)
        mine = a.keys.set_index("name").loc[name]
        assert (mine["length_mm"], mine["n_keys"]) == (sel.length_mm, sel.n_keys) == (45, 1)
        assert mine["margin_crush"] == pytest.approx(sel.margin_crush, rel=1e-15)
        # crushing by hand: σ = 2T/(d (h − t1) l_p), key 18x11x45, l_p = 45 − 18
        assert mine["crush_mpa"] == pytest.approx(2000 * torque / (60 * (11 - 7) * (45 - 18)), rel=1e-14)
    assert a.success


def test_seed002_optimised_over_the_catalog_re_evaluates_to_the_standalone_chain():
    r = _seed002().optimize(total_ratio=12.5, ratio_tol=0.0, objective="min_mass")
    assert r.success
    best = r.table.iloc[0]
    t1 = 4000 / _omega(1500) * 12.5 * 0.87
    alone = chain.design(torque_nm=t1, n1_rpm=120, ratio=1, z1=13, k_e=2.148)
    ok = alone.candidates[alone.candidates["feasible"]]
    # the drive's mass model written out: two sprockets as steel discs of their tip diameter and the
    # chain's width, plus the chain (mass per metre x length); the keys do not depend on the chain
    rho = 7850e-9
    mass = (rho * math.pi / 4 * (ok["sprocket1_tip_diameter_mm"] ** 2 + ok["sprocket2_tip_diameter_mm"] ** 2)
            * ok["width_mm"] + ok["chain_mass_kg"])
    lightest = ok.loc[mass.idxmin()]
    assert best["chain.designation"] == lightest["designation"]
    assert best["mass_kg"] == pytest.approx(mass.min(), rel=1e-12)
    # and the optimiser's vectorised margins are the standalone design's, re-evaluated in r.best
    assert best["min_margin"] == pytest.approx(r.best.min_margin, rel=1e-12)
    chain_rows = r.best.checks[r.best.checks["item"] == "chain"].set_index("check")["margin"]
    for check in ("pressure", "safety", "speed", "impacts"):
        assert chain_rows[check] == pytest.approx(lightest[f"margin_{check}"], rel=1e-14, abs=1e-15)


# ------------------------------------------------------------------------------ flow, by hand

def test_output_torque_runs_the_flow_backwards():
    stages = [gd.GearStage(2, z1=20, z2=50, efficiency=0.97), gd.GivenStage(4.0, 0.9, "box")]
    a = gd.Drive(output_torque_nm=1000, n_in_rpm=1000, stages=stages).analyse()
    u1, u2 = 50 / 20, 4.0
    t0 = 1000 / (u1 * 0.97 * u2 * 0.9)
    assert a.flow["torque_nm"].tolist() == pytest.approx([t0, t0 * u1 * 0.97, 1000], rel=1e-14)
    assert a.flow["n_rpm"].tolist() == pytest.approx([1000, 400, 100], rel=1e-15)


def test_motor_sets_the_input_and_is_checked():
    sel = gd.motor.select(3.0, 1450)                        # AIR100S4: 3 kW, 1410 rpm
    d = gd.Drive(motor=sel, output_torque_nm=200, stages=[gd.GivenStage(10, 0.9, "box")])
    a = d.analyse()
    p_in = 200 / 0.9 * _omega(1410 / 10) / 1000             # power the box draws at its input
    row = a.checks.set_index("item").loc["motor"]
    assert a.flow["n_rpm"].iloc[0] == 1410
    assert row["margin"] == pytest.approx(1 - p_in / 3.0, rel=1e-12)


# ------------------------------------------------------------------------------ exhaustive enumeration

def _size_and_mass(m, geo, row, face_width_mm):
    """The documented models, written out: envelope (a + (D1+D2)/2)·max(D1, D2), discs ρπ/4·D²·b."""
    rho = 7850e-9
    gear_size = (geo.a_w + (geo.da1 + geo.da2) / 2) * max(geo.da1, geo.da2)
    de1, de2 = row["sprocket1_tip_diameter_mm"], row["sprocket2_tip_diameter_mm"]
    chain_size = (row["center_distance_mm"] + (de1 + de2) / 2) * max(de1, de2)
    gear_mass = rho * math.pi / 4 * (geo.da1 ** 2 + geo.da2 ** 2) * face_width_mm
    chain_mass = rho * math.pi / 4 * (de1 ** 2 + de2 ** 2) * row["width_mm"] + row["chain_mass_kg"]
    return gear_size + chain_size, gear_mass + chain_mass


@pytest.fixture(scope="module")
def small_case():
    gear = gd.GearStage(2, z1_range=(17, 19), z2_max=60, ratio_range=(1.0, 4.0), efficiency=0.97)
    ch = gd.ChainStage(ratio_range=(1.0, 3.0), z2_max=40, strands=(1, 2), efficiency=0.95)
    shafts = [gd.Shaft(30, 40, 1, "pinion"), gd.Shaft(45, 60, 2, "output")]
    drive = gd.Drive(power_kw=3.0, n_in_rpm=1410, stages=[gear, ch], shafts=shafts)
    U, tol = 6.0, 0.03
    designs = []
    for z1 in range(17, 20):
        for z2 in range(z1, 61):
            if not 1.0 <= z2 / z1 <= 4.0:
                continue
            shifts = {obj: optimize_shifts(z1, z2, obj, None, "exact", m=2) for obj in ("max_x_sum", "max_margin")}
            for zc1 in range(13, 28, 2):
                for zc2 in range(zc1, 41):
                    uc = zc2 / zc1
                    if not 1.0 <= uc <= 3.0 or zc1 > max(chain.recommended_z1(uc), 13):
                        continue
                    u = z2 / z1 * uc
                    if abs(u - U) / U > tol:
                        continue
                    n1 = 1410 / (z2 / z1)
                    t1 = 3000 / _omega(1410) * (z2 / z1) * 0.97
                    t2 = t1 * uc * 0.95
                    alone = chain.design(torque_nm=t1, n1_rpm=n1, ratio=uc, z1=zc1, strands=(1, 2))
                    keys = [key.select(30, t1, 40), key.select(45, t2, 60)]
                    keys_ok = all(k.feasible for k in keys)
                    key_margin = min(min(k.margin_crush, k.margin_shear) for k in keys)
                    for _, row in alone.candidates.iterrows():
                        for obj, s in shifts.items():
                            if not (s.success and not s.conflict):
                                continue
                            geo = gd.GearPair(2, z1, z2, s.x1, s.x2).geometry()
                            size, mass = _size_and_mass(2, geo, row, 4 * math.pi * 2)
                            gear_margin = min(s.margins.values())
                            margin = min(gear_margin if abs(gear_margin) > 1e-9 else 0.0, key_margin,
                                         *(row[f"margin_{c}"] for c in ("pressure", "safety", "speed", "impacts")))
                            ok = bool(row["feasible"]) and keys_ok
                            designs.append(dict(shift_objective=obj, z1=z1, z2=z2, zc1=zc1, zc2=zc2,
                                                designation=row["designation"], size=size, mass=mass,
                                                margin=margin, ok=ok, err=abs(u - U) / U))
    return drive, U, tol, designs


@pytest.mark.slow
@pytest.mark.parametrize("objective", ["min_size", "min_mass", "max_margin"])
def test_optimize_finds_the_best_of_an_exhaustive_enumeration(small_case, objective):
    drive, U, tol, designs = small_case
    shift_objective = "max_margin" if objective == "max_margin" else "max_x_sum"
    pool = [d for d in designs if d["ok"] and d["shift_objective"] == shift_objective]
    value = {"min_size": lambda d: d["size"], "min_mass": lambda d: d["mass"], "max_margin": lambda d: -d["margin"]}
    want = min(pool, key=lambda d: (round(value[objective](d), 9), round(d["err"], 12), d["size"]))
    r = drive.optimize(U, tol, objective=objective, top=5)
    best = r.table.iloc[0]
    got = (best["gear.z1"], best["gear.z2"], best["chain.z1"], best["chain.z2"], best["chain.designation"])
    assert got == (want["z1"], want["z2"], want["zc1"], want["zc2"], want["designation"])
    assert best["size_mm2"] == pytest.approx(want["size"], rel=1e-12)
    assert best["mass_kg"] == pytest.approx(want["mass"], rel=1e-12)
    assert best["min_margin"] == pytest.approx(want["margin"], rel=1e-9, abs=1e-12)
    # the listed runners-up are the enumeration's next best, in order
    ranked = sorted(pool, key=lambda d: (round(value[objective](d), 9), round(d["err"], 12), d["size"]))
    feasible_rows = r.table[r.table["feasible"]]
    assert [value[objective](d) for d in ranked[:len(feasible_rows)]] == pytest.approx(
        [{"min_size": s, "min_mass": m, "max_margin": -g}[objective] for s, m, g in
         feasible_rows[["size_mm2", "mass_kg", "min_margin"]].itertuples(index=False)], rel=1e-12)


def test_every_returned_design_passes_each_stage_re_evaluated(small_case):
    drive, U, tol, _ = small_case
    r = drive.optimize(U, tol, objective="min_mass", top=5)
    rows = r.table[r.table["feasible"]]
    assert len(rows) == 5
    for _, row in rows.iterrows():
        u1 = row["gear.z2"] / row["gear.z1"]
        pair = gd.GearPair(2, int(row["gear.z1"]), int(row["gear.z2"]), row["gear.x1"], row["gear.x2"])
        assert (pair.checks()["margin"] >= -1e-9).all()
        t1 = 3000 / _omega(1410) * u1 * 0.97
        uc = row["chain.z2"] / row["chain.z1"]
        alone = chain.design(torque_nm=t1, n1_rpm=1410 / u1, ratio=uc, z1=int(row["chain.z1"]), strands=(1, 2))
        assert bool(alone.candidates.set_index("designation").loc[row["chain.designation"], "feasible"])
        for d, hub, t, name in ((30, 40, t1, "pinion"), (45, 60, t1 * uc * 0.95, "output")):
            sel = key.select(d, t, hub)
            assert sel.feasible and sel.n_keys == row[f"key '{name}'.n_keys"]
        assert abs(row["total_ratio"] - U) / U <= tol
        # the same design through the public API, fully fixed, gives the same figures
        fixed = gd.Drive(power_kw=3.0, n_in_rpm=1410, shafts=drive.shafts, stages=[
            gd.GearStage(2, z1=int(row["gear.z1"]), z2=int(row["gear.z2"]), x1=row["gear.x1"], x2=row["gear.x2"],
                         efficiency=0.97),
            gd.ChainStage(z1=int(row["chain.z1"]), z2=int(row["chain.z2"]), designation=row["chain.designation"],
                          strands=(int(row["chain.strands"]),), efficiency=0.95)]).analyse()
        assert fixed.success
        assert fixed.mass_kg == pytest.approx(row["mass_kg"], rel=1e-12)
        assert fixed.size_mm2 == pytest.approx(row["size_mm2"], rel=1e-12)
        assert fixed.min_margin == pytest.approx(row["min_margin"], rel=1e-9, abs=1e-12)


# ------------------------------------------------------------------------------ infeasible, bad input

def test_infeasible_drive_names_stage_and_checks():
    stages = [gd.GearStage(2, z1_range=(17, 18), z2_max=40, ratio_range=(1, 2)), gd.ChainStage(ratio_range=(1, 2))]
    weak = gd.Shaft(12, 20, 2, "output")          # a 5x5 key in a 20 mm hub cannot carry ~130 N·m
    r = gd.Drive(power_kw=4, n_in_rpm=1410, stages=stages, shafts=[weak]).optimize(3.0)
    assert not r.success and r.best is None
    assert any("key 'output': crushing" in c for c in r.conflict)
    assert "key 'output': crushing" in r.message
    assert not r.table["feasible"].any() and r.table["reason"].str.startswith("fails").all()


def test_unreachable_ratio_is_a_result():
    stages = [gd.GivenStage(2, 0.9, "box"), gd.GearStage(2, ratio_range=(1, 2))]
    r = gd.Drive(power_kw=1, n_in_rpm=1000, stages=stages).optimize(20)
    # the box (u = 2) times the gear's ratio range [1, 2] reaches u in [2, 4], not 20
    assert not r.success and "reach u in [2, 4]" in r.message and r.conflict[0].startswith("ratio")


@pytest.mark.parametrize("make, name", [
    (lambda: gd.Drive(power_kw=1, output_torque_nm=5, n_in_rpm=1000, stages=[gd.GivenStage(2, 0.9)]), "power_kw"),
    (lambda: gd.Drive(power_kw=1, n_in_rpm=1000, stages=[gd.GivenStage(2, 0.9)], shafts=[gd.Shaft(30, 40, 3)]), "at = 3"),
    (lambda: gd.Drive(power_kw=1, n_in_rpm=1000, stages=[gd.GivenStage(2, 0.9)]).optimize(2, objective="cheap"),
     "objective"),
    (lambda: gd.Drive(power_kw=1, n_in_rpm=1000, stages=[gd.GivenStage(2, 0.9)]).optimize(-2), "total_ratio"),
    (lambda: gd.GivenStage(2, 1.5), "efficiency"),
    (lambda: gd.GearStage(2, x1=0.1), "x2"),
    (lambda: gd.Shaft(60, 5, 1), "hub_length_mm"),
    (lambda: gd.ChainStage(designation="PR-99"), "designation"),
    (lambda: gd.Drive(power_kw=1, n_in_rpm=1000, stages=[gd.GearStage(2)]).analyse(), "free tooth counts"),
])
def test_bad_inputs_are_one_named_error(make, name):
    with pytest.raises(GearDesignError) as e:
        make()
    assert name in str(e.value)


def test_power_flow_is_vectorised():
    n, t, p = gd.drives.drive.power_flow(1000, np.array([[2.0, 3.0], [4.0, 1.0]]), [0.9, 0.8], power_kw=2)
    t0 = 2000 / _omega(1000)
    assert t[:, 2].tolist() == pytest.approx([t0 * 2 * 0.9 * 3 * 0.8, t0 * 4 * 0.9 * 1 * 0.8], rel=1e-15)
    assert n[:, 2].tolist() == pytest.approx([1000 / 6, 250], rel=1e-15)


def test_enumerations_are_bounded_up_front():
    from geardesign.drives.stages import GEAR_PAIRS_MAX
    wide = gd.GearStage(1, z1_range=(10, 400), z2_max=4000, ratio_range=(1, 10))
    with pytest.raises(GearDesignError) as e:
        gd.Drive(power_kw=1, n_in_rpm=1000, stages=[wide]).optimize(5, ratio_tol=0.5)
    assert str(GEAR_PAIRS_MAX) in str(e.value) and "z1_range" in str(e.value)


def test_helical_stage_flows_through():
    # a helical pair: the same flow; the tip circles of the solved shifts enter the size
    st = gd.GearStage(2, beta_deg=15, z1_range=(17, 18), z2_max=60, ratio_range=(2, 3))
    r = gd.Drive(power_kw=2, n_in_rpm=1000, stages=[st]).optimize(2.5, 0.02)
    b = r.table.iloc[0]
    pair = gd.GearPair(2, int(b["gear.z1"]), int(b["gear.z2"]), b["gear.x1"], b["gear.x2"], beta_deg=15)
    g = pair.geometry()
    assert b["size_mm2"] == pytest.approx((g.a_w + (g.da1 + g.da2) / 2) * max(g.da1, g.da2), rel=1e-12)


def test_progress_reports_the_walk(small_case):
    drive, U, tol, _ = small_case
    calls = []
    drive.optimize(U, tol, objective="min_size", progress=lambda done, total: calls.append((done, total)))
    assert calls and all(0 < d <= t for d, t in calls) and [d for d, _ in calls] == sorted(d for d, _ in calls)
