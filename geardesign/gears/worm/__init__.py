"""Cylindrical worm pairs: DIN 3975 geometry, checks, the pair object and standard series."""
