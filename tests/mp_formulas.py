"""Independent involute relations in mpmath, shared by the test modules that need them
(tests/gears/test_pair.py, tests/shifts/test_center_distance.py): no number from geardesign."""
import mpmath as mp

mp.mp.dps = 40


def a_w(m, z1, z2, x_sum, alpha_deg=20):
    """a_w from inv α_w = inv α + 2 x_Σ tan α / z_Σ, a_w = a cos α / cos α_w (ISO 21771 (62), (63))."""
    a = mp.radians(alpha_deg)
    inv_a = mp.tan(a) - a
    inv_w = inv_a + 2 * mp.mpf(x_sum) * mp.tan(a) / (z1 + z2)
    aw = mp.findroot(lambda t: mp.tan(t) - t - inv_w, mp.mpf("0.4"))
    return mp.mpf(m) * (z1 + z2) / 2 * mp.cos(a) / mp.cos(aw)
