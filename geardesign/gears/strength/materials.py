"""Gear materials for ISO 6336: the material groups and quality grades of ISO 6336-5 (σ_Hlim and σ_Flim
from the surface hardness by the part-5 lines) and named steels from the bundled catalog."""
from __future__ import annotations

import difflib
import functools
import math
from dataclasses import dataclass

from ...catalogs.materials import QUALITIES, material_group_lines, named_materials
from ...errors import GearDesignError
from ...validate import one_number, require_range
from .root_factors import MATERIAL_KINDS as _ROOT_KINDS

__all__ = ["Material", "material", "material_names", "allowable_stress_number", "MATERIAL_KINDS",
           "SURFACE_HARDENED_KINDS", "STEEL_E_MPA", "STEEL_NU"]

# The material kinds of ISO 6336-5 (what the life factors, y_α, y_β, C_ay, Z_W and the root factors depend on),
# one list for the whole package: the root factors' (see root_factors.MATERIAL_KINDS for their meaning).
MATERIAL_KINDS = tuple(_ROOT_KINDS)
SURFACE_HARDENED_KINDS = frozenset({"Eh", "IF", "NT", "NV(nitr)", "NV(nitrocar)"})
# kinds whose relative notch sensitivity (ISO 6336-3 clause 13) needs a strength (σ_0.2, σ_S or σ_B)
STRENGTH_NEEDED_KINDS = frozenset({"St", "V", "GG", "GGG(perl)", "GGG(ferr)", "GTS"})
STEEL_E_MPA = 206_000.0     # ISO 6336-2 (Z_E = 189.8 √MPa for steel on steel)
STEEL_NU = 0.3
_STEEL_GROUPS = frozenset({"St", "St_cast", "V_carbon", "V_alloy", "V_cast_carbon", "V_cast_alloy", "Eh", "IF", "NT",
                           "NV", "NV_nitrocar"})
E_RANGE_MPA = (1e3, 1e6)
SIGMA_RANGE_MPA = (1.0, 5000.0)
HARDNESS_SCALES = ("HBW", "HV", "HRC")


@dataclass(frozen=True)
class Material:
    """A gear material: its ISO 6336 ``kind`` (one of :data:`MATERIAL_KINDS`), Young's modulus ``E_mpa``,
    Poisson's ratio ``nu``, the surface ``hardness`` on ``hardness_scale`` (HBW, HV or HRC), the allowable
    stress numbers ``sigma_Hlim_mpa`` (contact) and ``sigma_Flim_mpa`` (bending, of the reference test gear,
    used with Y_ST = 2), the ISO 6336-5 ``quality`` grade (ML, MQ, ME) and where the numbers come from;
    ``yield_mpa`` the strength the root's notch sensitivity needs (ISO 6336-3 clause 13: σ_0.2 for V, GGG(perl),
    GTS; σ_S for St; σ_B for GG, GGG(ferr); None for surface-hardened kinds).

    >>> m = Material("my steel", "V", 206000, 0.3, 300, "HV", 767.0, 314.5, "MQ", "my test")
    >>> m.sigma_Hlim_mpa
    767.0
    >>> Material("x", "steel", 206000, 0.3, 300, "HV", 700, 300, "MQ", "")
    Traceback (most recent call last):
    ...
    geardesign.errors.GearDesignError: kind must be one of ['St', 'V', 'GG', 'GGG(perl)', 'GGG(ferr)', 'GTS', 'Eh', 'IF', 'NT', 'NV(nitr)', 'NV(nitrocar)'], got 'steel'
    """

    name: str
    kind: str
    E_mpa: float
    nu: float
    hardness: float
    hardness_scale: str
    sigma_Hlim_mpa: float
    sigma_Flim_mpa: float
    quality: str = "MQ"
    source: str = ""
    treatment: str = ""
    group: str = ""
    yield_mpa: float | None = None

    def __post_init__(self):
        if self.kind not in MATERIAL_KINDS:
            raise GearDesignError(f"kind must be one of {list(MATERIAL_KINDS)}, got {self.kind!r}")
        if self.quality not in QUALITIES:
            raise GearDesignError(f"quality must be one of {list(QUALITIES)}, got {self.quality!r}")
        if self.hardness_scale not in HARDNESS_SCALES:
            raise GearDesignError(f"hardness_scale must be one of {list(HARDNESS_SCALES)}, got {self.hardness_scale!r}")
        checks = (("E_mpa", E_RANGE_MPA, False), ("nu", (0.0, 0.5), True), ("hardness", (0.0, 2000.0), True),
                  ("sigma_Hlim_mpa", SIGMA_RANGE_MPA, False), ("sigma_Flim_mpa", SIGMA_RANGE_MPA, False))
        for field, (lo, hi), open_ in checks:
            value = one_number(field, require_range(field, getattr(self, field), lo, hi, lo_open=open_,
                                                    hi_open=open_))
            object.__setattr__(self, field, value)
        if self.yield_mpa is not None:
            object.__setattr__(self, "yield_mpa", one_number("yield_mpa", require_range(
                "yield_mpa", self.yield_mpa, 1.0, 5000.0, unit="MPa")))

    @property
    def surface_hardened(self) -> bool:
        """True for case-, flame-, induction-hardened and nitrided materials (ISO 6336-2 Z_W)."""
        return self.kind in SURFACE_HARDENED_KINDS

    @property
    def brinell(self) -> float:
        """Hardness as HB for Z_W (ISO 6336-2): HBW as is, HV ≈ HB below 450 (a conversion within a few per cent
        of ISO 18265 for steels); NaN for HRC."""
        return self.hardness if self.hardness_scale in ("HBW", "HV") else math.nan


