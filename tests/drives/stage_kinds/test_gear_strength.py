"""The strength sizing of a gear stage (geardesign.drives.stage_kinds.gear_strength) computes the root
checks only where they decide the answer (contact first over the grid). Against the plain computation
written here: every (m, b) of the grid checked by pair_strength with all three checks, the candidates
that hold all of them sorted smallest module then narrowest width, the closest design (largest smallest
margin) when none holds. The sizing must give the same first candidates, the same chosen (m, b) and its
margins, whatever limits the pair (contact or root) and whether any design holds: a design skipped
that would have held, or a closest design picked from a partial grid, fails here."""
import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import geardesign as gd
from geardesign.drives.stage_kinds.gear import _series
from geardesign.drives.stage_kinds.gear_strength import strength_sizes, strength_sizes_many
from geardesign.gears.strength import Load, pair_strength

TOL = 1e-9
PSI = np.round(np.arange(0.2, 1.0 + 1e-9, 0.05), 10)     # the documented ψ_d = b/d1 range and step
PITCHES_MIN = 3          # and no width below three circular pitches (Shigley's 3p <= b <= 5p)


def _grid(stage, torque_nm, n_rpm, z1, z2, x1, x2):
    """(M, B, {check: margin}) of the whole grid, every design with every check."""
    modules = np.asarray(_series())
    if stage.face_width_mm is None:
        grid = [(m, max(math.ceil(p * m * z1 - 1e-9), math.ceil(PITCHES_MIN * math.pi * m - 1e-9)))
                for m in modules for p in PSI]
    else:
        grid = [(m, stage.face_width_mm) for m in modules]
    M, B = np.array(grid).T
    out = pair_strength(M, z1, z2, x1, x2, load=Load(torque_nm=torque_nm, n_rpm=n_rpm), material1=stage.material,
                        face_width_mm=B)
    return M, B, {"contact_strength": np.minimum(out["S_H1"], out["S_H2"]) / out["S_Hmin"] - 1,
                  "root_strength1": out["S_F1"] / out["S_Fmin"] - 1, "root_strength2": out["S_F2"] / out["S_Fmin"] - 1}


def _plain(stage, torque_nm, n_rpm, z1, z2, x1, x2, tries):
    """(candidates, (m, b, margins)) from the whole grid: the first ``tries`` designs holding every check
    by (m, b), and the first of them or, when none holds, the design of the largest smallest margin."""
    M, B, margins = _grid(stage, torque_nm, n_rpm, z1, z2, x1, x2)
    worst = np.nan_to_num(np.minimum.reduce(list(margins.values())), nan=-np.inf)
    holding = sorted((M[i], B[i], i) for i in range(M.size) if worst[i] >= -TOL)
    i = holding[0][2] if holding else int(np.argmax(worst))
    return [(m, b) for m, b, _ in holding[:tries]], (M[i], B[i], {k: v[i] for k, v in margins.items()})


