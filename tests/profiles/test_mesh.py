"""Both gears of a pair in mesh, exported: the files re-open with two closed outlines whose areas are the
generated gears' own (1e-9 relative) and whose centres sit at the origin and at (0, a_w)."""
import xml.etree.ElementTree as ET

import numpy as np
import pandas as pd
import pytest

import geardesign as gd
from geardesign.profiles.export import gear_outline, outline_area_mm2
from geardesign.profiles.mesh import pair_outlines


def _centroid(x, y):
    """Centroid of a closed polygon (shoelace moments); a gear's is its centre by symmetry."""
    cross = x[:-1] * y[1:] - x[1:] * y[:-1]
    area = cross.sum() / 2
    return np.array([((x[:-1] + x[1:]) * cross).sum(), ((y[:-1] + y[1:]) * cross).sum()]) / (6 * area)


def _areas(pair, points):
    return [outline_area_mm2(*gear_outline(p)) for p in gd.pair_profiles(pair, points)]


def test_pair_profiles_are_cut_at_the_pairs_tip_circles():
    """Tip shortening included: the profiles' tip radius is the pair's d_a/2, the thickness there s_a."""
    pair = gd.GearPair(8, 17, 26, 0.898, 0.517)
    g = pair.geometry()
    for k, p in enumerate(gd.pair_profiles(pair, points=100), start=1):
        assert np.hypot(p.x_mm[-1], p.y_mm[-1]) == pytest.approx(getattr(g, f"da{k}") / 2, rel=1e-12)
        assert p.tip_thickness_mm == pytest.approx(getattr(g, f"sa{k}"), abs=1e-9 * 8)


def _read(path):
    """name -> closed (x, y) from an exported file, read back by an independent reader."""
    if path.suffix == ".csv":
        f = pd.read_csv(path)
        return {n: (g.x_mm.to_numpy(), g.y_mm.to_numpy()) for n, g in f.groupby("outline")}
    if path.suffix == ".svg":
        out = {}
        for el in ET.parse(path).getroot().iter("{http://www.w3.org/2000/svg}path"):
            d = el.get("d")
            assert d.startswith("M ") and d.endswith(" Z")
            pts = np.array([[float(v) for v in s.split(",")] for s in d[2:-2].split()])
            pts = np.vstack([pts, pts[:1]])
            out[el.get("id")] = (pts[:, 0], -pts[:, 1])
        return out
    import ezdxf
    out = {}
    for poly in ezdxf.readfile(path).modelspace().query("LWPOLYLINE"):
        assert poly.closed
        pts = np.array([v[:2] for v in poly.get_points()])
        pts = np.vstack([pts, pts[:1]])
        out[poly.dxf.layer] = (pts[:, 0], pts[:, 1])
    return out


@pytest.mark.parametrize("suffix", [".svg", ".dxf", ".csv"])
def test_pair_export_reopens_with_both_gears_in_place(tmp_path, suffix):
    pair = gd.GearPair(8, 17, 26, 0.898, 0.517)
    path = gd.export_profiles(pair, tmp_path / f"gears{suffix}", points=60, roll_deg=3.0)
    read = _read(path)
    assert sorted(read) == ["gear1", "gear2"]
    a_w = pair.geometry().a_w
    for (name, (x, y)), area, centre in zip(sorted(read.items()), _areas(pair, 60), ([0, 0], [0, a_w])):
        assert (x[0], y[0]) == (x[-1], y[-1])
        assert outline_area_mm2(x, y) == pytest.approx(area, rel=1e-9)
        assert np.allclose(_centroid(x, y), centre, atol=1e-9 * a_w)
    with pytest.raises(gd.GearDesignError, match="exists: give --overwrite"):
        gd.export_profiles(pair, path)
    gd.export_profiles(pair, path, overwrite=True, points=60)


def test_pair_outlines_turn_together():
    """Rolling by one pitch of gear 1 brings the picture back onto itself (both gears advance one tooth)."""
    pair = gd.GearPair(3, 12, 24, 0.6, 0.36)
    (_, x1, y1), (_, x2, y2) = pair_outlines(pair, 0.0, points=40)
    (_, u1, v1), (_, u2, v2) = pair_outlines(pair, 360.0 / 12, points=40)
    for (x, y), (u, v) in (((x1, y1), (u1, v1)), ((x2, y2), (u2, v2))):
        # the same point set, shifted by one tooth's worth of points along the closed outline
        n = x.size - 1
        shift = n // (12 if x is x1 else 24)
        assert np.allclose(np.roll(u[:-1], -shift), x[:-1], atol=1e-9) or np.allclose(np.roll(u[:-1], shift), x[:-1], atol=1e-9)


def test_export_refuses_bad_input_by_name(tmp_path):
    pair = gd.GearPair(2, 20, 40)
    with pytest.raises(gd.GearDesignError, match="roll_deg"):
        gd.export_profiles(pair, tmp_path / "g.svg", roll_deg=float("nan"))
    with pytest.raises(gd.GearDesignError, match="must end in"):
        gd.export_profiles(pair, tmp_path / "g.png")
    with pytest.raises(gd.GearDesignError, match="pair must be a GearPair"):
        gd.export_profiles((2, 20, 40), tmp_path / "g.svg")
    assert not list(tmp_path.iterdir())
