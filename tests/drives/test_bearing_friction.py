"""Bearing friction after the SKF model (geardesign.drives.bearing_friction): an independent implementation on
random cases, and what it refuses."""
from __future__ import annotations

import math

import numpy as np
import pytest

from geardesign.drives.bearing import bearing_catalog
from geardesign.drives.bearing_friction import SKF_CONSTANTS, bearing_friction, frictional_power_w
from geardesign.errors import GearDesignError


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
    with pytest.raises(GearDesignError, match="F_r_n and F_a_n"):
        bearing_friction("6208", 0.0, 0.0, 1500.0, 68.0)
