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
