"""Catalog tables (CSV, loaded with pandas and validated against their schemas) and standard series.

>>> from geardesign import catalogs
>>> float(catalogs.module_series((1,), min_mm=2, max_mm=3)[0])   # ISO 54 series 1 from 2 mm
2.0
"""
from .tables import (CHAIN_CATALOGS, catalog_dir, catalog_names, center_distance_series, chain_catalog,
                     key_lengths_mm, load_catalog, measuring_ball_series, module_series, preferred_numbers)

__all__ = ["CHAIN_CATALOGS", "catalog_dir", "catalog_names", "center_distance_series", "chain_catalog",
           "key_lengths_mm", "load_catalog", "measuring_ball_series", "module_series", "preferred_numbers"]
