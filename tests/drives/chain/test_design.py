"""Roller-chain drive design: choice, layout and result (geardesign.drives.chain.design). Every number is
recomputed by hand here (formula written out) or taken from a cited source: seed 002 (the brake test stand
course work) and Bhandari's worked examples (both in docs/references.md), or the catalog tables."""
import json
import math

import numpy as np
import pytest

from geardesign import chain, sprocket
from tests.drives.chain import SEED


def test_seed002_choice_by_objective():
    # The seed picks the smallest pitch that passes: 31.75 mm with two strands (its estimate
    # 30.35 mm) against 38.1 mm with one (estimate 36.23 mm). That is the smallest-sprocket choice.
    small = chain.design(**SEED, objective="min_sprocket_diameter")
    assert small.best["designation"] == "2PR-31,75-177"
    # Lightest per metre: PR-38.1 (5.5 kg/m) beats 2PR-31.75 (7.3 kg/m, GOST 13568-75 masses);
    # its pressure F·K_e/A with A = 395 mm2 and v = 13·38.1·120/60000 stays under 29 MPa
    light = chain.design(**SEED)
    assert light.best["designation"] == "PR-38,1-127"
    v = 13 * 38.1 * 120 / 60000
    assert 380 * 2 * math.pi * 2 / v * 2.148 / 395 < 29


def test_seed002_sprocket_geometry():
    # seed 002, 1.9.6: d = t/sin(180/z) = 132.67, De = t(0.5 + ctg(180/z)) = 144.69, Di = d - 2(0.5025·d1 + 0.05) = 113.43
    r = chain.design(**SEED, objective="min_sprocket_diameter")
    b = r.best
    assert b["sprocket1_pitch_diameter_mm"] == pytest.approx(132.67, abs=0.005)
    assert b["sprocket1_tip_diameter_mm"] == pytest.approx(144.69, abs=0.005)
    assert b["sprocket1_root_diameter_mm"] == pytest.approx(113.43, abs=0.015)


def test_bhandari_14_3_links_and_centre_distance():
    # Bhandari Ex. 14.3: p = 12.7, z1 = 21, z2 = 63, a = 500 -> Ln = 121.875 -> 122, a = 500.804717 mm; chain 08A
    r = chain.design(power_kw=5, n1_rpm=1400, ratio=3, z1=21, k_e=1.3, catalog="iso606a", strands=(1,),
                     center_distance_mm=500, method="power_rating")
    row = r.candidates[r.candidates["designation"] == "08A"].iloc[0]
    assert row["links"] == 122
    assert row["center_distance_mm"] == pytest.approx(500.804717, abs=1e-6)
    assert r.best["designation"] == "08A"


def test_no_candidate_says_what_stops_each_family():
    r = chain.design(torque_nm=20000, n1_rpm=120, ratio=1, z1=13, k_e=2.148, allowable_pressure_mpa=29, strands=(1, 2))
    assert not r.success and r.best is None
    assert "no candidate passes" in r.message
    assert set(r.blocking["designation"]) == set(r.candidates["designation"])
    assert (r.blocking["limiting_check"] == "pressure").all() and (r.blocking["min_margin"] < 0).all()


def test_result_object():
    r = chain.design(**SEED)
    text = repr(r)
    assert "PR-38,1-127" in text and "margins" in text
    d = r.to_dict()
    json.dumps(d)
    assert d["best"]["designation"] == "PR-38,1-127" and d["n_candidates"] == len(r.to_frame())
    for col in ("designation", "pitch_mm", "strands", "z1", "z2", "links", "center_distance_mm", "speed_m_s",
                "force_n", "pressure_mpa", "allowable_pressure_mpa", "safety_factor", "allowable_safety_factor",
                "mass_kg_m", "feasible"):
        assert col in r.candidates.columns
    # links are even and the centre distance is exact for them
    c = r.candidates
    assert (c["links"] % 2 == 0).all()
    np.testing.assert_allclose(sprocket.link_count(c["center_distance_mm"], c["pitch_mm"], c["z1"], c["z2"]), c["links"])


def test_no_warning_escapes_when_a_strand_count_has_no_allowable_pressure_at_the_speed():
    """Issue 29 §3.13: 'All-NaN slice encountered' from the pitch estimate at 2850.8 rpm, where the
    hinge-pressure table gives no [p] for these pitches."""
    import warnings
    import geardesign as gd
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        d = gd.chain.design(power_kw=80.152, n1_rpm=2850.8, ratio=3.673)
    assert len(d.candidates) > 0


def test_a_vanishing_centre_distance_is_refused_without_a_warning():
    """Found by the project's fuzzing: center_distance_mm = 5e-324 overflowed a division (a warning) before
    it was refused; the range starts at 1 mm (CENTER_DISTANCE_MIN_MM) and is checked first."""
    import warnings

    import geardesign as gd
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(gd.GearDesignError, match=r"center_distance_mm must be in \[1, 100000\] mm, got 5e-324"):
            gd.chain.design(torque_nm=598.23, n1_rpm=1353.8, ratio=2.98, catalog="gost13568",
                            method="hinge_pressure", center_distance_mm=5e-324)
