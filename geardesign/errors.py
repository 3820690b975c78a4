"""The one exception family of geardesign.

Every message names the input, the value it got and the range it allows, so that a
user (or the command line, which prints the message as one line) knows what to change.
The validators that raise these live in :mod:`geardesign.validate`.
"""
from __future__ import annotations

__all__ = ["GearDesignError", "CatalogError"]


class GearDesignError(ValueError):
    """Bad input to geardesign: names the input, its value and the allowed range."""


class CatalogError(GearDesignError):
    """A catalog file that is missing, malformed or inconsistent (names file, row and column)."""
