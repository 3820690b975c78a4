"""Type confusion and extreme values at every entry point give one clear GearDesignError."""
import pytest

import geardesign as gd


@pytest.mark.parametrize("call", [
    lambda: gd.pair_geometry(1, [17, 18, 19], [26, 27], 0, 0),
    lambda: gd.BasicRack(ha=[1, 2]),
    lambda: gd.GearPair(1, 17, 26).checks(eps_alpha_min="abc"),
    lambda: gd.optimize_shifts(17, 26, objective=["max_x_sum"]),
    lambda: gd.GearPair(10**400, 17, 26),
    lambda: gd.BasicRack(alpha_deg=5e-324),
    lambda: gd.GearPair(8, 62, 63, 8, 2.046),
    lambda: gd.optimize_shifts(17, 26, grid_n=5000, method="grid"),
    lambda: gd.optimize_shifts(17, 26, bounds=(3, -1)),
    lambda: gd.GearPair(5e-324, 17, 26),
    lambda: gd.GearPair(1, 17, 26, 1e308, 0),
])
def test_type_confusion_and_extremes_are_one_clear_error(call):
    with pytest.raises(gd.GearDesignError):
        call()


def test_a_missing_required_argument_is_named_not_a_type_error():
    """hint_unknown_arguments also names required arguments left out (Python's TypeError 'missing 1 required
    positional argument' was the answer), for every class it wraps."""
    with pytest.raises(gd.GearDesignError, match=r"^GearPair needs z2 \(missing\)"):
        gd.GearPair(4, 20)
    with pytest.raises(gd.GearDesignError, match=r"^GearPair needs z1, z2 \(missing\)"):
        gd.GearPair(m=4)
    assert gd.GearPair(4, z2=60, z1=20).z1 == 20
