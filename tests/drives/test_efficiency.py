"""Bearing friction (SKF model) and a stage's efficiency (geardesign.drives.bearing_friction, .efficiency):
an independent implementation of the SKF model on random cases, and the properties issue 37 asks for."""
from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from geardesign.drives.bearing import bearing_catalog
from geardesign.drives.bearing_friction import SKF_CONSTANTS, bearing_friction, frictional_power_w
from geardesign.drives.efficiency import BearingLoad, stage_efficiency
from geardesign.errors import GearDesignError
from geardesign.gears.efficiency import Lubricant
from geardesign.gears.pair import GearPair
from geardesign.gears.strength import Load


def _skf_reference(R1, R2, S1, S2, d, D, C0, Fr, Fa, n, nu, K_rs, mu_bl=0.12, mu_ehl=0.05):
    """The SKF model written out again from its equations (module docstring's source), in plain math."""
    dm = 0.5 * (d + D)
    phi_ish = 1 / (1 + 1.84e-9 * (n * dm) ** 1.28 * nu ** 0.64)
    phi_rs = math.exp(-K_rs * nu * n * (d + D) * math.sqrt(3.1 / (2 * (D - d))))
    if Fa == 0:
        G_rr = R1 * dm ** 1.96 * Fr ** 0.54
        G_sl = S1 * dm ** -0.26 * Fr ** (5 / 3)
    else:
        aF = math.radians(24.6 * (Fa / C0) ** 0.24)
        G_rr = R1 * dm ** 1.96 * (Fr + R2 / math.sin(aF) * Fa) ** 0.54
        G_sl = S1 * dm ** -0.145 * (Fr ** 5 + S2 * dm ** 1.5 / math.sin(aF) * Fa ** 4) ** (1 / 3)
    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    mu_sl = phi_bl * mu_bl + (1 - phi_bl) * mu_ehl
    return phi_ish * phi_rs * G_rr * (nu * n) ** 0.6 + G_sl * mu_sl


def test_skf_model_against_an_independent_implementation():
    rows = bearing_catalog(["62", "63"])
    rng = np.random.default_rng(37)
    for _ in range(60):
        row = rows.iloc[int(rng.integers(len(rows)))]
        Fr = float(rng.uniform(10, 20000))
        Fa = float(rng.choice([0.0, rng.uniform(10, 3000)]))
        n, nu = float(rng.uniform(10, 6000)), float(rng.uniform(5, 500))
        lub = str(rng.choice(["oil_jet", "grease"]))
        got = bearing_friction(row["designation"], Fr, Fa, n, nu, lub)
        ref = _skf_reference(*SKF_CONSTANTS[row["series"]], row["d_mm"], row["D_mm"], 1000 * row["C0_kn"], Fr, Fa, n,
                             nu, {"oil_jet": 3e-8, "grease": 6e-8}[lub])
        assert got.M_nmm == pytest.approx(ref, rel=1e-9)
        assert got.power_loss_w == pytest.approx(ref * n * 2 * math.pi / 60 / 1000, rel=1e-12)


def test_frictional_power_is_skf_rounded_factor():
    # SKF 17000/1 EN p. 132: P_loss = 1.05e-4 M n (W, N·mm, r/min) — 2π/60/1000 = 1.0472e-4
    assert float(frictional_power_w(1.0, 1.0)) == pytest.approx(1.05e-4, rel=0.003)


def test_bearing_friction_grows_with_load_and_series():
    light = bearing_friction("6208", 1000.0, 0.0, 1500.0, 68.0)
    heavy = bearing_friction("6208", 4000.0, 0.0, 1500.0, 68.0)
    assert heavy.M_nmm > light.M_nmm
    assert bearing_friction("6308", 1000.0, 0.0, 1500.0, 68.0).M_nmm > light.M_nmm * 0.9
    assert bearing_friction("6208", 1000.0, 500.0, 1500.0, 68.0).M_nmm > light.M_nmm


