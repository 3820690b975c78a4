"""One-page calculation reports as self-contained HTML: a gear pair's inputs, its geometry in the
handbook's two-column layout (quantity | symbol | unit | gear 1 | gear 2), its checks with the
verdict first, the blocking contour and the meshing drawing inline (PNG in the page), printable.

The page has no outside reference (no script, font or picture fetched), so it opens, prints and
archives as one file. It sits in the scene layer because it draws on every layer below it: the
pair (gears), its region and optimum (shifts) and its drawing (profiles).
"""
from __future__ import annotations

import base64
import html
import io
import math
import re
from dataclasses import dataclass
from pathlib import Path

from ..errors import GearDesignError
from ..files import check_output_path, write_file_atomic
from ..gears.checks import DEFAULT_EPS_ALPHA_MIN, DEFAULT_SA_MIN
from ..gears.pair import GearPair
from ..gears.quantities import geometry_table

__all__ = ["pair_report", "pair_report_html", "drive_report", "drive_report_html",
           "handbook_rows"]


_CSS = """
body { font: 13px/1.35 "DejaVu Sans", Arial, sans-serif; color: #111; margin: 18px auto; max-width: 1060px; }
h1 { font-size: 19px; margin: 0 0 4px; } h2 { font-size: 15px; margin: 16px 0 6px; border-bottom: 1px solid #999; }
h3 { font-size: 14px; margin: 12px 0 4px; } h4 { font-size: 13px; margin: 8px 0 3px; }
.verdict { padding: 6px 10px; border-radius: 4px; font-weight: bold; margin: 6px 0 10px; }
.verdict.ok { background: #dff0d8; border: 1px solid #3c763d; color: #2b542c; }
.verdict.fail { background: #f2dede; border: 1px solid #a94442; color: #843534; }
table { border-collapse: collapse; margin: 4px 0; } th, td { border: 1px solid #bbb; padding: 2px 7px; }
th { background: #eee; text-align: left; } td.num { text-align: right; font-variant-numeric: tabular-nums; }
td.span { text-align: center; } tr.failrow td { background: #fbeaea; } td.mark { font-weight: bold; }
.figs { display: grid; grid-template-columns: 1.15fr 0.85fr; gap: 12px; align-items: start; }
figure { margin: 8px 0; } figure img { width: 100%; border: 1px solid #ccc; }
figcaption { font-size: 12px; color: #333; } .small { font-size: 11px; color: #555; }
@media print {
  body { margin: 0; max-width: none; font-size: 10px; line-height: 1.25; } h2 { break-after: avoid; margin: 8px 0 3px; }
  th, td { padding: 0.5px 5px; } h1 { font-size: 15px; } .verdict { padding: 3px 8px; margin: 3px 0 5px; }
  table, figure, .verdict { break-inside: avoid; } .pictures { break-before: page; }
  .figs { grid-template-columns: 1fr; } figure img { max-height: 112mm; width: auto; max-width: 100%; }
  @page { size: A4; margin: 11mm; }
}
"""


def handbook_rows(pair: GearPair) -> list[tuple]:
    """The geometry table's rows: (quantity, symbol in HTML, unit, gear 1, gear 2) as text, from the handbook
    layout of :func:`geardesign.gears.quantities.geometry_table` (one table of rows for the terminal and the
    page); a pair quantity has one value (gear 2 None), shown across both gear columns."""
    table = geometry_table(pair.geometry(), helical=bool(pair.beta_deg))
    rows = [("number of teeth", "z", "–", f"{pair.z1:d}", f"{pair.z2:d}"),
            ("profile shift coefficient", "x", "–", f"{pair.x1:.4f}", f"{pair.x2:.4f}")]
    for quantity, symbol, unit, v1, v2 in table.itertuples(index=False, name=None):
        pair_wide = v2 is None or (isinstance(v2, float) and math.isnan(v2) and not math.isnan(v1))
        fmt = "{:.4f}" if pair_wide else "{:.3f}"
        rows.append((quantity, _html_symbol(symbol), unit.replace("-", "–"), _fmt(fmt, v1),
                     None if pair_wide else _fmt(fmt, v2)))
    return rows


def _html_symbol(symbol: str) -> str:
    """``d_w`` -> d<sub>w</sub>, ``m/ρ_red`` -> m/ρ<sub>red</sub>: the text layout's subscripts for a page."""
    return re.sub(r"_([^\s/]+)", r"<sub>\1</sub>", html.escape(symbol))


