"""The exception family (geardesign.errors): GearDesignError is a ValueError (bad input is a value
error, so callers catching ValueError keep working), CatalogError a GearDesignError; both are what
the package exports, and a bad catalog file is reported as CatalogError naming the file."""
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
