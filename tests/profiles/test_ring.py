"""The ring gear as its shaper cutter generates it (profiles/ring.py) against independent models of it.

The profile comes from rolling the cutter in the ring and the law of gearing; the tests compare it with
the textbook ring involute (KHK / SDP-SI *Elements of Metric Gear Technology*, Table 5-1: s2 =
m(π/2 − 2 x2 tan α), s_y = d_y(s2/d2 − inv α + inv α_y)), with the 50-digit pair reference, with a
zero-backlash cutting distance solved here in mpmath from the tooth thicknesses, with the checks'
form limit ρ_F2 and with a brute-force sweep of the cutter's own rack-generated outline."""
import math

import mpmath as mp
import numpy as np
import pytest
from matplotlib.path import Path

import geardesign as gd
from geardesign.gears.ring import cutting_mesh
from geardesign.profiles.export import turned
from geardesign.profiles.ring import RIM_MODULES, ring_profile
from tests.reference_mp import pair_reference

# (m, z2, x2, z0 or None for the default cutter, beta_deg): rings whose involute reaches their tip
CLEAN = [(2.0, 60, 0.6, None, 0.0), (4.0, 90, 0.3, None, 0.0), (1.0, 80, 0.0, 40, 0.0), (3.0, 45, 1.0, 20, 0.0),
         (2.5, 71, 0.4, None, 20.0), (2.0, 55, -0.2, 25, 35.0)]


def _alpha_t(beta_deg):
    return math.atan(math.tan(math.radians(20.0)) / math.cos(math.radians(beta_deg)))


def _ring(m, z, x, z0, beta, points=200):
    return ring_profile(m, z, x, gd.ShaperCutter(z0=z0), points=points, beta_deg=beta)


@pytest.mark.parametrize("m, z, x, z0, beta", CLEAN)
def test_ring_flank_is_the_textbook_ring_involute(m, z, x, z0, beta):
    """The flank's polar angle from the tooth's centre line is s2/d2 − inv α_t + inv α_y (transverse)."""
    p = _ring(m, z, x, z0, beta)
    a_t, cb = _alpha_t(beta), math.cos(math.radians(beta))
    r_b = m / cb * z / 2 * math.cos(a_t)
    sel = p.segment == "involute"
    r = np.hypot(p.x_mm[sel], p.y_mm[sel])
    eta = np.arctan2(p.x_mm[sel], p.y_mm[sel])
    a_y = np.arccos(r_b / r)
    half = math.pi / (2 * z) - 2 * x * math.tan(math.radians(20.0)) / z - (math.tan(a_t) - a_t) + (np.tan(a_y) - a_y)
    assert np.max(np.abs(eta - half) * r) <= 1e-9 * m
    assert not p.cutting_interference


@pytest.mark.parametrize("m, z, x, z0, beta", CLEAN)
def test_ring_tip_thickness_is_the_reference_s_a2(m, z, x, z0, beta):
    """s_a2 measured on the generated profile equals the 50-digit reference's (any pinion: 17 teeth)."""
    ref, why = pair_reference(m, 17, z, 0.2, x, beta_deg=beta, internal=True)
    assert ref is not None, why
    p = ring_profile(m, z, x, gd.ShaperCutter(z0=z0), tip_diameter_mm=float(ref["da2"]), beta_deg=beta)
    assert p.tip_thickness_mm == pytest.approx(float(ref["sa2"]), abs=1e-9 * m)
    g = gd.GearPair(m, 17, z, 0.2, x, beta_deg=beta, internal=True).geometry()
    assert p.tip_thickness_mm == pytest.approx(g.sa2, abs=1e-9 * m)


