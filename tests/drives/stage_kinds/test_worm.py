"""A worm gear stage (geardesign.drives.stage_kinds.worm): seed 002's gear motor (u = 12.5, η = 0.87, 4 kW at
1500 rpm) as a computed worm pair; the search choosing the wheel's teeth in a ratio range with every margin the
pair's own; the efficiency given, or taken from the installed function; scenes and the diagram."""
import math

import numpy as np
import pytest

import geardesign as gd
from geardesign.drives.stage_kinds import Designs, kind_named, kind_of, set_worm_efficiency
from geardesign.drives.stage_kinds.worm import WormKind, WormStage

GEAR_MOTOR = dict(m_x=4, q=12.5, z1=4, z2=50, a=125, efficiency=0.87, name="gear motor")


def test_the_kind_and_its_ratio_span():
    s = WormStage(**GEAR_MOTOR)
    kind = kind_of(s)
    assert isinstance(kind, WormKind) and kind_named("worm") is kind and gd.WormStage is WormStage
    assert kind.ratio_span(s) == (12.5, 12.5) and kind.fixed_ratio(s) == 12.5
    free = WormStage(m_x=4, q=10, z1=2, ratio_range=(10, 20), efficiency=0.8)
    assert kind.ratio_span(free) == (10.0, 20.0)
    with pytest.raises(gd.GearDesignError, match="free wheel teeth"):
        kind.fixed_ratio(free)
    opts = kind.options(free, 12.0, 14.0)
    assert opts["z2"].tolist() == [24, 25, 26, 27, 28] and np.allclose(opts["ratio"], opts["z2"] / 2)


def test_seed_002_gear_motor_in_a_drive():
    a = gd.Drive(power_kw=4, n_in_rpm=1500, stages=[WormStage(**GEAR_MOTOR)]).analyse()
    t_out = 4000 / (1500 * math.pi / 30) * 12.5 * 0.87          # 276.93 N·m, seed 002's gear motor
    assert a.flow["n_rpm"].iloc[-1] == pytest.approx(120.0, rel=1e-15)
    assert a.flow["torque_nm"].iloc[-1] == pytest.approx(t_out, rel=1e-14)
    pair = gd.WormPair(4, 4, 50, 12.5, 0.0)
    want = pair.checks(worm_length_min=False).set_index("check")["margin"]
    got = a.checks.set_index("check")["margin"]
    for name in want.index:
        assert got[name] == pytest.approx(want[name], abs=1e-15)
    assert "worm_length" not in got.index and a.success


