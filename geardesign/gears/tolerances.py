"""Flank tolerances of ISO 1328-1:2013 (cylindrical gears, ISO system of flank tolerance classification, part 1),
vectorised: single pitch, cumulative pitch, profile and helix (total, form, slope), in µm.

The 2013 edition's flank tolerance classes A = 1 … 11 are NOT the 1995 edition's accuracy grades 0 … 12 (other
formulas; notes, trap 7): an example that quotes a 1995 grade does not carry over. Each class is the class-5
value times √2^(A − 5) (clause 5.2.2); a value is rounded (clause 5.2.3) to the nearest 0.1 µm below 5 µm, to
0.5 µm from 5 to 10 µm and to 1 µm above 10 µm, the totals F_αT, F_βT taken from the unrounded parts. The
formulas hold for 5 ≤ z ≤ 1000, 5 ≤ d ≤ 15 000 mm, 0.5 ≤ m_n ≤ 70 mm, 4 ≤ b ≤ 1200 mm and β ≤ 45° (clause 1 and
5.2.1: not to be extrapolated); outside them one clear GearDesignError.

Sources: ISO 1328-1:2013 clause 5.3, formulas (5)–(12) (identical in ANSI/AGMA ISO 1328-1-B14). The standard's
text was not available here; the formulas, ranges and rounding are as stated, identically, by two public
implementations found with the search tools (cited in tests/data/iso1328_2013.md).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, fields

import numpy as np

from ..errors import GearDesignError
from ..renamed import renamed_keywords
from ..results import Result, plain
from ..validate import broadcast_inputs, require_int, require_range

__all__ = ["FlankTolerances", "flank_tolerances", "round_iso1328", "class_factor", "single_pitch_tolerance_um",
           "cumulative_pitch_tolerance_um", "profile_slope_tolerance_um", "profile_form_tolerance_um",
           "profile_total_tolerance_um", "helix_slope_tolerance_um", "helix_form_tolerance_um",
           "helix_total_tolerance_um", "ISO1328_RANGES", "ISO1328_CLASSES"]

ISO1328_CLASSES = (1, 11)
# ISO 1328-1:2013 clause 1: the formulas' range (not to be extrapolated)
ISO1328_RANGES = {"z": (5, 1000), "d_mm": (5.0, 15000.0), "m_n": (0.5, 70.0), "face_width_mm": (4.0, 1200.0),
                  "beta_deg": (0.0, 45.0)}


def class_factor(accuracy_class):
    """√2^(A − 5): one class step is a factor √2 (ISO 1328-1:2013, 5.2.2).

    >>> round(float(class_factor(7)), 12)
    2.0
    """
    return np.sqrt(2.0) ** (np.asarray(accuracy_class, dtype=float) - 5.0)


def round_iso1328(value_um):
    """ISO 1328-1:2013, 5.2.3: to 0.1 µm below 5 µm, to 0.5 µm from 5 to 10 µm, to 1 µm above 10 µm (halves up).

    >>> [float(round_iso1328(v)) for v in (4.94, 8.94, 9.76, 10.5, 23.4)]
    [4.9, 9.0, 10.0, 11.0, 23.0]
    """
    v = np.asarray(value_um, dtype=float)
    step = np.where(v > 10.0, 1.0, np.where(v >= 5.0, 0.5, 0.1))
    out = np.floor(v / step + 0.5 + 1e-9) * step
    out = np.round(out, 1)
    return float(out) if out.ndim == 0 else out


def single_pitch_tolerance_um(d_mm, m_n, accuracy_class):
    """f_pT = (0.001 d + 0.4 m_n + 5) √2^(A−5), µm (ISO 1328-1:2013 formula (5)); unrounded."""
    return (0.001 * np.asarray(d_mm) + 0.4 * np.asarray(m_n) + 5.0) * class_factor(accuracy_class)


def cumulative_pitch_tolerance_um(d_mm, m_n, accuracy_class):
    """F_pT = (0.002 d + 0.55 √d + 0.7 m_n + 12) √2^(A−5), µm (ISO 1328-1:2013 formula (6)); unrounded."""
    d = np.asarray(d_mm, dtype=float)
    return (0.002 * d + 0.55 * np.sqrt(d) + 0.7 * np.asarray(m_n) + 12.0) * class_factor(accuracy_class)


def profile_slope_tolerance_um(d_mm, m_n, accuracy_class):
    """f_HαT = (0.4 m_n + 0.001 d + 4) √2^(A−5), µm (ISO 1328-1:2013 formula (7)); ± this; unrounded."""
    return (0.4 * np.asarray(m_n) + 0.001 * np.asarray(d_mm) + 4.0) * class_factor(accuracy_class)


def profile_form_tolerance_um(m_n, accuracy_class):
    """f_fαT = (0.55 m_n + 5) √2^(A−5), µm (ISO 1328-1:2013 formula (8)); unrounded."""
    return (0.55 * np.asarray(m_n) + 5.0) * class_factor(accuracy_class)


def profile_total_tolerance_um(d_mm, m_n, accuracy_class):
    """F_αT = √(f_HαT² + f_fαT²) of the unrounded parts, µm (ISO 1328-1:2013 formula (9)); unrounded."""
    return np.hypot(profile_slope_tolerance_um(d_mm, m_n, accuracy_class), profile_form_tolerance_um(m_n, accuracy_class))


def helix_slope_tolerance_um(d_mm, face_width_mm, accuracy_class):
    """f_HβT = (0.05 √d + 0.35 √b + 4) √2^(A−5), µm (ISO 1328-1:2013 formula (10)); ± this; unrounded."""
    return (0.05 * np.sqrt(np.asarray(d_mm, dtype=float)) + 0.35 * np.sqrt(np.asarray(face_width_mm, dtype=float))
            + 4.0) * class_factor(accuracy_class)


def helix_form_tolerance_um(d_mm, face_width_mm, accuracy_class):
    """f_fβT = (0.07 √d + 0.45 √b + 4) √2^(A−5), µm (ISO 1328-1:2013 formula (11)); unrounded."""
    return (0.07 * np.sqrt(np.asarray(d_mm, dtype=float)) + 0.45 * np.sqrt(np.asarray(face_width_mm, dtype=float))
            + 4.0) * class_factor(accuracy_class)


def helix_total_tolerance_um(d_mm, face_width_mm, accuracy_class):
    """F_βT = √(f_HβT² + f_fβT²) of the unrounded parts, µm (ISO 1328-1:2013 formula (12)); unrounded."""
    return np.hypot(helix_slope_tolerance_um(d_mm, face_width_mm, accuracy_class),
                    helix_form_tolerance_um(d_mm, face_width_mm, accuracy_class))


_NAMES = {"f_pT": "single pitch", "F_pT": "cumulative pitch (total)", "F_alphaT": "profile total",
          "f_falphaT": "profile form", "f_HalphaT": "profile slope (±)", "F_betaT": "helix total",
          "f_fbetaT": "helix form", "f_HbetaT": "helix slope (±)"}


@dataclass(frozen=True)
class FlankTolerances(Result):
    """ISO 1328-1:2013 flank tolerances of a class, µm, rounded by clause 5.2.3 (floats, or arrays for many gears);
    the helix ones are None without a face width. ``d_mm`` the reference diameter they were taken at."""

    accuracy_class: object
    m_n: object
    z: object
    d_mm: object
    face_width_mm: object
    f_pT: object
    F_pT: object
    F_alphaT: object
    f_falphaT: object
    f_HalphaT: object
    F_betaT: object
    f_fbetaT: object
    f_HbetaT: object

    _success_field = "in_range"
    in_range = True      # out of range is refused before a result exists

    def to_frame(self):
        """Rows ``symbol, tolerance, value_um`` for one gear; one row per gear for arrays."""
        import pandas as pd

        if np.ndim(self.f_pT) == 0:
            return pd.DataFrame([(k, v, getattr(self, k)) for k, v in _NAMES.items() if getattr(self, k) is not None],
                                columns=["symbol", "tolerance", "value_um"])
        return pd.DataFrame({fl.name: np.ravel(np.broadcast_to(getattr(self, fl.name), np.shape(self.f_pT)))
                             for fl in fields(self) if getattr(self, fl.name) is not None})

    def to_dict(self) -> dict:
        out = {fl.name: plain(getattr(self, fl.name)) for fl in fields(self)}
        out["status"] = self.status
        return out

    def __repr__(self) -> str:
        if np.ndim(self.f_pT) != 0:
            return f"FlankTolerances(<{np.size(self.f_pT)} gears; to_frame() for the table>)"
        head = f"FlankTolerances(ISO 1328-1:2013 class {int(self.accuracy_class)}, m_n {self.m_n:g} mm, d {self.d_mm:.4g} mm"
        lines = [head + (f", b {self.face_width_mm:g} mm" if self.face_width_mm is not None else "")]
        lines += [f"  {k:<10} {getattr(self, k):6.1f} µm  {v}" for k, v in _NAMES.items() if getattr(self, k) is not None]
        return "\n".join(lines) + ")"


def _check_range(name, value, lo, hi, unit=""):
    return require_range(f"{name} (ISO 1328-1:2013 range)", value, lo, hi, unit=unit)


@renamed_keywords(m_n="m")
def flank_tolerances(m, z, accuracy_class, *, beta_deg=0.0, face_width_mm=None, d_mm=None) -> FlankTolerances:
    """The ISO 1328-1:2013 flank tolerances (µm) of a gear: (normal) module m (mm; ``m_n=`` is its old name), tooth count z, flank tolerance class
    A (1 … 11), helix β, face width b (for the helix tolerances) and the reference diameter d (default
    z m_n / cos β); arrays broadcast. Outside the standard's ranges (module docstring): GearDesignError.

    >>> t = flank_tolerances(3, 40, 6, face_width_mm=30)      # d = 120 mm: f_pT = 6.32·√2 = 8.94 -> 9.0 µm
    >>> t.f_pT, t.F_pT, t.F_alphaT
    (9.0, 29.0, 12.0)
    """
    a = require_int("accuracy_class (ISO 1328-1:2013 flank tolerance class)", accuracy_class, *ISO1328_CLASSES)
    m_n = _check_range("m", m, *ISO1328_RANGES["m_n"], unit="mm")
    z = require_int("z (ISO 1328-1:2013 range)", z, *ISO1328_RANGES["z"])
    if np.ndim(beta_deg) != 0:
        raise GearDesignError("beta_deg must be one number for flank_tolerances")
    beta = float(_check_range("beta_deg", beta_deg, *ISO1328_RANGES["beta_deg"], unit="deg"))
    d = (m_n * z / math.cos(math.radians(beta))) if d_mm is None else d_mm
    d = _check_range("d_mm (reference diameter)", d, *ISO1328_RANGES["d_mm"], unit="mm")
    b = None if face_width_mm is None else _check_range("face_width_mm", face_width_mm, *ISO1328_RANGES["face_width_mm"],
                                                        unit="mm")
    arrays = broadcast_inputs(a=a, m_n=m_n, z=z, d=d, **({} if b is None else {"b": b}))
    a, m_n, z, d = arrays[:4]
    b = arrays[4] if b is not None else None
    r = round_iso1328

    def fl(v):
        if v is None:
            return None
        v = np.asarray(v)
        return (int(v) if v.dtype.kind in "iu" else float(v)) if v.ndim == 0 else v

    helix = (None, None, None) if b is None else (
        r(helix_total_tolerance_um(d, b, a)), r(helix_form_tolerance_um(d, b, a)), r(helix_slope_tolerance_um(d, b, a)))
    return FlankTolerances(
        accuracy_class=fl(a), m_n=fl(m_n), z=fl(z), d_mm=fl(d), face_width_mm=fl(b),
        f_pT=fl(r(single_pitch_tolerance_um(d, m_n, a))), F_pT=fl(r(cumulative_pitch_tolerance_um(d, m_n, a))),
        F_alphaT=fl(r(profile_total_tolerance_um(d, m_n, a))), f_falphaT=fl(r(profile_form_tolerance_um(m_n, a))),
        f_HalphaT=fl(r(profile_slope_tolerance_um(d, m_n, a))),
        F_betaT=fl(helix[0]), f_fbetaT=fl(helix[1]), f_HbetaT=fl(helix[2]))
