"""The stage protocol (geardesign.drives.stage_kinds): a stage kind made up here — a V-belt between
two pulleys of a short diameter list, checked for belt speed — is registered in this file only, and
the drive's analyse, the search, the scene loader and the diagram all use it; nothing else is edited.
Every value is worked by hand here (belt speed v = π·d1·n1/60 000, the envelope (a + (D1 + D2)/2)·
max(D1, D2) with a = d1 + d2, the power flow T = P/ω, T_out = T_in·u·η)."""
import math
from dataclasses import dataclass, replace

import matplotlib
import numpy as np
import pytest
from matplotlib.patches import Circle

import geardesign as gd
from geardesign.drives.stage_kinds import Batch, StageKind, kind_names, register, unregister
from geardesign.drives.stages import stage_area_mm2
from geardesign.errors import GearDesignError
from geardesign.scene import load_scene
from geardesign.scene.drive import build_drive
from tests.scene_files import write

matplotlib.use("Agg")


# ------------------------------------------------------------------ the made-up kind (docs/extending.md)

@dataclass(frozen=True)
class BeltStage:
    """A V-belt: pulleys d1 (driving) and d2 [mm] from two short lists, or given."""

    d1_mm: float | None = None
    d2_mm: float | None = None
    v_max_m_s: float = 30.0
    efficiency: float = 0.95
    name: str = "belt"
    d1_list: tuple = (90.0, 100.0, 112.0, 125.0)
    d2_list: tuple = (180.0, 200.0, 224.0, 250.0, 280.0, 315.0)


def belt_speed_m_s(d1_mm, n1_rpm):
    """v = π·d1·n1/60 000 [m/s]."""
    return np.pi * np.asarray(d1_mm, dtype=float) * np.asarray(n1_rpm, dtype=float) / 60_000.0


class BeltKind(StageKind):
    name = "belt"
    stage_class = BeltStage
    colour = "#e5d8bd"

    def _pairs(self, st):
        d1 = np.array(st.d1_list if st.d1_mm is None else (st.d1_mm,))
        d2 = np.array(st.d2_list if st.d2_mm is None else (st.d2_mm,))
        D1, D2 = (a.ravel() for a in np.meshgrid(d1, d2, indexing="ij"))
        return D1, D2

    def ratio_span(self, st):
        D1, D2 = self._pairs(st)
        return (float((D2 / D1).min()), float((D2 / D1).max()))

    def fixed_ratio(self, st):
        return st.d2_mm / st.d1_mm

    def options(self, st, ratio_lo, ratio_hi):
        D1, D2 = self._pairs(st)
        ok = (D2 / D1 >= ratio_lo * (1 - 1e-12)) & (D2 / D1 <= ratio_hi * (1 + 1e-12))
        return dict(d1=D1[ok], d2=D2[ok], ratio=D2[ok] / D1[ok])

    def batch(self, st, designs):
        d1, d2 = designs.option["d1"], designs.option["d2"]
        speed = 1.0 - belt_speed_m_s(d1, designs.n_in_rpm) / st.v_max_m_s
        return Batch(margins={"speed": speed}, size_mm2=stage_area_mm2(d1 + d2, d1, d2))

    def design_columns(self, st, option, info, c):
        return {f"{st.name}.d1_mm": float(option["d1"]), f"{st.name}.d2_mm": float(option["d2"])}

    def fix(self, st, option, info, c, objective, flow=None):
        return replace(st, d1_mm=float(option["d1"]), d2_mm=float(option["d2"]))

    def analyse(self, st, flow, objective):
        v = float(belt_speed_m_s(st.d1_mm, flow.n_in_rpm))
        return dict(stage=st, margins={"speed": 1.0 - v / st.v_max_m_s},
                    size=float(stage_area_mm2(st.d1_mm + st.d2_mm, st.d1_mm, st.d2_mm)),
                    summary=dict(name=st.name, kind="belt", d1_mm=st.d1_mm, d2_mm=st.d2_mm, speed_m_s=v,
                                 ratio=st.d2_mm / st.d1_mm, efficiency=st.efficiency))

    def scene_keys(self):
        return {"d1_mm": dict(kind="float", lo=20.0, hi=2000.0), "d2_mm": dict(kind="float", lo=20.0, hi=2000.0),
                "efficiency": dict(kind="float", default=0.95, lo=0.3, hi=1.0, lo_open=True)}

    wheels = True                      # two pulleys on the shafts

    def first_offset(self, s):
        return 0.35

    def last_offset(self, s):
        return min(0.35 * s["ratio"], 0.9)

    def draw(self, canvas, x, s):
        r1 = 0.35
        r2 = min(r1 * s["ratio"], 0.9)
        x2 = x + r1 + r2 + 0.8
        canvas.circle(x, r1, self.colour)
        canvas.circle(x2, r2, self.colour)
        canvas.line([x, x2], [r1, r2])
        canvas.line([x, x2], [-r1, -r2])
        return x2, f"{s['name']}: d {s['d1_mm']:g}/{s['d2_mm']:g} mm, v {s['speed_m_s']:.1f} m/s"

