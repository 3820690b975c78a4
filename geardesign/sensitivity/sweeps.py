"""Sweeps and local sensitivities: how the optimum and the margins move when an input moves.

* :func:`sweep` varies one or two inputs (a check limit, a tooth count, a rack parameter, a
  centre distance; or for a chain a load, a speed, the service factor K_e, [p]) over given
  values and returns one row per point with the optimum and every margin. Tooth-count sweeps
  go through the batched :func:`geardesign.shifts.atlas.shift_atlas`; limit and rack sweeps start
  each solve from the previous optimum.
* :func:`local_sensitivities` gives d(fun)/d(input) at one design: the convex method's duals
  and the exact method's KKT multipliers for the limits, central differences of re-solved
  optima for everything (the tornado chart's bars).
* Plots (matplotlib; call ``matplotlib.use("Agg")`` before when writing files):
  :func:`plot_tornado`, :func:`plot_margins`, :func:`plot_region_motion`.
"""
from __future__ import annotations

import functools
import itertools

import numpy as np
import pandas as pd

from .. import parallel
from ..errors import GearDesignError
from ..gears.checks import make_checks, option, options as check_options
from ..gears.rack import BasicRack
from ..validate import require_finite

__all__ = ["sweep", "sweep_parameters", "local_sensitivities", "plot_tornado", "plot_margins",
           "plot_region_motion", "LIMIT_PARAMETERS", "RACK_PARAMETERS", "CHAIN_PARAMETERS"]

def limit_parameters() -> tuple:
    """The check limits a sweep may vary: the check registry's options marked sweepable."""
    return tuple(name for name, opt in check_options().items() if opt.sweep)


LIMIT_PARAMETERS = limit_parameters()
RACK_PARAMETERS = ("alpha_deg", "ha", "c", "rho_f")
TOOTH_PARAMETERS = ("z1", "z2")
GEAR_PARAMETERS = LIMIT_PARAMETERS + RACK_PARAMETERS + TOOTH_PARAMETERS + ("a_w",)
CHAIN_PARAMETERS = ("torque_nm", "power_kw", "n1_rpm", "ratio", "k_e", "allowable_pressure_mpa",
                    "allowable_safety_factor", "z1", "center_distance_mm", "sag_factor")
_RACK_DEFAULTS = {k: getattr(BasicRack(), k) for k in RACK_PARAMETERS}


STUDY_VALUES_MAX = 2000      # values of one parameter (~10 s of optimisation at ~5 ms each), per worker
STUDY_POINTS_MAX = 10_000    # points of a two-parameter study, e.g. 100 x 100 (~1 min), per worker
# Points solved one after another, each from the last optimum; every run starts cold, so that runs
# can go to different workers and the sweep is the same wherever it ran. ~25 x 5 ms = 0.1 s a run,
# well above a task's ~2 ms of scheduling; SWEEP_CHUNK_MAX runs at most go in one task.
WARM_START_RUN = 25
SWEEP_CHUNK_MAX = 20


def sweep_parameters(target: str = "gear") -> tuple:
    """The inputs :func:`sweep` can vary for ``target`` ("gear" or "chain")."""
    if target == "gear":
        return GEAR_PARAMETERS
    if target == "chain":
        return CHAIN_PARAMETERS
    raise GearDesignError(f"target must be 'gear' or 'chain', got {target!r}")


# --- gear ----------------------------------------------------------------------------------------


def _rack_with(rack, **changes):
    base = {k: getattr(rack, k) for k in RACK_PARAMETERS} if rack is not None else dict(_RACK_DEFAULTS)
    base.update(changes)
    return BasicRack(**base)


def _gear_row(res, params: dict) -> dict:
    row = dict(params)
    row.update(x1=res.x1, x2=res.x2, x_sum=res.x_sum, fun=res.fun, eps_alpha=res.eps_alpha, a_w_mm=res.a_w,
               success=bool(res.success), active=",".join(res.active))
    row.update({f"margin_{k}": v for k, v in res.margins.items()})
    row.update({f"sens_{k}": res.sensitivity.get(k, 0.0) for k in res.margins})
    return row