def _fmt(fmt: str, value) -> str:
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "–"
    if fmt == "{:d}":
        return fmt.format(int(value))
    text = fmt.format(float(value))
    if text.startswith("-") and float(text) == 0.0:     # a rounding's "-0.0000" is zero
        text = ("+" if "+" in fmt else "") + text[1:]
    return text


@dataclass(frozen=True)
class _Limits:
    eps_alpha_min: float = DEFAULT_EPS_ALPHA_MIN
    sa_min: float = DEFAULT_SA_MIN
    housing_a_w: float | None = None
    eps_gamma_min: float | None = None
    load_case: tuple = ()     # the strength checks' context (load, material, ...) as items

    @property
    def checks(self) -> dict:
        """The limits and the load case as make_checks options."""
        out = {"eps_alpha_min": self.eps_alpha_min, "sa_min": self.sa_min, **dict(self.load_case)}
        if self.eps_gamma_min is not None:
            out["eps_gamma_min"] = self.eps_gamma_min
        return out


def _png(fig) -> str:
    """A matplotlib figure as a data: URL (closed afterwards)."""
    import matplotlib.pyplot as plt

    buf = io.BytesIO()
    try:
        fig.savefig(buf, format="png", dpi=110, bbox_inches="tight")
    finally:
        plt.close(fig)
    return "data:image/png;base64," + base64.b64encode(buf.getvalue()).decode("ascii")


def _pictures(pair: GearPair, lim: _Limits, table) -> tuple[str, str, object]:
    """(contour PNG, mesh PNG, the optimum) of the pair: its region with the pair and the optimum
    marked (on the housing's a_w line when one is given), and its meshing drawing titled with the
    verdict of the report's own checks ``table`` (its limits and load case)."""
    from ..profiles.drawing import plot_mesh
    from ..shifts.optimize import optimize_shifts
    from ..shifts.region import feasible_region

    checks = lim.checks
    kind = dict(rack=pair.rack, tip_shortening=pair.tip_shortening, beta_deg=pair.beta_deg,
                internal=pair.internal, face_width_mm=pair.face_width_mm)
    region = feasible_region(pair.z1, pair.z2, checks=checks, m=pair.m, **kind)
    opt = optimize_shifts(pair.z1, pair.z2, checks=checks, m=pair.m, a_w=lim.housing_a_w, **kind)
    ax = region.plot(optimum=opt if opt.success else None, proposed=(pair.x1, pair.x2), x_sum=opt.x_sum_fixed)
    contour = _png(ax.figure)
    mesh = _png(plot_mesh(pair, checks=table).figure)
    return contour, mesh, opt


def _table(head, rows, classes=None) -> str:
    th = "".join(f"<th>{h}</th>" for h in head)
    body = []
    for i, r in enumerate(rows):
        cls = f' class="{classes[i]}"' if classes and classes[i] else ""
        body.append(f"<tr{cls}>" + "".join(r) + "</tr>")
    return f"<table><thead><tr>{th}</tr></thead><tbody>{''.join(body)}</tbody></table>"


def _td(text, cls="") -> str:
    return f'<td class="{cls}">{text}</td>' if cls else f"<td>{text}</td>"


def _inputs(pair: GearPair, lim: _Limits) -> str:
    r = pair.rack
    rows = [("module", "m" + (" (normal)" if pair.beta_deg else ""), "mm", f"{pair.m:g}"),
            ("numbers of teeth", "z<sub>1</sub>, z<sub>2</sub>", "–", f"{pair.z1}, {pair.z2}"),
            ("profile shift coefficients", "x<sub>1</sub>, x<sub>2</sub>", "–", f"{pair.x1:.4g}, {pair.x2:.4g}"),
            ("kind", "", "", ("internal" if pair.internal else "external") + (" helical" if pair.beta_deg else " spur")),
            ("basic rack: pressure angle, addendum, clearance, root fillet", "α, h<sub>a</sub>*, c*, ρ<sub>f</sub>*",
             "°, –, –, –", f"{r.alpha_deg:g}, {r.ha:g}, {r.c:g}, {r.rho_f:g}"),
            ("tip shortening by Δy·m", "", "", "yes" if pair.tip_shortening else "no")]
    if pair.beta_deg:
        rows.append(("reference helix angle", "β", "°", f"{pair.beta_deg:g}"))
    if pair.face_width_mm is not None:
        rows.append(("face width", "b", "mm", f"{pair.face_width_mm:g}"))
    rows += [("smallest contact ratio", "ε<sub>α,min</sub>", "–", f"{lim.eps_alpha_min:g}"),
             ("smallest tip thickness", "s<sub>a,min</sub>/m", "–", f"{lim.sa_min:g}")]
    if lim.housing_a_w is not None:
        rows.append(("housing centre distance", "a<sub>w</sub>", "mm", f"{lim.housing_a_w:g}"))
    return _table(["input", "symbol", "unit", "value"],
                  [[_td(a), _td(b), _td(c), _td(d, "num")] for a, b, c, d in rows])


