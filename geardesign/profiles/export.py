"""Generated gears as closed outlines, written as CSV points, SVG or DXF (ezdxf), in mm.

Every writer checks the path first, writes under a temporary name and moves the file into place
when complete (:mod:`geardesign.files`); an existing file is replaced only with ``overwrite``.
"""
from __future__ import annotations

import math

import numpy as np

from ..errors import GearDesignError
from ..files import check_output_path, write_file_atomic

__all__ = ["gear_outline", "turned", "outline_area_mm2", "write_outlines", "FORMATS", "EXPORT_POINTS_MAX",
           "require_export_size"]

FORMATS = (".svg", ".dxf", ".csv")
# SVG is a drawing: 10 significant digits put a point within 1e-10 of its size (0.1 µm on a 1 m gear) at ~60 %
# of the file a full repr takes; CSV and DXF keep every digit of a double
SVG_DIGITS = 10
# points over all outlines of one file: ~40 bytes a point in DXF, so ~80 MB; a 1000-tooth gear at 200 points a
# segment has ~1.3 million
EXPORT_POINTS_MAX = 2_000_000
# the data block's text height in a DXF, mm (ISO 3098-1 / GOST 2.304 size 3.5) and its line pitch
DATA_BLOCK_TEXT_MM = 3.5
DATA_BLOCK_LINE_PITCH = 1.6


def gear_outline(profile) -> tuple[np.ndarray, np.ndarray]:
    """The whole gear's outline (mm), closed: the tooth outline turned z times about the centre;
    the last point repeats the first. More than ``EXPORT_POINTS_MAX`` points are refused before any are made."""
    xs, ys = profile.outline()
    xs, ys = xs[:-1], ys[:-1]                 # the next tooth starts where this one ends
    require_export_size(xs.size * profile.z + 1, f"a gear of z = {profile.z} teeth at {xs.size} points a tooth")
    t = -2.0 * math.pi * np.arange(profile.z)[:, None] / profile.z
    c, s = np.cos(t), np.sin(t)
    x, y = (c * xs - s * ys).ravel(), (s * xs + c * ys).ravel()
    return np.append(x, x[0]), np.append(y, y[0])


def require_export_size(n_points: int, what: str) -> None:
    """Refuse an outline of more than ``EXPORT_POINTS_MAX`` points (the file would pass ~100 MB)."""
    if n_points > EXPORT_POINTS_MAX:
        raise GearDesignError(f"{what} makes {n_points:,} outline points; an export takes at most "
                              f"{EXPORT_POINTS_MAX:,}: lower points= (per segment) or export fewer teeth")


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


def _dxf(outlines, title, stroke_mm, data_block=None):
    import ezdxf   # only when a DXF is asked for
    from ezdxf import units

    doc = ezdxf.new()
    doc.units = units.MM
    msp = doc.modelspace()
    for name, x, y in outlines:
        doc.layers.add(name)
        # one array in, not a point at a time: ezdxf's add_lwpolyline appends each point with a copy of the
        # whole vertex array (quadratic: 12-15 s for a 25-tooth gear, issue 29 item 3.7)
        poly = msp.add_lwpolyline([], close=True, dxfattribs={"layer": name})
        zero = np.zeros(x.size - 1)
        poly.lwpoints.extend(np.column_stack([x[:-1], y[:-1], zero, zero, zero]))
    if data_block:
        _dxf_text(doc, msp, outlines, data_block)
    return lambda tmp: doc.saveas(tmp)


def _dxf_text(doc, msp, outlines, lines) -> None:
    """The data block as TEXT lines on layer ``data_block``, its top left corner one text height right of the
    outlines' bounding box, level with its top."""
    doc.layers.add("data_block")
    x_right = max(float(np.max(x)) for _, x, _ in outlines) + 4.0 * DATA_BLOCK_TEXT_MM
    y_top = max(float(np.max(y)) for _, _, y in outlines)
    for i, line in enumerate(lines):
        msp.add_text(line, height=DATA_BLOCK_TEXT_MM, dxfattribs={"layer": "data_block"}).set_placement(
            (x_right, y_top - (i + 1) * DATA_BLOCK_LINE_PITCH * DATA_BLOCK_TEXT_MM))


_WRITERS = {".csv": _csv, ".svg": _svg, ".dxf": _dxf}


def write_outlines(outlines, path, overwrite: bool = False, title: str = "", stroke_mm: float = 0.1,
                   suffixes=FORMATS, what: str = "path", data_block=None):
    """Closed outlines ``[(name, x_mm, y_mm), ...]`` into one file, its format by the suffix: CSV rows
    ``outline,x_mm,y_mm``; SVG, one closed ``<path id=name>`` each; DXF, one closed LWPOLYLINE each
    on a layer of its name. ``data_block``: text lines, or the DataFrame of
    :func:`geardesign.gears.data_block.data_block`, written into a DXF beside the outlines (layer ``data_block``).
    More than ``EXPORT_POINTS_MAX`` points in all are refused before anything is written."""
    out = check_output_path(path, overwrite=overwrite, suffixes=suffixes, what=what)
    require_export_size(sum(int(np.size(x)) for _, x, _ in outlines), "these outlines")
    if data_block is None:
        return write_file_atomic(out, _WRITERS[out.suffix.lower()](outlines, title, stroke_mm))
    if out.suffix.lower() != ".dxf":
        raise GearDesignError(f"data_block is written into a DXF drawing; {str(out)!r} is a {out.suffix} file")
    return write_file_atomic(out, _dxf(outlines, title, stroke_mm, _block_lines(data_block)))


def _block_lines(data_block) -> list:
    if hasattr(data_block, "itertuples"):
        from ..gears.data_block import data_block_lines   # here: the measuring chain loads only for a data block
        return data_block_lines(data_block)
    if not isinstance(data_block, (list, tuple)) or not all(isinstance(v, str) for v in data_block):
        raise GearDesignError("data_block must be the DataFrame of geardesign.gears.data_block.data_block or a "
                              f"list of text lines, got {type(data_block).__name__}")
    if len(data_block) > 200:
        raise GearDesignError(f"data_block has {len(data_block)} lines; a drawing's data block takes at most 200")
    return list(data_block)
