"""The strength of one gear pair as a result object: stresses, safety factors, the factor table (every factor
with the clause it comes from), what was given and what left a formula's range."""
from __future__ import annotations

import html
import math
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from ...results import Result, notes_text, plain
from .defaults import MIN_SAFETY_SOURCE

__all__ = ["StrengthResult", "FACTOR_TABLE", "from_chain", "load_case", "case_text"]

P1, P2, P3 = "ISO 6336-1:2019", "ISO 6336-2:2019", "ISO 6336-3:2019"
# (symbol, key in the chain's dict, gear (0 = the pair), clause or equation): every clause names its standard and
# edition, as the chain mixes editions where the 2019 text was not at hand (y_α, y_β, F_βx, f_sh, C_ay, Z_W, Y_β: 2006)
FACTOR_TABLE = (
    ("F_t", "F_t", 0, f"{P1} eq. (1), N"), ("v", "v", 0, f"{P1} eq. (3), m/s"),
    ("K_A", "K_A", 0, f"{P1} 6.3"), ("K_gamma", "K_gamma", 0, f"{P1} 6.4"),
    ("f_pb", "f_pb", 0, "ISO 1328-1:1995 6.3.1 (f_pt cos α_t), µm"), ("f_falpha", "f_falpha", 0, "ISO 1328-1:1995 6.3.4, µm"),
    ("F_beta", "F_beta", 0, "ISO 1328-1:1995 6.3.6, µm"), ("f_Hbeta", "f_Hbeta", 0, "ISO 1328-1:1995 6.3.7, µm"),
    ("c_th", "c_th", 0, f"{P1} eq. (73), (74), N/(mm·µm)"), ("C_B", "C_B", 0, f"{P1} eq. (75)"),
    ("C_R", "C_R", 0, f"{P1} 9.3.3, eq. (72) (1: solid gears)"),
    ("c_prime", "c_prime", 0, f"{P1} eq. (70), (71), N/(mm·µm)"),
    ("c_gamma_alpha", "c_gamma_alpha", 0, f"{P1} eq. (76), N/(mm·µm)"),
    ("c_gamma_beta", "c_gamma_beta", 0, f"{P1} eq. (77), N/(mm·µm)"),
    ("y_alpha", "y_alpha", 0, "ISO 6336-1:2006/Cor.1:2008 8.3.5, µm"), ("C_a", "C_a", 0, "tip relief (C_ay: ISO 6336-1:2006 B.1), µm"),
    ("m_red", "m_red", 0, f"{P1} eq. (30), kg/mm"), ("n_E1", "n_E1", 0, f"{P1} eq. (29), rpm"),
    ("N", "N", 0, f"{P1} eq. (28)"), ("K_v", "K_v", 0, f"{P1} 6.5.9, method B"),
    ("f_sh", "f_sh", 0, "ISO 6336-1:2006 7.6.2.2 eq. (44), µm"), ("f_ma", "f_ma", 0, "f_Hβ (ISO 6336-1:2006 7.6.2.1), µm"),
    ("F_betax", "F_betax", 0, "ISO 6336-1:2006/Cor.1:2008 7.6.2.1, µm"), ("y_beta", "y_beta", 0, "ISO 6336-1:2006 7.6.3, µm"),
    ("f_Kalpha", "f_Kalpha", 0, "deviation in K_Halpha: f_pb, or with transverse_deviation='larger' the larger "
                                "of f_pb, f_falpha (ISO 6336-1:2006 8.3.2), µm"),
    ("K_Hbeta", "K_Hbeta", 0, f"{P1} 7.6, method C"), ("N_F", "N_F", 0, f"{P1} eq. (56)"),
    ("K_Fbeta", "K_Fbeta", 0, f"{P1} eq. (55)"), ("K_Halpha", "K_Halpha", 0, f"{P1} 8.3.2, method B"),
    ("K_Falpha", "K_Falpha", 0, f"{P1} 8.3.2, method B"),
    ("Z_H", "Z_H", 0, f"{P2} eq. (8) at α_wt"), ("Z_E", "Z_E", 0, f"{P2} eq. (11), √MPa"),
    ("Z_eps", "Z_eps", 0, f"{P2} eq. (12)-(14)"), ("Z_beta", "Z_beta", 0, f"{P2} eq. (15)"),
    ("Z_B", "Z_B", 1, f"{P2} clause 6"), ("Z_D", "Z_D", 2, f"{P2} clause 6"),
    ("Z_NT", "Z_NT1", 1, f"{P2} clause 10"), ("Z_NT", "Z_NT2", 2, f"{P2} clause 10"),
    ("Z_L", "Z_L1", 1, f"{P2} eq. (21)"), ("Z_L", "Z_L2", 2, f"{P2} eq. (21)"),
    ("Z_v", "Z_v1", 1, f"{P2} eq. (25)"), ("Z_v", "Z_v2", 2, f"{P2} eq. (25)"),
    ("Z_R", "Z_R1", 1, f"{P2} eq. (27)"), ("Z_R", "Z_R2", 2, f"{P2} eq. (27)"),
    ("Z_W", "Z_W1", 1, "ISO 6336-2:2006 clause 13 (without the 2019 roughness term)"),
    ("Z_W", "Z_W2", 2, "ISO 6336-2:2006 clause 13 (without the 2019 roughness term)"),
    ("Z_X", "Z_X", 0, f"{P2} clause 14"),
    ("Y_F", "Y_F1", 1, f"{P3} clause 6, method B"), ("Y_F", "Y_F2", 2, f"{P3} clause 6, method B"),
    ("Y_S", "Y_S1", 1, f"{P3} clause 7"), ("Y_S", "Y_S2", 2, f"{P3} clause 7"),
    ("Y_Fa", "Y_Fa1", 1, "ISO 6336-3:1996 method C"), ("Y_Fa", "Y_Fa2", 2, "ISO 6336-3:1996 method C"),
    ("Y_Sa", "Y_Sa1", 1, "ISO 6336-3:1996 method C"), ("Y_Sa", "Y_Sa2", 2, "ISO 6336-3:1996 method C"),
    ("Y_eps", "Y_eps", 0, "ISO 6336-3:1996 eq. (20)"), ("Y_beta", "Y_beta", 0, "ISO 6336-3:2006 clause 8 (1 - eps_beta beta/120; the 2019 form is not used)"),
    ("Y_B", "Y_B1", 1, f"{P3} clause 9 (solid gear)"), ("Y_B", "Y_B2", 2, f"{P3} clause 9 (solid gear)"),
    ("Y_DT", "Y_DT", 0, f"{P3} clause 10"),
    ("Y_NT", "Y_NT1", 1, f"{P3} clause 12"), ("Y_NT", "Y_NT2", 2, f"{P3} clause 12"),
    ("Y_deltarelT", "Y_deltarelT1", 1, f"{P3} clause 13"), ("Y_deltarelT", "Y_deltarelT2", 2, f"{P3} clause 13"),
    ("Y_RrelT", "Y_RrelT1", 1, f"{P3} clause 14"), ("Y_RrelT", "Y_RrelT2", 2, f"{P3} clause 14"),
    ("Y_X", "Y_X1", 1, f"{P3} clause 15"), ("Y_X", "Y_X2", 2, f"{P3} clause 15"),
)
# what a flag of the chain means, for the notes
_FLAG_NOTES = {
    "stiffness_out_of_range": "x1, x2 outside the stiffness regression's range (x1 >= x2, -0.5 <= x1 + x2 <= 2, "
                              "ISO 6336-1:2019 9.3.2): c' extrapolated",
    "K_v_resonance": "running in or near the main resonance (N_S < N < 1.5): ISO 6336-1 advises against it",
    "K_Halpha_limited": "K_Halpha capped at eps_gamma/(eps_alpha Z_eps^2) (ISO 6336-1:2019 eq. (64))",
    "K_Falpha_limited": "K_Falpha capped at eps_gamma/(0.25 eps_alpha + 0.75) (ISO 6336-1:2019 eq. (65))",
    "root_out_of_range1": "gear 1: q_s outside [1, 8), the range of the Y_S formula (ISO 6336-3:2019 7.2)",
    "root_out_of_range2": "gear 2: q_s outside [1, 8), the range of the Y_S formula (ISO 6336-3:2019 7.2)",
    "strength_clipped1": "gear 1: yield strength outside the slip-layer table of ISO 6336-3:2019 clause 13, "
                         "clipped to its end for Y_deltarelT",
    "strength_clipped2": "gear 2: yield strength outside the slip-layer table of ISO 6336-3:2019 clause 13, "
                         "clipped to its end for Y_deltarelT",
    "root_unavailable": "root strength not computed: the ISO 6336-3 factor module is not installed",
}
_STRESSES = ("S_H1", "S_H2", "S_F1", "S_F2", "sigma_H0", "sigma_H1", "sigma_H2", "sigma_F1", "sigma_F2",
             "sigma_HP1", "sigma_HP2", "sigma_FP1", "sigma_FP2")


