"""A generated gear as a closed outline, written as CSV points, SVG or DXF (ezdxf), in mm.

Every writer checks the path first, writes under a temporary name and moves the file into place
when complete (:mod:`geardesign.files`); an existing file is replaced only with ``overwrite``.
"""
from __future__ import annotations

import math

import numpy as np

from ..files import check_output_path, write_file_atomic

__all__ = ["gear_outline", "outline_area_mm2", "write_csv", "write_svg", "write_dxf"]


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


def outline_area_mm2(x, y) -> float:
    """Area enclosed by a closed polygon (shoelace), mm²."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    return float(abs(np.dot(x[:-1], y[1:]) - np.dot(x[1:], y[:-1])) / 2.0)


def write_csv(profile, path, overwrite: bool = False):
    """The gear outline as ``x_mm,y_mm`` rows (closed: the last row repeats the first)."""
    out = check_output_path(path, overwrite=overwrite, suffixes=(".csv",), what="path")
    x, y = gear_outline(profile)

    def write(tmp):
        with open(tmp, "w", encoding="utf-8") as fh:
            fh.write("x_mm,y_mm\n")
            fh.writelines(f"{a!r},{b!r}\n" for a, b in zip(x.tolist(), y.tolist()))

    return write_file_atomic(out, write)


def write_svg(profile, path, overwrite: bool = False):
    """The gear outline as one closed SVG path in mm (y up, as in a drawing)."""
    out = check_output_path(path, overwrite=overwrite, suffixes=(".svg",), what="path")
    x, y = gear_outline(profile)
    r = float(np.max(np.hypot(x, y))) * 1.02
    points = " ".join(f"{a!r},{-b!r}" for a, b in zip(x[:-1].tolist(), y[:-1].tolist()))
    text = (f'<svg xmlns="http://www.w3.org/2000/svg" width="{2 * r:.6g}mm" height="{2 * r:.6g}mm" '
            f'viewBox="{-r!r} {-r!r} {2 * r!r} {2 * r!r}">\n'
            f'  <title>gear m = {profile.m:g} mm, z = {profile.z}, x = {profile.x:g}</title>\n'
            f'  <path d="M {points} Z" fill="none" stroke="black" stroke-width="{profile.m / 50:.6g}"/>\n'
            f'</svg>\n')

    def write(tmp):
        with open(tmp, "w", encoding="utf-8") as fh:
            fh.write(text)

    return write_file_atomic(out, write)


def write_dxf(profile, path, overwrite: bool = False):
    """The gear outline as one closed LWPOLYLINE in a DXF drawing in mm (ezdxf)."""
    import ezdxf   # only when a DXF is asked for
    from ezdxf import units

    out = check_output_path(path, overwrite=overwrite, suffixes=(".dxf",), what="path")
    x, y = gear_outline(profile)
    doc = ezdxf.new()
    doc.units = units.MM
    doc.modelspace().add_lwpolyline(list(zip(x[:-1].tolist(), y[:-1].tolist())), close=True)
    return write_file_atomic(out, lambda tmp: doc.saveas(tmp))