def _assert_same(got, want):
    assert got[0] == want[0]
    assert got[1][:2] == want[1][:2]
    assert got[1][2] == pytest.approx(want[1][2], rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("material, pair, torque_nm, limited_by", [
    ("42CrMo4", (25, 100, 0.3, 0.2), 2000.0, "contact"),
    ("18CrNiMo7-6", (25, 100, 0.3, 0.2), 2000.0, "root"),
    ("42CrMo4", (17, 40, 0.0, 0.0), 2e8, "nothing holds"),
])
def test_the_sizing_equals_the_whole_grid_checked(material, pair, torque_nm, limited_by):
    stage = gd.GearStage(m=None, material=material)
    for tries in (1, 8):
        want = _plain(stage, torque_nm, 1000.0, *pair, tries)
        _assert_same(strength_sizes(stage, torque_nm, 1000.0, *pair, _series(), TOL, tries), want)
    # each case is what it says: the first design of the grid (by m, then b) that holds contact holds the
    # root checks too, or fails one (the sizing must look past it), or no design holds contact at all
    M, B, margins = _grid(stage, torque_nm, 1000.0, *pair)
    held = np.flatnonzero(margins["contact_strength"] >= -TOL)
    if limited_by == "nothing holds":
        assert held.size == 0 and not want[0]
        return
    first = held[np.lexsort((B[held], M[held]))[0]]
    root_ok = min(margins["root_strength1"][first], margins["root_strength2"][first]) >= -TOL
    assert root_ok == (limited_by == "contact")


@settings(max_examples=25, deadline=None)
@given(z1=st.integers(12, 40), u=st.floats(1.0, 6.0), x1=st.floats(-0.3, 0.8), x2=st.floats(-0.3, 0.8),
       log_torque=st.floats(1.0, 6.0), n_rpm=st.floats(10.0, 3000.0),
       material=st.sampled_from(["42CrMo4", "18CrNiMo7-6", "C45"]), width=st.sampled_from([None, 40.0]),
       tries=st.sampled_from([1, 3, 8]))
def test_several_pairs_sized_at_once_equal_the_whole_grid_checked(z1, u, x1, x2, log_torque, n_rpm, material, width,
                                                                   tries):
    stage = gd.GearStage(m=None, material=material, face_width_mm=width)
    pairs = [(z1, max(z1, round(u * z1)), x1, x2), (z1 + 3, max(z1 + 3, round(u * z1)) + 5, x2, x1)]
    got = strength_sizes_many(stage, 10 ** log_torque, n_rpm, pairs, _series(), TOL, tries)
    for g, p in zip(got, pairs):
        _assert_same(g, _plain(stage, 10 ** log_torque, n_rpm, *p, tries))


# -- a stage with a spectrum (issue 38 §4): the damage checks join the grid. Against the whole grid rated here by
# pair_life under the duty cycle's bins worked by hand (T_i = q_i·T_n at n_n for share_i·L_h hours), margins 1 − D.
def _plain_life(stage, q, share, torque_nm, n_rpm, z1, z2, x1, x2, tries):
    from geardesign.gears.strength.service_life import pair_life

    M, B, _ = _grid(stage, torque_nm, n_rpm, z1, z2, x1, x2)
    out = pair_strength(M, z1, z2, x1, x2, load=Load(torque_nm=torque_nm, n_rpm=n_rpm, life_h=stage.life_h),
                        material1=stage.material, face_width_mm=B)          # the single load for the required life
    single = {"contact_strength": np.minimum(out["S_H1"], out["S_H2"]) / out["S_Hmin"] - 1,
              "root_strength1": out["S_F1"] / out["S_Fmin"] - 1, "root_strength2": out["S_F2"] / out["S_Fmin"] - 1}
    spec = gd.LoadSpectrum.from_bins(np.asarray(q) * torque_nm, n_rpm, share=share, duration_h=stage.life_h)
    D = pair_life(M, z1, z2, x1, x2, spectrum=spec, material1=stage.material, face_width_mm=B, life_h=stage.life_h)
    margins = {**(single if stage.single_load else {}),
               **{f"{k}{g}": 1 - D[f"D_{mode}{g}"] for k, mode in (("pitting_damage", "H"), ("root_damage", "F"))
                  for g in (1, 2)}}
    worst = np.nan_to_num(np.minimum.reduce(list(margins.values())), nan=-np.inf)
    holding = sorted((M[i], B[i], i) for i in range(M.size) if worst[i] >= -TOL)
    i = holding[0][2] if holding else int(np.argmax(worst))
    return [(m, b) for m, b, _ in holding[:tries]], (M[i], B[i], {k: v[i] for k, v in margins.items()}), margins


@pytest.mark.parametrize("single_load", [True, False])
@pytest.mark.parametrize("q, share, torque_nm", [((1.0,), (1.0,), 300.0), ((3.0, 1.0, 0.4), (0.02, 0.5, 0.48), 300.0),
                                                 ((2.0, 1.0), (0.5, 0.5), 5e7)])
def test_the_life_sizing_equals_the_whole_grid_rated(single_load, q, share, torque_nm):
    stage = gd.GearStage(m=None, material="42CrMo4", life_h=20000, spectrum=gd.DutyCycle(q, share),
                         single_load=single_load)
    pair = (20, 71, 0.3, -0.1)
    for tries in (1, 6):
        *want, margins = _plain_life(stage, q, share, torque_nm, 960.0, *pair, tries)
        _assert_same(strength_sizes(stage, torque_nm, 960.0, *pair, _series(), TOL, tries), want)
    if torque_nm > 1e6:
        assert not want[0]          # nothing carries 5e7 N·m: the closest design is found over the whole grid
    elif q[0] > 1:                  # the overload: the damage, not the single load, decides
        worst_single = np.minimum.reduce([margins[k] for k in margins if "strength" in k] or [np.zeros(1)])
        assert np.any((worst_single >= -TOL) & (np.minimum(margins["pitting_damage1"], margins["root_damage1"]) < 0))


def test_a_standard_housing_sizing_finds_the_smallest_module_that_holds():
    # regression: an estimate S_H ∝ m^1.5 from the middle module passed over m = 3.5 for 20/71 at 7.5 kW, 1450 rpm
    # (K_Hβ grows with the width, so S_H falls more slowly towards the small modules) and the stage came out m 5.5.
    # m 3.5 on GOST 2185's a_w 160 mm, b 46 mm, the sized stage's shift window and mating type, holds every check:
    kw = dict(material="42CrMo4", life_h=20000)
    held = gd.GearStage(3.5, 20, 71, face_width_mm=46, center_distance=160, shift_bounds=(-1.2, 1.2), mating_type="B",
                        **kw)
    assert gd.Drive(stages=[held], n_in_rpm=1450, power_kw=7.5).analyse().success
    sized = gd.Drive(stages=[gd.GearStage(None, 20, 71, **kw)], n_in_rpm=1450, power_kw=7.5).analyse()
    assert sized.success and sized.stages[0]["summary"]["m"] <= 3.5
