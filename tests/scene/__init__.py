"""Tests of geardesign.scene."""