def _page(title: str, parts: list) -> str:
    head = (f'<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)}</title>'
            f"<style>{_CSS}</style></head><body>")
    return head + "\n".join(parts) + "</body></html>\n"


def _frame(frame, formats: dict) -> str:
    """A DataFrame as a table, numbers right-aligned in the given formats (others as text)."""
    rows = []
    for _, r in frame.iterrows():
        rows.append([_td(_fmt(formats[c], r[c]), "num") if c in formats else _td(html.escape(str(r[c])))
                     for c in frame.columns])
    return _table([html.escape(str(c)) for c in frame.columns], rows)


def _geometry(pair: GearPair) -> str:
    rows = []
    for name, sym, unit, v1, v2 in handbook_rows(pair):
        cells = [_td(name), _td(sym), _td(unit)]
        cells += [_td(v1, "num"), _td(v2, "num")] if v2 is not None else ['<td class="num span" colspan="2">'
                                                                          f"{v1}</td>"]
        rows.append(cells)
    return _table(["quantity", "symbol", "unit", "gear 1", "gear 2" + (" (ring)" if pair.internal else "")], rows)


def _checks(table) -> tuple[str, str, bool]:
    """(verdict HTML, checks table HTML, all hold) with the failing checks first."""
    t = table.assign(_order=~table["ok"]).sort_values("_order", ascending=False, kind="stable")
    rows, classes = [], []
    for _, r in t.iterrows():
        ok = bool(r["ok"])
        rows.append([_td("holds" if ok else "FAILS", "mark"), _td(html.escape(str(r["check"]))),
                     _td(html.escape(str(r["label"]))), _td(_fmt("{:.5g}", r["value"]), "num"),
                     _td(_fmt("{:.5g}", r["limit"]), "num"), _td(_fmt("{:+.4f}", r["margin"]), "num")])
        classes.append("" if ok else "failrow")
    failed = [f"{html.escape(str(r['check']))} (value {_fmt('{:.5g}', r['value'])}, limit {_fmt('{:.5g}', r['limit'])})"
              for _, r in table.loc[~table["ok"]].iterrows()]
    verdict = ('<div class="verdict ok">Every check holds ({} checks).</div>'.format(len(table)) if not failed else
               '<div class="verdict fail">FAILS: {}</div>'.format("; ".join(failed)))
    return verdict, _table(["verdict", "check", "what it asks", "value", "limit", "margin (≥ 0 holds)"], rows,
                           classes), not failed


def pair_report_html(pair: GearPair, eps_alpha_min: float = DEFAULT_EPS_ALPHA_MIN, sa_min: float = DEFAULT_SA_MIN,
                     housing_a_w: float | None = None, eps_gamma_min: float | None = None,
                     pictures: bool = True, **load_case) -> str:
    """The report of ``pair`` as one HTML page (a string); limits as :meth:`GearPair.checks`; ``load_case``
    (``load``, ``material``, ``material2``, ``face_width_mm``, ``strength``, as a ``checks`` dict takes them)
    adds the strength checks and the ISO 6336 result with its factor table."""
    if not isinstance(pair, GearPair):
        raise GearDesignError(f"pair must be a geardesign.GearPair, got {type(pair).__name__}")
    lim = _Limits(eps_alpha_min, sa_min, housing_a_w, eps_gamma_min, tuple(load_case.items()))
    table = pair.checks(**lim.checks, housing_a_w=housing_a_w)
    verdict, checks, _ = _checks(table)
    title = (f"Gear pair m = {pair.m:g} mm, z<sub>1</sub>/z<sub>2</sub> = {pair.z1}/{pair.z2}, "
             f"x<sub>1</sub> = {pair.x1:.4g}, x<sub>2</sub> = {pair.x2:.4g}")
    from .. import __version__
    parts = [f"<h1>{title}</h1>", verdict, "<h2>Checks</h2>", checks, "<h2>Inputs</h2>", _inputs(pair, lim),
             "<h2>Geometry</h2>", _geometry(pair), *_strength_part(pair, load_case),
             f'<p class="small">geardesign {__version__}. Geometry: ISO 21771:2007; GOST 16532-70 (external), '
             "GOST 19274-73 (internal). Margins are dimensionless, ≥ 0 where a check holds.</p>"]
    if pictures:
        contour, mesh, opt = _pictures(pair, lim, table)
        best = (f"the optimum of {opt.objective} x<sub>1</sub> = {opt.x1:.4f}, x<sub>2</sub> = {opt.x2:.4f} (star)"
                if opt.success else "no feasible optimum")
        parts += ['<h2 class="pictures">Pictures</h2><div class="figs">',
                  f'<figure id="contour"><img alt="blocking contour" src="{contour}"><figcaption>Blocking contour of '
                  f"z<sub>1</sub>/z<sub>2</sub> = {pair.z1}/{pair.z2}: every check's curve, ticks on its forbidden "
                  f"side; this pair (cross) and {best}.</figcaption></figure>",
                  f'<figure id="mesh"><img alt="the pair in mesh" src="{mesh}"><figcaption>The pair in mesh: both '
                  "gears' generated teeth, their circles and the line of action.</figcaption></figure></div>"]
    return _page(f"Gear pair {pair.z1}/{pair.z2}, m = {pair.m:g} mm", parts)


