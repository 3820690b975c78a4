"""A drive: an input (a motor, or a power or output torque at a speed), stages linked by shafts,
the power flow through them, and the ratio split optimised across the stages.

Power flow (shaft k is the output of stage k; shaft 0 the input):
n_k = n_{k−1}/u_k, T_k = T_{k−1}·u_k·η_k, P_k = T_k·ω_k, T_0 = P/ω_0 (P in W, ω in rad/s);
with an output torque instead of a power, T_k = T_N/∏_{j>k}(u_j·η_j).

:meth:`Drive.optimize` chooses the ratio split and every free variable together: it enumerates the
tooth pairs of every stage whose product meets the total ratio within its tolerance, times the
chain catalog rows, evaluates every non-gear check of all of them in vectorised passes (chains
with one load per design, keys by their capacity, bought units by their rated torque), then walks
the gear tooth pairs best bound first, solving the shifts of a pair only while its bound can still
reach the best designs found (branch and bound; the bound replaces each gear by its base circles,
below any tip circle, and leaves its margins unknown). Every limit on the work is a named constant.
"""
from __future__ import annotations

import heapq
import math
import time
from dataclasses import dataclass, field, replace
from functools import lru_cache

import numpy as np
import pandas as pd

from ..errors import GearDesignError
from ..results import Result, plain
from ..validate import one_number, require_range
from .stages import ChainStage, GearStage, GivenStage, Shaft, disc_mass_kg, stage_area_mm2

__all__ = ["Drive", "DriveAnalysis", "DriveOptimum", "power_flow", "OBJECTIVES", "STAGES_MAX", "COMBINATIONS_MAX",
           "CANDIDATES_MAX", "TOP_MAX", "TOTAL_RATIO_RANGE", "RATIO_TOL_RANGE", "SPEED_RANGE_RPM", "MARGIN_TOL"]

OBJECTIVES = ("min_size", "min_mass", "max_margin")
STAGES_MAX = 6                    # stages in one drive
COMBINATIONS_MAX = 200_000        # ratio combinations (one tooth pair per stage) inside the ratio window
CANDIDATES_MAX = 2_000_000        # designs evaluated at once: combinations × chain catalog rows
TOP_MAX = 1000                    # alternatives listed
TOTAL_RATIO_RANGE = (1e-3, 1e5)
RATIO_TOL_RANGE = (0.0, 0.5)
SPEED_RANGE_RPM = (0.1, 100_000.0)
POWER_RANGE_KW = (1e-6, 1e5)
TORQUE_RANGE_NM = (1e-3, 1e9)
MARGIN_TOL = 1e-9                 # the exact shift solver holds its checks to 1e-9: such margins hold
_SHIFT_CACHE = 4096               # solved tooth pairs kept between calls (each ~2-6 ms to solve)
_INFEASIBLE_SHOWN = 5             # closest failing designs listed after the feasible ones


def power_flow(n_in_rpm, ratios, efficiencies, power_kw=None, output_torque_nm=None):
    """Speeds [rpm], torques [N·m] and powers [kW] of every shaft: arrays (..., N+1) for
    ``ratios`` (..., N) and ``efficiencies`` (N,).

    n_k = n_{k−1}/u_k, T_k = T_{k−1}·u_k·η_k; T_0 = P/ω_0, ω = 2πn/60 (or T_N given).

    Seed 002: 4 kW at 1500 rpm through the gear motor u = 12.5, η = 0.87:

    >>> n, T, P = power_flow(1500, [12.5], [0.87], power_kw=4)
    >>> [round(float(v), 3) for v in (n[1], T[0], T[1], P[1])]
    [120.0, 25.465, 276.93, 3.48]
    """
    u = np.asarray(ratios, dtype=float)
    eta = np.asarray(efficiencies, dtype=float)
    ones = np.ones(u.shape[:-1] + (1,))
    n = float(n_in_rpm) / np.concatenate([ones, np.cumprod(u, axis=-1)], axis=-1)
    gain = np.concatenate([ones, np.cumprod(u * eta, axis=-1)], axis=-1)
    omega = 2.0 * np.pi * n / 60.0
    if power_kw is not None:
        torque = 1000.0 * power_kw / omega[..., :1] * gain
    else:
        torque = output_torque_nm * gain / gain[..., -1:]
    return n, torque, torque * omega / 1000.0


# ---------------------------------------------------------------------------------------------- gears

@lru_cache(maxsize=_SHIFT_CACHE)
def _shift_solution(m, z1, z2, checks_key, beta_deg, face_width_mm, objective) -> dict:
    """The shifts of one tooth pair by optimize_shifts (exact), with the pair's geometry and margins."""
    from ..gears.pair import GearPair
    from ..shifts.optimize import optimize_shifts

    checks = dict(checks_key) or None
    try:
        r = optimize_shifts(int(z1), int(z2), objective, checks, "exact", m=m, beta_deg=beta_deg, face_width=face_width_mm)
    except GearDesignError as exc:
        return dict(feasible=False, reason=str(exc), margins={})
    if not (r.success and not r.conflict):
        why = "conflict: " + ", ".join(r.conflict) if r.conflict else r.message
        return dict(feasible=False, reason=why, margins=dict(r.margins))
    geo = GearPair(m, int(z1), int(z2), r.x1, r.x2, beta_deg=beta_deg, face_width=face_width_mm).geometry()
    return dict(feasible=True, reason="", x1=r.x1, x2=r.x2, margins=dict(r.margins), a_w=geo.a_w, da1=geo.da1,
                da2=geo.da2)


