"""The two backends of the strength chain (geardesign.gears.strength.ops): Python floats for one design, numpy for
many, the same function for function (compared here on random values), and the range check that picks the path."""
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.errors import GearDesignError
from geardesign.gears.strength.ops import ArrayOps, FloatOps, MixedOps, checked, once, ops_of, per_load_case

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


def test_mixed_ops_take_math_for_floats_and_numpy_for_arrays():
    """MixedOps (one design in floats carrying arrays of load cases): each operation is FloatOps' on Python floats
    (a float back) and ArrayOps' where an operand is an array."""
    arr = np.array([0.2, 0.7])
    for name in ("sin", "cos", "tan", "sqrt", "cbrt", "arccos", "exp", "exp2", "log", "radians", "degrees", "abs"):
        f = getattr(MixedOps, name)
        one = f(0.3)
        assert type(one) is float and one == getattr(FloatOps, name)(0.3), name
        many = f(arr)
        assert type(many) is np.ndarray and np.array_equal(many, getattr(ArrayOps, name)(arr)), name
    assert type(MixedOps.maximum(0.2, 0.3)) is float and MixedOps.maximum(0.2, 0.3) == 0.3
    assert np.array_equal(MixedOps.maximum(arr, 0.5), [0.5, 0.7])
    assert np.array_equal(MixedOps.minimum(0.5, arr), [0.2, 0.5])
    assert MixedOps.clip(3.0, 1.0, 2.0) == 2.0 and np.array_equal(MixedOps.clip(arr, 0.3, 0.6), [0.3, 0.6])
    assert MixedOps.where(True, 1.0, 2.0) == 1.0 and np.array_equal(MixedOps.where(arr > 0.5, 1.0, 2.0), [2.0, 1.0])
    assert MixedOps.any(False) is False and MixedOps.all(arr > 0.1)
    assert MixedOps.asarray(2) == 2.0 and type(MixedOps.asarray(2)) is float
    assert type(MixedOps.asarray([1.0])) is np.ndarray
    assert MixedOps.like(1.0, 5.0) == 5.0 and np.array_equal(MixedOps.like(arr, 5.0), [5.0, 5.0])
    xs, ys = (0.0, 1.0, 2.0), (1.0, 3.0, 2.0)
    assert MixedOps.interp(0.5, xs, ys) == FloatOps.interp(0.5, xs, ys)
    assert np.array_equal(MixedOps.interp(arr, xs, ys), np.interp(arr, xs, ys))


def _bins(torque_nm, n_rpm, **kw):
    """A Load whose torque and speed are arrays (as service_life hands the chain a spectrum's bins)."""
    from geardesign.gears.strength import Load

    load = Load(torque_nm=1.0, n_rpm=1.0, **kw)
    object.__setattr__(load, "torque_nm", np.asarray(torque_nm, dtype=float))
    object.__setattr__(load, "n_rpm", np.asarray(n_rpm, dtype=float))
    return load


@pytest.mark.parametrize("case", [
    dict(beta_deg=0.0),
    dict(beta_deg=15.0, options="C"),
    dict(beta_deg=8.0, life=3000.0, factors={"K_Hbeta": 1.3}),
])
def test_a_float_design_under_arrays_of_loads_is_the_float_chain_bin_by_bin(case):
    """Two routes to each bin's factors and stresses: the chain over all bins at once on MixedOps (the design in
    Python floats, torque and speed arrays) and the float path run on one Load per bin; and the array path (the
    design as 0-d arrays) over all bins. numpy's and math's transcendental functions may differ in the last ulp."""
    from geardesign import GearPair
    from geardesign.gears.strength import Load, StrengthOptions, pair_strength

    pair = GearPair(3, 19, 71, 0.4, 0.2, face_width_mm=30, beta_deg=case["beta_deg"])
    T, n = np.array([40.0, 150.0, 420.0, 800.0]), np.array([3000.0, 1500.0, 1500.0, 600.0])
    life = case.get("life")
    opts = StrengthOptions(root_method=case.get("options", "B"), factors=case.get("factors"))
    kw = dict(material1="42CrMo4", face_width_mm=30.0, geometry=pair._geo, beta_deg=pair.beta_deg, options=opts)
    mixed = pair_strength(pair.m, pair.z1, pair.z2, pair.x1, pair.x2, load=_bins(T, n, life_h=life), **kw)
    arrays = pair_strength(np.float64(pair.m), pair.z1, pair.z2, pair.x1, pair.x2, load=_bins(T, n, life_h=life), **kw)
    names = ("sigma_H1", "sigma_H2", "sigma_F1", "sigma_F2", "sigma_HG1", "sigma_FG2", "S_H1", "S_F1", "K_v",
             "K_Hbeta", "K_Halpha", "K_Fbeta", "K_Falpha", "Z_v1", "Z_NT1", "Y_NT2")
    for i in range(T.size):
        one = pair_strength(pair.m, pair.z1, pair.z2, pair.x1, pair.x2,
                            load=Load(torque_nm=float(T[i]), n_rpm=float(n[i]), life_h=life), **kw)
        for k in names:
            assert float(np.broadcast_to(mixed[k], T.shape)[i]) == pytest.approx(one[k], rel=1e-13), (k, i)
    for k in names:
        np.testing.assert_allclose(np.broadcast_to(mixed[k], T.shape), np.broadcast_to(arrays[k], T.shape),
                                   rtol=1e-13, err_msg=k)