def _cutting_distance_mp(m, z, x, z0, x0, beta):
    """a_w0 of the cutter in the ring at zero backlash, solved in mpmath from the thicknesses: the
    cutter's tooth fills the ring's space on their operating circles, s_w0 + s_w2 = p_w, with
    s_y = d_y(s0/d0 + inv α − inv α_y) for the cutter and d_y(s2/d2 − inv α + inv α_y) for the ring."""
    mp.mp.dps = 50
    cb = mp.cos(mp.radians(beta))
    m_t, a_t = mp.mpf(m) / cb, mp.atan(mp.tan(mp.radians(20)) / cb)
    inv = lambda a: mp.tan(a) - a   # noqa: E731
    # transverse thicknesses: the shift x·m_n moves a transverse flank of slope tan α_t
    s0 = (m_t * mp.pi / 2 + 2 * x0 * m * mp.tan(a_t)) / (m_t * z0)      # s0/d0 (x0 normal)
    s2 = (m_t * mp.pi / 2 - 2 * x * m * mp.tan(a_t)) / (m_t * z)         # s2/d2

    def backlash(a_w):
        d_w0, d_w2 = m_t * z0 * mp.cos(a_t) / mp.cos(a_w), m_t * z * mp.cos(a_t) / mp.cos(a_w)
        return d_w0 * (s0 + inv(a_t) - inv(a_w)) + d_w2 * (s2 - inv(a_t) + inv(a_w)) - mp.pi * d_w0 / z0

    a_w = mp.findroot(backlash, a_t + mp.mpf("0.05"))
    return m_t * (z - z0) * mp.cos(a_t) / (2 * mp.cos(a_w))


@pytest.mark.parametrize("m, z, x, z0, beta", CLEAN + [(3.0, 24, 0.5, 8, 0.0), (3.0, 24, 0.5, 12, 0.0)])
def test_ring_root_is_the_cutters_not_the_rack_equivalent(m, z, x, z0, beta):
    """The generated root radius is a_w0 + r_a0 with a_w0 solved here from zero backlash. The geometry's
    d_f2 = d2 + 2(h_a* + c* + x2)m is the rack-equivalent root: equal only where the cutting
    pressure angle is α (x2 = x0)."""
    p = _ring(m, z, x, z0, beta, points=60)
    cb = math.cos(math.radians(beta))
    a_w0 = float(_cutting_distance_mp(m, z, x, p.z0, 0.0, beta))
    r_a0 = m / cb * p.z0 / 2 + 1.25 * m
    assert p.r_root_mm == pytest.approx(a_w0 + r_a0, abs=1e-9 * m)
    assert p.a_w0_mm == pytest.approx(a_w0, abs=1e-9 * m)
    df2 = gd.GearPair(m, 17, z, 0.0, x, beta_deg=beta, internal=True).geometry().df2
    if x == 0.0:
        assert 2 * p.r_root_mm == pytest.approx(df2, abs=1e-9 * m)
    else:
        assert abs(2 * p.r_root_mm - df2) > 1e-3 * m
    assert p.rim_diameter_mm == pytest.approx(2 * p.r_root_mm + 2 * RIM_MODULES * m, rel=1e-15)


@pytest.mark.parametrize("m, z, x, z0, beta", CLEAN)
def test_ring_involute_starts_at_the_checks_form_limit(m, z, x, z0, beta):
    """The fillet the cutter's tip corner sweeps hands over to the involute at ρ_F2 = ρ_a0 + a_w0 sin α_w0,
    the form limit the ring_interference check uses (gears/ring.py cutting_mesh)."""
    p = _ring(m, z, x, z0, beta)
    cb, a_t = math.cos(math.radians(beta)), _alpha_t(beta)
    cutter = gd.ShaperCutter(z0=z0)
    c = cutting_mesh(m, z, x, m * z, cutter, a_t, math.tan(math.radians(20.0)), cb)
    r_b = m / cb * z / 2 * math.cos(a_t)
    assert p.r_form_mm == pytest.approx(math.hypot(r_b, float(c.rho_form2)), abs=1e-9 * m)