@dataclass(frozen=True)
class StrengthResult(Result):
    """ISO 6336 load capacity of one pair. ``S_H1, S_H2`` (pitting) and ``S_F1, S_F2`` (tooth root) safety
    factors; ``sigma_H0`` nominal and ``sigma_H1, sigma_H2`` contact stresses, ``sigma_F1, sigma_F2`` root
    stresses and ``sigma_HP*``, ``sigma_FP*`` permissible stresses (MPa); ``factors`` a DataFrame with columns
    ``symbol, gear, value, clause`` (gear 0 = the pair); ``given`` the factors taken from the caller;
    ``notes`` the ranges left and limits applied; ``S_Hmin``, ``S_Fmin`` the minimum safety factors; ``case`` (from
    :func:`~geardesign.gears.strength.chain.strength`) what a reader needs to compute σ_HP again: each gear's
    material with σ_Hlim, σ_Flim, the accuracy grade, the lubricant's ν40 and the flank and root roughness."""

    S_H1: float
    S_H2: float
    S_F1: float
    S_F2: float
    sigma_H0: float
    sigma_H1: float
    sigma_H2: float
    sigma_F1: float
    sigma_F2: float
    sigma_HP1: float
    sigma_HP2: float
    sigma_FP1: float
    sigma_FP2: float
    S_Hmin: float
    S_Fmin: float
    _chain: dict = field(repr=False, compare=False)   # the chain's one-design dict: the factor table's source
    given: tuple = ()
    notes: tuple = ()
    title: str = ""
    case: dict | None = None
    _success_field = "ok"
    _table_fields = ("factors",)

    @property
    def factors(self) -> pd.DataFrame:
        """The factor table: columns ``symbol, gear, value, clause`` (built on first use, then kept)."""
        frame = self.__dict__.get("_frame")
        if frame is None:
            frame = pd.DataFrame(_factor_rows(self._chain), columns=["symbol", "gear", "value", "clause"])
            object.__setattr__(self, "_frame", frame)
        return frame

    @property
    def margins(self) -> dict:
        """S/S_min − 1 of the four checks (≥ 0 holds); NaN where a side was not computed."""
        return {"contact1": self.S_H1 / self.S_Hmin - 1.0, "contact2": self.S_H2 / self.S_Hmin - 1.0,
                "root1": self.S_F1 / self.S_Fmin - 1.0, "root2": self.S_F2 / self.S_Fmin - 1.0}

    @property
    def ok(self) -> bool:
        """True when every computed safety factor reaches its minimum (and the root side was computed)."""
        m = self.margins.values()
        return all(math.isfinite(v) for v in m) and all(v >= 0.0 for v in m)

    @property
    def governing(self) -> tuple[str, float]:
        """(check, margin) of the smallest margin: "contact1", "contact2", "root1" or "root2"."""
        finite = {k: v for k, v in self.margins.items() if math.isfinite(v)}
        key = min(finite, key=finite.get)
        return key, finite[key]

    def to_dict(self) -> dict:
        out = super().to_dict()
        out.update(factors=plain(self.factors), ok=self.ok, margins=plain(self.margins), governing=self.governing[0],
                   min_safety_source=MIN_SAFETY_SOURCE)
        return out

    def __repr__(self) -> str:
        check, margin = self.governing
        what = {"contact1": "contact, gear 1", "contact2": "contact, gear 2", "root1": "root, gear 1",
                "root2": "root, gear 2"}[check]
        verdict = "OK" if self.ok else "FAILS"
        lines = [f"StrengthResult{(' ' + self.title) if self.title else ''}: {verdict} "
                 f"(S_Hmin {self.S_Hmin:g}, S_Fmin {self.S_Fmin:g})",
                 f"  {'':9}{'gear 1':>10}{'gear 2':>10}",
                 f"  {'S_H':9}{_col(self.S_H1, '.3f')}{_col(self.S_H2, '.3f')}",
                 f"  {'S_F':9}{_col(self.S_F1, '.3f')}{_col(self.S_F2, '.3f')}",
                 f"  {'sigma_H':9}{_col(self.sigma_H1)}{_col(self.sigma_H2)}  MPa (sigma_H0 {_col(self.sigma_H0).strip()})",
                 f"  {'sigma_HP':9}{_col(self.sigma_HP1)}{_col(self.sigma_HP2)}  MPa",
                 f"  {'sigma_F':9}{_col(self.sigma_F1)}{_col(self.sigma_F2)}  MPa",
                 f"  {'sigma_FP':9}{_col(self.sigma_FP1)}{_col(self.sigma_FP2)}  MPa",
                 f"  governing: {what}, margin {margin:+.1%}"]
        if self.case:
            lines.extend(f"  {line}" for line in case_text(self.case))
        if self.given:
            lines.append(f"  given: {', '.join(self.given)}")
        lines.extend(notes_text(self.notes))
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        verdict = "OK" if self.ok else "FAILS"
        rows = "".join(f"<tr><td>{html.escape(r.symbol)}</td><td>{r.gear}</td><td>{r.value:.5g}</td>"
                       f"<td>{html.escape(r.clause)}</td></tr>" for r in self.factors.itertuples())
        notes = "".join(f"<li>{html.escape(n)}</li>" for n in self.notes)
        return (f"<div><b>StrengthResult {html.escape(self.title)}: {verdict}</b>"
                f"<table><tr><th></th><th>gear 1</th><th>gear 2</th><th>minimum</th></tr>"
                f"<tr><td>S_H</td><td>{self.S_H1:.3f}</td><td>{self.S_H2:.3f}</td><td>{self.S_Hmin:g}</td></tr>"
                f"<tr><td>S_F</td><td>{self.S_F1:.3f}</td><td>{self.S_F2:.3f}</td><td>{self.S_Fmin:g}</td></tr></table>"
                f"<details><summary>factors</summary><table><tr><th>symbol</th><th>gear</th><th>value</th>"
                f"<th>clause</th></tr>{rows}</table></details><ul>{notes}</ul></div>")


