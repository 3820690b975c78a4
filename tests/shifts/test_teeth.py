"""Tooth-count selection: enumeration checked by hand, the x-sum of a fixed centre distance from the
textbook inv α_w formula, feasibility re-checked with GearPair, the seed 000 case."""
import json
import math
from fractions import Fraction

import numpy as np
import pandas as pd
import pytest

import geardesign as gd
from geardesign.gears.checks import make_checks, margins
from geardesign.gears.geometry import mesh_geometry
from geardesign.gears.mesh import Mesh
from geardesign.shifts.teeth import TeethSelection, ratio_pairs, select_teeth

ALPHA = math.radians(20.0)


def inv(a):
    return math.tan(a) - a


def textbook_x_sum(m, z1, z2, a_w, alpha=ALPHA):
    """cos α_w = a cos α / a_w; x1 + x2 = (z1 + z2)(inv α_w − inv α) / (2 tan α)."""
    a = m * (z1 + z2) / 2
    alpha_w = math.acos(a * math.cos(alpha) / a_w)
    return (z1 + z2) * (inv(alpha_w) - inv(alpha)) / (2 * math.tan(alpha))


def pair_ok(row, **limits):
    """Re-check a table row with GearPair (independent of the optimiser)."""
    p = gd.GearPair(row["module_mm"], int(row["z1"]), int(row["z2"]), row["x1"], row["x2"])
    table = p.checks(jamming=False, **limits).set_index("check")
    return bool((table["margin"] >= -1e-9).all()), table


# --- enumeration -------------------------------------------------------------------------

def test_ratio_two_exact_gives_twice_z1_only():
    z1, z2 = ratio_pairs(2.0, 0.0, (8, 30))
    assert z1.tolist() == list(range(8, 31))
    assert z2.tolist() == [2 * z for z in range(8, 31)]


def test_enumeration_matches_brute_force_fractions():
    want = sorted((a, b) for a in range(8, 41) for b in range(3, 200)
                  if abs(Fraction(b, a) - Fraction(3, 2)) <= Fraction(2, 100) * Fraction(3, 2))
    z1, z2 = ratio_pairs(1.5, 0.02, (8, 40))
    assert sorted(zip(z1.tolist(), z2.tolist())) == want
    # 26/17 and 25/17 are 1/51 = 1.96 % off 1.5 (inside 2 %); 27/17 is 5.9 % off
    assert (17, 26) in want and (17, 25) in want and (17, 27) not in want


def test_z_sum_max_respected():
    z1, z2 = ratio_pairs(1.5, 0.02, (8, 40), z_sum_max=45)
    assert (z1 + z2).max() <= 45 and (18, 27) in zip(z1.tolist(), z2.tolist())
    assert (19, 28) not in zip(z1.tolist(), z2.tolist())        # 47 teeth


def test_table_ratio_columns_by_hand():
    sel = select_teeth(2.0, ratio_tol=0.0, m=2, z1_range=(20, 22), method="grid")
    assert sorted(zip(sel.table["z1"], sel.table["z2"])) == [(20, 40), (21, 42), (22, 44)]
    assert (sel.table["ratio_error"] == 0).all()
    assert np.allclose(sel.table["a_mm"], 2 * (sel.table["z1"] + sel.table["z2"]) / 2)
    for col in ("z1", "z2", "ratio", "ratio_error", "module_mm", "a_mm", "a_w_mm", "x1", "x2", "eps_alpha",
                "objective", "feasible", "reason", "margin_contact_ratio", "margin_undercut1",
                "margin_interference2", "margin_tip_thickness1"):
        assert col in sel.table.columns


# --- centre distance given ----------------------------------------------------------------

def test_fixed_center_distance_x_sum_is_textbook():
    sel = select_teeth(1.5, m=8, a_w=180.0)
    assert len(sel.table) >= 2
    for _, row in sel.table.iterrows():
        xs = textbook_x_sum(8, row["z1"], row["z2"], 180.0)
        assert row["x1"] + row["x2"] == pytest.approx(xs, abs=1e-9)
        assert row["a_w_mm"] == pytest.approx(180.0, rel=1e-12)
    # every pair with a·cos α >= 180 mm is skipped with that reason: z1 + z2 >= 48 at m = 8
    big = sel.skipped[sel.skipped["z1"] + sel.skipped["z2"] >= 48]
    assert len(big) and big["reason"].str.contains("a·cos").all()
    assert ((sel.table["z1"] + sel.table["z2"]) < 48).all()