def _gear_solve(point: dict, base: dict, start=None):
    from ..shifts.optimize import optimize_shifts
    kw = dict(base)
    checks = kw.pop("checks", None)
    checks = dict(checks or {})
    rack = kw.pop("rack", None)
    rack_changes = {}
    for k, v in point.items():
        if k in LIMIT_PARAMETERS:
            checks[k] = float(v)
        elif k in RACK_PARAMETERS:
            rack_changes[k] = float(v)
        elif k in TOOTH_PARAMETERS:
            kw[k] = int(v)
        elif k == "a_w":
            kw["a_w"] = float(v)
    if rack_changes:
        rack = _rack_with(rack, **rack_changes)
    if kw.get("a_w") is not None:
        start = None   # a fixed x-sum has one variable; the previous (x1, x2) is no start for it
    return optimize_shifts(checks=checks, rack=rack, start=start, **kw)


def _gear_sweep(points: list[dict], base: dict, where: dict) -> pd.DataFrame:
    names = list(points[0])
    only_teeth = all(n in TOOTH_PARAMETERS for n in names) and base.get("a_w") is None
    if only_teeth:
        from ..shifts.atlas import shift_atlas
        z1s = sorted({int(p["z1"] if "z1" in p else base["z1"]) for p in points})
        z2s = sorted({int(p["z2"] if "z2" in p else base["z2"]) for p in points})
        kind = {k: base[k] for k in ("beta_deg", "internal", "face_width_mm") if k in base}
        kw = {k: base[k] for k in ("objective", "checks", "method", "rack", "tip_shortening", "bounds") if k in base}
        m = float(base.get("m", 1.0))
        # the atlas works per unit module: its face width is b/m
        fw = None if kind.get("face_width_mm") is None else kind["face_width_mm"] / m
        at = shift_atlas(z1s, z2s, upper_only=False, **kw, **{**kind, "face_width_mm": fw}, **where)
        sgn = -1.0 if kind.get("internal") else 1.0
        at = at.rename(columns={"objective": "fun"}).assign(x_sum=lambda d: d["x2"] + sgn * d["x1"])
        at["success"] = at.pop("feasible")
        # a_w at the optimum for the module of the case
        from ..gears.geometry import pair_geometry
        geo = pair_geometry(m, at["z1"].to_numpy(), at["z2"].to_numpy(), at["x1"].to_numpy(), at["x2"].to_numpy(),
                            **({"rack": base["rack"]} if base.get("rack") is not None else {}), **kind)
        at["a_w_mm"] = np.where(at["success"], geo.a_w, np.nan)
        keys = pd.DataFrame(points).astype(int)
        full = keys.assign(**{k: base[k] for k in TOOTH_PARAMETERS if k not in keys.columns})
        out = full.merge(at, on=["z1", "z2"], how="left")
        lead = names + [c for c in ("x1", "x2", "x_sum", "fun", "eps_alpha", "a_w_mm", "success", "active")]
        rest = [c for c in out.columns if c not in lead and c not in ("z1", "z2", "area", "conflict")]
        out = out[lead + rest + ["area"]].rename(columns={"area": "region_area"})
        out.attrs.update(target="gear", batched="shift_atlas")
        return out
    runs = [points[s:s + WARM_START_RUN] for s in range(0, len(points), WARM_START_RUN)]
    rows = [row for part in _map_points(_gear_runs, runs, base, where) for run in part for row in run]
    out = pd.DataFrame(rows)
    out.attrs.update(target="gear", batched="warm start")
    return out


def _gear_runs(base: dict, runs: list) -> list:
    """The rows of each run of points, each run solved from a cold start and then warm-started."""
    out = []
    for run in runs:
        rows, start = [], None
        for p in run:
            res = _gear_solve(p, base, start)
            rows.append(_gear_row(res, p))
            # the last optimum seeds the next solve (optimize_shifts falls back to its grid when it is infeasible)
            start = (res.x1, res.x2) if res.success else None
        out.append(rows)
    return out


def _map_points(fn, items: list, base: dict, where: dict) -> list:
    """[fn(base, chunk) for each chunk of items], here or on the cluster ``where`` names."""
    n_workers = parallel.slots(**where)
    if not parallel.requested(**where):
        return [fn(base, items)]
    return parallel.map_chunks(functools.partial(fn, base),
                               [items[s] for s in parallel.chunk_slices(len(items), n_workers, 1, SWEEP_CHUNK_MAX)],
                               **where)


# --- chain ---------------------------------------------------------------------------------------


