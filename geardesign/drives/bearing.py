"""Rolling bearings: ISO 281 rating life, equivalent loads, static safety, and selection from a catalog.

One function per formula, each with its source; every one takes numpy arrays (a whole catalog at once).
Forces at the interface in N, load ratings in kN (as the catalogs print them), speeds in rpm, lives in
millions of revolutions (``_mrev``) or hours (``_h``).

Sources (docs/references.md, docs/bearings.md):

- ISO 281:2007 basic rating life L10 = (C/P)^p, p = 3 for ball and 10/3 for roller bearings, and
  L10h = 10^6 L10/(60 n), as printed in SKF *Rolling bearings*, PUB BU/P1 17000/1 EN (2018), p. 88-89;
- the equivalent dynamic load P = X Fr + Y Fa with e, X, Y of single row deep groove ball bearings against
  f0 Fa/C0r (the ISO 281 table, normal clearance) and of 40° angular contact ball bearings (e = 1.14,
  X = 0.35, Y = 0.57), the static load P0 and the minimum static safety s0: NTN *Ball and Roller Bearings*
  CAT. No. 2203/E, pp. B-27 (deep groove), B-61 (angular contact), A-31 Table 3.6 (s0);
- single row tapered roller bearings: P = Fr when Fa/Fr <= e, else 0.4 Fr + Y Fa; P0 = 0.5 Fr + Y0 Fa, not
  below Fr; e, Y, Y0 from the product table; the axial load a radial load induces, 0.5 Fr/Y, and the axial
  loads of two bearings adjusted against each other (SKF 17000/1 EN pp. 680-682, Table 7; NTN CAT. 2203/E
  Example 4, p. A-44);
- the life of a system of bearings, L = (Σ L_i^-e)^(-1/e), e = 10/9 ball, 9/8 roller (NTN CAT. 2203/E
  eq. (3.3), p. A-19);
- the reliability factor a1: SKF 17000/1 EN Table 3, p. 90 (values of ISO 281:2007);
- the life modification factor a_ISO (ISO 281:2007 clause 9.3, ball bearings) as printed in IBC *High
  Precision Bearings* TI-I-5050.0/E (2010), p. 158, eqs. (5.37)-(5.39). For roller bearings see
  :func:`life_modification_factor` (lower confidence, stated there).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

import math
from dataclasses import dataclass

import numpy as np

from ..catalogs.tables import load_catalog
from ..errors import GearDesignError
from ..results import RankedTable, Result
from ..renamed import renamed_keywords
from ..validate import broadcast_inputs, one_number, require_choice, require_range

__all__ = ["SERIES", "BEARING_KINDS", "LIFE_EXPONENT", "RELIABILITY_FACTORS", "ANGULAR_CONTACT_40",
           "S0_MIN_NORMAL", "basic_rating_life", "rating_life_hours", "deep_groove_factors",
           "equivalent_dynamic_load", "equivalent_static_load", "static_safety", "reliability_factor",
           "life_modification_factor", "reference_viscosity", "induced_axial_force", "tapered_axial_loads", "system_life",
           "bearing_catalog", "bearing_loads", "check_bearing", "select_bearing", "BearingCheck",
           "BearingSelection", "TAPERED_X", "BEARING_TYPES"]

# series -> (catalog table, bearing kind); the kind says which life exponent and which X/Y rule apply
if TYPE_CHECKING:       # pandas is imported where a catalog is read (the command's start-up stays light)
    import pandas as pd

SERIES = {
    "62": ("bearings_deep_groove", "deep_groove_ball"),
    "63": ("bearings_deep_groove", "deep_groove_ball"),
    "72B": ("bearings_angular_contact", "angular_contact_ball"),
    "73B": ("bearings_angular_contact", "angular_contact_ball"),
    "NU2": ("bearings_cylindrical_roller", "cylindrical_roller"),
    "NU3": ("bearings_cylindrical_roller", "cylindrical_roller"),
    "302": ("bearings_tapered_roller", "tapered_roller"),
    "303": ("bearings_tapered_roller", "tapered_roller"),
    "320X": ("bearings_tapered_roller", "tapered_roller"),
    "322": ("bearings_tapered_roller", "tapered_roller"),
    "323": ("bearings_tapered_roller", "tapered_roller"),
}
BEARING_KINDS = {"deep_groove_ball": "ball", "angular_contact_ball": "ball", "cylindrical_roller": "roller",
                 "tapered_roller": "roller"}
# the short names of the command line's --type -> bearing type
BEARING_TYPES = {"deep_groove": "deep_groove_ball", "angular_contact": "angular_contact_ball",
                 "cylindrical_roller": "cylindrical_roller", "tapered": "tapered_roller"}
LIFE_EXPONENT = {"ball": 3.0, "roller": 10.0 / 3.0}   # ISO 281:2007 eq. for L10 (SKF 17000 p. 88)

# a1 by reliability in % (SKF 17000/1 EN, Table 3, p. 90; the values of ISO 281:2007 Table 1)
RELIABILITY_FACTORS = {90.0: 1.0, 95.0: 0.64, 96.0: 0.55, 97.0: 0.47, 98.0: 0.37, 99.0: 0.25}

# single 40° angular contact ball bearing (suffix B), single or tandem (NTN CAT. 2203/E p. B-61):
# Fa/Fr <= e: X = 1, Y = 0; Fa/Fr > e: X = 0.35, Y = 0.57; static X0 = 0.5, Y0 = 0.26
ANGULAR_CONTACT_40 = {"e": 1.14, "X": 0.35, "Y": 0.57, "X0": 0.5, "Y0": 0.26}
# deep groove ball bearings: X = 0.56 when Fa/Fr > e; static P0 = 0.6 Fr + 0.5 Fa, not below Fr (NTN p. B-27)
DEEP_GROOVE_X = 0.56
DEEP_GROOVE_STATIC = {"X0": 0.6, "Y0": 0.5}
# single row tapered roller bearing (SKF 17000/1 EN p. 680): Fa/Fr > e: P = 0.4 Fr + Y Fa; P0 = 0.5 Fr + Y0 Fa
# (e, Y, Y0 per bearing from the product table); a radial load induces the axial load 0.5 Fr/Y (p. 681-682)
TAPERED_X = 0.4
TAPERED_X0 = 0.5
INDUCED_AXIAL_FACTOR = 0.5
# Weibull slopes of the system life (NTN CAT. 2203/E eq. (3.3)): 10/9 ball, 9/8 roller bearings
SYSTEM_LIFE_SLOPE = {"ball": 10.0 / 9.0, "roller": 9.0 / 8.0}
# least static safety s0 for normal rotation (NTN CAT. 2203/E Table 3.6, p. A-31): ball 1, roller 1.5
S0_MIN_NORMAL = {"ball": 1.0, "roller": 1.5}
S0_MIN_MAX = 100.0        # a least static safety asked for (NTN's table: 0.5 … 3; 0 would divide by zero)

A_ISO_MAX = 50.0          # ISO 281:2007 limits a_ISO to 50
KAPPA_RANGE = (0.1, 4.0)  # the a_ISO formulas hold for 0.1 <= κ <= 4; above 4 the value at 4 is used
FORCE_MAX_N = 1e8
TAPERED_Y_MAX = 10.0     # a tapered roller bearing's axial load factor Y (0.4·cot α > 10 is α < 2.3°)
TAPERED_Y_MIN = 0.1      # and its least: 0.4·cot α < 0.1 is α > 76° (the catalog's Y: 1.3…2.1); a subnormal Y gave NaN
SPEED_MAX_RPM = 1e6
LIFE_MAX_H = 1e7
LUBRICATIONS = ("grease", "oil")


def basic_rating_life(C_kn, P_n, exponent=3.0):
    """Basic rating life L10 = (C/P)^p in millions of revolutions (ISO 281:2007; SKF 17000 p. 88), with
    C in kN and P in N (×1000 inside); p = 3 ball, 10/3 roller bearings.

    SKF's rope sheave (SKF 17000/1 EN, C.2, p. 223): 6207 with C = 27 kN at P = 0.55 kN, 2 450 r/min,
    L10h = 804 800 h:

    >>> l10 = basic_rating_life(27.0, 550.0)
    >>> round(float(rating_life_hours(l10, 2450)), -2)
    804800.0
    """
    return (1000.0 * np.asarray(C_kn, dtype=float) / np.asarray(P_n, dtype=float)) ** np.asarray(exponent)


def rating_life_hours(life_mrev, n_rpm):
    """A life in millions of revolutions as operating hours at constant speed, L_h = 10^6 L/(60 n)
    (SKF 17000/1 EN p. 88). NTN's Example 1 (CAT. 2203/E p. A-42): 6208, Cr = 32.5 kN, Pr = Fr = 3.2 kN,
    650 min⁻¹, "approximately 27 000 hours" (read off a nomogram):

    >>> round(float(rating_life_hours(basic_rating_life(32.5, 3200.0), 650)))
    26862
    """
    return 1e6 * np.asarray(life_mrev, dtype=float) / (60.0 * np.asarray(n_rpm, dtype=float))


def _factor_table():
    t = load_catalog("bearing_factors_deep_groove")
    return t["f0_fa_c0r"].to_numpy(), t["e"].to_numpy(), t["Y"].to_numpy()


def deep_groove_factors(f0_fa_c0r):
    """e and Y of a single row deep groove ball bearing (X = 0.56 when Fa/Fr > e) against the relative
    axial load f0·Fa/C0r, by linear interpolation in the ISO 281 table (NTN CAT. 2203/E p. B-27, normal
    clearance). Below the first row (0.172) the first row's values hold (the smallest e and largest Y: the
    conservative side); above the last (6.89, about Fa = 0.5 C0) the table says nothing: NaN.

    NTN's Example 2 (p. A-43): 6208 with f0 = 14.0, C0r = 17.8 kN, Fa = 1.8 kN, "e = 0.30", "Y = 1.44":

    >>> e, Y = deep_groove_factors(14.0 * 1.8 / 17.8)
    >>> round(float(e), 2), round(float(Y), 2)
    (0.3, 1.44)
    """
    x = np.asarray(f0_fa_c0r, dtype=float)
    xs, es, ys = _factor_table()
    inside = x <= xs[-1]
    e = np.where(inside, np.interp(x, xs, es), np.nan)
    Y = np.where(inside, np.interp(x, xs, ys), np.nan)
    return e, Y


@renamed_keywords(fr_n="F_r_n", fa_n="F_a_n")
def equivalent_dynamic_load(F_r_n, F_a_n, e, X, Y):
    """Equivalent dynamic load P = Fr when Fa/Fr <= e, else X·Fr + Y·Fa (ISO 281; NTN CAT. 2203/E eq. (4.28)),
    in the unit of the forces. Written as Fa <= e·Fr so that a pure axial load (Fr = 0) takes X Fr + Y Fa.

    NTN's Example 2, X = 0.56 and Y = 1.44: Pr = 4.38 kN (its arithmetic line shows Y = 1.43, a slip: that
    gives 4.37; the printed 4.38 is the result of the Y = 1.44 it reads from the table).

    >>> round(float(equivalent_dynamic_load(3.2, 1.8, 0.30, 0.56, 1.44)), 2)
    4.38
    """
    Fr, Fa = np.asarray(F_r_n, dtype=float), np.asarray(F_a_n, dtype=float)
    return np.where(Fa <= np.asarray(e) * Fr, Fr, np.asarray(X) * Fr + np.asarray(Y) * Fa)


@renamed_keywords(fr_n="F_r_n", fa_n="F_a_n")
def equivalent_static_load(F_r_n, F_a_n, X0, Y0):
    """Equivalent static load P0 = X0·Fr + Y0·Fa, not below Fr (NTN CAT. 2203/E pp. B-27, B-61: "when
    P0r < Fr use P0r = Fr"); deep groove X0 = 0.6, Y0 = 0.5, 40° angular contact 0.5 and 0.26.

    >>> float(equivalent_static_load(1000.0, 2000.0, 0.6, 0.5))
    1600.0
    """
    Fr, Fa = np.asarray(F_r_n, dtype=float), np.asarray(F_a_n, dtype=float)
    return np.maximum(np.asarray(X0) * Fr + np.asarray(Y0) * Fa, Fr)


def static_safety(C0_kn, P0_n):
    """Static safety s0 = C0/P0 (ISO 76; NTN CAT. 2203/E eq. (3.12)), C0 in kN and P0 in N.

    >>> float(static_safety(17.8, 8900.0))
    2.0
    """
    with np.errstate(divide="ignore"):
        return 1000.0 * np.asarray(C0_kn, dtype=float) / np.asarray(P0_n, dtype=float)


def reliability_factor(reliability_pct=90.0) -> float:
    """Life adjustment factor a1 for a reliability of 90 … 99 % (SKF 17000/1 EN Table 3, p. 90: the values
    of ISO 281:2007). Only the tabulated reliabilities are accepted.

    >>> reliability_factor(99)
    0.25
    """
    r = float(one_number("reliability", require_range("reliability", reliability_pct, 90.0, 99.0, unit="%")))
    if r not in RELIABILITY_FACTORS:
        raise GearDesignError(f"reliability must be one of {', '.join(f'{k:g}' for k in RELIABILITY_FACTORS)} % "
                              f"(the values of ISO 281's table of a1), got {r:g}")
    return RELIABILITY_FACTORS[r]


def life_modification_factor(kind, kappa, ec_cu_over_p):
    """Life modification factor a_ISO of ISO 281:2007 from the viscosity ratio κ = ν/ν1 and e_C·C_u/P
    (the contamination factor times the fatigue load limit over the equivalent load), capped at 50.

    Ball bearings (IBC TI-I-5050.0/E p. 158, eqs. (5.37)-(5.39), the ISO 281:2007 formulas):
    a = 0.1·[1 − (2.5671 − A/κ^b)^0.83·(e_C C_u/P)^(1/3)]^(−9.3) with (A, b) = (2.2649, 0.054381) for
    0.1 <= κ < 0.4, (1.9987, 0.19087) for 0.4 <= κ < 1 and (1.9987, 0.071739) for 1 <= κ <= 4.

    Roller bearings: a = 0.1·[1 − (1.5859 − A/κ^b)·(e_C C_u/P)^0.4]^(−9.185) with (A, b) = (1.3993, 0.054381),
    (1.2348, 0.19087), (1.2348, 0.071739) on the same κ ranges. The constants are those of the same IBC page;
    the text layer of that page also shows the exponent 0.83 beside the roller formulas, which we could not
    check against the standard: the roller form here (without it) is lower confidence (docs/bearings.md).

    κ above 4 counts as 4 (ISO 281); κ below 0.1 is outside the formulas and refused. At κ = 0.1 the inner
    difference (2.5671 − 2.2649/κ^b, 1.5859 − 1.3993/κ^b) is zero but for the rounding of the printed constants
    (about −5·10⁻⁶): it is taken as zero, a_ISO = 0.1, never below. Where the bracket
    reaches zero (a very clean, lightly loaded bearing) a_ISO is the cap, 50.

    >>> round(float(life_modification_factor("ball", 1.0, 0.0)), 6)     # no contamination credit: 0.1
    0.1
    >>> float(life_modification_factor("ball", 4.0, 10.0))               # the cap
    50.0
    """
    kind = require_choice("kind", kind, ("ball", "roller"))
    k = np.asarray(kappa, dtype=float)
    if np.any(~np.isfinite(k)) or np.any(k < KAPPA_RANGE[0]):
        raise GearDesignError(f"kappa (viscosity ratio) must be >= {KAPPA_RANGE[0]:g} (the a_ISO formulas of "
                              f"ISO 281 start there), got {np.min(k)!r}")
    k = np.minimum(k, KAPPA_RANGE[1])
    x = np.asarray(ec_cu_over_p, dtype=float)
    if np.any(~np.isfinite(x)) or np.any(x < 0):
        raise GearDesignError(f"e_C·C_u/P must be a finite number >= 0, got {np.min(x)!r}")
    low, mid = k < 0.4, k < 1.0
    b = np.where(low, 0.054381, np.where(mid, 0.19087, 0.071739))
    if kind == "ball":
        A = np.where(low, 2.2649, 1.9987)
        term = np.maximum(2.5671 - A / k ** b, 0.0) ** 0.83 * np.cbrt(x)
        power = -9.3
    else:
        A = np.where(low, 1.3993, 1.2348)
        term = np.maximum(1.5859 - A / k ** b, 0.0) * x ** 0.4
        power = -9.185
    base = 1.0 - term
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        a = np.where(base > 0, 0.1 * np.maximum(base, 1e-300) ** power, np.inf)
    return np.minimum(a, A_ISO_MAX)


@renamed_keywords(fr_n="F_r_n")
def induced_axial_force(F_r_n, Y):
    """The axial load a radial load Fr induces in a single row tapered roller bearing, 0.5·Fr/Y (N; SKF
    17000/1 EN Table 7, p. 682; NTN CAT. 2203/E Example 4, p. A-44: 0.5 × 5.98/2.06 = 1.45 kN).

    >>> round(float(induced_axial_force(5.98, 2.06)), 2)
    1.45
    """
    return INDUCED_AXIAL_FACTOR * np.asarray(F_r_n, dtype=float) / np.asarray(Y, dtype=float)


def tapered_axial_loads(fr_a_n, fr_b_n, Y_a, Y_b, ka_n=0.0):
    """The axial loads (Fa_A, Fa_B) in N of two single row tapered roller bearings A and B adjusted against
    each other to zero clearance without preload (back-to-back or face-to-face), under their radial loads
    Fr_A, Fr_B and an external axial force Ka on the shaft. ``ka_n`` >= 0 acts toward the bearing B, that is,
    B takes it (SKF's load cases 1a-1c); a negative Ka acts toward A (cases 2a-2c).

    SKF *Rolling bearings* 17000/1 EN, Table 7, p. 682: with Ka toward B, when 0.5 Fr_A/Y_A + Ka >=
    0.5 Fr_B/Y_B, Fa_A = 0.5 Fr_A/Y_A and Fa_B = Fa_A + Ka; otherwise Fa_B = 0.5 Fr_B/Y_B and Fa_A = Fa_B − Ka.
    Each bearing so carries at least its own induced load. NTN writes only the load one bearing passes to the
    other (its Example 4 has Fa_I = 0 where SKF's table gives 0.5 Fr_I/Y_I); the equivalent loads agree, since
    a bearing's own induced load 0.5/Y·Fr stays below e·Fr (e·Y = 0.6) and leaves P = Fr.

    NTN CAT. 2203/E Example 4 (p. A-44): Fr = 5.98 and 4.18 kN, Y = 2.06 and 2.07, Ka = 0: bearing II
    carries 1.45 kN:

    >>> fa = tapered_axial_loads(5.98, 4.18, 2.06, 2.07)
    >>> [round(float(v), 2) for v in fa]
    [1.45, 1.45]
    """
    fr_a_n, fr_b_n, Y_a, Y_b, ka = broadcast_inputs(
        fr_a_n=require_range("fr_a_n", fr_a_n, 0.0, FORCE_MAX_N, unit="N"),
        fr_b_n=require_range("fr_b_n", fr_b_n, 0.0, FORCE_MAX_N, unit="N"),
        # Y = 0.4·cot α: 0.69 … 2.3 for the contact angles 10° … 30° of the catalogs; 0 would divide by zero
        Y_a=require_range("Y_a", Y_a, TAPERED_Y_MIN, TAPERED_Y_MAX),
        Y_b=require_range("Y_b", Y_b, TAPERED_Y_MIN, TAPERED_Y_MAX),
        ka_n=require_range("ka_n", ka_n, -FORCE_MAX_N, FORCE_MAX_N, unit="N"))
    fa_ind = induced_axial_force(fr_a_n, Y_a)
    fb_ind = induced_axial_force(fr_b_n, Y_b)
    ka = ka.astype(float)
    # with Ka toward B (k >= 0): A sets the loads when its induced load plus Ka is at least B's; toward A the
    # same with the roles swapped
    toward_b = ka >= 0
    k = np.abs(ka)
    first, second = np.where(toward_b, fa_ind, fb_ind), np.where(toward_b, fb_ind, fa_ind)
    first_rules = first + k >= second
    fa_first = np.where(first_rules, first, second - k)
    fa_second = np.where(first_rules, first + k, second)
    return np.where(toward_b, fa_first, fa_second), np.where(toward_b, fa_second, fa_first)


def system_life(lives, kind):
    """The life of a set of bearings that fails when the first one fails (the rating life of a shaft or a
    gearbox), L = (Σ L_i^(−e))^(−1/e) with the Weibull slope e = 10/9 for ball and 9/8 for roller bearings
    (NTN CAT. 2203/E eq. (3.3), p. A-19), in the unit of the lives. NTN's Example 4 (p. A-44): 1 900 h and
    7 550 h give "1 600 hours":

    >>> round(float(system_life([1900.0, 7550.0], "roller")), -2)
    1600.0
    """
    kind = require_choice("kind", kind, tuple(SYSTEM_LIFE_SLOPE))
    L = np.asarray(lives, dtype=float)
    if L.ndim == 0 or L.size == 0 or np.any(~np.isfinite(L)) or np.any(L <= 0):
        raise GearDesignError(f"lives must be one or more finite lives > 0, got {lives!r}")
    e = SYSTEM_LIFE_SLOPE[kind]
    return np.sum(L ** -e, axis=-1) ** (-1.0 / e)


def reference_viscosity(n_rpm, dpw_mm):
    """The reference kinematic viscosity ν1 (mm²/s) a bearing needs at its speed, for the viscosity ratio
    κ = ν/ν1 of :func:`life_modification_factor`: ν1 = 45 000·n^−0.83·D_pw^−0.5 below 1 000 min⁻¹ and
    4 500·n^−0.5·D_pw^−0.5 from 1 000 min⁻¹ on (ISO 281:2007 as printed by NTN CAT. 2203/E eqs. (3.10),
    (3.11), pp. A-24/A-25), n in rpm and D_pw the pitch diameter of the rolling elements, about (d + D)/2, in mm.

    SKF's rope sheave (17000/1 EN C.2, p. 224): d_m = 53.5 mm at 2 450 r/min, "ν1 is close to 12 mm²/s" (read off
    SKF's diagram 14):

    >>> round(float(reference_viscosity(2450, 53.5)), 1)
    12.4
    """
    n = np.asarray(require_range("n_rpm", n_rpm, 0.0, SPEED_MAX_RPM, lo_open=True, unit="rpm"), dtype=float)
    dpw = np.asarray(require_range("dpw_mm", dpw_mm, 0.0, 1e4, lo_open=True, unit="mm"), dtype=float)
    return np.where(n < 1000.0, 45000.0 * n ** -0.83, 4500.0 * n ** -0.5) / np.sqrt(dpw)


def bearing_catalog(series) -> pd.DataFrame:
    """The catalog rows of one or more series (``"62"``, ``"63"``, ``"72B"``, ``"73B"``, ``"NU2"``, ``"NU3"``,
    the tapered roller ``"302"``, ``"303"``, ``"320X"``, ``"322"``, ``"323"``, or a list of them), with a column
    ``kind`` ("ball" or "roller")."""
    if not isinstance(series, (str, list, tuple)) and np.ndim(series) == 0:
        raise GearDesignError(f"series must be a series name or a list of them ({', '.join(SERIES)}), got "
                              f"{series!r}")
    names = [series] if isinstance(series, str) else list(series)
    if not names:
        raise GearDesignError(f"series must name at least one of {', '.join(SERIES)}")
    frames = []
    for name in names:
        name = require_choice("series", name, tuple(SERIES))
        table, kind = SERIES[name]
        frame = load_catalog(table)
        frames.append(frame[frame["series"] == name].assign(kind=BEARING_KINDS[kind], bearing_type=kind))
    import pandas as pd

    return pd.concat(frames, ignore_index=True)


@renamed_keywords(fr_n="F_r_n", fa_n="F_a_n")
def bearing_loads(rows: pd.DataFrame, F_r_n, F_a_n):
    """e, X, Y, P and P0 of each catalog row under Fr and Fa (N), by the row's bearing type, as a dict of
    arrays; ``axial_ok`` is False where the type cannot take the axial load (a cylindrical roller bearing
    of type NU carries none; a deep groove ball bearing beyond the end of the e/X/Y table). For a tapered
    roller bearing ``F_a_n`` is its whole axial load, the induced part included (:func:`tapered_axial_loads`)."""
    n = len(rows)
    Fr = np.broadcast_to(np.asarray(F_r_n, dtype=float), (n,))
    Fa = np.broadcast_to(np.asarray(F_a_n, dtype=float), (n,))
    t = rows["bearing_type"].to_numpy()
    C0 = rows["C0_kn"].to_numpy(dtype=float)
    f0 = rows["f0"].to_numpy(dtype=float)
    e = np.full(n, np.nan)
    X = np.ones(n)
    Y = np.zeros(n)
    X0, Y0 = np.ones(n), np.zeros(n)
    dg = t == "deep_groove_ball"
    if dg.any():
        e_dg, Y_dg = deep_groove_factors(f0[dg] * Fa[dg] / (1000.0 * C0[dg]))
        e[dg], Y[dg], X[dg] = e_dg, Y_dg, DEEP_GROOVE_X
        X0[dg], Y0[dg] = DEEP_GROOVE_STATIC["X0"], DEEP_GROOVE_STATIC["Y0"]
    ac = t == "angular_contact_ball"
    e[ac], X[ac], Y[ac] = ANGULAR_CONTACT_40["e"], ANGULAR_CONTACT_40["X"], ANGULAR_CONTACT_40["Y"]
    X0[ac], Y0[ac] = ANGULAR_CONTACT_40["X0"], ANGULAR_CONTACT_40["Y0"]
    tr = t == "tapered_roller"
    if tr.any():
        e[tr] = rows["e"].to_numpy(dtype=float)[tr]
        X[tr], Y[tr] = TAPERED_X, rows["Y"].to_numpy(dtype=float)[tr]
        X0[tr], Y0[tr] = TAPERED_X0, rows["Y0"].to_numpy(dtype=float)[tr]
    nu = t == "cylindrical_roller"
    e[nu] = np.inf                                     # P = Fr; any axial load is refused below
    axial_ok = np.isfinite(e) | (nu & (Fa == 0))
    with np.errstate(invalid="ignore"):      # inf·0 (an NU row under a pure axial load) is masked by axial_ok
        P = np.where(axial_ok, equivalent_dynamic_load(Fr, Fa, np.where(np.isfinite(e), e, np.inf), X, Y), np.nan)
    P0 = np.where(axial_ok, equivalent_static_load(Fr, Fa, X0, Y0), np.nan)
    with np.errstate(invalid="ignore", over="ignore"):
        below = np.isinf(e) | (Fa <= np.nan_to_num(e, nan=np.inf) * Fr)   # P = Fr: the X and Y in use are 1 and 0
    return {"e": e, "X": np.where(below, 1.0, X), "Y": np.where(below, 0.0, Y), "P_n": P, "P0_n": P0,
            "axial_ok": axial_ok}


def _inputs(F_r_n, F_a_n, n_rpm, life_h, reliability, kappa, e_c, lubrication):
    fr = one_number("F_r_n", require_range("F_r_n", F_r_n, 0.0, FORCE_MAX_N, unit="N"))
    fa = one_number("F_a_n", require_range("F_a_n", F_a_n, 0.0, FORCE_MAX_N, unit="N"))
    if fr == 0.0 and fa == 0.0:
        raise GearDesignError("F_r_n and F_a_n are both 0: a bearing needs a load to have a life")
    n = one_number("n_rpm", require_range("n_rpm", n_rpm, 0.0, SPEED_MAX_RPM, lo_open=True, unit="rpm"))
    life = None if life_h is None else one_number(
        "life_h", require_range("life_h", life_h, 0.0, LIFE_MAX_H, lo_open=True, unit="h"))
    a1 = reliability_factor(reliability)
    if (kappa is None) != (e_c is None):
        raise GearDesignError("give kappa and e_c together (the modified life needs both), or neither")
    if kappa is not None:
        kappa = one_number("kappa", require_range("kappa", kappa, KAPPA_RANGE[0], 1e3))
        e_c = one_number("e_c", require_range("e_c", e_c, 0.0, 1.0))
    require_choice("lubrication", lubrication, LUBRICATIONS)
    return fr, fa, n, life, a1, kappa, e_c


def _evaluate(rows, fr, fa, n, life, a1, kappa, e_c, lubrication, s0_min):
    """Every row's loads, lives, safety and margins (a DataFrame, one row per bearing)."""
    loads = bearing_loads(rows, fr, fa)
    kind = rows["kind"].to_numpy()
    p = np.where(kind == "ball", LIFE_EXPONENT["ball"], LIFE_EXPONENT["roller"])
    C, C0 = rows["C_kn"].to_numpy(dtype=float), rows["C0_kn"].to_numpy(dtype=float)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):   # a tiny load: an infinite life
        L10 = basic_rating_life(C, loads["P_n"], p)
        L10h = rating_life_hours(L10, n)
        if kappa is not None:
            cu = rows["Cu_kn"].to_numpy(dtype=float)
            x = np.where(np.isfinite(loads["P_n"]), e_c * 1000.0 * cu / loads["P_n"], 0.0)
            a_iso = np.where(kind == "ball", life_modification_factor("ball", kappa, x),
                             life_modification_factor("roller", kappa, x))
        else:
            a_iso = np.ones(len(rows))
        Lnmh = a1 * a_iso * L10h
        s0 = static_safety(C0, loads["P0_n"])
    s0_need = np.where(kind == "ball", S0_MIN_NORMAL["ball"], S0_MIN_NORMAL["roller"]) if s0_min is None \
        else np.full(len(rows), one_number("s0_min", require_range("s0_min", s0_min, 0.0, S0_MIN_MAX, lo_open=True)))
    speed = rows[f"speed_{lubrication}_rpm"].to_numpy(dtype=float)
    table = rows[["designation", "series", "bearing_type", "d_mm", "D_mm", "B_mm", "C_kn", "C0_kn", "Cu_kn", "f0"]].copy()
    table = table.assign(e=loads["e"], X=loads["X"], Y=loads["Y"], P_n=loads["P_n"], P0_n=loads["P0_n"],
                         L10_mrev=L10, L10h=L10h, a1=a1, a_iso=a_iso, Lnmh=Lnmh, s0=s0, s0_min=s0_need,
                         speed_limit_rpm=speed)
    # a yes/no check has margin +1 (holds) or -1 (fails); where the axial load cannot be carried the other
    # checks have no value (NaN) and the axial check is the limiting one; without a required life the life
    # check is not made (NaN)
    ok = loads["axial_ok"]
    with np.errstate(over="ignore"):      # a required life of 5e-324 h: the life margin is +inf, not a warning (fuzz)
        life_margin = Lnmh / life - 1.0 if life is not None else np.full(len(rows), np.nan)
    margins = {"axial_load": np.where(ok, 1.0, -1.0),
               "life": np.where(ok, life_margin, np.nan),
               "static_safety": np.where(ok, s0 / s0_need - 1.0, np.nan),
               "speed": np.where(np.isfinite(speed), 1.0 - n / speed, 0.0)}
    for name, m in margins.items():
        table[f"margin_{name}"] = m
    m = np.column_stack(list(margins.values()))
    m = np.where(ok[:, None], m, np.where(np.arange(m.shape[1]) == 0, -1.0, np.nan))
    table["min_margin"] = np.nanmin(m, axis=1)
    table["limiting_check"] = np.array(list(margins))[np.nanargmin(m, axis=1)]
    table["feasible"] = ok & np.all(np.isnan(m) | (m >= 0), axis=1)     # NaN: a check not asked for
    return table


@dataclass(frozen=True, eq=False)
class BearingCheck(Result):
    """One bearing under one load case (:func:`check_bearing`): its equivalent loads, lives, static safety
    and a margin per check (>= 0 holds); ``ok`` when every one holds."""

    ok: bool
    message: str
    designation: str
    series: str
    d_mm: float
    D_mm: float
    B_mm: float
    C_kn: float
    C0_kn: float
    F_r_n: float
    F_a_n: float
    n_rpm: float
    e: float
    X: float
    Y: float
    P_n: float
    P0_n: float
    L10_mrev: float
    L10h: float
    a1: float
    a_iso: float
    Lnmh: float
    life_h: float | None
    s0: float
    s0_min: float
    speed_limit_rpm: float
    margins: dict
    limiting_check: str

    _success_field = "ok"

    def __repr__(self) -> str:
        life = f"L10h = {self.L10h:.6g} h" + (f", Lnmh = {self.Lnmh:.6g} h" if self.Lnmh != self.L10h else "")
        head = (f"BearingCheck({self.designation}: {self.message})\n  d x D x B = {self.d_mm:g} x {self.D_mm:g} x "
                f"{self.B_mm:g} mm, C = {self.C_kn:g} kN, C0 = {self.C0_kn:g} kN")
        if not math.isfinite(self.P_n):       # the axial load cannot be carried: no load, life or safety to show
            return head
        return head + f"\n  P = {self.P_n:.6g} N (X = {self.X:g}, Y = {self.Y:.4g}), {life}, s0 = {self.s0:.4g}"


@dataclass(frozen=True, eq=False)
class BearingSelection(RankedTable):
    """Result of :func:`select_bearing`: every candidate of the series with its margins, ranked (feasible
    first, then the smallest outside diameter), and the best as a :class:`BearingCheck`."""

    message: str
    checked: BearingCheck | None
    table: pd.DataFrame

    def __repr__(self) -> str:
        head = f"BearingSelection: {self.message}"
        return head if self.checked is None else head + "\n  " + "\n".join(repr(self.checked).splitlines()[1:])


def _check_from_row(row, fr, fa, n, life) -> BearingCheck:
    margins = {k[len("margin_"):]: float(row[k]) for k in row.index if k.startswith("margin_")}
    ok = bool(row["feasible"])
    limiting = str(row["limiting_check"])
    what = {"life": (f"life {row['Lnmh']:.6g} h" + (f" against the required {life:g} h" if life else "")),
            "static_safety": f"static safety s0 = {row['s0']:.4g} against {row['s0_min']:g}",
            "speed": f"speed {n:g} rpm against the allowable {row['speed_limit_rpm']:g} rpm",
            "axial_load": (f"a type NU bearing carries no axial load (Fa = {fa:g} N)"
                           if row["bearing_type"] == "cylindrical_roller" else
                           f"f0 Fa/C0r = {row['f0'] * fa / (1000 * row['C0_kn']):.3g} is beyond the end of the "
                           f"ISO 281 table, 6.89 (about Fa = 0.5 C0)")}
    msg = (f"{row['designation']} holds: {what['life']}, s0 = {row['s0']:.4g}" if ok
           else f"{row['designation']} fails {limiting}: {what[limiting]}")
    def f(k):
        return float(row[k])

    return BearingCheck(ok=ok, message=msg, designation=str(row["designation"]), series=str(row["series"]),
                        d_mm=f("d_mm"), D_mm=f("D_mm"), B_mm=f("B_mm"), C_kn=f("C_kn"), C0_kn=f("C0_kn"),
                        F_r_n=fr, F_a_n=fa, n_rpm=n, e=f("e"), X=f("X"), Y=f("Y"), P_n=f("P_n"), P0_n=f("P0_n"),
                        L10_mrev=f("L10_mrev"), L10h=f("L10h"), a1=f("a1"), a_iso=f("a_iso"), Lnmh=f("Lnmh"),
                        life_h=life, s0=f("s0"), s0_min=f("s0_min"), speed_limit_rpm=f("speed_limit_rpm"),
                        margins=margins, limiting_check=limiting)


@renamed_keywords(fr_n="F_r_n", fa_n="F_a_n")
def check_bearing(designation: str, F_r_n, F_a_n=0.0, n_rpm=None, life_h=None, reliability=90.0, kappa=None,
                  e_c=None, lubrication="grease", s0_min=None) -> BearingCheck:
    """The lives, static safety and checks of the catalog bearing ``designation`` (e.g. ``"6208"``,
    ``"7310B"``, ``"NU210EA"``) under a radial load ``F_r_n`` and an axial load ``F_a_n`` (N) at ``n_rpm``.

    ``life_h``: the required life (None: no life check); ``reliability`` 90 … 99 % (a1); ``kappa`` and
    ``e_c``: viscosity ratio and contamination factor for the modified life Lnm = a1·a_ISO·L10 (None: a_ISO
    = 1, Lnm = a1·L10); ``lubrication``: which allowable speed of the catalog applies; ``s0_min``: the least
    static safety (None: NTN's values for normal rotation, 1 ball, 1.5 roller).

    NTN's Example 2 (CAT. 2203/E p. A-43): 6208, Fr = 3.2 kN, Fa = 1.8 kN, 650 min⁻¹: e = 0.30, X = 0.56,
    Y = 1.44, L10h "approximately 10 500 hours" (a nomogram reading; the formula gives 10 410 h):

    >>> r = check_bearing("6208", 3200, 1800, 650)
    >>> round(r.e, 2), r.X, round(r.Y, 2), round(r.L10h, -1)
    (0.3, 0.56, 1.44, 10410.0)
    """
    if not isinstance(designation, str):
        raise GearDesignError(f"designation must be a catalog designation such as '6208', got {designation!r}")
    if n_rpm is None:
        raise GearDesignError("n_rpm (the bearing's speed) is needed, got None")
    fr, fa, n, life, a1, kappa, e_c = _inputs(F_r_n, F_a_n, n_rpm, life_h, reliability, kappa, e_c, lubrication)
    rows = bearing_catalog(tuple(SERIES))
    rows = rows[rows["designation"] == designation.strip()]
    if rows.empty:
        raise GearDesignError(f"designation {designation!r} is in none of the bearing catalogs (series "
                              f"{', '.join(SERIES)}); see geardesign.drives.bearing.bearing_catalog")
    table = _evaluate(rows.iloc[:1].reset_index(drop=True), fr, fa, n, life, a1, kappa, e_c, lubrication, s0_min)
    return _check_from_row(table.iloc[0], fr, fa, n, life)


@renamed_keywords(fr_n="F_r_n", fa_n="F_a_n")
def select_bearing(series, bore_mm, F_r_n, F_a_n=0.0, n_rpm=None, life_h=None, reliability=90.0, kappa=None,
                   e_c=None, lubrication="grease", s0_min=None) -> BearingSelection:
    """The smallest bearing of ``series`` (one or a list: "62", "63", "72B", "73B", "NU2", "NU3", the tapered
    roller "302", "303", "320X", "322", "323") whose bore fits a seat of at least ``bore_mm`` and that passes every check (life, static safety, speed, axial
    load): all candidates are evaluated in one vectorised pass and ranked feasible first, then by outside
    diameter and bore. Arguments otherwise as :func:`check_bearing`; ``life_h`` is required here.

    >>> s = select_bearing("62", 40, 3200, 1800, 650, life_h=10000)
    >>> s.best["designation"]
    '6208'
    """
    if n_rpm is None:
        raise GearDesignError("n_rpm (the bearing's speed) is needed, got None")
    if life_h is None:
        raise GearDesignError("life_h (the required life, h) is needed to select a bearing")
    fr, fa, n, life, a1, kappa, e_c = _inputs(F_r_n, F_a_n, n_rpm, life_h, reliability, kappa, e_c, lubrication)
    rows = bearing_catalog(series)
    d_max = float(rows["d_mm"].max())
    bore = one_number("bore_mm", require_range("bore_mm", bore_mm, 0.0, d_max, lo_open=True, unit="mm"))
    rows = rows[rows["d_mm"] >= bore].reset_index(drop=True)
    table = _evaluate(rows, fr, fa, n, life, a1, kappa, e_c, lubrication, s0_min)
    order = np.lexsort((table["d_mm"].to_numpy(), table["D_mm"].to_numpy(), ~table["feasible"].to_numpy()))
    table = table.iloc[order].reset_index(drop=True)
    table.insert(0, "rank", np.arange(1, len(table) + 1))
    names = series if isinstance(series, str) else ", ".join(series)
    if bool(table["feasible"].iloc[0]):
        checked = _check_from_row(table.iloc[0], fr, fa, n, life)
        msg = (f"{checked.designation} (d = {checked.d_mm:g} mm, D = {checked.D_mm:g} mm) is the smallest of "
               f"series {names} with d >= {bore:g} mm that passes: {checked.message.split(': ', 1)[1]}")
    else:
        near = table.sort_values("min_margin", ascending=False, kind="stable").iloc[0]
        checked = None
        msg = (f"no bearing of series {names} with d >= {bore:g} mm passes; the nearest, {near['designation']}, "
               f"fails {near['limiting_check']} (margin {near['min_margin']:+.3g})")
    return BearingSelection(message=msg, checked=checked, table=table)
