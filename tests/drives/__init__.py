"""Tests of geardesign.drives."""
