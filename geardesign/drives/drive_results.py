"""The results of a drive: :class:`DriveAnalysis` (the power flow of a fully given drive, every check)
and :class:`DriveOptimum` (the ranked alternatives of :meth:`~geardesign.drives.drive.Drive.optimize`)."""
from __future__ import annotations

from dataclasses import dataclass, field

import pandas as pd

from ..inline import html_view
from ..results import Result, plain
from .diagram import plot_drive

__all__ = ["DriveAnalysis", "DriveOptimum", "SHAFTING_TABLES"]

# the tables a drive with shafting adds (Drive(shafting=...)): DriveAnalysis.table(name), to_dict's keys
SHAFTING_TABLES = ("shafts", "bearings", "sections", "seat_keys", "gear_deflections", "efficiency",
                   "mesh_misalignment")


@dataclass(frozen=True, eq=False)
class DriveAnalysis(Result):
    """The power flow of a fully specified drive, every stage's checks and every key.

    ``flow``: one row per shaft (n_rpm, torque_nm, power_kw); ``checks``: one row per check of the
    whole drive (item, check, margin, ok); ``keys``: one row per keyed hub; ``stages``: per stage
    its result (GearPair and its checks, ChainDesign and the chosen row, or the given unit) and
    ``flow``, the :class:`~geardesign.drives.stage_kinds.StageFlow` through it (speed and torque in
    and out: what a load-based check of the stage reads), and for a gear stage with a material
    ``strength``, its :class:`~geardesign.gears.strength.StrengthResult` at that flow (``to_dict`` gives it
    with each stage's summary);
    ``min_margin`` and ``limiting``: the smallest margin of the drive and its item and check.
    """

    success: bool
    message: str
    flow: pd.DataFrame
    checks: pd.DataFrame
    keys: pd.DataFrame
    stages: tuple
    min_margin: float
    limiting: str
    total_ratio: float
    size_mm2: float
    mass_kg: float
    drive: object = field(repr=False, default=None)
    key_results: tuple = field(repr=False, default=())
    overall_efficiency: float = float("nan")
    heat_kw: float = float("nan")
    shafting: dict | None = field(repr=False, default=None)

    _table_fields = ("flow", "checks", "keys")

    def to_dict(self) -> dict:
        out = {"status": self.status, "success": self.success, "message": self.message,
               "total_ratio": self.total_ratio, "min_margin": self.min_margin, "limiting": self.limiting,
               "size_mm2": self.size_mm2, "mass_kg": self.mass_kg, "overall_efficiency": self.overall_efficiency,
               "heat_kw": self.heat_kw, "flow": self.flow, "checks": self.checks, "keys": self.keys,
               "stages": [_stage_dict(s) for s in self.stages]}
        if self.shafting is not None:
            out.update({k: self.shafting[k] for k in SHAFTING_TABLES if self.shafting.get(k) is not None})
        return plain(out)

    def table(self, name: str) -> pd.DataFrame:
        """One of the shafting's tables by name (:data:`SHAFTING_TABLES`: shafts, bearings, sections, seat_keys,
        gear_deflections, efficiency, mesh_misalignment); a drive without shafting has none."""
        from ..errors import GearDesignError

        if name not in SHAFTING_TABLES:
            raise GearDesignError(f"table must be one of {', '.join(SHAFTING_TABLES)}, got {name!r}")
        if self.shafting is None or self.shafting.get(name) is None:
            raise GearDesignError(f"this drive has no {name} table (give Drive(shafting=Shafting(...)))")
        return self.shafting[name]

    def __repr__(self) -> str:
        with pd.option_context("display.width", 160, "display.max_columns", 20):
            flow = self.flow.to_string(index=False, float_format=lambda v: f"{v:.5g}")
        text = f"DriveAnalysis: {self.message}\n{flow}"
        if self.shafting is not None:
            text += (f"\noverall efficiency {self.overall_efficiency:.5f}, heat to dissipate "
                     f"{1000 * self.heat_kw:.4g} W")
            for _, r in self.shafting["shafts"].iterrows():
                text += (f"\n  shaft {r['shaft']} ({r['layout']}): d_bearing {r['d_bearing_mm']:g} mm, bearings "
                         f"{r['bearings']}, least DIN 743 safety {r['least_safety']:.3g}")
        return text

    def _repr_html_(self) -> str:
        """Jupyter's view: the text, and the drive's diagram inline."""
        return html_view(repr(self), lambda ax: self.plot(ax=ax), tables=(("checks", self.to_frame()),),
                         figsize=(2.2 + 2.4 * len(self.stages), 4.0),
                         alt="drive diagram")

    def plot(self, ax=None):
        """The drive's diagram (input, stages, shafts with n and T, keys): a matplotlib Axes."""
        return plot_drive(self, ax=ax)

    def plot_layout(self, ax=None):
        """A drive with shafting: its shafts, gears and bearings seen from above, to scale (a matplotlib Axes)."""
        from .diagram import plot_layout

        return plot_layout(self, ax=ax)


