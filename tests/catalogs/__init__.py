"""Tests of geardesign.catalogs."""
