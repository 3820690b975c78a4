"""The result of :func:`~geardesign.shifts.optimize.optimize_shifts`, in the manner of
``scipy.optimize.OptimizeResult``."""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..gears.mesh import kind_text
from ..inline import html_view
from ..results import Result
from .looks import margin_bars

__all__ = ["ShiftResult", "Outcome"]



@dataclass
class ShiftResult(Result):
    """The optimum of :func:`optimize_shifts`, in the manner of ``scipy.optimize.OptimizeResult``.

    ``fun`` is the objective in its natural sense (x1 + x2 for ``max_x_sum``, ε_α for
    ``max_eps_alpha``, max |ϑ| for ``balanced_sliding``, the specific pressure coefficient for
    ``min_specific_pressure``, the distance in x to the nearest check boundary for ``max_margin``).
    """

    x1: float
    x2: float
    fun: float
    objective: str
    success: bool
    message: str
    method: str
    tol: float
    nit: int
    time_s: float
    margins: dict = field(default_factory=dict)
    active: list = field(default_factory=list)
    sensitivity: dict = field(default_factory=dict)
    conflict: list = field(default_factory=list)
    z1: int = 0
    z2: int = 0
    m: float = 1.0
    x_sum_fixed: float | None = None
    a_w: float = math.nan
    eps_alpha: float = math.nan
    sensitivity_sides: dict = field(default_factory=dict)
    accuracy: str = ""
    beta_deg: float = 0.0
    internal: bool = False

    @property
    def x(self) -> np.ndarray:
        return np.array([self.x1, self.x2])

    @property
    def x_sum(self) -> float:
        """x_Σ: x1 + x2, or x2 − x1 for an internal pair (what a_w fixes)."""
        return self.x2 - self.x1 if self.internal else self.x1 + self.x2

    def to_frame(self):
        """One row per check: margin, active, sensitivity (d fun / d limit; at a corner where it
        is one-sided, the value as the limit rises, and both sides in their own columns)."""
        import pandas as pd   # only when a table is asked for: importing pandas costs more than a solve

        side = {k: self.sensitivity_sides.get(k, {}) for k in self.margins}
        return pd.DataFrame({
            "check": list(self.margins),
            "margin": list(self.margins.values()),
            "active": [k in self.active for k in self.margins],
            "sensitivity": [self.sensitivity.get(k, 0.0) for k in self.margins],
            "sensitivity_raised": [side[k].get("raised", self.sensitivity.get(k, 0.0)) for k in self.margins],
            "sensitivity_lowered": [side[k].get("lowered", self.sensitivity.get(k, 0.0)) for k in self.margins],
        })

    def _sensitivity_text(self, name, value) -> str:
        sides = self.sensitivity_sides.get(name)
        if sides:
            return f"{name} {sides['raised']:+.4g} if raised / {sides['lowered']:+.4g} if lowered (corner)"
        return f"{name} {value:+.4g}"

    def _repr_html_(self) -> str:
        """Jupyter's view: the text, and every check's margin at the optimum as a bar (active ones
        outlined), in the checks' colours."""
        return html_view(repr(self), self.plot_margins, tables=(("margins", self.to_frame()),), dpi=60,
                         figsize=(6.4, 1.3 + 0.3 * len(self.margins)),
                         alt="margins at the optimum")

    def plot_margins(self, ax=None):
        """Bars of every check's margin at the optimum (≥ 0 holds; active checks outlined, their
        curves pass through the optimum). Returns the Axes."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(6.4, 1.3 + 0.3 * len(self.margins)))
        return margin_bars(ax, self.margins, self.active,
                           f"z1/z2 = {self.z1}/{self.z2}, m = {self.m:g} mm: x1 = {self.x1:.4f}, x2 = {self.x2:.4f} "
                           f"({self.objective}{'' if self.success else ', FAILED'})")

    def __repr__(self) -> str:
        lines = [
            f"     message: {self.message}",
            f"     success: {self.success}",
            f"       pairs: z1/z2 = {self.z1}/{self.z2}" + kind_text(self.beta_deg, self.internal)
            + (f", x_Σ fixed at {self.x_sum_fixed:.10g}" if self.x_sum_fixed is not None else ""),
            f"      x1, x2: {self.x1:.10g}, {self.x2:.10g}",
            f"         fun: {self.fun:.10g}  ({self.objective})",
            f"   eps_alpha: {self.eps_alpha:.6g}   a_w: {self.a_w:.6g} mm (m = {self.m:g})",
            f"      active: {', '.join(self.active) if self.active else '-'}",
            " sensitivity: " + (", ".join(self._sensitivity_text(k, v) for k, v in self.sensitivity.items()) or "-"),
            "     margins: " + ", ".join(f"{k} {v:+.4g}" for k, v in self.margins.items()),
            f"      method: {self.method}, tol {self.tol:g}, nit {self.nit}, {self.time_s * 1e3:.2f} ms",
            f"    accuracy: {self.accuracy}",
        ]
        if self.conflict:
            lines.insert(2, "    conflict: " + conflict_text(self.conflict, self.margins))
        return "\n".join(lines)



def conflict_text(conflict, margins: dict) -> str:
    """The conflict line of a failed result: the checks that cannot all hold at once, and which of them fail at
    the point shown (the others hold there: a conflict is about holding together, not each alone)."""
    names = ", ".join(conflict)
    if len(conflict) < 2:
        return names
    failing = [c for c in conflict if c in margins and margins[c] < 0]
    holding = [c for c in conflict if c in margins and margins[c] >= 0]
    if not holding:
        return f"{names} (not all at once)"
    return f"{names} (not all at once: here {', '.join(failing) or '-'} fail{'s' if len(failing) == 1 else ''}, " \
           f"{', '.join(holding)} hold{'s' if len(holding) == 1 else ''})"


@dataclass
class Outcome:
    """What a method hands back to :func:`~geardesign.shifts.optimize.optimize_shifts`, which
    evaluates the design at ``v`` and wraps it in a :class:`ShiftResult`."""

    v: np.ndarray            # the free variables: (x1, x2), or x1 on a fixed-a_w line
    nit: int
    success: bool
    message: str
    sensitivity: dict = field(default_factory=dict)
    sides: dict = field(default_factory=dict)
    conflict: list = field(default_factory=list)
    tol: float | None = None  # the tolerance achieved, when the method changes it (grid spacing)
    accuracy: str | None = None   # what the point is accurate to, when it is not what the method's table says
