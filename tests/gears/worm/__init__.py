"""Tests of geardesign.gears.worm."""
