"""The batch searches on a local Dask cluster of two processes give the serial table bit for bit, in
the same order: the atlas (spur with infeasible pairs, whose least infeasible point SLSQP finds, and
internal helical), the tooth-count search (free and fixed centre distance), the planetary search;
their size limits scale with the workers."""
import pytest

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.shifts import atlas
from tests.dask_cluster import assert_same_bits, client  # noqa: F401

pytestmark = pytest.mark.slow   # clusters, browsers, notebooks: seconds each (CONTRIBUTING.md)


@pytest.fixture(autouse=True)
def small_chunks(monkeypatch):
    # several chunks per worker even for these small batches, so order and joins are exercised
    monkeypatch.setattr(atlas, "ATLAS_CHUNK_MIN", 7)
    monkeypatch.setattr("geardesign.shifts.teeth.TEETH_CHUNK_MIN", 3)
    monkeypatch.setattr("geardesign.shifts.planetary_teeth.PLANETARY_CHUNK_MIN", 1)


def test_atlas_on_a_cluster_is_the_serial_atlas(client):  # noqa: F811
    kw = dict(z1_values=range(8, 15), z2_values=range(8, 25))    # z1 8..11: slivers and infeasible pairs
    serial = gd.shift_atlas(**kw)
    done = []
    assert_same_bits(gd.shift_atlas(**kw, client=client, progress=done.append), serial)
    assert done[-1] == len(serial) and done == sorted(done)
    assert not serial.feasible.all()          # the one-by-one (infeasible) path is exercised


def test_internal_helical_atlas_on_a_cluster_is_the_serial_atlas(client):  # noqa: F811
    kw = dict(z1_values=[18, 21, 25], z2_values=range(40, 60, 3), beta_deg=12.0, internal=True,
              objective="balanced_sliding", method="convex")
    assert_same_bits(gd.shift_atlas(**kw, client=client), gd.shift_atlas(**kw))


def test_atlas_limit_scales_with_the_workers(client):  # noqa: F811
    z1, z2 = range(3, 600), range(3, 600)                  # 178,503 pairs: over one machine's limit
    n = atlas.atlas_size(z1, z2)
    assert atlas.ATLAS_PAIRS_MAX < n <= 2 * atlas.ATLAS_PAIRS_MAX
    with pytest.raises(GearDesignError, match="at most 100,000 pairs"):
        gd.shift_atlas(z1, z2)
    big = range(3, 800)                                     # 317,806 pairs: over two workers' limit too
    with pytest.raises(GearDesignError, match=r"at most 200,000 pairs \(100,000 per worker\)"):
        gd.shift_atlas(big, big, client=client)


@pytest.mark.parametrize("kw", [dict(ratio=2.5, ratio_tol=0.03, z1_range=(8, 30)),
                                dict(ratio=1.6, a_w=125.0, m="series", m_range=(2, 5), z1_range=(14, 30))])
def test_select_teeth_on_a_cluster_is_the_serial_search(client, kw):  # noqa: F811
    serial = gd.select_teeth(**kw)
    steps = []
    par = gd.select_teeth(**kw, client=client, progress=lambda d, t: steps.append((d, t)))
    assert_same_bits(par.table, serial.table)
    assert_same_bits(par.skipped, serial.skipped)
    assert par.n_solved == serial.n_solved and steps[-1] == (serial.n_solved, serial.n_solved)


def test_select_teeth_limit_scales_with_the_workers(client):  # noqa: F811
    from geardesign.shifts import teeth
    small, large = (8, 60), (8, 80)      # ratio 3 ± 50 %: about 5,400 and 9,600 distinct pairs
    assert teeth.MAX_SOLVES < teeth.ratio_pairs(3.0, 0.5, small)[0].size < 2 * teeth.MAX_SOLVES
    assert teeth.ratio_pairs(3.0, 0.5, large)[0].size > 2 * teeth.MAX_SOLVES
    with pytest.raises(GearDesignError, match=f"more than the limit {teeth.MAX_SOLVES}:"):
        gd.select_teeth(ratio=3.0, ratio_tol=0.5, z1_range=small)
    with pytest.raises(GearDesignError, match=rf"more than the limit {2 * teeth.MAX_SOLVES} \(3000 per worker x 2\)"):
        gd.select_teeth(ratio=3.0, ratio_tol=0.5, z1_range=large, client=client)