def _gear_solution(stage: GearStage, z1: int, z2: int, objective: str) -> dict:
    """Shifts, geometry and margins of one tooth pair of a gear stage (fixed or solved shifts)."""
    if not stage.free_shifts:
        pair = stage.fixed_pair()
        table = pair.checks(**{"jamming": False, **(stage.checks or {})})
        geo = pair.geometry()
        margins = dict(zip(table["check"], table["margin"].astype(float)))
        failing = [k for k, v in margins.items() if v < -MARGIN_TOL]
        return dict(feasible=not failing, reason=("fails " + ", ".join(failing)) if failing else "", x1=pair.x1,
                    x2=pair.x2, margins=margins, a_w=geo.a_w, da1=geo.da1, da2=geo.da2)
    shift_objective = stage.shift_objective or ("max_margin" if objective == "max_margin" else "max_x_sum")
    return _shift_solution(stage.m, int(z1), int(z2), stage.checks_key(), stage.beta_deg, stage.face_width_mm,
                           shift_objective)


def _gear_bounds(stage: GearStage, z1, z2):
    """Lower bounds of a gear stage's size [mm²] and mass [kg] whatever its shifts: base circles
    (below every tip circle) at the centre distance a·cos α_t (below every operating one)."""
    alpha_t = math.atan(math.tan(math.radians(20.0)) / math.cos(math.radians(stage.beta_deg)))
    scale = stage.m / math.cos(math.radians(stage.beta_deg))
    db1, db2 = scale * z1 * math.cos(alpha_t), scale * z2 * math.cos(alpha_t)
    a_cos = 0.5 * scale * (z1 + z2) * math.cos(alpha_t)
    return stage_area_mm2(a_cos, db1, db2), disc_mass_kg(db1, stage.width_mm) + disc_mass_kg(db2, stage.width_mm)


def _min_margin(margins: dict):
    """(smallest margin, its check) of a {check: margin} dict; margins within MARGIN_TOL of 0 are 0."""
    if not margins:
        return math.inf, ""
    name = min(margins, key=lambda k: (margins[k] if np.isfinite(margins[k]) else -math.inf))
    v = float(margins[name])
    return (0.0 if abs(v) <= MARGIN_TOL else v), name


# ---------------------------------------------------------------------------------------------- chains

def _chain_check_names(stage: ChainStage) -> list:
    """The margins that decide a chain (as chain.design's evaluate): the method's, the centre distance's."""
    cd = ["margin_center_distance"] if stage.center_distance_mm is not None else []
    if stage.method == "hinge_pressure":
        return ["margin_pressure", "margin_safety", "margin_speed", "margin_impacts"] + cd
    return ["margin_power"] + cd + (["margin_safety"] if stage.allowable_safety_factor is not None else [])


def _chain_batch(stage: ChainStage, rows, z1, z2, n1_rpm, torque_nm) -> dict:
    """Every margin, size and mass of chain candidates that each carry their own load."""
    from ..catalogs.tables import catalog_dir
    from .chain.candidates import Candidates, evaluate, reference_tables, with_loads

    chains = stage.table()
    c = Candidates(chains, rows, z1, z2)
    checks, _ = evaluate(c, with_loads(stage._inputs, n1_rpm, torque_nm), reference_tables(catalog_dir()), summary=False)
    out = {k[len("margin_"):]: np.asarray(c[k], dtype=float) for k in checks}
    de1, de2 = c["sprocket1_tip_diameter_mm"], c["sprocket2_tip_diameter_mm"]
    width = c["width_mm"]
    size = stage_area_mm2(c["center_distance_mm"], de1, de2)
    mass = disc_mass_kg(de1, width) + disc_mass_kg(de2, width) + c["chain_mass_kg"]
    return dict(margins=out, size=size, mass=mass, designation=chains.take("designation", rows),
                strands=np.asarray(c["strands"]), pitch=np.asarray(c["pitch_mm"]), links=np.asarray(c["links"]),
                a=np.asarray(c["center_distance_mm"]))


# ---------------------------------------------------------------------------------------------- results

@dataclass(frozen=True, eq=False)
class DriveAnalysis(Result):
    """The power flow of a fully specified drive, every stage's checks and every key.

    ``flow``: one row per shaft (n_rpm, torque_nm, power_kw); ``checks``: one row per check of the
    whole drive (item, check, margin, ok); ``keys``: one row per keyed hub; ``stages``: per stage
    its result (GearPair and its checks, ChainDesign and the chosen row, or the given unit);
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

    _table_fields = ("flow", "checks", "keys")

    def to_dict(self) -> dict:
        return plain({"status": self.status, "success": self.success, "message": self.message,
                      "total_ratio": self.total_ratio, "min_margin": self.min_margin, "limiting": self.limiting,
                      "size_mm2": self.size_mm2, "mass_kg": self.mass_kg, "flow": self.flow, "checks": self.checks,
                      "keys": self.keys, "stages": [s["summary"] for s in self.stages]})

    def __repr__(self) -> str:
        with pd.option_context("display.width", 160, "display.max_columns", 20):
            flow = self.flow.to_string(index=False, float_format=lambda v: f"{v:.5g}")
        return f"DriveAnalysis: {self.message}\n{flow}"

    def _repr_html_(self) -> str:
        """Jupyter's view: the text, and the drive's diagram inline."""
        from ..inline import html_view
        return html_view(repr(self), lambda ax: self.plot(ax=ax), figsize=(2.2 + 2.4 * len(self.stages), 4.0),
                         alt="drive diagram")

    def plot(self, ax=None):
        """The drive's diagram (input, stages, shafts with n and T, keys): a matplotlib Axes."""
        from .diagram import plot_drive
        return plot_drive(self, ax=ax)


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
        from ..inline import html_view
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


# ---------------------------------------------------------------------------------------------- drive

