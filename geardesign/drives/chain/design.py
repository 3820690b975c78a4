"""Chain design as a recipe: validate, load, build the candidates, evaluate, rank, wrap."""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ...catalogs.tables import catalog_dir
from ...results import Result, plain
from .candidates import Candidates, candidate_table
from .checks import evaluate
from .inputs import FACTOR_NAMES, OBJECTIVE_KEYS, Inputs, validate_inputs
from .tables import ReferenceTables, load_chains, reference_tables, strand_index
from .formulas import pitch_estimate_mm, recommended_z1

from typing import TYPE_CHECKING

if TYPE_CHECKING:       # pandas is imported where a table is made (start-up cost)
    import pandas as pd


@dataclass(frozen=True, eq=False)
class ChainDesign(Result):
    """Result of :func:`design`: every candidate ranked, the best feasible one, and why.

    Attributes
    ----------
    candidates : DataFrame, ranked (feasible first, then by the objective).
    best : Series or None, the top feasible candidate.
    success : bool; message : str.
    blocking : DataFrame, per chain family (designation) the candidate closest to passing, its
        limiting check and margin — filled whenever no candidate passes, and always available.
    pitch_estimate_mm : dict strands -> classic pitch estimate (hinge method), a starting point.
    """

    candidates: pd.DataFrame
    best: pd.Series | None
    success: bool
    message: str
    method: str
    objective: str
    catalog: str
    k_e: float
    inputs: dict
    pitch_estimate_mm: dict
    blocking: pd.DataFrame
    notes: tuple = field(default_factory=tuple)

    _table_fields = ("candidates",)

    def to_dict(self) -> dict:
        return plain({
            "status": self.status,
            "success": self.success,
            "message": self.message,
            "method": self.method,
            "objective": self.objective,
            "catalog": self.catalog,
            "k_e": self.k_e,
            "inputs": self.inputs,
            "pitch_estimate_mm": self.pitch_estimate_mm,
            "best": None if self.best is None else dict(self.best.items()),
            "blocking": self.blocking,
            "notes": list(self.notes),
            "n_candidates": int(len(self.candidates)),
            "n_feasible": int(self.candidates["feasible"].sum()),
        })

    def __repr__(self) -> str:
        lines = [f"ChainDesign({self.method}, objective={self.objective}, catalog={self.catalog}, "
                 f"K_e={self.k_e:.4g}): {self.message}"]
        if self.pitch_estimate_mm:
            est = ", ".join(f"{k} strand{'s' if k > 1 else ''}: {v:.2f} mm" for k, v in self.pitch_estimate_mm.items())
            lines.append(f"  pitch estimate t >= {est}")
        if self.best is not None:
            b = self.best
            lines.append(
                f"  best: {b['designation']}  p={b['pitch_mm']:g} mm x{int(b['strands'])}  z1/z2={int(b['z1'])}/{int(b['z2'])}"
                f"  links={int(b['links'])}  a={b['center_distance_mm']:.1f} mm  v={b['speed_m_s']:.3g} m/s"
                f"  F_t={b['force_n']:.0f} N")
            checks = "  ".join(f"{c[7:]}={b[c]:+.3f}" for c in _MARGINS if c in b and np.isfinite(b[c]))
            lines.append(f"  margins: {checks}")
        lines.append(f"  {len(self.candidates)} candidates, {int(self.candidates['feasible'].sum())} feasible")
        return "\n".join(lines)

_MARGINS = ("margin_pressure", "margin_safety", "margin_speed", "margin_impacts", "margin_power")

_RESULT_FRONT = ("rank", "designation", "pitch_mm", "strands", "z1", "z2", "links", "center_distance_mm",
                 "speed_m_s", "force_n", "pressure_mpa", "allowable_pressure_mpa", "safety_factor",
                 "allowable_safety_factor", "mass_kg_m", "feasible", "min_margin", "limiting_check")