def _strength_part(pair: GearPair, load_case: dict) -> list:
    """The load capacity section: the ISO 6336 result per gear and every factor with its clause."""
    if load_case.get("load") is None:
        return []
    r = pair.strength(load_case["load"], load_case.get("material"), material2=load_case.get("material2"),
                      face_width_mm=load_case.get("face_width_mm"), **(load_case.get("strength") or {}))
    return ["<h2>Load capacity (ISO 6336:2019)</h2>", *strength_html(r, load_case["load"])]


_GOVERNING = {"contact1": "contact (pitting), gear 1", "contact2": "contact (pitting), gear 2",
              "root1": "tooth root, gear 1", "root2": "tooth root, gear 2"}


def strength_case_rows(r) -> list[tuple]:
    """(input, symbol, unit, gear 1, gear 2) of what a :class:`~geardesign.StrengthResult` was computed with:
    each gear's material and its σ_Hlim, σ_Flim (ISO 6336-5), the accuracy grade, the lubricant and the
    roughness (one value for both gears: gear 2 None); with the factor table, enough to compute σ_HP
    (= σ_Hlim Z_NT Z_L Z_v Z_R Z_W Z_X / S_Hmin) and σ_FP again."""
    c = r.case or {}
    if not c:
        return []
    return [("material", "", "", c["material1"], c["material2"]),
            ("contact endurance limit", "σ<sub>Hlim</sub>", "MPa", f"{c['sigma_Hlim1_mpa']:g}", f"{c['sigma_Hlim2_mpa']:g}"),
            ("bending endurance limit", "σ<sub>Flim</sub>", "MPa", f"{c['sigma_Flim1_mpa']:g}", f"{c['sigma_Flim2_mpa']:g}"),
            ("accuracy grade (ISO 1328-1:1995)", "Q", "–", f"{c['accuracy_grade']}", None),
            ("lubricant viscosity at 40 °C", "ν<sub>40</sub>", "mm²/s", f"{c['nu40_mm2_s']:g}", None),
            ("flank roughness (mean of both flanks)", "R<sub>z</sub>", "µm", f"{c['Rz_flank_um']:g}", None),
            ("root roughness", "R<sub>z,root</sub>", "µm", f"{c['Rz_root_um']:g}", None),
            ("minimum safety factors", "S<sub>Hmin</sub>, S<sub>Fmin</sub>", "–", f"{r.S_Hmin:g}, {r.S_Fmin:g}", None)]


def _two_columns(head: list, rows: list) -> str:
    """A (name, symbol, unit, gear 1, gear 2) table; gear 2 None spans both gear columns."""
    out = []
    for name, sym, unit, v1, v2 in rows:
        cells = [_td(html.escape(name)), _td(sym), _td(unit)]
        cells += ([_td(html.escape(str(v1)), "num"), _td(html.escape(str(v2)), "num")] if v2 is not None else
                  [f'<td class="num span" colspan="2">{html.escape(str(v1))}</td>'])
        out.append(cells)
    return _table(head, out)


