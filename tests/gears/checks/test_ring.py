"""The checks of an internal (ring) pair (geardesign.gears.checks.ring) on KHK's Table 5-4 pairs with small tooth
differences (SDP/SI-KHK "Elements of Metric Gear Technology" §5.3, tests/data/internal_helical_examples.csv):
the text says every pair is free of tip (trochoid) interference and still has trimming interference (the pinion
goes in axially), and the ring tip's limit is its base circle, computed here."""
import math
from pathlib import Path

import pandas as pd
import pytest

import geardesign as gd

DATA = pd.read_csv(Path(__file__).parents[2] / "data" / "internal_helical_examples.csv")
TABLE_5_4 = DATA[DATA.example_id.str.startswith("I54_KHK_int")].drop_duplicates("example_id")


def _checks(r, **options):
    # KHK Table 5-1's tips: d_a1 = d1 + 2(1 + x1)m, d_a2 = d2 − 2(1 − x2)m, i.e. no tip shortening
    pair = gd.GearPair(r.m, r.z1, r.z2, r.x1, r.x2, internal=True, tip_shortening=False)
    return pair, pair.checks(**options).set_index("check")


@pytest.mark.parametrize("r", list(TABLE_5_4.itertuples()), ids=lambda r: r.example_id)
def test_khk_table_5_4(r):
    pair, t = _checks(r, radial_assembly=True, tooth_difference_min=10)
    alpha_w = DATA[(DATA.example_id == r.example_id) & (DATA.parameter == "alpha_w_deg")].published_value.iloc[0]
    assert pair.geometry().alpha_w_deg == pytest.approx(alpha_w, abs=5e-5)      # the printed α_w, 4 decimals
    assert t.loc["tip_interference", "margin"] >= 0         # "free of trochoid interference"
    assert t.loc["radial_assembly", "margin"] < 0           # "trimming interference is still there"
    assert t.loc["tooth_difference", "value"] == r.z2 - r.z1 and t.loc["tooth_difference", "limit"] == 10
    assert not t.loc["tooth_difference", "ok"]              # KHK's rule of thumb wants more than 9


def test_the_ring_tip_limit_is_its_base_circle():
    pair, t = _checks(TABLE_5_4.iloc[0])
    z2, x2 = pair.z2, pair.x2
    assert t.loc["ring_tip", "limit"] == pytest.approx(z2 * math.cos(math.radians(20)) / 2, rel=1e-14)
    assert t.loc["ring_tip", "value"] == pytest.approx((z2 - 2 * (1 - x2)) / 2, rel=1e-14)   # r_a2/m


def test_a_ring_pair_checks_what_a_ring_needs():
    _, t = _checks(TABLE_5_4.iloc[-1])
    names = set(t.index)
    assert {"ring_tip", "tip_interference", "cutter_trimming", "cutter_interference", "interference1",
            "interference2", "undercut1", "contact_ratio"} <= names
    assert "undercut2" not in names and "jamming2" not in names     # a ring is not undercut by a rack
    assert "radial_assembly" not in names and "tooth_difference" not in names   # both optional, off by default