def test_the_batch_margins_are_the_pairs():
    s = WormStage(m_x=3.15, q=10, z1=1, a=80, ratio_range=(20, 60), efficiency=0.7)
    kind = kind_of(s)
    z2 = kind.options(s, 20, 60)["z2"]
    n = np.ones(z2.shape)
    b = kind.batch(s, Designs(option=dict(z2=z2, ratio=z2), rows=None, n_in_rpm=n, torque_in_nm=n, n_out_rpm=n,
                              torque_out_nm=n))
    for i in (0, len(z2) // 2, len(z2) - 1):
        x2 = 80 / 3.15 - (10 + z2[i]) / 2
        try:
            table = gd.WormPair(3.15, 1, int(z2[i]), 10, x2).checks(worm_length_min=False).set_index("check")
        except gd.GearDesignError:          # the wheel does not exist: every margin fails
            assert all(v[i] == -np.inf for v in b.margins.values())
            continue
        for name, v in b.margins.items():
            assert v[i] == pytest.approx(table.loc[name, "margin"], abs=1e-12), (z2[i], name)


def test_the_search_picks_the_wheel_teeth():
    st = [WormStage(m_x=4, q=12.5, z1=2, a=125, ratio_range=(8, 40), efficiency=0.85, name="worm"),
          gd.ChainStage(name="chain", ratio_range=(1, 3))]
    o = gd.Drive(power_kw=4, n_in_rpm=1500, stages=st).optimize(25, progress=False)
    row = o.table.iloc[0]
    assert bool(row["feasible"]) and abs(row["total_ratio"] / 25 - 1) <= 0.03
    z2 = int(row["worm.z2"])
    assert row["worm.x2"] == pytest.approx(125 / 4 - (12.5 + z2) / 2, abs=1e-12)
    assert o.best.success and o.best.stages[0]["summary"]["z2"] == z2


def test_efficiency_given_or_from_the_installed_function():
    with pytest.raises(gd.GearDesignError, match="efficiency is needed") as err:
        WormStage(m_x=4, q=12.5, z1=4, z2=50)
    assert "'computed'" in str(err.value)     # the way out a Python user has, not only the installer's hook
    with pytest.raises(gd.GearDesignError, match="efficiency is needed when z2 is free"):
        WormStage(m_x=4, q=12.5, z1=4)

    def screw(pair, mu=0.05):
        # a stand-in model (the screw's η = tan γ / tan(γ + ρ'), ρ' = atan(μ/cos α_n)): any function of the pair
        g = pair.geometry()
        gamma, rho = math.radians(g.gamma_m_deg), math.atan(mu / math.cos(math.radians(g.alpha_n_deg)))
        return math.tan(gamma) / math.tan(gamma + rho)

    before = set_worm_efficiency(screw)
    try:
        s = WormStage(m_x=4, q=12.5, z1=4, z2=50)
        assert s.efficiency == pytest.approx(screw(gd.WormPair(4, 4, 50, 12.5)), rel=1e-15)
        assert WormStage(m_x=4, q=12.5, z1=4, z2=50, efficiency=0.8).efficiency == 0.8
    finally:
        set_worm_efficiency(before)
    with pytest.raises(gd.GearDesignError, match="must be callable"):
        set_worm_efficiency(0.9)


@pytest.mark.parametrize("kwargs,words", [
    (dict(m_x=0, q=10, z1=1, z2=40, efficiency=0.8), ["m_x", "> 0"]),
    (dict(m_x=2, q=10, z1=0, z2=40, efficiency=0.8), ["z1", "[1, 10]"]),
    (dict(m_x=2, q=10, z1=1, z2=40, efficiency=1.5), ["efficiency", "1.5"]),
    (dict(m_x=2, q=10, z1=1, ratio_range=(50, 10), efficiency=0.8), ["ratio_range", "min <= max"]),
    (dict(m_x=2, q=10, z1=1, z2=40, efficiency=0.8, flank_form="ZX"), ["flank_form"]),
    (dict(m_x=2, q=10, z1=1, z2=40, efficiency=0.8, checks={"sa_mn": 0.3}), ["unknown option 'sa_mn'"]),
])
def test_bad_stage_input(kwargs, words):
    with pytest.raises(gd.GearDesignError) as info:
        WormStage(**kwargs)
    for w in words:
        assert w in str(info.value), (w, str(info.value))


def test_scene_and_diagram(tmp_path):
    import matplotlib
    matplotlib.use("Agg")
    from geardesign.drives.diagram import plot_drive

    kind = kind_named("worm")
    s = kind.from_scene(dict(m_x=4.0, q=12.5, z1=4, z2=50, a=125.0, efficiency=0.87, name="gear motor",
                             ratio_range=[8.0, 80.0]))
    assert s == WormStage(**GEAR_MOTOR)
    assert set(kind.scene_keys()) >= {"m_x", "q", "z1", "z2", "x2", "a", "efficiency", "flank_form"}
    a = gd.Drive(power_kw=4, n_in_rpm=1500, stages=[s, gd.ChainStage(z1=13, z2=13, name="chain")]).analyse()
    ax = plot_drive(a)
    texts = " ".join(t.get_text() for t in ax.texts)
    assert "gear motor: ZA worm, z 4/50" in texts


def test_seed_002_scene_with_the_worm_computed():
    from pathlib import Path

    from geardesign.scene import load_scene
    from geardesign.scene.drive import build_drive

    scene = Path(__file__).resolve().parents[3] / "studies" / "scenes" / "seed002_worm_drive.toml"
    drive, _ = build_drive(load_scene(str(scene)).sections["drive"])
    a = drive.analyse()
    assert a.success and a.flow["n_rpm"].iloc[1] == pytest.approx(120.0, rel=1e-15)
    assert a.stages[0]["summary"]["kind"] == "worm" and a.stages[0]["summary"]["a"] == 125.0


def test_a_computed_worm_efficiency_is_the_mesh_efficiency_at_the_speed_into_the_stage():
    # issue 39 §3, §5: the efficiency used in the power flow; worm-driving η = tan γ / tan(γ + ρ'),
    # ρ' = arctan(μ / cos α_n) (Niemann-Winter III, worm gears), μ the pair's own at the sliding speed
    import math

    import geardesign as gd

    w = gd.WormStage(m_x=4, q=12.5, z1=4, z2=50, a=125, efficiency="computed", name="gear motor")
    d = gd.Drive(power_kw=3, n_in_rpm=1500, stages=[gd.GivenStage(1.0, 1.0, "coupling"), w])
    st = d.stages[1]
    e = st.pair().efficiency(1500.0)
    g = st.pair().geometry()
    rho = math.atan(e["mu"] / math.cos(math.radians(g.alpha_n_deg)))
    gamma = math.radians(g.gamma_m_deg)
    assert st.efficiency == pytest.approx(math.tan(gamma) / math.tan(gamma + rho), rel=1e-12)
    assert st.efficiency_n1_rpm == 1500.0
    a = d.analyse()
    P = a.flow["power_kw"].to_numpy()
    assert P[2] == pytest.approx(P[1] * st.efficiency, rel=1e-12)
    # behind a stage whose ratio the search chooses, the speed is not fixed: refused by name
    with pytest.raises(gd.GearDesignError, match="efficiency='computed' needs the speed"):
        gd.Drive(power_kw=3, n_in_rpm=1500, stages=[gd.ChainStage(z1=13), w])
    with pytest.raises(gd.GearDesignError, match="'computed'"):
        gd.WormStage(m_x=4, q=12.5, z1=4, z2=50, efficiency="auto")


# -- sized by its load (AGMA 6034-B92, tests/gears/worm/test_agma.py checks the formulas against Shigley) ------------
SEED_T_OUT = 4000 / (1500 * math.pi / 30) * 12.5 * 0.87       # the gear motor's output torque, N·m


def _failing(a, m_x, q, z2, load):
    """The failing checks of the series pair (a, m_x, q) with z2 wheel teeth and z1 = 2 under ``load``."""
    from geardesign.gears.worm.geometry import x2_from_center_distance
    try:
        pair = gd.WormPair(m_x, 2, z2, q, float(x2_from_center_distance(a, m_x, z2, q)))
    except gd.GearDesignError:
        return ["the wheel does not exist"]
    t = pair.checks(worm_length_min=False, worm_load=load)
    return t.loc[~t["ok"], "check"].tolist()


def test_a_sized_stage_passes_every_check_and_the_next_smaller_series_size_fails_one():
    from geardesign.drives.stage_kinds.worm import size_worm
    from geardesign.gears.worm import agma
    from geardesign.gears.worm.checks import WormLoad
    from geardesign.gears.worm.series import default_q_values, worm_center_distance_series, worm_module_series

    st = WormStage(None, None, z1=2, z2=25, efficiency=0.87, casting="centrifugal", name="gear motor")
    sz = size_worm(st, 25, 1500.0, SEED_T_OUT)
    load = WormLoad(SEED_T_OUT, 1500.0, "centrifugal")
    assert sz.feasible and sz.a in worm_center_distance_series() and sz.m_x in worm_module_series()
    pair = gd.WormPair.from_center_distance(sz.a, sz.m_x, 2, 25, sz.q)
    table = pair.checks(worm_length_min=False, worm_load=load)
    assert table["ok"].all(), table
    # its capacity by hand from the AGMA factors on the pair's own geometry: W_t,all·η·d_2/2000
    g = pair.geometry()
    v = float(gd.gears.worm.efficiency.sliding_speed(g.d_m1, 1500.0, g.gamma_m_deg))
    eta = float(gd.gears.worm.efficiency.efficiency_worm_driving(
        g.gamma_m_deg, gd.gears.worm.efficiency.friction_coefficient_agma(v), g.alpha_n_deg))
    W = agma.allowable_tangential_load(agma.materials_factor(g.a, g.d_2, "centrifugal"), g.d_2,
                                       min(g.b_2, 0.67 * g.d_m1), agma.ratio_correction_factor(12.5),
                                       agma.velocity_factor(v))
    assert sz.T2_all == pytest.approx(float(W) * eta * g.d_2 / 2000.0, rel=1e-12)
    # every module × q of the next smaller series centre distance fails a check, and each that exists fails the load
    a_prev = float(worm_center_distance_series()[worm_center_distance_series() < sz.a].max())
    failures = {(m, q): _failing(a_prev, m, q, 25, load) for m in worm_module_series() for q in default_q_values()}
    assert all(failures.values())
    # some hold every geometric check there: the load is what they fail
    assert any(f == ["agma_load"] for f in failures.values())
    # and the candidates ranked before it at its own centre distance fail the load (size_worm names the last one)
    assert sz.smaller is not None and sz.smaller[1] == "agma_load"


def test_the_drive_sizes_the_stage_by_the_load_its_flow_brings():
    st = WormStage(None, None, z1=2, z2=25, efficiency=0.87, casting="centrifugal", name="gear motor")
    a = gd.Drive(power_kw=4, n_in_rpm=1500, stages=[st]).analyse()
    s = a.stages[0]["summary"]
    assert a.success and s["m_x"] is not None and s["S_AGMA"] >= 1.0
    assert s["T2_all_nm"] == pytest.approx(SEED_T_OUT * s["S_AGMA"], rel=1e-12)
    # twice the power needs a larger worm; the same worm then fails its load check
    b = gd.Drive(power_kw=8, n_in_rpm=1500, stages=[st]).analyse()
    assert b.stages[0]["summary"]["a"] > s["a"]
    fixed = WormStage(s["m_x"], s["q"], 2, 25, a=s["a"], efficiency=0.87, casting="centrifugal")
    c = gd.Drive(power_kw=8, n_in_rpm=1500, stages=[fixed]).analyse()
    assert not c.success and c.checks.set_index("check").loc["agma_load", "margin"] < 0


def test_the_search_sizes_each_design_at_its_own_torque():
    from geardesign.drives.stage_kinds.worm import size_worm

    st = WormStage(None, None, z1=2, ratio_range=(8, 40), efficiency=0.85, casting="sand", name="worm")
    drive = gd.Drive(power_kw=4, n_in_rpm=1500, stages=[st, gd.ChainStage(name="chain", k_e=2.148)])
    r = drive.optimize(total_ratio=25, ratio_tol=0.03, objective="min_size")
    assert r.success
    best = r.best.drive.stages[0]
    flow = r.best.stages[0]["flow"]
    sz = size_worm(st, best.z2, flow.n_in_rpm, flow.torque_out_nm)
    assert (best.m_x, best.q, best.a) == (sz.m_x, sz.q, sz.a)
    again = gd.Drive(power_kw=4, n_in_rpm=1500, stages=r.best.drive.stages).analyse()
    assert again.success and "agma_load" in set(again.checks["check"])
    row = r.table.iloc[0]
    assert row["worm.m_x"] == best.m_x and row["worm.a"] == best.a


def test_the_sized_scene_runs_from_the_command_line(capsys):
    import json
    from pathlib import Path

    from geardesign.cli import main

    scene = Path(__file__).resolve().parents[3] / "studies" / "scenes" / "seed002_worm_sized.toml"
    assert main(["drive", str(scene), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    worm = out["analysis"]["stages"][0] if "analysis" in out else out["stages"][0]
    assert worm["kind"] == "worm" and worm["casting"] == "centrifugal" and worm["S_AGMA"] >= 1.0


@pytest.mark.parametrize("kw, word", [
    (dict(m_x=None, q=None, z1=2, z2=25, efficiency=0.87), "casting"),
    (dict(m_x=4, q=None, z1=2, z2=25, efficiency=0.87), "q is needed"),
    (dict(m_x=None, q=None, z1=2, z2=25, efficiency=None, casting="sand"), "efficiency"),
    (dict(m_x=None, q=None, z1=2, z2=25, efficiency="auto", casting="sand"), "efficiency"),
    (dict(m_x=None, q=None, z1=2, efficiency="computed", casting="sand"), "needs z2"),
    (dict(m_x=4, q=10, z1=2, z2=25, efficiency=0.87, casting="bronze"), "casting"),
    (dict(m_x=4, q=10, z1=2, z2=25, efficiency=0.87, casting="sand", application_factor=0.5), "application_factor"),
])
def test_bad_sizing_input_is_refused_by_name(kw, word):
    with pytest.raises(gd.GearDesignError, match=word):
        WormStage(**kw)


# -- sized by its load with its efficiency computed (a fixed point of size and efficiency) ----------------------------
def _own_efficiency(stage, n1):
    """η_z of the stage's own pair at the worm speed n1, by the efficiency functions called on its geometry
    (tan γ_m/tan(γ_m + ρ'), μ from the AGMA curve at the sliding speed: tests/gears/worm/test_efficiency.py checks
    them against an independent implementation)."""
    from geardesign.gears.worm import efficiency as eff
    g = stage.pair().geometry()
    v = eff.sliding_speed(g.d_m1, n1, g.gamma_m_deg)
    return float(eff.efficiency_worm_driving(g.gamma_m_deg, eff.friction_coefficient_agma(v), g.alpha_n_deg))


def _capacity(stage, n1):
    """The allowable wheel torque of the stage's own pair at n1 (AGMA 6034-B92, agma_capacity on its geometry)."""
    from geardesign.gears.worm import agma
    geo = stage.pair().geometry().to_dict()
    return float(agma.agma_capacity(geo, n1, stage.casting, stage.application_factor)["T2_all"])


# (moves: the size at η = 1, the first round's, is not the settled one: the fixed point took more than one step)
@pytest.mark.parametrize("power_kw, casting, z1, z2, moves", [
    (4.0, "centrifugal", 2, 25, False), (0.5, "centrifugal", 2, 25, True), (3.0, "chill", 2, 60, True),
    (4.0, "sand", 4, 50, True), (45.0, "sand", 4, 50, False)])
def test_a_sized_stage_with_computed_efficiency_carries_the_torque_its_own_efficiency_gives(power_kw, casting, z1, z2,
                                                                                           moves):
    from geardesign.drives.stage_kinds.worm import size_worm

    st = WormStage(None, None, z1=z1, z2=z2, efficiency="computed", casting=casting, name="gear motor")
    before = gd.GivenStage(2.0, 0.95, "belt")             # the worm at 725 rpm, 95 % of the power
    d = gd.Drive(power_kw=power_kw, n_in_rpm=1450, stages=[before, st])
    w = d.stages[1]
    n1 = 1450 / 2.0
    assert w.m_x is not None and w.efficiency_n1_rpm == n1
    # its efficiency is its own pair's at its speed
    assert w.efficiency == pytest.approx(_own_efficiency(w, n1), rel=1e-12)
    # the torque that efficiency gives, by hand: P·η_belt/ω_worm·u·η
    T_out = power_kw * 1000 * 0.95 / (n1 * math.pi / 30) * (z2 / z1) * w.efficiency
    assert _capacity(w, n1) >= T_out
    a = d.analyse()
    assert a.flow["torque_nm"].iloc[-1] == pytest.approx(T_out, rel=1e-12)
    margin = a.checks.set_index("check").loc["agma_load", "margin"]
    assert margin >= 0 and margin == pytest.approx(_capacity(w, n1) / T_out - 1, rel=1e-9)
    # a fixed point: sized again at that torque, the same size (the smallest series size that carries it)
    sz = size_worm(st, z2, n1, T_out)
    assert (sz.a, sz.m_x, sz.q) == (w.a, w.m_x, w.q)
    first = size_worm(st, z2, n1, T_out / w.efficiency)     # the torque at η = 1
    assert ((first.a, first.m_x, first.q) != (w.a, w.m_x, w.q)) == moves


def test_with_the_output_torque_given_the_size_is_the_torques_and_the_efficiency_its_own():
    from geardesign.drives.stage_kinds.worm import size_worm

    st = WormStage(None, None, z1=2, z2=25, efficiency="computed", casting="sand", name="worm")
    chain = gd.ChainStage(z1=13, z2=26, name="chain", efficiency=0.96)
    d = gd.Drive(output_torque_nm=600.0, n_in_rpm=1500, stages=[st, chain])
    w = d.stages[0]
    T_worm = 600.0 / (2.0 * 0.96)                        # the chain's u = 2, η = 0.96: the worm's wheel torque
    sz = size_worm(st, 25, 1500.0, T_worm)
    assert (w.a, w.m_x, w.q) == (sz.a, sz.m_x, sz.q)
    assert w.efficiency == pytest.approx(_own_efficiency(w, 1500.0), rel=1e-12)
    # a free stage after it would give it a torque per design: refused by name
    with pytest.raises(gd.GearDesignError, match="stages after it must have fixed ratios"):
        gd.Drive(output_torque_nm=600.0, n_in_rpm=1500, stages=[st, gd.ChainStage(name="chain")])


def test_the_search_takes_the_sized_stage_at_its_computed_efficiency():
    st = WormStage(None, None, z1=2, z2=25, efficiency="computed", casting="centrifugal", name="worm")
    drive = gd.Drive(power_kw=4, n_in_rpm=1500, stages=[st, gd.ChainStage(name="chain", k_e=2.148)])
    r = drive.optimize(total_ratio=25, ratio_tol=0.03, objective="min_size")
    assert r.success
    w = r.best.drive.stages[0]
    assert w.efficiency == pytest.approx(_own_efficiency(w, 1500.0), rel=1e-12)
    T_out = r.best.stages[0]["flow"].torque_out_nm
    assert T_out == pytest.approx(4000 / (1500 * math.pi / 30) * 12.5 * w.efficiency, rel=1e-12)
    assert _capacity(w, 1500.0) >= T_out
    assert r.best.checks.set_index(["item", "check"]).loc[("worm", "agma_load"), "margin"] >= 0


def test_a_size_that_cycles_or_does_not_settle_is_refused_by_name(monkeypatch):
    from geardesign.drives.stage_kinds import worm

    # chill-cast 2/60 at 2.3 kW, 1450 rpm: a 125 mm worm (q 20, low lead angle) carries the torque its efficiency
    # gives with room to spare, a 100 mm one (q 8) would carry that torque but not its own higher efficiency's
    st = WormStage(None, None, z1=2, z2=60, efficiency="computed", casting="chill", name="hoist")
    with pytest.raises(gd.GearDesignError, match="'hoist'.*does not settle.*cycles a 125 mm.*a 100 mm") as err:
        gd.Drive(power_kw=2.3, n_in_rpm=1450, stages=[st])
    # the size it names as carrying its own efficiency's torque does
    assert "a 125 mm (m_x 3.15, q 20) carries" in str(err.value)
    held = WormStage(3.15, 20, z1=2, z2=60, a=125, efficiency="computed", casting="chill", name="hoist")
    a = gd.Drive(power_kw=2.3, n_in_rpm=1450, stages=[held]).analyse()
    assert a.success and a.checks.set_index("check").loc["agma_load", "margin"] >= 0
    # a bound on the rounds: with one round allowed, a stage that needs a second is refused
    monkeypatch.setattr(worm, "SIZING_ROUNDS", 1)
    with pytest.raises(gd.GearDesignError, match="did not settle on one size in 1 rounds"):
        gd.Drive(power_kw=4, n_in_rpm=1500, stages=[WormStage(None, None, z1=2, z2=25, efficiency="computed",
                                                             casting="centrifugal")])
    # at_speed of a sized stage needs the torque
    with pytest.raises(gd.GearDesignError, match="torque_out"):
        st.at_speed(1450.0)


def test_a_scene_sizes_and_computes_the_worm_together_and_a_cycle_exits_2(tmp_path, capsys):
    import json
    from pathlib import Path

    from geardesign.cli import main

    text = (Path(__file__).resolve().parents[3] / "studies" / "scenes" / "seed002_worm_sized.toml").read_text()
    scene = tmp_path / "computed.toml"
    scene.write_text(text.replace("efficiency = 0.87", 'efficiency = "computed"'))
    assert main(["drive", str(scene), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    worm = out["analysis"]["stages"][0] if "analysis" in out else out["stages"][0]
    st = WormStage(worm["m_x"], worm["q"], 2, 25, a=worm["a"], efficiency=0.5, casting="centrifugal")
    assert worm["efficiency"] == pytest.approx(_own_efficiency(st, 1500.0), rel=1e-12) and worm["S_AGMA"] >= 1.0
    cyc = tmp_path / "cycle.toml"
    cyc.write_text('[drive]\npower_kw = 2.3\nn_in_rpm = 1450\n\n[[drive.stage]]\nkind = "worm"\nname = "hoist"\n'
                   'z1 = 2\nz2 = 60\ncasting = "chill"\nefficiency = "computed"\n')
    assert main(["drive", str(cyc)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "'hoist'" in err[0] and "does not settle" in err[0]
