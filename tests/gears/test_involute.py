"""The involute function, its inverse and t − atan t (geardesign.gears.involute) against 50-digit mpmath
(tests/reference_mp.py; issue #2)."""
import math

import mpmath as mp
import numpy as np

import geardesign as gd
from tests import reference_mp as ref


def test_inv_inverse_against_mpmath():
    """inv_inverse to 1e-14 relative for every v on a dense log grid 1e-12 … 10 (issue #2)."""
    v = np.logspace(-12, 1, 1500)
    ours = gd.inv_inverse(v)
    worst = 0.0
    for vi, oi in zip(v, ours):
        r = ref.inv_inverse(mp.mpf(float(vi)))
        worst = max(worst, float(abs(mp.mpf(float(oi)) - r) / r))
    assert worst <= 1e-14, worst



def test_inv_against_mpmath():
    """inv α to ~1e-15 relative for α from 1e-8 to 1.5 rad."""
    alpha = np.concatenate([np.logspace(-8, np.log10(1.5), 1500),
                            np.linspace(0.28, 0.31, 200)])   # around the series/difference switch
    ours = gd.inv(alpha)
    worst, at = 0.0, None
    for ai, oi in zip(alpha, ours):
        r = ref.inv(mp.mpf(float(ai)))
        e = float(abs(mp.mpf(float(oi)) - r) / r)
        if e > worst:
            worst, at = e, float(ai)
    assert worst <= 1e-15, (worst, at)



def test_t_minus_atan_tabled_and_plain_against_mpmath():
    """The geometry's t − atan t (array and float) to 1e-15 relative on −10 … 10: the tabled node
    and its step below 8 (both sides of every node, tiny t on node 0), the plain difference above
    (both sides of the switch), NaN and inf passed through."""
    from geardesign.gears.involute import TABLE_T, t_minus_atan, t_minus_atan_float

    nodes = np.arange(1, int(TABLE_T * 32) + 1) / 32
    t = np.concatenate([np.geomspace(1e-9, 1e-2, 200), np.linspace(1e-6, 10.0, 3001), nodes,
                        np.nextafter(nodes, 0), np.nextafter(nodes, 10)])
    t = np.concatenate([t, -t])
    arr = t_minus_atan(t)
    worst = 0.0
    for ti, ai in zip(t, arr):
        r = mp.mpf(float(ti)) - mp.atan(mp.mpf(float(ti)))
        for ours in (ai, t_minus_atan_float(float(ti))):
            worst = max(worst, float(abs(mp.mpf(float(ours)) - r) / abs(r)))
    assert worst <= 1e-15, worst
    odd = np.array([np.nan, np.inf, -np.inf, 0.0])
    got = t_minus_atan(odd)
    assert np.isnan(got[0]) and got[1] == np.inf and got[2] == -np.inf and got[3] == 0.0
    assert math.isnan(t_minus_atan_float(math.nan)) and t_minus_atan_float(0.0) == 0.0
    assert t_minus_atan(np.empty((0, 3))).shape == (0, 3)



def test_inv_scalar_in_float_out():
    assert type(gd.inv(0.3)) is float
    assert type(gd.inv_inverse(0.01)) is float
    assert type(gd.inv(np.float64(0.3))) is float
    assert isinstance(gd.inv(np.array([0.3, 0.4])), np.ndarray)
    # round trip through the reference: inv_inverse(inv(20°)) = 20°
    a = math.radians(20.0)
    assert abs(gd.inv_inverse(float(ref.inv(a))) - a) <= 1e-15 * a
