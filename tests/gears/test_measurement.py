"""Measuring sizes (geardesign.gears.measurement): published examples, independent measurement on the generated
teeth, properties, errors."""
import csv
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq, minimize_scalar

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears import measurement_formulas as f
from geardesign.gears.measurement import tooth_measurements
from geardesign.gears.rack import BasicRack
from geardesign.gears.ring import ShaperCutter
from geardesign.profiles import ring as ring_mod
from geardesign.profiles.tooth import _Cutter, transverse_rack

DATA = Path(__file__).parent.parent / "data" / "measurement_examples.csv"
TOL = 1e-9   # times the module: the formulas against the generated flanks


def rows(example):
    with DATA.open(encoding="utf-8") as fh:
        return {r["quantity"]: r for r in csv.DictReader(fh) if r["example_id"] == example}


def rounded(value, digits):
    return round(float(value), int(digits))


# --- published examples: every printed digit --------------------------------------------------------------


def test_machinecalcs_span_example():
    r = rows("MC_span_20")
    t = tooth_measurements(2, 20, 0.0)
    assert int(t.k) == int(r["k"]["published_value"])
    assert rounded(t.w_k, 3) == float(r["w_k"]["published_value"])
    assert rounded(t.d_wk, 2) == float(r["d_wk"]["published_value"])


def test_sdp_si_spur_chordal_thickness_example():
    r = rows("SDP_T81_10_1")
    t = tooth_measurements(10, 12, 0.3)          # tip (1 + x) m: h_a = 13.000 as the table
    assert rounded(t.s_n, 4) == float(r["s_n"]["published_value"])
    assert rounded(t.s_chord, 4) == float(r["s_chord"]["published_value"])
    assert rounded(t.h_chord, 4) == float(r["h_chord"]["published_value"])


def test_sdp_si_helical_chordal_thickness_example():
    """SDP/SI's helical table uses the approximate virtual count z/cos³β: the formula functions on its d_n give
    every printed digit; tooth_measurements uses ISO 21771's z/(cos²β_b cos β) and differs by ~5e-4 mm."""
    r = rows("SDP_T81_10_3")
    m, z, beta = 5.0, 16, math.radians(25.0)
    s_n = f.normal_tooth_thickness(m, 0.2, math.radians(20))
    z_v = z / math.cos(beta) ** 3
    assert rounded(s_n, 4) == float(r["s_n"]["published_value"])
    assert rounded(z_v, 4) == float(r["z_v"]["published_value"])
    assert rounded(math.degrees(s_n / (z_v * m)), 5) == float(r["theta_v_deg"]["published_value"])
    assert rounded(f.chordal_thickness(z_v * m, s_n), 4) == float(r["s_chord"]["published_value"])
    assert rounded(f.chordal_height(z_v * m, s_n, 6.0), 4) == float(r["h_chord"]["published_value"])
    t = tooth_measurements(5, 16, 0.2, beta_deg=25)
    assert abs(t.s_chord - 8.5728) < 1e-3


# --- independent measurement on the generated teeth ---------------------------------------------------------


def _flank(m, z, x, beta_deg, d_a):
    """The generated right flank (the rack's law-of-gearing envelope of geardesign.profiles.tooth) as a function
    of its parameter s, and the parameter range of the involute up to the tip."""
    rack_t, cb = transverse_rack(BasicRack(), beta_deg)
    cut = _Cutter.of(m / cb, z, x * cb, rack_t)
    lo = min(cut.s_form(), cut.r * math.sin(cut.alpha))
    hi = float(cut.s_at_radius(d_a / 2.0))
    return cut, (min(lo, hi), max(lo, hi))


def _maximise(fun, bounds):
    r = minimize_scalar(lambda s: -fun(s), bounds=bounds, method="bounded", options={"xatol": 1e-13})
    assert bounds[0] + 1e-9 < r.x < bounds[1] - 1e-9, "the extreme must lie inside the involute"
    return -r.fun


