"""Generated gears as closed outlines, written as CSV points, SVG or DXF (ezdxf), in mm.

Every writer checks the path first, writes under a temporary name and moves the file into place
when complete (:mod:`geardesign.files`); an existing file is replaced only with ``overwrite``.
"""
from __future__ import annotations

import math

import numpy as np

from ..files import check_output_path, write_file_atomic

__all__ = ["gear_outline", "turned", "outline_area_mm2", "write_outlines", "FORMATS"]

FORMATS = (".svg", ".dxf", ".csv")
# SVG is a drawing: 10 significant digits put a point within 1e-10 of its size (0.1 µm on a 1 m gear) at ~60 %
# of the file a full repr takes; CSV and DXF keep every digit of a double
SVG_DIGITS = 10


def gear_outline(profile) -> tuple[np.ndarray, np.ndarray]:
    """The whole gear's outline (mm), closed: the tooth outline turned z times about the centre;
    the last point repeats the first."""
    xs, ys = profile.outline()
    xs, ys = xs[:-1], ys[:-1]                 # the next tooth starts where this one ends
    out_x, out_y = [], []
    for k in range(profile.z):
        t = -2.0 * math.pi * k / profile.z
        c, s = math.cos(t), math.sin(t)
        out_x.append(c * xs - s * ys)
        out_y.append(s * xs + c * ys)
    x, y = np.concatenate(out_x), np.concatenate(out_y)
    return np.append(x, x[0]), np.append(y, y[0])


def turned(x, y, angle_rad):
    """Points turned counter-clockwise about the origin."""
    c, s = math.cos(angle_rad), math.sin(angle_rad)
    return c * x - s * y, s * x + c * y


def outline_area_mm2(x, y) -> float:
    """Area enclosed by a closed polygon (shoelace), mm²."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    return float(abs(np.dot(x[:-1], y[1:]) - np.dot(x[1:], y[:-1])) / 2.0)


def _csv(outlines, title, stroke_mm):
    def write(tmp):
        with open(tmp, "w", encoding="utf-8") as fh:
            fh.write("outline,x_mm,y_mm\n")
            for name, x, y in outlines:
                fh.writelines(f"{name},{a!r},{b!r}\n" for a, b in zip(x.tolist(), y.tolist()))
    return write


def _svg(outlines, title, stroke_mm):
    # y up as in a drawing: SVG's y runs down, so every y is negated
    xs = np.concatenate([x for _, x, _ in outlines])
    ys = -np.concatenate([y for _, _, y in outlines])
    pad = 0.02 * float(max(np.ptp(xs), np.ptp(ys)))
    x0, y0 = float(xs.min()) - pad, float(ys.min()) - pad
    w, h = float(np.ptp(xs)) + 2 * pad, float(np.ptp(ys)) + 2 * pad
    paths = "".join(
        f'  <path id="{name}" d="M {" ".join(f"{a:.{SVG_DIGITS}g},{-b:.{SVG_DIGITS}g}" for a, b in zip(x[:-1].tolist(), y[:-1].tolist()))} Z" '
        f'fill="none" stroke="black" stroke-width="{stroke_mm:.6g}"/>\n' for name, x, y in outlines)
    text = (f'<svg xmlns="http://www.w3.org/2000/svg" width="{w:.6g}mm" height="{h:.6g}mm" '
            f'viewBox="{x0!r} {y0!r} {w!r} {h!r}">\n  <title>{title}</title>\n{paths}</svg>\n')

    def write(tmp):
        with open(tmp, "w", encoding="utf-8") as fh:
            fh.write(text)
    return write


def _dxf(outlines, title, stroke_mm):
    import ezdxf   # only when a DXF is asked for
    from ezdxf import units

    doc = ezdxf.new()
    doc.units = units.MM
    msp = doc.modelspace()
    for name, x, y in outlines:
        doc.layers.add(name)
        msp.add_lwpolyline(list(zip(x[:-1].tolist(), y[:-1].tolist())), close=True, dxfattribs={"layer": name})
    return lambda tmp: doc.saveas(tmp)


_WRITERS = {".csv": _csv, ".svg": _svg, ".dxf": _dxf}


def write_outlines(outlines, path, overwrite: bool = False, title: str = "", stroke_mm: float = 0.1,
                   suffixes=FORMATS, what: str = "path"):
    """Closed outlines ``[(name, x_mm, y_mm), ...]`` into one file, its format by the suffix: CSV rows
    ``outline,x_mm,y_mm``; SVG, one closed ``<path id=name>`` each; DXF, one closed LWPOLYLINE each
    on a layer of its name."""
    out = check_output_path(path, overwrite=overwrite, suffixes=suffixes, what=what)
    return write_file_atomic(out, _WRITERS[out.suffix.lower()](outlines, title, stroke_mm))
