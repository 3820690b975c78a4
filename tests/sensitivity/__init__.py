"""Tests of geardesign.sensitivity."""