@dataclass(frozen=True)
class Drive:
    """A drive: input speed ``n_in_rpm`` with ``power_kw`` (input power) or ``output_torque_nm``
    (torque on the last shaft), ``stages`` in the order of the power flow, keyed hubs ``shafts``.

    ``motor`` (a :class:`~geardesign.drives.motor.MotorSelection` or its ``.motor`` row) sets the
    input speed to its rated speed and, when no load is given, the power to its rated power; the
    motor then has a check ``power``: 1 − P_in/P_rated (when the load is given, not taken from it).
    """

    stages: tuple
    n_in_rpm: float | None = None
    power_kw: float | None = None
    output_torque_nm: float | None = None
    shafts: tuple = ()
    motor: object = None
    _load_from_motor: bool = field(default=False, init=False, repr=False, compare=False)

    def __post_init__(self):
        stages = tuple(self.stages) if isinstance(self.stages, (list, tuple)) else None
        if not stages or len(stages) > STAGES_MAX:
            raise GearDesignError(f"stages must list 1 to {STAGES_MAX} stages, got {self.stages!r}")
        for s in stages:
            if not isinstance(s, (GivenStage, GearStage, ChainStage)):
                raise GearDesignError(f"stages must be GivenStage, GearStage or ChainStage, got {type(s).__name__}")
        names = [s.name for s in stages]
        if len(set(names)) != len(names):
            raise GearDesignError(f"stage names must differ (they name the checks), got {names}")
        object.__setattr__(self, "stages", stages)
        motor = self.motor
        if motor is not None:
            motor = getattr(motor, "motor", motor)
            if motor is None or not all(k in motor for k in ("power_kw", "rated_speed_rpm", "designation")):
                raise GearDesignError("motor must be a MotorSelection (gd.motor.select) that found a motor, or its row")
            object.__setattr__(self, "motor", motor)
            if self.n_in_rpm is None:
                object.__setattr__(self, "n_in_rpm", float(motor["rated_speed_rpm"]))
            if self.power_kw is None and self.output_torque_nm is None:
                object.__setattr__(self, "power_kw", float(motor["power_kw"]))
                object.__setattr__(self, "_load_from_motor", True)
        if self.n_in_rpm is None:
            raise GearDesignError("n_in_rpm is required (or a motor)")
        object.__setattr__(self, "n_in_rpm", one_number("n_in_rpm", require_range(
            "n_in_rpm", self.n_in_rpm, *SPEED_RANGE_RPM, unit="rpm")))
        if (self.power_kw is None) == (self.output_torque_nm is None):
            raise GearDesignError("give exactly one of power_kw (input power) or output_torque_nm (torque on the output shaft)")
        if self.power_kw is not None:
            object.__setattr__(self, "power_kw", one_number("power_kw", require_range(
                "power_kw", self.power_kw, *POWER_RANGE_KW, unit="kW")))
        else:
            object.__setattr__(self, "output_torque_nm", one_number("output_torque_nm", require_range(
                "output_torque_nm", self.output_torque_nm, *TORQUE_RANGE_NM, unit="N·m")))
        shafts = tuple(self.shafts or ())
        for s in shafts:
            if not isinstance(s, Shaft):
                raise GearDesignError(f"shafts must be Shaft objects, got {type(s).__name__}")
            if s.at > len(stages):
                raise GearDesignError(f"shaft '{s.name}': at = {s.at} must be in [0, {len(stages)}] "
                                      f"(0 the input shaft, k the output shaft of stage k)")
        object.__setattr__(self, "shafts", shafts)

    # -- helpers
    def _efficiencies(self) -> np.ndarray:
        return np.array([s.efficiency for s in self.stages])

    def _flow(self, ratios):
        return power_flow(self.n_in_rpm, ratios, self._efficiencies(), self.power_kw, self.output_torque_nm)

    def _motor_margins(self, power_in_kw) -> dict:
        if self.motor is None or self._load_from_motor:   # its own rated power: nothing to check
            return {}
        return {"power": 1.0 - np.asarray(power_in_kw, dtype=float) / float(self.motor["power_kw"])}

    @staticmethod
    def _fixed_ratio(stage) -> float:
        if isinstance(stage, GivenStage):
            return stage.ratio
        if stage.z1 is None or stage.z2 is None:
            raise GearDesignError(f"analyse() needs every ratio: stage '{stage.name}' has free tooth counts "
                                  f"(give z1 and z2, or use optimize())")
        return stage.z2 / stage.z1

    # -- analyse
    def analyse(self, objective: str = "min_size") -> DriveAnalysis:
        """The power flow, every stage's checks and margins, every key, the smallest margin.

        Every stage needs its tooth counts; free gear shifts are solved (``objective`` only picks
        the shift rule, as in :meth:`optimize`), a free chain row is chosen by chain.design.
        """
        ratios = np.array([self._fixed_ratio(s) for s in self.stages])
        n, T, P = (a.ravel() for a in self._flow(ratios))
        rows = [("motor", name, float(v)) for name, v in self._motor_margins(P[0]).items()]
        stages_out = []
        size = mass = 0.0
        for i, st in enumerate(self.stages):
            if isinstance(st, GivenStage):
                out = _given_stage(st, T[i + 1])
            elif isinstance(st, GearStage):
                out = _gear_stage(st, objective)
            else:
                out = _chain_stage(st, T[i], n[i])
            rows += [(st.name, k, v) for k, v in out.pop("margins").items()]
            size += out.pop("size", 0.0)
            mass += out.pop("mass", 0.0)
            stages_out.append(out)
        key_rows, key_results = [], []
        for sh in self.shafts:
            sel = sh.select(float(T[sh.at]))
            key_results.append(sel)
            key_rows.append(dict(name=sh.name, at=sh.at, d_mm=sh.d_mm, hub_length_mm=sh.hub_length_mm,
                                 torque_nm=float(T[sh.at]), b_mm=sel.b_mm, h_mm=sel.h_mm, length_mm=sel.length_mm,
                                 n_keys=sel.n_keys, crush_mpa=sel.crush_mpa, shear_mpa=sel.shear_mpa,
                                 margin_crush=sel.margin_crush, margin_shear=sel.margin_shear, feasible=sel.feasible,
                                 message=sel.message))
            rows += [(f"key '{sh.name}'", "crushing", sel.margin_crush), (f"key '{sh.name}'", "shear", sel.margin_shear)]
        checks = _checks_table(rows)
        flow = pd.DataFrame({"shaft": np.arange(len(n)),
                             "after": ["input" if self.motor is None else f"motor {self.motor['designation']}"]
                             + [s.name for s in self.stages],
                             "n_rpm": n, "torque_nm": T, "power_kw": P})
        keys = pd.DataFrame(key_rows, columns=["name", "at", "d_mm", "hub_length_mm", "torque_nm", "b_mm", "h_mm",
                                               "length_mm", "n_keys", "crush_mpa", "shear_mpa", "margin_crush",
                                               "margin_shear", "feasible", "message"])
        mm, lim = _smallest(checks)
        ok = bool(checks["ok"].all())
        failing = checks[~checks["ok"]]
        msg = (f"u = {float(np.prod(ratios)):.6g}, output {n[-1]:.6g} rpm, {T[-1]:.6g} N·m; "
               + (f"every check holds; smallest margin {mm:+.4f} ({lim})" if ok else
                  "fails " + ", ".join(f"{a}: {b} ({c:+.3f})" for a, b, c in failing[["item", "check", "margin"]]
                                       .itertuples(index=False))))
        return DriveAnalysis(success=ok, message=msg, flow=flow, checks=checks, keys=keys, stages=tuple(stages_out),
                             min_margin=mm, limiting=lim, total_ratio=float(np.prod(ratios)), size_mm2=size,
                             mass_kg=mass, drive=self, key_results=tuple(key_results))

    # -- optimize
    def optimize(self, total_ratio, ratio_tol=0.03, objective="min_size", top=10, progress=None) -> DriveOptimum:
        """The ratio split and every free variable chosen together for ``objective``.

        ``min_size``: smallest sum of the stages' side-view envelopes (a + (D1 + D2)/2)·max(D1, D2)
        (gears at their tip circles and operating centre distance, chains at their sprocket tip
        circles and centre distance; bought units are fixed and left out); ``min_mass``: smallest
        mass of gear blanks and sprockets as steel discs of their tip diameters and face widths,
        plus the chain (mass per metre × length); ``max_margin``: the largest smallest margin of
        every check of the drive. Ties go to the smaller ratio error, then the smaller size.
        The total ratio must hold within ``ratio_tol`` (relative). ``top`` alternatives are listed.
        ``progress(done, total)`` is called after each group of designs sharing their gear tooth pairs
        (the walk may stop well before ``total``).
        """
        t0 = time.perf_counter()
        U = one_number("total_ratio", require_range("total_ratio", total_ratio, *TOTAL_RATIO_RANGE))
        tol = one_number("ratio_tol", require_range("ratio_tol", ratio_tol, *RATIO_TOL_RANGE))
        if objective not in OBJECTIVES:
            raise GearDesignError(f"objective must be one of {', '.join(OBJECTIVES)}, got {objective!r}")
        top = int(require_range("top", top, 1, TOP_MAX))
        search = _Search(self, U, tol, objective, top, t0)
        why = search.enumerate()                  # 1-3: options per stage, ratio combinations, chain rows
        if why:
            return search.no_split(why)
        search.non_gear_checks()                  # 4: every chain, key, bought unit and motor check at once
        search.branch_and_bound(progress)         # 5: the gears, best bound first
        return search.result()                    # 6: ranked table, the closest failing designs, the best

    def _ratio_span(self, st):
        if isinstance(st, GivenStage):
            return (st.ratio, st.ratio)
        if st.z1 is not None and st.z2 is not None:
            return (st.z2 / st.z1, st.z2 / st.z1)
        return st.ratio_range