def _chain_sweep(points: list[dict], base: dict, where: dict) -> pd.DataFrame:
    groups = [points[s:s + WARM_START_RUN] for s in range(0, len(points), WARM_START_RUN)]
    rows = [row for part in _map_points(_chain_rows, groups, base, where) for group in part for row in group]
    out = pd.DataFrame(rows)
    out.attrs.update(target="chain")
    return out


def _chain_rows(base: dict, groups: list) -> list:
    """The rows of each group of points (each point designed on its own)."""
    return [[_chain_row(p, base) for p in group] for group in groups]


def _chain_row(p: dict, base: dict) -> dict:
    """One point of a chain sweep: the best chain (or the closest) and its margins."""
    from ..drives.chain import design
    kw = dict(base)
    for k, v in p.items():
        if k == "torque_nm":
            kw.pop("power_kw", None)
        if k == "power_kw":
            kw.pop("torque_nm", None)
        kw[k] = int(v) if k == "z1" else float(v)
    res = design(**kw)
    row = dict(p)
    b = res.best
    if b is None:
        closest = res.candidates.iloc[0]
        row.update(success=False, designation=None, limiting_check=closest["limiting_check"],
                   min_margin=float(closest["min_margin"]))
    else:
        row.update(success=True, designation=b["designation"], pitch_mm=float(b["pitch_mm"]),
                   strands=int(b["strands"]), z1_teeth=int(b["z1"]), links=int(b["links"]),
                   pressure_mpa=float(b["pressure_mpa"]), limiting_check=b["limiting_check"],
                   min_margin=float(b["min_margin"]))
        row.update({c: float(b[c]) for c in b.index if c.startswith("margin_") and np.isfinite(b[c])})
    return row


def sweep(parameter: str, values, parameter2: str | None = None, values2=None, *, target: str = "gear",
          client=None, workers=None, **base) -> pd.DataFrame:
    """Vary one or two inputs and return the optimum and the margins at every point.

    Parameters
    ----------
    parameter, values : the input to vary and its values. For ``target="gear"``: a check
        limit (``eps_alpha_min``, ``sa_min``), a rack parameter (``alpha_deg``, ``ha``, ``c``,
        ``rho_f``), a tooth count (``z1``, ``z2``) or the centre distance ``a_w`` [mm]. For
        ``target="chain"``: ``torque_nm``, ``power_kw``, ``n1_rpm``, ``ratio``, the service
        factor ``k_e``, ``allowable_pressure_mpa``, ``allowable_safety_factor``, ``z1``,
        ``center_distance_mm``, ``sag_factor``.
    parameter2, values2 : an optional second input; the sweep covers every combination.
    **base : the fixed inputs, as for :func:`geardesign.shifts.optimize.optimize_shifts` (``z1``, ``z2``,
        ``objective``, ``checks`` as a dict of limits, ``rack``, ``method``, ``m``, ``a_w``) or
        :func:`geardesign.drives.chain.design`.
    client, workers : solve the points on a ``dask.distributed.Client`` or on a local cluster of
        ``workers`` processes made for the call; the table is the serial one bit for bit and
        STUDY_VALUES_MAX, STUDY_POINTS_MAX are multiplied by the number of workers (see
        :mod:`geardesign.parallel`). Limit, rack and centre-distance points are solved in runs of
        WARM_START_RUN, each run's first point from a cold start and the next from the last optimum,
        here and on a cluster alike (so the result does not depend on where it ran).

    Returns a DataFrame, one row per point: the input(s), then for gears ``x1, x2, x_sum, fun,
    eps_alpha, a_w_mm, success, active``, one ``margin_<check>`` and one ``sens_<check>``
    (d fun/d limit of the active checks) per check; for chains the best chain and its margins.
    Tooth-count sweeps are solved in one batched :func:`~geardesign.shifts.atlas.shift_atlas` call.

    >>> df = sweep("eps_alpha_min", [1.1, 1.2, 1.3], z1=17, z2=26)
    >>> bool(df["x_sum"].is_monotonic_decreasing)     # a stricter ε_α limit leaves less x-sum
    True
    """
    allowed = sweep_parameters(target)
    for name in (parameter, parameter2):
        if name is not None and name not in allowed:
            raise GearDesignError(f"parameter must be one of {', '.join(allowed)} for target {target!r}, got {name!r}")
    if (parameter2 is None) != (values2 is None):
        raise GearDesignError("give parameter2 and values2 together")
    if parameter2 == parameter:
        raise GearDesignError(f"parameter2 must differ from parameter, got {parameter2!r} twice")
    where = dict(client=client, workers=workers)
    scale = parallel.slots(**where)
    values_max, points_max = STUDY_VALUES_MAX * scale, STUDY_POINTS_MAX * scale
    v1 = list(np.atleast_1d(require_finite("values", values)).ravel())
    if not 1 <= len(v1) <= values_max:
        raise GearDesignError(f"values must hold 1 to {values_max} values, got {len(v1)}")
    if parameter2 is None:
        points = [{parameter: v} for v in v1]
    else:
        v2 = list(np.atleast_1d(require_finite("values2", values2)).ravel())
        if not 1 <= len(v2) <= values_max:
            raise GearDesignError(f"values2 must hold 1 to {values_max} values, got {len(v2)}")
        if len(v1) * len(v2) > points_max:
            raise GearDesignError(f"a two-parameter study takes at most {points_max:,} points, "
                                  f"got {len(v1)} x {len(v2)} = {len(v1) * len(v2):,}")
        points = [{parameter: a, parameter2: b} for a, b in itertools.product(v1, v2)]
    if target == "gear":
        for k in ("z1", "z2"):
            if k not in base and k not in (parameter, parameter2):
                raise GearDesignError(f"sweep over a gear pair needs {k} (a tooth count)")
        for p in points:
            for k in TOOTH_PARAMETERS:
                if k in p:
                    p[k] = int(round(p[k]))
        base = {k: v for k, v in base.items() if v is not None or k in ("checks", "rack")}
        return _gear_sweep(points, base, where)
    return _chain_sweep(points, base, where)


