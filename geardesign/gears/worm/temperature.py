"""Heat balance of a worm gearbox: the oil sump temperature the losses drive and the thermal safety.

The housing sheds the power loss P_V (W) to the air through its area A (m²) with the heat transfer
coefficient k (W/(m²·K)); in equilibrium P_V = k·A·(θ_S − θ_0). Autodesk Inventor's worm gear strength
check (after CSN 01 4686) writes the same balance as "safety against overheating: Q_od = ϑ_D·A·k >= P_z" and
estimates a well-ribbed housing's area A ≈ 9·10⁻⁵·a^1.85 m² (a in mm). ISO/TS 14521's own oil-temperature
formulas (method B with its housing constants) could not be read in a public text: k and A are the caller's.
"""
from __future__ import annotations

import numpy as np

from ...errors import GearDesignError
from ...validate import require_positive, require_range

__all__ = ["THETA_RANGE_C", "housing_area_estimate", "oil_sump_temperature", "thermal_safety",
           "allowable_power_loss"]

THETA_RANGE_C = (-40.0, 200.0)


def housing_area_estimate(a):
    """Heat-shedding area A (m²) of a well-ribbed worm gear housing of centre distance a (mm),
    A ≈ 9·10⁻⁵·a^1.85 (Autodesk Inventor help, *Strength calculation of worm gears*, "Increase of
    temperature check").

    >>> round(float(housing_area_estimate(100.0)), 4)
    0.4511
    """
    return 9e-5 * require_positive("a", a, unit="mm") ** 1.85


def _theta(name, value):
    return require_range(name, value, *THETA_RANGE_C, unit="°C")


def oil_sump_temperature(P_V, k_heat, A_housing, theta_0=20.0):
    """Oil sump temperature θ_S = θ_0 + P_V/(k·A) (°C) in thermal equilibrium: power loss P_V in W, heat
    transfer coefficient k in W/(m²·K), housing area A in m², ambient θ_0 in °C.

    >>> float(oil_sump_temperature(1000.0, 20.0, 1.0, 20.0))
    70.0
    """
    p = require_range("P_V", P_V, 0.0, 1e9, unit="W")
    k = require_positive("k_heat", k_heat, unit="W/(m²·K)")
    A = require_positive("A_housing", A_housing, unit="m²")
    return _theta("theta_0", theta_0) + p / (k * A)


def allowable_power_loss(k_heat, A_housing, theta_0=20.0, theta_lim=90.0):
    """The power loss Q = k·A·(θ_lim − θ_0) (W) the housing sheds at the oil temperature limit θ_lim."""
    t0 = _theta("theta_0", theta_0)
    tl = _theta("theta_lim", theta_lim)
    if np.any(tl <= t0):
        raise GearDesignError(f"theta_lim must be above theta_0, got theta_lim={tl!r}, theta_0={t0!r}")
    return require_positive("k_heat", k_heat, unit="W/(m²·K)") * require_positive(
        "A_housing", A_housing, unit="m²") * (tl - t0)


def thermal_safety(P_V, k_heat, A_housing, theta_0=20.0, theta_lim=90.0):
    """Safety against overheating S_T = Q/P_V, Q = k·A·(θ_lim − θ_0): the heat the housing can shed at the
    oil temperature limit over the heat the gearbox makes (Autodesk/CSN form; 1 means θ_S = θ_lim). Infinite
    for P_V = 0.

    >>> float(thermal_safety(1000.0, 20.0, 1.0, 20.0, 90.0))
    1.4
    """
    q = allowable_power_loss(k_heat, A_housing, theta_0, theta_lim)
    p = require_range("P_V", P_V, 0.0, 1e9, unit="W")
    with np.errstate(divide="ignore"):
        return np.where(p > 0, q / np.where(p > 0, p, 1.0), np.inf)