def test_select_planetary_teeth_on_a_cluster_is_the_serial_search(client):  # noqa: F811
    kw = dict(ratio=4.6, n_planets=3, m=2.0, ratio_tol=0.02, z_sun_range=(17, 22), nonstandard_max=1)
    serial = gd.select_planetary_teeth(**kw)
    par = gd.select_planetary_teeth(**kw, client=client)
    assert par.n_solved == serial.n_solved > 3
    assert_same_bits(par.table, serial.table)


def test_a_users_cluster_with_dasks_own_settings_gives_the_serial_atlas(tmp_path):
    """A cluster started by Dask's defaults runs its workers' BLAS on one thread; each chunk is run
    with the caller's BLAS threads, so the infeasible pairs' SLSQP points still agree bit for bit."""
    from dask.distributed import Client, LocalCluster
    with LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=":0",
                      local_directory=str(tmp_path)) as cluster, Client(cluster) as user:
        assert set(user.run(lambda: __import__("os").environ.get("OPENBLAS_NUM_THREADS")).values()) == {"1"}
        kw = dict(z1_values=range(8, 12), z2_values=range(8, 20))
        assert_same_bits(gd.shift_atlas(**kw, client=user), gd.shift_atlas(**kw))


@pytest.mark.parametrize("numpy_threads, scipy_threads", [(1, 2), (2, 1)])
def test_atlas_on_a_cluster_follows_each_blas_library_of_the_caller(client, numpy_threads, scipy_threads):  # noqa: F811
    """numpy's and scipy's OpenBLAS share threadpoolctl's prefix; once a Dask cluster has started in a process they
    can run on different thread counts (Dask puts OPENBLAS_NUM_THREADS=1 into the caller's environment before scipy's
    library loads). Keyed by prefix, one count reached the workers for both, and the infeasible pairs' SLSQP points
    differed from the serial ones (in about half the runs: threadpoolctl's order followed the hash seed); each library
    keeps its own count now, whichever of the two runs on more threads."""
    import os

    import scipy.linalg  # noqa: F401  (scipy's OpenBLAS loaded, as SLSQP loads it)
    from threadpoolctl import ThreadpoolController

    from geardesign import parallel
    libs = {os.path.basename(lib.filepath): lib for lib in ThreadpoolController().lib_controllers}
    numpy_lib = next((lib for name, lib in libs.items() if "openblas64" in name), None)
    scipy_lib = next((lib for name, lib in libs.items() if "openblas" in name and "openblas64" not in name), None)
    if numpy_lib is None or scipy_lib is None:
        pytest.skip("needs numpy's and scipy's own OpenBLAS builds (the wheels')")
    before = numpy_lib.num_threads, scipy_lib.num_threads
    try:
        numpy_lib.set_num_threads(numpy_threads)
        scipy_lib.set_num_threads(scipy_threads)
        assert len(parallel._blas_threads()) == len(libs)       # one count per library, not per prefix
        kw = dict(z1_values=range(8, 12), z2_values=range(8, 25))
        serial = gd.shift_atlas(**kw)
        assert not serial.feasible.all()
        assert_same_bits(gd.shift_atlas(**kw, client=client), serial)
    finally:
        numpy_lib.set_num_threads(before[0])
        scipy_lib.set_num_threads(before[1])


def test_a_dask_worker_keeps_its_heap(client):  # noqa: F811
    """Dask starts its workers with MALLOC_TRIM_THRESHOLD_=65536, under which every block of temporaries was given
    back to the system and faulted in again (an atlas cost a worker twice its serial CPU: benchmarks/bench_parallel.py);
    a chunk raises the threshold once per worker process, and only where that environment set it."""
    from geardesign import parallel
    gd.shift_atlas(range(12, 14), range(30, 40), client=client)
    assert set(client.run(lambda: __import__("os").environ.get("MALLOC_TRIM_THRESHOLD_")).values()) == {"65536"}
    assert [True] in client.run(lambda: list(parallel._HEAP_KEPT)).values()   # the worker(s) that ran a chunk
