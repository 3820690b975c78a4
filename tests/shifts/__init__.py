"""Tests of geardesign.shifts."""
