"""Heat balance of a worm gearbox: the identity θ_S = θ_lim exactly where S_T = 1, Autodesk's housing-area
estimate (tests/data/worm_efficiency_examples.md), bad input by name."""
import numpy as np
import pytest

from geardesign.errors import GearDesignError
from geardesign.gears.worm import temperature as t


def test_oil_temperature_reaches_the_limit_exactly_where_the_thermal_safety_is_one():
    # Niemann-Winter III Beispiel 3's cooling data: k = 0.028 kW/(m²K) = 28 W/(m²K), A = 2.9 m², 20 -> 90 °C
    k, A, t0, tl = 28.0, 2.9, 20.0, 90.0
    Q = k * A * (tl - t0)                                # 5684 W shed at the limit
    assert float(t.allowable_power_loss(k, A, t0, tl)) == pytest.approx(5684.0, rel=1e-14)
    assert float(t.oil_sump_temperature(Q, k, A, t0)) == pytest.approx(tl, rel=1e-14)
    assert float(t.thermal_safety(Q, k, A, t0, tl)) == pytest.approx(1.0, rel=1e-14)
    assert float(t.thermal_safety(Q / 2, k, A, t0, tl)) == pytest.approx(2.0, rel=1e-14)
    assert float(t.thermal_safety(0.0, k, A, t0, tl)) == np.inf
    assert float(t.oil_sump_temperature(0.0, k, A, t0)) == t0


def test_housing_area_estimate_is_autodesks_power_law():
    a = np.array([50.0, 100.0, 250.0])
    assert np.allclose(t.housing_area_estimate(a), 9e-5 * a ** 1.85, rtol=1e-15)
    # doubling a multiplies the area by 2^1.85
    assert float(t.housing_area_estimate(200.0) / t.housing_area_estimate(100.0)) == pytest.approx(2 ** 1.85)


@pytest.mark.parametrize("call, name", [
    (lambda: t.oil_sump_temperature(-1.0, 20.0, 1.0), "P_V"),
    (lambda: t.oil_sump_temperature(100.0, 0.0, 1.0), "k_heat"),
    (lambda: t.oil_sump_temperature(100.0, 20.0, -1.0), "A_housing"),
    (lambda: t.oil_sump_temperature(100.0, 20.0, 1.0, 500.0), "theta_0"),
    (lambda: t.thermal_safety(100.0, 20.0, 1.0, 60.0, 50.0), "theta_lim"),
    (lambda: t.housing_area_estimate(0.0), "a"),
])
def test_bad_input_is_refused_by_name(call, name):
    with pytest.raises(GearDesignError, match=name):
        call()