def _line(group: str, quality: str, stress: str):
    lines = material_group_lines()
    row = lines[(lines.group == group) & (lines.quality == quality) & (lines.stress == stress)]
    if row.empty:
        groups = sorted(set(lines.group))
        raise GearDesignError(f"material group must be one of {groups}, got {group!r}")
    return row.iloc[0]


def allowable_stress_number(group: str, quality: str, stress: str, hardness: float) -> float:
    """σ_Hlim (``stress="contact"``) or σ_Flim (``"bending"``) in MPa from the surface hardness,
    σ = A·x + B (ISO 6336-5:2016 clause 5 and Table 1; x in HBW or HV as the group's line says).

    Refuses a hardness outside the line's range: the standard gives no value there.

    >>> allowable_stress_number("V_alloy", "MQ", "contact", 300)      # 1.313·300 + 373
    766.9
    >>> allowable_stress_number("Eh", "MQ", "contact", 700)
    1500.0
    >>> allowable_stress_number("V_alloy", "MQ", "contact", 400)
    Traceback (most recent call last):
    ...
    geardesign.errors.GearDesignError: hardness must be in [200, 360] HV for the V_alloy MQ contact line of ISO 6336-5, got 400
    """
    if quality not in QUALITIES:
        raise GearDesignError(f"quality must be one of {list(QUALITIES)}, got {quality!r}")
    row = _line(group, quality, stress)
    h = one_number("hardness", require_range("hardness", hardness, 0.0, 2000.0, lo_open=True))
    if not row.hardness_min <= h <= row.hardness_max:
        raise GearDesignError(f"hardness must be in [{row.hardness_min:g}, {row.hardness_max:g}] {row.hardness_scale}"
                              f" for the {group} {quality} {stress} line of ISO 6336-5, got {h:g}")
    return round(float(row.A) * h + float(row.B), 10)


def material_names() -> tuple[str, ...]:
    """Names :func:`material` accepts: the named steels, their aliases and the ISO 6336-5 groups."""
    named = named_materials()
    aliases = [a for text in named.aliases for a in text.split("|") if a]
    return tuple(named.index) + tuple(aliases) + tuple(dict.fromkeys(material_group_lines().group))


def _catalog_spelling(name: str) -> str:
    """``name`` as the catalog spells it: an exact name, else the one name that matches it ignoring case
    (``42crmo4`` is 42CrMo4); a name that matches none is refused with the nearest names (difflib)."""
    names = material_names()
    if name in names:
        return name
    folded = {}
    for n in names:
        folded.setdefault(n.casefold(), n)
    if name.casefold() in folded:
        return folded[name.casefold()]
    near = [folded[k] for k in difflib.get_close_matches(name.casefold(), list(folded), n=3, cutoff=0.5)]
    hint = f"; nearest: {', '.join(near)}" if near else ""
    raise GearDesignError(f"material must be a name of the catalog or an ISO 6336-5 group (see material_names()), "
                          f"got {name!r}{hint}")


