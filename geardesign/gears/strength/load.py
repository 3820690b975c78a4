"""The load a gear pair carries: a torque or a power at the speed of the gear it is given on."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...errors import GearDesignError
from ...validate import hint_unknown_arguments, one_number, require_range

__all__ = ["Load", "TORQUE_RANGE_NM", "SPEED_RANGE_RPM", "APPLICATION_FACTOR_RANGE", "LIFE_RANGE_H"]

TORQUE_RANGE_NM = (0.0, 1e9)          # open below; a watch to a mill drive with room to spare
POWER_RANGE_KW = (0.0, 1e6)
SPEED_RANGE_RPM = (0.0, 1e6)          # open below: a static load has no speed-dependent factor
APPLICATION_FACTOR_RANGE = (1.0, 10.0)   # ISO 6336-6 Annex: 1.0 (uniform) to ~2.25; beyond 10 is a typo
LIFE_RANGE_H = (0.0, 1e7)             # ~1100 years


@dataclass(frozen=True)
class Load:
    """A torque (N·m) or a power (kW), at the speed ``n_rpm`` of the gear ``on_gear`` (1 or 2) it is
    given on (both are stored: the one not given is derived, :attr:`given` says which was);
    ``application_factor`` K_A (ISO 6336-1:2019 clause 6.3, 1.0 = uniform); ``life_h``
    the required life in hours (None: endurance, Z_NT = Y_NT = 1 at the knee of the S-N curve).

    The torque and power are related by P = T·2πn/60 (kW = N·m·rpm/9549.3).

    >>> round(Load(power_kw=75, n_rpm=1480).torque_nm, 2)   # a 75 kW motor at 1480 rpm
    483.92
    >>> round(Load(torque_nm=9000, n_rpm=360).power_kw, 2)   # ISO/TR 6336-30 example 1
    339.29
    >>> Load(torque_nm=1, power_kw=1, n_rpm=1)
    Traceback (most recent call last):
    ...
    geardesign.errors.GearDesignError: give either torque_nm or power_kw, not both (got torque_nm=1, power_kw=1)
    """

    torque_nm: float | None = None
    power_kw: float | None = None
    n_rpm: float | None = None
    on_gear: int = 1
    application_factor: float = 1.0
    life_h: float | None = None

    def __post_init__(self):
        if (self.torque_nm is None) == (self.power_kw is None):
            got = f"torque_nm={self.torque_nm}, power_kw={self.power_kw}"
            which = "not both" if self.torque_nm is not None else "one is needed"
            raise GearDesignError(f"give either torque_nm or power_kw, {which} (got {got})")
        if self.n_rpm is None:
            raise GearDesignError("n_rpm (the speed of the gear the load is given on) is needed, got None")
        n = one_number("n_rpm", require_range("n_rpm", self.n_rpm, *SPEED_RANGE_RPM, lo_open=True, unit="rpm"))
        object.__setattr__(self, "n_rpm", n)
        if self.torque_nm is not None:
            t = one_number("torque_nm", require_range("torque_nm", self.torque_nm, *TORQUE_RANGE_NM,
                                                      lo_open=True, unit="N·m"))
            object.__setattr__(self, "torque_nm", t)
            object.__setattr__(self, "power_kw", t * n * math.pi / 30.0 / 1e3)
            object.__setattr__(self, "_given", "torque")
        else:
            p = one_number("power_kw", require_range("power_kw", self.power_kw, *POWER_RANGE_KW, lo_open=True,
                                                     unit="kW"))
            object.__setattr__(self, "power_kw", p)
            t = p * 1e3 * 30.0 / math.pi / n    # not P/ω: ω of a denormal speed underflows to 0 (inf here: refused)
            if not t <= TORQUE_RANGE_NM[1]:
                raise GearDesignError(f"power_kw and n_rpm must give a torque in (0, {TORQUE_RANGE_NM[1]:g}] N·m, got "
                                      f"power_kw={p!r} at n_rpm={n!r} ({t:.4g} N·m)")
            object.__setattr__(self, "torque_nm", t)
            object.__setattr__(self, "_given", "power")
        if self.on_gear not in (1, 2) or isinstance(self.on_gear, bool):
            raise GearDesignError(f"on_gear must be 1 or 2 (the gear the torque and speed are given on), "
                                  f"got {self.on_gear!r}")
        object.__setattr__(self, "application_factor", one_number("application_factor", require_range(
            "application_factor", self.application_factor, *APPLICATION_FACTOR_RANGE)))
        if self.life_h is not None:
            object.__setattr__(self, "life_h", one_number("life_h", require_range(
                "life_h", self.life_h, *LIFE_RANGE_H, lo_open=True, unit="h")))

    @classmethod
    def per_design(cls, torque_nm, n_rpm, application_factor: float = 1.0, life_h: float | None = None) -> "Load":
        """A torque and speed per design (arrays broadcast with the designs of a :func:`pair_strength` call, on
        gear 1): many load cases in one vectorised call, as a drive search sizes a stage at each flow into it.
        Each element is validated as :class:`Load` validates one.

        >>> L = Load.per_design([400.0, 800.0], [1000.0, 500.0])
        >>> L.power_kw.round(3).tolist()
        [41.888, 41.888]
        """
        T = np.array(require_range("torque_nm", torque_nm, *TORQUE_RANGE_NM, lo_open=True, unit="N·m"), dtype=float)
        n = np.array(require_range("n_rpm", n_rpm, *SPEED_RANGE_RPM, lo_open=True, unit="rpm"), dtype=float)
        T, n = np.broadcast_arrays(T, n)
        one = _PerDesign(torque_nm=1.0, n_rpm=1.0, application_factor=application_factor, life_h=life_h)
        for name, value in (("torque_nm", T), ("n_rpm", n), ("power_kw", T * n * math.pi / 30.0 / 1e3)):
            value.flags.writeable = False
            object.__setattr__(one, name, value)
        return one

    @property
    def omega(self) -> float:
        """Angular speed of the gear the load is given on, rad/s."""
        return self.n_rpm * math.pi / 30.0

    @property
    def given(self) -> str:
        """"torque" or "power": which of the two was given (the other is derived)."""
        return object.__getattribute__(self, "_given")


class _PerDesign(Load):
    """A :meth:`Load.per_design`: its arrays make it one object, equal to itself alone (a check's memo keys on it)."""

    __eq__ = object.__eq__
    __hash__ = object.__hash__


# Names a user may reach for: the hint the error gives (each quantity's name carries its unit).
hint_unknown_arguments(Load, {
    "torque": "the torque is torque_nm={value!r} (N·m)",
    "T": "the torque is torque_nm={value!r} (N·m)",
    "power": "the power is power_kw={value!r} (kW)",
    "P": "the power is power_kw={value!r} (kW)",
    **{k: "the speed is n_rpm={value!r} (rpm, of the gear on_gear)" for k in ("n", "speed", "speed_rpm", "rpm")},
    "K_A": "the application factor is application_factor={value!r}",
    **{k: "the required life is life_h={value!r} (hours)" for k in ("life", "life_hours")},
    "gear": "the gear the load is given on is on_gear={value!r} (1 or 2)",
})
