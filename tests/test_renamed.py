"""Renamed keywords (geardesign.renamed): the old name runs the function as the new one with a DeprecationWarning
that names the new one, both at once are refused by name, and the signature shows only the new name."""
import inspect
import warnings

import pytest

from geardesign.errors import GearDesignError
from geardesign.renamed import renamed_keywords


@renamed_keywords(speed_rpm="n_rpm", m_n="m")
def f(m, n_rpm=1.0):
    return m * n_rpm


def test_the_old_names_warn_and_work():
    with pytest.warns(DeprecationWarning, match=r"f\(speed_rpm=\.\.\.\) is deprecated: use n_rpm="):
        assert f(2.0, speed_rpm=3.0) == 6.0
    with pytest.warns(DeprecationWarning, match="use m="):
        assert f(m_n=2.0) == 2.0
    with warnings.catch_warnings():
        warnings.simplefilter("error")        # the new names: no warning
        assert f(2.0, n_rpm=3.0) == 6.0


def test_both_names_are_refused_and_the_signature_is_the_new_one():
    with pytest.raises(GearDesignError, match="give n_rpm, not both n_rpm and its old name speed_rpm"):
        f(1.0, n_rpm=2.0, speed_rpm=2.0)
    assert list(inspect.signature(f).parameters) == ["m", "n_rpm"]
    assert f.renamed_keywords == {"speed_rpm": "n_rpm", "m_n": "m"}


def test_the_warning_points_at_the_caller():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        f(1.0, speed_rpm=1.0)
    assert caught[0].filename == __file__