def span_on_generated_teeth(m, z, x, k, beta_deg=0.0):
    """W_k as the distance between the two parallel planes touching k generated teeth: the teeth turned by the
    angular pitch, the group symmetric about +y, so the outermost right flank's largest x is half the span in the
    transverse section; times cos β_b into the normal section of the base helix."""
    t = tooth_measurements(m, z, x, k=k, beta_deg=beta_deg)
    cut, bounds = _flank(m, z, x, beta_deg, t.d_a)
    g = (k - 1) * math.pi / z
    half = _maximise(lambda s: float(np.dot(np.ravel(cut.flank(np.array([s]))), (math.cos(g), math.sin(g)))), bounds)
    sc = gd.Mesh(17, 26, beta_deg=beta_deg).section
    return 2.0 * half * sc.cos_beta_b, t


@pytest.mark.parametrize("m, z, x, k, beta", [(2, 20, 0.0, 3, 0.0), (3, 24, 0.4, 4, 0.0), (1, 57, -0.3, 7, 0.0),
                                              (5, 13, 0.5, 2, 0.0), (3, 24, 0.4, 4, 20.0), (2, 41, 0.1, 5, 33.0)])
def test_span_equals_tangent_planes_on_generated_teeth(m, z, x, k, beta):
    measured, t = span_on_generated_teeth(m, z, x, k, beta)
    assert abs(measured - t.w_k) < TOL * m


def _ball_centre_radius(distance, d_m_guess, m):
    return brentq(distance, d_m_guess / 2 - 0.3 * m, d_m_guess / 2 + 0.3 * m, xtol=1e-15, rtol=1e-15)


@pytest.mark.parametrize("m, z, x, ball", [(2, 20, 0.0, None), (3, 24, 0.4, None), (1, 57, -0.3, 1.9),
                                           (5, 13, 0.5, None), (2, 21, 0.1, 3.0)])
def test_ball_equals_circle_tangent_to_generated_flanks(m, z, x, ball):
    """The ball centre lies on the space's axis where its distance to the generated flank is D/2."""
    t = tooth_measurements(m, z, x, ball_mm=ball)
    cut, bounds = _flank(m, z, x, 0.0, t.d_a)
    axis = (math.sin(math.pi / z), math.cos(math.pi / z))

    def gap(rc):
        def dist(s):
            px, py = cut.flank(np.array([s]))
            return math.hypot(px[0] - rc * axis[0], py[0] - rc * axis[1])
        r = minimize_scalar(dist, bounds=bounds, method="bounded", options={"xatol": 1e-13})
        return r.fun - t.ball_mm / 2.0

    rc = _ball_centre_radius(gap, t.d_m, m)
    assert abs(2.0 * rc - t.d_m) < TOL * m
    centre = 2.0 * rc if z % 2 == 0 else 2.0 * rc * math.cos(math.pi / (2 * z))
    assert abs(centre + t.ball_mm - t.m_d) < TOL * m


@pytest.mark.parametrize("m, z, x, beta", [(3, 24, 0.4, 20.0), (1.5, 17, 0.3, 30.0)])
def test_ball_on_helical_gear_is_exact(m, z, x, beta):
    """A ball touching the helicoid (the transverse generated flank swept along the helix) in 3-D."""
    t = tooth_measurements(m, z, x, beta_deg=beta, ball_mm="exact")
    cut, bounds = _flank(m, z, x, beta, t.d_a)
    twist = math.tan(math.radians(beta)) / cut.r
    axis = (math.sin(math.pi / z), math.cos(math.pi / z))

    def gap(rc):
        cx, cy = rc * axis[0], rc * axis[1]

        def at_section(zeta):
            c, s = math.cos(zeta * twist), math.sin(zeta * twist)

            def dist(u):
                px, py = cut.flank(np.array([u]))
                return math.sqrt((c * px[0] - s * py[0] - cx) ** 2 + (s * px[0] + c * py[0] - cy) ** 2 + zeta ** 2)
            return minimize_scalar(dist, bounds=bounds, method="bounded", options={"xatol": 1e-12}).fun
        return minimize_scalar(at_section, bounds=(-3 * m, 3 * m), method="bounded",
                               options={"xatol": 1e-12}).fun - t.ball_mm / 2.0

    rc = brentq(gap, t.d_m / 2 - 0.3 * m, t.d_m / 2 + 0.3 * m, xtol=1e-14, rtol=1e-15)
    assert abs(2.0 * rc - t.d_m) < TOL * m
    # where it touches: the closest point of the helicoid (an argmin, so only ~√ε·m sharp: 1e-6·m)
    cx, cy = rc * axis[0], rc * axis[1]
    best = {}

    def section(zeta):
        c, s = math.cos(zeta * twist), math.sin(zeta * twist)

        def dist(u):
            px, py = cut.flank(np.array([u]))
            return math.sqrt((c * px[0] - s * py[0] - cx) ** 2 + (s * px[0] + c * py[0] - cy) ** 2 + zeta ** 2)
        r = minimize_scalar(dist, bounds=bounds, method="bounded", options={"xatol": 1e-13})
        best[zeta] = math.hypot(*np.ravel(cut.flank(np.array([r.x]))))
        return r.fun
    zeta = minimize_scalar(section, bounds=(-3 * m, 3 * m), method="bounded", options={"xatol": 1e-13}).x
    section(zeta)
    assert abs(2.0 * best[zeta] - t.d_ball) < 1e-6 * m
    assert abs(t.d_ball - t.d_y) < 1e-9 * m                 # the default ball touches the aim circle


