"""Golden tests of the pair geometry against published worked examples.

Sources (each row of tests/data/gear_examples.csv names its own; docs/references.md lists them):
* KHK Gear Technical Reference, profile-shifted external pair 12/24, m 3, x 0.6/0.36,
  as reproduced by bolsover/UtilitiesForAlibre unit tests and bolsover.com (E1, E2);
* bolsover/GearCalculator standard pair 18/25, m 2.5 (E7);
* KHK undercut limits x_min for z = 12 and 24 (U_KHK_xmin);
* seed 001 (Bryansk TMM guide, table 3): unshifted pairs, checked against the guide's formulas;
* seed 000 (engine course work): 17/26, x 0.898/0.517 recomputed (the seed's inv α_w = 0.38868
  is a slip for 0.03886, its α_w = 26°08' for 27.13°, its ε_α = 0.133 for 1.153).
"""
import math
from pathlib import Path

import pandas as pd
import pytest

import geardesign as gd

DATA = pd.read_csv(Path(__file__).parent / "data" / "gear_examples.csv")

# (parameter, member) in the CSV -> geometry field
FIELD = {
    ("alpha_w_deg", "pair"): "alpha_w_deg", ("inv_alpha_w", "pair"): "inv_alpha_w",
    ("a_w", "pair"): "a_w", ("y_centre_distance_mod_coeff", "pair"): "y",
    ("delta_y_tip_reduction", "pair"): "dy", ("eps_alpha", "pair"): "eps_alpha",
    ("a0", "pair"): "a",
    **{(p, str(j)): f"{f}{j}" for j in (1, 2)
       for p, f in (("d", "d"), ("d_b", "db"), ("d_w", "dw"), ("d_a", "da"), ("d_f", "df"))},
}


def _decimals(text: str) -> int:
    text = str(text)
    return len(text.split(".")[1]) if "." in text else 0


def _rows(example):
    rows = DATA[DATA.example_id == example]
    out = []
    for _, r in rows.iterrows():
        key = (r.parameter, str(r.member))
        if key in FIELD and isinstance(r.published_value, str) or (key in FIELD and not pd.isna(r.published_value)):
            out.append((FIELD[key], r.published_value, r.source))
    return out


@pytest.mark.parametrize("field,published,source", _rows("E1_KHK_ext_12_24"))
def test_khk_external_12_24(field, published, source):
    # KHK computes a_w from x (56.49987 mm); published values are rounded to the digits shown.
    geo = gd.GearPair(3, 12, 24, 0.6, 0.36).geometry()
    value = getattr(geo, field)
    half_unit = 0.5 * 10.0 ** -_decimals(published) + 1e-12
    assert abs(value - float(published)) <= half_unit, (field, value, published, source)


def test_khk_tip_shortening_and_heights():
    # KHK table: h_a1 = (1 + y − x2)m = 4.420, h_a2 = 3.700, whole depth 6.370 (rounded to 3 decimals)
    geo = gd.GearPair(3, 12, 24, 0.6, 0.36).geometry()
    assert round((geo.da1 - geo.d1) / 2, 3) == 4.420
    assert round((geo.da2 - geo.d2) / 2, 3) == 3.700
    assert round((geo.da1 - geo.df1) / 2, 3) == 6.370
    assert round(geo.dy, 5) == 0.12671   # implied by KHK's h_a (see the CSV note)


def test_khk_inverse_from_center_distance():
    # E2: a_w = 56.4999 given -> x_sum 0.960013, alpha_w 26.0886, d_w 37.6666 / 75.3332
    pair = gd.GearPair.from_center_distance(3, 12, 24, 56.4999, x1=0.6)
    geo = pair.geometry()
    assert abs(pair.x1 + pair.x2 - 0.960013) < 5e-7
    assert abs(geo.alpha_w_deg - 26.0886) < 5e-5
    assert abs(geo.dw1 - 37.6666) < 5e-5 and abs(geo.dw2 - 75.3332) < 5e-5
    assert abs(geo.a_w - 56.4999) < 1e-12


def test_khk_from_center_distance_page_variant():
    # bolsover.com page / GearCalculator use a_w = 56.500 as input: alpha_w = 26.08883 deg, y = 0.83333
    geo = gd.GearPair.from_center_distance(3, 12, 24, 56.5, x1=0.6).geometry()
    assert abs(geo.alpha_w_deg - 26.08883) < 5e-6
    assert abs(geo.y - 0.83333) < 5e-6


@pytest.mark.parametrize("field,published,source", _rows("E7_std_18_25_m2_5"))
def test_standard_pair_18_25(field, published, source):
    geo = gd.GearPair(2.5, 18, 25).geometry()
    half_unit = 0.5 * 10.0 ** -_decimals(published) + 1e-12
    assert abs(getattr(geo, field) - float(published)) <= half_unit, (field, source)


@pytest.mark.parametrize("z,x_min", [(12, 0.29813), (24, -0.40373)])
def test_khk_undercut_limit(z, x_min):
    # KHK uses x_min = h_a* − z sin²α/2, i.e. a cutter whose straight flank ends at h_a*:
    # rho_f* = c*/(1 − sin α) gives exactly that (the standard 0.38 rounds it).
    rack = gd.BasicRack(rho_f=0.25 / (1 - math.sin(math.radians(20))))
    geo = gd.GearPair(3, z, 60, 0.0, 0.0, rack=rack).geometry()
    assert abs(geo.x_min1 - x_min) < 5e-6
    # the standard rack's 0.38 shifts the limit by 0.38(1 − sin 20°) − 0.25 = 3.2e-5
    std = gd.GearPair(3, z, 60).geometry()
    assert abs(std.x_min1 - (x_min - (0.38 * (1 - math.sin(math.radians(20))) - 0.25))) < 5e-6


