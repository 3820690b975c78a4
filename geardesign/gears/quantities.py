"""The pair's geometry as a gear engineer reads it: the handbook's two-column layout (quantity | symbol |
unit | gear 1 | gear 2), with symbols instead of code names (``d_w`` for ``dw1``/``dw2``).

The layout follows the calculation sheets of ISO 21771:2007 (symbols, clause 4) and GOST 16532-70
(Table 1: one line per quantity, one column per gear). The field names of
:data:`~geardesign.gears.geometry.GEOMETRY_FIELDS` stay the keys of ``to_dict()`` and the JSON output;
this module only lays them out.
"""
from __future__ import annotations

import math

__all__ = ["PAIR_ROWS", "GEAR_ROWS", "geometry_table", "geometry_rows", "GEOMETRY_COLUMNS", "SUMMARY_PAIR", "SUMMARY_GEAR"]

# (quantity, symbol, unit, field): one value for the pair
PAIR_ROWS = (
    ("reference centre distance", "a", "mm", "a"),
    ("operating centre distance", "a_w", "mm", "a_w"),
    ("operating pressure angle (transverse)", "α_w", "°", "alpha_w_deg"),
    ("centre distance modification coefficient", "y", "-", "y"),
    ("tip shortening coefficient", "Δy", "-", "dy"),
    ("transverse base pitch", "p_b", "mm", "p_b"),
    ("circular pitch on the operating circle", "p_w", "mm", "p_w"),
    ("length of path of contact", "g_α", "mm", "g_alpha"),
    ("transverse contact ratio", "ε_α", "-", "eps_alpha"),
    ("overlap ratio", "ε_β", "-", "eps_beta"),
    ("total contact ratio", "ε_γ", "-", "eps_gamma"),
    ("specific pressure coefficient at the pitch point", "m/ρ_red", "-", "spec_pressure_pitch"),
    ("transverse module", "m_t", "mm", "m_t"),
    ("transverse pressure angle", "α_t", "°", "alpha_t_deg"),
    ("base helix angle", "β_b", "°", "beta_b_deg"),
)

# (quantity, symbol, unit, field of gear 1, field of gear 2)
GEAR_ROWS = (
    ("reference diameter", "d", "mm", "d1", "d2"),
    ("base diameter", "d_b", "mm", "db1", "db2"),
    ("operating pitch diameter", "d_w", "mm", "dw1", "dw2"),
    ("tip diameter", "d_a", "mm", "da1", "da2"),
    ("root diameter", "d_f", "mm", "df1", "df2"),
    ("tooth thickness on the reference circle", "s", "mm", "s1", "s2"),
    ("tooth thickness on the operating circle", "s_w", "mm", "sw1", "sw2"),
    ("tooth thickness on the tip circle", "s_a", "mm", "sa1", "sa2"),
    ("tip thickness, normal section", "s_an", "mm", "san1", "san2"),
    ("pressure angle at the tip", "α_a", "°", "alpha_a1_deg", "alpha_a2_deg"),
    ("tip-to-root clearance", "c", "mm", "clearance1", "clearance2"),
    ("smallest shift without undercut", "x_min", "-", "x_min1", "x_min2"),
    ("form circle diameter", "d_Ff", "mm", "d_l1", "d_l2"),
    ("start of active profile diameter", "d_Nf", "mm", "d_p1", "d_p2"),
    ("curvature radius at the form point", "ρ_l", "mm", "rho_l1", "rho_l2"),
    ("curvature radius at the start of active profile", "ρ_p", "mm", "rho_p1", "rho_p2"),
    ("specific sliding at the root", "ϑ_root", "-", "sliding1_root", "sliding2_root"),
    ("specific sliding at the tip", "ϑ_tip", "-", "sliding1_tip", "sliding2_tip"),
    ("centre of the mate to this gear's interference point", "O₂N₁ / O₁N₂", "mm", "o2n1", "o1n2"),
    ("virtual tooth count", "z_n", "-", "z_n1", "z_n2"),
)

# the few lines a repr shows
SUMMARY_PAIR = ("a_w", "alpha_w_deg", "y", "dy", "eps_alpha")
SUMMARY_GEAR = ("d", "d_w", "d_a", "d_f", "d_b", "s_a", "ϑ_root")

_HELICAL_ONLY = {"eps_beta", "eps_gamma", "m_t", "alpha_t_deg", "beta_b_deg", "san1", "z_n1"}


def _value(geo, name):
    v = getattr(geo, name, None)
    return None if v is None else float(v)


GEOMETRY_COLUMNS = ("quantity", "symbol", "unit", "gear 1", "gear 2")


def geometry_table(geo, helical: bool | None = None):
    """One pair's :class:`~geardesign.gears.geometry.Geometry` as a DataFrame ``quantity, symbol, unit,
    gear 1, gear 2`` (the pair's own quantities have gear 2 empty). ``helical=False`` leaves out the
    helical-only rows (ε_β, m_t, ...); by default they are shown when β ≠ 0."""
    import pandas as pd

    return pd.DataFrame(geometry_rows(geo, helical), columns=list(GEOMETRY_COLUMNS))


def geometry_rows(geo, helical: bool | None = None) -> list[tuple]:
    """The rows of :func:`geometry_table` as tuples of plain Python values (gear 2 ``None`` for the pair's own
    quantities), without pandas (what ``geardesign pair`` prints)."""
    if helical is None:
        beta = _value(geo, "beta_b_deg")
        helical = beta is not None and math.isfinite(beta) and beta != 0.0
    rows = []
    for quantity, symbol, unit, f in PAIR_ROWS:
        if (f in _HELICAL_ONLY and not helical) or _value(geo, f) is None:
            continue
        rows.append((quantity, symbol, unit, _value(geo, f), None))
    for quantity, symbol, unit, f1, f2 in GEAR_ROWS:
        if (f1 in _HELICAL_ONLY and not helical) or _value(geo, f1) is None:
            continue
        rows.append((quantity, symbol, unit, _value(geo, f1), _value(geo, f2)))
    return rows


def summary_lines(geo) -> list[str]:
    """A dozen lines: the pair's a_w, α_w, y, Δy, ε_α and each gear's main diameters and s_a."""
    pair = {f: (s, u) for _, s, u, f in PAIR_ROWS}
    head = ", ".join(f"{pair[f][0]} = {_fmt(_value(geo, f))}{_unit(pair[f][1])}"
                     for f in SUMMARY_PAIR if _value(geo, f) is not None)
    lines = [f"  {head}", f"  {'':<8}{'unit':<6}{'gear 1':>12}{'gear 2':>12}"]
    for _, symbol, unit, f1, f2 in GEAR_ROWS:
        if symbol in SUMMARY_GEAR and _value(geo, f1) is not None:
            lines.append(f"  {symbol:<8}{unit:<6}{_fmt(_value(geo, f1)):>12}{_fmt(_value(geo, f2)):>12}")
    return lines


def _unit(unit: str) -> str:
    return "" if unit == "-" else unit if unit == "°" else " " + unit


def _fmt(v) -> str:
    return "—" if v is None or not math.isfinite(v) else f"{v:.7g}"
