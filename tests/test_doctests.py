"""Run the doctests of every geardesign module (each reproduces a published number)."""
import doctest
import importlib
import pkgutil

import pytest

import geardesign

MODULES = sorted(m.name for m in pkgutil.walk_packages(geardesign.__path__, "geardesign.")
                 if not m.name.endswith("__main__"))


@pytest.mark.parametrize("name", MODULES)
def test_doctests(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0
