"""Sprocket and chain-loop geometry (geardesign.drives.sprocket), against seed 002 and Bhandari's worked
examples (both in docs/references.md) and hand computations written out here."""
import math

import numpy as np
import pytest

from geardesign import chain, sprocket
from tests.drives.chain import SEED


def test_seed002_link_count_slip():
    # The seed counts links with l = (3a + π·d)/t (a three-sided loop around its layout), 30 links,
    # a = 178.57 mm. For the two-sprocket drive the tool designs, L = 2a/t + (z1 + z2)/2 + 0:
    seed_links = (3 * 180 + 3.14 * 132.67) / 31.75
    assert seed_links == pytest.approx(30.13, abs=0.005)  # the seed prints 30.14, a rounding slip; either way 30
    two_sprocket = 2 * 180 / 31.75 + 13
    assert sprocket.link_count(180, 31.75, 13, 13) == pytest.approx(two_sprocket)
    assert sprocket.even_links(two_sprocket) == 24
    # z1 = z2: a = t·(L - z)/2 exactly
    assert sprocket.center_distance_for_links_mm(24, 31.75, 13, 13) == pytest.approx(31.75 * 11 / 2)
    r = chain.design(**SEED, center_distance_mm=180, objective="min_sprocket_diameter")
    assert r.best["links"] == 24 and r.best["center_distance_mm"] == pytest.approx(174.625)


def test_bhandari_14_4_diameters_and_distance():
    # Bhandari Ex. 14.4: 12B, z = 17/34: D1 = 103.673741, D2 = 206.462975, Ln = 105.683 -> 106 at a = 40p,
    # a = 763.496160 mm after a 0.2 % sag allowance
    assert sprocket.pitch_diameter_mm(19.05, 17) == pytest.approx(103.673741, abs=1e-6)
    assert sprocket.pitch_diameter_mm(19.05, 34) == pytest.approx(206.462975, abs=1e-6)
    assert sprocket.link_count(40 * 19.05, 19.05, 17, 34) == pytest.approx(105.683, abs=1e-3)
    assert sprocket.center_distance_for_links_mm(106, 19.05, 17, 34) * 0.998 == pytest.approx(763.496160, abs=1e-5)


def test_pitch_diameter_closes_the_pitch_polygon():
    # The pitch circle is the circumcircle of a regular z-gon of side p (ISO 606 Annex A): its z vertices,
    # placed independently with complex exponentials, lie exactly one pitch apart and close the loop.
    for p, z in [(12.7, 19), (31.75, 13), (19.05, 34), (8.0, 9), (50.8, 120)]:
        r = sprocket.pitch_diameter_mm(p, z) / 2
        vertices = r * np.exp(2j * np.pi * np.arange(z + 1) / z)
        np.testing.assert_allclose(np.abs(np.diff(vertices)), p, rtol=1e-12)


def test_pitch_diameter_published_and_exact():
    # Six teeth: a regular hexagon, d = 2p exactly. ANSI 40 (1/2 in pitch), 19 teeth: U.S. Tsubaki sprocket
    # catalog, No. 40 plain bore sprockets, pitch diameter 3.038 in = 77.16 mm (online.flippingbook.com/view/
    # 303869790/42-43); by hand 12.7/sin(9.4737°) = 12.7/0.1645946 = 77.1593 mm.
    assert sprocket.pitch_diameter_mm(12.7, 6) == pytest.approx(25.4, rel=1e-14)
    assert sprocket.pitch_diameter_mm(12.7, 19) / 25.4 == pytest.approx(3.038, abs=5e-4)
    assert sprocket.pitch_diameter_mm(12.7, 19) == pytest.approx(12.7 / 0.1645946, rel=1e-6)


def test_tip_diameter_of_a_hexagon():
    # z = 6: cot 30° = √3, D_e = p·(0.5 + √3) (GOST 591-69 formula, hand-evaluated)
    assert sprocket.tip_diameter_mm(10.0, 6) == pytest.approx(10.0 * (0.5 + math.sqrt(3)), rel=1e-14)


def test_centre_distance_inverts_the_link_count():
    # L(a) from ISO 10823 clause 6 and a(L) from its quadratic solution must be inverse functions on real
    # layouts (the sprockets' tip circles apart: L(a) turns back below a = p·|z2 - z1|/(2π·√2), inside them)
    a = np.array([400.0, 763.5, 2000.0])
    for p, z1, z2 in [(12.7, 21, 63), (19.05, 17, 34), (31.75, 13, 13), (25.4, 11, 70)]:
        assert a.min() > (sprocket.tip_diameter_mm(p, z1) + sprocket.tip_diameter_mm(p, z2)) / 2
        links = sprocket.link_count(a, p, z1, z2)
        np.testing.assert_allclose(sprocket.center_distance_for_links_mm(links, p, z1, z2), a, rtol=1e-11)


def test_even_links_round_to_nearest_even_ties_up():
    assert sprocket.even_links([23.0, 24.9, 25.0, 25.1, 122.9]).tolist() == [24, 24, 26, 26, 122]


def test_chain_speed_is_one_pitch_per_tooth():
    # per revolution the chain advances z1 pitches: v = z1·p·n/60 in mm/s, /1000 for m/s
    assert sprocket.chain_speed_m_s(13, 31.75, 120) == pytest.approx(13 * 31.75 * 2 / 1000)
