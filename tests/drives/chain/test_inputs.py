"""A chain design's inputs (geardesign.drives.chain.inputs): K_e the product of the named operating factors of
catalogs/chain_operating_factors.csv (each row cited there), the small sprocket's tooth counts by the rule
z1 = 29 − 2u, P = T·2πn/60, and each bad input refused by name."""
import math

import numpy as np
import pytest

from geardesign.catalogs import load_catalog
from geardesign.drives.chain.inputs import Conditions, validate_inputs
from geardesign.errors import GearDesignError

BASE = dict(torque_nm=380.0, power_kw=None, n1_rpm=120.0, ratio=1.0, conditions=None, k_e=None,
            allowable_pressure_mpa=None, allowable_safety_factor=None, catalog="gost13568", strands=(1, 2),
            z1=None, center_distance_mm=None, objective="min_mass", method="hinge_pressure", sag_factor=6.0,
            z2_max=120, center_distance_pitches=40.0)


def _factor(name, condition):
    t = load_catalog("chain_operating_factors")
    return float(t[(t["factor"] == name) & (t["condition"] == condition)]["value"].iloc[0])


def test_k_e_is_the_product_of_the_named_factors():
    c = Conditions.from_mapping({"k_d": "variable", "k_reg": "fixed", "k_lub": "irregular"})
    want = _factor("k_d", "variable") * _factor("k_reg", "fixed") * _factor("k_lub", "irregular")
    assert c.k_e == pytest.approx(want, rel=1e-15) and want == pytest.approx(1.35 * 1.25 * 1.5)
    inp = validate_inputs(**{**BASE, "conditions": {"k_d": "variable"}})
    assert inp.k_e == _factor("k_d", "variable") and inp.k_d == _factor("k_d", "variable")
    assert validate_inputs(**{**BASE, "k_e": 2.148}).k_e == 2.148     # seed 002's product, given as one number


def test_load_and_tooth_counts():
    inp = validate_inputs(**BASE)
    assert inp.power_w == pytest.approx(380.0 * 2 * math.pi * 120 / 60, rel=1e-15)
    # u = 1: odd z1 from 13 up to 29 − 2 = 27
    assert inp.z1_values.tolist() == list(range(13, 28, 2)) and not inp.z1_given
    by_power = validate_inputs(**{**BASE, "torque_nm": None, "power_kw": 4.0})
    assert by_power.torque == pytest.approx(4000 / (2 * math.pi * 120 / 60), rel=1e-15)
    assert np.array_equal(validate_inputs(**{**BASE, "z1": [13, 15]}).z1_values, [13, 15])


@pytest.mark.parametrize("change, words", [
    (dict(power_kw=4.0), "exactly one of torque_nm or power_kw"), (dict(n1_rpm=-1), "n1_rpm"),
    (dict(ratio=50), "ratio"), (dict(objective="cheapest"), "objective must be one of"),
    (dict(method="guess"), "method must be one of"), (dict(strands=5), "strands"),
    (dict(conditions={"k_d": "variable"}, k_e=2.0), "not both"), (dict(conditions={"k_x": 1.0}), "conditions key"),
    (dict(conditions={"k_lub": "sometimes"}), "k_lub"), (dict(z1=[61], ratio=3.0), "z2_max"),
    (dict(ratio=10.0, z2_max=120), "z2 = 130"),
])
def test_bad_inputs_are_refused_by_name(change, words):
    with pytest.raises(GearDesignError, match=words):
        validate_inputs(**{**BASE, **change})
