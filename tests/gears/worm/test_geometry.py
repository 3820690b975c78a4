"""Worm pair geometry: the published examples of tests/data/worm_examples.csv, an independent implementation of
every field in mpmath (50 digits) on random designs of every flank form (1e-12), the array and float paths
agreeing, and the centre distance and shift being each other's inverse."""
import csv
import math
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.gears.rack import BasicRack
from geardesign.gears.worm import geometry as wg

DATA = Path(__file__).resolve().parents[2] / "data" / "worm_examples.csv"
ROWS = list(csv.DictReader(DATA.open(encoding="utf-8")))


@pytest.mark.parametrize("row", ROWS, ids=[f"{r['example_id']}:{r['quantity']}" for r in ROWS])
def test_published_examples(row):
    rack = BasicRack(alpha_deg=float(row["alpha_deg"]), ha=float(row["ha_star"]), c=float(row["c_star"]),
                     rho_f=0.0)
    g = wg.worm_geometry(float(row["m_x"]), int(row["z1"]), int(row["z2"]), float(row["q"]), float(row["x2"]),
                         row["flank_form"], rack)
    assert float(g[row["quantity"]]) == pytest.approx(float(row["published_value"]), abs=float(row["abs_tol"]))


def test_every_example_file_row_names_a_field_and_a_source():
    for r in ROWS:
        assert r["quantity"] in wg.WORM_FIELDS and r["source"].strip()
    assert tuple(wg.FIELD_INFO) == wg.WORM_FIELDS


# --- the independent implementation ---------------------------------------------------------------------

mp.mp.dps = 50


def _inv(t):
    return t - mp.atan(t)


def mp_geometry(m_x, z1, z2, q, x2, form, alpha_deg, ha, c, rho_f):
    """Every field from its textbook form (DIN 3975; ISO 21771 rack-and-gear mesh in the mid-plane), in mpmath."""
    m_x, z1, z2, q, x2 = (mp.mpf(v) for v in (m_x, z1, z2, q, x2))
    ha, c, rho_f = mp.mpf(ha), mp.mpf(c), mp.mpf(rho_f)
    a0 = mp.radians(alpha_deg)
    g = mp.atan(z1 / q)
    if form == "ZA":
        ax, an = a0, mp.atan(mp.tan(a0) * mp.cos(g))
    else:
        an, ax = a0, mp.atan(mp.tan(a0) / mp.cos(g))
    d1 = q * m_x
    d2 = z2 * m_x
    da1 = d1 + 2 * ha * m_x
    da2 = d2 + 2 * (ha + x2) * m_x
    rb2 = d2 / 2 * mp.cos(ax)
    ra2 = da2 / 2
    path = mp.sqrt(ra2 ** 2 - rb2 ** 2) - d2 / 2 * mp.sin(ax) + (ha - x2) * m_x / mp.sin(ax)
    s2 = m_x * (mp.pi / 2 + 2 * x2 * mp.tan(ax))
    aa2 = mp.acos(rb2 / ra2)
    sx1 = mp.pi * m_x / 2
    sn1 = sx1 * mp.cos(g)
    zv = z2 / mp.cos(g) ** 3
    mn = m_x * mp.cos(g)
    psi = s2 / (zv * m_x)
    return {
        "m_x": m_x, "z1": z1, "z2": z2, "q": q, "x2": x2, "alpha_x_deg": mp.degrees(ax), "alpha_n_deg": mp.degrees(an),
        "gamma_m_deg": mp.degrees(g), "m_n": mn, "d_m1": d1, "d_a1": da1, "d_f1": d1 - 2 * (ha + c) * m_x,
        "d_w1": d1 + 2 * x2 * m_x, "d_2": d2, "d_a2": da2, "d_e2": da2 + 6 * m_x / (z1 + 2),
        "d_f2": d2 - 2 * (ha + c - x2) * m_x, "a": (d1 + d2) / 2 + x2 * m_x,
        "b_1": mp.pi * m_x * (mp.mpf("4.5") + mp.mpf("0.02") * z2), "b_2": 2 * m_x * mp.sqrt(ha * (q + ha)),
        "p_x": mp.pi * m_x, "p_z": z1 * mp.pi * m_x, "u": z2 / z1,
        "eps_alpha": path / (mp.pi * m_x * mp.cos(ax)),
        "x_min2": ha + c - rho_f * (1 - mp.sin(ax)) - z2 * mp.sin(ax) ** 2 / 2,
        "san1": (sx1 - 2 * ha * m_x * mp.tan(ax)) * mp.cos(mp.atan(z1 * m_x / da1)),
        "sa2": da2 * (s2 / d2 + _inv(mp.tan(ax)) - _inv(mp.tan(aa2))),
        "b_1_min": mp.pi * m_x * (mp.mpf("4.5") + mp.mpf("0.02") * z2), "b_2_max": mp.mpf("0.75") * da1,
        "b_2_h": 2 * m_x * mp.sqrt(ha * (q + ha)),
        "s_x1": sx1, "s_n1": sn1, "s_chord1": sn1, "h_chord1": ha * m_x + (sn1 * mp.sin(g)) ** 2 / (4 * d1),
        "z_v2": zv, "s_chord2": zv * mn * mp.sin(psi), "h_chord2": (ha + x2) * m_x + zv * mn * (1 - mp.cos(psi)) / 2,
    }


