"""Tests of geardesign.gears."""
