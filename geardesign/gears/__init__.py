"""Gears: the involute, the basic rack, the mesh description, pair geometry, checks and :class:`GearPair`.

Imports only :mod:`geardesign.errors` and :mod:`geardesign.validate` from above it.
"""
