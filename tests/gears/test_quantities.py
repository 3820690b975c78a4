"""The handbook's two-column layout of one pair's geometry (geardesign.gears.quantities), and GearPair's
refusal of arguments that belong elsewhere (issue 28)."""
import math

import pytest

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears.geometry import GEOMETRY_FIELDS
from geardesign.gears.quantities import GEAR_ROWS, PAIR_ROWS


def test_every_field_is_laid_out_once():
    laid = [f for *_, f in PAIR_ROWS] + [f for *_, f1, f2 in GEAR_ROWS for f in (f1, f2)]
    assert len(laid) == len(set(laid))
    assert set(laid) <= set(GEOMETRY_FIELDS)
    # the one field left out is an intermediate value of no use on a calculation sheet
    assert set(GEOMETRY_FIELDS) - set(laid) == {"inv_alpha_w"}


def test_table_by_hand_for_the_khk_pair():
    """KHK's worked example (m 3, z 12/24, x 0.6/0.36; KHK Gear Technical Reference, the profile-shifted spur
    gear table, as tests/data/gear_examples.csv cites it): a_w 56.4999, α_w 26.0886°, d_w 37.667 / 75.333,
    d_a 44.840 / 79.400, d_f 32.100 / 66.660 mm; base diameters m·z·cos 20°."""
    g = gd.GearPair(3, 12, 24, 0.6, 0.36).geometry()
    t = g.to_table().set_index("symbol")
    assert list(t.columns) == ["quantity", "unit", "gear 1", "gear 2"]
    assert t.loc["a_w", "gear 1"] == pytest.approx(56.4999, abs=1e-4) and math.isnan(t.loc["a_w", "gear 2"])
    assert t.loc["α_w", "gear 1"] == pytest.approx(26.0886, abs=1e-4)
    assert t.loc["d", ["gear 1", "gear 2"]].tolist() == [36.0, 72.0]
    assert t.loc["d_b", "gear 1"] == pytest.approx(36 * math.cos(math.radians(20)), rel=1e-14)
    assert t.loc["d_a", "gear 1"] == pytest.approx(44.84, abs=1e-3)
    assert t.loc["d_a", "gear 2"] == pytest.approx(79.400, abs=1e-3)
    assert t.loc["d_w", ["gear 1", "gear 2"]].tolist() == pytest.approx([37.667, 75.333], abs=1e-3)
    assert t.loc["d_f", ["gear 1", "gear 2"]].tolist() == pytest.approx([32.100, 66.660], abs=1e-3)
    assert "ε_β" not in t.index                     # spur: no helical rows
    assert "ε_β" in gd.GearPair(3, 12, 24, beta_deg=15, face_width_mm=20).geometry().to_table()["symbol"].tolist()


@pytest.mark.parametrize("name, value, hint", [
    ("alpha", 25, "rack=BasicRack(alpha_deg=25)"),
    ("alpha_deg", 25, "rack=BasicRack(alpha_deg=25)"),
    ("module", 8, "m=8"),
    ("a_w", 180, "GearPair.from_center_distance"),
    ("speed", 3, "its arguments are"),
])
def test_gearpair_unknown_argument_is_named_with_a_hint(name, value, hint):
    with pytest.raises(GearDesignError) as exc:
        gd.GearPair(8, 17, 26, **{name: value})
    assert repr(name) in str(exc.value) and hint in str(exc.value)


def test_gearpair_keywords_still_work():
    p = gd.GearPair(m=8, z1=17, z2=26, x1=0.898, x2=0.517, rack=gd.BasicRack(alpha_deg=25, rho_f=0.3))
    assert p.rack.alpha_deg == 25
