"""The basic rack profile (ISO 53 / GOST 13755-81) that generates and defines a spur gear."""
from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import GearDesignError
from ..validate import _show, ndim, one_number, require_finite, require_range

__all__ = ["BasicRack", "STANDARD_RACK", "ALPHA_RANGE_DEG", "HA_RANGE", "C_RANGE", "require_rack"]

# Pressure angles accepted: 1°–44° (standards use 14.5°–25°; the accuracy tests cover 10°–35°).
# At 0° the involute degenerates, at 45° the rack tooth has no tip land.
ALPHA_RANGE_DEG = (1.0, 44.0)
# Addendum coefficient: stub teeth use 0.8, standard 1.0, high-contact designs up to ~1.3; below
# 0.3 there is no tooth to speak of and the contact ratio collapses to nothing.
HA_RANGE = (0.3, 2.0)
C_RANGE = (0.0, 1.0)       # bottom clearance coefficient: 0.25 standard, up to ~0.4 for fine pitch


@dataclass(frozen=True)
class BasicRack:
    """Basic rack profile, in units of the module.

    Parameters
    ----------
    alpha_deg : pressure angle α in degrees, 1 <= α <= 44 (standard 20).
    ha : addendum coefficient h_a* (standard 1.0); the gear tooth addendum is h_a*·m.
    c : bottom clearance coefficient c* (standard 0.25); the dedendum is (h_a* + c*)·m.
    rho_f : root fillet radius coefficient ρ_f* of the rack tip that cuts the root
        (standard 0.38, ISO 53 profile A / GOST 13755-81).

    The defaults are the standard rack. ``rho_f`` must fit on the tip of the generating rack:
    0 <= ρ_f* <= s_tip·cos α / (2(1 − sin α)), s_tip = π/2 − 2(h_a* + c*) tan α the cutter's
    tip land. (ρ_f* = c*/(1 − sin α) = 0.37995 makes the fillet end exactly h_a* above the datum;
    the standard's 0.38 rounds it.)

    >>> r = BasicRack()
    >>> round(r.h_limit, 5)        # straight flank of the cutter ends ~h_a* above the datum
    0.99997
    >>> round(r.z_min_no_undercut, 3)
    17.097
    """

    alpha_deg: float = 20.0
    ha: float = 1.0
    c: float = 0.25
    rho_f: float = 0.38

    def __post_init__(self):
        if (type(self.alpha_deg) is float and type(self.ha) is float and type(self.c) is float
                and type(self.rho_f) is float and ALPHA_RANGE_DEG[0] <= self.alpha_deg <= ALPHA_RANGE_DEG[1]
                and HA_RANGE[0] <= self.ha <= HA_RANGE[1] and C_RANGE[0] <= self.c <= C_RANGE[1]
                and 0.0 <= self.rho_f <= self.rho_f_max + 1e-12):
            return   # plain floats in range (the standard rack): no numpy validation needed
        for name in ("alpha_deg", "ha", "c", "rho_f"):
            value = getattr(self, name)
            if ndim(value) != 0:
                raise GearDesignError(f"{name} must be a single number, got {_show(value)}")
            object.__setattr__(self, name, one_number(name, require_finite(name, value)))
        require_range("alpha_deg", self.alpha_deg, *ALPHA_RANGE_DEG, unit="deg")
        require_range("ha", self.ha, *HA_RANGE)
        require_range("c", self.c, *C_RANGE)
        rho_max = self.rho_f_max
        if not (0.0 <= self.rho_f <= rho_max + 1e-12):
            raise GearDesignError(
                f"rho_f must be in [0, {rho_max:.4g}] for alpha_deg={self.alpha_deg:g}, "
                f"ha={self.ha:g}, c={self.c:g} (the fillet must fit on the cutter tip), got {self.rho_f!r}")

    @property
    def alpha(self) -> float:
        """Pressure angle in radians."""
        return math.radians(self.alpha_deg)

    @property
    def rho_f_max(self) -> float:
        """Largest fillet radius coefficient that fits on the generating rack's tip."""
        a = self.alpha
        one_minus_sin = 1.0 - math.sin(a)
        land = math.pi / 2 - 2.0 * (self.ha + self.c) * math.tan(a)  # tip land of the cutter, /m
        if land <= 0:
            return 0.0
        return land * math.cos(a) / (2.0 * one_minus_sin)

    @property
    def h_limit(self) -> float:
        """Height (/m) above the datum line where the cutter's straight flank ends.

        h_l* = h_a* + c* − ρ_f*(1 − sin α): the cutter tooth is h_a* + c* high and its tip
        fillet of radius ρ_f* meets the straight flank (1 − sin α)·ρ_f* below the tip line.
        This point generates the limit point of the involute (Litvin & Fuentes, Gear Geometry
        and Applied Theory, 2nd ed., §10.5; ISO 21771:2007, §5.4).
        """
        return self.ha + self.c - self.rho_f * (1.0 - math.sin(self.alpha))

    @property
    def z_min_no_undercut(self) -> float:
        """Smallest unshifted tooth count without undercut, 2 h_l*/sin²α (17.1 for 20°)."""
        return 2.0 * self.h_limit / math.sin(self.alpha) ** 2


# The standard rack, shared as the default of every mesh and pair (a frozen value: sharing is safe).
STANDARD_RACK = BasicRack()


def require_rack(rack) -> BasicRack:
    """``rack``, or the standard rack for None; anything else is refused by name."""
    if rack is None:
        return STANDARD_RACK
    if not isinstance(rack, BasicRack):
        raise GearDesignError(f"rack must be a geardesign.BasicRack or None, got {_show(rack)}")
    return rack
