"""Issue 35 §2-4: standard centre distances (GOST 2185-66, ISO 3 preferred numbers) and the manufactured state
of a pair (its checks with the teeth thinned by their allowances, the housing within its allowance)."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import geardesign as gd
from geardesign.catalogs import center_distance_series, preferred_numbers
from geardesign.drives.housing import REDUCER_X_SUM_WINDOW, standard_center_distance
from geardesign.errors import GearDesignError


def test_iso3_preferred_numbers_are_the_standards_rounded_values():
    """ISO 3:1973 Table 1 (= DIN 323-1): R10 and R20 between 100 and 1000, as printed."""
    assert preferred_numbers("R10", 100, 1000).tolist() == [100, 125, 160, 200, 250, 315, 400, 500, 630, 800, 1000]
    assert preferred_numbers("R20", 100, 250).tolist() == [100, 112, 125, 140, 160, 180, 200, 224, 250]
    # every R40 value lies within 1.3 % of the exact geometric series 10^(i/40) (ISO 3's rounding)
    r40 = preferred_numbers("R40", 1, 9.99)
    exact = 10 ** (np.arange(40) / 40)
    assert np.max(np.abs(r40 / exact - 1)) < 0.013
    with pytest.raises(GearDesignError, match="series"):
        preferred_numbers("R7")


def _x_sum(m, z1, z2, a_w, beta_deg=0.0):
    """x1 + x2 for a_w, written out here: inv α_wt = inv α_t + 2 x_Σ tan α_n / z_Σ (ISO 21771 eq. (62))."""
    an = math.radians(20)
    b = math.radians(beta_deg)
    at = math.atan(math.tan(an) / math.cos(b))
    a = m * (z1 + z2) / (2 * math.cos(b))
    awt = math.acos(a * math.cos(at) / a_w)
    inv = lambda t: math.tan(t) - t
    return (inv(awt) - inv(at)) * (z1 + z2) / (2 * math.tan(an))


@settings(max_examples=60, deadline=None)
@given(st.sampled_from([1.5, 2, 2.5, 3, 4, 5, 6, 8]), st.integers(14, 30), st.integers(30, 140),
       st.sampled_from([0.0, 8.0, 15.0]))
def test_the_standard_center_distance_is_the_smallest_series_value_in_the_window(m, z1, z2, beta):
    """Brute force over GOST 2185-66: the chosen a_w is the smallest series value whose x-sum (computed here)
    lies in the reducer window; NaN when none does."""
    got = standard_center_distance(m, z1, z2, "gost2185", beta)
    lo, hi = REDUCER_X_SUM_WINDOW
    a_ref = m * (z1 + z2) / (2 * math.cos(math.radians(beta)))
    at = math.atan(math.tan(math.radians(20)) / math.cos(math.radians(beta)))
    fits = [a for a in center_distance_series((1, 2)) if a > a_ref * math.cos(at)
            and lo - 1e-9 <= _x_sum(m, z1, z2, a, beta) <= hi + 1e-9]
    if fits:
        assert got == fits[0]
    else:
        assert math.isnan(got)


def test_stage_options_are_checked_by_name():
    with pytest.raises(GearDesignError, match="center_distance"):
        gd.GearStage(3, center_distance="R7")
    with pytest.raises(GearDesignError, match="center_distance"):
        gd.GearStage(3, center_distance=-5)
    with pytest.raises(GearDesignError, match="mating_type"):
        gd.GearStage(3, mating_type="Q")
    with pytest.raises(GearDesignError, match="shift_bounds"):
        gd.GearStage(3, shift_bounds=(1, 0))
    assert gd.GearStage(None, material="42CrMo4").housing == "gost2185"
    assert gd.GearStage(3).housing == "free" and gd.GearStage(3).fit is None


def test_a_given_housing_puts_the_pair_there():
    """A stage of given module in a housing of a_w = 125 mm: the analysed pair runs at 125 mm."""
    a = gd.Drive(power_kw=5, n_in_rpm=1460, stages=[gd.GearStage(3, z1=20, z2=62, center_distance=125.0,
                                                                 mating_type="B")]).analyse()
    assert a.stages[0]["pair"].geometry().a_w == pytest.approx(125.0, abs=1e-9)
    assert a.success


def test_a_check_at_zero_margin_is_reported_as_such():
    """Issue 35 §4: a design on a boundary holds, and its analysis says which check has no reserve. 17/26 m 8 at
    the max_x_sum shifts sits on ε_α = 1.2 (seed 000's pair, optimize_shifts' own optimum)."""
    r = gd.optimize_shifts(17, 26, m=8)
    a = gd.Drive(power_kw=5, n_in_rpm=1000, stages=[gd.GearStage(8, z1=17, z2=26, x1=r.x1, x2=r.x2)]).analyse()
    assert a.success
    assert "at its limit, no reserve: gear: contact_ratio" in a.message
