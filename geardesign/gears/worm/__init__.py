"""Cylindrical worm gear pairs: efficiency (worm.efficiency) and load capacity (worm.rating)."""
