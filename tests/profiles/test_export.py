"""Closed outlines written as CSV, SVG and DXF (geardesign.profiles.export), read back by independent
readers (numpy, xml.etree, ezdxf); the shoelace area against shapes whose area is known in closed form."""
import math

import numpy as np
import pytest

from geardesign.errors import GearDesignError
from geardesign.profiles.export import outline_area_mm2, turned, write_outlines
from geardesign.profiles.tooth import tooth_profile


def test_exports_reopen_closed_with_the_outline_area(tmp_path):
    """CSV, SVG (parsed) and DXF (read back with ezdxf) hold one closed outline whose area is the
    generated outline's to 1e-9 relative; an existing file is kept unless overwrite."""
    import xml.etree.ElementTree as ET

    import ezdxf

    from geardesign.profiles.export import gear_outline, outline_area_mm2

    p = tooth_profile(8, 17, 0.898, points=80)
    x, y = gear_outline(p)
    area = outline_area_mm2(x, y)
    # between the root and tip circles, and close to the tooth-and-space average
    assert math.pi * (17 * 4 - 10) ** 2 < area < math.pi * (17 * 4 + 15.2) ** 2
    assert (x[0], y[0]) == (x[-1], y[-1])

    p.to_csv(tmp_path / "g.csv")
    rows = np.loadtxt(tmp_path / "g.csv", delimiter=",", skiprows=1, usecols=(1, 2))
    assert outline_area_mm2(rows[:, 0], rows[:, 1]) == pytest.approx(area, rel=1e-9)

    p.to_svg(tmp_path / "g.svg")
    path = ET.parse(tmp_path / "g.svg").getroot().find("{http://www.w3.org/2000/svg}path").get("d")
    assert path.startswith("M ") and path.endswith(" Z")
    pts = np.array([[float(v) for v in s.split(",")] for s in path[2:-2].split()])
    closed = np.vstack([pts, pts[:1]])
    assert outline_area_mm2(closed[:, 0], -closed[:, 1]) == pytest.approx(area, rel=1e-9)

    p.to_dxf(tmp_path / "g.dxf")
    poly = list(ezdxf.readfile(tmp_path / "g.dxf").modelspace().query("LWPOLYLINE"))
    assert len(poly) == 1 and poly[0].closed
    dx = np.array([v[:2] for v in poly[0].get_points()])
    closed = np.vstack([dx, dx[:1]])
    assert outline_area_mm2(closed[:, 0], closed[:, 1]) == pytest.approx(area, rel=1e-9)

    with pytest.raises(GearDesignError, match="exists: give --overwrite"):
        p.to_dxf(tmp_path / "g.dxf")
    p.to_dxf(tmp_path / "g.dxf", overwrite=True)


def test_shoelace_area_of_known_shapes():
    # unit square either way round; a regular n-gon of circumradius r: n/2·r²·sin(2π/n)
    assert outline_area_mm2([0, 1, 1, 0, 0], [0, 0, 1, 1, 0]) == 1.0
    assert outline_area_mm2([0, 0, 1, 1, 0], [0, 1, 1, 0, 0]) == 1.0
    for n, r in [(3, 1.0), (6, 2.5), (1000, 40.0)]:
        t = 2 * np.pi * np.arange(n + 1) / n
        assert outline_area_mm2(r * np.cos(t), r * np.sin(t)) == pytest.approx(n / 2 * r * r * math.sin(2 * math.pi / n),
                                                                             rel=1e-12)


def test_turned_is_a_rotation():
    x, y = np.array([1.0, 0.0, 3.0]), np.array([0.0, 2.0, -4.0])
    tx, ty = turned(x, y, 0.7)
    np.testing.assert_allclose(tx + 1j * ty, (x + 1j * y) * np.exp(0.7j), rtol=0, atol=1e-15)


def test_write_outlines_keeps_names_and_points(tmp_path):
    t = np.linspace(0, 2 * np.pi, 9)
    a = ("hub", np.cos(t), np.sin(t))
    b = ("rim", 3 * np.cos(t), 3 * np.sin(t))
    path = write_outlines([a, b], tmp_path / "two.csv")
    lines = path.read_text().splitlines()
    assert lines[0] == "outline,x_mm,y_mm" and len(lines) == 1 + 2 * 9
    rows = [ln.split(",") for ln in lines[1:]]
    assert [r[0] for r in rows] == ["hub"] * 9 + ["rim"] * 9
    np.testing.assert_array_equal([float(r[1]) for r in rows[9:]], 3 * np.cos(t))   # repr: bit for bit
    with pytest.raises(GearDesignError):
        write_outlines([a], tmp_path / "two.png")
    with pytest.raises(GearDesignError, match="overwrite"):
        write_outlines([a], path)
    assert path.read_text().splitlines() == lines


