"""A duty cycle (geardesign.drives.duty_cycle): a spectrum relative to a stage's nominal load. Its bins at a load are
the factors times that load, worked here by hand; a spectrum made relative and scaled back is the spectrum."""
import numpy as np
import pytest

import geardesign as gd
from geardesign.drives.duty_cycle import DutyCycle
from geardesign.errors import GearDesignError


def test_bins_at_a_nominal_load_are_the_factors_times_it():
    duty = DutyCycle([2.0, 1.0, -0.5], [0.01, 0.39, 0.6], speed_factor=[1.0, 1.0, 0.5])
    s = duty.at(150.0, 960.0, 25000.0)
    assert s.torque_nm.tolist() == [300.0, 150.0, -75.0]
    assert s.n_rpm.tolist() == [960.0, 960.0, 480.0]
    assert s.time_h == pytest.approx([250.0, 9750.0, 15000.0], rel=1e-15)
    assert duty.reverses and s.reverses
    # ISO 6336-6 Annex A's T_eq of the bins scales with the nominal torque, K_A = T_eq/T_n does not
    k_a = [duty.at(T, 960.0, 25000.0).application_factor(T, 6.61) for T in (10.0, 150.0, 4000.0)]
    assert k_a == pytest.approx([k_a[0]] * 3, rel=1e-12)
    # ... and is the duty cycle's own: Σ n_i q_i^p over Σ n_i with n_i ∝ share_i·q_n,i, by hand
    n = np.array([0.01, 0.39, 0.6 * 0.5])
    assert duty.application_factor(6.61) == pytest.approx(((n @ np.array([2.0, 1.0, 0.5]) ** 6.61) / n.sum())
                                                          ** (1 / 6.61), rel=1e-14)
    assert k_a[0] == pytest.approx(duty.application_factor(6.61), rel=1e-12)


def test_a_spectrum_made_relative_and_scaled_back_is_the_spectrum():
    spec = gd.LoadSpectrum.from_bins([120.0, 90.0, 60.0], [1000.0, 1000.0, 800.0], time_h=[2000, 8000, 10000])
    duty = DutyCycle.from_spectrum(spec, 80.0, 1000.0)
    assert duty.torque_factor.tolist() == [1.5, 1.125, 0.75]
    assert duty.speed_factor.tolist() == [1.0, 1.0, 0.8]
    assert duty.share.tolist() == pytest.approx([0.1, 0.4, 0.5], rel=1e-15)
    back = duty.at(80.0, 1000.0, spec.duration_h)
    for k in ("torque_nm", "n_rpm", "time_h"):
        assert getattr(back, k) == pytest.approx(getattr(spec, k), rel=1e-15)


@pytest.mark.parametrize("kw, words", [
    (dict(torque_factor=[1.0, 0.5], share=[0.5, 0.4]), "share must sum to 1"),
    (dict(torque_factor=[1.0, 0.5], share=[1.0]), "share must be one per bin"),
    (dict(torque_factor=[0.0, 0.0], share=[0.5, 0.5]), "all bins are 0"),
    (dict(torque_factor=[1e3], share=[1.0]), "torque_factor"),
    (dict(torque_factor=[np.nan], share=[1.0]), "torque_factor"),
    (dict(torque_factor=[1.0], share=[1.0], speed_factor=0.0), "speed_factor"),
    (dict(torque_factor=[1.0, 0.5], share=[0.5, 0.5], speed_factor=[1, 1, 1]), "speed_factor"),
])
def test_bad_duty_cycles_are_refused_by_name(kw, words):
    with pytest.raises(GearDesignError, match=words):
        DutyCycle(**kw)


def test_a_spectrum_counted_per_tooth_is_not_a_duty_cycle():
    per_tooth = gd.LoadSpectrum.from_curve([100.0, 100.0], angle_deg=[0.0, 360.0], n_rpm=600, teeth=(20, 40))
    with pytest.raises(GearDesignError, match="per tooth"):
        DutyCycle.from_spectrum(per_tooth, 100.0, 600.0)
    with pytest.raises(GearDesignError, match="more than 100 times"):
        DutyCycle.from_spectrum(gd.LoadSpectrum.from_bins([5e4], 600, time_h=[1.0]), 100.0, 600.0)