def strength_html(r, load, level: int = 3) -> list:
    """A :class:`~geardesign.StrengthResult` as page parts: the load, the inputs it was computed with, the
    governing check, S, σ and σ_P per gear, the notes and the factor table (each factor with its clause)."""
    finite = [v for v in r.margins.values() if math.isfinite(v)]
    check, margin = r.governing if finite else (None, math.nan)
    verdict = "holds" if r.ok else "FAILS"
    rows = [[_td(name), _td(_fmt("{:.4g}", a), "num"), _td(_fmt("{:.4g}", b), "num"), _td(_fmt("{:.4g}", lo), "num")]
            for name, a, b, lo in (("safety S<sub>H</sub> (contact)", r.S_H1, r.S_H2, r.S_Hmin),
                                   ("safety S<sub>F</sub> (root)", r.S_F1, r.S_F2, r.S_Fmin),
                                   ("σ<sub>H</sub>, MPa", r.sigma_H1, r.sigma_H2, None),
                                   ("σ<sub>HP</sub>, MPa", r.sigma_HP1, r.sigma_HP2, None),
                                   ("σ<sub>F</sub>, MPa", r.sigma_F1, r.sigma_F2, None),
                                   ("σ<sub>FP</sub>, MPa", r.sigma_FP1, r.sigma_FP2, None))]
    notes = "".join(f"<li>{html.escape(n)}</li>" for n in r.notes)
    h = f"h{level}"
    case = strength_case_rows(r)
    return [f"<p>{load.torque_nm:.6g} N·m at {load.n_rpm:.6g} rpm on gear {load.on_gear} ({load.power_kw:.4g} kW), "
            f"K<sub>A</sub> = {load.application_factor:g}, life " + (f"{load.life_h:g} h" if load.life_h else "endurance")
            + (f". Governing: {_GOVERNING[check]}, margin {margin:+.4f} ({verdict}).</p>" if check else
               ". No safety factor could be computed (see the notes).</p>"),
            *([f"<{h}>Strength inputs</{h}>", _two_columns(["input", "symbol", "unit", "gear 1", "gear 2"], case)]
              if case else []),
            f"<{h}>Safety factors and stresses</{h}>", _table(["", "gear 1", "gear 2", "minimum"], rows),
            f"<ul>{notes}</ul>" if notes else "",
            f"<{h}>Factors (gear 0: the pair)</{h}>", _frame(r.factors, {"value": "{:.6g}"})]


def pair_report(pair: GearPair, path, overwrite: bool = False, **limits):
    """Write the one-page calculation report of ``pair`` to ``path`` (.html): inputs, geometry
    (gear 1 | gear 2), checks with the verdict first, the blocking contour and the meshing
    drawing, self-contained and printable. ``limits``: ``eps_alpha_min``, ``sa_min``,
    ``housing_a_w``, ``eps_gamma_min`` as :meth:`GearPair.checks`, and a load case (``load``,
    ``material``, ``material2``, ``face_width_mm``, ``strength``) for the ISO 6336 section. The file appears whole or not
    at all; an existing one is replaced only with ``overwrite``. Returns the path."""
    p = check_output_path(path, overwrite=overwrite, suffixes=(".html", ".htm"), what="report")
    page = pair_report_html(pair, **limits)
    return write_file_atomic(p, lambda tmp: Path(tmp).write_text(page, encoding="utf-8"))


def _analysis(result):
    """The DriveAnalysis of a Drive (analysed), a DriveOptimum (its best) or an analysis itself."""
    from ..drives.drive import Drive, DriveAnalysis, DriveOptimum

    if isinstance(result, Drive):
        return result.analyse()
    if isinstance(result, DriveOptimum):
        if result.best is None:
            raise GearDesignError(f"the drive optimum has no design to report: {result.message}")
        return result.best
    if isinstance(result, DriveAnalysis):
        return result
    raise GearDesignError(f"a drive report needs a Drive, DriveAnalysis or DriveOptimum, got {type(result).__name__}")


def _stage_overview(an) -> str:
    """One row per stage: kind, u, η, its design in short, and for a gear stage with a material its strength
    (material, the smallest S_H, S_F of each gear, the governing check)."""
    rows = []
    for st in an.stages:
        s = st["summary"]
        rest = ", ".join(f"{k} {_fmt('{:.5g}', v) if isinstance(v, float) else html.escape(str(v))}"
                         for k, v in s.items() if k not in ("name", "kind", "ratio", "efficiency"))
        r = st.get("strength")
        if r is not None:
            finite = any(math.isfinite(v) for v in r.margins.values())
            check, margin = r.governing if finite else (None, math.nan)
            strength = [_td(html.escape(_materials(r))), _td(_fmt("{:.4g}", min(r.S_H1, r.S_H2)), "num"),
                        _td(_fmt("{:.4g}", r.S_F1), "num"), _td(_fmt("{:.4g}", r.S_F2), "num"),
                        _td(f"{_GOVERNING[check]} ({margin:+.4f})" if check else "–")]
        else:
            strength = [_td("–")] * 5
        rows.append([_td(html.escape(str(s["name"]))), _td(s["kind"]), _td(_fmt("{:.5g}", s["ratio"]), "num"),
                     _td(_fmt("{:.3g}", s["efficiency"]), "num"), _td(rest), *strength])
    return _table(["stage", "kind", "u", "η", "design", "material", "S<sub>H</sub>", "S<sub>F1</sub>",
                   "S<sub>F2</sub>", "governing (margin)"], rows)


