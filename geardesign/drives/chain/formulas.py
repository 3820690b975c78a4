"""Roller-chain formulas, one function each with its source: sprocket teeth, pitch estimate, hinge
pressure, breaking-load safety, rated power, allowable pressure."""
from __future__ import annotations


import numpy as np

from ...catalogs.tables import load_catalog

from typing import TYPE_CHECKING

if TYPE_CHECKING:       # pandas is imported where a table is made (start-up cost)
    import pandas as pd


HP_TO_KW = 0.745699872  # 1 mechanical horsepower in kW

IN_MM = 25.4

G = 9.81  # m/s²


def recommended_z1(ratio):
    """Small-sprocket teeth from the rule z1 = 29 − 2u, rounded to odd, bounded to [13, 29].

    Source: Russian course-design practice (Chernavsky, course design of machine parts, chain
    drives; docs/references.md): odd tooth counts spread the wear with an even number of links.

    >>> recommended_z1(1), recommended_z1(3), recommended_z1(8)
    (27, 23, 13)
    """
    u = float(ratio)
    z = 29.0 - 2.0 * u
    odd = 2 * np.floor(z / 2.0) + 1  # the nearest odd number (an even z rounds up)
    return int(np.clip(odd, 13, 29))


def pitch_estimate_mm(torque_nm, z1, allowable_pressure_mpa, k_e=1.0, strand_factor=1.0):
    """Classic starting estimate of the pitch, t >= 2.8·(T1·K_e / (z1·[p]·m))^(1/3) [mm].

    T1 in N·mm inside the root (the argument is N·m); m = strands·K_m is the effective strand
    factor (1, 1.7, 2.5, 3). It follows from p = F_t·K_e/A with A ≈ 0.28·t² per strand and
    F_t = 2T/d, d ≈ z·t/π. Source: Chernavsky, course design of machine parts; seed 002 1.9.5.

    >>> round(float(pitch_estimate_mm(380, 13, 29, 2.1484, 1.0)), 2)  # seed 002: 36.23 mm
    36.23
    >>> round(float(pitch_estimate_mm(380, 13, 29, 2.1484, 2 * 0.85)), 2)  # seed 002: 30.35 mm
    30.35
    """
    t_nmm = np.asarray(torque_nm, dtype=float) * 1000.0
    return 2.8 * np.cbrt(t_nmm * k_e / (np.asarray(z1, dtype=float) * allowable_pressure_mpa * strand_factor))


def hinge_pressure_mpa(force_n, k_e, hinge_area_mm2, strand_factor):
    """Hinge (pin-bushing) pressure p = F_t·K_e / (A·m_eff) [MPa].

    A is the projected bearing area of one strand (pin diameter × inner-link width) in mm²,
    m_eff = strands·K_m. Source: Chernavsky, course design of machine parts (chain check
    p <= [p]); GOST 13568-75 gives A.

    >>> round(float(hinge_pressure_mpa(5785.0, 2.148, 260.0, 1.7)), 2)
    28.11
    """
    return np.asarray(force_n, dtype=float) * k_e / (np.asarray(hinge_area_mm2, dtype=float) * strand_factor)


def safety_factor(breaking_load_n, force_n, k_d, mass_kg_m, speed_m_s, center_distance_mm, sag_factor=6.0):
    """Breaking-load safety factor s = Q / (K_d·F_t + F_v + F_f).

    F_v = q·v² (centrifugal tension), F_f = 9.81·k_f·q·a (sag tension, a in m; k_f = 6 for a
    horizontal drive, 1.5 at 40°, 1 vertical). Source: Chernavsky, course design of machine
    parts; Ivanov, Machine parts (chain drives).

    Bhandari Ex. 14.1 uses s = Q/F_t alone (no K_d, no F_v, no F_f): 31 100 N over the tension
    that carries 14.32 kW at 5.3975 m/s gives 11.722:

    >>> round(float(safety_factor(31100, 14320 / 5.3975, 1.0, 0.0, 5.3975, 0.0)), 4)
    11.7222
    """
    q = np.asarray(mass_kg_m, dtype=float)
    v = np.asarray(speed_m_s, dtype=float)
    f_v = q * v * v
    f_f = G * sag_factor * q * np.asarray(center_distance_mm, dtype=float) / 1000.0
    return np.asarray(breaking_load_n, dtype=float) / (k_d * np.asarray(force_n, dtype=float) + f_v + f_f)


