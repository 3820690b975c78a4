"""Every margin of every chain candidate, vectorised: speed limits, breaking-load safety, the
hinge-pressure or power-rating checks, and the limiting check."""
from __future__ import annotations

import numpy as np

from ...errors import GearDesignError
from .candidates import Candidates, layout
from .formulas import interp_speed, hinge_pressure_mpa, rated_power_link_plate_kw, rated_power_roller_bushing_kw, safety_factor
from .inputs import Inputs
from .tables import ReferenceTables, strand_index


def _lookup_by_pitch(pitches: np.ndarray, match: np.ndarray, table_n: np.ndarray, table_y: np.ndarray, n1: float):
    """Interpolate a table along n1 for each distinct pitch; returns (values, status) per candidate.

    ``match[i, j]`` says whether table row j belongs to the i-th distinct pitch (np.unique
    order). Status as in :func:`interp_speed`; 2 where no row matches (value NaN).
    """
    _, inverse = np.unique(pitches, return_inverse=True)
    if np.ndim(n1):
        return _lookup_per_candidate(inverse, match, table_n, table_y, np.asarray(n1, dtype=float))
    values = np.full(len(match), np.nan)
    status = np.full(len(match), 2, dtype=np.int64)
    for i in np.flatnonzero(match.any(axis=1)):
        rows = match[i]
        values[i], status[i] = interp_speed(table_n[rows], table_y[rows], n1)
    return values[inverse], status[inverse]


def _lookup_per_candidate(inverse, match, table_n, table_y, n1):
    """:func:`_lookup_by_pitch` when each candidate has its own speed n1 (same rule as
    :func:`interp_speed`: the first value below the table with status -1, NaN above it with 1)."""
    values = np.full(len(n1), np.nan)
    status = np.full(len(n1), 2, dtype=np.int64)
    for i in np.flatnonzero(match.any(axis=1)):
        mine = inverse == i
        tn, ty, n = table_n[match[i]], table_y[match[i]], n1[mine]
        below, above = n < tn[0], n > tn[-1]
        values[mine] = np.where(below, ty[0], np.where(above, np.nan, np.interp(n, tn, ty)))
        status[mine] = np.where(below, -1, np.where(above, 1, 0))
    return values, status


def _pressure_groups(unique_pitches, pitch_min, pitch_max, tol=1e-6):
    """match[i, j]: the i-th pitch lies in the j-th row's pitch group of the [p] table."""
    p = unique_pitches[:, None]
    return (pitch_min[None, :] - tol <= p) & (p <= pitch_max[None, :] + tol)


def _speed_limits(c: Candidates, inp: Inputs, tables: ReferenceTables) -> None:
    """Maximum small-sprocket speed n1_max and allowed impacts per second [w] of each pitch.

    A pitch matches a table row within np.isclose (atol 1e-6 mm); a pitch without a row gets
    NaN (the check then has no table data). Source: catalogs/chain_speed_limits.csv.
    Raises GearDesignError (hinge-pressure method) when n1 is above the limit of every pitch.
    """
    t = c["pitch_mm"]
    unique, inverse = np.unique(t, return_inverse=True)
    close = np.isclose(tables.speed_pitch_mm[None, :], unique[:, None], atol=1e-6)
    match = np.where(close.any(axis=1), close.argmax(axis=1), -1)
    n_max_u = np.where(match >= 0, tables.n1_max_rpm[match], np.nan)
    w_max_u = np.where(match >= 0, tables.impacts_allowed_per_s[match], np.nan)
    if (inp.method == "hinge_pressure" and np.ndim(inp.n1) == 0 and np.isfinite(n_max_u).any()
            and inp.n1 > np.nanmax(n_max_u)):
        j = int(np.nanargmax(n_max_u))
        raise GearDesignError(
            f"n1_rpm = {inp.n1:g} rpm is above the maximum speed of every chain in {str(inp.catalog)!r} "
            f"(the fastest, pitch {unique[j]:g} mm, allows {n_max_u[j]:g} rpm); use a belt or gear stage first")
    c["n1_max_rpm"] = n_max_u[inverse]
    c["allowable_impacts_per_s"] = w_max_u[inverse]