def _materials(r) -> str:
    c = r.case or {}
    if not c:
        return "–"
    return c["material1"] if c["material1"] == c["material2"] else f"{c['material1']} / {c['material2']}"


def _data_blocks(pair: GearPair, allowances=None) -> str:
    """The drawing's data block of both gears (ISO 1340, GOST 2.403: gear, control sizes, reference data) side by
    side; the control sizes with the stage's shop ``allowances`` (its manufactured state: tooth thickness
    a_sne/a_sni per gear, centre distance a_ai/a_ae, mm) when the analysis gives them, else nominal."""
    from ..gears.data_block import data_block

    if allowances is None:
        a, b = data_block(pair, 1), data_block(pair, 2)
    else:
        centre = (allowances.a_ai, allowances.a_ae)
        a, b = (data_block(pair, g, thickness_allowance_mm=(getattr(allowances, f"a_sne{g}"),
                                                             getattr(allowances, f"a_sni{g}")),
                           center_distance_allowance_mm=centre) for g in (1, 2))
    rows = [[_td(html.escape(str(p))), _td(html.escape(str(sym))), _td(html.escape(str(v1)), "num"),
             _td(html.escape(str(v2)), "num"), _td(html.escape(str(u)))]
            for p, sym, v1, v2, u in zip(a["parameter"], a["symbol"], a["value"], b["value"], a["unit"])]
    return _table(["parameter", "symbol", "gear 1", "gear 2", "unit"], rows)


def _chain_part(st: dict) -> list:
    """A chain stage: the chosen chain and sprockets, the load on the chain and each check's value and limit."""
    row, design = st["row"], st.get("design")
    items = [("chain", "", "", str(row["designation"])), ("pitch", "t", "mm", _fmt("{:.4g}", row["pitch_mm"])),
             ("strands", "", "–", f"{int(row['strands'])}"), ("sprocket teeth", "z<sub>1</sub>, z<sub>2</sub>", "–",
                                                               f"{int(row['z1'])}, {int(row['z2'])}"),
             ("links", "", "–", f"{int(row['links'])}"),
             ("centre distance", "a", "mm", _fmt("{:.1f}", row["center_distance_mm"])),
             ("sprocket pitch diameters", "d<sub>1</sub>, d<sub>2</sub>", "mm",
              f"{row['sprocket1_pitch_diameter_mm']:.2f}, {row['sprocket2_pitch_diameter_mm']:.2f}"),
             ("chain speed", "v", "m/s", _fmt("{:.4g}", row["speed_m_s"])),
             ("chain pull", "F<sub>t</sub>", "N", _fmt("{:.5g}", row["force_n"])),
             ("hinge pressure (allowed)", "p ([p])", "MPa",
              f"{row['pressure_mpa']:.4g} ({row['allowable_pressure_mpa']:.4g})"),
             ("breaking-load safety (required)", "s ([s])", "–",
              f"{row['safety_factor']:.4g} ({row['allowable_safety_factor']:.4g})")]
    if design is not None and getattr(design, "k_e", None) is not None:
        items.append(("service factor", "K<sub>e</sub>", "–", _fmt("{:.4g}", design.k_e)))
    margins = [(k[len("margin_"):], row[k]) for k in row.index if str(k).startswith("margin_")]
    items += [(f"margin: {k}", "", "–", _fmt("{:+.4f}", v)) for k, v in margins]
    return [_table(["quantity", "symbol", "unit", "value"],
                   [[_td(html.escape(a)), _td(b), _td(c), _td(html.escape(d), "num")] for a, b, c, d in items])]


def life_html(r) -> list:
    """A drive stage's service life under its spectrum (ISO 6336-6): the verdict, the damage table (D, life, S per
    gear and mode) and the S-N diagrams with the spectrum on them."""
    return ["<h3>Service life under the spectrum (ISO 6336-6:2019)</h3>",
            f"<p>{r.life_h:.4g} h of {r.required_life_h:.6g} h required ({'holds' if r.ok else 'FAILS'}); S-N curve "
            f"{html.escape(r.sn_curve)}; Y<sub>M</sub> = {'/'.join(f'{v:g}' for v in r.mean_stress_factor)}.</p>",
            _frame(r.damage_table(), {"D": "{:.4g}", "life_h": "{:.4g}", "S": "{:.4g}"}),
            f'<figure><img alt="S-N diagrams" src="{_png(r.plot())}"></figure>']


