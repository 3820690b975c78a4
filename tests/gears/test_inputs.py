"""A pair's inputs and the conditions for its geometry to exist (geardesign.gears.inputs): each refusal names the
input, its value and the limit, the limits computed here from the textbook conditions (ISO 21771:2007):
inv α_w > 0, the root diameter d_f = m (z − 2 (h_a* + c* − x)) > 0, and a positive path of contact."""
import math
import re

import numpy as np
import pytest

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears.inputs import M_RANGE_MM, X_ABS_MAX, plain_inputs_ok, validate_inputs

A20 = math.radians(20)


def _limit_in(message: str, name: str) -> float:
    return float(re.search(rf"{re.escape(name)} must be > (-?[0-9.e+-]+)", message).group(1))


def test_x_sum_too_negative_names_the_limit():
    with pytest.raises(GearDesignError) as e:
        gd.pair_geometry(8, 17, 26, -0.5, -0.5)
    # inv α_w = inv α + 2 tan α x_Σ / z_Σ > 0  <=>  x_Σ > −z_Σ inv α / (2 tan α)
    want = -43 * (math.tan(A20) - A20) / (2 * math.tan(A20))
    assert "x1 + x2 = -1" in str(e.value)
    assert _limit_in(str(e.value), "x1 + x2") == pytest.approx(want, rel=1e-5)


def test_a_tip_inside_its_base_circle_names_the_gear_and_the_design_index():
    x = np.array([0.0, -7.0])
    with pytest.raises(GearDesignError) as e:
        gd.pair_geometry(2, 12, 30, x, 8.0, tip_shortening=False)   # x1 + x2 = 1 exists; gear 1's tip does not
    msg = str(e.value)
    assert "(design at index 1)" in msg and "x1 = -7" in msg and "tip circle of gear 1" in msg
    assert f"d_b1 = {2 * 12 * math.cos(A20):.6g}" in msg
    # d_a = m (z + 2 (h_a* + x)) > d_b = m z cos α  <=>  x > −h_a* − z sin²(α/2)
    assert _limit_in(msg, "x1") == pytest.approx(-1 - 12 * math.sin(A20 / 2) ** 2, rel=1e-5)


def test_gears_that_do_not_mesh_are_refused_by_gear_pair():
    with pytest.raises(GearDesignError, match="do not mesh"):
        gd.GearPair(2, 12, 12, 3.0, 3.0)


@pytest.mark.parametrize("args, words", [
    ((M_RANGE_MM[1] * 10, 17, 26, 0.0, 0.0), "m \\(module\\)"), ((0.0, 17, 26, 0.0, 0.0), "m \\(module\\)"),
    ((2, 2, 26, 0.0, 0.0), "z1 must be a whole number in \\[3, 100000\\]"), ((2, 17, 26.5, 0.0, 0.0), "z2"),
    ((2, 17, 26, X_ABS_MAX + 1, 0.0), "x1"), ((2, 17, 26, 0.0, float("nan")), "x2"),
])
def test_each_input_is_refused_by_name(args, words):
    with pytest.raises(GearDesignError, match=words):
        validate_inputs(*args)


def test_plain_inputs_take_the_fast_path_only_inside_their_ranges():
    assert plain_inputs_ok(8, 0.5, -0.2) and plain_inputs_ok(8.0, X_ABS_MAX, -X_ABS_MAX)
    assert not plain_inputs_ok(8, X_ABS_MAX + 1, 0.0) and not plain_inputs_ok(np.float64(8), 0.0, 0.0)
    assert not plain_inputs_ok(M_RANGE_MM[1] * 2, 0.0, 0.0) and not plain_inputs_ok(True, 0.0, 0.0)
