"""A batch larger than a block (geardesign.gears.strength.blocks) gives what the whole batch's call gives: the same
values bit for bit, in the same order, and the same refusal. The reference is the same chain with blocking turned off
(chain.BLOCK raised above the batch), which evaluates the batch in one pass as before blocks existed."""
import numpy as np
import pytest

from geardesign.errors import GearDesignError
from geardesign.gears.strength import Load, material, pair_strength
from geardesign.gears.strength import chain
from geardesign.gears.strength.blocks import BLOCK, batch_shape

LOAD = Load(torque_nm=200, n_rpm=1000, life_h=20_000)


def _designs(n, seed):
    rng = np.random.default_rng(seed)
    z1 = rng.integers(17, 45, n)
    z2 = z1 + rng.integers(1, 90, n)
    return rng.choice([2.0, 3.0, 4.0, 5.0, 6.0], n), z1, z2, rng.uniform(0.0, 0.6, n), rng.uniform(0.0, 0.6, n)


def _whole(monkeypatch, *args, **kw):
    with monkeypatch.context() as mp:
        mp.setattr(chain, "BLOCK", 10 ** 9)
        return pair_strength(*args, **kw)


def _same(a: dict, b: dict):
    assert list(a) == list(b)
    for k in a:
        if isinstance(a[k], tuple):
            assert a[k] == b[k], k
        else:
            x, y = np.asarray(a[k]), np.asarray(b[k])
            assert x.shape == y.shape and x.dtype == y.dtype, k
            assert np.array_equal(x, y, equal_nan=x.dtype.kind == "f"), k


@pytest.mark.parametrize("case", [
    dict(),
    dict(beta_deg=15.0, root_method="C", material2="18CrNiMo7-6", face_width2_mm=50.0, accuracy_grade=4),
    dict(internal=True, cycles_per_rev=(3, 1), rim_mm=(None, 60.0)),
    dict(root=False, factors={"K_Hbeta": 1.3}),
])
def test_blocks_give_the_whole_batch_values_bit_for_bit(monkeypatch, case):
    m, z1, z2, x1, x2 = _designs(2 * BLOCK + 777, 1)
    if case.get("internal"):
        z2 = z2 + 40
    args = (m, z1, z2, x1, x2)
    kw = dict(load=LOAD, material1=material("42CrMo4"), face_width_mm=10 * m, **case)
    blocked, whole = pair_strength(*args, **kw), _whole(monkeypatch, *args, **kw)
    _same(blocked, whole)
    if "f_ma" in whole:
        assert (blocked["f_ma"] is blocked["f_Hbeta"]) == (whole["f_ma"] is whole["f_Hbeta"])   # one array, as there


def test_a_batch_of_two_dimensions(monkeypatch):
    m, z1, z2, x1, x2 = _designs(20 * 1000, 2)
    # (20, 1) modules and pinions against (1, 1000) wheels: the designs broadcast to (20, 1000)
    args = (m[:20, None], z1[:20, None], z2[None, :1000], x1.reshape(20, 1000), x2.reshape(20, 1000))
    kw = dict(load=LOAD, material1="C45", face_width_mm=30.0)
    _same(pair_strength(*args, **kw), _whole(monkeypatch, *args, **kw))


@pytest.mark.parametrize("where", [10, BLOCK + 10, 2 * BLOCK + 5])
def test_a_refusal_anywhere_names_what_the_whole_batch_names(monkeypatch, where):
    m, z1, z2, x1, x2 = _designs(2 * BLOCK + 100, 3)
    z1[where], x1[where] = 7, -0.3                        # an undercut pinion: Z_B has no value there
    x1[BLOCK + 50] = 3.5                                   # and a shift the root factors refuse, later on
    kw = dict(load=LOAD, material1="42CrMo4", face_width_mm=10 * m)
    with pytest.raises(GearDesignError) as blocked:
        pair_strength(m, z1, z2, x1, x2, **kw)
    with pytest.raises(GearDesignError) as whole:
        _whole(monkeypatch, m, z1, z2, x1, x2, **kw)
    assert str(blocked.value) == str(whole.value)


def test_unvalidated_geometry_gives_nan_where_the_whole_batch_does(monkeypatch):
    from geardesign.gears.geometry import mesh_geometry
    from geardesign.gears.mesh import Mesh
    from geardesign.gears.strength.chain import CHAIN_GEOMETRY_FIELDS

    m, z1, z2, x1, x2 = _designs(BLOCK + 300, 4)
    z1[::89], x1[::89] = 7, -0.5                           # undercut pinions: no Z_B, no root section
    mesh = Mesh(z1.astype(float), z2.astype(float))
    with np.errstate(all="ignore"):
        g = mesh_geometry(mesh, m, x1, x2, full=False)
    geo = {k: g[k] for k in CHAIN_GEOMETRY_FIELDS + ("_z1", "_z2")}
    kw = dict(load=LOAD, material1="42CrMo4", face_width_mm=10 * m, geometry=geo)
    blocked, whole = pair_strength(m, z1, z2, x1, x2, **kw), _whole(monkeypatch, m, z1, z2, x1, x2, **kw)
    _same(blocked, whole)
    assert np.isnan(blocked["S_H1"][::89]).all() and np.isfinite(blocked["S_H1"][1::89]).all()


def test_batch_shape():
    assert batch_shape([np.zeros((3, 1)), np.zeros(4), 2.0, None]) == (3, 4)
    assert batch_shape([np.zeros(3), np.zeros(2)]) is None