@pytest.mark.parametrize("m, z, x", [(2, 60, 0.3), (1, 48, 0.0), (3, 71, 0.5)])
def test_ball_between_ring_teeth_generated_by_the_shaper(m, z, x):
    """A ring (ring_profile's shaper-cutter envelope): the ball in a space, tangent to the generated flank."""
    rack = BasicRack()
    t = tooth_measurements(m, z, x, internal=True)
    cut, t_a0, *_ = ring_mod._cutter_in_place(m, z, x, t.d_a / 2, ShaperCutter(), rack, rack.alpha, m, 1.0)
    axis = (math.sin(math.pi / z), math.cos(math.pi / z))

    def gap(rc):
        def dist(u):
            px, py = ring_mod._mirror(z, *cut.envelope(*cut.flank(np.array([u]))))
            return math.hypot(px[0] - rc * axis[0], py[0] - rc * axis[1])
        return minimize_scalar(dist, bounds=(1e-6, t_a0), method="bounded", options={"xatol": 1e-13}).fun - t.ball_mm / 2

    rc = _ball_centre_radius(gap, t.d_m, m)
    assert abs(2.0 * rc - t.d_m) < TOL * m
    assert abs(t.m_d - (t.d_m - t.ball_mm if z % 2 == 0 else t.d_m * math.cos(math.pi / (2 * z)) - t.ball_mm)) < 1e-12 * m


def test_undercut_stub_flags_its_ball():
    t = tooth_measurements(1, 8, -0.5)               # heavily undercut: little involute left
    assert t.d_ff < t.d_y < t.d_a
    thin = tooth_measurements(1, 8, -0.5, thickness_allowance_mm=-0.125, ball_mm=t.ball_mm)
    assert thin.ball_ok and thin.m_d_max < t.m_d


@pytest.mark.parametrize("m, z, x", [(2, 60, 0.3), (1, 48, 0.0), (3, 71, 0.5)])
def test_ring_span_over_spaces_equals_the_anvil_planes_in_the_shaper_generated_ring(m, z, x):
    """k spaces symmetric about +y: the anvil in the outermost space touches the facing flank (the left flank of
    the ring tooth at kπ/z, ring_profile's right flank mirrored) where it reaches farthest out."""
    rack = BasicRack()
    t = tooth_measurements(m, z, x, internal=True)
    k = int(t.k)
    cut, t_a0, *_ = ring_mod._cutter_in_place(m, z, x, t.d_a / 2, ShaperCutter(), rack, rack.alpha, m, 1.0)
    g = k * math.pi / z

    def reach(u):
        px, py = np.ravel(ring_mod._mirror(z, *cut.envelope(*cut.flank(np.array([u])))))
        return -px * math.cos(g) + py * math.sin(g)

    half = _maximise(reach, (1e-9, t_a0 * (1 - 1e-12)))
    assert abs(2.0 * half - t.w_k) < TOL * m


