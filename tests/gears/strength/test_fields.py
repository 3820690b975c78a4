"""``pair_strength(..., fields=...)``: only the fields asked for, with the values of the call that returns every field
(bit for bit: the same chain, the others dropped block by block), the same refusal of a design without a result, and a
name the result does not have refused with the names it has (issue 36 §3: 10⁷ designs peaked at 5.7 GB)."""
import numpy as np
import pytest

from geardesign.errors import GearDesignError
from geardesign.gears.strength import Load, material, pair_strength
from geardesign.gears.strength.blocks import BLOCK

LOAD = Load(torque_nm=200, n_rpm=1000, life_h=20_000)
FIELDS = ("S_H1", "S_F2", "K_Hbeta", "Z_NT1")


def _designs(n, seed):
    rng = np.random.default_rng(seed)
    z1 = rng.integers(17, 45, n)
    z2 = z1 + rng.integers(1, 90, n)
    return rng.choice([2.0, 3.0, 4.0, 5.0, 6.0], n), z1, z2, rng.uniform(0.0, 0.6, n), rng.uniform(0.0, 0.6, n)


@pytest.mark.parametrize("n", [1, 7, 2 * BLOCK + 777])
def test_fields_are_the_full_calls_values(n):
    m, z1, z2, x1, x2 = _designs(n, 3)
    if n == 1:      # one design in plain numbers: the float path
        m, z1, z2, x1, x2 = float(m[0]), int(z1[0]), int(z2[0]), float(x1[0]), float(x2[0])
    kw = dict(load=LOAD, material1=material("42CrMo4"), face_width_mm=10 * np.asarray(m))
    if n == 1:
        kw["face_width_mm"] = float(kw["face_width_mm"])
    full = pair_strength(m, z1, z2, x1, x2, **kw)
    some = pair_strength(m, z1, z2, x1, x2, fields=FIELDS, **kw)
    assert list(some) == [*FIELDS, "given", "given_unused"]
    for k in FIELDS:
        assert np.array_equal(np.asarray(some[k]), np.asarray(full[k])), k
    assert some["given"] == full["given"] and some["given_unused"] == full["given_unused"]


def test_a_field_the_result_lacks_is_refused_with_the_names_it_has():
    m, z1, z2, x1, x2 = _designs(2 * BLOCK + 5, 4)
    kw = dict(load=LOAD, material1=material("42CrMo4"), face_width_mm=10 * m)
    with pytest.raises(GearDesignError, match="'S_F1' not in pair_strength's result; it has .*S_H1"):
        pair_strength(m, z1, z2, x1, x2, fields=("S_H1", "S_F1"), root=False, **kw)
    with pytest.raises(GearDesignError, match="fields must be names"):
        pair_strength(m, z1, z2, x1, x2, fields=3, **kw)


def test_a_design_without_a_result_is_refused_as_without_fields():
    m, z1, z2, x1, x2 = _designs(2 * BLOCK + 100, 5)
    x1[BLOCK + 50] = 3.5                    # a shift the root factors refuse
    kw = dict(load=LOAD, material1=material("42CrMo4"), face_width_mm=10 * m)
    with pytest.raises(GearDesignError) as full:
        pair_strength(m, z1, z2, x1, x2, **kw)
    with pytest.raises(GearDesignError) as some:
        pair_strength(m, z1, z2, x1, x2, fields=("S_H1",), **kw)
    assert str(some.value) == str(full.value)


def test_a_small_batchs_refusal_names_the_factor_as_without_fields():
    """Below a block the chain leaves the fields not asked for at their own shapes (fields=): the refusal of a
    design without a result still names the design and the factor the call with every field names."""
    m, z1, z2, x1, x2 = _designs(7, 6)
    x1[4] = 3.5
    kw = dict(load=LOAD, material1=material("42CrMo4"), face_width_mm=10 * m)
    with pytest.raises(GearDesignError) as full:
        pair_strength(m, z1, z2, x1, x2, **kw)
    with pytest.raises(GearDesignError) as some:
        pair_strength(m, z1, z2, x1, x2, fields=("sigma_H1", "sigma_FG2"), **kw)
    assert str(some.value) == str(full.value)
