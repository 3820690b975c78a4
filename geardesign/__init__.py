"""geardesign: gear geometry and drive checks as constraints, optimised."""
from .errors import GearDesignError, CatalogError

__version__ = "0.1.0"