_RESULT_TAIL = ("edition", "source", "note")

_BLOCKING_COLUMNS = ("designation", "pitch_mm", "strands", "z1", "feasible", "limiting_check", "min_margin")

# The computed columns, in the order they follow the catalog's own columns before the result
# table puts the main ones first (see _RESULT_FRONT).
_COMPUTED_ORDER = (
    "z1", "z2", "speed_m_s", "force_n", "links", "center_distance_mm",
    "sprocket1_pitch_diameter_mm", "sprocket1_tip_diameter_mm", "sprocket1_root_diameter_mm",
    "sprocket2_pitch_diameter_mm", "sprocket2_tip_diameter_mm", "sprocket2_root_diameter_mm",
    "width_mm", "chain_mass_kg", "impacts_per_s", "breaking_load_n", "margin_center_distance", "safety_factor",
    "n1_max_rpm", "allowable_impacts_per_s", "allowable_safety_factor", "margin_safety", "strand_factor",
    "pressure_mpa", "allowable_pressure_mpa", "margin_pressure", "margin_speed", "margin_impacts",
    "rated_power_kw", "rating_limit", "design_power_kw", "margin_power",
    "min_margin", "limiting_check", "feasible",
)


def _rank(c: Candidates, inp: Inputs) -> np.ndarray:
    """The candidate order: feasible first, then the objective, then smaller pitch, fewer
    strands, z1 nearest the rule z1 = 29 − 2u. A stable sort; NaN objective values go last.
    """
    column, ascending = OBJECTIVE_KEYS[inp.objective]
    key = np.asarray(c[column], dtype=float)
    nan = np.isnan(key)
    key = np.where(nan, 0.0, key if ascending else -key)
    zdist = np.abs(c["z1"] - recommended_z1(inp.u))
    return np.lexsort((zdist, c["strands"], c["pitch_mm"], key, nan, ~c["feasible"]))


def _result_table(c: Candidates, order: np.ndarray, checks: list) -> dict:
    """The ranked candidate table as {column: array}, in the column order users see.

    First rank, the chain, the geometry, the loads, feasibility and the margins that decide it;
    then the other columns (the catalog's, then the computed ones); the catalog's edition,
    source and note last.
    """
    catalog_cols = c.chains.columns
    columns = catalog_cols + [k for k in _COMPUTED_ORDER if k in c.columns and k not in catalog_cols]
    columns += [k for k in c.columns if k not in columns]
    front = list(_RESULT_FRONT) + checks
    rest = [k for k in columns if k not in front and k not in _RESULT_TAIL]
    tail = [k for k in _RESULT_TAIL if k in columns]
    rows = c.rows[order]
    table = {}
    for k in front + rest + tail:
        if k == "rank":
            table[k] = np.arange(1, len(order) + 1)
        elif k in c.columns:
            table[k] = np.asarray(c.columns[k])[order]
        else:
            table[k] = c.chains.take(k, rows)
    return table


def _frame(table: dict, index, attrs: dict) -> pd.DataFrame:
    """A DataFrame of some rows (``index``, or all) of a column table, with the catalog's attrs."""
    import pandas as pd   # here: pandas costs ~0.3 s to import; `geardesign --help` reads this module's constants only

    frame = pd.DataFrame({k: v if index is None else v[index] for k, v in table.items()}, copy=False)
    frame.attrs = dict(attrs)
    return frame


def _blocking(table: dict, attrs: dict) -> tuple[pd.DataFrame, int]:
    """Per chain family (designation) the candidate closest to passing, by pitch and strands.

    Returns the table and the row (in ranked order) of the candidate closest to passing overall
    (largest smallest margin; NaN margins last; ties keep the ranked order).
    """
    mm = np.asarray(table["min_margin"], dtype=float)
    nan = np.isnan(mm)
    by_margin = np.lexsort((np.where(nan, 0.0, -mm), nan))
    first: dict = {}
    for i, name in enumerate(np.asarray(table["designation"], dtype=object)[by_margin].tolist()):
        first.setdefault(name, i)
    keep = by_margin[np.fromiter(first.values(), dtype=np.int64, count=len(first))]
    keep = keep[np.lexsort((table["strands"][keep], table["pitch_mm"][keep]))]
    blocking = _frame({k: table[k] for k in _BLOCKING_COLUMNS}, keep, attrs)
    return blocking, int(by_margin[0])