def _designs(n, seed):
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        m_x = float(np.exp(rng.uniform(np.log(0.2), np.log(40.0))))
        z1 = int(rng.integers(1, 7))
        z2 = int(rng.integers(20, 400))
        q = float(rng.uniform(6.0, 25.0))
        x2 = float(rng.uniform(-0.9, 0.9))
        form = str(rng.choice(list(wg.FLANK_FORMS)))
        alpha = float(rng.uniform(12.0, 30.0))
        ha = float(rng.uniform(0.8, 1.2))
        c = float(rng.uniform(0.1, 0.35))
        out.append((m_x, z1, z2, q, x2, form, alpha, ha, c))
    return out


def _close(got, ref, scale):
    return abs(got - float(ref)) <= 1e-12 * (abs(float(ref)) + scale)


@pytest.mark.parametrize("design", _designs(60, 7))
def test_against_mpmath_float_path(design):
    m_x, z1, z2, q, x2, form, alpha, ha, c = design
    rack = BasicRack(alpha_deg=alpha, ha=ha, c=c, rho_f=0.0)
    rack = BasicRack(alpha_deg=alpha, ha=ha, c=c, rho_f=0.5 * rack.rho_f_max)
    got = wg.worm_geometry_float(m_x, z1, z2, q, x2, form, rack)
    ref = mp_geometry(m_x, z1, z2, q, x2, form, alpha, ha, c, rack.rho_f)
    bad = {k: (got[k], float(ref[k])) for k in wg.WORM_FIELDS if not _close(got[k], ref[k], m_x)}
    assert not bad


def test_against_mpmath_array_path_every_form():
    designs = _designs(80, 11)
    for form in wg.FLANK_FORMS:
        cols = list(zip(*designs))
        rack = BasicRack(alpha_deg=20.0, ha=1.0, c=0.2, rho_f=0.3)
        got = wg.worm_geometry(np.array(cols[0]), np.array(cols[1]), np.array(cols[2]), np.array(cols[3]),
                               np.array(cols[4]), form, rack)
        for i, (m_x, z1, z2, q, x2, *_rest) in enumerate(designs):
            ref = mp_geometry(m_x, z1, z2, q, x2, form, 20.0, 1.0, 0.2, 0.3)
            bad = {k: (float(got[k][i]), float(ref[k])) for k in wg.WORM_FIELDS
                   if not _close(float(got[k][i]), ref[k], m_x)}
            assert not bad, (form, i)


def test_float_and_array_paths_agree_and_lengths_given():
    g1 = wg.worm_geometry_float(4.0, 2, 41, 10.0, 0.3, "ZI", BasicRack(), 90.0, 30.0)
    g2 = wg.worm_geometry(4.0, 2, 41, 10.0, 0.3, "ZI", BasicRack(), 90.0, 30.0)
    for k in wg.WORM_FIELDS:
        assert g1[k] == pytest.approx(float(g2[k]), rel=1e-15, abs=1e-15)
    assert g1["b_1"] == 90.0 and g1["b_2"] == 30.0