# --- issue 27 (the data block) and issue 29 item 3.7 (DXF linear in the points; a size bound) ---------------------


def test_dxf_holds_every_point_once_in_one_polyline_per_outline(tmp_path):
    """The DXF is written from one array per outline (ezdxf's point-at-a-time append was quadratic); the points
    read back are the outline's, bit for bit."""
    import ezdxf

    from geardesign.profiles.export import gear_outline

    p = tooth_profile(2, 25, 0.3)
    x, y = gear_outline(p)
    p.to_dxf(tmp_path / "g.dxf")
    polys = list(ezdxf.readfile(tmp_path / "g.dxf").modelspace().query("LWPOLYLINE"))
    assert len(polys) == 1 and polys[0].closed
    pts = np.array([(v[0], v[1]) for v in polys[0].get_points("xy")])
    assert pts.shape == (x.size - 1, 2)
    assert np.array_equal(pts[:, 0], x[:-1]) and np.array_equal(pts[:, 1], y[:-1])


def test_gear_outline_is_the_tooth_turned_by_the_angular_pitch():
    from geardesign.profiles.export import gear_outline

    p = tooth_profile(3, 7, 0.2, points=20)
    xs, ys = p.outline()
    x, y = gear_outline(p)
    n = xs.size - 1
    for k in range(7):
        tx, ty = turned(xs[:-1], ys[:-1], -2 * math.pi * k / 7)
        assert np.allclose(x[k * n:(k + 1) * n], tx, rtol=0, atol=1e-12) and np.allclose(y[k * n:(k + 1) * n], ty, atol=1e-12)


@pytest.mark.parametrize("suffix", [".svg", ".csv", ".dxf"])
def test_exports_beyond_the_point_bound_are_refused_before_writing(tmp_path, suffix):
    from geardesign.profiles.export import EXPORT_POINTS_MAX
    from geardesign.profiles.ring import ring_profile

    ring = ring_profile(10, 100000, -0.4, points=8)      # issue 29: 6.4 million points
    with pytest.raises(GearDesignError, match=f"at most {EXPORT_POINTS_MAX:,}"):
        getattr(ring, "to_" + suffix[1:])(tmp_path / ("r" + suffix))
    assert list(tmp_path.iterdir()) == []
    too_many = [("a", np.zeros(EXPORT_POINTS_MAX + 1), np.zeros(EXPORT_POINTS_MAX + 1))]
    with pytest.raises(GearDesignError, match="outline points"):
        write_outlines(too_many, tmp_path / ("w" + suffix))


def test_data_block_is_written_beside_the_gear_in_the_dxf(tmp_path):
    import ezdxf

    import geardesign as gd
    from geardesign.gears.data_block import data_block, data_block_lines

    pair = gd.GearPair(3, 12, 24, 0.6, 0.36)
    table = data_block(pair, 1, 7, thickness_allowance_mm=(-0.05, -0.1))
    p1 = gd.pair_profiles(pair)[0]
    p1.to_dxf(tmp_path / "g.dxf", data_block=table)
    msp = ezdxf.readfile(tmp_path / "g.dxf").modelspace()
    texts = [e for e in msp.query("TEXT") if e.dxf.layer == "data_block"]
    assert [e.dxf.text for e in texts] == data_block_lines(table)
    right = max(v[0] for v in list(msp.query("LWPOLYLINE"))[0].get_points("xy"))
    assert all(e.dxf.insert[0] > right for e in texts)
    gd.export_profiles(pair, tmp_path / "pair.dxf", data_block=["line one", "line two"])
    assert [e.dxf.text for e in ezdxf.readfile(tmp_path / "pair.dxf").modelspace().query("TEXT")] == ["line one", "line two"]
    with pytest.raises(GearDesignError, match="DXF"):
        gd.export_profiles(pair, tmp_path / "pair.svg", data_block=["x"])
    with pytest.raises(GearDesignError, match="data_block"):
        p1.to_dxf(tmp_path / "h.dxf", data_block=42)