def _message(best, table: dict, closest: int) -> str:
    """One line: the best candidate and its limiting check, or the candidate closest to passing."""
    if best is not None:
        return (f"{best['designation']} with z1/z2 = {int(best['z1'])}/{int(best['z2'])}, {int(best['links'])} links; "
                f"limiting check {best['limiting_check']} (margin {best['min_margin']:+.3f})")
    return (f"no candidate passes; closest is {table['designation'][closest]} (z1 = {int(table['z1'][closest])}), "
            f"stopped by {table['limiting_check'][closest]} with margin {table['min_margin'][closest]:+.3f}; "
            "see .blocking for every family")


def _pitch_estimates(c: Candidates, inp: Inputs, tables: ReferenceTables) -> dict:
    """Classic pitch estimate (:func:`pitch_estimate_mm`) per strand count, hinge method only.

    [p] is the override or the largest table [p] among that strand count's candidates; z1 the
    first given tooth count or the rule's. A strand count without [p] data gets no estimate.
    """
    estimate = {}
    if inp.method != "hinge_pressure":
        return estimate
    strands, p_allow = c["strands"], np.asarray(c["allowable_pressure_mpa"], dtype=float)
    for s in inp.strands:
        p_ref = inp.allowable_pressure_mpa
        if p_ref is None:
            mine = p_allow[(strands == s) & np.isfinite(p_allow)]   # no [p] at this speed: no estimate
            p_ref = float(mine.max()) if mine.size else np.nan
        z_ref = float(inp.z1_values[0]) if inp.z1_given else float(recommended_z1(inp.u))
        factor = float(tables.hinge_strand_factor[strand_index(tables, np.array([s]))[0]])
        t_est = float(pitch_estimate_mm(inp.torque, z_ref, p_ref, inp.k_e, factor))
        if np.isfinite(t_est):   # no [p] for these pitches and speed: no estimate either
            estimate[s] = t_est
    return estimate


def _inputs_record(inp: Inputs) -> dict:
    """The inputs as the result reports them (``ChainDesign.inputs``)."""
    inputs = dict(torque_nm=inp.torque, power_kw=inp.power_w / 1000.0, n1_rpm=inp.n1, ratio=inp.u, k_e=inp.k_e,
                  k_d=inp.k_d, allowable_pressure_mpa=inp.allowable_pressure_mpa,
                  allowable_safety_factor=inp.allowable_safety_factor, strands=list(inp.strands),
                  z1=[int(z) for z in inp.z1_values] if inp.z1_given else None,
                  center_distance_mm=inp.center_distance_mm, sag_factor=inp.sag)
    if inp.conditions is not None:
        inputs.update({k: getattr(inp.conditions, k) for k in FACTOR_NAMES})
    return inputs


def _wrap_result(c: Candidates, order: np.ndarray, checks: list, notes: list, inp: Inputs,
                 tables: ReferenceTables) -> ChainDesign:
    """Build the ranked candidate table, the best feasible row, the blocking table and the message."""
    attrs = c.chains.attrs
    table = _result_table(c, order, checks)
    candidates = _frame(table, None, attrs)
    best = candidates.iloc[0] if table["feasible"][0] else None
    blocking, closest = _blocking(table, attrs)
    return ChainDesign(candidates=candidates, best=best, success=best is not None,
                       message=_message(best, table, closest), method=inp.method, objective=inp.objective,
                       catalog=str(inp.catalog), k_e=inp.k_e, inputs=_inputs_record(inp),
                       pitch_estimate_mm=_pitch_estimates(c, inp, tables), blocking=blocking, notes=tuple(notes))