@pytest.mark.parametrize("m, z, x, internal", [(10, 12, 0.3, False), (2, 31, -0.2, False), (2, 60, 0.3, True),
                                              (3, 71, 0.5, True)])
def test_chordal_thickness_and_height_on_the_generated_tooth(m, z, x, internal):
    """The chord between the generated flanks on the reference circle, and its height over the caliper's tongue:
    on the tip's middle for an external tooth, on the two tip corners of a ring's concave tip."""
    t = tooth_measurements(m, z, x, internal=internal)
    r = m * z / 2.0
    if internal:
        rack = BasicRack()
        cut, t_a0, *_ = ring_mod._cutter_in_place(m, z, x, t.d_a / 2, ShaperCutter(), rack, rack.alpha, m, 1.0)

        def point(u):
            return np.ravel(ring_mod._mirror(z, *cut.envelope(*cut.flank(np.array([u])))))
        u_r = brentq(lambda u: math.hypot(*point(u)) - r, 1e-9, t_a0 * (1 - 1e-12), xtol=1e-15, rtol=1e-15)
        u_a = brentq(lambda u: math.hypot(*point(u)) - t.d_a / 2, 1e-9, t_a0 * (1 - 1e-12), xtol=1e-15, rtol=1e-15)
        psi, eta_a = (math.atan2(*point(u)) for u in (u_r, u_a))
        height = r * math.cos(psi) - t.d_a / 2 * math.cos(eta_a)
    else:
        cut = _Cutter.of(m, z, x, BasicRack())
        psi = math.atan2(*np.ravel(cut.flank(cut.s_at_radius(np.array([r])))))
        height = t.d_a / 2 - r * math.cos(psi)
    assert abs(2 * r * math.sin(psi) - t.s_chord) < TOL * m
    assert abs(height - t.h_chord) < TOL * m


def test_default_ball_touches_the_aim_circle():
    for internal, z in ((False, 31), (True, 64)):
        t = tooth_measurements(2.5, z, 0.25, internal=internal, beta_deg=15, ball_mm="exact")
        assert abs(t.d_ball - t.d_y) < 1e-9 * 2.5


# --- properties ---------------------------------------------------------------------------------------------

def measured(*args, **kwargs):
    """tooth_measurements, or a skipped example where the gear does not exist (pointed, tip in the base circle)."""
    try:
        return tooth_measurements(*args, **kwargs)
    except GearDesignError:
        assume(False)


gears = st.tuples(st.floats(0.5, 20), st.integers(8, 300), st.floats(-0.5, 1.0), st.sampled_from([0.0, 10.0, 25.0]))


@settings(max_examples=60, deadline=None)
@given(gears, st.integers(1, 6))
def test_next_tooth_adds_a_normal_base_pitch(g, k):
    m, z, x, beta = g
    k = min(k, z - 2)
    w = [measured(m, z, x, k=kk, beta_deg=beta).w_k for kk in (k, k + 1)]
    assert abs((w[1] - w[0]) - math.pi * m * math.cos(math.radians(20))) < 1e-12 * m * z


@settings(max_examples=60, deadline=None)
@given(gears, st.floats(0.001, 0.2))
def test_thinning_allowance_reduces_the_sizes_of_an_external_gear(g, thin):
    m, z, x, beta = g
    nominal = measured(m, z, x, beta_deg=beta)
    t = measured(m, z, x, beta_deg=beta, thickness_allowance_mm=(-thin * m / 2, -thin * m),
                           ball_mm=nominal.ball_mm)
    assume(nominal.ok and t.ok)        # a flagged size is no measurement (an undercut stub of a gear)
    assert t.w_k_max < nominal.w_k and t.w_k_min < t.w_k_max
    assert t.m_d_max < nominal.m_d and t.m_d_min < t.m_d_max
    assert t.s_chord_max < nominal.s_chord and t.x_e_sni < t.x_e_sne < x
    assert abs((nominal.w_k - t.w_k_min) - thin * m * math.cos(math.radians(20))) < 1e-11 * m * z


