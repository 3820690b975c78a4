"""Parallel keys. Numbers are recomputed by hand in each test with the formula written out."""
import pytest

from geardesign import key
from geardesign.errors import GearDesignError


def test_seed002_key_recomputed():
    # Seed 002, 1.9.7: d = 60 mm, T = 503.129 N·m, steel 45 key with [σ]cm = 300 MPa, [τ] = 120 MPa.
    # GOST 23360 section for 58 < d <= 65: b x h = 18 x 11, t1 = 7, t2 = 4.4, so k = h - t1 = 4 mm.
    # The strength alone needs l_p >= 2T/(d·k·[σ]) = 13.976 mm, l >= 32 mm (the seed's key);
    # designers take the longest standard length <= hub − 5 mm = 45 mm (Dunaevsky & Lelikov §6.1).
    sel = key.select(60, 503.129, 50, allowable_crush_mpa=300, allowable_shear_mpa=120)
    assert (sel.b_mm, sel.h_mm, sel.t1_mm, sel.t2_mm, sel.length_mm, sel.n_keys) == (18, 11, 7, 4.4, 45, 1)
    sigma = 2 * 503129 / (60 * 4 * (45 - 18))
    tau = 2 * 503129 / (60 * 18 * (45 - 18))
    assert sel.crush_mpa == pytest.approx(sigma) and sel.shear_mpa == pytest.approx(tau)
    assert sel.margin_crush == pytest.approx(1 - sigma / 300)
    assert "longest standard length <= hub 50 mm - 5 mm" in sel.message and "t2 = 4.4 mm" in sel.message
    # the seed's 32 mm key carries the torque too: capacity 300·60·4·14/2000 = 504 N·m >= 503.129
    assert key.capacity(60, 32, 300, 120)["torque_nm"] == pytest.approx(504.0)


def test_seed002_key_slip():
    # The seed prints l > 27.952 mm while stating [σ]cm = 300 MPa and k = h - t1: 27.952 is what
    # 2·503129/(60·4·[σ]) gives with [σ] = 150 MPa, half its own allowable (seeds/README: the
    # allowable stress and effective height do not match the result).
    assert 2 * 503129 / (60 * 4 * 150) == pytest.approx(27.952, abs=1e-3)
    assert 2 * 503129 / (60 * 4 * 300) == pytest.approx(13.976, abs=1e-3)


def test_two_keys_fallback_default_stresses():
    # defaults [σ] = 130, [τ] = 85 MPa; hub 50 -> the 45 mm key (l_p = 27 mm).
    # One key: σ = 2·503000/(60·4·27) = 155.2 > 130. Two keys at 180° (n_eff = 1.5): 103.5 MPa.
    sel = key.select(60, 503, 50)
    assert sel.feasible and sel.n_keys == 2 and sel.length_mm == 45
    assert "two keys" in sel.message
    assert sel.crush_mpa == pytest.approx(2 * 503000 / (60 * 4 * 27 * 1.5))


def test_capacity_worked_example_3net():
    # 3-net.ru worked example (REF key_allowable_stress.csv): d = 40, key 12x8, T = 250 N·m,
    # k = 0.47·h = 3.76 mm, [σ] = 130 MPa -> l_p = 25.57 mm, L = l_p + b = 37.57 mm.
    cap = key.capacity(40, 37.57, 130, 1e4, b_mm=12, h_mm=8, t1_mm=8 - 3.76)
    # T = [σ]·d·k·l_p/2 = 130·40·3.76·25.57/2000
    assert cap["torque_nm"] == pytest.approx(130 * 40 * 3.76 * 25.57 / 2000)
    assert cap["torque_nm"] == pytest.approx(250, rel=1e-3)
    assert cap["governing"] == "crushing"


def test_capacity_two_keys_and_flat_ends():
    # flat ends: l_p = l; two keys: n_eff = 1.5. d = 60, 18x11 (k = 4), l = 40, [σ] = 100:
    # T = 100·60·4·40·1.5/2000 = 720 N·m; shear [τ] = 60: 60·60·18·40·1.5/2000 = 1944 N·m
    cap = key.capacity(60, 40, 100, 60, end="flat", n_keys=2)
    assert cap["torque_nm"] == pytest.approx(720.0)
    assert cap["torque_shear_nm"] == pytest.approx(1944.0)


def test_section_boundaries():
    # GOST 23360-78 / DIN 6885-1: 22 < d <= 30 -> 8x7; 30 < d <= 38 -> 10x8
    assert (key.section(30).b_mm, key.section(30).h_mm) == (8, 7)
    assert (key.section(30.1).b_mm, key.section(30.1).h_mm) == (10, 8)


def test_nothing_fits_is_reported():
    short = key.select(60, 503, 10)
    assert not short.feasible and "fits" in short.message
    heavy = key.select(60, 5000, 50)
    assert not heavy.feasible and "crushing" in heavy.message and heavy.margin_crush < 0


def test_bad_input():
    with pytest.raises(GearDesignError, match=r"d_mm must be in \(6, 500\] mm, got 5"):
        key.select(5, 10, 20)
    with pytest.raises(GearDesignError, match=r"torque_nm must be in \(0, 1e\+09\] N·m, got -5"):
        key.select(60, -5, 50)
    with pytest.raises(GearDesignError, match="end must be one of"):
        key.select(60, 5, 50, end="square")
    with pytest.raises(GearDesignError, match="length_mm must exceed"):
        key.capacity(60, 18)