def rated_power_link_plate_kw(z1, n1_rpm, pitch_mm, k_plate=0.004):
    """Link-plate fatigue rating of one strand, ANSI: HP = K·N^1.08·n^0.9·p^(3.0 − 0.07p) [kW].

    N small-sprocket teeth, n its rpm, p the pitch in inches; K = 0.004 (0.0022 for No. 41).
    Source: ANSI/ASME B29.1 horsepower formulas as printed in roller-chain catalogue pages
    (docs/references.md).

    >>> hp = 0.004 * 17**1.08 * 1400**0.9 * 0.5**(3.0 - 0.07 * 0.5)
    >>> round(float(rated_power_link_plate_kw(17, 1400, 12.7)) / 0.745699872 - hp, 12)
    0.0
    """
    p_in = np.asarray(pitch_mm, dtype=float) / IN_MM
    hp = (np.asarray(k_plate, dtype=float) * np.asarray(z1, dtype=float) ** 1.08
          * np.asarray(n1_rpm, dtype=float) ** 0.9 * p_in ** (3.0 - 0.07 * p_in))
    return hp * HP_TO_KW


def rated_power_roller_bushing_kw(z1, n1_rpm, pitch_mm, k_roller=17.0):
    """Roller-bushing impact rating of one strand, ANSI: HP = 1000·K·N^1.5·p^0.8 / n^1.5 [kW].

    K = 29 for No. 25 and 35, 3.4 for No. 41, 17 for No. 40-240. Same source as
    :func:`rated_power_link_plate_kw`.
    """
    p_in = np.asarray(pitch_mm, dtype=float) / IN_MM
    hp = (1000.0 * np.asarray(k_roller, dtype=float) * np.asarray(z1, dtype=float) ** 1.5 * p_in ** 0.8
          / np.asarray(n1_rpm, dtype=float) ** 1.5)
    return hp * HP_TO_KW


def interp_speed(values_n, values_y, n1):
    """Interpolate a table row y(n1) linearly; return (value, status).

    status 0: inside the table; -1: below its first speed (the first value is returned: the
    allowable values fall, and [s] rises, with speed, so the first column is the conservative
    one for [p] and is flagged); +1: above its last speed (NaN: no silent extrapolation).
    """
    if n1 < values_n[0]:
        return float(values_y[0]), -1
    if n1 > values_n[-1]:
        return float("nan"), 1
    return float(np.interp(n1, values_n, values_y)), 0


def allowable_pressure_mpa(pitch_mm, n1_rpm, table: pd.DataFrame | None = None):
    """Allowable hinge pressure [p] for a pitch at small-sprocket speed n1 [MPa], with status.

    Linear interpolation between the table's speeds. Returns ``(value, status)`` with status
    as in :func:`interp_speed`; a pitch outside every group gives (NaN, 2).
    Source: catalogs/chain_allowable_pressure.csv (Chernavsky/Sheinblit layout, z1 = 17 basis).

    >>> allowable_pressure_mpa(31.75, 200)
    (29.0, 0)
    >>> allowable_pressure_mpa(31.75, 125)  # halfway between 35 MPa (50 rpm) and 29 MPa (200 rpm)
    (32.0, 0)
    """
    table = load_catalog("chain_allowable_pressure") if table is None else table
    tol = 1e-6
    rows = table[(table["pitch_min_mm"] - tol <= pitch_mm) & (pitch_mm <= table["pitch_max_mm"] + tol)]
    if rows.empty:
        return float("nan"), 2
    return interp_speed(rows["n1_rpm"].to_numpy(), rows["allowable_pressure_mpa"].to_numpy(), n1_rpm)