def _safety_check(c: Candidates, inp: Inputs, tables: ReferenceTables, notes: list) -> None:
    """Breaking-load safety s (:func:`safety_factor`) against [s]: margin s/[s] − 1.

    [s] is the override or the catalogs/chain_safety_factor.csv value of the pitch,
    interpolated linearly along n1 (its lowest-speed column below the table, with a note).
    """
    c["safety_factor"] = safety_factor(c["breaking_load_n"], c["force_n"], inp.k_d, c["mass_kg_m"],
                                       c["speed_m_s"], c["center_distance_mm"], inp.sag)
    t = c["pitch_mm"]
    if inp.allowable_safety_factor is not None:
        s_allow = np.full(t.shape, inp.allowable_safety_factor)
    else:
        pitch, n1_rpm, value = tables.safety
        match = np.isclose(pitch[None, :], np.unique(t)[:, None], rtol=0, atol=1e-6)
        s_allow, s_status = _lookup_by_pitch(t, match, n1_rpm, value, inp.n1)
        if (s_status == -1).any():
            notes.append(f"n1 = {_speed_text(inp.n1)} rpm is below the [s] table: its lowest-speed column is used")
    c["allowable_safety_factor"] = s_allow
    c["margin_safety"] = c["safety_factor"] / s_allow - 1.0


def _hinge_checks(c: Candidates, inp: Inputs, tables: ReferenceTables, notes: list) -> list:
    """Hinge-pressure method: p = F_t·K_e/(A·m_eff) against [p], n1 against n1_max, w against [w].

    Margins 1 − p/[p], 1 − n1/n1_max, 1 − w/[w] (Chernavsky, course design of machine parts).
    m_eff = strands·K_m from catalogs/chain_strand_factors.csv; [p] is the override or
    catalogs/chain_allowable_pressure.csv interpolated along n1, never extrapolated above the
    table (NaN: the check has no data). Returns the names of the checks that decide feasibility.
    """
    t = c["pitch_mm"]
    m_eff = tables.hinge_strand_factor[strand_index(tables, c["strands"])]
    p = hinge_pressure_mpa(c["force_n"], inp.k_e, c["hinge_area_mm2"], m_eff)
    if inp.allowable_pressure_mpa is not None:
        p_allow = np.full(t.shape, inp.allowable_pressure_mpa)
    else:
        lo, hi, n1_rpm, value = tables.pressure
        p_allow, p_status = _lookup_by_pitch(t, _pressure_groups(np.unique(t), lo, hi), n1_rpm, value, inp.n1)
        if (p_status == -1).any():
            notes.append(f"n1 = {_speed_text(inp.n1)} rpm is below the [p] table (50 rpm): the 50 rpm value is used "
                         "(conservative: [p] falls with speed)")
        if (p_status == 1).any():
            notes.append(f"n1 = {_speed_text(inp.n1)} rpm is above the [p] table for some pitches: no extrapolation, "
                         "those candidates fail with 'pressure (no [p] data)'")
    c["strand_factor"] = m_eff
    c["pressure_mpa"] = p
    c["allowable_pressure_mpa"] = p_allow
    c["margin_pressure"] = 1.0 - p / p_allow
    c["margin_speed"] = 1.0 - inp.n1 / c["n1_max_rpm"]
    c["margin_impacts"] = 1.0 - c["impacts_per_s"] / c["allowable_impacts_per_s"]
    return ["margin_pressure", "margin_safety", "margin_speed", "margin_impacts"]


