"""Sweeps on a local Dask cluster of two processes give the serial table bit for bit: a limit sweep
longer than one warm-started run, a two-parameter tooth-count sweep (through the atlas) and a chain
sweep; the point limits scale with the workers."""
import numpy as np
import pytest

import geardesign as gd
from geardesign import sweeps
from geardesign.errors import GearDesignError
from tests.dask_cluster import assert_same_bits, client  # noqa: F401

pytestmark = pytest.mark.slow   # clusters, browsers, notebooks: seconds each (CONTRIBUTING.md)


def test_limit_sweep_on_a_cluster_is_the_serial_sweep(client):  # noqa: F811
    values = np.linspace(1.05, 1.45, sweeps.WARM_START_RUN + 6)     # two runs: the second starts cold
    serial = gd.sweep("eps_alpha_min", values, z1=17, z2=26, m=4)
    assert_same_bits(gd.sweep("eps_alpha_min", values, z1=17, z2=26, m=4, client=client), serial)
    assert serial["success"].all() and serial["x_sum"].is_monotonic_decreasing


def test_a_run_starts_cold_wherever_it_is():
    """Each run of WARM_START_RUN points is solved as if it were a sweep of its own."""
    values = np.linspace(1.05, 1.45, sweeps.WARM_START_RUN + 6)
    whole = gd.sweep("eps_alpha_min", values, z1=17, z2=26)
    tail = gd.sweep("eps_alpha_min", values[sweeps.WARM_START_RUN:], z1=17, z2=26)
    assert_same_bits(whole.iloc[sweeps.WARM_START_RUN:].reset_index(drop=True), tail)


def test_tooth_sweep_on_a_cluster_is_the_serial_sweep(client):  # noqa: F811
    kw = dict(parameter="z1", values=[12, 14, 17], parameter2="z2", values2=[26, 31, 40], m=3)
    assert_same_bits(gd.sweep(**kw, client=client), gd.sweep(**kw))


def test_chain_sweep_on_a_cluster_is_the_serial_sweep(client):  # noqa: F811
    kw = dict(target="chain", torque_nm=380, n1_rpm=120, ratio=1, z1=13)
    assert_same_bits(gd.sweep("k_e", [1.5, 2.0, 2.148], **kw, client=client), gd.sweep("k_e", [1.5, 2.0, 2.148], **kw))


def test_point_limits_scale_with_the_workers(client):  # noqa: F811
    over = np.linspace(1.0, 1.5, sweeps.STUDY_VALUES_MAX + 1)
    with pytest.raises(GearDesignError, match=f"values must hold 1 to {sweeps.STUDY_VALUES_MAX} values"):
        gd.sweep("eps_alpha_min", over, z1=17, z2=26)
    with pytest.raises(GearDesignError, match=f"values must hold 1 to {2 * sweeps.STUDY_VALUES_MAX} values"):
        gd.sweep("eps_alpha_min", np.linspace(1.0, 1.5, 2 * sweeps.STUDY_VALUES_MAX + 1), z1=17, z2=26, client=client)
