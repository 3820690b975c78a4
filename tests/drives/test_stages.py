"""Drive stages (geardesign.drives.stages): the size and mass models against independent
computations written here (the bounding box of the two wheels' sampled circles; a steel disc's volume
by hand), a bought unit's rated-torque margin, and inputs refused by name."""
import math

import numpy as np
import pytest

from geardesign.drives.stages import (EFFICIENCY_RANGE, GIVEN_RATIO_RANGE, STEEL_DENSITY_KG_M3, GivenStage, Shaft,
                                      disc_mass_kg, stage_area_mm2)
from geardesign.errors import GearDesignError


@pytest.mark.parametrize("a, d1, d2", [(100, 40, 160), (250, 120, 300), (80, 60, 60), (500, 300, 90)])
def test_stage_area_is_the_box_around_both_wheels(a, d1, d2):
    t = np.linspace(0, 2 * np.pi, 200_001)
    x = np.concatenate([d1 / 2 * np.cos(t), a + d2 / 2 * np.cos(t)])
    y = np.concatenate([d1 / 2 * np.sin(t), d2 / 2 * np.sin(t)])
    assert float(stage_area_mm2(a, d1, d2)) == pytest.approx(np.ptp(x) * np.ptp(y), rel=1e-9)


def test_disc_mass_by_hand():
    # d = 200 mm, b = 20 mm: V = π/4·0.2²·0.02 = 6.283185e-4 m³; steel 7850 kg/m³ -> 4.93230 kg
    assert STEEL_DENSITY_KG_M3 == 7850.0
    assert float(disc_mass_kg(200, 20)) == pytest.approx(math.pi / 4 * 0.04 * 0.02 * 7850, rel=1e-14)
    assert float(disc_mass_kg(200, 20)) == pytest.approx(4.93230, abs=5e-6)
    np.testing.assert_allclose(disc_mass_kg([100, 200], [10, 20]), [4.93230 / 8, 4.93230], rtol=1e-6)


def test_given_stage_rated_torque_margin():
    s = GivenStage(12.5, 0.87, "gear motor", rated_output_torque_nm=400)
    np.testing.assert_allclose(s.margins([200, 400, 500])["rated_torque"], [0.5, 0.0, -0.25])
    assert GivenStage(12.5, 0.87).margins(1e9) == {}
    assert GivenStage(2, 1.0).efficiency == 1.0           # a lossless stage is allowed


@pytest.mark.parametrize("kw, words", [
    (dict(ratio=GIVEN_RATIO_RANGE[1] * 2, efficiency=0.9), "ratio"),
    (dict(ratio=2, efficiency=EFFICIENCY_RANGE[0]), "efficiency"),
    (dict(ratio=2, efficiency=1.01), "efficiency"),
    (dict(ratio=2, efficiency=0.9, name="  "), "name"),
    (dict(ratio=2, efficiency=0.9, rated_output_torque_nm=0), "rated_output_torque_nm"),
])
def test_given_stage_refuses_by_name(kw, words):
    with pytest.raises(GearDesignError, match=words):
        GivenStage(**kw)


def test_shaft_refuses_a_hub_too_short_and_a_number_out_of_range():
    with pytest.raises(GearDesignError, match="at"):
        Shaft(d_mm=60, hub_length_mm=50, at=65)
    with pytest.raises(GearDesignError, match="hub_length_mm"):
        Shaft(d_mm=60, hub_length_mm=1, at=1)
