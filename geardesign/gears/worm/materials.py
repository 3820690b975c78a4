"""Worm wheel materials: the bundled table ``catalogs/worm_materials.csv`` (cast bronzes after EN 1982, each row
with its source) and one row of it by name.

The table holds what the sources print: tensile strength, 0.2 % proof stress, elongation, Brinell hardness and,
where printed, the modulus range and density. ISO/TS 14521's rating values of these bronzes (σ_Hlim, τ_Flim,
the wear and friction factors) are not in it: they could not be read in a public text (docs/worm_rating.md).
"""
from __future__ import annotations

from ...catalogs.tables import BUNDLED, Column, Schema, load_catalog, register_catalog
from ...errors import GearDesignError

__all__ = ["WORM_MATERIALS_SCHEMA", "worm_materials", "worm_material"]


def _f(name, required=True):
    return Column(name, "float", required=required, positive=True)


WORM_MATERIALS_SCHEMA = Schema(
    "worm_materials",
    (Column("name", "str"), Column("material_number", "str", required=False), Column("casting", "str"),
     Column("role", "str"), _f("Rm_mpa"), _f("Rp02_mpa"), _f("elongation_pct"), _f("hardness_HB"),
     _f("E_min_mpa", False), _f("E_max_mpa", False), _f("density_kg_m3", False)),
    description="worm wheel materials (cast bronzes, EN 1982): Rm, Rp0.2, A, HB; modulus range and density "
                "where the source prints them")

if "worm_materials" not in BUNDLED:
    register_catalog("worm_materials", "worm_materials.csv", WORM_MATERIALS_SCHEMA)


def worm_materials():
    """The bundled worm wheel materials as a DataFrame (validated; a fresh copy)."""
    return load_catalog("worm_materials")


def worm_material(name: str):
    """One row of :func:`worm_materials` by its ``name`` (e.g. ``"CuSn12Ni2-C-GZ"``), as a pandas Series.

    >>> worm_material("CuSn12Ni2-C-GZ")["Rm_mpa"]     # EN 1982 minimum, centrifugal casting
    np.float64(300.0)
    """
    frame = worm_materials()
    hit = frame[frame["name"] == name]
    if hit.empty:
        raise GearDesignError(f"worm material must be one of {list(frame['name'])}, got {name!r}")
    return hit.iloc[0]
