"""The cylinder pressure over the working cycle (the indicator diagram p(φ)) and the gas force it puts on the piston.

An :class:`IndicatorDiagram` is a table of absolute pressure against the cycle angle (0 … 720° for a four-stroke
engine, measured from the top dead centre at the start of intake; 0 … 360° for a two-stroke, from the firing top
dead centre), read periodically with linear interpolation. It comes from a measured table, a CSV file, or the
documented parametric curve :func:`otto_pressure` (the polytropic cycle of the engine course works' thermal
calculation).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import GearDesignError
from ..files import read_text_bounded
from ..validate import one_number, require_count, require_finite, require_positive, require_range
from .kinematics import check_lengths, piston_displacement

__all__ = ["IndicatorDiagram", "gas_force", "piston_area", "otto_pressure", "cycle_volume", "STROKES",
           "ATMOSPHERE_MPA", "PRESSURE_RANGE_MPA"]

STROKES = {2: 360.0, 4: 720.0}    # strokes per cycle -> the cycle's crank angle, degrees
ATMOSPHERE_MPA = 0.101325         # standard atmosphere (ISO 2533): the crankcase pressure by default
PRESSURE_RANGE_MPA = (0.0, 100.0)  # absolute; 100 MPa is beyond any firing pressure (diesels reach ~25 MPa)
DIAGRAM_BYTES_MAX = 16 << 20   # an indicator diagram: a measured cycle of some 10^5 points at most


def piston_area(cylinder_bore_mm) -> np.ndarray:
    """Piston crown area A = π·D²/4 (mm²).

    >>> round(float(piston_area(100)), 4)
    7853.9816
    """
    d = require_positive("cylinder_bore_mm", cylinder_bore_mm, "mm")
    return math.pi * d * d / 4.0


def gas_force(pressure_mpa, cylinder_bore_mm, crankcase_pressure_mpa=ATMOSPHERE_MPA) -> np.ndarray:
    """Gas force on the piston, F_g = (p − p₀)·π·D²/4 (N; MPa·mm² = N), positive pushing the piston towards the
    crank; p absolute, p₀ the crankcase pressure under the piston (Kolchin & Demidov 1980 §10.1).

    >>> round(float(gas_force(5.101325, 100)), 3)      # 5 MPa over the crankcase on a 100 mm bore
    39269.908
    """
    p = require_range("pressure_mpa", pressure_mpa, *PRESSURE_RANGE_MPA, unit="MPa")
    p0 = require_range("crankcase_pressure_mpa", crankcase_pressure_mpa, *PRESSURE_RANGE_MPA, unit="MPa")
    return (p - p0) * piston_area(cylinder_bore_mm)


def _strokes(strokes) -> float:
    if isinstance(strokes, bool) or not isinstance(strokes, (int, float, np.integer, np.floating)) \
            or strokes not in STROKES:
        raise GearDesignError(f"strokes must be 2 or 4 (a two- or four-stroke cycle), got {strokes!r}")
    return STROKES[int(strokes)]


@dataclass(frozen=True, eq=False)
class IndicatorDiagram:
    """Absolute cylinder pressure ``pressure_mpa`` (MPa) at the cycle angles ``crank_angle_deg`` (degrees, strictly
    increasing inside one cycle of ``strokes``), read periodically by linear interpolation.

    >>> d = IndicatorDiagram([0, 180, 360, 540], [0.1, 0.1, 3.0, 0.3])
    >>> [round(float(p), 6) for p in d.pressure([90, 450, 630, 720 + 90])]
    [0.1, 1.65, 0.2, 0.1]
    """

    crank_angle_deg: np.ndarray
    pressure_mpa: np.ndarray
    strokes: int = 4
    source: str = field(default="table", compare=False)

    def __post_init__(self):
        cycle = _strokes(self.strokes)
        phi = require_finite("crank_angle_deg", self.crank_angle_deg).astype(float).ravel()
        p = require_range("pressure_mpa", self.pressure_mpa, *PRESSURE_RANGE_MPA, unit="MPa").astype(float).ravel()
        if phi.size != p.size:
            raise GearDesignError(f"crank_angle_deg and pressure_mpa must have one value each per point, got "
                                  f"{phi.size} angles and {p.size} pressures")
        if phi.size < 2:
            raise GearDesignError(f"an indicator diagram needs at least 2 points, got {phi.size}")
        if not (np.all(np.diff(phi) > 0) and phi[0] >= 0 and phi[-1] < cycle):
            raise GearDesignError(f"crank_angle_deg must increase strictly inside one cycle [0, {cycle:g}) degrees "
                                  f"of a {self.strokes}-stroke engine, got {phi[0]:g} ... {phi[-1]:g}")
        object.__setattr__(self, "crank_angle_deg", phi)
        object.__setattr__(self, "pressure_mpa", p)

    @property
    def cycle_deg(self) -> float:
        """The cycle's crank angle: 720° (four-stroke) or 360° (two-stroke)."""
        return STROKES[self.strokes]

    def pressure(self, crank_angle_deg) -> np.ndarray:
        """Absolute pressure (MPa) at any cycle angles (degrees, taken modulo the cycle)."""
        phi = np.mod(require_finite("crank_angle_deg", crank_angle_deg), self.cycle_deg)
        return np.interp(phi, self.crank_angle_deg, self.pressure_mpa, period=self.cycle_deg)

    @classmethod
    def from_csv(cls, path, strokes: int = 4) -> IndicatorDiagram:
        """Read a CSV file with the columns ``crank_angle_deg`` and ``pressure_mpa`` (absolute)."""
        import csv

        text = read_text_bounded(path, "indicator diagram", DIAGRAM_BYTES_MAX)
        rows = list(csv.DictReader(text.splitlines()))
        if not rows or not {"crank_angle_deg", "pressure_mpa"} <= set(rows[0]):
            raise GearDesignError(f"indicator diagram {str(path)!r}: expected the columns crank_angle_deg, "
                                  f"pressure_mpa, got {', '.join(rows[0]) if rows else 'no rows'}")
        try:
            phi = [float(r["crank_angle_deg"]) for r in rows]
            p = [float(r["pressure_mpa"]) for r in rows]
        except (TypeError, ValueError):
            raise GearDesignError(f"indicator diagram {str(path)!r}: every row needs a number in crank_angle_deg "
                                  f"and pressure_mpa") from None
        return cls(np.array(phi), np.array(p), strokes, source=str(path))

    @classmethod
    def otto(cls, crank_radius_mm, rod_length_mm, compression_ratio, *, offset_mm=0.0, points: int = 1440,
             **kw) -> IndicatorDiagram:
        """The parametric cycle of :func:`otto_pressure` tabulated at ``points`` angles over the cycle."""
        strokes = kw.get("strokes", 4)
        cycle = _strokes(strokes)
        points = require_count("points", points, 8, 1_000_000)
        phi = np.arange(points) * (cycle / points)
        p = otto_pressure(phi, crank_radius_mm, rod_length_mm, compression_ratio, offset_mm=offset_mm, **kw)
        return cls(phi, p, strokes, source="otto_pressure")

    def __repr__(self) -> str:
        return (f"IndicatorDiagram({self.crank_angle_deg.size} points, {self.strokes}-stroke, p "
                f"{self.pressure_mpa.min():.4g} … {self.pressure_mpa.max():.4g} MPa, from {self.source})")


