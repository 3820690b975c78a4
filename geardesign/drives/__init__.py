"""Drives: sprockets, roller chains and keys, sized from :mod:`geardesign.catalogs`."""
