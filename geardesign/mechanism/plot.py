"""Plots of an engine's torque over the cycle (matplotlib, imported on the first call)."""
from __future__ import annotations

import numpy as np

from ..errors import GearDesignError
from ..validate import require_axes, require_bool

__all__ = ["plot_torque"]

_FIELDS = ("engine", "crank_angle_deg", "torque_nm", "cylinder_torque_nm", "journal_torque_nm", "mean_torque_nm",
           "reversal_angles_deg", "unevenness")


def plot_torque(result, ax=None, journals: bool = False):
    """The crankshaft's torque over the cycle of an :class:`~geardesign.mechanism.engine.EngineTorque`: each
    cylinder's curve (thin), the resultant (thick) with its mean M_i and the angles where it reverses; with
    ``journals``, seed 004's journal torques M_z1 … M_z(n+1) instead of the cylinders. Returns the Axes.
    """
    # the result's fields, not its class: engine.py imports this module (EngineTorque.plot), not the other way
    if not all(hasattr(result, a) for a in _FIELDS):
        raise GearDesignError(f"result must be an EngineTorque (Engine.analyse()), got {type(result).__name__}")
    journals = require_bool("journals", journals)
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=(9, 4.8), constrained_layout=True)
    else:
        require_axes("ax", ax)
    phi = result.crank_angle_deg
    close = np.append(phi, result.engine.cycle_deg)       # the curve drawn round to the cycle's end

    def closed(y):
        return np.append(y, y[0])

    if journals:
        for i, m in enumerate(result.journal_torque_nm[:-1], 1):
            ax.plot(close, closed(m), lw=0.9, label=f"journal {i}: M_z{i}")
    else:
        for i, m in enumerate(result.cylinder_torque_nm, 1):
            ax.plot(close, closed(m), lw=0.8, alpha=0.8, label=f"cylinder {i} (phase {result.engine.phases[i - 1]:g}°)")
    ax.plot(close, closed(result.torque_nm), color="black", lw=2.0, label="resultant (last journal)")
    ax.axhline(result.mean_torque_nm, color="tab:red", ls="--", lw=1.2,
               label=f"mean M_i = {result.mean_torque_nm:.4g} N·m")
    ax.axhline(0.0, color="grey", lw=0.6)
    for a in result.reversal_angles_deg:
        ax.axvline(a, color="grey", ls=":", lw=0.8)
    e = result.engine
    ax.set_xlim(0, e.cycle_deg)
    ax.set_xticks(np.arange(0, e.cycle_deg + 1, 90 if e.cycle_deg > 360 else 45))
    ax.set_xlabel("crank angle φ of cylinder 1, deg")
    ax.set_ylabel("torque on the crankshaft, N·m")
    mu = f", μ = {result.unevenness:.3g}" if result.unevenness is not None else ""
    ax.set_title(f"{e.name + chr(10) if e.name else ''}{e.cylinders}-cylinder {e.diagram.strokes}-stroke, "
                 f"{e.n_rpm:g} rpm{mu}; dotted: torque reversals", fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=3, frameon=False)
    return ax