def test_center_distance_series_picks_next_standard():
    # 17/26, m = 8: a = 172 mm; GOST 2185-66 has 160 and 180 mm around it
    sel = select_teeth(1.5, m=8, a_w="series", z1_range=(17, 17))
    row = sel.table.set_index(["z1", "z2"]).loc[(17, 26)]
    assert row["a_w_mm"] == pytest.approx(180.0)
    assert row["x_sum"] == pytest.approx(textbook_x_sum(8, 17, 26, 180.0), abs=1e-9)


def test_module_series_with_fixed_center_distance():
    sel = select_teeth(2.0, ratio_tol=0.0, m="series", a_w=100.0, z1_range=(10, 30), m_range=(1, 6))
    standard = set(gd.catalogs.module_series((1, 2), 1, 6).tolist())
    assert set(sel.table["module_mm"]) <= standard
    for _, row in sel.table.iterrows():
        assert row["x1"] + row["x2"] == pytest.approx(
            textbook_x_sum(row["module_mm"], row["z1"], row["z2"], 100.0), abs=1e-9)
    # ranking: among feasible exact-ratio rows, first-series modules come before second-series ones
    feas = sel.table[sel.table["feasible"]]
    s = feas["module_series"].tolist()
    assert s == sorted(s, key=lambda v: 0 if v == 1 else 1)
    per = sel.best_per_module()
    assert per["module_mm"].is_unique and per["feasible"].all()
    assert set(per["module_mm"]) == set(feas["module_mm"])


# --- ranking and feasibility ----------------------------------------------------------------

def test_ranking_and_rows_recheck_with_gearpair():
    sel = select_teeth(1.5, m=3, z1_range=(8, 20), z_sum_max=45)
    t = sel.table
    feas = t["feasible"].to_numpy()
    assert not (~feas[:-1] & feas[1:]).any()                    # feasible block first
    f = t[t["feasible"]]
    err = f["ratio_error"].abs().round(12).to_numpy()
    assert (np.diff(err) >= 0).all()
    for e in np.unique(err):                                    # max_x_sum: larger first within a ratio error
        xs = f.loc[np.isclose(f["ratio_error"].abs(), e, atol=1e-12), "x_sum"].to_numpy()
        assert (np.diff(xs) <= 1e-9).all()
    for _, row in f.iterrows():
        ok, _ = pair_ok(row)
        assert ok, (row["z1"], row["z2"])
    bad = t[~t["feasible"]]
    assert (bad["reason"].str.len() > 0).all()
    # 8/12 cannot avoid undercut at eps_alpha >= 1.2 (x_min = 1 - 8 sin²20°/2 = 0.532 each)
    assert "undercut" in t.set_index(["z1", "z2"]).loc[(8, 12), "reason"]