def _power_checks(c: Candidates, inp: Inputs, tables: ReferenceTables, notes: list) -> list:
    """Power-rating method: rated power of the strands against the design power P·K_e.

    Rated power = min(link-plate, roller-bushing rating) of one strand (ANSI B29.1 formulas,
    :func:`rated_power_link_plate_kw`, :func:`rated_power_roller_bushing_kw`; K from the
    catalog's rating_k_plate / rating_k_roller columns, else 0.004 and 17) times the
    multiple-strand factor of catalogs/chain_strand_factors.csv; margin P_rated/P_design − 1.
    The hinge pressure is reported at K_e = 1 and not checked. Returns the check names.
    """
    t, z1a = c["pitch_mm"], c["z1"].astype(float)
    k_pl = c["rating_k_plate"] if "rating_k_plate" in c else np.full(t.shape, 0.004)
    k_rb = c["rating_k_roller"] if "rating_k_roller" in c else np.full(t.shape, 17.0)
    m_pow = tables.power_strand_factor[strand_index(tables, c["strands"])]
    plate = rated_power_link_plate_kw(z1a, inp.n1, t, k_pl)
    roller = rated_power_roller_bushing_kw(z1a, inp.n1, t, k_rb)
    c["strand_factor"] = m_pow
    c["rated_power_kw"] = np.minimum(plate, roller) * m_pow
    c["rating_limit"] = np.where(plate <= roller, "link_plate", "roller_bushing")
    c["design_power_kw"] = np.full(t.shape, inp.power_w / 1000.0 * inp.k_e)
    c["margin_power"] = c["rated_power_kw"] / c["design_power_kw"] - 1.0
    c["pressure_mpa"] = hinge_pressure_mpa(c["force_n"], 1.0, c["hinge_area_mm2"], m_pow)
    c["allowable_pressure_mpa"] = np.full(t.shape, np.nan)
    if not str(inp.catalog).startswith("ansi") and not str(inp.catalog).startswith("iso606a"):
        notes.append("power ratings use the ANSI B29.1 formulas; for chains that are not ANSI/ISO A series "
                     "they are an approximation")
    return ["margin_power"]


def _speed_text(n1) -> str:
    """n1 for a note: the one speed, or the range when each candidate has its own."""
    return f"{n1:g}" if np.ndim(n1) == 0 else f"{np.min(n1):g}…{np.max(n1):g}"


def _limiting_check(c: Candidates, checks: list) -> None:
    """The smallest margin of each candidate, the check it belongs to, and feasibility.

    A check without table data (NaN margin) cannot pass but is named as limiting only when
    every check that has data holds; a candidate is feasible when every margin is >= 0.
    """
    margins = np.column_stack([np.asarray(c[k], dtype=float) for k in checks])
    no_data = np.isnan(margins)
    rows = np.arange(len(c))
    worst = np.argmin(np.where(no_data, np.inf, margins), axis=1)
    min_margin = np.where(no_data.all(axis=1), np.nan, margins[rows, np.minimum(worst, len(checks) - 1)])
    names = np.array([k[len("margin_"):] for k in checks], dtype=object)
    missing = np.argmax(no_data, axis=1)
    show_missing = no_data.any(axis=1) & ~(min_margin < 0)
    c["min_margin"] = min_margin
    c["limiting_check"] = np.where(show_missing, names[missing] + " (no table data)", names[worst])
    c["feasible"] = ~no_data.any(axis=1) & (min_margin >= 0)


def evaluate(c: Candidates, inp: Inputs, tables: ReferenceTables, summary: bool = True) -> tuple[list, list]:
    """Every check of every candidate, vectorised: layout, speed limits, safety, the method's checks.

    ``inp.n1``, ``inp.power_w`` and ``inp.torque`` are one load for all candidates (:func:`design`)
    or arrays aligned with them (a drive, where each candidate's load follows the ratio split
    upstream; see :func:`with_loads`): the same formulas either way, and a speed above every
    chain's limit then fails the speed check of those candidates instead of stopping the design.
    ``summary=False`` leaves out min_margin, limiting_check and feasible (a caller that combines
    the margins with its own checks computes them itself).

    Returns (checks, notes): the margin columns that decide feasibility, in report order, and
    the notes about table ranges.
    """
    notes: list[str] = []
    layout(c, inp)
    _speed_limits(c, inp, tables)
    _safety_check(c, inp, tables, notes)
    cd_check = ["margin_center_distance"] if inp.center_distance_mm is not None else []
    if inp.method == "hinge_pressure":
        checks = _hinge_checks(c, inp, tables, notes) + cd_check
    else:
        checks = (_power_checks(c, inp, tables, notes) + cd_check
                  + (["margin_safety"] if inp.allowable_safety_factor is not None else []))
    if summary:
        _limiting_check(c, checks)
    return checks, notes
