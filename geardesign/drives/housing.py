"""The housing of a gear stage: its centre distance from a standard series, and the shift rules a reducer
designer follows around it.

A reducer's housing is bored to a standard centre distance (GOST 2185-66, or the ISO 3 preferred numbers), and
the tooth counts, module and the sum of the profile shifts follow from it: x_Σ = z_Σ (inv α_wt − inv α_t) /
(2 tan α_n) (ISO 21771:2007 eq. (62)). :func:`standard_center_distance` picks, for each (m, z1, z2), the
smallest standard a_w whose x_Σ lies in :data:`REDUCER_X_SUM_WINDOW`; the split of x_Σ is then the stage's
shift objective (balanced specific sliding by default, optimize_shifts' choice for a fixed x-sum).

The windows are our modelling choices, stated here and in docs/drive_train.md: |x| <= 1.2 per gear
(:data:`REDUCER_SHIFT_BOUNDS`) and −0.5 <= x_Σ <= 1.0 (:data:`REDUCER_X_SUM_WINDOW`), the shifts a designer uses
without special reasons. The recommendations of ISO/TR 4467:1982 and DIN 3992:1964 (their x_Σ and distribution
lines for speed reducers) could not be obtained for this project and are not reproduced.
"""
from __future__ import annotations

from functools import lru_cache

import numpy as np

from ..errors import GearDesignError
from ..gears.center_distance import center_distance_from_x_sum, min_center_distance
from ..validate import one_number, require_range

__all__ = ["CENTER_DISTANCE_SERIES", "CENTER_DISTANCE_RANGE_MM", "REDUCER_X_SUM_WINDOW", "REDUCER_SHIFT_BOUNDS", "series_values",
           "standard_center_distance", "check_center_distance"]

# a name of a standard series -> (what it is, how to get its values)
CENTER_DISTANCE_SERIES = {
    "gost2185": "GOST 2185-66 series 1 and 2",
    "gost2185-1": "GOST 2185-66 series 1 (preferred)",
    "R10": "ISO 3 preferred numbers R10",
    "R20": "ISO 3 preferred numbers R20",
    "R40": "ISO 3 preferred numbers R40",
}
REDUCER_X_SUM_WINDOW = (-0.5, 1.0)
REDUCER_SHIFT_BOUNDS = (-1.2, 1.2)
CENTER_DISTANCE_RANGE_MM = (1.0, 1e5)


@lru_cache(maxsize=16)
def series_values(series: str) -> np.ndarray:
    """The centre distances [mm] of a standard series (a name of :data:`CENTER_DISTANCE_SERIES`).

    >>> series_values("gost2185")[:4].tolist()
    [40.0, 50.0, 63.0, 71.0]
    """
    from ..catalogs.tables import center_distance_series, preferred_numbers   # here: the catalog module's import (~20 modules) is needed only for a named series

    if series == "gost2185":
        values = center_distance_series((1, 2))
    elif series == "gost2185-1":
        values = center_distance_series(1)
    elif series in ("R10", "R20", "R40"):
        values = preferred_numbers(series, *CENTER_DISTANCE_RANGE_MM)
    else:
        values = None
    if values is not None:
        values.flags.writeable = False      # kept (lru_cache): a caller cannot change the series
        return values
    raise GearDesignError(f"center_distance series must be one of {', '.join(CENTER_DISTANCE_SERIES)}, "
                          f"got {series!r}")


def check_center_distance(value):
    """A stage's ``center_distance`` checked: None, "free", a series name or a housing's a_w in mm."""
    if value is None or value == "free" or (isinstance(value, str) and value in CENTER_DISTANCE_SERIES):
        return value
    if isinstance(value, str):
        raise GearDesignError(f"center_distance must be 'free', one of {', '.join(CENTER_DISTANCE_SERIES)} or a "
                              f"centre distance in mm, got {value!r}")
    return one_number("center_distance", require_range("center_distance", value, *CENTER_DISTANCE_RANGE_MM,
                                                       unit="mm"))


def standard_center_distance(m, z1, z2, series: str = "gost2185", beta_deg: float = 0.0,
                             x_sum_window=REDUCER_X_SUM_WINDOW, rack=None):
    """The smallest centre distance of ``series`` [mm] whose shift sum x_Σ lies in ``x_sum_window`` for each
    module m [mm] and tooth pair z1, z2 (arrays broadcast); NaN where none does.

    >>> float(standard_center_distance(3, 20, 61))      # a = 121.5 mm; 125 mm needs x_Σ = 1.21 > 1.0
    nan
    >>> float(standard_center_distance(3, 20, 62))      # a = 123 mm: 125 mm at x_Σ = 0.69
    125.0
    """
    from ..gears.rack import BasicRack

    rack = BasicRack() if rack is None else rack
    values = series_values(series)
    lo, hi = (center_distance_from_x_sum(m, z1, z2, s, rack, beta_deg) for s in x_sum_window)
    lo, hi = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)
    # a small tooth sum cannot reach the window's lower end (inv α_w <= 0): its least a_w is a cos α_t
    lo = np.where(np.isnan(lo), min_center_distance(m, z1, z2, rack, beta_deg), lo)
    i = np.searchsorted(values, lo * (1 - 1e-12), side="left")
    a_w = values[np.minimum(i, values.size - 1)]
    out = np.where((i < values.size) & (a_w <= hi * (1 + 1e-12)), a_w, np.nan)
    return float(out) if np.ndim(out) == 0 else out