def _stage_parts(k: int, st: dict) -> list:
    """The section of stage ``k`` of the reducer: a gear pair's geometry, strength and data block; a chain's
    design; a bought unit's ratio, efficiency and rating."""
    s = st["summary"]
    kinds = {"gear": "gear pair", "chain": "roller chain", "given": "bought unit"}
    head = f"<h2>Stage {k}, '{html.escape(str(s['name']))}': {html.escape(kinds.get(s['kind'], s['kind']))}</h2>"
    flow = st.get("flow")
    at = (f"<p>In: {flow.n_in_rpm:.6g} rpm, {flow.torque_in_nm:.6g} N·m; out: {flow.n_out_rpm:.6g} rpm, "
          f"{flow.torque_out_nm:.6g} N·m; u = {s['ratio']:.6g}, η = {s['efficiency']:g}.</p>") if flow is not None else ""
    if s["kind"] == "gear" and isinstance(st.get("pair"), GearPair):
        pair = st["pair"]
        parts = [head, at, "<h3>Geometry</h3>", _geometry(pair)]
        r = st.get("strength")
        if r is not None:
            parts += ["<h3>Load capacity (ISO 6336:2019)</h3>",
                      *strength_html(r, st["stage"].load(flow.torque_in_nm, flow.n_in_rpm), level=4)]
        elif st.get("life") is None:
            parts.append("<p>No material given: the stage's strength is not checked.</p>")
        if st.get("life") is not None:
            parts += life_html(st["life"])
        shop = st.get("allowances")      # the manufactured state the analysis assumed, when it gives one
        what = (f"Control sizes with the allowances of the manufactured state the checks assumed: "
                f"{html.escape(shop.describe())}" if shop is not None else
                "Control sizes: nominal, no tooth-thickness allowance assumed")
        return parts + [f"<h3>Drawing data</h3><p>{what}.</p>", _data_blocks(pair, shop)]
    if s["kind"] == "chain" and st.get("row") is not None:
        return [head, at, *_chain_part(st)]
    # a worm's or a bought unit's summary: its numbers to the overview's precision, not the float's 16 digits
    rest = ", ".join(f"{key} {_fmt('{:.6g}', v) if isinstance(v, float) else html.escape(str(v))}"
                     for key, v in s.items() if key not in ("name", "kind"))
    return [head, at, f"<p>{rest}</p>"]