def material(name: str, *, hardness: float | None = None, quality: str | None = None, E_mpa: float | None = None,
             nu: float | None = None, yield_mpa: float | None = None) -> Material:
    """A :class:`Material` by name: a named steel of ``catalogs/materials_iso6336.csv`` (``"42CrMo4"``,
    ``"18CrNiMo7-6"``, ``"40Х"``, ...) or an ISO 6336-5 group (``"V_alloy"``, ``"Eh"``, ``"GGG"``, ... with
    ``hardness`` in the group's scale). ``hardness`` and ``quality`` override the catalog's; σ_Hlim and
    σ_Flim come from the part-5 lines at that hardness (:func:`allowable_stress_number`). Cast irons need
    ``E_mpa`` and ``nu`` (the catalog gives only steel's); ``yield_mpa`` overrides the catalog's strength (see
    :class:`Material`; an ISO 6336-5 group has none unless given).

    >>> m = material("42CrMo4")
    >>> m.kind, m.hardness, m.sigma_Hlim_mpa, m.sigma_Flim_mpa
    ('V', 300.0, 766.9, 314.5)
    >>> material("40Х").name
    '40Cr'
    >>> material("42crmo4").name          # any case
    '42CrMo4'
    >>> material("42CrMo5")
    Traceback (most recent call last):
    ...
    geardesign.errors.GearDesignError: material must be a name of the catalog or an ISO 6336-5 group (see material_names()), got '42CrMo5'; nearest: 42CrMo4, 42CrMo4-IF, 34CrNiMo6
    """
    try:
        return _material_cached(name, hardness, quality, E_mpa, nu, yield_mpa)
    except TypeError:            # an unhashable argument (a list, an array): refused by name below
        return _material(name, hardness, quality, E_mpa, nu, yield_mpa)


@functools.lru_cache(maxsize=256)
def _material_cached(name, hardness, quality, E_mpa, nu, yield_mpa) -> Material:
    return _material(name, hardness, quality, E_mpa, nu, yield_mpa)


def _material(name, hardness, quality, E_mpa, nu, yield_mpa) -> Material:
    """:func:`material` without the cache (a Material is frozen: one per set of arguments is enough)."""
    if quality is not None and quality not in QUALITIES:
        raise GearDesignError(f"quality must be one of {list(QUALITIES)}, got {quality!r}")
    if not isinstance(name, str) or not name:
        raise GearDesignError(f"material must be a name of the catalog or an ISO 6336-5 group (see material_names()), "
                              f"got {name!r}")
    name = _catalog_spelling(name)
    named = named_materials()
    row = None
    if isinstance(name, str):
        if name in named.index:
            row = named.loc[name]
        else:
            hits = named[named.aliases.apply(lambda text: name in text.split("|"))]
            row = hits.iloc[0] if len(hits) else None
    group = row.group if row is not None else name
    q = quality if quality is not None else (row.quality if row is not None else "MQ")
    if hardness is None and row is None:
        raise GearDesignError(f"material group {name!r} needs a hardness (HBW or HV as its ISO 6336-5 line says)")
    h = hardness if hardness is not None else float(row.hardness)
    steel = group in _STEEL_GROUPS
    if not steel and (E_mpa is None or nu is None):
        raise GearDesignError(f"material group {group!r} is a cast iron: give E_mpa and nu (no default is bundled)")
    contact = _line(group, q, "contact")
    return Material(name=row.name if row is not None else group, kind=contact.kind,
                    E_mpa=STEEL_E_MPA if E_mpa is None else E_mpa, nu=STEEL_NU if nu is None else nu,
                    hardness=h, hardness_scale=contact.hardness_scale,
                    sigma_Hlim_mpa=allowable_stress_number(group, q, "contact", h),
                    sigma_Flim_mpa=allowable_stress_number(group, q, "bending", h), quality=q,
                    source=(row.source if row is not None else contact.source), group=group,
                    treatment=(row.treatment if row is not None else contact.description),
                    yield_mpa=yield_mpa if yield_mpa is not None else (
                        float(row.yield_mpa) if row is not None and row.yield_mpa == row.yield_mpa else None))
