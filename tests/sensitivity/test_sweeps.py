"""Sensitivity studies: sweeps against direct solves and invariants, duals and KKT multipliers
against finite differences of the optimum, and the plots."""
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import geardesign as gd  # noqa: E402
from geardesign import sweeps  # noqa: E402
from geardesign.errors import GearDesignError  # noqa: E402


def fd_of_optimum(z1, z2, limit, checks, h=1e-4):
    f = []
    for v in (checks[limit] - h, checks[limit] + h):
        f.append(gd.optimize_shifts(z1, z2, checks={**checks, limit: v}, method="exact").fun)
    return (f[1] - f[0]) / (2 * h)


@pytest.mark.parametrize("z1, z2, checks, limit, check", [
    (17, 26, {"eps_alpha_min": 1.2, "sa_min": 0.25}, "eps_alpha_min", "contact_ratio"),   # one active check
    (12, 40, {"eps_alpha_min": 1.2, "sa_min": 0.4}, "eps_alpha_min", "contact_ratio"),    # vertex with undercut1
    (30, 60, {"eps_alpha_min": 1.2, "sa_min": 0.4}, "eps_alpha_min", "contact_ratio"),    # vertex with interference2
])
def test_duals_and_kkt_match_finite_differences(z1, z2, checks, limit, check):
    exact = gd.optimize_shifts(z1, z2, checks=checks, method="exact")
    convex = gd.optimize_shifts(z1, z2, checks=checks, method="convex")
    names = [check]
    assert check in exact.active and check in convex.active
    fd = fd_of_optimum(z1, z2, limit, checks)
    assert fd != 0
    assert sum(convex.sensitivity[n] for n in names) == pytest.approx(fd, rel=1e-4)
    assert sum(exact.sensitivity[n] for n in names) == pytest.approx(fd, rel=1e-4)


def test_limit_sweep_invariants_and_direct_solves():
    vals = [1.1, 1.2, 1.3]
    df = sweeps.sweep("eps_alpha_min", vals, z1=17, z2=26, m=8)
    assert list(df["eps_alpha_min"]) == vals and df["success"].all()
    assert np.allclose(df["eps_alpha"], vals, atol=1e-8)            # the active limit holds with equality
    assert (np.diff(df["x_sum"]) < 0).all()                          # a stricter limit leaves less x-sum
    for v, row in zip(vals, df.itertuples()):                        # each point equals a cold solve
        r = gd.optimize_shifts(17, 26, checks={"eps_alpha_min": v, "sa_min": 0.25})
        assert (row.x1, row.x2) == pytest.approx((r.x1, r.x2), abs=1e-8)
    # the sweep's own slope column agrees with the slope between its points
    mid = (df["fun"].iloc[2] - df["fun"].iloc[0]) / 0.2
    assert df["sens_contact_ratio"].iloc[1] == pytest.approx(mid, rel=2e-2)


def test_tooth_count_sweep_is_batched_and_matches_direct_solves():
    df = sweeps.sweep("z1", [14, 17, 20], "z2", [26, 40], objective="max_x_sum", m=2)
    assert df.attrs["batched"] == "shift_atlas" and len(df) == 6
    for row in df.itertuples():
        r = gd.optimize_shifts(row.z1, row.z2)
        assert (row.x1, row.x2) == pytest.approx((r.x1, r.x2), abs=1e-7)
        assert row.a_w_mm == pytest.approx(gd.pair_geometry(2, row.z1, row.z2, row.x1, row.x2).a_w, rel=1e-12)


def test_rack_sweep_and_chain_service_factor_sweep():
    df = sweeps.sweep("ha", [0.9, 1.0, 1.1], z1=17, z2=26)
    assert df["success"].all()
    # a taller tooth gives more contact ratio at the same shifts, so the ε_α limit allows more x-sum
    assert (np.diff(df["x_sum"]) > 0).all()
    ch = sweeps.sweep("k_e", [1.5, 2.0, 2.148], target="chain", torque_nm=380, n1_rpm=120, ratio=1, z1=13,
                       allowable_pressure_mpa=29, strands=(1, 2), objective="min_sprocket_diameter",
                       center_distance_mm=180)
    same = ch[ch["designation"] == ch["designation"].iloc[-1]]
    assert len(same) >= 2
    assert np.allclose(same["pressure_mpa"] / same["k_e"], same["pressure_mpa"].iloc[0] / same["k_e"].iloc[0],
                       rtol=1e-12)                                    # p = F_t·K_e/(A·m·K_m) is linear in K_e


def test_sweep_errors():
    with pytest.raises(GearDesignError, match="parameter must be one of"):
        sweeps.sweep("colour", [1], z1=17, z2=26)
    with pytest.raises(GearDesignError, match="needs z2"):
        sweeps.sweep("eps_alpha_min", [1.2], z1=17)
    with pytest.raises(GearDesignError, match="together"):
        sweeps.sweep("eps_alpha_min", [1.2], "sa_min", None, z1=17, z2=26)


def test_study_sizes_are_refused_before_any_work():
    with pytest.raises(gd.GearDesignError, match="values must hold 1 to 2000 values, got 20000"):
        gd.sweep("eps_alpha_min", np.linspace(1.0, 1.5, 20000), z1=17, z2=26)
    with pytest.raises(gd.GearDesignError, match="at most 10,000 points"):
        gd.sweep("eps_alpha_min", np.linspace(1.0, 1.5, 200), "sa_min", np.linspace(0.2, 0.4, 200), z1=17, z2=26)


def test_local_sensitivities_and_plots():
    tor = sweeps.local_sensitivities(17, 26, step=0.01)
    row = tor.set_index("input").loc["eps_alpha_min"]
    assert row["slope_dual"] == pytest.approx(row["slope_kkt"], rel=1e-6)
    assert row["slope_dual"] == pytest.approx(row["slope_fd"], rel=1e-3)
    # sa is not active at this optimum: no dual, and moving the limit does not move the optimum
    assert tor.set_index("input").loc["sa_min", "slope_fd"] == pytest.approx(0, abs=1e-9)
    fig, axes = plt.subplots(1, 3)
    sweeps.plot_tornado(tor, ax=axes[0])
    assert len(axes[0].patches) == 2 * len(tor)
    sw = sweeps.sweep("eps_alpha_min", [1.1, 1.3], z1=17, z2=26)
    sweeps.plot_margins(sw, "eps_alpha_min", ax=axes[1])
    assert len(axes[1].lines) == sum(c.startswith("margin_") for c in sw.columns) + 1
    sweeps.plot_region_motion("eps_alpha_min", [1.1, 1.3], 17, 26, ax=axes[2])
    assert len(axes[2].lines) >= 2
    plt.close(fig)


def test_sweep_margins_at_the_optimum_are_exact_zeros():
    """An active check's margin is 0 in a sweep, not a rounding residue of ±1e-16 that a log or
    two-parameter plot shows as a dip (both the tooth-count path and the limit path)."""
    import geardesign as gd

    teeth = gd.sweep("z2", [26, 30, 34, 40], z1=17)
    limits = gd.sweep("eps_alpha_min", [1.15, 1.2, 1.25], z1=17, z2=26)
    for frame in (teeth, limits):
        assert (frame["margin_contact_ratio"] == 0.0).all()