def test_flank_forms_differ_only_by_the_section_of_the_pressure_angle():
    za = wg.worm_geometry_float(5.0, 3, 40, 8.0, 0.0, "ZA")
    zn = wg.worm_geometry_float(5.0, 3, 40, 8.0, 0.0, "ZN")
    assert za["alpha_x_deg"] == 20.0 and zn["alpha_n_deg"] == 20.0
    assert zn["alpha_x_deg"] > 20.0 > za["alpha_n_deg"]
    # tan α_n = tan α_x cos γ in both
    for g in (za, zn):
        assert math.tan(math.radians(g["alpha_n_deg"])) == pytest.approx(
            math.tan(math.radians(g["alpha_x_deg"])) * math.cos(math.radians(g["gamma_m_deg"])), rel=1e-14)


@settings(max_examples=200, deadline=None)
@given(a=st.floats(30.0, 600.0), m_x=st.floats(0.5, 20.0), z2=st.integers(20, 120), q=st.floats(6.0, 25.0))
def test_shift_for_a_center_distance_reproduces_it(a, m_x, z2, q):
    x2 = wg.x2_from_center_distance(a, m_x, z2, q)
    assert wg.center_distance(m_x, z2, q, x2) == pytest.approx(a, rel=1e-14)
    assert float(wg.worm_geometry(m_x, 1, z2, q, x2, validate=False)["a"]) == pytest.approx(a, rel=1e-13)


def test_contact_ratio_and_wheel_tip_fall_as_x2_rises():
    x2 = np.linspace(-0.8, 0.8, 161)
    g = wg.worm_geometry(3.0, 2, 40, 10.0, x2)
    assert np.all(np.diff(g["eps_alpha"]) < 0) and np.all(np.diff(g["sa2"]) < 0)


def test_a_wheel_that_does_not_exist_is_refused_or_nan_unvalidated():
    from geardesign.errors import GearDesignError

    # the throat inside the base circle: x2 far below −h_a* − z2(1 − cos α)/2 = −1.60
    with pytest.raises(GearDesignError, match=r"x2 = -2 \(at index 1\) is too small for z2 = 20: the wheel's throat"):
        wg.worm_geometry(1.0, 1, 20, 10.0, [0.0, -2.0])
    g = wg.worm_geometry(1.0, 1, 20, 10.0, -2.0, validate=False)
    assert math.isnan(float(g["sa2"])) and math.isnan(float(g["eps_alpha"]))


@pytest.mark.parametrize("kwargs,words", [
    (dict(m_x=[1.0, -1.0]), ["m_x must be > 0 mm", "-1.0 (at index 1)"]),
    (dict(z1=[1, 11]), ["z1 must be a whole number in [1, 10]", "11"]),
    (dict(z2=40.5), ["z2 must be a whole number", "40.5"]),
    (dict(q=2.0), ["q must be in (2.5, 100]", "2.0"]),
    (dict(x2=float("nan")), ["x2 must be finite"]),
    (dict(worm_length_mm=0.0), ["worm_length_mm must be in"]),
    (dict(m_x=[1.0, 2.0], z1=[1, 2, 3]), ["do not broadcast"]),
])
def test_bad_array_inputs_are_refused_by_name(kwargs, words):
    from geardesign.errors import GearDesignError

    args = dict(m_x=1.0, z1=1, z2=40, q=10.0, x2=0.0)
    args.update(kwargs)
    with pytest.raises(GearDesignError) as info:
        wg.worm_geometry(**args)
    for w in words:
        assert w in str(info.value), (w, str(info.value))


def test_bad_flank_form_is_refused_by_name():
    from geardesign.errors import GearDesignError

    with pytest.raises(GearDesignError, match="flank_form must be one of"):
        wg.worm_geometry(1.0, 1, 40, 10.0, 0.0, "ZX")