# ---------------------------------------------------------------------------------------------- analyse

def _given_stage(st: GivenStage, torque_out_nm) -> dict:
    """A bought unit's margins (its rated output torque) and summary."""
    return dict(stage=st, margins={k: float(v) for k, v in st.margins(torque_out_nm).items()},
                summary=dict(name=st.name, kind="given", ratio=st.ratio, efficiency=st.efficiency))


def _gear_stage(st: GearStage, objective: str) -> dict:
    """A gear stage at its tooth counts (free shifts solved): its checks, size and mass."""
    from ..gears.pair import GearPair

    sol = _gear_solution(st, st.z1, st.z2, objective)
    if not sol["feasible"] and "x1" not in sol:
        raise GearDesignError(f"stage '{st.name}': z1/z2 = {st.z1}/{st.z2} has no feasible shifts ({sol['reason']})")
    pair = GearPair(st.m, st.z1, st.z2, sol["x1"], sol["x2"], beta_deg=st.beta_deg, face_width=st.face_width_mm)
    table = pair.checks(**{"jamming": False, **(st.checks or {})})
    geo = pair.geometry()
    return dict(stage=st, pair=pair, checks=table, margins=dict(zip(table["check"], table["margin"].astype(float))),
                size=float(stage_area_mm2(geo.a_w, geo.da1, geo.da2)),
                mass=float(disc_mass_kg(geo.da1, st.width_mm) + disc_mass_kg(geo.da2, st.width_mm)),
                summary=dict(name=st.name, kind="gear", m=st.m, z1=st.z1, z2=st.z2, x1=pair.x1, x2=pair.x2,
                             a_w_mm=geo.a_w, da1_mm=geo.da1, da2_mm=geo.da2, ratio=st.z2 / st.z1,
                             efficiency=st.efficiency))


