"""The ISO 6336-5 material tables: the material-group lines (σ_lim = A·x + B of the surface hardness x)
and the named steels, loaded with pandas from the bundled CSV files and checked on loading.

>>> lines = material_group_lines()
>>> row = lines[(lines.group == "V_alloy") & (lines.quality == "MQ") & (lines.stress == "contact")].iloc[0]
>>> float(row.A), float(row.B), row.hardness_scale
(1.313, 373.0, 'HV')
>>> named_materials().loc["42CrMo4", "group"]
'V_alloy'
"""
from __future__ import annotations

from functools import lru_cache

import pandas as pd

from ..errors import CatalogError
from .tables import catalog_dir

__all__ = ["material_group_lines", "named_materials", "QUALITIES", "HARDNESS_SCALES"]

QUALITIES = ("ML", "MQ", "ME")            # ISO 6336-5 quality grades
HARDNESS_SCALES = ("HBW", "HV")            # the scales the part-5 lines use
_GROUP_FILE = "material_groups_iso6336.csv"
_NAMED_FILE = "materials_iso6336.csv"
_GROUP_FLOATS = ("A", "B", "hardness_min", "hardness_max")
_NAMED_FLOATS = ("hardness", "E_mpa", "nu", "yield_mpa")   # yield_mpa blank: not needed


def _read(file: str, floats: tuple) -> pd.DataFrame:
    path = catalog_dir() / file
    try:
        frame = pd.read_csv(path, dtype=str, keep_default_na=False, na_values={"yield_mpa": [""]})
    except (OSError, pd.errors.ParserError) as exc:
        raise CatalogError(f"{file}: cannot read the bundled material table ({exc})") from None
    for col in floats:
        try:
            frame[col] = frame[col].astype(float)
        except (KeyError, ValueError) as exc:
            raise CatalogError(f"{file}: column '{col}' must hold numbers ({exc})") from None
    if "source" not in frame or (frame["source"].str.strip() == "").any():
        raise CatalogError(f"{file}: every row needs a source")
    return frame


@lru_cache(maxsize=1)
def _group_lines() -> pd.DataFrame:
    frame = _read(_GROUP_FILE, _GROUP_FLOATS)
    bad = ~frame["quality"].isin(QUALITIES) | ~frame["stress"].isin(("contact", "bending")) \
        | ~frame["hardness_scale"].isin(HARDNESS_SCALES) | (frame["hardness_min"] >= frame["hardness_max"])
    if bad.any():
        line = int(bad.to_numpy().nonzero()[0][0]) + 2
        raise CatalogError(f"{_GROUP_FILE}: row {line}: quality, stress, hardness scale or range out of place")
    if frame.duplicated(["group", "quality", "stress"]).any():
        raise CatalogError(f"{_GROUP_FILE}: a (group, quality, stress) appears twice")
    return frame


@lru_cache(maxsize=1)
def _named() -> pd.DataFrame:
    frame = _read(_NAMED_FILE, _NAMED_FLOATS)
    groups = set(_group_lines()["group"])
    unknown = ~frame["group"].isin(groups)
    if unknown.any():
        raise CatalogError(f"{_NAMED_FILE}: group {frame['group'][unknown].iloc[0]!r} is not in {_GROUP_FILE}")
    return frame.set_index("name", drop=False)


def material_group_lines() -> pd.DataFrame:
    """The ISO 6336-5 lines, one row per (group, quality, stress) with A, B, the hardness scale and the
    hardness range the line holds for (a fresh copy)."""
    return _group_lines().copy()


def named_materials() -> pd.DataFrame:
    """The named steels (index: name) with their group, quality, hardness, E, ν and source (a fresh copy)."""
    return _named().copy()