def _stage_dict(stage: dict) -> dict:
    """A stage's summary; a gear stage with a material also its ISO 6336 result (material with σ_Hlim, σ_Flim,
    S_H, S_F, σ_H, σ_F, the governing check, the factor table: :meth:`StrengthResult.to_dict`) and, with a spectrum,
    its ISO 6336-6 service life (damage sums, lives, safety factors for the required life, the bins:
    :meth:`LifeResult.to_dict`)."""
    out = dict(stage["summary"])
    if stage.get("strength") is not None:
        out["strength"] = stage["strength"].to_dict()
    if stage.get("life") is not None:
        out["life"] = stage["life"].to_dict()
    return out


@dataclass(frozen=True, eq=False)
class DriveOptimum(Result):
    """Result of :meth:`Drive.optimize`: the ranked alternatives and the best design analysed.

    ``table``: feasible designs best first (``reason`` says why each loses to the one above it),
    then the closest failing ones (``reason`` names the stage and checks that fail); ``best``: the
    :class:`DriveAnalysis` of rank 1, re-evaluated by the standalone functions; ``conflict``: when
    nothing passes, the stage checks that fail in the closest design.
    """

    success: bool
    message: str
    objective: str
    total_ratio: float
    ratio_tol: float
    table: pd.DataFrame
    best: DriveAnalysis | None
    conflict: tuple
    n_combinations: int
    n_candidates: int
    n_shift_solves: int
    time_s: float

    _table_fields = ("table",)

    def to_dict(self) -> dict:
        out = {f: getattr(self, f) for f in ("success", "message", "objective", "total_ratio", "ratio_tol",
                                             "conflict", "n_combinations", "n_candidates", "n_shift_solves",
                                             "time_s")}
        records = [{k: (None if v is pd.NA else v) for k, v in r.items()} for r in self.table.to_dict("records")]
        out.update(status=self.status, table=records, best=None if self.best is None else self.best.to_dict())
        return plain(out)

    def _repr_html_(self) -> str:
        """Jupyter's view: the text, and the best design's diagram inline (when there is one)."""
        draw = None if self.best is None else (lambda ax: self.best.plot(ax=ax))
        return html_view(repr(self), draw, figsize=(2.2 + 2.4 * len(self.best.stages if self.best else ()), 4.0),
                         alt="drive diagram")

    def __repr__(self) -> str:
        cols = [c for c in self.table.columns if c not in ("reason",)][:14]
        with pd.option_context("display.width", 180, "display.max_columns", 20):
            body = self.table[cols].head(8).to_string(index=False, float_format=lambda v: f"{v:.5g}")
        return (f"DriveOptimum({self.objective}, u = {self.total_ratio:g} ± {100 * self.ratio_tol:g} %): {self.message}\n"
                f"  {self.n_combinations} ratio combinations, {self.n_candidates} designs, {self.n_shift_solves} shift "
                f"solves, {self.time_s:.3f} s\n{body}")