def test_seed_000_alternatives_and_choice():
    """Seed 000: u = 1.5, z2 = 26 → z1 = 17, ratio 26/17 = 1.529 (the seed rounds it to 1.5), shifts
    0.898/0.517 from Kudryavtsev's tables give ε_α = 1.153 < 1.2 (the seed prints 0.133)."""
    seed = gd.GearPair(8, 17, 26, 0.898, 0.517).checks().set_index("check")
    assert seed.loc["contact_ratio", "margin"] < 0

    sel = select_teeth(1.5, m=8, z_sum_max=45)      # pairs no larger than the seed's 43 teeth (+2)
    t = sel.table.set_index(["z1", "z2"])
    # the seed's pair is listed, with shifts that hold every check
    seed_row = t.loc[(17, 26)]
    assert seed_row["ratio_error"] == pytest.approx(float(Fraction(26, 17) / Fraction(3, 2) - 1), abs=1e-15)
    assert seed_row["feasible"] and pair_ok(seed_row.to_dict() | {"z1": 17, "z2": 26})[0]
    # the choice: exact ratio, feasible (re-checked), and its x-sum is the largest feasible one among the
    # exact pairs — checked against a brute-force grid over (x1, x2) on the textbook checks
    best = sel.best
    assert best is not None and best["ratio_error"] == 0
    assert pair_ok(best)[0]
    exact = [(z, 3 * z // 2) for z in range(8, 19, 2)]          # 8/12 ... 18/27 (z_sum <= 45)
    g = np.arange(-0.5, 2.0, 0.01)
    X1, X2 = np.meshgrid(g, g, indexing="ij")
    brute = {}
    for z1, z2 in exact:
        geo = mesh_geometry(Mesh(z1, z2, gd.BasicRack(), True), 8.0, X1, X2)
        ok = np.all([v >= 0 for v in margins(geo, make_checks()).values()], axis=0)
        brute[(z1, z2)] = (X1 + X2)[ok].max() if ok.any() else -np.inf
    winner = max(brute, key=brute.get)
    assert (best["z1"], best["z2"]) == winner
    assert best["x_sum"] == pytest.approx(brute[winner], abs=0.03)
    assert "exact" in sel.choice and f"{winner[0]}/{winner[1]}" in sel.choice

    # with the seed's own layout: a_w from GOST 2185 just above a = 172 mm is 180 mm, where 18/27 needs no shift
    sel_w = select_teeth(1.5, m=8, a_w=180.0)
    bw = sel_w.best
    assert (bw["z1"], bw["z2"]) == (18, 27)                      # a = 8·45/2 = 180 mm: x1 + x2 = 0
    assert bw["x1"] + bw["x2"] == pytest.approx(0.0, abs=1e-9)
    assert pair_ok(bw)[0]


def test_no_feasible_candidate():
    sel = select_teeth(1.0, ratio_tol=0.0, m=1, z1_range=(5, 6))  # 5/5, 6/6: no shifts give ε_α >= 1.2 without undercut
    assert sel.best is None and not sel.table["feasible"].any()
    assert "no feasible" in sel.choice
    assert sel.table["reason"].str.contains("conflict").all()


def test_result_object():
    sel = select_teeth(2.0, ratio_tol=0.0, m=2, z1_range=(20, 21), method="grid")
    assert isinstance(sel, TeethSelection)
    assert "TeethSelection" in repr(sel) and "choice" in repr(sel)
    d = sel.to_dict()
    json.dumps(d, default=float)
    assert d["best"]["z1"] in (20, 21) and len(d["table"]) == 2
    assert isinstance(sel.to_frame(), pd.DataFrame)


@pytest.mark.parametrize("kwargs,words", [
    (dict(ratio=0.5), ["ratio", "[1, 100]", "0.5"]),
    (dict(ratio=1.5, ratio_tol=-0.1), ["ratio_tol", "-0.1"]),
    (dict(ratio=1.5, z1_range=(2, 10)), ["z1_range min", "in [3, 100000]", "2"]),
    (dict(ratio=1.5, z1_range=(20, 10)), ["z1_range", "min <= max"]),
    (dict(ratio=1.5, m=-2), ["m (module)", "-2"]),
    (dict(ratio=1.5, m="big"), ["m must be", "'big'"]),
    (dict(ratio=1.5, m=2, a_w=0), ["a_w", "(0, 1e+10]", "0"]),
    (dict(ratio=1.5, m=2, a_w="nearest"), ["a_w", "'nearest'"]),
    (dict(ratio=1.5, objective="cheap"), ["objective", "'cheap'"]),
    (dict(ratio=float("nan")), ["ratio", "finite"]),
])
def test_bad_input(kwargs, words):
    with pytest.raises(gd.GearDesignError) as info:
        select_teeth(**kwargs)
    for w in words:
        assert w in str(info.value), (w, str(info.value))


# --- issue 29 §3: defects found by generated input ------------------------------------------

def test_internal_rows_marked_feasible_mesh_when_contact_ratio_is_dropped():
    """§3.1: the 25/26 ring pair with ε_α dropped was marked feasible at ε_α = −0.42."""
    sel = select_teeth(1.0, ratio_tol=0.05, z1_range=(21, 25), m=5, internal=True, checks={"eps_alpha_min": None})
    assert len(sel.feasible) > 0
    for _, r in sel.feasible.iterrows():
        pair = gd.GearPair(5, int(r.z1), int(r.z2), r.x1, r.x2, internal=True)   # refuses gears that do not mesh
        assert pair.geometry().eps_alpha > 0


@pytest.mark.parametrize("m, beta_deg", [(0.2, 30.0), (32.5, 0.0), (8.0, 15.0)])
def test_internal_rows_are_solved_with_the_cutter_of_their_module(m, beta_deg):
    """§3.2: the ring's shaper cutter has a standard size per module; the rows were solved with m = 1's
    and failed interference2 / cutter_interference at the module designed. Every feasible row must
    hold GearPair(m, ...).checks() (to ~1e-9: the feasibility tolerance is issue 29 §2)."""
    sel = select_teeth(5.5, m=m, internal=True, z1_range=(20, 24), ratio_tol=0.05, beta_deg=beta_deg)
    assert len(sel.feasible) > 0
    for _, r in sel.feasible.iterrows():
        table = gd.GearPair(m, int(r.z1), int(r.z2), r.x1, r.x2, beta_deg=beta_deg, internal=True).checks()
        assert table["margin"].min() >= -1e-9, table[table["margin"] < -1e-9]
        assert r.a_w_mm == pytest.approx(gd.GearPair(m, int(r.z1), int(r.z2), r.x1, r.x2, beta_deg=beta_deg,
                                                     internal=True).geometry().a_w, rel=1e-9)


@pytest.mark.parametrize("m", [1e300, 2**63, 1e5, 1e-5, 1e-300])
def test_the_module_is_range_checked_with_the_center_distance_free(m):
    """§3.3: m = 1e300 gave a 'feasible' row with a_w 1.5e301 mm; the range is geometry.M_RANGE_MM."""
    from geardesign.gears.geometry import M_RANGE_MM
    with pytest.raises(gd.GearDesignError, match=r"m \(module\) must be in \[0\.0001, 10000\] mm") as info:
        select_teeth(1.925, m=m, z1_range=(8, 10))
    assert M_RANGE_MM == (1e-4, 1e4) and len(str(info.value).splitlines()) == 1


def test_internal_search_skips_pairs_without_a_ring_quietly():
    """Issue 29 §3.13: a ratio tolerance reaching below 1 brought z2 = z1 ring pairs (a = 0) into the
    x-sum formula: 'divide by zero'. They are skipped with a reason now."""
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sel = select_teeth(1.442, ratio_tol=0.5, z1_range=(17, 18), a_w=222.1, internal=True)
    assert (sel.table["z2"] > sel.table["z1"]).all()
    no_ring = sel.skipped[sel.skipped["z2"] <= sel.skipped["z1"]]
    assert len(no_ring) > 0 and no_ring["reason"].str.contains("z2 <= z1").all()


@pytest.mark.parametrize("a_w", [1.7976931348623157e+308, 1.0000001e10])
def test_a_centre_distance_beyond_any_gear_is_refused_by_name(a_w):
    # issue 36 §1.10: a_w = DBL_MAX let a RuntimeWarning (overflow, center_distance.py) escape; the limit is
    # A_W_RANGE_MM, past the largest pair the module and tooth ranges allow: 1e4 mm · 2e5 teeth / 2 / cos 60°
    import warnings

    from geardesign.gears.inputs import A_W_RANGE_MM, M_RANGE_MM
    from geardesign.gears.mesh import Z_MAX
    assert A_W_RANGE_MM[1] >= M_RANGE_MM[1] * 2 * Z_MAX / 2 / math.cos(math.radians(60))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(gd.GearDesignError, match=r"a_w \(center distance\) must be in \(0, 1e\+10\] mm"):
            select_teeth(3.497, ratio_tol=0.05, z1_range=(13, 16), a_w=a_w, beta_deg=23.6376, internal=True,
                         face_width_mm=29.63)
        with pytest.raises(gd.GearDesignError, match=r"a_w \(center distance\) must be in \(0, 1e\+10\] mm"):
            gd.optimize_planetary_shifts(21, 43, 108, 3, 1.75, a_w=a_w)
        # the largest one allowed runs without a warning: no pair reaches it
        sel = select_teeth(3.497, ratio_tol=0.05, z1_range=(13, 16), m=2, a_w=A_W_RANGE_MM[1], internal=True)
        assert sel.best is None and len(sel.skipped) > 0


def test_standard_centre_distance_of_a_tooth_search_is_the_nearest_above_a_whatever_its_x_sum():
    # docs/drive_train.md said a_w="standard" keeps a reducer's x-sum window (-0.5 ... 1.0) as a drive stage does;
    # it takes the nearest GOST 2185-66 value >= a: 18/90 at m = 4 (a = 216 mm) goes to 225 mm, and x_Σ follows
    # from ISO 21771 eq. (62), computed here: inv α_w = inv α + 2 tan α x_Σ / z_Σ, cos α_w = a cos α / a_w
    alpha = math.radians(20.0)
    alpha_w = math.acos(216.0 * math.cos(alpha) / 225.0)
    x_sum = (math.tan(alpha_w) - alpha_w - (math.tan(alpha) - alpha)) * 108 / (2 * math.tan(alpha))
    t = gd.select_teeth(5, m=4, a_w="standard").table
    row = t[(t.z1 == 18) & (t.z2 == 90)].iloc[0]
    assert row.a_w_mm == pytest.approx(225.0, abs=1e-9) and row.x_sum == pytest.approx(x_sum, rel=1e-12) and row.x_sum > 1
    held = gd.select_teeth(5, m=4, a_w="standard", x_sum_window=(-0.5, 1.0)).table
    assert ((held.x_sum >= -0.5 - 1e-12) & (held.x_sum <= 1.0 + 1e-12)).all()
    assert not ((held.z1 == 18) & (held.z2 == 90)).any()