# ------------------------------------------------------------------------------------------ tests


@pytest.fixture
def belt():
    register(BeltKind())
    yield
    unregister("belt")


def _omega(n_rpm):
    return 2 * math.pi * n_rpm / 60


def test_an_unregistered_stage_is_refused_naming_the_kinds():
    with pytest.raises(GearDesignError, match="stages must be GivenStage, GearStage, ChainStage or WormStage, got BeltStage"):
        gd.Drive(power_kw=4, n_in_rpm=1450, stages=[BeltStage(100, 250)])


def test_analyse_hands_the_kind_its_flow(belt):
    d = gd.Drive(power_kw=4, n_in_rpm=1450, stages=[BeltStage(100.0, 250.0), gd.GivenStage(10, 0.9, "reducer")])
    a = d.analyse()
    t0 = 4000 / _omega(1450)
    t1 = t0 * 2.5 * 0.95
    v = math.pi * 100 * 1450 / 60_000                      # 7.592 m/s
    got = a.checks.set_index(["item", "check"])["margin"]
    assert got[("belt", "speed")] == pytest.approx(1 - v / 30, rel=1e-14)
    flow = a.stages[0]["flow"]
    assert (flow.n_in_rpm, flow.n_out_rpm) == pytest.approx((1450, 580), rel=1e-15)
    assert (flow.torque_in_nm, flow.torque_out_nm) == pytest.approx((t0, t1), rel=1e-14)
    assert a.size_mm2 == pytest.approx((350 + 175) * 250, rel=1e-15)
    assert a.flow["torque_nm"].iloc[-1] == pytest.approx(t1 * 10 * 0.9, rel=1e-14)


def test_the_search_picks_the_smallest_belt_of_a_brute_force(belt):
    d = gd.Drive(power_kw=4, n_in_rpm=2900, stages=[BeltStage(v_max_m_s=17.0), gd.GivenStage(10, 0.9, "reducer")])
    r = d.optimize(total_ratio=22, ratio_tol=0.03, objective="min_size", top=3)
    # brute force over the two lists: inside the ratio window, belt speed within 17 m/s, smallest envelope
    pool = []
    for d1 in BeltStage.d1_list:
        for d2 in BeltStage.d2_list:
            u = d2 / d1 * 10
            v = math.pi * d1 * 2900 / 60_000
            if abs(u - 22) / 22 <= 0.03 and v <= 17.0:
                pool.append(((d1 + d2 + (d1 + d2) / 2) * max(d1, d2), abs(u - 22) / 22, d1, d2))
    want = min(pool)
    best = r.table.iloc[0]
    assert (best["belt.d1_mm"], best["belt.d2_mm"]) == (want[2], want[3])
    assert best["size_mm2"] == pytest.approx(want[0], rel=1e-14)
    assert r.best.stages[0]["stage"].d1_mm == want[2]     # the design fixed and analysed by the kind
    assert r.success and len(r.table[r.table["feasible"]]) == min(3, len(pool))


