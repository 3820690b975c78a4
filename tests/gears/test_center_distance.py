"""Centre distance and the x-sum (geardesign.gears.center_distance) on KHK's worked examples (KHK Gear Technical
Reference / SDP/SI D785 §4-5: the external pair z 12/24, m 3, x 0.6/0.36, a_w 56.4999 mm; the internal pair
z 16/24, m 3, x 0/0.5, a_w 13.1683 mm) and the closed forms inv α_w = 2 tan α x_Σ/z_Σ + inv α, a_w = a cos α/cos α_w."""
import math

import numpy as np
import pytest

from geardesign.gears import center_distance as cd
from geardesign.gears.rack import BasicRack

A20 = math.radians(20)


def inv(a):
    return math.tan(a) - a


def test_operating_angle_of_khks_external_example():
    got = float(cd.inv_operating_angle(12, 24, 0.6, 0.36, A20))
    assert got == pytest.approx(0.034316, abs=5e-7)                                # KHK prints 0.034316
    assert got == pytest.approx(2 * math.tan(A20) * 0.96 / 36 + inv(A20), rel=1e-14)


def test_x_sum_and_centre_distance_both_ways():
    assert cd.x_sum_from_center_distance(3, 12, 24, 56.4999) == pytest.approx(0.960013, abs=5e-7)   # KHK
    assert float(cd.center_distance_from_x_sum(3, 12, 24, 0.960013)) == pytest.approx(56.4999, abs=5e-5)
    assert cd.x_sum_from_center_distance(3, 16, 24, 13.1683, internal=True) == pytest.approx(0.5, abs=5e-5)
    # a_w = a cos α / cos α_w with a = m (z1 + z2)/2
    xs = np.linspace(-0.5, 2.0, 11)
    for x in xs:
        alpha_w = _solve_inv(2 * math.tan(A20) * x / 36 + inv(A20))
        assert float(cd.center_distance_from_x_sum(3, 12, 24, x)) == pytest.approx(
            54 * math.cos(A20) / math.cos(alpha_w), rel=1e-12)


def _solve_inv(v):
    a = 0.5
    for _ in range(60):                 # Newton on tan a − a = v (d/da = tan² a)
        a -= (math.tan(a) - a - v) / math.tan(a) ** 2
    return a


def test_min_center_distance_and_undercut_limit():
    assert float(cd.min_center_distance(2.5, 12, 31)) == pytest.approx(2.5 * 43 / 2 * math.cos(A20), rel=1e-15)
    # KHK's undercut limit with a rack whose fillet ends h_a* above the datum: x_min = 1 − z sin²α/2
    rack = BasicRack(rho_f=0.25 / (1 - math.sin(A20)))
    got = [float(cd.undercut_x_min(z, rack)) for z in (12, 24)]
    assert got == pytest.approx([0.29813, -0.40373], abs=5e-6)                  # KHK prints both
    assert got == pytest.approx([1 - z * math.sin(A20) ** 2 / 2 for z in (12, 24)], abs=1e-9)