@settings(max_examples=40, deadline=None)
@given(st.floats(0.5, 10), st.integers(30, 300), st.floats(-0.3, 1.0), st.floats(0.001, 0.2))
def test_thinning_a_ring_widens_its_spaces(m, z, x, thin):
    nominal = measured(m, z, x, internal=True)
    t = measured(m, z, x, internal=True, thickness_allowance_mm=-thin * m, ball_mm=nominal.ball_mm)
    assume(nominal.ok and t.ok)
    assert t.m_d_min > nominal.m_d and t.w_k_min > nominal.w_k and t.x_e_sne > x


def test_arrays_broadcast_like_the_scalars():
    z = np.array([[17], [40]])
    x = np.array([0.0, 0.3, 0.6])
    t = tooth_measurements(2, z, x, beta_deg=12, thickness_allowance_mm=-0.05)
    assert np.shape(t.w_k) == (2, 3) and len(t.to_frame()) == 6
    one = tooth_measurements(2, 40, 0.3, beta_deg=12, thickness_allowance_mm=-0.05)
    assert t.w_k[1, 1] == one.w_k and t.m_d[1, 1] == one.m_d and t.k[1, 1] == one.k


def test_every_array_option_broadcasts():
    t = tooth_measurements(2, 40, 0.2, k=[3, 4, 5, 6])
    assert np.allclose(np.diff(t.w_k), math.pi * 2 * math.cos(math.radians(20)), rtol=0, atol=1e-12)
    assert np.shape(tooth_measurements(2, 40, 0.2, ball_mm=[3, 3.5]).m_d) == (2,)
    assert list(tooth_measurements(2, 40, 0.2, beta_deg=20, face_width_mm=[5, 50]).span_ok) == [False, True]
    with pytest.raises(GearDesignError, match="broadcast"):
        tooth_measurements(2, [40, 41], 0.2, k=[3, 4, 5])


def test_pair_measurements_use_the_pair_tips_and_ring():
    p = gd.GearPair(2, 20, 60, 0.3, 0.6, internal=True)
    g1, g2 = p.measurements()
    assert g2.internal and not g1.internal
    assert g2.d_a == pytest.approx(float(p.geometry().da2), abs=1e-12)
    assert p.measurements(gear=1).w_k == g1.w_k


def test_span_does_not_depend_on_the_centre_distance_or_tip_shortening():
    """Trap 10: W_k has no Δy term; shortened and full tips, any mate, the same span and balls."""
    short = gd.GearPair(3, 12, 24, 0.6, 0.36).measurements(gear=1)
    full = gd.GearPair(3, 12, 24, 0.6, 0.36, tip_shortening=False).measurements(gear=1)
    other = gd.GearPair(3, 12, 40, 0.6, 1.0).measurements(gear=1)
    assert short.w_k == full.w_k == other.w_k and short.m_d == full.m_d == other.m_d
    assert short.h_chord < full.h_chord                      # only the tip-referenced chordal height moves


def test_span_flags():
    ring = tooth_measurements(2, 60, 0.3, internal=True)
    assert not ring.span_ok and ring.notes
    narrow = tooth_measurements(3, 40, 0.0, beta_deg=30, face_width_mm=5)
    assert not narrow.span_ok and narrow.face_width_min_mm > 5
    wide = tooth_measurements(3, 40, 0.0, beta_deg=30, face_width_mm=60)
    assert wide.span_ok
    outside = tooth_measurements(2, 40, 0.0, k=15)            # anvils far above the tip
    assert not outside.span_ok
    assert len(repr(wide).splitlines()) <= 15 and wide.to_dict()["status"] == "success"