def load_case(material1, material2, accuracy_grade, nu40, Rz_flank_um, Rz_root_um) -> dict:
    """The inputs of a strength result a report names (plain values, JSON-ready): each gear's material name,
    σ_Hlim and σ_Flim [MPa] (ISO 6336-5, the catalog row), the ISO 1328-1:1995 accuracy grade, ν40 [mm²/s],
    Rz of flank and root [µm]."""
    out = {}
    for k, mat in ((1, material1), (2, material2)):
        out.update({f"material{k}": mat.name, f"sigma_Hlim{k}_mpa": float(mat.sigma_Hlim_mpa),
                    f"sigma_Flim{k}_mpa": float(mat.sigma_Flim_mpa)})
    out.update(accuracy_grade=plain(accuracy_grade), nu40_mm2_s=float(nu40), Rz_flank_um=float(Rz_flank_um),
               Rz_root_um=float(Rz_root_um))
    return out


def case_text(case: dict) -> list[str]:
    """Two lines of a :func:`load_case`: the materials with σ_Hlim/σ_Flim; the grade, ν40 and the roughness."""
    mats = [f"{case[f'material{k}']} (sigma_Hlim {case[f'sigma_Hlim{k}_mpa']:g}, sigma_Flim {case[f'sigma_Flim{k}_mpa']:g} MPa)"
            for k in (1, 2)]
    mat = f"material {mats[0]}" if mats[0] == mats[1] else f"materials {mats[0]} / {mats[1]}"
    return [mat, f"accuracy grade {case['accuracy_grade']} (ISO 1328-1:1995), nu40 {case['nu40_mm2_s']:g} mm2/s, "
                 f"Rz flank {case['Rz_flank_um']:g} um, root {case['Rz_root_um']:g} um"]


