"""The two backends of the strength chain (geardesign.gears.strength.ops): Python floats for one design, numpy for
many, the same function for function (compared here on random values), and the range check that picks the path."""
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.errors import GearDesignError
from geardesign.gears.strength.ops import ArrayOps, FloatOps, checked, once, ops_of, per_load_case

POS = st.floats(1e-6, 1e6, allow_nan=False)


@settings(max_examples=200, deadline=None)
@given(POS, POS)
def test_float_and_array_functions_agree(a, b):
    for name in ("sqrt", "cbrt", "exp2", "log"):
        f, g = getattr(FloatOps, name), getattr(ArrayOps, name)
        v = min(a, 1000.0) if name == "exp2" else a     # 2^1024 overflows: math raises where numpy gives inf
        assert f(v) == pytest.approx(float(g(np.float64(v))), rel=1e-15)
    x = a / (1 + a)                       # in (0, 1): arccos's domain
    assert FloatOps.arccos(x) == pytest.approx(float(ArrayOps.arccos(np.float64(x))), rel=1e-15)
    assert FloatOps.maximum(a, b) == max(a, b) == float(ArrayOps.maximum(a, b))
    assert FloatOps.clip(a, 1.0, 10.0) == float(np.clip(a, 1.0, 10.0))
    xs, ys = (0.0, 1.0, 2.0), (1.0, 3.0, 2.0)
    t = 2 * x
    assert FloatOps.interp(t, xs, ys) == pytest.approx(float(np.interp(t, xs, ys)), rel=1e-15, abs=1e-15)


def test_one_design_takes_the_float_path():
    assert ops_of(1.0, 2.0) is FloatOps
    assert ops_of(1.0, np.float64(2.0)) is ArrayOps and ops_of(1) is ArrayOps and ops_of([1.0]) is ArrayOps


def test_checked_returns_floats_or_arrays_and_refuses_by_name():
    assert checked("q_s", 2, 0.1, 50.0) == 2.0 and type(checked("q_s", 2, 0.1, 50.0)) is float
    arr = np.array([1.0, 2.0])
    assert checked("b", arr, 0.0, 10.0, lo_open=True) is arr
    for value in (0.0, float("nan"), np.array([1.0, math.inf]), 51.0):
        with pytest.raises(GearDesignError, match="q_s"):
            checked("q_s", value, 0.0, 50.0, lo_open=True)


def test_once_and_per_load_case_compute_once():
    calls = []

    def factor(n, k):
        calls.append(n)
        return n * k

    memo = {}
    assert once(memo, "Z", factor, 2.0, 3.0) == once(memo, "Z", factor, 5.0, 5.0) == 6.0 and calls == [2.0]
    calls.clear()
    assert per_load_case(factor, 7.0, 3.0) == per_load_case(factor, 7.0, 3.0) == 21.0 and len(calls) <= 1
    many = np.array([1.0, 2.0])
    assert np.array_equal(per_load_case(factor, many, 3.0), many * 3.0)
