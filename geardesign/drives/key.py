"""Parallel keys (GOST 23360-78 / DIN 6885-1): selection and load capacity.

Checks, each a margin (>= 0 holds):

- crushing (bearing) of the key flank in the hub, σ = 2T / (d·(h − t1)·l_p·n_eff): ``1 − σ/[σ]``;
- shear of the key, τ = 2T / (d·b·l_p·n_eff): ``1 − τ/[τ]``;

with l_p the working length (l − b for rounded ends, l − b/2 for one rounded end, l for flat
ends) and n_eff = 1 for one key, 2·0.75 = 1.5 for two keys at 180° (load-sharing factor 0.75).
T in N·mm inside (N·m at the interface), lengths in mm, stresses in MPa.

Sources (docs/references.md): the crushing and shear formulas of GOST 23360-78 course-design
practice (worked example http://3-net.ru/sign/sign-256685.php; https://dzen.ru/media/kbsemenov/
raschet-shponochnyh-soedinenii-648c556c0cc0384792bfe899); the two-key load-sharing factor 0.75 (the
same dzen.ru page; https://www.mechanixcalc.com/standards/din-6885, DIN 6885 after Roloff/Matek).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..catalogs.tables import key_lengths_mm, load_catalog
from ..errors import GearDesignError
from ..results import Result
from ..validate import one_number, require_count, require_positive, require_range

from typing import TYPE_CHECKING

if TYPE_CHECKING:       # pandas is imported where a table is made (start-up cost)
    import pandas as pd

__all__ = ["KeySelection", "select", "capacity", "section", "crushing_stress_mpa", "shear_stress_mpa",
           "working_length_mm", "DEFAULT_CRUSH_MPA", "DEFAULT_SHEAR_MPA", "TWO_KEY_FACTOR"]

# Defaults (low confidence, single sources; docs/references.md): [σ] = 130 MPa, improved-steel hub, from the
# 3-net.ru worked example (key 12x8, d = 40, T = 250 N·m); [τ] = 85 MPa, steel 45 key under pulsating load,
# from a published course-design key calculator whose own source is not stated.
DEFAULT_CRUSH_MPA = 130.0
DEFAULT_SHEAR_MPA = 85.0
TWO_KEY_FACTOR = 0.75
ENDS = ("rounded", "half", "flat")


HUB_ALLOWANCE_MM = 5.0     # key shorter than the hub by 5…10 mm (Dunaev & Lelikov §6.1): the lower end
LENGTH_MAX_MM = 10_000.0   # keys, hubs and shafts up to 10 m; past that the tables say nothing
TORQUE_MAX_NM = 1e9
ALLOWABLE_MPA_MAX = 1e4   # allowable stresses above 10 GPa are typing slips
MAX_KEYS = 2              # one key, or two at 180°: the load-sharing factor (TWO_KEY_FACTOR) is given for two


def working_length_mm(length_mm, b_mm, end="rounded"):
    """Working (bearing) length l_p of a key: l − b (rounded ends), l − b/2 (one), l (flat).

    >>> float(working_length_mm(32, 18))
    14.0
    """
    if end not in ENDS:
        raise GearDesignError(f"end must be one of {', '.join(ENDS)}, got {end!r}")
    cut = {"rounded": 1.0, "half": 0.5, "flat": 0.0}[end]
    return np.asarray(length_mm, dtype=float) - cut * np.asarray(b_mm, dtype=float)


def crushing_stress_mpa(torque_nm, d_mm, h_mm, t1_mm, working_length_mm, n_keys=1):
    """Crushing stress σ = 2T / (d·(h − t1)·l_p·n_eff) [MPa], T in N·m (×1000 inside).

    n_eff = 1 for one key, 1.5 for two keys at 180°.

    Seed 002 (1.9.7) with d = 60, key 18x11 (t1 = 7, so h − t1 = 4 mm), T = 503.129 N·m:
    l_p = 13.976 mm brings σ to the 300 MPa it allows:

    >>> round(float(crushing_stress_mpa(503.129, 60, 11, 7, 2 * 503129 / (60 * 4 * 300))), 6)
    300.0
    """
    n_eff = _n_eff(n_keys)
    k = np.asarray(h_mm, dtype=float) - np.asarray(t1_mm, dtype=float)
    return (2000.0 * np.asarray(torque_nm, dtype=float)
            / (np.asarray(d_mm, dtype=float) * k * np.asarray(working_length_mm, dtype=float) * n_eff))


def shear_stress_mpa(torque_nm, d_mm, b_mm, working_length_mm, n_keys=1):
    """Shear stress τ = 2T / (d·b·l_p·n_eff) [MPa], T in N·m (×1000 inside)."""
    n_eff = _n_eff(n_keys)
    return (2000.0 * np.asarray(torque_nm, dtype=float)
            / (np.asarray(d_mm, dtype=float) * np.asarray(b_mm, dtype=float)
               * np.asarray(working_length_mm, dtype=float) * n_eff))


def _n_eff(n_keys):
    n = np.asarray(n_keys)
    return np.where(n >= 2, 2.0 * TWO_KEY_FACTOR, 1.0)


def section(d_mm) -> pd.Series:
    """The key section (b, h, t1, t2, length range) for a shaft of diameter d (d_over < d <= d_upto).

    >>> s = section(60); (float(s.b_mm), float(s.h_mm), float(s.t1_mm))
    (18.0, 11.0, 7.0)
    """
    keys = load_catalog("keys")
    lo, hi = float(keys["d_over_mm"].iloc[0]), float(keys["d_upto_mm"].iloc[-1])
    d = one_number("d_mm", require_range("d_mm", d_mm, lo, hi, lo_open=True, unit="mm"))
    row = keys[(keys["d_over_mm"] < d) & (d <= keys["d_upto_mm"])].iloc[0]
    return row


@dataclass(frozen=True, eq=False)
class KeySelection(Result):
    """Result of :func:`select`: the chosen key (or why none fits) and every length tried."""

    feasible: bool
    message: str
    d_mm: float
    torque_nm: float
    hub_length_mm: float
    b_mm: float
    h_mm: float
    t1_mm: float
    t2_mm: float
    length_mm: float
    working_length_mm: float
    n_keys: int
    crush_mpa: float
    shear_mpa: float
    allowable_crush_mpa: float
    allowable_shear_mpa: float
    margin_crush: float
    margin_shear: float
    end: str
    candidates: pd.DataFrame

    _success_field = "feasible"
    _table_fields = ("candidates",)

    def __repr__(self) -> str:
        head = (f"KeySelection(d={self.d_mm:g} mm, T={self.torque_nm:g} N·m, hub {self.hub_length_mm:g} mm): "
                f"{self.message}")
        if not self.feasible:
            return head
        return (head + f"\n  key {self.b_mm:g}x{self.h_mm:g}x{self.length_mm:g} ({self.end} ends), t1={self.t1_mm:g} mm, "
                f"n_keys={self.n_keys}, l_p={self.working_length_mm:g} mm"
                f"\n  crush {self.crush_mpa:.1f}/{self.allowable_crush_mpa:g} MPa (margin {self.margin_crush:+.3f}), "
                f"shear {self.shear_mpa:.1f}/{self.allowable_shear_mpa:g} MPa (margin {self.margin_shear:+.3f})")


def select(d_mm, torque_nm, hub_length_mm, allowable_crush_mpa=DEFAULT_CRUSH_MPA,
           allowable_shear_mpa=DEFAULT_SHEAR_MPA, end="rounded", max_keys=2,
           hub_allowance_mm=HUB_ALLOWANCE_MM) -> KeySelection:
    """Pick the parallel key as designers do: the longest standard length that fits the hub
    with its usual allowance, l <= l_hub − (5…10) mm (Dunaev & Lelikov, Konstruirovanie
    uzlov i detalei mashin, §6.1; ``hub_allowance_mm`` = 5 by default), then check it.

    The section (b, h, t1, t2) comes from the shaft diameter; lengths from the standard series,
    within the section's length range where the table gives one. One key first; if it fails,
    two keys of that length at 180° (n_eff = 1.5), and the message says so.
    When nothing fits, ``feasible`` is False and the message says by how much the longest key
    that fits falls short.

    Parameters: d_mm shaft diameter [mm]; torque_nm [N·m]; hub_length_mm [mm];
    allowable_crush_mpa [σ], allowable_shear_mpa [τ] [MPa]; end "rounded" | "half" | "flat";
    max_keys 1 or 2.
    """
    sec = section(d_mm)
    d = float(d_mm)
    torque = one_number("torque_nm", require_range("torque_nm", torque_nm, 0.0, TORQUE_MAX_NM, lo_open=True, unit="N·m"))
    hub = one_number("hub_length_mm", require_range("hub_length_mm", hub_length_mm, 0.0, LENGTH_MAX_MM, lo_open=True, unit="mm"))
    allowance = one_number("hub_allowance_mm", require_range("hub_allowance_mm", hub_allowance_mm, 0.0, 50.0, unit="mm"))
    s_cr = one_number("allowable_crush_mpa", require_range("allowable_crush_mpa", allowable_crush_mpa, 0.0, ALLOWABLE_MPA_MAX, lo_open=True, unit="MPa"))
    s_sh = one_number("allowable_shear_mpa", require_range("allowable_shear_mpa", allowable_shear_mpa, 0.0, ALLOWABLE_MPA_MAX, lo_open=True, unit="MPa"))
    if end not in ENDS:
        raise GearDesignError(f"end must be one of {', '.join(ENDS)}, got {end!r}")
    max_keys = require_count("max_keys", max_keys, 1, MAX_KEYS)
    b, h, t1, t2 = (float(sec[c]) for c in ("b_mm", "h_mm", "t1_mm", "t2_mm"))
    cand, longest = _candidates(sec, d, torque, hub - allowance, s_cr, s_sh, end, max_keys)
    common = dict(d_mm=d, torque_nm=torque, hub_length_mm=hub, b_mm=b, h_mm=h, t1_mm=t1, t2_mm=t2,
                  allowable_crush_mpa=s_cr, allowable_shear_mpa=s_sh, end=end, candidates=cand)
    ok = cand[cand["feasible"] & longest]
    if len(ok):
        row = ok.iloc[0]  # ordered by n_keys, then length: one key before two, shortest first
        rule = (f"the longest standard length <= hub {hub:g} mm - {allowance:g} mm allowance; "
                f"t1 = {t1:g} mm in the shaft, t2 = {t2:g} mm in the hub")
        msg = (f"one key {b:g}x{h:g}x{row['length_mm']:g} ({rule})" if int(row["n_keys"]) == 1 else
               f"one key fails; two keys {b:g}x{h:g}x{row['length_mm']:g} at 180 deg (load-sharing factor "
               f"{TWO_KEY_FACTOR}; {rule})")
        return KeySelection(feasible=True, message=msg, **_key_fields(row), **common)
    if not cand["fits_hub"].any():
        L, lp = cand["length_mm"].to_numpy(), cand["working_length_mm"].to_numpy()
        l_min = float(sec["l_min_mm"]) if np.isfinite(sec["l_min_mm"]) else 0.0
        msg = (f"no standard length of the {b:g}x{h:g} key fits a {hub:g} mm hub with {allowance:g} mm allowance "
               f"(shortest usable {max(l_min, L[lp > 0].min() if (lp > 0).any() else np.inf):g} mm)")
        # no key at all: its figures are absent (None), not numbers
        return KeySelection(feasible=False, message=msg, length_mm=None, working_length_mm=None, n_keys=0,
                            crush_mpa=None, shear_mpa=None, margin_crush=None, margin_shear=None, **common)
    fitting = cand[cand["fits_hub"] & longest]
    best = fitting.assign(m=np.minimum(fitting["margin_crush"], fitting["margin_shear"])).sort_values(
        "m", ascending=False).iloc[0]
    check = "crushing" if best["margin_crush"] <= best["margin_shear"] else "shear"
    msg = (f"nothing fits: the best is {int(best['n_keys'])} key(s) {b:g}x{h:g}x{best['length_mm']:g}, "
           f"which fails {check} with margin {min(best['margin_crush'], best['margin_shear']):+.3f}; "
           f"lengthen the hub, raise the allowable stress or use a spline")
    return KeySelection(feasible=False, message=msg, **_key_fields(best), **common)


def _candidates(sec, d, torque, l_fit, s_cr, s_sh, end, max_keys):
    """Every standard length × 1..max_keys keys with its stresses and margins, and which rows have the
    longest length that fits (``l_fit`` = hub − allowance, within the section's length range)."""
    b, h, t1 = (float(sec[c]) for c in ("b_mm", "h_mm", "t1_mm"))
    lengths = key_lengths_mm()
    l_min = float(sec["l_min_mm"]) if np.isfinite(sec["l_min_mm"]) else 0.0
    l_max = float(sec["l_max_mm"]) if np.isfinite(sec["l_max_mm"]) else np.inf
    n_keys = np.arange(1, max_keys + 1)
    L = np.tile(lengths, len(n_keys))
    N = np.repeat(n_keys, len(lengths))
    lp = working_length_mm(L, b, end)
    fits = (L <= l_fit) & (L >= l_min) & (L <= l_max) & (lp > 0)
    # the rule takes the longest length that fits; shorter ones are listed, not chosen
    longest = L == (L[fits].max() if fits.any() else -1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        lp_pos = np.where(lp > 0, lp, np.nan)
        sig = crushing_stress_mpa(torque, d, h, t1, lp_pos, N)
        tau = shear_stress_mpa(torque, d, b, lp_pos, N)
    import pandas as pd   # here: pandas costs ~0.3 s to import; `geardesign --help` reads this module's constants only

    cand = pd.DataFrame({"n_keys": N, "length_mm": L, "working_length_mm": lp, "fits_hub": fits,
                         "crush_mpa": sig, "shear_mpa": tau, "margin_crush": 1.0 - sig / s_cr,
                         "margin_shear": 1.0 - tau / s_sh})
    cand["feasible"] = fits & (cand["margin_crush"] >= 0) & (cand["margin_shear"] >= 0)
    return cand, longest


def _key_fields(row) -> dict:
    """The chosen (or closest) key's length, count, stresses and margins from a candidates row."""
    return dict(length_mm=float(row["length_mm"]), working_length_mm=float(row["working_length_mm"]),
                n_keys=int(row["n_keys"]), crush_mpa=float(row["crush_mpa"]), shear_mpa=float(row["shear_mpa"]),
                margin_crush=float(row["margin_crush"]), margin_shear=float(row["margin_shear"]))


@dataclass(frozen=True)
class KeyCapacity(Result):
    """Result of :func:`capacity`: the torque a key carries and which stress governs it. Fields are
    also readable as ``cap["torque_nm"]`` (the mapping :func:`capacity` returned before)."""

    torque_nm: float
    torque_crush_nm: float
    torque_shear_nm: float
    governing: str           # "crushing" or "shear"
    working_length_mm: float
    b_mm: float
    h_mm: float
    t1_mm: float
    n_keys: int

    _success_field = "carries"

    @property
    def carries(self) -> bool:
        return self.torque_nm > 0

    def __getitem__(self, name):
        return getattr(self, name)


def capacity(d_mm, length_mm, allowable_crush_mpa=DEFAULT_CRUSH_MPA, allowable_shear_mpa=DEFAULT_SHEAR_MPA,
             b_mm=None, h_mm=None, t1_mm=None, end="rounded", n_keys=1) -> KeyCapacity:
    """The largest torque a key carries [N·m]: the smaller of the crushing and shear limits.

    T_crush = [σ]·d·(h − t1)·l_p·n_eff / 2000, T_shear = [τ]·d·b·l_p·n_eff / 2000 (T in N·m).
    b, h, t1 default to the standard section for d.

    Seed 002 key 18x11x32 on d = 60 with [σ] = 300 MPa: 300·60·4·14/2000 = 504 N·m.

    >>> round(capacity(60, 32, 300, 120)["torque_nm"], 6)
    504.0
    """
    d = one_number("d_mm", require_range("d_mm", d_mm, 0.0, LENGTH_MAX_MM, lo_open=True, unit="mm"))
    if b_mm is None or h_mm is None or t1_mm is None:
        sec = section(d)
        b_mm = float(sec["b_mm"]) if b_mm is None else b_mm
        h_mm = float(sec["h_mm"]) if h_mm is None else h_mm
        t1_mm = float(sec["t1_mm"]) if t1_mm is None else t1_mm
    b = one_number("b_mm", require_positive("b_mm", b_mm, "mm"))
    h = one_number("h_mm", require_positive("h_mm", h_mm, "mm"))
    t1 = one_number("t1_mm", require_range("t1_mm", t1_mm, 0.0, h, lo_open=True, hi_open=True, unit="mm"))
    length = one_number("length_mm", require_range("length_mm", length_mm, 0.0, LENGTH_MAX_MM, lo_open=True, unit="mm"))
    n = require_count("n_keys", n_keys, 1, 2)
    lp = float(working_length_mm(length, b, end))
    if lp <= 0:
        raise GearDesignError(f"length_mm must exceed the rounded ends ({length:g} mm leaves l_p = {lp:g} mm)")
    s_cr = one_number("allowable_crush_mpa", require_range("allowable_crush_mpa", allowable_crush_mpa, 0.0, ALLOWABLE_MPA_MAX, lo_open=True, unit="MPa"))
    s_sh = one_number("allowable_shear_mpa", require_range("allowable_shear_mpa", allowable_shear_mpa, 0.0, ALLOWABLE_MPA_MAX, lo_open=True, unit="MPa"))
    n_eff = float(_n_eff(n))
    t_crush = s_cr * d * (h - t1) * lp * n_eff / 2000.0
    t_shear = s_sh * d * b * lp * n_eff / 2000.0
    return KeyCapacity(torque_nm=min(t_crush, t_shear), torque_crush_nm=t_crush, torque_shear_nm=t_shear,
                       governing="crushing" if t_crush <= t_shear else "shear", working_length_mm=lp,
                       b_mm=b, h_mm=h, t1_mm=t1, n_keys=n)
