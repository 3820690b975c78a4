"""Standard series of worm gears and the choice of a worm pair from them: the axial modules (GOST 19672-74) and
the reducers' centre distances (GOST 2144-76) from ``catalogs/``, and :func:`select_worm`, which ranks every
module × diameter quotient × starts for a ratio and (or) a centre distance, with the wheel's shift x2 exact for
each (the centre distance fixes it; without one, :meth:`WormPair.optimize_x2` picks it).

The standard series of q (GOST 19672-74, DIN 3976) could not be retrieved from a source this project can cite,
so none is bundled: the default candidates are the ISO 3 R10 preferred numbers from 6.3 to 25 (``catalogs/
preferred_numbers_iso3.csv``), a series of preferred numbers, not a worm standard; give ``q`` to use others.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from ...catalogs.tables import load_catalog, preferred_numbers
from ...errors import GearDesignError
from ...results import RankedTable
from ...validate import _show, one_number, require_choice, require_int, require_range
from .. import checks as _checks
from ..rack import require_rack
from .geometry import FLANK_FORMS, LENGTH_RANGE_MM, Z1_RANGE, worm_geometry
from .pair import _X2_SENSE, X2_OBJECTIVES, WormPair

__all__ = ["worm_module_series", "worm_center_distance_series", "default_q_values", "select_worm", "WormSelection",
           "Z1_DEFAULT", "RATIO_TOL_DEFAULT"]

Z1_DEFAULT = (1, 2, 3, 4)        # the starts of power worms (DIN 3975's examples run 1 … 4)
RATIO_TOL_DEFAULT = 0.04         # |u/u_wanted − 1|: the 4 % a reducer's catalogue ratio usually allows
CANDIDATES_MAX = 200_000


def _series(name: str, column: str, series, lo, hi) -> np.ndarray:
    wanted = (series,) if np.ndim(series) == 0 else tuple(series)
    if not wanted or any(s not in (1, 2) for s in wanted):
        raise GearDesignError(f"series must be 1, 2 or (1, 2), got {series!r}")
    frame = load_catalog(name)
    values = np.sort(frame.loc[frame["series"].isin(wanted), column].to_numpy(dtype=float))
    lo = -np.inf if lo is None else lo
    hi = np.inf if hi is None else hi
    return values[(values >= lo) & (values <= hi)]


def worm_module_series(series=(1, 2), min_mm: float | None = None, max_mm: float | None = None) -> np.ndarray:
    """Standard axial modules of worm gears, mm (GOST 19672-74, 1.6 … 16 mm; ``catalogs/worm_modules_gost19672.csv``
    with its source per row), sorted; ``series`` 1 (preferred), 2 or (1, 2).

    >>> worm_module_series(2).tolist()
    [3.0, 3.5, 6.0, 7.0, 12.0]
    """
    return _series("worm_modules", "module_mm", series, min_mm, max_mm)


def worm_center_distance_series(series=(1, 2), min_mm: float | None = None, max_mm: float | None = None) -> np.ndarray:
    """Standard centre distances of worm reducers, mm (GOST 2144-76: 1st row 40 … 500, 2nd row 140, 180, 225, 355,
    450; ``catalogs/worm_center_distances_gost2144.csv``), sorted.

    >>> worm_center_distance_series(2).tolist()
    [140.0, 180.0, 225.0, 355.0, 450.0]
    """
    return _series("worm_center_distances", "a_w_mm", series, min_mm, max_mm)


def default_q_values() -> np.ndarray:
    """The diameter quotients :func:`select_worm` tries when none are given: the ISO 3 R10 preferred numbers
    6.3 … 25 (no worm standard's q series could be cited; see the module docstring).

    >>> default_q_values().tolist()
    [6.3, 8.0, 10.0, 12.5, 16.0, 20.0, 25.0]
    """
    return preferred_numbers("R10", 6.3, 25.0)


@dataclass
class WormSelection(RankedTable):
    """The ranked worm pairs of :func:`select_worm`: ``table`` one row per candidate (best first: feasible
    ones, then the smallest ratio error, then the objective), ``best`` its first row when feasible, ``pair()`` the
    :class:`WormPair` of a row, ``choice`` why the first row was chosen."""

    table: object
    ratio: float | None
    a: float | None
    objective: str
    checks: list = field(default_factory=list)
    n_candidates: int = 0
    time_s: float = 0.0

    def pair(self, row: int = 0, **kw) -> WormPair:
        """The :class:`WormPair` of row ``row`` (0: the best); ``kw`` its flank form, rack, lengths."""
        r = self.table.iloc[row]
        return WormPair(float(r["m_x"]), int(r["z1"]), int(r["z2"]), float(r["q"]), float(r["x2"]), **kw)

    @property
    def choice(self) -> str:
        b = self.best
        if b is None:
            return (f"no feasible candidate among {len(self.table)}: the first row fails "
                    f"{self.table.iloc[0]['limiting_check']} least")
        return (f"m_x = {b['m_x']:g} mm, q = {b['q']:g}, z1/z2 = {int(b['z1'])}/{int(b['z2'])} (u = {b['u']:.6g}), "
                f"x2 = {b['x2']:.6g}, a = {b['a']:.6g} mm: {int(self.table['feasible'].sum())} of {len(self.table)} "
                f"candidates feasible; ranked by ratio error, module series, then {self.objective}")

    def __repr__(self) -> str:
        return f"WormSelection({self.choice})"


def select_worm(ratio: float | None = None, a: float | None = None, *, z1=None, z2=None, m_x=None, q=None,
                objective: str = "min_abs_x2", checks: dict | None = None, flank_form: str = "ZA", rack=None,
                ratio_tol: float = RATIO_TOL_DEFAULT) -> WormSelection:
    """Rank worm pairs for a gear ratio ``ratio`` (u = z2/z1) and/or a centre distance ``a`` (mm).

    Candidates: every ``m_x`` (default: the standard modules, :func:`worm_module_series`) × ``q`` (default:
    :func:`default_q_values`) × ``z1`` (default 1 … 4) × ``z2`` (default: the z2 nearest ``ratio``·z1; or given).
    With ``a`` the wheel's shift is x2 = a/m_x − (q + z2)/2 for each, exactly and all at once; without it each
    candidate's x2 is the ``objective`` of :meth:`WormPair.optimize_x2` ("min_abs_x2" or "max_margin") and ``m_x``
    is required. Ranked: feasible first, then the smallest ratio error, then the module's row of the series (the
    first preferred), then the objective, then the largest smallest margin. ``checks`` are the worm's :func:`~geardesign.gears.checks.make_checks` options (the worm length
    check is off: each candidate's worm is as long as its mesh needs). Candidates whose
    ratio misses ``ratio`` by more than ``ratio_tol`` (relative) are left out.

    >>> s = select_worm(12.5, 125, z1=2)               # seed 002's gear motor: u = 12.5 (z2 = 25)
    >>> b = s.best
    >>> int(b["z2"]), bool(b["feasible"]), round(float(b["a"]), 9)
    (25, True, 125.0)
    """
    t0 = time.perf_counter()
    require_choice("objective", objective, X2_OBJECTIVES)
    require_choice("flank_form", flank_form, FLANK_FORMS)
    rack = require_rack(rack)
    if ratio is None and z2 is None:
        raise GearDesignError("select_worm needs ratio or z2")
    if ratio is not None:
        ratio = one_number("ratio", require_range("ratio", ratio, 1.0, 1000.0))
    if a is not None:
        # at most the largest worm the lengths allow (a of 1e308 mm overflowed the wheel's diameters)
        a = one_number("a (center distance)", require_range("a (center distance)", a, 0.0, LENGTH_RANGE_MM[1],
                                                            lo_open=True, unit="mm"))
    elif m_x is None:
        raise GearDesignError("select_worm needs m_x when no centre distance a is given (the size is free)")
    ratio_tol = one_number("ratio_tol", require_range("ratio_tol", ratio_tol, 0.0, 1.0))
    z1s = _values("z1", Z1_DEFAULT if z1 is None else z1, integer=True, lo=Z1_RANGE[0], hi=Z1_RANGE[1])
    ms = worm_module_series() if m_x is None else _values("m_x", m_x, lo=1e-4, hi=1e4)
    qs = default_q_values() if q is None else _values("q", q, lo=1.0, hi=100.0)
    rows = []
    for zz1 in z1s:
        z2s = ([int(round(ratio * zz1))] if z2 is None else _values("z2", z2, integer=True, lo=3, hi=100_000))
        for zz2 in z2s:
            u = zz2 / zz1
            err = 0.0 if ratio is None else u / ratio - 1.0
            if abs(err) > ratio_tol + 1e-12:
                continue
            rows += [(m, qq, int(zz1), int(zz2), u, err) for m in ms for qq in qs]
    if not rows:
        raise GearDesignError(f"no z1/z2 within ratio_tol = {ratio_tol:g} of ratio = {ratio:g} for z1 in {list(z1s)}")
    if len(rows) > CANDIDATES_MAX:
        raise GearDesignError(f"{len(rows)} candidates is too many (at most {CANDIDATES_MAX}): give fewer m_x, q, z1 or z2")
    cand = np.array(rows, dtype=float)
    limits = dict(checks or {})
    # every candidate's worm is as long as its mesh needs (b_1 = b_1min): that check holds by construction
    limits.setdefault("worm_length_min", False)
    cs = _checks.make_checks(kind="worm", **limits)
    names = [c.name for c in cs]
    if a is not None:
        m_, q_, z1_, z2_ = cand[:, 0], cand[:, 1], cand[:, 2], cand[:, 3]
        x2 = a / m_ - (q_ + z2_) / 2.0
        geo = worm_geometry(m_, z1_, z2_, q_, x2, flank_form, rack, validate=False)
        margins = np.column_stack([np.nan_to_num(np.asarray(c.margin(geo), float) * np.ones(len(cand)), nan=-np.inf)
                                   for c in cs])
        exists = (geo["d_f2"] > 0) & np.isfinite(geo["sa2"]) & (geo["eps_alpha"] > 0) & (q_ > 2 * (rack.ha + rack.c))
        a_col, eps, gam = geo["a"], geo["eps_alpha"], geo["gamma_m_deg"]
    else:
        x2, margins, exists, a_col, eps, gam = [], [], [], [], [], []
        for m, qq, zz1, zz2, _, _ in rows:
            try:
                res = WormPair(m, zz1, zz2, qq, 0.0, flank_form, rack).optimize_x2(objective, **limits)
            except GearDesignError:
                x2.append(np.nan), margins.append([-np.inf] * len(cs)), exists.append(False)
                a_col.append(np.nan), eps.append(np.nan), gam.append(np.nan)
                continue
            x2.append(res.x2), margins.append([res.margins[n] for n in names]), exists.append(True)
            a_col.append(res.a), eps.append(res.eps_alpha), gam.append(math.degrees(math.atan2(zz1, qq)))
        x2, margins, exists = np.array(x2), np.array(margins, float).reshape(len(rows), len(cs)), np.array(exists)
        a_col, eps, gam = np.array(a_col), np.array(eps), np.array(gam)
    return _ranked(cand, x2, margins, names, exists, a_col, eps, gam, ratio, a, objective, t0)


def _ranked(cand, x2, margins, names, exists, a_col, eps, gam, ratio, a, objective, t0) -> WormSelection:
    import pandas as pd   # only for the table

    tol = _checks.FEASIBILITY_TOL
    margins = np.where(exists[:, None], margins, -np.inf)
    worst = margins.min(axis=1)
    limiting = [names[i] for i in margins.argmin(axis=1)]
    table = pd.DataFrame({"m_x": cand[:, 0], "q": cand[:, 1], "z1": cand[:, 2].astype(int),
                          "z2": cand[:, 3].astype(int), "u": cand[:, 4], "ratio_error": cand[:, 5], "x2": x2,
                          "a": a_col, "gamma_m_deg": gam, "eps_alpha": eps, "min_margin": worst,
                          "limiting_check": limiting, "feasible": exists & (worst >= -tol)})
    for j, n in enumerate(names):
        table[f"margin_{n}"] = margins[:, j]
    moving = [f"margin_{n}" for n in names if n in _X2_SENSE]   # the margins x2 moves (the objective's)
    goal = np.abs(table["x2"]) if objective == "min_abs_x2" else -table[moving].min(axis=1)
    # the module's row of the series (1 preferred to 2: "При выборе m 1-й ряд следует предпочитать 2-му", the
    # course-design guide the catalog cites); 3: a module outside the series
    frame = load_catalog("worm_modules")
    rows = dict(zip(frame["module_mm"].round(9), frame["series"]))
    table.insert(1, "module_series", [int(rows.get(round(float(v), 9), 3)) for v in table["m_x"]])
    table = (table.assign(_f=~table["feasible"], _e=table["ratio_error"].abs().round(12), _s=table["module_series"],
                          _g=goal, _w=-table["min_margin"])
             .sort_values(["_f", "_e", "_s", "_g", "_w"], kind="stable").drop(columns=["_f", "_e", "_s", "_g", "_w"])
             .reset_index(drop=True))
    return WormSelection(table=table, ratio=ratio, a=a, objective=objective, checks=names, n_candidates=len(table),
                         time_s=time.perf_counter() - t0)


def _values(name, value, integer=False, lo=None, hi=None) -> list:
    """One number or a list of them, each checked (integers for tooth counts), as a sorted list."""
    try:
        items = [value] if np.ndim(value) == 0 else list(np.ravel(np.asarray(value, dtype=object)))
    except ValueError:          # a ragged list: no shape to read
        raise GearDesignError(f"{name} must be a number or a flat list of them, got {_show(value)}") from None
    if not items:
        raise GearDesignError(f"{name} must be a number or a non-empty list, got {_show(value)}")
    out = []
    for v in items:
        if integer:
            out.append(int(one_number(name, require_int(name, v, lo, hi))))
        else:
            out.append(one_number(name, require_range(name, v, lo, hi)))
    return sorted(set(out))