def drive_report_html(result, pictures: bool = True) -> str:
    """The report of a drive (a reducer) as one HTML page: the verdict, the power flow, the stages in short
    with each gear stage's strength, every check (the smallest margins first), then a section per stage —
    a gear pair's geometry (gear 1 | gear 2), its ISO 6336 strength (material with σ_Hlim and σ_Flim, S, σ
    and σ_P per gear, the governing check, the factor table) and the drawing's data block of both gears; a
    chain's design — the keys and the diagram. ``result``: a Drive (analysed here), a DriveAnalysis or a
    DriveOptimum (its best)."""
    an = _analysis(result)
    t = an.checks.sort_values("margin", kind="stable")
    rows = [[_td("holds" if r["ok"] else "FAILS", "mark"), _td(html.escape(str(r["item"]))),
             _td(html.escape(str(r["check"]))), _td(_fmt("{:+.4f}", r["margin"]), "num")] for _, r in t.iterrows()]
    failed = [f"{html.escape(str(r['item']))}: {html.escape(str(r['check']))} ({_fmt('{:+.4f}', r['margin'])})"
              for _, r in t.loc[~t["ok"]].iterrows()]
    verdict = (f'<div class="verdict ok">Every check holds ({len(t)} checks); smallest margin '
               f"{an.min_margin:+.4f} ({html.escape(an.limiting)}).</div>" if not failed and an.success else
               f'<div class="verdict fail">FAILS: {"; ".join(failed) or html.escape(an.message)}</div>')
    p_in = an.flow["power_kw"].iloc[0]
    parts = [f"<h1>Drive u = {an.total_ratio:.5g}: {p_in:.4g} kW at {an.flow['n_rpm'].iloc[0]:.5g} rpm, "
             f"{len(an.stages)} stage{'s' * (len(an.stages) != 1)}</h1>", verdict,
             "<h2>Power flow</h2>", _frame(an.flow, {"n_rpm": "{:.5g}", "torque_nm": "{:.5g}", "power_kw": "{:.4g}"}),
             "<h2>Stages</h2>", _stage_overview(an),
             "<h2>Checks (smallest margin first; ≥ 0 holds)</h2>",
             _table(["verdict", "item", "check", "margin"], rows, ["" if r["ok"] else "failrow" for _, r in t.iterrows()])]
    for k, st in enumerate(an.stages, start=1):
        parts += _stage_parts(k, st)
    if len(an.keys):
        k = an.keys
        keys = k[["name", "at", "d_mm", "hub_length_mm", "torque_nm"]].assign(
            key_mm=[f"{b:g}×{h:g}×{n:g}" if n == n else "none fits" for b, h, n in zip(k["b_mm"], k["h_mm"], k["length_mm"])],
            n_keys=k["n_keys"], crush_mpa=k["crush_mpa"], shear_mpa=k["shear_mpa"], margin_crush=k["margin_crush"],
            margin_shear=k["margin_shear"])
        parts += ["<h2>Keys</h2>", _frame(keys, {"d_mm": "{:.4g}", "hub_length_mm": "{:.4g}", "torque_nm": "{:.4g}",
                                                 "crush_mpa": "{:.4g}", "shear_mpa": "{:.4g}",
                                                 "margin_crush": "{:+.4f}", "margin_shear": "{:+.4f}"})]
    parts += _shafting_parts(an)
    from .. import __version__
    parts.append(f'<p class="small">geardesign {__version__}. Geometry: ISO 21771:2007; strength: ISO 6336-1, -2, -3:2019 '
                 "(each factor with its clause); data block: ISO 1340:1976, GOST 2.403-75. Margins are dimensionless, "
                 "≥ 0 where a check holds.</p>")
    if pictures:
        diagram = _png(an.plot().figure)
        parts += ['<h2 class="pictures">Diagram</h2>',
                  f'<figure id="diagram"><img alt="drive diagram" src="{diagram}" style="width:auto;max-width:100%">'
                  "<figcaption>The drive seen end-on: each dot a shaft with its speed and torque, black squares "
                  "keyed hubs, rings the bearings of a shaft on bearings (red: one of its checks fails)."
                  "</figcaption></figure>"]
        if getattr(an, "shafting", None) is not None:
            layout = _png(an.plot_layout().figure)
            parts += [f'<figure id="layout"><img alt="shafts and bearings seen from above" src="{layout}" '
                      'style="width:auto;max-width:100%"><figcaption>The shafts seen from above, to scale: '
                      "sections, gears (tip diameter × face width), bearings in the housing walls (dashed)."
                      "</figcaption></figure>"]
    return _page(f"Drive u = {an.total_ratio:.5g}", parts)


_SHAFTING_SECTIONS = (("shafts", "Shafts (DIN 743; the default layout: docs/shafts_in_drive.md)"),
                      ("bearings", "Bearings (ISO 281 L10h)"), ("sections", "Checked sections (DIN 743 S_D, S_F)"),
                      ("seat_keys", "Keys at the seats"), ("gear_deflections", "Deflection and slope at each gear"),
                      ("efficiency", "Efficiency of each stage (ISO/TR 14179-2, SKF)"),
                      ("mesh_misalignment", "K_Hβ from the shafts (ISO 6336-1 method C with their f_sh)"))


def _shafting_parts(an) -> list:
    """A drive with shafting: its overall efficiency and heat, and a table per shafting result."""
    sh = getattr(an, "shafting", None)
    if sh is None:
        return []
    parts = ["<h2>Shafts, bearings and efficiency</h2>",
             f"<p>Overall efficiency {an.overall_efficiency:.5f}; heat to dissipate {1000 * an.heat_kw:.5g} W.</p>"]
    for name, title in _SHAFTING_SECTIONS:
        table = sh.get(name)
        if table is not None and len(table):
            fmt = {c: "{:.5g}" for c in table.columns if table[c].dtype.kind == "f"}
            parts += [f"<h3>{html.escape(title)}</h3>", _frame(table, fmt)]
    return parts


def drive_report(result, path, overwrite: bool = False):
    """Write :func:`drive_report_html` to ``path`` (.html), whole or not at all; an existing file
    is replaced only with ``overwrite``. Returns the path."""
    p = check_output_path(path, overwrite=overwrite, suffixes=(".html", ".htm"), what="report")
    page = drive_report_html(result)
    return write_file_atomic(p, lambda tmp: Path(tmp).write_text(page, encoding="utf-8"))