def test_bearing_friction_refuses_what_it_does_not_model():
    with pytest.raises(GearDesignError, match="deep groove ball bearing of series 62, 63"):
        bearing_friction("NU208", 1000.0, 0.0, 1500.0, 68.0)
    with pytest.raises(GearDesignError, match="lubrication"):
        bearing_friction("6208", 1000.0, 0.0, 1500.0, 68.0, lubrication="mist")
    with pytest.raises(GearDesignError, match="n_rpm"):
        bearing_friction("6208", 1000.0, 0.0, 0.0, 68.0)
    with pytest.raises(GearDesignError, match="Fr_n and Fa_n"):
        bearing_friction("6208", 0.0, 0.0, 1500.0, 68.0)


PAIR = GearPair(3.0, 21, 64, 0.3, 0.2, face_width_mm=40)     # an ordinary reducer stage, u ≈ 3


def _stage(torque_nm, oil, t=60.0, **kw):
    force = 2000.0 * torque_nm / PAIR.geometry().dw1          # tangential force, shared by the two bearings
    bearings = [BearingLoad("6307", 1, force / 2), BearingLoad("6307", 1, force / 2),
                BearingLoad("6310", 2, force / 2), BearingLoad("6310", 2, force / 2)]
    return stage_efficiency(PAIR, Load(torque_nm=torque_nm, n_rpm=1450), oil, t, bearings=bearings, **kw)


OILS = [Lubricant(32, 5.4), Lubricant(100, 11.1), Lubricant(320, 24), Lubricant(680, 40)]


def test_efficiency_falls_as_the_oil_thickens_at_low_load():
    eta = [_stage(10.0, oil).efficiency for oil in OILS]
    assert all(a > b for a, b in itertools.pairwise(eta)), eta


def test_a_larger_load_raises_the_load_dependent_loss():
    losses = [_stage(t, OILS[1]).mesh_loss_w for t in (20.0, 100.0, 400.0)]
    assert losses[0] < losses[1] < losses[2]
    # μ_mZ ∝ (F/b)^0.2 at fixed speed: P_VZP ∝ T^1.2
    assert losses[2] / losses[1] == pytest.approx(4.0 ** 1.2, rel=1e-9)


def test_mesh_efficiency_of_a_usual_spur_pair_is_about_0_99():
    r = _stage(400.0, OILS[1], Ra_um=0.5)
    assert 0.985 < r.mesh_efficiency < 0.995
    assert r.efficiency < r.mesh_efficiency
    assert r.loss_w == pytest.approx(r.mesh_loss_w + r.no_load_loss_w + r.bearing_loss_w, rel=1e-15)
    assert r.heat_w == r.loss_w
    assert r.to_frame()["power_w"].sum() == pytest.approx(r.loss_w, rel=1e-12)


def test_a_given_no_load_loss_is_counted_and_the_load_may_be_on_gear_2():
    base = _stage(100.0, OILS[1])
    more = _stage(100.0, OILS[1], no_load_loss_w=50.0)
    assert more.loss_w - base.loss_w == pytest.approx(50.0, rel=1e-12)
    on2 = stage_efficiency(PAIR, Load(torque_nm=100.0 * 64 / 21, n_rpm=1450 * 21 / 64, on_gear=2), OILS[1], 60.0)
    alone = stage_efficiency(PAIR, Load(torque_nm=100.0, n_rpm=1450), OILS[1], 60.0)
    assert on2.efficiency == pytest.approx(alone.efficiency, rel=1e-12)


def test_stage_efficiency_bad_inputs():
    with pytest.raises(GearDesignError, match="load"):
        stage_efficiency(PAIR, 100.0, OILS[1], 60.0)
    with pytest.raises(GearDesignError, match="lubricant"):
        stage_efficiency(PAIR, Load(torque_nm=100.0, n_rpm=1450), 68, 60.0)
    with pytest.raises(GearDesignError, match="shaft"):
        BearingLoad("6307", 3, 100.0)
    with pytest.raises(GearDesignError, match="no_load_loss_w"):
        _stage(100.0, OILS[1], no_load_loss_w=-1.0)