def local_sensitivities(z1, z2, objective=None, checks=None, rack=None, step=0.02, m=1.0, a_w=None,
                        method=None, tip_shortening=True, bounds=None, beta_deg: float = 0.0,
                        internal: bool = False, face_width_mm: float | None = None) -> pd.DataFrame:
    """d(fun)/d(input) at the optimum of one pair, for every limit and rack parameter.

    For each input the optimum is re-solved (method "exact") with the input moved by
    ±``step`` (relative); ``slope_fd`` is the central difference. For the check limits
    ``slope_dual`` is the convex method's dual value and ``slope_kkt`` the exact method's KKT
    multiplier (both zero when the check is not active). ``method`` is accepted and ignored
    (a scene passes its own).
    """
    from ..shifts.optimize import optimize_shifts
    kw = dict(objective=objective, m=m, a_w=a_w, tip_shortening=tip_shortening, beta_deg=beta_deg,
              internal=internal, face_width_mm=face_width_mm)
    if bounds is not None:
        kw["bounds"] = tuple(bounds)
    limits = dict(checks or {})
    exact = optimize_shifts(z1, z2, checks=limits, rack=rack, method="exact", **kw)
    convex = optimize_shifts(z1, z2, checks=limits, rack=rack, method="convex", **kw)
    # each sweepable limit of the checks this case builds, and the names of the checks it sets
    name_of = {}
    for c in make_checks(**{"internal": internal, **limits}):
        if c.option is not None and c.option.sweep:
            name_of.setdefault(c.option.name, []).append(c.name)
    rows = []
    inputs = list(name_of) + list(RACK_PARAMETERS)
    for k in inputs:
        v0 = (float(limits.get(k, option(k).default)) if k in LIMIT_PARAMETERS
              else float(getattr(rack, k) if rack else _RACK_DEFAULTS[k]))
        h = step * abs(v0) if v0 != 0 else step
        funs = []
        for v in (v0 - h, v0 + h):
            try:
                if k in LIMIT_PARAMETERS:
                    r = optimize_shifts(z1, z2, checks={**limits, k: v}, rack=rack, method="exact", **kw)
                else:
                    r = optimize_shifts(z1, z2, checks=limits, rack=_rack_with(rack, **{k: v}), method="exact", **kw)
                funs.append(r.fun if r.success else np.nan)
            except GearDesignError:
                funs.append(np.nan)
        row = {"input": k, "value": v0, "low": v0 - h, "high": v0 + h, "fun": exact.fun,
               "fun_low": funs[0], "fun_high": funs[1], "slope_fd": (funs[1] - funs[0]) / (2 * h)}
        if k in LIMIT_PARAMETERS:
            row["slope_dual"] = sum(convex.sensitivity.get(n, 0.0) for n in name_of[k])
            row["slope_kkt"] = sum(exact.sensitivity.get(n, 0.0) for n in name_of[k])
        else:
            row["slope_dual"] = np.nan
            row["slope_kkt"] = np.nan
        rows.append(row)
    out = pd.DataFrame(rows)
    out.attrs.update(objective=exact.objective, x1=exact.x1, x2=exact.x2, active=list(exact.active))
    return out