def cycle_volume(crank_angle_deg, crank_radius_mm, rod_length_mm, compression_ratio, offset_mm=0.0) -> np.ndarray:
    """Cylinder volume per unit piston area, V/A = s(φ) + S/(ε − 1) (mm; S the stroke, ε the compression ratio):
    the clearance volume V_c = V_h/(ε − 1) above the piston at top dead centre (Heywood 1988 eq. 2.4)."""
    r, l_, e = check_lengths(crank_radius_mm, rod_length_mm, offset_mm)
    eps = one_number("compression_ratio", require_range("compression_ratio", compression_ratio, 1.0, 40.0, lo_open=True))
    top = math.sqrt((l_ + r) ** 2 - e * e)
    stroke = top - math.sqrt((l_ - r) ** 2 - e * e)
    return piston_displacement(crank_angle_deg, r, l_, e) + stroke / (eps - 1.0)


def otto_pressure(crank_angle_deg, crank_radius_mm, rod_length_mm, compression_ratio, *, offset_mm=0.0,
                  intake_pressure_mpa=0.09, exhaust_pressure_mpa=0.11, peak_pressure_mpa=5.0,
                  polytropic_compression=1.37, polytropic_expansion=1.25, strokes: int = 4) -> np.ndarray:
    """Absolute cylinder pressure of the idealised polytropic cycle (MPa), the indicator diagram of the engine
    course works' thermal calculation (Kolchin & Demidov 1980 §3-§5): at the cycle angle φ (degrees),

    - four-stroke (φ from the top dead centre at the start of intake): intake 0-180° at p_a; compression
      180-360°, p = p_a·(V_a/V)^n₁; heat added at constant volume at 360° up to p_z; expansion 360-540°,
      p = p_z·(V_c/V)^n₂; exhaust 540-720° at p_r;
    - two-stroke (φ from the firing top dead centre): expansion 0-180° from p_z, then compression 180-360° from
      p_a at the bottom dead centre (the scavenging at bottom dead centre is instantaneous).

    V(φ) is the exact cylinder volume (:func:`cycle_volume`). The ideal diagram's corners (at the dead centres)
    are where the piston stands still, so the torque it gives is continuous. ``peak_pressure_mpa`` must exceed
    the end of compression, p_a·ε^n₁.

    >>> p = otto_pressure([90, 360, 360.0001], 70, 250, 8.0, intake_pressure_mpa=0.1, peak_pressure_mpa=5.0)
    >>> round(float(p[0]), 6), round(float(p[1]), 4), round(float(p[2]), 4)   # p_c = 0.1·8^1.37 at TDC
    (0.1, 1.7268, 5.0)
    """
    cycle = _strokes(strokes)
    pa = one_number("intake_pressure_mpa", require_range("intake_pressure_mpa", intake_pressure_mpa, *PRESSURE_RANGE_MPA, lo_open=True,
                             unit="MPa"))
    pr = one_number("exhaust_pressure_mpa", require_range("exhaust_pressure_mpa", exhaust_pressure_mpa, *PRESSURE_RANGE_MPA, lo_open=True,
                             unit="MPa"))
    pz = one_number("peak_pressure_mpa", require_range("peak_pressure_mpa", peak_pressure_mpa, *PRESSURE_RANGE_MPA, lo_open=True,
                             unit="MPa"))
    n1 = one_number("polytropic_compression", require_range("polytropic_compression", polytropic_compression, 1.0, 1.7))
    n2 = one_number("polytropic_expansion", require_range("polytropic_expansion", polytropic_expansion, 1.0, 1.7))
    eps = one_number("compression_ratio", require_range("compression_ratio", compression_ratio, 1.0, 40.0, lo_open=True))
    if not pz > pa * eps ** n1:
        raise GearDesignError(f"peak_pressure_mpa must exceed the end of compression p_a·ε^n1 = "
                              f"{pa * eps ** n1:.6g} MPa, got {pz:g}")
    phi = np.mod(require_finite("crank_angle_deg", crank_angle_deg), cycle)
    v = cycle_volume(phi, crank_radius_mm, rod_length_mm, eps, offset_mm)
    v_c = cycle_volume(0.0, crank_radius_mm, rod_length_mm, eps, offset_mm)   # ≈ clearance (at φ = 0)
    v_a = cycle_volume(180.0, crank_radius_mm, rod_length_mm, eps, offset_mm)
    compression = pa * (v_a / v) ** n1
    expansion = pz * (v_c / v) ** n2
    if strokes == 4:
        return np.select([phi < 180.0, phi <= 360.0, phi < 540.0], [np.full_like(v, pa), compression, expansion],
                         default=pr)
    return np.where(phi < 180.0, expansion, compression)
