"""The exception family (geardesign.errors): GearDesignError is a ValueError (bad input is a value
error, so callers catching ValueError keep working), CatalogError a GearDesignError; both are what
the package exports, and a bad catalog file is reported as CatalogError naming the file."""
import numpy as np
import pytest

import geardesign as gd
from geardesign.catalogs import load_catalog
from geardesign.errors import CatalogError, GearDesignError


def test_hierarchy():
    assert issubclass(GearDesignError, ValueError) and issubclass(CatalogError, GearDesignError)
    assert gd.GearDesignError is GearDesignError
    assert not issubclass(GearDesignError, (TypeError, ArithmeticError))


def test_bad_input_is_caught_as_value_error():
    with pytest.raises(ValueError, match="z1"):
        gd.pair_geometry(2.0, -3, 40, 0.0, 0.0)


def test_a_broken_catalog_is_a_catalog_error_naming_the_file(tmp_path):
    bad = tmp_path / "empty.csv"
    bad.write_text("")
    with pytest.raises(CatalogError, match="empty.csv"):
        load_catalog(bad)


def _pair():
    return gd.GearPair(2, 17, 26, 0.3, 0.2)


# issue 29 §3.12: wrong types escaped as plain exceptions; each call, and the like on the same functions
WRONG_TYPES = [
    (lambda: gd.tooth_profile(5, 60, 1.0, rack="x"), "rack"),
    (lambda: gd.ring_profile(2, 60, 0.6, rack=-17), "rack"),
    (lambda: gd.tooth_profile(10, [100], 0.3), "z"),
    (lambda: gd.plot_diagrams(_pair(), axes=1), "axes"),
    (lambda: gd.optimize_shifts(17, 26, start=17), "start"),
    (lambda: gd.optimize_shifts(17, 26, checks=np.array(17)), "checks"),
    (lambda: gd.optimize_planetary_shifts(21, 43, 108, 3, m=1.75, planet_angles_deg=0), "planet_angles_deg"),
    (lambda: gd.select_teeth(5.05, m="series", a_w=290.5, m_range=()), "m_range"),
    (lambda: gd.ChainStage(designation=[17]), "designation"),
    (lambda: gd.key.capacity(100, 32, n_keys=()), "n_keys"),
    # the like, found by substituting wrong types into the same functions' other arguments
    (lambda: gd.ring_profile(2, [60], 0.6), "z"),
    (lambda: gd.plot_mesh(_pair(), ax="left"), "ax"),
    (lambda: __import__("geardesign.profiles.planetary", fromlist=["x"]).plot_planetary("set"), "PlanetarySet"),
    (lambda: gd.optimize_shifts(17, 26, start=(0.1, 0.2, 0.3)), "start"),
    (lambda: gd.select_teeth(2.0, m=2, x_sum_window=5), "x_sum_window"),
    (lambda: gd.select_teeth(2.0, m=2, progress=1), "progress"),
    (lambda: gd.select_teeth(2.0, rack=0), "rack"),
    (lambda: gd.shift_atlas([17], [26], progress="x"), "progress"),
    (lambda: gd.shift_atlas([17], [26], bounds=None), "bounds"),
    (lambda: gd.ChainStage(strands=[[1], [2, 3]]), "strands"),
    (lambda: gd.key.select(60, torque_nm=500, hub_length_mm=80, max_keys=()), "max_keys"),
]


@pytest.mark.parametrize("call, name", WRONG_TYPES, ids=[w[1] + str(i) for i, w in enumerate(WRONG_TYPES)])
def test_wrong_types_give_one_gear_design_error_naming_the_argument(call, name):
    with pytest.raises(GearDesignError) as info:
        call()
    text = str(info.value)
    assert name in text and "\n" not in text and len(text) < 300, text