def _col(v: float, fmt: str = ".1f") -> str:
    """A right-aligned column of the repr, 10 wide; a number too long for it in 4 significant digits."""
    text = format(v, fmt)
    return f"{text if len(text) <= 9 else format(v, '.4g'):>10}"


def _scalar(v) -> float:
    return v if type(v) is float else float(np.asarray(v).reshape(-1)[0])


def _factor_rows(out: dict) -> list:
    """(symbol, gear, value, clause) of every factor in the chain's one-design dict."""
    given = set(out.get("given", ()))   # a given factor was not computed by its clause: its row says where it came from
    source = out.get("given_source") or {}
    rows = [(sym, gear, _scalar(out[key]),
             (source.get(key, "given by the caller, not computed") if key in given else clause))
            for sym, key, gear, clause in FACTOR_TABLE if key in out]
    rows.append(("Y_ST", 0, 2.0, "ISO 6336-3:2019 (reference test gear: sigma_FE = sigma_Flim Y_ST)"))
    return rows


def from_chain(out: dict, title: str = "", case: dict | None = None) -> StrengthResult:
    """The :class:`StrengthResult` of a one-design dict of :func:`~geardesign.gears.strength.chain.pair_strength`
    (its factor table built when first read); ``case`` the inputs it was computed with (:func:`load_case`)."""
    notes = []
    for flag, text in _FLAG_NOTES.items():
        if flag in out and (out[flag] if type(out[flag]) is bool else bool(np.any(out[flag]))):
            notes.append(text)
    for name in out.get("given", ()):
        notes.append((out.get("given_source") or {}).get(name) or f"{name} given, not computed")
    for name in out.get("given_unused", ()):
        notes.append(f"{name} given but not used (another given factor or the root method makes it unneeded)")
    fields = {k: _scalar(out[k]) for k in _STRESSES}
    fields.update(S_Hmin=float(out["S_Hmin"]), S_Fmin=float(out["S_Fmin"]), _chain=out,
                  given=tuple(n for n in out.get("given", ()) if n not in (out.get("given_source") or {})),
                  notes=tuple(notes), title=title, case=case)
    # every field set at once: the frozen dataclass's __init__ sets them one by one through object.__setattr__,
    # which costs as much again as the rest of this function (there is no __post_init__ to skip)
    result = object.__new__(StrengthResult)
    result.__dict__.update(fields)
    return result