# --- plots ---------------------------------------------------------------------------------------


def plot_tornado(frame: pd.DataFrame, ax=None):
    """Tornado chart of :func:`local_sensitivities`: the change of the optimum for each input
    moved down and up, widest bar on top."""
    import matplotlib.pyplot as plt
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 4.5))
    f = frame.assign(lo=frame["fun_low"] - frame["fun"], hi=frame["fun_high"] - frame["fun"])
    f = f.assign(width=(f["hi"] - f["lo"]).abs().fillna(0)).sort_values("width")
    y = np.arange(len(f))
    ax.barh(y, f["lo"].fillna(0), color="tab:blue", label="input −step")
    ax.barh(y, f["hi"].fillna(0), color="tab:orange", label="input +step")
    ax.set_yticks(y, [f"{r.input} = {r.value:g}" for r in f.itertuples()])
    ax.axvline(0, color="k", lw=0.8)
    ax.set_xlabel(f"change of the optimum ({frame.attrs.get('objective', 'fun')})")
    ax.legend(loc="lower right", fontsize=8)
    ax.set_title("Local sensitivity of the optimum")
    return ax


def plot_margins(frame: pd.DataFrame, parameter: str, ax=None, by: str | None = None):
    """Margins of every check along a sweep (one line per check); with ``by`` (the second
    input of a two-input sweep) the smallest margin, one line per value of ``by``."""
    import matplotlib.pyplot as plt
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 4.5))
    cols = [c for c in frame.columns if c.startswith("margin_")]
    f = frame.sort_values(parameter)
    if by is None:
        for c in cols:
            ax.plot(f[parameter], f[c], marker=".", label=c[7:])
    else:
        for v, g in f.groupby(by):
            ax.plot(g[parameter], g[cols].min(axis=1), marker=".", label=f"{by} = {v:g}")
        ax.set_title("smallest margin")
    ax.axhline(0, color="k", lw=0.8)
    ax.set_xlabel(parameter)
    ax.set_ylabel("margin (>= 0 holds)")
    ax.legend(fontsize=7, ncol=2)
    return ax


def plot_region_motion(parameter: str, values, z1, z2, checks=None, rack=None, ax=None, tip_shortening=True,
                       bounds=(-1.5, 3.0), **_ignored):
    """The feasible region of (x1, x2) for each value of one limit or rack parameter, overlaid."""
    import matplotlib.pyplot as plt
    from ..shifts.region import feasible_region
    if parameter not in LIMIT_PARAMETERS + RACK_PARAMETERS:
        raise GearDesignError(f"parameter must be one of {', '.join(LIMIT_PARAMETERS + RACK_PARAMETERS)}, "
                              f"got {parameter!r}")
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 6))
    cmap = plt.get_cmap("viridis")
    vals = list(values)
    for i, v in enumerate(vals):
        lim = dict(checks or {})
        rk = rack
        if parameter in LIMIT_PARAMETERS:
            lim[parameter] = float(v)
        else:
            rk = _rack_with(rack, **{parameter: float(v)})
        reg = feasible_region(z1, z2, rack=rk, checks=lim, method="grid", n=201, tip_shortening=tip_shortening,
                              bounds=tuple(bounds))
        color = cmap(i / max(len(vals) - 1, 1))
        first = True
        for _, comp in reg.boundary.groupby("component"):
            xs = np.append(comp["x1"].to_numpy(), comp["x1"].iloc[0])
            ys = np.append(comp["x2"].to_numpy(), comp["x2"].iloc[0])
            ax.plot(xs, ys, color=color, label=f"{parameter} = {v:g} (area {reg.area:.3f})" if first else None)
            first = False
        if not reg.feasible:
            ax.plot([], [], color=color, label=f"{parameter} = {v:g}: empty")
    ax.set_xlabel("x1")
    ax.set_ylabel("x2")
    ax.set_title(f"Feasible region of z1/z2 = {z1}/{z2} as {parameter} moves")
    ax.legend(fontsize=7)
    return ax
