"""Pieces of the drive search (geardesign.drives.search): the smallest margin and its check, and a hub's key
capacities, computed here by hand for seed 002's sprocket hubs (d 60 mm, hub 50 mm, key 18x11x45 of GOST
23360-78 with t1 = 7 mm, [σ]cm = 300 MPa, [τ] = 120 MPa)."""
import math

import numpy as np
import pytest

import geardesign as gd
from geardesign.drives.limits import MARGIN_TOL
from geardesign.drives.search import key_caps, min_margin


def test_min_margin_names_the_smallest_and_rounds_to_zero_within_the_tolerance():
    assert min_margin({"a": 0.3, "b": -0.1, "c": 0.2}) == (-0.1, "b")
    assert min_margin({"a": 0.3, "b": MARGIN_TOL / 2}) == (0.0, "b")      # the exact solver's 1e-9: holds
    assert min_margin({"a": 0.3, "b": float("nan")})[1] == "b"              # a margin that does not exist fails
    assert min_margin({}) == (math.inf, "")
    assert min_margin({"a": np.float64(0.5)}) == (0.5, "a")


def test_key_capacities_by_hand():
    length, caps = key_caps(gd.Shaft(60, 50, 1, "driving sprocket", allowable_crush_mpa=300, allowable_shear_mpa=120))
    assert length == 45.0                       # the longest standard key that fits the 50 mm hub
    l_p = 45 - 18                               # rounded ends: the working length is l − b
    crush = 300 * 60 * (11 - 7) * l_p / 2000    # T = σ d (h − t1) l_p / 2, N·m
    shear = 120 * 60 * 18 * l_p / 2000          # T = τ d b l_p / 2
    assert caps[1] == (pytest.approx(crush, rel=1e-14), pytest.approx(shear, rel=1e-14))
    # two keys at 180° carry 2 × 0.75 = 1.5 times one key (the load-sharing factor of geardesign.drives.key)
    assert caps[2] == (pytest.approx(1.5 * crush, rel=1e-14), pytest.approx(1.5 * shear, rel=1e-14))