def _cutter_outline(m, z0, n=80):
    """The spur cutter (x0 = 0, h_a0* = 1.25) written out here: the involute of its base circle,
    ψ(r) = π/(2 z0) + inv α − inv α_r, radial below the base circle down to the root r0 − 1.25 m, and
    its tip and root arcs; a closed polygon, clockwise."""
    a = math.radians(20.0)
    r0 = m * z0 / 2
    r_b, r_a, r_f = r0 * math.cos(a), r0 + 1.25 * m, r0 - 1.25 * m
    r = np.linspace(r_f, r_a, n)
    a_r = np.arccos(np.minimum(r_b / r, 1.0))
    psi = math.pi / (2 * z0) + (math.tan(a) - a) - (np.tan(a_r) - a_r)
    tip = np.linspace(-psi[-1], psi[-1], n // 4)
    xs, ys = [], []
    for k in range(z0):
        c = 2 * math.pi * k / z0
        gap = np.linspace(psi[0], 2 * math.pi / z0 - psi[0], n // 4)[1:-1]
        ang = np.concatenate([c - psi, c + tip, c + psi[::-1], c + gap])
        rad = np.concatenate([r, np.full(tip.size, r_a), r[::-1], np.full(gap.size, r_f)])
        xs.append(rad * np.sin(ang))
        ys.append(rad * np.cos(ang))
    return np.concatenate(xs), np.concatenate(ys)


def _sweep(p, step_rad=3e-4):
    """The ring's outline points (generation frame) tested against the cutter's outline written out in
    :func:`_cutter_outline` (not the ring module's cutter model) at positions of the cutting roll
    ``step_rad`` apart: (material side) points pushed 1e-3·m into the ring's material are inside no
    cutter position; (space side) points pushed 1e-3·m into the space are inside some position."""
    cx, cy = _cutter_outline(p.m, p.z0)
    r_a0 = p.m * p.z0 / 2 + 1.25 * p.m
    ox, oy = p.outline()
    seg = np.concatenate([p.segment, p.segment[-2::-1]])
    # the generated parts, less each run's end points (where a normal from neighbours would mix two parts)
    keep = np.isin(seg, ("fillet", "involute", "interference", "root"))
    keep[1:-1] &= (seg[:-2] == seg[1:-1]) & (seg[2:] == seg[1:-1])
    keep[[0, -1]] = False
    gx, gy = turned(ox, oy, math.pi / p.z)          # a space on +y, as the cutter cut it
    t = np.gradient(np.column_stack([gx, gy]), axis=0)[keep]
    pts = np.column_stack([gx, gy])[keep]
    # the outline runs clockwise about the ring's centre with the material on its left: the space on the right
    n = np.column_stack([t[:, 1], -t[:, 0]]) / np.hypot(t[:, 0], t[:, 1])[:, None]
    # every roll where the cutter's tip circle reaches the ring's tip circle, about both spaces beside the tooth
    r_a2 = float(np.min(np.hypot(ox, oy)))
    span = 2.0 * math.pi / p.z + math.acos((r_a2 ** 2 + p.a_w0_mm ** 2 - r_a0 ** 2) / (2 * r_a2 * p.a_w0_mm))
    steps = int(span / step_rad)
    into_material, into_space = np.zeros(len(pts), bool), np.zeros(len(pts), bool)
    for phi2 in np.linspace(-span, span, steps):
        fx, fy = turned(cx, cy, phi2 * p.z / p.z0)
        rx, ry = turned(fx, fy + p.a_w0_mm, -phi2)
        path = Path(np.column_stack([rx, ry]))
        into_material |= path.contains_points(pts - 1e-3 * p.m * n)
        into_space |= path.contains_points(pts + 1e-3 * p.m * n)
    return into_material, into_space


@pytest.mark.slow
@pytest.mark.parametrize("m, z, x, z0", [(3.0, 24, 0.5, 8), (3.0, 36, 0.3, 12)])
def test_ring_is_what_the_cutters_outline_leaves(m, z, x, z0):
    """Independent of the generation code: the cutter's own outline, swept, removes the space side of
    every generated point and none of the material side — also on KHK's 24-tooth ring cut by an
    8-tooth cutter, whose tip lies past the cutting mesh's interference point (the flank there is not
    the involute: what the cutter leaves)."""
    p = _ring(m, z, x, z0, 0.0, points=60)
    # both rings' tips lie past the cutting mesh's interference point N0 (KHK eq. (5-4) with the cutter
    # as pinion fails): ρ_a2 < N0N2 = a_w0 sin α_w0, with a_w0 cos α_w0 = r_b2 − r_b0
    r_b2, r_b0, r_a2 = m * z / 2 * math.cos(math.radians(20)), m * z0 / 2 * math.cos(math.radians(20)), m * z / 2 - (1 - x) * m
    assert math.sqrt(r_a2 ** 2 - r_b2 ** 2) < math.sqrt(p.a_w0_mm ** 2 - (r_b2 - r_b0) ** 2)
    assert p.cutting_interference
    into_material, into_space = _sweep(p)
    assert not into_material.any()
    assert into_space.all()


@pytest.mark.slow
def test_ring_annulus_area_and_export(tmp_path):
    """The ring's file holds the toothed bore and the rim; the annulus between them has the area of the
    rim circle less the bore (each outline's area reproduced after re-reading, 1e-9 relative)."""
    from geardesign.profiles.export import outline_area_mm2

    from .test_mesh import _read

    p = ring_profile(2.0, 60, 0.6, points=80)
    for suffix in (".svg", ".dxf", ".csv"):
        path = getattr(p, f"to_{suffix[1:]}")(tmp_path / f"ring{suffix}")
        read = _read(path)
        assert sorted(read) == ["ring", "ring_rim"]
        (_, bx, by), (_, rx, ry) = p.outlines()
        assert outline_area_mm2(*read["ring"]) == pytest.approx(outline_area_mm2(bx, by), rel=1e-9)
        assert outline_area_mm2(*read["ring_rim"]) == pytest.approx(outline_area_mm2(rx, ry), rel=1e-9)
    r = p.rim_diameter_mm / 2
    # the rim polygon within 1e-4·m of its circle: area short by at most 2π r·1e-4·m
    assert 0 < math.pi * r * r - outline_area_mm2(rx, ry) <= 2 * math.pi * r * 1e-4 * p.m


def test_ring_refusals_name_the_input():
    with pytest.raises(gd.GearDesignError, match="z0 = 60 teeth, the ring z = 60"):
        ring_profile(2.0, 60, 0.0, gd.ShaperCutter(z0=60))
    with pytest.raises(gd.GearDesignError, match="inside its base circle"):
        ring_profile(2.0, 60, 0.0, tip_diameter_mm=110.0)
    with pytest.raises(gd.GearDesignError, match="cutter must be a geardesign.ShaperCutter"):
        ring_profile(2.0, 60, 0.0, cutter=12)
    with pytest.raises(gd.GearDesignError, match="beta_deg"):
        ring_profile(2.0, 60, 0.0, beta_deg=60.0)


def test_a_cutter_whose_tip_is_inside_its_base_circle_is_refused_by_name():
    """Issue 29 §3.6: 'math domain error'. z0 = 8, x0 = −0.9, h_a0* = 0.5 at m = 2: d_a0 = m (z0 + 2(h_a0* + x0))
    = 14.4 mm, d_b0 = m z0 cos 20° = 15.035 mm; no involute at the cutter's tip."""
    import math
    d_a0, d_b0 = 2 * (8 + 2 * (0.5 - 0.9)), 2 * 8 * math.cos(math.radians(20))
    assert d_a0 < d_b0
    with pytest.raises(gd.GearDesignError) as info:
        gd.ring_profile(2, 16, 0.06, cutter=gd.ShaperCutter(z0=8, x0=-0.9, ha0=0.5))
    text = str(info.value)
    assert "z0 = 8" in text and f"{d_a0:.6g}" in text and f"{d_b0:.6g}" in text and "\n" not in text
