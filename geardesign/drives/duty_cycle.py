"""A duty cycle: a load spectrum relative to a stage's nominal load, the form a drive's spectrum takes (each gear
stage of a drive carries its own nominal torque and speed from the power flow, so one duty cycle loads them all).

Each bin is a torque factor (the bin's torque over the nominal torque; negative: the other flank), a speed factor
(the bin's speed over the nominal speed) and a time share; with the nominal torque T_n and speed n_n of a stage and
the required life L_h its bins are T_i = q_T,i·T_n, n_i = q_n,i·n_n for t_i = share_i·L_h hours (a
:class:`~geardesign.gears.spectrum.LoadSpectrum`, :meth:`DutyCycle.at`). This is how gear rating programs take a
spectrum for a gearbox (a torque or power factor, a speed factor and a frequency per bin relative to the nominal
load) and how ISO 6336-6:2019 Annex A relates a spectrum to the nominal torque (K_A = T_eq/T_n).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import GearDesignError
from ..gears.spectrum import BINS_MAX, LoadSpectrum, equivalent_torque
from ..validate import one_number, require_range

__all__ = ["DutyCycle", "FACTOR_RANGE"]

FACTOR_RANGE = (-100.0, 100.0)     # a bin's torque or speed over the nominal: overloads of a few times, not 1e9


@dataclass(frozen=True, eq=False)      # arrays: compared by identity (as a LoadSpectrum)
class DutyCycle:
    """Bins of a load spectrum relative to the nominal load: ``torque_factor`` (T_i/T_n, signed: negative loads the
    other flank), ``share`` (each bin's share of the time, summing to 1) and ``speed_factor`` (n_i/n_n, one number
    or one per bin, > 0). :meth:`at` gives the bins of one nominal load over a required life.

    >>> duty = DutyCycle([1.0, 0.5], [0.1, 0.9])
    >>> duty
    DutyCycle(2 bins, T/T_n 0.5..1)
    >>> s = duty.at(200.0, 1000.0, 10000.0)         # T_n = 200 N·m at 1000 rpm for 10 000 h
    >>> [float(t) for t in s.torque_nm], [float(h) for h in s.time_h]
    ([200.0, 100.0], [1000.0, 9000.0])
    """

    torque_factor: np.ndarray
    share: np.ndarray
    speed_factor: object = 1.0

    def __post_init__(self):
        q = require_range("torque_factor", self.torque_factor, *FACTOR_RANGE).astype(float).ravel()
        if q.size == 0 or q.size > BINS_MAX:
            raise GearDesignError(f"torque_factor must have 1 to {BINS_MAX} bins, got {q.size}")
        if not np.any(q != 0.0):
            raise GearDesignError("torque_factor must load some bin: all bins are 0")
        s = require_range("share", self.share, 0.0, 1.0).astype(float).ravel()
        if s.shape != q.shape:
            raise GearDesignError(f"share must be one per bin ({q.size} bins), got {s.size}")
        if not math.isclose(float(s.sum()), 1.0, rel_tol=1e-6):
            raise GearDesignError(f"share must sum to 1, got {float(s.sum()):.9g}")
        n = require_range("speed_factor", self.speed_factor, 0.0, FACTOR_RANGE[1], lo_open=True).astype(float).ravel()
        if n.size not in (1, q.size):
            raise GearDesignError(f"speed_factor must be one number or one per bin ({q.size} bins), got {n.size}")
        n = np.broadcast_to(n, q.shape).copy()
        for name, v in (("torque_factor", q), ("share", s / s.sum()), ("speed_factor", n)):
            v.setflags(write=False)
            object.__setattr__(self, name, v)

    @classmethod
    def from_spectrum(cls, spectrum: LoadSpectrum, torque_nm: float, n_rpm: float) -> "DutyCycle":
        """The duty cycle of ``spectrum`` (bins of torque and speed of one shaft) relative to that shaft's nominal
        torque ``torque_nm`` (N·m) and speed ``n_rpm`` (rpm): factors T_i/T_n, n_i/n_n and time shares t_i/Σt. A
        spectrum counted per tooth is refused (its teeth are one pair's)."""
        if not isinstance(spectrum, LoadSpectrum):
            raise GearDesignError(f"spectrum must be a geardesign LoadSpectrum, got {type(spectrum).__name__}")
        if spectrum.per_tooth:
            raise GearDesignError("a spectrum counted per tooth (LoadSpectrum.from_curve) belongs to one pair's teeth; "
                                  "a duty cycle takes bins of torque, speed and time")
        T = one_number("torque_nm", require_range("torque_nm", torque_nm, 0.0, 1e9, lo_open=True, unit="N·m"))
        n = one_number("n_rpm", require_range("n_rpm", n_rpm, 0.0, 1e6, lo_open=True, unit="rpm"))
        q = spectrum.torque_nm / T
        big = np.abs(q) > FACTOR_RANGE[1]
        if big.any():
            i = int(np.flatnonzero(big)[0])
            raise GearDesignError(f"the spectrum's torque {spectrum.torque_nm[i]:g} N·m (bin {i}) is more than "
                                  f"{FACTOR_RANGE[1]:g} times the nominal {T:g} N·m")
        return cls(q, spectrum.time_h / spectrum.duration_h, spectrum.n_rpm / n)

    def at(self, torque_nm: float, n_rpm: float, life_h: float) -> LoadSpectrum:
        """The bins on the pinion of a stage of nominal torque ``torque_nm`` (N·m) and speed ``n_rpm`` (rpm) over the
        required life ``life_h`` (h): T_i = q_T,i·T_n, n_i = q_n,i·n_n, t_i = share_i·L_h."""
        return LoadSpectrum(self.torque_factor * float(torque_nm), self.speed_factor * float(n_rpm),
                            self.share * float(life_h))

    def application_factor(self, p: float) -> float:
        """K_A = T_eq/T_n the duty cycle stands for (ISO 6336-6:2019 Annex A): the equivalent of its torque factors'
        magnitudes weighted by their load cycles (share × speed factor) for the S-N curve's exponent ``p`` written in
        torque (:func:`~geardesign.gears.strength.service_life.torque_exponent`).

        >>> round(DutyCycle([1.0, 0.5], [0.1, 0.9]).application_factor(6.6), 4)    # (0.1 + 0.9·0.5^6.6)^(1/6.6)
        0.715
        """
        return equivalent_torque(np.abs(self.torque_factor), self.share * self.speed_factor, p)

    @property
    def reverses(self) -> bool:
        """True when some bin loads the other flank (a negative torque factor)."""
        return bool(np.any(self.torque_factor < 0))

    def __repr__(self) -> str:
        q = np.abs(self.torque_factor)
        return (f"DutyCycle({q.size} bins, T/T_n {q.min():.4g}..{q.max():.4g}"
                f"{'' if np.all(self.speed_factor == 1.0) else ', speed factors'}{', reversing' if self.reverses else ''})")