@pytest.mark.parametrize("kwargs, word", [
    (dict(m=0, z=20), "m"), (dict(m=2, z=2), "z"), (dict(m=2, z=20, x=11), "x"),
    (dict(m=2, z=20, k=20), "k"), (dict(m=2, z=20, ball_mm=-1), "ball_mm"),
    (dict(m=2, z=20, thickness_allowance_mm=(-0.2, -0.1)), "A_sni"),
    (dict(m=2, z=20, thickness_allowance_mm=-5), "thickness_allowance_mm"),
    (dict(m=2, z=20, beta_deg=50), "beta_deg"), (dict(m=2, z=20, internal=1), "internal"),
    (dict(m=2, z=20, rack="x"), "rack"), (dict(m=[1, 2], z=[10, 20, 30]), "broadcast"),
    (dict(m=1, z=3, x=-10), "base circle"), (dict(m=1, z=17, x=3), "pointed"),
    (dict(m=1, z=[17, 40], x=[0.0, 3.0]), "index 1"), (dict(m=2, z=20, ball_mm=1e308), "ball_mm"),
    (dict(m=2, z=20, ball_mm=25.0), "modules"), (dict(m=2, z=20, tip_diameter_mm=1e308), "tip_diameter_mm"),
])
def test_bad_input_is_one_clear_error(kwargs, word):
    with pytest.raises(GearDesignError, match=word):
        tooth_measurements(**kwargs)


# --- issue 36 §1.5: the allowance's sign, the stocked ball ---------------------------------------------------------

@pytest.mark.parametrize("call", [
    lambda: tooth_measurements(3, 24, thickness_allowance_mm=(0.1, 0.05)),
    lambda: tooth_measurements(3, 24, thickness_allowance_mm=0.02),
    lambda: gd.GearPair(3, 20, 40).backlash((0.1, 0.05)),
    lambda: gd.GearPair(3, 20, 40).measurements(gear=1, thickness_allowance_mm=0.05),
])
def test_an_allowance_that_thickens_the_tooth_is_refused_with_the_convention(call):
    # was accepted silently: a tooth thicker than nominal jams the mesh at the nominal centre distance
    with pytest.raises(GearDesignError, match=r"thicker than nominal; .*A_sni <= A_sne <= 0"):
        call()


def test_the_ball_series_is_its_source_s_inch_sizes():
    # the catalogue prints the inch balls to 4 decimals: each is its fraction of an inch (25.4 mm) rounded so
    from geardesign.catalogs import load_catalog

    rows = load_catalog("measuring_balls")
    for d, inch in zip(rows["ball_mm"], rows["inch"]):
        if isinstance(inch, str) and inch:
            num, _, den = inch.partition("/")
            assert abs(d - 25.4 * int(num) / int(den or 1)) <= 0.6e-4, (d, inch)


@pytest.mark.parametrize("m, z, x, beta, internal", [
    (3, 24, 0.4, 20.0, False), (3, 20, 0.3, 0.0, False), (2.5, 64, 0.25, 15.0, True), (4, 17, 0.0, 0.0, False),
    (5, 80, -0.2, 0.0, True),
])
def test_the_default_ball_is_the_nearest_stocked_size_that_measures(m, z, x, beta, internal):
    from geardesign.catalogs.tables import measuring_ball_series

    series = measuring_ball_series()
    t = tooth_measurements(m, z, x, beta_deg=beta, internal=internal)
    exact = tooth_measurements(m, z, x, beta_deg=beta, internal=internal, ball_mm="exact")
    assert t.ball_exact_mm == exact.ball_mm and abs(exact.d_ball - exact.d_y) < 1e-9 * m
    assert t.ball_mm in series and t.ball_ok and t.ball_mm != t.ball_exact_mm
    # every stocked size nearer the exact one fails to measure the gear
    nearer = series[np.abs(series - t.ball_exact_mm) < abs(t.ball_mm - t.ball_exact_mm)]
    assert all(not tooth_measurements(m, z, x, beta_deg=beta, internal=internal, ball_mm=b).ball_ok for b in nearer)
    # and the sizes are those of that ball given by hand
    given_ball = tooth_measurements(m, z, x, beta_deg=beta, internal=internal, ball_mm=t.ball_mm)
    assert (given_ball.m_d, given_ball.d_ball) == (t.m_d, t.d_ball)


def test_a_gear_beyond_the_ball_series_keeps_the_exact_ball_and_says_so():
    t = tooth_measurements(0.3, 24)            # D_M ~0.5 mm: below the smallest stocked ball (1.5 mm)
    assert t.ball_mm == t.ball_exact_mm and any("no stocked ball" in n for n in t.notes)


def test_data_block_is_public():
    from geardesign.gears.data_block import data_block
    assert gd.data_block is data_block and "data_block" in gd.__all__
