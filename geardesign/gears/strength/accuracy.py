"""Gear accuracy grade → the deviations ISO 6336-1 needs (ISO 1328-1:1995 clause 6.3, the formulas behind its
tables), in µm.

ISO 1328-1:1995 builds its tables from these formulas evaluated at the geometric mean of each range of
module, diameter and face width and rounds the result; here they are evaluated at the gear's own m, d and b
without rounding (the values differ from the tables by up to a few per cent). Every tolerance of grade Q is
the grade-5 value times 2^((Q − 5)/2). Grades of ISO 1328-1:1995 (0 to 12) are not the flank tolerance
classes of ISO 1328-1:2013; ISO/TR 6336-30 and these formulas use the 1995 grades.
"""
from __future__ import annotations

import functools

from .ops import FloatOps, ops_of

__all__ = ["grade_step", "single_pitch_deviation", "profile_form_deviation", "helix_deviation_total",
           "helix_slope_deviation", "GRADE_RANGE"]

GRADE_RANGE = (0, 12)   # ISO 1328-1:1995 grades


def grade_step(grade):
    """2^((Q − 5)/2): the factor from grade 5 to grade Q (ISO 1328-1:1995 clause 6.2).

    >>> float(grade_step(7))
    2.0
    """
    if type(grade) is float:
        return _float_grade_step(grade)
    xp = ops_of(grade)
    return xp.exp2((xp.asarray(grade) - 5.0) / 2.0)


@functools.lru_cache(maxsize=32)
def _float_grade_step(grade: float) -> float:
    """:func:`grade_step` of one grade given as a Python float (once per grade: the four deviations share it)."""
    return FloatOps.exp2((grade - 5.0) / 2.0)


def single_pitch_deviation(m_n_mm, d_mm, grade):
    """f_pt = (0.3(m_n + 0.4√d) + 4)·2^((Q−5)/2), µm (ISO 1328-1:1995 clause 6.3.1).

    >>> round(float(single_pitch_deviation(7.746, 187.08, 5)), 2)   # grade 5 at the range means m 7.75, d 187 mm
    7.97
    """
    xp = ops_of(m_n_mm, d_mm)
    return (0.3 * (xp.asarray(m_n_mm) + 0.4 * xp.sqrt(d_mm)) + 4.0) * grade_step(grade)


def profile_form_deviation(m_n_mm, d_mm, grade):
    """f_fα = (2.5√m_n + 0.17√d + 0.5)·2^((Q−5)/2), µm (ISO 1328-1:1995 clause 6.3.4).

    >>> round(float(profile_form_deviation(7.746, 187.08, 5)), 2)
    9.78
    """
    xp = ops_of(m_n_mm, d_mm)
    return (2.5 * xp.sqrt(m_n_mm) + 0.17 * xp.sqrt(d_mm) + 0.5) * grade_step(grade)


def helix_deviation_total(d_mm, b_mm, grade):
    """F_β = (0.1√d + 0.63√b + 4.2)·2^((Q−5)/2), µm (ISO 1328-1:1995 clause 6.3.6).

    >>> round(float(helix_deviation_total(187.08, 109.54, 5)), 2)
    12.16
    """
    xp = ops_of(d_mm, b_mm)
    return (0.1 * xp.sqrt(d_mm) + 0.63 * xp.sqrt(b_mm) + 4.2) * grade_step(grade)


def helix_slope_deviation(d_mm, b_mm, grade):
    """f_Hβ = f_fβ = (0.07√d + 0.45√b + 3)·2^((Q−5)/2), µm (ISO 1328-1:1995 clause 6.3.7).

    >>> round(float(helix_slope_deviation(187.08, 109.54, 5)), 2)
    8.67
    """
    xp = ops_of(d_mm, b_mm)
    return (0.07 * xp.sqrt(d_mm) + 0.45 * xp.sqrt(b_mm) + 3.0) * grade_step(grade)
