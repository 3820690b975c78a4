"""The fixed-centre-distance job: a housing a_w fixes x1 + x2; the reachable range of a_w; the split.

Expected values come from the involute relations in mpmath (tests/mp_formulas.py).
"""
import mpmath as mp
import pytest

import geardesign as gd
from geardesign.cli import main
from geardesign.gears.geometry import mesh_geometry
from geardesign.gears.mesh import Mesh

from tests.mp_formulas import a_w as _a_w


def test_center_distance_needs_the_module(capsys):
    assert main(["shift", "--z1", "12", "--z2", "31", "--center-distance", "55"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "needs the module" in err[0] and "55" in err[0]
    with pytest.raises(gd.GearDesignError, match="needs the module"):
        gd.optimize_shifts(12, 31, a_w=180)


def test_unreachable_center_distance_names_the_reachable_range():
    # window x in [-1.5, 3]: the x-sum reaches 6 at most; at the low end a_w falls to a cos α
    # (x-sum -3 is below the x-sum where inv α_w = 0 for z_Σ = 43)
    hi = float(_a_w(2.5, 12, 31, 6.0))
    lo = float(mp.mpf(2.5) * 43 / 2 * mp.cos(mp.radians(20)))
    with pytest.raises(gd.GearDesignError) as info:
        gd.optimize_shifts(12, 31, a_w=250, m=2.5)
    text = str(info.value)
    assert f"({lo:.8g}, {hi:.8g}] mm" in text and "250" in text
    # 52/189: the x-sum where inv α_w = 0 lies below -3, so the low end is a_w(x-sum = -3)
    lo2 = float(_a_w(1, 52, 189, -3.0))
    with pytest.raises(gd.GearDesignError, match=rf"must be in \({lo2:.8g}, "):
        gd.optimize_shifts(52, 189, a_w=116.29567, m=1)


def test_fixed_center_distance_defaults_to_balanced_sliding_and_matches_pair():
    r = gd.optimize_shifts(12, 31, a_w=55, m=2.5)
    assert r.success and r.objective == "balanced_sliding"
    assert "balanced_sliding" in r.message and "fixed by a_w = 55 mm" in r.message
    assert float(_a_w(2.5, 12, 31, r.x1 + r.x2)) == pytest.approx(55, rel=1e-13)
    # no check is active here, so the optimum is the split of equal root sliding
    geo = mesh_geometry(Mesh(12, 31, gd.BasicRack(), True), 2.5, r.x1, r.x2)
    assert geo["sliding1_root"] == pytest.approx(geo["sliding2_root"], rel=1e-9)
    pair = gd.GearPair.from_center_distance(2.5, 12, 31, 55)
    assert (pair.x1, pair.x2) == pytest.approx((r.x1, r.x2), abs=1e-9)


@pytest.mark.parametrize("method", ["grid", "convex", "exact"])
def test_fixed_center_distance_stays_in_the_window(method):
    r = gd.optimize_shifts(17, 26, "max_eps_alpha", a_w=float(_a_w(1, 17, 26, 0.3)), m=1, method=method,
                           bounds=(-0.333, 2.354))
    assert -0.333 - 1e-12 <= r.x1 <= 2.354 + 1e-12 and -0.333 - 1e-12 <= r.x2 <= 2.354 + 1e-12
    assert r.x1 + r.x2 == pytest.approx(0.3, abs=1e-12)


def test_fixed_center_distance_picks_split():
    # a_w fixed -> x1 + x2 fixed; balanced_sliding picks the split with equal root sliding
    pair = gd.GearPair(2, 17, 34, 0.3, 0.2)
    a_w = pair.geometry().a_w
    r = gd.optimize_shifts(17, 34, "balanced_sliding", a_w=a_w, m=2)
    assert abs(r.x1 + r.x2 - 0.5) < 1e-12
    geo = gd.GearPair(2, 17, 34, r.x1, r.x2).geometry()
    assert geo.sliding1_root == pytest.approx(geo.sliding2_root, rel=1e-9)
    assert r.a_w == pytest.approx(a_w, rel=1e-12)
