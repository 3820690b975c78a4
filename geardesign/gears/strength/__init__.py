"""Load capacity of cylindrical gears after ISO 6336 (contact and tooth-root strength).

One function per formula in :mod:`.factors` (ISO 6336-1), :mod:`.contact` and :mod:`.life` (ISO 6336-2),
:mod:`.root` and :mod:`.root_factors` (ISO 6336-3), :mod:`.materials` (ISO 6336-5); the chain of a pair,
vectorised, in :func:`pair_strength`; one pair as a :class:`StrengthResult` with :func:`strength`; each mesh of
a planetary set with :func:`planetary_strength`; service life under a spectrum (ISO 6336-6) with :func:`pair_life` and,
a set's with the planet over both its meshes, :func:`planetary_life`.
"""
import importlib

# public name -> module; loaded on first use (PEP 562), so that the checks' defaults
# (geardesign.gears.strength.defaults) load without the chain and its materials catalog (pandas)
_NAMES = {"GIVEN_FACTORS": "chain", "STRENGTH_FIELDS": "chain", "pair_strength": "chain", "strength": "chain",
          "MIN_SAFETY_SOURCE": "defaults", "S_FMIN": "defaults", "S_HMIN": "defaults", "Load": "load",
          "MATERIAL_KINDS": "materials", "Material": "materials", "material": "materials",
          "material_names": "materials", "planetary_strength": "planetary_meshes",
          "planetary_life": "planetary_meshes", "StrengthResult": "result",
          "StrengthOptions": "options", "pair_life": "service_life", "LifeResult": "life_result"}

__all__ = sorted(_NAMES)


def __getattr__(name):
    if name not in _NAMES:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f".{_NAMES[name]}", __name__), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(__all__))