def test_the_search_reports_the_kinds_failing_check(belt):
    d = gd.Drive(power_kw=4, n_in_rpm=2900, stages=[BeltStage(v_max_m_s=10.0)])
    r = d.optimize(total_ratio=2.0, ratio_tol=0.0)
    # u = 2: 90/180, 100/200, 112/224, 125/250, all too fast; the closest is the smallest pulley
    v = math.pi * 90 * 2900 / 60_000            # 13.67 m/s
    assert not r.success
    assert r.conflict == (f"belt: speed ({1 - v / 10:+.3g})",)
    assert r.table["belt.d1_mm"].tolist() == [90, 100, 112, 125]


def test_the_diagram_draws_the_kind(belt):
    import matplotlib.pyplot as plt

    a = gd.Drive(power_kw=4, n_in_rpm=1450, stages=[BeltStage(100.0, 250.0)]).analyse()
    ax = a.plot()
    try:
        pulleys = [p for p in ax.patches if isinstance(p, Circle)]
        assert [p.radius for p in pulleys] == pytest.approx([0.35, 0.875])
        assert "belt: d 100/250 mm, v 7.6 m/s" in [t.get_text() for t in ax.texts]
    finally:
        plt.close(ax.figure)


def test_a_scene_names_the_kind(belt, tmp_path):
    body = """
[drive]
power_kw = 4
n_in_rpm = 1450
[[drive.stage]]
kind = "belt"
d1_mm = 100
d2_mm = 250
"""
    section = load_scene(str(write(tmp_path, body))).sections["drive"]
    drive, _ = build_drive(section)
    assert drive.stages == (BeltStage(100.0, 250.0),)
    with pytest.raises(GearDesignError, match="d3_mm"):
        load_scene(str(write(tmp_path, body + "d3_mm = 1\n")))


def test_the_kind_leaves_with_unregister():
    register(BeltKind())
    assert "belt" in kind_names()
    unregister("belt")
    assert kind_names() == ("given", "gear", "chain", "worm")


def test_the_extending_guide_runs_this_files_kind():
    """docs/extending.md's worked example is this file's kind, runs as written, and the figures it
    quotes are the ones it prints."""
    import contextlib
    import inspect
    import io
    import re
    from pathlib import Path

    import matplotlib.pyplot as plt

    doc = (Path(__file__).resolve().parents[3] / "docs" / "extending.md").read_text(encoding="utf-8")
    section = doc[doc.index("## Adding a drive stage kind"):]
    block = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    for obj in (BeltStage, belt_speed_m_s, BeltKind):
        assert inspect.getsource(obj) in block
    out = io.StringIO()
    try:
        with contextlib.redirect_stdout(out):
            ns = {}
            exec(compile(block, "docs/extending.md", "exec"), ns)
        plt.close(ns["ax"].figure)
    finally:
        unregister("belt")
    message = out.getvalue().splitlines()[0]
    assert message.split("; ")[0] in section
    best = ns["r"].table.iloc[0]
    assert (best["belt.d1_mm"], best["belt.d2_mm"]) == (90.0, 200.0)


def test_analyse_keeps_each_gear_stages_flow():
    """What a load-based check of a gear stage reads: the speed and torque in and out of it, as the
    hand-worked flow (4 kW at 1500 rpm, gear motor u = 12.5, η = 0.87, then the pair 20/50, η = 0.97)."""
    a = gd.Drive(power_kw=4, n_in_rpm=1500, stages=[gd.GivenStage(12.5, 0.87, "gear motor"),
                                                    gd.GearStage(2, z1=20, z2=50, efficiency=0.97)]).analyse()
    t1 = 4000 / _omega(1500) * 12.5 * 0.87
    flow = a.stages[1]["flow"]
    assert (flow.n_in_rpm, flow.n_out_rpm) == pytest.approx((120, 48), rel=1e-15)
    assert (flow.torque_in_nm, flow.torque_out_nm) == pytest.approx((t1, t1 * 2.5 * 0.97), rel=1e-14)
