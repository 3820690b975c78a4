"""geardesign: gear geometry and drive checks as constraints, optimised.

>>> import geardesign as gd
>>> pair = gd.GearPair(m=8, z1=17, z2=26, x1=0.898, x2=0.517)
>>> round(pair.geometry().eps_alpha, 3)
1.153
"""
from . import catalogs, chain, checks, involute, key, sprocket
from .checks import make_checks
from .errors import CatalogError, GearDesignError
from .geometry import GEOMETRY_FIELDS, Geometry, pair_geometry, x_sum_from_center_distance
from .involute import inv, inv_inverse
from .pair import GearPair
from .rack import BasicRack
from .shift import ShiftResult, optimize_shifts
from .region import Region, feasible_region
from .atlas import shift_atlas
from .teeth import TeethSelection, select_teeth
from . import scene, studies
from .scene import load_scene, run_scene
from .studies import sweep

__version__ = "0.1.0"

__all__ = [
    "BasicRack", "GearPair", "Geometry", "GEOMETRY_FIELDS", "GearDesignError", "CatalogError",
    "pair_geometry", "x_sum_from_center_distance", "inv", "inv_inverse", "make_checks",
    "checks", "involute", "optimize_shifts", "ShiftResult", "feasible_region", "Region", "shift_atlas", "select_teeth", "TeethSelection", "scene", "studies", "load_scene", "run_scene", "sweep", "catalogs", "chain", "key", "sprocket",
]
