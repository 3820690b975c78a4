"""Diagrams of an analysed shaft: bending moments (two planes and resultant), torque, deflection (matplotlib)."""
from __future__ import annotations

import numpy as np

from ..errors import GearDesignError

__all__ = ["plot_shaft"]


def plot_shaft(analysis, path=None, *, overwrite: bool = False):
    """Three stacked diagrams along the shaft: the bending moments My, Mz and M (N·m), the torque T (N·m)
    and the deflections wy, wz and w (µm), with the supports (triangles), the load positions (dotted) and
    the shaft's outline under the first axes. Returns the figure; with ``path`` also writes a PNG (whole or
    not at all, never over an existing file unless ``overwrite``)."""
    from .shaft_beam import ShaftAnalysis

    if not isinstance(analysis, ShaftAnalysis):
        raise GearDesignError(f"analysis must be a ShaftAnalysis, got {type(analysis).__name__}")
    import matplotlib
    if path is not None:
        matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    d = analysis.diagrams
    x = d["x_mm"].to_numpy()
    model = analysis.model
    fig, axes = plt.subplots(3, 1, figsize=(8, 8), sharex=True, constrained_layout=True)
    ax = axes[0]
    ax.plot(x, d["Mz_nm"], label="Mz (x-y plane)", color="tab:blue", lw=1)
    ax.plot(x, d["My_nm"], label="My (x-z plane)", color="tab:green", lw=1)
    ax.plot(x, d["M_nm"], label="M resultant", color="black", lw=1.8)
    ax.set_ylabel("bending moment, N·m")
    axes[1].plot(x, d["T_nm"], color="tab:red", lw=1.5)
    axes[1].set_ylabel("torque T, N·m")
    ax = axes[2]
    ax.plot(x, 1000 * d["wy_mm"], label="wy", color="tab:blue", lw=1)
    ax.plot(x, 1000 * d["wz_mm"], label="wz", color="tab:green", lw=1)
    ax.plot(x, 1000 * d["w_mm"], label="w resultant", color="black", lw=1.8)
    ax.set_ylabel("deflection, µm")
    ax.set_xlabel("x along the shaft, mm")
    for a in axes:
        a.axhline(0, color="grey", lw=0.6)
        a.grid(alpha=0.3)
        for ld in model.loads:
            a.axvline(ld.x_mm, color="grey", ls=":", lw=0.8)
        lo = a.get_ylim()[0]
        a.plot(model.supports_mm, [lo] * len(model.supports_mm), "^", color="tab:orange", ms=9, clip_on=False)
    axes[0].legend(loc="best", fontsize=8)
    axes[2].legend(loc="best", fontsize=8)
    # the shaft's outline (diameters to scale in their own axis units) as an inset strip
    ends = model.section_ends_mm
    ds = np.array([s[1] for s in model.sections])
    strip = axes[1].inset_axes([0, 1.02, 1, 0.18], sharex=axes[1])
    for x0, x1, dd in zip(ends[:-1], ends[1:], ds):
        strip.fill_between([x0, x1], -dd / 2, dd / 2, color="lightsteelblue", ec="steelblue")
    strip.set_ylim(-ds.max() * 0.6, ds.max() * 0.6)
    strip.axis("off")
    fig.suptitle(f"shaft: L = {model.length_mm:g} mm, max M = {d['M_nm'].max():.4g} N·m, "
                 f"max deflection {1000 * analysis.max_deflection_mm:.4g} µm, "
                 f"n_crit ≈ {analysis.critical_speed_rpm:.0f} rpm (Rayleigh)", fontsize=10)
    if path is not None:
        from ..files import check_output_path, write_file_atomic

        target = check_output_path(path, overwrite=overwrite)
        write_file_atomic(target, lambda tmp: fig.savefig(tmp, dpi=110, format="png"))
        plt.close(fig)
    return fig
