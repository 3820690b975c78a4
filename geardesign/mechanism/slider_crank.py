"""One cylinder's slider-crank: its dimensions, masses and inertia, checked once (:class:`SliderCrank`)."""
from __future__ import annotations

from dataclasses import dataclass

from ..errors import GearDesignError
from ..results import compact_repr
from ..validate import hint_unknown_arguments, one_number, require_finite, require_range
from .kinematics import LENGTH_RANGE_MM, check_lengths

__all__ = ["SliderCrank", "MASS_MAX_KG", "INERTIA_MAX_KG_M2"]

MASS_MAX_KG = 1e5          # a ship engine's piston is ~1 t; beyond 100 t a value is a typing slip
INERTIA_MAX_KG_M2 = 1e5


@dataclass(frozen=True)
class SliderCrank:
    """A crank (radius ``crank_radius_mm``), a connecting rod (``rod_length_mm`` between pin centres, centre of
    gravity ``rod_cg_mm`` from the crank pin — seed 000's L_CS) and a piston on a line ``offset_mm`` from the crank
    axis (0: central). Masses in kg: ``piston_mass_kg`` (the whole piston group: piston, rings, pin),
    ``rod_mass_kg`` with ``rod_inertia_kg_m2`` (kg·m², about its centre of gravity), ``crank_mass_kg`` with its
    centre of gravity at ``crank_cg_mm`` from the axis towards the crank pin (negative: a counterweighted crank).
    ``cylinder_bore_mm`` (the piston diameter) turns a pressure into the gas force.

    >>> SliderCrank(70, 250, rod_cg_mm=75, rod_mass_kg=4.7)
    SliderCrank(crank_radius_mm=70, rod_length_mm=250, rod_cg_mm=75, rod_mass_kg=4.7)
    >>> SliderCrank(70, 250, rod_cg_mm=300)
    Traceback (most recent call last):
    ...
    geardesign.errors.GearDesignError: rod_cg_mm must be in [0, 250] mm, got 300.0
    """

    crank_radius_mm: float
    rod_length_mm: float
    rod_cg_mm: float = 0.0
    offset_mm: float = 0.0
    piston_mass_kg: float = 0.0
    rod_mass_kg: float = 0.0
    rod_inertia_kg_m2: float = 0.0
    crank_mass_kg: float = 0.0
    crank_cg_mm: float = 0.0
    cylinder_bore_mm: float | None = None

    def __post_init__(self):
        for name in ("crank_radius_mm", "rod_length_mm", "rod_cg_mm", "offset_mm", "piston_mass_kg", "rod_mass_kg",
                     "rod_inertia_kg_m2", "crank_mass_kg", "crank_cg_mm"):
            one_number(name, require_finite(name, getattr(self, name)))
        r, l_, _ = check_lengths(self.crank_radius_mm, self.rod_length_mm, self.offset_mm)
        require_range("rod_cg_mm", self.rod_cg_mm, 0.0, l_, unit="mm")
        for name in ("piston_mass_kg", "rod_mass_kg", "crank_mass_kg"):
            require_range(name, getattr(self, name), 0.0, MASS_MAX_KG, unit="kg")
        require_range("rod_inertia_kg_m2", self.rod_inertia_kg_m2, 0.0, INERTIA_MAX_KG_M2, unit="kg·m²")
        require_range("crank_cg_mm", self.crank_cg_mm, -10 * r, 10 * r, unit="mm")
        if self.cylinder_bore_mm is not None:
            # at most the lengths' range (a bore of 1e308 mm overflowed the gas force)
            one_number("cylinder_bore_mm", require_range("cylinder_bore_mm", self.cylinder_bore_mm, 0.0,
                                                         LENGTH_RANGE_MM[1], lo_open=True, unit="mm"))

    @property
    def ratio(self) -> float:
        """λ = r/l, the crank-to-rod ratio (seed 004's λ_r)."""
        return self.crank_radius_mm / self.rod_length_mm

    @property
    def stroke_mm(self) -> float:
        """The piston's stroke between the dead centres (2r for a central mechanism), mm."""
        r, l_, e = self.crank_radius_mm, self.rod_length_mm, self.offset_mm
        return ((l_ + r) ** 2 - e * e) ** 0.5 - ((l_ - r) ** 2 - e * e) ** 0.5

    def need_bore(self) -> float:
        if self.cylinder_bore_mm is None:
            raise GearDesignError("cylinder_bore_mm is needed to turn a cylinder pressure into a gas force; "
                                  "give SliderCrank(..., cylinder_bore_mm=...)")
        return float(self.cylinder_bore_mm)

    def __repr__(self) -> str:
        return compact_repr(self)


hint_unknown_arguments(SliderCrank, {"bore_mm": "the cylinder's bore is cylinder_bore_mm",
                                     "rod_cg_from_pin_mm": "name it rod_cg_mm"})
