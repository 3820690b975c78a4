"""Backlash of a gear pair from its tooth-thickness and centre-distance allowances; the inverse (allowances for
a wanted backlash); the generating profile-shift sum for a backlash at a given centre distance; the GOST 1643-81
fits (mating types H, E, D, C, B, A: the guaranteed least normal backlash j_n,min by centre-distance interval).

The kinds of backlash (ISO 21771:2007 §5.? "Flankenspiel"; ISO/TR 10064-2:1996 §3; notes, trap 9) are kept
apart by name, all in mm:

- ``jt``  circumferential backlash on the operating pitch circle, transverse section (ISO j_wt): the arc gear 1
  turns through with gear 2 held;
- ``jbt`` the same along the transverse line of action, j_bt = j_wt cos α'_wt (exactly r_b1 times that turn);
- ``jbn`` normal backlash, the shortest distance between the non-working flanks, along the line of action in the
  normal section, j_bn = j_bt cos β_b (ISO j_bn; GOST 1643-81's j_n);
- ``jn``  circular backlash in the normal section on the reference cylinder, j_n = j_bn / cos α_n: the sum of the
  two teeth's normal thickness reductions that gives this j_bn at the nominal centre distance;
- ``jr``  radial backlash, the decrease of the centre distance that closes the backlash, j_r = j_wt/(2 tan α'_wt).

A thickness allowance A_sn shifts the flank like a generating profile shift x_E = x ± A_sn/(2 m_n tan α_n)
(:func:`~geardesign.gears.measurement_formulas.generating_shift`), which is how they enter here. The backlash is
computed exactly for the actual centre distance a' = a_w + A_a (α'_wt from cos α'_wt = a cos α_t / a'), not
linearised: j_wt = r'_w1 [2π/z1 − 2(ψ_b1 − inv α'_wt) − 2 (z2/z1)(ψ_b2 ∓ inv α'_wt)], ψ_b = s/d ± inv α_t the
base half-angles (+ external tooth; a ring's tooth ψ + inv α). To first order j_bn = −(A_sn1 + A_sn2) cos α_n
± 2 A_a sin α_wt cos β_b (+ external, − internal: a larger centre distance pushes a pinion into its ring).
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from ..errors import GearDesignError
from ..renamed import renamed_keywords
from ..catalogs.tables import catalog_dir
from ..results import Result
from ..validate import one_number, require_choice, require_range
from .geometry import min_center_distance, require_module, x_sum_from_center_distance
from .involute import inv_from_tan
from .measurement import refuse_thickening
from .measurement_formulas import generating_shift
from .mesh import Mesh, section_constants
from .rack import STANDARD_RACK, BasicRack

__all__ = ["Backlash", "pair_backlash", "backlash_from_shifts", "x_sum_for_backlash", "allowances_for_backlash",
           "gost1643_jn_min", "GOST1643_TYPES", "BACKLASH_KINDS"]

BACKLASH_KINDS = ("jt", "jbt", "jbn", "jn", "jr")
GOST1643_TYPES = ("H", "E", "D", "C", "B", "A")


def backlash_from_shifts(m_n, z1, z2, x1, x2, a_mm, rack: BasicRack = STANDARD_RACK, beta_deg: float = 0.0,
                         internal: bool = False) -> dict:
    """Every kind of backlash (mm, see the module docstring) of gears generated with the shifts x1, x2 (the
    generating shifts x_E when the teeth carry allowances) running at the centre distance ``a_mm``; arrays
    broadcast. Negative values: the teeth would overlap at that distance.

    >>> j = backlash_from_shifts(3, 12, 24, 0.6, 0.36, 56.49987)   # KHK 12/24 at its own a_w: no backlash
    >>> abs(j["jt"]) < 1e-5
    True
    """
    mesh = Mesh(z1, z2, rack, True, beta_deg, internal)
    m_n = require_module(m_n)
    x1, x2 = (require_range(n, v, -10.0, 10.0) for n, v in (("x1", x1), ("x2", x2)))
    a_mm = require_range("a_mm (center distance)", a_mm, 0.0, 1e9, lo_open=True, unit="mm")
    sc = section_constants(rack.alpha, math.radians(mesh.beta_deg))
    z1, z2 = np.asarray(mesh.z1, dtype=float), np.asarray(mesh.z2, dtype=float)
    a_ref = np.asarray(m_n, dtype=float) / sc.cos_beta * ((z2 - z1) if internal else (z1 + z2)) / 2.0
    if np.any(~(np.asarray(a_mm) > a_ref * sc.cos_t)):
        raise GearDesignError(f"a_mm must exceed a cos(alpha_t) = {float(np.min(a_ref * sc.cos_t)):.6g} mm (the base "
                              f"circles' distance), got {float(np.min(a_mm)):g} mm")
    cos_w = a_ref * sc.cos_t / np.asarray(a_mm, dtype=float)
    tan_w = np.sqrt((1.0 - cos_w) * (1.0 + cos_w)) / cos_w
    inv_w, inv_t = inv_from_tan(tan_w), inv_from_tan(sc.tan_t)
    tn = sc.tan_n
    psi1 = (math.pi / 2.0 + 2.0 * np.asarray(x1) * tn) / z1 + inv_t          # s/d + inv α_t
    if internal:
        psi2 = (math.pi / 2.0 - 2.0 * np.asarray(x2) * tn) / z2 - inv_t      # ring: s_y = d_y (ψ + inv α_y)
        turn = 2.0 * math.pi / z1 - 2.0 * (psi1 - inv_w) - 2.0 * (z2 / z1) * (psi2 + inv_w)
    else:
        psi2 = (math.pi / 2.0 + 2.0 * np.asarray(x2) * tn) / z2 + inv_t
        turn = 2.0 * math.pi / z1 - 2.0 * (psi1 - inv_w) - 2.0 * (z2 / z1) * (psi2 - inv_w)
    r_b1 = np.asarray(m_n, dtype=float) / sc.cos_beta * z1 / 2.0 * sc.cos_t
    jbt = r_b1 * turn
    jwt = jbt / cos_w
    jbn = jbt * sc.cos_beta_b
    out = {"jt": jwt, "jbt": jbt, "jbn": jbn, "jn": jbn / math.cos(rack.alpha), "jr": jwt / (2.0 * tan_w)}
    return {k: (float(v) if np.ndim(v) == 0 else v) for k, v in out.items()}


@dataclass(frozen=True)
class Backlash(Result):
    """Least and most backlash of a pair, mm (kinds in :mod:`geardesign.gears.backlash`), and the allowances that
    gave them: ``a_sne1``/``a_sni1``, ``a_sne2``/``a_sni2`` (normal tooth thickness, upper/lower) and the
    centre-distance allowances ``a_ai``/``a_ae`` (lower/upper). ``ok``: the least backlash is >= 0."""

    jt_min: float
    jt_max: float
    jbt_min: float
    jbt_max: float
    jbn_min: float
    jbn_max: float
    jn_min: float
    jn_max: float
    jr_min: float
    jr_max: float
    a_sne1: float
    a_sni1: float
    a_sne2: float
    a_sni2: float
    a_ai: float
    a_ae: float
    a_w: float

    _success_field = "ok"

    @property
    def ok(self) -> bool:
        return self.jbn_min >= 0.0

    def to_frame(self):
        import pandas as pd

        rows = [(k, getattr(self, f"{k}_min"), getattr(self, f"{k}_max")) for k in BACKLASH_KINDS]
        return pd.DataFrame(rows, columns=["kind", "least_mm", "most_mm"])

    def __repr__(self) -> str:
        lines = [f"Backlash(a_w {self.a_w:.4f} mm, A_a {self.a_ai:+.4g}/{self.a_ae:+.4g} mm,"
                 f" A_sn1 {self.a_sne1:+.4g}/{self.a_sni1:+.4g}, A_sn2 {self.a_sne2:+.4g}/{self.a_sni2:+.4g} mm"]
        names = {"jt": "circumferential (operating pitch circle)", "jbt": "transverse, line of action",
                 "jbn": "normal (line of action)", "jn": "normal circular (reference cylinder)", "jr": "radial"}
        for k in BACKLASH_KINDS:
            lines.append(f"  {k:<4} {getattr(self, k + '_min'):.5f} .. {getattr(self, k + '_max'):.5f} mm  {names[k]}")
        return "\n".join(lines) + ")"


def _pair_of(name, value, lo=-1e4, hi=1e4):
    """(upper, lower) or (lower, upper) pairs of one-number allowances, as floats."""
    if isinstance(value, (int, float, np.floating, np.integer)) and not isinstance(value, bool):
        value = (value, value)
    if not (isinstance(value, (tuple, list)) and len(value) == 2):
        raise GearDesignError(f"{name} must be one number or a pair of numbers (mm), got {value!r}")
    return tuple(one_number(name, require_range(name, v, lo, hi, unit="mm")) for v in value)


def pair_backlash(pair, thickness_allowance1_mm=0.0, thickness_allowance2_mm=0.0,
                  center_distance_allowance_mm=0.0) -> Backlash:
    """Least and most backlash of a :class:`~geardesign.gears.pair.GearPair` (mm).

    ``thickness_allowance1_mm``/``2``: (A_sne, A_sni) of each gear's normal tooth thickness (one number: both);
    ``center_distance_allowance_mm``: (A_ai, A_ae), the lower and upper centre-distance allowances (one number f:
    ±|f|). The least backlash has the thickest teeth (A_sne) at the centre distance that closes it (the smallest
    for an external pair, the largest for an internal one); the most the thinnest teeth at the other end.

    >>> from geardesign import GearPair
    >>> b = pair_backlash(GearPair(3, 12, 24, 0.6, 0.36))          # no allowances: no backlash
    >>> abs(b.jt_min) < 1e-12 and abs(b.jt_max) < 1e-12
    True
    """
    sne1, sni1 = _pair_of("thickness_allowance1_mm", thickness_allowance1_mm)
    sne2, sni2 = _pair_of("thickness_allowance2_mm", thickness_allowance2_mm)
    for name, e, i in (("thickness_allowance1_mm", sne1, sni1), ("thickness_allowance2_mm", sne2, sni2)):
        if i > e:
            raise GearDesignError(f"{name}: the lower allowance A_sni = {i:g} mm exceeds the upper A_sne = {e:g} mm")
        refuse_thickening(name, e)
    if isinstance(center_distance_allowance_mm, (tuple, list)):
        ai, ae = _pair_of("center_distance_allowance_mm", center_distance_allowance_mm)
    else:
        f = abs(_pair_of("center_distance_allowance_mm", center_distance_allowance_mm)[0])
        ai, ae = -f, f
    if ai > ae:
        raise GearDesignError(f"center_distance_allowance_mm: the lower A_ai = {ai:g} mm exceeds the upper A_ae = {ae:g} mm")
    m, rack, beta, internal = pair.m, pair.rack, pair.beta_deg, pair.internal
    a_w = float(pair._geo["a_w"])
    if max(abs(ai), abs(ae)) > 0.5 * m:
        raise GearDesignError(f"center_distance_allowance_mm must be within ±{0.5 * m:g} mm (half a module), "
                              f"got ({ai:g}, {ae:g})")
    an = rack.alpha
    x1e, x2e = [generating_shift(pair.x1, a, m, an) for a in (sne1, sni1)], [
        generating_shift(pair.x2, a, m, an, internal) for a in (sne2, sni2)]
    tight, loose = (a_w + ae, a_w + ai) if internal else (a_w + ai, a_w + ae)
    least = backlash_from_shifts(m, pair.z1, pair.z2, x1e[0], x2e[0], tight, rack, beta, internal)
    most = backlash_from_shifts(m, pair.z1, pair.z2, x1e[1], x2e[1], loose, rack, beta, internal)
    vals = {f"{k}_min": least[k] for k in BACKLASH_KINDS} | {f"{k}_max": most[k] for k in BACKLASH_KINDS}
    return Backlash(**vals, a_sne1=sne1, a_sni1=sni1, a_sne2=sne2, a_sni2=sni2, a_ai=ai, a_ae=ae, a_w=a_w)


def _to_jbn(backlash_mm, kind: str, alpha_n, cos_beta_b, cos_wt, tan_wt):
    """A backlash of ``kind`` as the normal backlash j_bn (first-order relations at the operating angle)."""
    if kind == "jbn":
        return backlash_mm
    if kind == "jn":
        return backlash_mm * math.cos(alpha_n)
    if kind == "jbt":
        return backlash_mm * cos_beta_b
    if kind == "jt":
        return backlash_mm * cos_wt * cos_beta_b
    return backlash_mm * 2.0 * tan_wt * cos_wt * cos_beta_b   # jr


def x_sum_for_backlash(m, z1, z2, a_w, backlash_mm, kind: str = "jbn", rack: BasicRack = STANDARD_RACK,
                       beta_deg: float = 0.0, internal: bool = False):
    """The generating profile-shift sum (x_E1 + x_E2; internal x_E2 − x_E1) that gives a backlash of ``kind`` at
    the centre distance a_w (mm); arrays broadcast.

    x_E,Σ = x_Σ(a_w) − j_bn/(2 m_n sin α_n)  for the normal backlash j_bn (``kind="jbn"``), and
    x_E,Σ = x_Σ(a_w) − j_n/(2 m_n tan α_n)   for the circular one j_n in the normal section (``"jn"``)
    (ISO 21771:2007 §5.4 eq. (63) and its circular form: the two differ by sin α_n against tan α_n, trap 9);
    ``"jt"`` (circumferential on the operating pitch circle) and ``"jr"`` go through j_bn = j_wt cos α_wt cos β_b
    and j_wt = 2 j_r tan α_wt. A ring's sum grows instead (its teeth thin with x2). x_Σ(a_w) is the zero-backlash
    sum (:func:`~geardesign.gears.geometry.x_sum_from_center_distance`).

    >>> round(float(x_sum_for_backlash(2.5, 47, 50, 122.0, 0.1, "jt")), 6)   # drivetrainhub: 0.252 (0.306857 − 0.054612)
    0.252245
    """
    kind = require_choice("kind", kind, BACKLASH_KINDS)
    m, z1, z2, a_w, backlash_mm = _checked(m, z1, z2, a_w, backlash_mm, rack, beta_deg, internal)
    sc = section_constants(rack.alpha, math.radians(beta_deg))
    xs0 = np.asarray(x_sum_from_center_distance(m, z1, z2, a_w, rack, beta_deg, internal))
    zs = (np.asarray(z2) - np.asarray(z1)) if internal else (np.asarray(z1) + np.asarray(z2))
    cos_w = np.asarray(m, dtype=float) / sc.cos_beta * zs / 2.0 * sc.cos_t / np.asarray(a_w, dtype=float)
    tan_w = np.sqrt((1.0 - cos_w) * (1.0 + cos_w)) / cos_w
    jbn = _to_jbn(np.asarray(backlash_mm, dtype=float), kind, rack.alpha, sc.cos_beta_b, cos_w, tan_w)
    delta = jbn / (2.0 * np.asarray(m, dtype=float) * math.sin(rack.alpha))
    out = xs0 + delta if internal else xs0 - delta
    return float(out) if np.ndim(out) == 0 else out


def _checked(m, z1, z2, a_w, backlash_mm, rack, beta_deg, internal):
    """The inputs of :func:`x_sum_for_backlash`, each refused by name when out of range."""
    if not isinstance(rack, BasicRack):
        raise GearDesignError(f"rack must be a geardesign.BasicRack, got {type(rack).__name__}")
    mesh = Mesh(z1, z2, rack, True, beta_deg, internal)
    m = require_module(m)
    a_w = require_range("a_w (center distance)", a_w, 0.0, 1e9, lo_open=True, unit="mm")
    j = require_range("backlash_mm", backlash_mm, 0.0, 1e4, unit="mm")
    a_min = min_center_distance(m, mesh.z1, mesh.z2, rack, mesh.beta_deg, mesh.internal)
    if np.any(~(a_w > a_min)):
        raise GearDesignError(f"a_w must exceed a cos(alpha_t) = {float(np.min(a_min)):.6g} mm, got "
                              f"{float(np.min(a_w)):g} mm")
    if np.any(j > np.asarray(m)):
        raise GearDesignError(f"backlash_mm must be at most one module ({float(np.min(m)):g} mm), got {float(np.max(j)):g}")
    return m, mesh.z1, mesh.z2, a_w, j


def allowances_for_backlash(pair, jbn_min_mm: float, center_distance_allowance_mm=0.0, share1: float = 0.5,
                            thickness_tolerance_mm=None) -> dict:
    """Upper tooth-thickness allowances (A_sne1, A_sne2, mm) that give the least normal backlash ``jbn_min_mm`` at
    the tight end of the centre distance (the inverse of :func:`pair_backlash`): their sum from the exact backlash
    (one root-find of a linear function), split ``share1`` : 1 − ``share1``. With ``thickness_tolerance_mm``
    (T_sn1, T_sn2) the lower allowances A_sni = A_sne − T_sn follow, and the most backlash with them.

    >>> from geardesign import GearPair
    >>> p = GearPair(3, 12, 24, 0.6, 0.36)
    >>> a = allowances_for_backlash(p, 0.1)
    >>> round(pair_backlash(p, a["a_sne1"], a["a_sne2"]).jbn_min, 12)
    0.1
    """
    j = one_number("jbn_min_mm", require_range("jbn_min_mm", jbn_min_mm, 0.0, 0.5 * pair.m, unit="mm"))
    s1 = one_number("share1", require_range("share1", share1, 0.0, 1.0))
    probe = pair_backlash(pair, 0.0, 0.0, center_distance_allowance_mm)
    # j_bn is linear in A_sn1 + A_sn2 (each shifts the flank by A cos α_n along the line of action)
    total = -(j - probe.jbn_min) / math.cos(pair.rack.alpha)
    out = {"a_sne1": s1 * total, "a_sne2": (1.0 - s1) * total, "a_ai": probe.a_ai, "a_ae": probe.a_ae}
    if thickness_tolerance_mm is not None:
        t1, t2 = _pair_of("thickness_tolerance_mm", thickness_tolerance_mm, 0.0, 1e4)
        out.update(a_sni1=out["a_sne1"] - t1, a_sni2=out["a_sne2"] - t2)
        out["backlash"] = pair_backlash(pair, (out["a_sne1"], out["a_sni1"]), (out["a_sne2"], out["a_sni2"]),
                                        (probe.a_ai, probe.a_ae))
    return out


@functools.lru_cache(maxsize=1)
def _gost_columns() -> dict:
    """The GOST 1643 table's columns as read-only arrays (read once: a drive's sizing asks per design)."""
    import pandas as pd


    with (catalog_dir() / "gost1643_backlash.csv").open("r", encoding="utf-8") as fh:
        table = pd.read_csv(fh)
    cols = {c: table[c].to_numpy(dtype=float) for c in table.columns if c.startswith(("a_w_", "jn_min_um_"))}
    for v in cols.values():
        v.flags.writeable = False
    return cols


@renamed_keywords(a_w_mm="a_w")
def gost1643_jn_min(mating_type: str, a_w):
    """The guaranteed least normal backlash j_n,min (mm) of a GOST 1643-81 mating type (H, E, D, C, B, A) at the
    centre distance a_w (mm; up to 3150), from ``catalogs/gost1643_backlash.csv`` (GOST 1643-81 Table 13);
    arrays of a_w broadcast. GOST's j_n is the normal backlash j_bn here.

    >>> gost1643_jn_min("C", 100)     # over 80 up to 125 mm: 87 µm
    0.087
    """
    mating_type = require_choice("mating_type", mating_type, GOST1643_TYPES)
    a = require_range("a_w", a_w, 0.0, 3150.0, lo_open=True, unit="mm")
    table = _gost_columns()
    upper = table["a_w_max_mm"]
    col = table[f"jn_min_um_{mating_type}"]
    idx = np.searchsorted(upper, a, side="left")
    out = col[idx] / 1000.0
    return float(out) if np.ndim(out) == 0 else out
