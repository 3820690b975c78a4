"""SliderCrank: its inputs checked by name, its derived sizes."""
import math

import pytest

from geardesign.errors import GearDesignError
from geardesign.mechanism.slider_crank import SliderCrank


def test_stroke_and_ratio():
    assert SliderCrank(70, 250).stroke_mm == pytest.approx(140.0, abs=1e-12)
    assert SliderCrank(70, 250).ratio == pytest.approx(0.28)
    # offset: the dead centres are where crank and rod line up, √((l ± r)² − e²)
    assert SliderCrank(50, 160, offset_mm=10).stroke_mm == pytest.approx(math.sqrt(210**2 - 100)
                                                                         - math.sqrt(110**2 - 100), rel=1e-15)


@pytest.mark.parametrize("kw, match", [
    (dict(rod_length_mm=60), "rod_length_mm must exceed crank_radius_mm"),
    (dict(rod_cg_mm=-1), "rod_cg_mm must be in \\[0, 250\\] mm"),
    (dict(piston_mass_kg=-0.1), "piston_mass_kg must be in \\[0, 100000\\] kg"),
    (dict(rod_inertia_kg_m2=float("nan")), "rod_inertia_kg_m2 must be finite"),
    (dict(crank_cg_mm=1e4), "crank_cg_mm must be in \\[-700, 700\\] mm"),
    (dict(cylinder_bore_mm=0), r"cylinder_bore_mm must be in \(0, 100000\] mm, got 0"),
    (dict(rod_mass_kg=[1, 2]), "rod_mass_kg must be one number"),
    (dict(bore_mm=90), "SliderCrank has no argument 'bore_mm': the cylinder's bore is cylinder_bore_mm"),
])
def test_bad_inputs_are_refused_by_name(kw, match):
    args = dict(crank_radius_mm=70, rod_length_mm=250) | kw
    with pytest.raises(GearDesignError, match=match):
        SliderCrank(**args)


def test_bore_is_asked_for_by_name_when_a_pressure_needs_it():
    with pytest.raises(GearDesignError, match="cylinder_bore_mm is needed"):
        SliderCrank(70, 250).need_bore()
    assert SliderCrank(70, 250, cylinder_bore_mm=100).need_bore() == 100.0


def test_a_bore_beyond_the_lengths_is_refused_by_name():
    """Fuzzing found an overflow RuntimeWarning escaping an engine with cylinder_bore_mm = 1e308."""
    with pytest.raises(GearDesignError, match=r"cylinder_bore_mm must be in \(0, 100000\] mm, got 1e\+308"):
        SliderCrank(45, 150, cylinder_bore_mm=1e308)
