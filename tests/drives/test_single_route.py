"""Issue 35 §1: one route from a load to a margin. A load model registered once with the check registry (the
docs/extending.md example: the line load w = F_t/b = 2000·T1/(d_w1·b), a handbook sizing rule) appears in a
pair's checks, in a feasible region and in a drive stage sized by its load, each time with the value the formula
gives for that design (computed here from the design's own d_w1, independently of the check)."""
from __future__ import annotations

from dataclasses import dataclass

import pytest

import geardesign as gd
from geardesign.gears.checks import Check, Option, register, unregister

LIMIT = Option("line_load_max_n_mm", "limit", None, "largest line load F_t/b at the pitch circle, N/mm",
               source="the designer's rule", range=(1.0, 5000.0))


def _with_load_case(cls, value, context):
    spec = context.get("strength_spec")
    return [] if spec is None else [cls(limit=value, spec=spec)]


@dataclass(frozen=True)
class LineLoad(Check):
    option, colour, order = LIMIT, "sienna", 85
    fd_gradient = True
    build = classmethod(_with_load_case)
    spec: object = None

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or "line_load")
        object.__setattr__(self, "label", self.label or f"F_t/b <= {self.limit:g} N/mm")

    def value(self, geo):
        return 2000.0 * self.spec.load.torque_nm / geo["dw1"] / self.spec.width(geo)

    def margin(self, geo):
        return 1.0 - self.value(geo) / self.limit

    def gradient(self, geo):
        return None


@pytest.fixture()
def line_load():
    register(LineLoad)
    yield
    unregister(LineLoad)


def test_a_registered_load_model_reaches_a_pair_a_region_and_a_sized_drive(line_load):
    case = {"load": gd.Load(torque_nm=400, n_rpm=1000), "material": "42CrMo4", "face_width_mm": 40.0}
    pair = gd.GearPair(4, 20, 60, 0.3, 0.2, face_width_mm=40)
    row = pair.checks(line_load_max_n_mm=300, **case).set_index("check").loc["line_load"]
    assert float(row["value"]) == pytest.approx(2000 * 400 / pair.geometry().dw1 / 40, rel=1e-12)

    region = gd.feasible_region(20, 60, checks={"line_load_max_n_mm": 300, **case}, m=4, n=21)
    assert "line_load" in list(region.checks)

    # a drive stage sized by its load: 11 kW at 1460 rpm, a line-load limit that decides the width
    stage = gd.GearStage(None, z1_range=(19, 19), ratio_range=(3, 3.2), material="42CrMo4",
                         checks={"line_load_max_n_mm": 150})
    best = gd.Drive(power_kw=11, n_in_rpm=1460, stages=[stage]).optimize(3.1, 0.03).best
    t = best.checks.set_index("check")
    assert "line_load" in t.index
    st = best.drive.stages[0]
    torque = 11e3 / (1460 * 2 * 3.141592653589793 / 60)
    dw1 = gd.GearPair(st.m, st.z1, st.z2, st.x1, st.x2).geometry().dw1
    assert float(t.loc["line_load", "margin"]) == pytest.approx(1 - 2000 * torque / dw1 / st.face_width_mm / 150,
                                                                abs=1e-9)
    assert float(t.loc["line_load", "margin"]) >= 0          # the sizing held it


def test_select_teeth_takes_standard_as_the_series_housing():
    """Issue 35 §2: select_teeth(..., a_w="standard") puts each pair on a GOST 2185-66 centre distance."""
    from geardesign.catalogs import center_distance_series

    sel = gd.select_teeth(3.15, 0.03, m=3, a_w="standard", z1_range=(18, 22))
    rows = sel.table[sel.table["feasible"]]
    assert len(rows)
    series = center_distance_series((1, 2))
    for a in rows["a_w_mm"]:
        assert abs(series - a).min() < 1e-9 * a