# Seed 001, table 3: unshifted pairs (variant: m, z1, z2). Its formulas: d = mz, d_a = d + 2m,
# d_f = d − 2.5m, d_b = d cos 20°, a_w = m(z1 + z2)/2 (the seed's a_w = 0.5(z1 + z2) omits m,
# a slip its drawing corrects to 51 mm for variant 2-like 17/34, m = 2), p = πm, s = p/2.
SEED001 = [(1, 4, 19, 38), (2, 1, 17, 34), (5, 4, 18, 27), (10, 2, 17, 51), (13, 6, 19, 48),
           (21, 7, 17, 51), (26, 6, 23, 69), (30, 3, 20, 40)]


@pytest.mark.parametrize("variant,m,z1,z2", SEED001)
def test_seed001_unshifted(variant, m, z1, z2):
    geo = gd.GearPair(m, z1, z2).geometry()
    c20 = math.cos(math.radians(20))
    assert geo.alpha_w_deg == pytest.approx(20.0, abs=1e-12)
    assert geo.a_w == pytest.approx(m * (z1 + z2) / 2, rel=1e-15)
    assert geo.da1 == pytest.approx(m * (z1 + 2), rel=1e-15)
    assert geo.df2 == pytest.approx(m * (z2 - 2.5), rel=1e-15)
    assert geo.db1 == pytest.approx(m * z1 * c20, rel=1e-15)
    assert geo.sw1 == pytest.approx(math.pi * m / 2, rel=1e-14)
    # contact ratio as the seed defines it: active length of the line of action over the base pitch
    ra1, ra2, rb1, rb2 = m * (z1 + 2) / 2, m * (z2 + 2) / 2, m * z1 * c20 / 2, m * z2 * c20 / 2
    g = math.sqrt(ra1**2 - rb1**2) + math.sqrt(ra2**2 - rb2**2) - m * (z1 + z2) / 2 * math.sin(math.radians(20))
    assert geo.eps_alpha == pytest.approx(g / (math.pi * m * c20), rel=1e-13)


def test_seed001_task2_drawing():
    # Seed 001, task 2 (z 17/34, m 2): d_w 34/68, d_a 38/72, d_f 29/63, d_b 31.95/63.9, a_w 51 mm.
    geo = gd.GearPair(2, 17, 34).geometry()
    assert (geo.dw1, geo.dw2, geo.da1, geo.da2, geo.df1, geo.df2) == pytest.approx((34, 68, 38, 72, 29, 63), rel=1e-14)
    assert round(geo.db1, 2) == 31.95 and round(geo.db2, 1) == 63.9
    assert geo.a_w == pytest.approx(51.0, rel=1e-15)


def test_seed000_engine_pair():
    """Seed 000: m 8, z 17/26, x 0.898/0.517 (Kudryavtsev's tables), standard rack."""
    pair = gd.GearPair(8, 17, 26, 0.898, 0.517)
    geo = pair.geometry()
    # inv α_w = 2·1.415·tan20°/43 + inv 20° = 0.0388587 (the seed prints 0.38868: a slipped digit)
    inv_w = 2 * 1.415 * math.tan(math.radians(20)) / 43 + (math.tan(math.radians(20)) - math.radians(20))
    assert geo.inv_alpha_w == pytest.approx(inv_w, rel=1e-14)
    assert round(inv_w, 5) == 0.03886
    # α_w is about 27.13° (the seed's 26°08' is read off a wrong table line)
    assert geo.alpha_w_deg == pytest.approx(27.13, abs=0.005)
    # a_w = 172 cos20°/cos α_w, computed here from the α_w above independently
    assert geo.a_w == pytest.approx(172 * math.cos(math.radians(20)) / math.cos(math.radians(geo.alpha_w_deg)), rel=1e-14)
    assert geo.a_w == pytest.approx(181.60, abs=0.005)       # seed: 181.632 with its wrong α_w
    # seed's unaffected items: d 136/208, d_f 130.368/196.272 (seed rounds 130.3/196.2), d_b 127.8/195.5
    assert (geo.d1, geo.d2) == (136.0, 208.0)
    assert geo.df1 == pytest.approx(136 - 2 * (1.25 - 0.898) * 8, rel=1e-15)
    assert geo.df2 == pytest.approx(208 - 2 * (1.25 - 0.517) * 8, rel=1e-15)
    # ε_α is below 1.2 (the seed prints 0.133, a slip for q_a/p_b with its own 26.07/23.6 = 1.10)
    assert 1.10 < geo.eps_alpha < 1.2
    table = pair.checks().set_index("check")
    assert not table.loc["contact_ratio", "ok"]
    assert table.drop(index="contact_ratio")["ok"].all()
    # the seed's jamming test r_a2 < O2N1 holds: its 114.4 < 128.14; recomputed O2N1 ≈ 128.09
    assert table.loc["jamming1", "ok"] and geo.da2 / 2 < geo.o2n1
    assert geo.o2n1 == pytest.approx(128.1, abs=0.05)


def test_seed000_without_tip_shortening_contact_ratio_rises():
    # Without shortening the tips are Δy·m longer: ε_α grows but the clearance drops below c*·m.
    short = gd.GearPair(8, 17, 26, 0.898, 0.517).geometry()
    full = gd.GearPair(8, 17, 26, 0.898, 0.517, tip_shortening=False).geometry()
    assert full.da1 - short.da1 == pytest.approx(2 * 8 * short.dy, rel=1e-12)
    assert full.eps_alpha > short.eps_alpha
    assert full.clearance1 == pytest.approx(8 * (0.25 - short.dy), rel=1e-12)