def _chain_stage(st: ChainStage, torque_nm, n1_rpm) -> dict:
    """A chain stage by chain.design with the flow's load (its designation, when fixed, picks the row)."""
    from .chain import design as chain_design

    res = chain_design(torque_nm=float(torque_nm), n1_rpm=float(n1_rpm), ratio=st.z2 / st.z1, z1=st.z1,
                       **st.design_kwargs())
    cand = res.candidates
    if st.designation is not None:
        cand = cand[cand["designation"] == st.designation]
    row = cand.iloc[0]   # ranked: the best feasible, or the closest when none passes
    de1, de2, w = row["sprocket1_tip_diameter_mm"], row["sprocket2_tip_diameter_mm"], row["width_mm"]
    return dict(stage=st, design=res, row=row, margins={k[len("margin_"):]: float(row[k]) for k in _chain_check_names(st)},
                size=float(stage_area_mm2(row["center_distance_mm"], de1, de2)),
                mass=float(disc_mass_kg(de1, w) + disc_mass_kg(de2, w) + row["chain_mass_kg"]),
                summary=dict(name=st.name, kind="chain", designation=row["designation"], strands=int(row["strands"]),
                             pitch_mm=float(row["pitch_mm"]), z1=st.z1, z2=st.z2, links=int(row["links"]),
                             center_distance_mm=float(row["center_distance_mm"]), ratio=st.z2 / st.z1,
                             efficiency=st.efficiency))


def _checks_table(rows) -> pd.DataFrame:
    """item, check, margin, ok; margins within MARGIN_TOL of zero are zero."""
    checks = pd.DataFrame(rows, columns=["item", "check", "margin"])
    checks["margin"] = checks["margin"].astype(float)
    checks.loc[checks["margin"].abs() <= MARGIN_TOL, "margin"] = 0.0
    checks["ok"] = checks["margin"] >= 0
    return checks


def _smallest(checks: pd.DataFrame):
    """(smallest margin, "item: check") of a checks table (NaN counts as −inf)."""
    if checks.empty:
        return math.inf, ""
    j = int(np.argmin(checks["margin"].fillna(-np.inf).to_numpy()))
    return float(checks["margin"].iloc[j]), f"{checks['item'].iloc[j]}: {checks['check'].iloc[j]}"


