"""Roller-chain sprocket and chain-loop geometry: one function per formula.

Lengths in mm, speeds in rpm and m/s. Every function broadcasts over numpy arrays (tooth
counts, pitches, centre distances) so that a whole candidate table is one call.
"""
from __future__ import annotations

import numpy as np

__all__ = [
    "pitch_diameter_mm",
    "tip_diameter_mm",
    "root_diameter_mm",
    "chain_speed_m_s",
    "link_count",
    "even_links",
    "center_distance_for_links_mm",
    "impacts_per_second",
]


def pitch_diameter_mm(pitch_mm, z):
    """Pitch-circle diameter d = p / sin(180°/z) of a sprocket with z teeth [mm].

    Source: ISO 606:2004 Annex A (pitch circle diameters); GOST 591-69.

    >>> round(float(pitch_diameter_mm(31.75, 13)), 2)  # seed 002, 1.9.6 a): 132.67 mm
    132.67
    >>> round(float(pitch_diameter_mm(19.05, 34)), 4)  # Bhandari Ex. 14.4: D2 = 206.462975 mm
    206.463
    """
    return np.asarray(pitch_mm, dtype=float) / np.sin(np.pi / np.asarray(z, dtype=float))


def tip_diameter_mm(pitch_mm, z):
    """Tip diameter D_e = p·(0.5 + cot(180°/z)) [mm].

    Source: GOST 591-69 as used in Russian course design (Chernavsky); seed 002, 1.9.6 b).

    >>> round(float(tip_diameter_mm(31.75, 13)), 2)  # seed 002: 144.69 mm
    144.69
    """
    p = np.asarray(pitch_mm, dtype=float)
    return p * (0.5 + 1.0 / np.tan(np.pi / np.asarray(z, dtype=float)))


def root_diameter_mm(pitch_mm, z, roller_d1_mm):
    """Root diameter D_i = d − 2·(0.5025·d1 + 0.05) with d the pitch diameter [mm].

    Source: GOST 591-69 (seating-curve radius r = 0.5025·d1 + 0.05); seed 002, 1.9.6 c).

    >>> round(float(root_diameter_mm(31.75, 13, 19.05)), 2)  # seed 002 prints 113.43 (from d rounded to 132.67)
    113.42
    """
    d1 = np.asarray(roller_d1_mm, dtype=float)
    return pitch_diameter_mm(pitch_mm, z) - 2.0 * (0.5025 * d1 + 0.05)


def chain_speed_m_s(z1, pitch_mm, n1_rpm):
    """Mean chain speed v = z1·p·n1 / 60 000 [m/s] (p in mm, n1 in rpm).

    Source: Chernavsky, course design of machine parts (chain drives); Bhandari, Design of
    Machine Elements, eq. (14.4).

    >>> round(float(chain_speed_m_s(17, 19.05, 1000)), 4)  # Bhandari Ex. 14.1: v = 5.3975 m/s
    5.3975
    """
    return np.asarray(z1, dtype=float) * np.asarray(pitch_mm, dtype=float) * np.asarray(n1_rpm, dtype=float) / 60000.0


def link_count(center_distance_mm, pitch_mm, z1, z2):
    """Exact (fractional) number of links of a two-sprocket loop.

    L = 2a/p + (z1 + z2)/2 + ((z2 − z1)/(2π))²·p/a.

    Source: ISO 10823:2004 clause 6; Bhandari eq. (14.9).

    >>> round(float(link_count(500, 12.7, 21, 63)), 3)  # Bhandari Ex. 14.3: Ln = 121.875
    121.875
    """
    a = np.asarray(center_distance_mm, dtype=float)
    p = np.asarray(pitch_mm, dtype=float)
    z1 = np.asarray(z1, dtype=float)
    z2 = np.asarray(z2, dtype=float)
    return 2.0 * a / p + 0.5 * (z1 + z2) + ((z2 - z1) / (2.0 * np.pi)) ** 2 * p / a


def even_links(links):
    """The nearest even whole number of links (an odd count needs a cranked link), ties up.

    >>> even_links([121.875, 105.683, 25.0]).tolist()
    [122, 106, 26]
    """
    return (2 * np.floor(np.asarray(links, dtype=float) / 2.0 + 0.5)).astype(np.int64)


def center_distance_for_links_mm(links, pitch_mm, z1, z2):
    """Exact centre distance of a loop of ``links`` links [mm].

    a = p/4·[L − (z1+z2)/2 + sqrt((L − (z1+z2)/2)² − 8·((z2 − z1)/(2π))²)].

    Source: ISO 10823:2004 clause 6; Bhandari eq. (14.10).

    >>> round(float(center_distance_for_links_mm(122, 12.7, 21, 63)), 6)  # Bhandari Ex. 14.3: 500.804717
    500.804717

    Bhandari Ex. 14.4 prints a = 763.496160 mm for 106 links of 12B on 17/34 teeth: that is this
    exact distance less the 0.2 % sag allowance the example applies:

    >>> round(float(center_distance_for_links_mm(106, 19.05, 17, 34)) * (1 - 0.002), 4)
    763.4962
    """
    L = np.asarray(links, dtype=float)
    p = np.asarray(pitch_mm, dtype=float)
    s = L - 0.5 * (np.asarray(z1, dtype=float) + np.asarray(z2, dtype=float))
    delta = (np.asarray(z2, dtype=float) - np.asarray(z1, dtype=float)) / (2.0 * np.pi)
    return 0.25 * p * (s + np.sqrt(s * s - 8.0 * delta * delta))


def impacts_per_second(z1, n1_rpm, links):
    """Roller impacts on the sprocket teeth per second, w = 4·z1·n1 / (60·L) [1/s].

    Source: Chernavsky, course design of machine parts (chain drives: number of impacts ν).

    >>> round(float(impacts_per_second(13, 120, 26)), 3)
    4.0
    """
    return 4.0 * np.asarray(z1, dtype=float) * np.asarray(n1_rpm, dtype=float) / (60.0 * np.asarray(links, dtype=float))
