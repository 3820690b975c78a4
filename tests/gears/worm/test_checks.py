"""The worm pair's checks in the registry: built for the pair kind "worm" only, each margin signed and checked
against its quantity computed here from the formulas (independently of geometry.py's dict), each able to fail."""
import math

import numpy as np

import pytest

from geardesign.errors import GearDesignError
from geardesign.gears import checks as ck
from geardesign.gears.worm import checks as wc
from geardesign.gears.worm.geometry import worm_geometry_float

NAMES = ["undercut2", "tip_thickness1", "tip_thickness2", "x2_range", "worm_length", "wheel_width", "contact_ratio"]


def test_built_for_worms_only_and_registered():
    assert [c.name for c in ck.make_checks(kind="worm")] == NAMES
    spur = [type(c) for c in ck.make_checks()] + [type(c) for c in ck.make_checks(internal=True)]
    assert not any(issubclass(t, (wc.WheelUndercut, wc.WormLength, wc.WheelShiftRange)) for t in spur)
    for cls in (wc.WheelUndercut, wc.WormTipThickness, wc.WheelTipThickness, wc.WheelShiftRange, wc.WormLength,
                wc.WheelWidth, wc.WormContactRatio):
        assert cls in ck.registered()
    assert set(wc.worm_options()) == {"undercut", "sa_min", "x2_abs_max", "worm_length_min", "wheel_width_max",
                                      "eps_alpha_min"}


def test_worm_only_options_stay_off_the_spur_commands():
    for name in ("x2_abs_max", "worm_length_min", "wheel_width_max"):
        assert ck.option(name).cli is False


def test_options_switch_and_limit_the_worm_checks():
    names = [c.name for c in ck.make_checks(kind="worm", undercut=False, eps_alpha_min=None, worm_length_min=False)]
    assert names == ["tip_thickness1", "tip_thickness2", "x2_range", "wheel_width"]
    with pytest.raises(GearDesignError, match="x2_abs_max must be in"):
        ck.make_checks(kind="worm", x2_abs_max=5)
    with pytest.raises(GearDesignError, match="kind must be one of"):
        ck.make_checks(kind="bevel")


def _margins(geo, **limits):
    return {c.name: float(c.margin(geo)) for c in ck.make_checks(kind="worm", **limits)}


def test_margins_are_the_quantities_against_their_limits():
    m, z1, z2, q, x2 = 4.0, 2, 30, 10.0, 0.25
    g = worm_geometry_float(m, z1, z2, q, x2, "ZA", worm_length_mm=70.0, face_width_mm=40.0)
    mg = _margins(g, sa_min=0.3, eps_alpha_min=1.3, x2_abs_max=0.8)
    a = math.radians(20.0)
    # the wheel's undercut limit with the standard rack (h_a* 1, c* 0.25, ρ_f* 0.38)
    x_min = 1.25 - 0.38 * (1 - math.sin(a)) - z2 * math.sin(a) ** 2 / 2
    assert mg["undercut2"] == pytest.approx(x2 - x_min, rel=1e-14)
    assert mg["x2_range"] == pytest.approx(0.8 - 0.25, rel=1e-14)
    assert mg["worm_length"] == pytest.approx((70.0 - math.pi * m * (4.5 + 0.02 * z2)) / m, rel=1e-14)
    assert mg["wheel_width"] == pytest.approx((0.75 * (q + 2) * m - 40.0) / m, rel=1e-14)
    r2, rb2, ra2 = z2 * m / 2, z2 * m / 2 * math.cos(a), z2 * m / 2 + (1 + x2) * m
    eps = (math.sqrt(ra2 ** 2 - rb2 ** 2) - r2 * math.sin(a) + (1 - x2) * m / math.sin(a)) / (math.pi * m * math.cos(a))
    assert mg["contact_ratio"] == pytest.approx(eps - 1.3, rel=1e-13)
    san1 = m * (math.pi / 2 - 2 * math.tan(a)) * math.cos(math.atan(z1 / (q + 2)))
    assert mg["tip_thickness1"] == pytest.approx(san1 / m - 0.3, rel=1e-13)


@pytest.mark.parametrize("geometry,limits,failing", [
    (dict(z2=20, x2=-0.6), {}, "undercut2"),                       # a small wheel shifted negative: undercut
    (dict(z2=20, x2=1.0), {}, "tip_thickness2"),        # a positive shift points a small wheel: s_a2 = 0.164 m_x
    (dict(z2=40, x2=0.9), dict(x2_abs_max=0.5), "x2_range"),
    (dict(z2=40, x2=0.0, worm_length_mm=20.0), {}, "worm_length"),
    (dict(z2=40, x2=0.0, face_width_mm=60.0), {}, "wheel_width"),
    (dict(z2=40, x2=0.9), dict(eps_alpha_min=1.7), "contact_ratio"),   # ε_α = 1.59
])
def test_each_check_can_fail(geometry, limits, failing):
    kw = dict(geometry)
    g = worm_geometry_float(4.0, 2, kw.pop("z2"), 10.0, kw.pop("x2"), "ZA", **kw)
    assert _margins(g, **limits)[failing] < 0


def test_worm_tip_thickness_fails_for_a_steep_tall_thread():
    from geardesign.gears.rack import BasicRack

    rack = BasicRack(alpha_deg=30.0, ha=1.3, c=0.25, rho_f=0.0)
    g = worm_geometry_float(2.0, 1, 40, 10.0, 0.0, "ZA", rack)
    assert _margins(g)["tip_thickness1"] < 0      # π/2 − 2·1.3·tan 30° = 0.070 < 0.25


def test_the_agma_load_check_is_built_with_a_load_only_and_is_the_ratings_safety():
    from geardesign.gears.worm.geometry import worm_geometry
    from geardesign.gears.worm.rating import worm_rating

    assert "agma_load" not in [c.name for c in ck.make_checks(kind="worm")]
    T = np.array([150.0, 300.0, 600.0])
    n1 = np.array([1500.0, 1000.0, 750.0])
    load = wc.WormLoad(T, n1, "chill", 1.25)
    (check,) = [c for c in ck.make_checks(kind="worm", worm_load=load, S_AGMAmin=1.2) if c.name == "agma_load"]
    geo = worm_geometry(5.0, 2, 40, 10.0)
    margins = check.margin(geo)
    for i in range(3):
        r = worm_rating(T[i], n1[i], 5.0, 2, 40, 10.0, alpha_n_deg=float(geo["alpha_n_deg"]), b_2=float(geo["b_2"]),
                        casting="chill", application_factor=1.25)
        assert margins[i] == pytest.approx(r.S_AGMA / 1.2 - 1.0, rel=1e-12)
    with pytest.raises(GearDesignError, match="worm_load"):
        ck.make_checks(kind="worm", worm_load=(300.0, 1500.0))
    with pytest.raises(GearDesignError, match="S_AGMAmin"):
        ck.make_checks(kind="worm", worm_load=load, S_AGMAmin=0.1)
