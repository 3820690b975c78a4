"""The writers registry (geardesign.writers): a lower layer's object reaches the writer an upper layer
registered, by name, with no import going up."""
import pytest

import geardesign as gd
from geardesign import writers
from geardesign.errors import GearDesignError


def test_the_package_registers_the_pair_report():
    assert writers.writer("pair_report") is not None


def test_a_writer_is_found_by_name_and_replaced_by_a_later_one():
    writers.register("_test_writer", lambda obj: ("first", obj))
    assert writers.writer("_test_writer")(1) == ("first", 1)
    writers.register("_test_writer", lambda obj: ("second", obj))
    assert writers.writer("_test_writer")(2) == ("second", 2)
    writers._WRITERS.pop("_test_writer")


def test_bad_writers_and_unknown_names_are_refused_by_name():
    with pytest.raises(GearDesignError, match="'x' must be callable"):
        writers.register("x", 3)
    with pytest.raises(GearDesignError, match="no writer 'nothing'"):
        writers.writer("nothing")
    assert isinstance(gd.GearDesignError("x"), ValueError)
