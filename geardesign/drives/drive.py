"""A drive: an input (a motor, or a power or output torque at a speed), stages linked by shafts,
the power flow through them, and the ratio split optimised across the stages.

Power flow (shaft k is the output of stage k; shaft 0 the input):
n_k = n_{k−1}/u_k, T_k = T_{k−1}·u_k·η_k, P_k = T_k·ω_k, T_0 = P/ω_0 (P in W, ω in rad/s);
with an output torque instead of a power, T_k = T_N/∏_{j>k}(u_j·η_j).

Each stage is reached through its kind (:mod:`geardesign.drives.stage_kinds`): :meth:`Drive.analyse`
hands every stage the flow into and out of it and collects its checks; :meth:`Drive.optimize` runs
the search of :mod:`geardesign.drives.search` (options per stage, ratio combinations, every batch
check vectorised, then a branch and bound over the options solved one at a time). Every limit on
the work is a named constant (:mod:`geardesign.drives.limits`).
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from ..errors import GearDesignError
from ..progress import bar_for
from ..validate import one_number, require_range
from .drive_results import DriveAnalysis, DriveOptimum
from .limits import (CANDIDATES_MAX, COMBINATIONS_MAX, MARGIN_TOL, OBJECTIVES, POWER_RANGE_KW, RATIO_TOL_RANGE,
                     SPEED_RANGE_RPM, STAGES_MAX, TOP_MAX, TORQUE_RANGE_NM, TOTAL_RATIO_RANGE)
from .search import WALK_LABEL, Search
from .stage_kinds import StageFlow, kind_of
from .stages import Shaft

__all__ = ["Drive", "DriveAnalysis", "DriveOptimum", "power_flow", "OBJECTIVES", "STAGES_MAX", "COMBINATIONS_MAX",
           "CANDIDATES_MAX", "TOP_MAX", "TOTAL_RATIO_RANGE", "RATIO_TOL_RANGE", "SPEED_RANGE_RPM", "MARGIN_TOL",
           "POWER_RANGE_KW", "TORQUE_RANGE_NM"]


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


@dataclass(frozen=True)
class Drive:
    """A drive: input speed ``n_in_rpm`` with ``power_kw`` (input power) or ``output_torque_nm``
    (torque on the last shaft), ``stages`` in the order of the power flow, keyed hubs ``shafts``.

    ``motor`` (a :class:`~geardesign.drives.motor.MotorSelection` or its ``.motor`` row) sets the
    input speed to its rated speed and, when no load is given, the power to its rated power; the
    motor then has a check ``power``: 1 − P_in/P_rated (when the load is given, not taken from it).

    ``shafting`` (a :class:`~geardesign.drives.shafting.Shafting`, None: none) puts the gear stages on shafts
    (the default layout, or the shafts it gives) and adds to :meth:`analyse` the bearing reactions, DIN 743
    safeties, seat sizes, bearings and their lives, keys at the seats, K_Hβ from the shafts' deflection and,
    with a lubricant, the gear stages' computed efficiencies (docs/shafts_in_drive.md).
    """

    stages: tuple
    n_in_rpm: float | None = None
    power_kw: float | None = None
    output_torque_nm: float | None = None
    shafts: tuple = ()
    motor: object = None
    shafting: object = None
    _load_from_motor: bool = field(default=False, init=False, repr=False, compare=False)

    def __repr__(self) -> str:
        motor = None if self.motor is None else str(getattr(self.motor, "get", lambda k, d=None: d)("designation", "motor"))
        load = (f"{self.power_kw:g} kW in" if self.power_kw is not None else
                f"{self.output_torque_nm:g} N·m out" if self.output_torque_nm is not None else "no load given")
        speed = "" if self.n_in_rpm is None else f"{self.n_in_rpm:g} rpm, "
        lines = [f"Drive({speed}{load}{', motor ' + motor if motor else ''}; {len(self.stages)} stage(s), "
                 f"{len(self.shafts)} keyed shaft(s); .analyse() or .optimize(total_ratio=...))"]
        lines += [f"  {i}. {s!r}" for i, s in enumerate(self.stages[:8], 1)]
        lines += [f"  {s!r}" for s in self.shafts[:4]]
        return "\n".join(lines)

    def __post_init__(self):
        stages = tuple(self.stages) if isinstance(self.stages, (list, tuple)) else None
        if not stages or len(stages) > STAGES_MAX:
            raise GearDesignError(f"stages must list 1 to {STAGES_MAX} stages, got {self.stages!r}")
        for s in stages:
            kind_of(s)     # a stage of no registered kind is refused here, naming the kinds
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
        object.__setattr__(self, "stages", self._computed_efficiencies(self.stages))
        shafts = tuple(self.shafts or ())
        for s in shafts:
            if not isinstance(s, Shaft):
                raise GearDesignError(f"shafts must be Shaft objects, got {type(s).__name__}")
            if s.at > len(stages):
                raise GearDesignError(f"shaft '{s.name}': at = {s.at} must be in [0, {len(stages)}] "
                                      f"(0 the input shaft, k the output shaft of stage k)")
        object.__setattr__(self, "shafts", shafts)
        if self.shafting is not None:
            from .shafting import Shafting

            if not isinstance(self.shafting, Shafting):
                raise GearDesignError(f"shafting must be a Shafting (geardesign.drives.shafting), got "
                                      f"{type(self.shafting).__name__}")
            for ds in self.shafting.layout:
                if ds.at > len(stages):
                    raise GearDesignError(f"shafting layout: shaft {ds.at} is beyond the drive's shafts 0 … "
                                          f"{len(stages)}")
            types = self.shafting.bearing_type
            beyond = sorted(k for k in types if k > len(stages)) if isinstance(types, dict) else []
            if beyond:
                raise GearDesignError(f"shafting bearing_type: shaft {beyond[0]} is beyond the drive's shafts 0 … "
                                      f"{len(stages)}")

    def _computed_efficiencies(self, stages: tuple) -> tuple:
        """The stages with ``efficiency='computed'`` (a worm stage's) given their number at the speed into them:
        n_in over the ratios before them, which must be fixed (a stage whose ratio the search chooses would give
        the worm a speed per design, and the power flow holds one efficiency per stage)."""
        if not any(getattr(s, "efficiency", None) == "computed" for s in stages):
            return stages
        out, n, speeds = [], self.n_in_rpm, []
        for s in stages:
            speeds.append(n)
            if getattr(s, "efficiency", None) == "computed":
                if n is None:
                    raise GearDesignError(f"stage '{s.name}': efficiency='computed' needs the speed into it fixed: the "
                                          f"stages before it must have fixed ratios (or put the worm first)")
                if not getattr(s, "sized", False):
                    s = s.at_speed(n)
            out.append(s)
            try:
                n = None if n is None else n / kind_of(s).fixed_ratio(s)
            except GearDesignError:      # a ratio the search chooses
                n = None
        # a stage sized by its load: its size and efficiency together, at the torque the flow gives it (which
        # depends on the efficiencies before it with the input power given, after it with the output torque)
        order = range(len(out)) if self.power_kw is not None else reversed(range(len(out)))
        for i in order:
            if getattr(out[i], "efficiency", None) == "computed":
                out[i] = out[i].at_speed(speeds[i], torque_out=self._torque_out_of(out, i))
        return tuple(out)

    def _torque_out_of(self, stages: list, i: int):
        """The torque out of stage i (N·m) as a function of its efficiency: with the input power given, from the
        stages up to it (their ratios fixed: the speed into it is); with the output torque given, from the stages
        after it, whose ratios and efficiencies must then be fixed."""
        def ratio(s):
            try:
                return kind_of(s).fixed_ratio(s)
            except GearDesignError:
                raise GearDesignError(f"stage '{stages[i].name}': efficiency='computed' on a stage sized by its load "
                                      f"needs the torque out of it fixed: with output_torque_nm the stages after "
                                      f"it must have fixed ratios (or give power_kw)") from None

        upto = stages if self.power_kw is None else stages[:i + 1]
        ratios = [ratio(s) for s in upto]
        effs = [s.efficiency for j, s in enumerate(upto) if j != i]
        if any(isinstance(e, str) for e in effs):
            raise GearDesignError(f"stage '{stages[i].name}': efficiency='computed' on a stage sized by its load "
                                  f"needs the efficiencies of the stages {'after' if self.power_kw is None else 'before'}"
                                  f" it as numbers")

        def torque_out(eta):
            _, T, _ = power_flow(self.n_in_rpm, ratios, effs[:i] + [eta] + effs[i:], self.power_kw,
                                 self.output_torque_nm)
            return float(np.ravel(T)[i + 1])
        return torque_out

    # -- helpers
    def _efficiencies(self) -> np.ndarray:
        return np.array([s.efficiency for s in self.stages])

    def _flow(self, ratios):
        return power_flow(self.n_in_rpm, ratios, self._efficiencies(), self.power_kw, self.output_torque_nm)

    def _motor_margins(self, power_in_kw) -> dict:
        if self.motor is None or self._load_from_motor:   # its own rated power: nothing to check
            return {}
        return {"power": 1.0 - np.asarray(power_in_kw, dtype=float) / float(self.motor["power_kw"])}

    def _keys(self, T):
        """(rows of the keys table, key.select results, check rows) of every hub at its shaft's torque."""
        key_rows, key_results, rows = [], [], []
        for sh in self.shafts:
            sel = sh.select(float(T[sh.at]))
            key_results.append(sel)
            key_rows.append(dict(name=sh.name, at=sh.at, d_mm=sh.d_mm, hub_length_mm=sh.hub_length_mm,
                                 torque_nm=float(T[sh.at]), b_mm=sel.b_mm, h_mm=sel.h_mm, length_mm=sel.length_mm,
                                 n_keys=sel.n_keys, crush_mpa=sel.crush_mpa, shear_mpa=sel.shear_mpa,
                                 margin_crush=sel.margin_crush, margin_shear=sel.margin_shear, feasible=sel.feasible,
                                 message=sel.message))
            rows += [(f"key '{sh.name}'", "crushing", sel.margin_crush), (f"key '{sh.name}'", "shear", sel.margin_shear)]
        return key_rows, key_results, rows

    # -- analyse
    def _stage_pass(self, kinds, n, T, objective) -> tuple:
        """(stage results, their check rows, size, mass) of every stage at the flow n, T."""
        rows, stages_out = [], []
        size = mass = 0.0
        for i, (kind, st) in enumerate(zip(kinds, self.stages)):
            flow = StageFlow(float(n[i]), float(T[i]), float(n[i + 1]), float(T[i + 1]))
            out = kind.analyse(st, flow, objective)
            rows += [(st.name, k, v) for k, v in out.pop("margins").items()]
            size += out.pop("size", 0.0)
            mass += out.pop("mass", 0.0)
            stages_out.append(dict(out, flow=flow))
        return stages_out, rows, size, mass

    def analyse(self, objective: str = "min_size") -> DriveAnalysis:
        """The power flow, every stage's checks and margins, every key, the smallest margin.

        Every stage needs its tooth counts; free gear shifts are solved (``objective`` only picks
        the shift rule, as in :meth:`optimize`), a free chain row is chosen by chain.design. To re-analyse
        an optimum, take ``best.drive`` (its shifts fixed); tooth counts alone are solved again for
        ``objective``, which must then be the optimum's to give the same shifts.

        With ``shafting``: the shafts, bearings, seat keys and (with a lubricant) the computed efficiencies
        too; the power flow is solved again with the computed efficiencies until they change by less than
        :data:`EFFICIENCY_TOL`, then the gear stages' strength is checked with K_Hβ from the shafts' f_sh.
        """
        kinds = [kind_of(s) for s in self.stages]
        ratios = np.array([kind.fixed_ratio(s) for kind, s in zip(kinds, self.stages)])
        eta = self._efficiencies()
        shafting = efficiency = None
        for _ in range(EFFICIENCY_PASSES):
            n, T, P = (a.ravel() for a in power_flow(self.n_in_rpm, ratios, eta, self.power_kw,
                                                     self.output_torque_nm))
            stages_out, stage_rows, size, mass = self._stage_pass(kinds, n, T, objective)
            if self.shafting is None:
                break
            from .shafting_analysis import analyse_shafting, stage_efficiencies

            shafting = analyse_shafting(self, stages_out, n, T)
            computed, efficiency = stage_efficiencies(self, stages_out, n, T, shafting)
            if float(np.max(np.abs(computed - eta))) <= EFFICIENCY_TOL:
                break
            eta = computed
        if shafting is not None:
            from .shafting_analysis import stiffened_for_gears

            shafting["efficiency"] = efficiency
            stages_out, stage_rows, mesh, shafting = stiffened_for_gears(self, kinds, stages_out, stage_rows,
                                                                         shafting, n, T, objective)
            shafting["mesh_misalignment"] = mesh
            for st, e in zip(stages_out, eta):      # the η the power flow took (computed where not given)
                st["summary"]["efficiency"] = float(e)
        rows = [("motor", name, float(v)) for name, v in self._motor_margins(P[0]).items()] + stage_rows
        key_rows, key_results, key_checks = self._keys(T)
        rows += key_checks
        if shafting is not None:
            rows += shafting["rows"]
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
        at_limit = checks.loc[checks["ok"] & (checks["margin"].abs() <= AT_LIMIT), ["item", "check"]]
        zero = ("; at its limit, no reserve: " + ", ".join(f"{a}: {b}" for a, b in at_limit.itertuples(index=False))
                if len(at_limit) else "")
        msg = (f"u = {float(np.prod(ratios)):.6g}, output {n[-1]:.6g} rpm, {T[-1]:.6g} N·m; "
               + (f"every check holds; smallest margin {mm:+.4f} ({lim}){zero}" if ok else
                  "fails " + ", ".join(f"{a}: {b} ({c:+.3f})" for a, b, c in failing[["item", "check", "margin"]]
                                       .itertuples(index=False))))
        return DriveAnalysis(success=ok, message=msg, flow=flow, checks=checks, keys=keys, stages=tuple(stages_out),
                             min_margin=mm, limiting=lim, total_ratio=float(np.prod(ratios)), size_mm2=size,
                             mass_kg=mass, drive=self, key_results=tuple(key_results),
                             overall_efficiency=float(P[-1] / P[0]), heat_kw=float(P[0] - P[-1]), shafting=shafting)

    # -- optimize
    def optimize(self, total_ratio, ratio_tol=0.03, objective="min_size", top=10, progress=None, *, client=None,
                 workers=None) -> DriveOptimum:
        """The ratio split and every free variable chosen together for ``objective``.

        ``min_size``: smallest sum of the stages' side-view envelopes (a + (D1 + D2)/2)·max(D1, D2)
        (gears at their tip circles and operating centre distance, chains at their sprocket tip
        circles and centre distance; bought units are fixed and left out); ``min_mass``: smallest
        mass of gear blanks and sprockets as steel discs of their tip diameters and face widths,
        plus the chain (mass per metre × length); ``max_margin``: the largest smallest margin of
        every check of the drive. Ties go to the smaller ratio error, then the smaller size.
        The total ratio must hold within ``ratio_tol`` (relative). ``top`` alternatives are listed.
        ``progress``: None shows a bar on stderr when it is a terminal (tqdm, once the search has run a
        few seconds), True always, False never; a callable ``progress(done, total)`` is called instead after
        each group of designs sharing their gear tooth pairs (the walk may stop well before ``total``).
        ``client=`` (a ``dask.distributed.Client``) or ``workers=N`` solve the tooth pairs the walk takes together
        on a cluster, in chunks sharing one cache of solved pairs (:mod:`geardesign.drives.spread`): the same shift
        solves and the same optimum as here, bit for bit (docs/scale.md); a split too large to enumerate whole
        (built under a cost limit, docs/drive_train.md "Large splits") is solved here.
        """
        t0 = time.perf_counter()
        U = one_number("total_ratio", require_range("total_ratio", total_ratio, *TOTAL_RATIO_RANGE))
        tol = one_number("ratio_tol", require_range("ratio_tol", ratio_tol, *RATIO_TOL_RANGE))
        if objective not in OBJECTIVES:
            raise GearDesignError(f"objective must be one of {', '.join(OBJECTIVES)}, got {objective!r}")
        top = int(require_range("top", top, 1, TOP_MAX))
        report, bar = bar_for(progress, WALK_LABEL)
        try:
            return Search(self, U, tol, objective, top, t0).run(report, dict(client=client, workers=workers))
        finally:
            if bar is not None:
                bar.close()


def _checks_table(rows) -> pd.DataFrame:
    """item, check, margin, ok; margins within MARGIN_TOL of zero are zero."""
    checks = pd.DataFrame(rows, columns=["item", "check", "margin"])
    checks["margin"] = checks["margin"].astype(float)
    checks.loc[checks["margin"].abs() <= MARGIN_TOL, "margin"] = 0.0
    checks["ok"] = checks["margin"] >= 0
    return checks


EFFICIENCY_TOL = 1e-6   # the computed efficiencies' fixed point: passes stop when no η moves by more
EFFICIENCY_PASSES = 6   # ... or after this many power flows (the losses change little with the torque)
AT_LIMIT = 1e-6     # a margin this close to 0 holds with no reserve: the message says so


def _smallest(checks: pd.DataFrame):
    """(smallest margin, "item: check") of a checks table (NaN counts as −inf)."""
    if checks.empty:
        return math.inf, ""
    j = int(np.argmin(checks["margin"].fillna(-np.inf).to_numpy()))
    return float(checks["margin"].iloc[j]), f"{checks['item'].iloc[j]}: {checks['check'].iloc[j]}"
