"""Load capacity of cylindrical gears after ISO 6336 (contact and tooth-root strength).

One function per formula in :mod:`.factors` (ISO 6336-1), :mod:`.contact` and :mod:`.life` (ISO 6336-2),
:mod:`.root` and :mod:`.root_factors` (ISO 6336-3), :mod:`.materials` (ISO 6336-5); the chain of a pair,
vectorised, in :func:`pair_strength`; one pair as a :class:`StrengthResult` with :func:`strength`; each mesh of
a planetary set with :func:`planetary_strength`.
"""
from .chain import GIVEN_FACTORS, STRENGTH_FIELDS, pair_strength, strength
from .defaults import MIN_SAFETY_SOURCE, S_FMIN, S_HMIN
from .load import Load
from .materials import MATERIAL_KINDS, Material, material, material_names
from .planetary_strength import planetary_strength
from .result import StrengthResult

__all__ = ["Load", "Material", "material", "material_names", "MATERIAL_KINDS", "pair_strength", "strength",
           "planetary_strength", "StrengthResult", "GIVEN_FACTORS", "STRENGTH_FIELDS", "S_HMIN", "S_FMIN",
           "MIN_SAFETY_SOURCE"]