class _Search:
    """One :meth:`Drive.optimize` call: the designs (one option per stage × chain rows) as index
    arrays, their flow and non-gear margins, and what the branch and bound has evaluated (``ex``)."""

    def __init__(self, drive: Drive, U: float, tol: float, objective: str, top: int, t0: float):
        self.drive, self.stages, self.U, self.tol = drive, drive.stages, U, tol
        self.objective, self.top, self.t0 = objective, top, t0
        self.u_lo, self.u_hi = U * (1 - tol), U * (1 + tol)
        self.gear_k = [k for k, st in enumerate(self.stages) if isinstance(st, GearStage)]
        self.n_solves = 0

    # -- 1-3: the designs
    def enumerate(self) -> str:
        """Options, combinations and chain rows; the reason when there is no design, else ''."""
        why = self._stage_options() or self._combinations()
        if why:
            return why
        self._chain_rows()
        self.ratios = np.column_stack([self.options[k]["ratio"][self.idx[:, k]] for k in range(len(self.stages))])
        self.n, self.T, self.P = self.drive._flow(self.ratios)
        self.err = np.abs(np.prod(self.ratios, axis=1) - self.U) / self.U
        return ""

    def _stage_options(self) -> str:
        """Each stage's options (tooth pairs) inside the window its neighbours leave it."""
        stages, N = self.stages, len(self.stages)
        span = [self.drive._ratio_span(s) for s in stages]
        self.options = []
        for k, st in enumerate(stages):
            lo_rest = math.prod(span[j][0] for j in range(N) if j != k)
            hi_rest = math.prod(span[j][1] for j in range(N) if j != k)
            w_lo, w_hi = self.u_lo / hi_rest, self.u_hi / lo_rest
            if isinstance(st, GivenStage):
                z1 = z2 = np.zeros(1, dtype=np.int64)
                ratio = np.array([st.ratio])
                ratio = ratio if w_lo * (1 - 1e-12) <= st.ratio <= w_hi * (1 + 1e-12) else ratio[:0]
            else:
                z1, z2 = st.pairs(w_lo, w_hi)
                ratio = z2 / z1
            if ratio.size == 0:
                reach = (math.prod(a for a, _ in span), math.prod(b for _, b in span))
                return (f"stage '{st.name}' has no option with a ratio in [{w_lo:.4g}, {w_hi:.4g}], the window "
                        f"the other stages leave it for u = {self.U:g} ± {100 * self.tol:g} % (the stages' ratio "
                        f"ranges reach u in [{reach[0]:.4g}, {reach[1]:.4g}])")
            self.options.append(dict(z1=z1, z2=z2, ratio=ratio))
        return ""

    def _combinations(self) -> str:
        """One option per stage, the product inside the ratio window (the remaining stages' range
        bounds each partial product)."""
        options, N = self.options, len(self.options)
        idx = np.zeros((1, 0), dtype=np.int64)
        prod = np.ones(1)
        for k, o in enumerate(options):
            rest_lo = math.prod(float(options[j]["ratio"].min()) for j in range(k + 1, N))
            rest_hi = math.prod(float(options[j]["ratio"].max()) for j in range(k + 1, N))
            new = prod[:, None] * o["ratio"][None, :]
            keep = (new * rest_hi >= self.u_lo * (1 - 1e-12)) & (new * rest_lo <= self.u_hi * (1 + 1e-12))
            i, j = np.nonzero(keep)
            if i.size > COMBINATIONS_MAX:
                raise GearDesignError(f"the ratio split has {i.size} combinations of tooth pairs, more than "
                                      f"{COMBINATIONS_MAX}: narrow the stages' z1_range, z2_max or ratio_range")
            idx = np.column_stack([idx[i], j])
            prod = new[i, j]
        if prod.size == 0:
            return f"no combination of the stages' tooth pairs gives u = {self.U:g} ± {100 * self.tol:g} %"
        self.idx, self.n_comb = idx, prod.size
        return ""

    def _chain_rows(self) -> None:
        """The combinations times the catalog rows of every chain stage."""
        idx, rows = self.idx, {}
        for k, st in enumerate(self.stages):
            if isinstance(st, ChainStage):
                r = st.rows()
                total = idx.shape[0] * r.size
                if total > CANDIDATES_MAX:
                    raise GearDesignError(f"{total} designs (ratio combinations x chain rows) exceed {CANDIDATES_MAX}: "
                                          f"narrow the stages' ranges, strands or catalog")
                idx = np.repeat(idx, r.size, axis=0)
                for kk in rows:
                    rows[kk] = np.repeat(rows[kk], r.size)
                rows[k] = np.tile(r, idx.shape[0] // r.size)
        self.idx, self.chain_rows, self.n_cand = idx, rows, idx.shape[0]

    # -- 4: every non-gear check
    def non_gear_checks(self) -> None:
        n_cand, T = self.n_cand, self.T
        margins: dict = {("motor", name): v for name, v in self.drive._motor_margins(self.P[:, 0]).items()}
        self.ng_size, self.ng_mass, self.chain_info = np.zeros(n_cand), np.zeros(n_cand), {}
        for k, st in enumerate(self.stages):
            if isinstance(st, GivenStage):
                margins.update({(st.name, name): v for name, v in st.margins(T[:, k + 1]).items()})
            elif isinstance(st, ChainStage):
                z1 = self.options[k]["z1"][self.idx[:, k]]
                z2 = self.options[k]["z2"][self.idx[:, k]]
                ch = _chain_batch(st, self.chain_rows[k], z1, z2, self.n[:, k], T[:, k])
                margins.update({(st.name, name): v for name, v in ch["margins"].items()})
                self.ng_size += ch["size"]
                self.ng_mass += ch["mass"]
                self.chain_info[k] = dict(ch, z1=z1, z2=z2)
        self.key_n = {}
        for sh in self.drive.shafts:
            _, caps = _key_caps(sh)
            Ts = T[:, sh.at]
            one = (Ts <= min(caps[1])) | (sh.max_keys < 2)
            crush = np.where(one, caps[1][0], caps[2][0])
            shear = np.where(one, caps[1][1], caps[2][1])
            margins[(f"key '{sh.name}'", "crushing")] = 1.0 - Ts / crush
            margins[(f"key '{sh.name}'", "shear")] = 1.0 - Ts / shear
            self.key_n[sh.name] = np.where(one, 1, 2)
        self.names = list(margins)
        M = (np.column_stack([np.asarray(margins[k], dtype=float) for k in self.names]) if self.names
             else np.zeros((n_cand, 0)))
        self.M = np.where(np.abs(M) <= MARGIN_TOL, 0.0, M)
        Mf = np.where(np.isnan(self.M), -np.inf, self.M)
        self.ng_min = Mf.min(axis=1) if self.names else np.full(n_cand, np.inf)
        self.ng_arg = Mf.argmin(axis=1) if self.names else np.zeros(n_cand, dtype=np.int64)
        self.ng_ok = self.ng_min >= 0

    # -- 5: the gears, branch and bound
    def _solution(self, k: int, j: int) -> dict:
        key = (k, int(j))
        if key not in self._solved:
            before = _shift_solution.cache_info().misses
            o = self.options[k]
            self._solved[key] = _gear_solution(self.stages[k], o["z1"][j], o["z2"][j], self.objective)
            self.n_solves += _shift_solution.cache_info().misses - before
        return self._solved[key]

    def _lower_bounds(self) -> np.ndarray:
        """Each design's cost whatever its gears' shifts (base circles at a·cos α_t; margins unknown)."""
        if self.objective == "max_margin":
            return -self.ng_min
        bound = (self.ng_size if self.objective == "min_size" else self.ng_mass).copy()
        for k in self.gear_k:
            o = self.options[k]
            s, m_ = _gear_bounds(self.stages[k], o["z1"].astype(float), o["z2"].astype(float))
            bound += (s if self.objective == "min_size" else m_)[self.idx[:, k]]
        return bound

    def branch_and_bound(self, progress) -> None:
        """Designs grouped by their gear tooth pairs, solved best bound first while a bound can still
        enter the ``top`` list; what each evaluated design costs is kept in ``self.ex``."""
        n_cand, top = self.n_cand, self.top
        self._solved = {}
        lb_cost = self._lower_bounds()
        group_key = np.zeros(n_cand, dtype=np.int64)
        for k in self.gear_k:
            group_key = group_key * self.options[k]["ratio"].size + self.idx[:, k]
        # limiting checks and gear reasons as codes into lists (object arrays of ~10⁶ strings are slow)
        labels = [f"{a}: {b}" for a, b in self.names] or [""]
        self.ex = ex = dict(cost=np.full(n_cand, np.nan), mm=np.full(n_cand, np.nan), size=np.full(n_cand, np.nan),
                            mass=np.full(n_cand, np.nan), feas=np.zeros(n_cand, dtype=bool),
                            done=np.zeros(n_cand, dtype=bool), lim=self.ng_arg.astype(np.int64),
                            why=np.full(n_cand, -1, dtype=np.int64), labels=labels, reasons=[])
        heap: list = []          # the `top` best costs so far, as a max-heap of −cost
        cand = np.flatnonzero(self.ng_ok)
        order = cand[np.argsort(group_key[cand], kind="stable")]
        if not order.size:
            return
        gk = group_key[order]
        starts = np.flatnonzero(np.r_[True, gk[1:] != gk[:-1]])
        glb = np.minimum.reduceat(lb_cost[order], starts)
        ends = np.r_[starts[1:], order.size]
        for g in np.argsort(glb, kind="stable"):
            if len(heap) >= top and glb[g] > -heap[0] + 1e-12 * abs(heap[0]):
                break      # no design of this or any later group can enter the list
            members = order[starts[g]:ends[g]]
            sols = [self._solution(k, self.idx[members[0], k]) for k in self.gear_k]
            if progress is not None:
                progress(int(np.count_nonzero(glb <= glb[g])), starts.size)
            self._exact(members, sols)
            for v in np.sort(ex["cost"][members][ex["feas"][members]])[:top]:
                if len(heap) < top:
                    heapq.heappush(heap, -float(v))
                elif -v > heap[0]:
                    heapq.heapreplace(heap, -float(v))

    def _exact(self, members, sols) -> None:
        """Cost, smallest margin, size, mass and feasibility of the designs ``members``, which share
        their gear tooth pairs (solutions ``sols``), written into ``ex``."""
        ex = self.ex
        gsize = gmass = 0.0
        gmm, glim, gfeas, why = math.inf, "", True, ""
        for k, sol in zip(self.gear_k, sols):
            st = self.stages[k]
            m, name = _min_margin(sol["margins"]) if sol["margins"] else (-math.inf, "shifts")
            if m < gmm:
                gmm, glim = m, f"{st.name}: {name}"
            if not sol["feasible"]:
                gfeas, why = False, f"stage '{st.name}': {sol['reason']}"
                continue
            gsize += float(stage_area_mm2(sol["a_w"], sol["da1"], sol["da2"]))
            gmass += float(disc_mass_kg(sol["da1"], st.width_mm) + disc_mass_kg(sol["da2"], st.width_mm))
        ng = self.ng_min[members]
        mm = np.minimum(ng, gmm)
        size, mass = self.ng_size[members] + gsize, self.ng_mass[members] + gmass
        ex["size"][members], ex["mass"][members], ex["mm"][members] = size, mass, mm
        if glim:
            ex["labels"].append(glim)
            ex["lim"][members] = np.where(gmm < ng, len(ex["labels"]) - 1, ex["lim"][members])
        ex["feas"][members] = gfeas & (mm >= 0)
        if why:
            ex["reasons"].append(why)
            ex["why"][members] = len(ex["reasons"]) - 1
        ex["done"][members] = True
        ex["cost"][members] = {"min_size": size, "min_mass": mass, "max_margin": -mm}[self.objective]

    # -- 6: the result
    def no_split(self, why: str) -> DriveOptimum:
        return DriveOptimum(success=False, message=f"no design: {why}", objective=self.objective, total_ratio=self.U,
                            ratio_tol=self.tol, table=pd.DataFrame(), best=None, conflict=(f"ratio: {why}",),
                            n_combinations=0, n_candidates=0, n_shift_solves=0, time_s=time.perf_counter() - self.t0)

    def _row(self, c) -> dict:
        row = {"total_ratio": float(np.prod(self.ratios[c])), "ratio_error": float(self.err[c])}
        for k, st in enumerate(self.stages):
            p = st.name
            row[f"{p}.ratio"] = float(self.ratios[c, k])
            if isinstance(st, GearStage):
                row[f"{p}.z1"] = int(self.options[k]["z1"][self.idx[c, k]])
                row[f"{p}.z2"] = int(self.options[k]["z2"][self.idx[c, k]])
            elif isinstance(st, ChainStage):
                ci = self.chain_info[k]
                row[f"{p}.designation"] = str(ci["designation"][c])
                row[f"{p}.strands"] = int(ci["strands"][c])
                row[f"{p}.pitch_mm"] = float(ci["pitch"][c])
                row[f"{p}.z1"] = int(ci["z1"][c])
                row[f"{p}.z2"] = int(ci["z2"][c])
                row[f"{p}.links"] = int(ci["links"][c])
                row[f"{p}.center_distance_mm"] = float(ci["a"][c])
        for name, nk in self.key_n.items():
            row[f"key '{name}'.n_keys"] = int(nk[c])
        return row

    def _gear_cols(self, c, solve=True) -> dict:
        out = {}
        for k in self.gear_k:
            st = self.stages[k]
            j = self.idx[c, k]
            z1, z2 = self.options[k]["z1"][j], self.options[k]["z2"][j]
            sol = _gear_solution(st, z1, z2, self.objective) if solve else None
            out[f"{st.name}.x1"] = sol["x1"] if sol and sol["feasible"] else np.nan
            out[f"{st.name}.x2"] = sol["x2"] if sol and sol["feasible"] else np.nan
            out[f"{st.name}.a_w_mm"] = sol["a_w"] if sol and sol["feasible"] else np.nan
        return out

    def _ranked_rows(self, feas) -> list:
        ex = self.ex
        what = {"min_size": "size", "min_mass": "mass", "max_margin": "smallest margin"}[self.objective]
        rows = []
        for rank, c in enumerate(feas[:self.top]):
            row = {"rank": rank + 1, "feasible": True, "size_mm2": ex["size"][c], "mass_kg": ex["mass"][c],
                   "min_margin": ex["mm"][c], "limiting": ex["labels"][ex["lim"][c]], **self._row(c),
                   **self._gear_cols(c)}
            if rank == 0:
                row["reason"] = "best"
            else:
                c0, d = ex["cost"][feas[0]], ex["cost"][c] - ex["cost"][feas[0]]
                row["reason"] = (f"{what} {100 * abs(d) / max(abs(c0), 1e-300):.3g} % worse than rank 1"
                                 if d > 1e-9 * max(abs(c0), 1e-300) else
                                 "ties rank 1 on the objective; loses on ratio error or size")
            rows.append(row)
        return rows

    def _failing_rows(self) -> tuple[list, tuple]:
        """The closest failing designs (largest smallest margin), each with the stage checks that fail;
        and the first one's failing checks."""
        ex, names, M = self.ex, self.names, self.M
        bad = np.flatnonzero((ex["done"] & ~ex["feas"]) | ~self.ng_ok)
        mm = np.where(ex["done"], ex["mm"], self.ng_min)[bad]
        bad = bad[np.argsort(-np.where(np.isnan(mm), -np.inf, mm), kind="stable")][:_INFEASIBLE_SHOWN]
        rows, first = [], ()
        for c in bad:
            fails = [f"{names[j][0]}: {names[j][1]} ({M[c, j]:+.3g})" for j in range(len(names)) if not M[c, j] >= 0]
            if ex["why"][c] >= 0:
                fails.append(ex["reasons"][ex["why"][c]])
            elif ex["done"][c] and ex["mm"][c] < 0 and not fails:
                fails.append(f"{ex['labels'][ex['lim'][c]]} ({ex['mm'][c]:+.3g})")
            known = bool(ex["done"][c]) or not self.gear_k
            rows.append({"rank": None, "feasible": False,
                         "size_mm2": ex["size"][c] if ex["done"][c] else (self.ng_size[c] if known else np.nan),
                         "mass_kg": ex["mass"][c] if ex["done"][c] else (self.ng_mass[c] if known else np.nan),
                         "min_margin": ex["mm"][c] if ex["done"][c] else self.ng_min[c],
                         "limiting": ex["labels"][ex["lim"][c]], **self._row(c),
                         **self._gear_cols(c, solve=bool(ex["done"][c])), "reason": "fails " + "; ".join(fails)})
            first = first or tuple(fails)
        return rows, first

    def result(self) -> DriveOptimum:
        ex, err = self.ex, self.err
        feas = np.flatnonzero(ex["feas"])
        feas = feas[np.lexsort((ex["size"][feas], np.round(err[feas], 12), np.round(ex["cost"][feas], 9)))]
        failing, conflict = self._failing_rows()
        table = pd.DataFrame(self._ranked_rows(feas) + failing)
        if len(table):
            table["rank"] = table["rank"].astype("Int64")     # failing designs have no rank
        if feas.size:
            c = feas[0]
            best = self._fixed(c).analyse(self.objective)
            msg = (f"u = {float(np.prod(self.ratios[c])):.6g} ({100 * float(err[c]):.3g} % off): size "
                   f"{ex['size'][c]:.6g} mm², mass {ex['mass'][c]:.4g} kg, smallest margin {ex['mm'][c]:+.4f} "
                   f"({ex['labels'][ex['lim'][c]]}); {int(ex['done'].sum())} of {self.n_cand} designs evaluated in full")
            conflict = ()
        else:
            best = None
            msg = ("no design passes every check; the closest fails " + "; ".join(conflict)) if conflict else \
                "no design passes every check"
        return DriveOptimum(success=bool(feas.size), message=msg, objective=self.objective, total_ratio=self.U,
                            ratio_tol=self.tol, table=table, best=best, conflict=conflict,
                            n_combinations=int(self.n_comb), n_candidates=int(self.n_cand),
                            n_shift_solves=int(self.n_solves), time_s=time.perf_counter() - self.t0)

    def _fixed(self, c) -> Drive:
        """The drive with every free variable fixed at design c (shifts, teeth, chain row)."""
        new = []
        for k, st in enumerate(self.stages):
            if isinstance(st, GearStage):
                j = self.idx[c, k]
                z1, z2 = int(self.options[k]["z1"][j]), int(self.options[k]["z2"][j])
                sol = _gear_solution(st, z1, z2, self.objective)
                new.append(replace(st, z1=z1, z2=z2, x1=sol["x1"], x2=sol["x2"]))
            elif isinstance(st, ChainStage):
                ci = self.chain_info[k]
                new.append(replace(st, z1=int(ci["z1"][c]), z2=int(ci["z2"][c]), designation=str(ci["designation"][c]),
                                   strands=(int(ci["strands"][c]),)))
            else:
                new.append(st)
        fixed = replace(self.drive, stages=tuple(new))
        object.__setattr__(fixed, "_load_from_motor", self.drive._load_from_motor)
        return fixed


@lru_cache(maxsize=256)
def _key_caps_cached(d, hub, crush, shear, end, max_keys):
    from . import key

    sh = Shaft(d, hub, 0, allowable_crush_mpa=crush, allowable_shear_mpa=shear, end=end, max_keys=max_keys)
    sel = sh.select(1e-6)
    caps = {}
    for n_keys in (1, 2):
        cap = key.capacity(d, sel.length_mm, crush, shear, end=end, n_keys=min(n_keys, max_keys))
        caps[n_keys] = (cap.torque_crush_nm, cap.torque_shear_nm)
    return sel.length_mm, caps


def _key_caps(sh: Shaft):
    """(key length, {n_keys: (torque at the crushing limit, at the shear limit)}) of a hub [mm, N·m]."""
    return _key_caps_cached(sh.d_mm, sh.hub_length_mm, sh.allowable_crush_mpa, sh.allowable_shear_mpa, sh.end,
                            sh.max_keys)