def design(torque_nm=None, power_kw=None, *, n1_rpm, ratio, conditions=None, k_e=None,
           allowable_pressure_mpa=None, allowable_safety_factor=None, catalog="gost13568",
           strands=(1, 2, 3), z1=None, center_distance_mm=None, objective="min_mass",
           method="hinge_pressure", sag_factor=6.0, z2_max=120, center_distance_pitches=40.0) -> ChainDesign:
    """Size a roller-chain drive from a catalog.

    Parameters
    ----------
    torque_nm, power_kw : float
        Load on the small (driving) sprocket: give one, torque in N·m or power in kW.
    n1_rpm : float
        Speed of the small sprocket [rpm].
    ratio : float
        Speed ratio u = n1/n2 in [1, 10]; with the smallest small sprocket z1 = 13 the large one
        needs z2 = 13·u <= ``z2_max``, so above z2_max/13 (9.23 at the default 120, the usual limit
        of chain wear elongation) raise ``z2_max`` (at most 250) or split the ratio.
    conditions : Conditions or mapping, optional
        The operating factors K_d, K_a, K_n, K_reg, K_lub, K_mode (numbers or condition names);
        K_e is their product. ``k_e`` gives the product directly (K_d is then taken as 1 in
        the safety factor). Neither: K_e = 1.
    allowable_pressure_mpa, allowable_safety_factor : float, optional
        Override the [p] and [s] tables.
    catalog : str or path
        ``"gost13568"``, ``"iso606"``, ``"iso606a"``, ``"iso606b"``, ``"ansi_b29"`` or a CSV path.
    strands : iterable of int
        Strand counts to consider.
    z1 : int, optional
        Small-sprocket teeth. Default: every odd count from 13 to the rule z1 = 29 − 2u.
    center_distance_mm : float, optional
        Target centre distance; default 40 pitches (30-50 recommended), at least the sprocket
        clearance 0.5·(D_e1 + D_e2) + 30 mm. The link count is the nearest even number and the
        centre distance is recomputed exactly for it.
    objective : {"min_mass", "min_width", "min_sprocket_diameter", "max_safety"}
        min_mass: lightest chain per metre; min_width: narrowest chain over all strands;
        min_sprocket_diameter: smallest tip diameter of the large sprocket; max_safety: largest
        smallest margin. Ties go to the smaller pitch, then to fewer strands.
    method : {"hinge_pressure", "power_rating"}
        hinge_pressure: checks p <= [p], s >= [s], n1 <= n1_max, impacts <= [w] (Russian
        practice, GOST tables). power_rating: rated power of the strands (ANSI link-plate and
        roller-bushing formulas, z1 enters directly, multiple-strand factor) against the design
        power P·K_e; [s] is checked only when ``allowable_safety_factor`` is given.
    sag_factor : float
        k_f of the sag tension (6 horizontal, 1.5 at 40°, 1 vertical).

    The steps: :func:`validate_inputs`, :func:`candidate_table` (catalog rows × z1),
    :func:`evaluate` (every margin, vectorised), :func:`_rank`, :func:`_wrap_result`.
    """
    inp = validate_inputs(torque_nm, power_kw, n1_rpm, ratio, conditions, k_e, allowable_pressure_mpa,
                           allowable_safety_factor, catalog, strands, z1, center_distance_mm, objective, method,
                           sag_factor, z2_max, center_distance_pitches)
    folder = catalog_dir()
    chains = load_chains(inp, folder)
    tables = reference_tables(folder)
    cand = candidate_table(chains, inp)
    checks, notes = evaluate(cand, inp, tables)
    order = _rank(cand, inp)
    return _wrap_result(cand, order, checks, notes, inp, tables)
