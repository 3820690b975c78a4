"""The chain of one design in plain numbers runs on Python floats (math); arrays of designs run on numpy. Both
evaluate the same formulas (geardesign.gears.strength.ops): every field agrees to 1e-12 on random designs,
external and internal, spur and helical, methods B and C, with given factors and two materials."""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from geardesign.errors import GearDesignError
from geardesign.gears.strength import Load, material, pair_strength

NAMES = ("42CrMo4", "18CrNiMo7-6", "31CrMoV9", "C45", "42CrMo4-IF")
GIVEN = (None, {"K_Hbeta": 1.2}, {"K_v": 1.05, "Z_NT1": 0.95}, {"Y_F1": 2.1, "Y_eps": 0.7},
         {"f_sh": 3.0, "c_prime": 14.0})

design = st.fixed_dictionaries(dict(
    m=st.sampled_from([1.0, 2.0, 3.0, 5.5, 8.0, 12.0]), z1=st.integers(12, 45), dz=st.integers(1, 90),
    x1=st.floats(-0.3, 0.8), x2=st.floats(-0.3, 0.8), beta=st.sampled_from([0.0, 8.0, 15.0, 30.0]),
    internal=st.booleans(), b_over_m=st.floats(5.0, 20.0), torque=st.floats(5.0, 5000.0),
    n=st.sampled_from([10.0, 300.0, 1500.0, 3000.0, 20000.0]), on_gear=st.sampled_from([1, 2]),
    life=st.one_of(st.none(), st.floats(100.0, 1e6)), method=st.sampled_from(["B", "C"]),
    mat1=st.sampled_from(NAMES), mat2=st.sampled_from(NAMES), grade=st.integers(3, 11),
    factors=st.sampled_from(GIVEN), rim=st.booleans(),
))


def _call(d, wrap):
    z2 = d["z1"] + d["dz"] + (20 if d["internal"] else 0)
    m = d["m"]
    args = (m, d["z1"], z2, d["x1"], d["x2"])
    return pair_strength(*(wrap(a) for a in args), load=Load(torque_nm=d["torque"], n_rpm=d["n"], on_gear=d["on_gear"],
                                                                 life_h=d["life"]),
                         material1=d["mat1"], material2=d["mat2"], face_width_mm=d["b_over_m"] * m, beta_deg=d["beta"],
                         internal=d["internal"], root_method=d["method"], accuracy_grade=d["grade"],
                         factors=d["factors"], rim_mm=(3.0 * m, None) if d["rim"] else (None, None))


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(design)
def test_one_design_in_floats_matches_the_array_path(d):
    try:
        one = _call(d, lambda v: v)
    except GearDesignError:     # a design that does not exist: the array path refuses it too (naming its index)
        with pytest.raises(GearDesignError):
            _call(d, lambda v: np.array([v]))
        return
    arr = _call(d, lambda v: np.array([v]))
    assert isinstance(one["S_H1"], float)          # the float path was taken
    assert set(one) == set(arr)
    for key, value in one.items():
        if isinstance(value, tuple):
            assert value == arr[key], key
            continue
        got, want = float(np.ravel(arr[key])[0]), float(value)
        assert got == pytest.approx(want, rel=1e-12, abs=0.0) or (math.isnan(got) and math.isnan(want)), key


def test_math_domain_errors_of_the_float_path_fall_back_to_the_array_path():
    # z1 = 3 passes the geometry's range (3 teeth and up) and is refused by the root form factors (5 and up):
    # the float path meets a negative square root on the way, the array path names the input
    with pytest.raises(GearDesignError, match=r"z must be a whole number in \[5, 100000\], got 3.0"):
        pair_strength(4.0, 3, 60, 0.3, 0.1, load=Load(torque_nm=200, n_rpm=1000), material1=material("42CrMo4"),
                      face_width_mm=40.0)
