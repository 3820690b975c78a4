"""geardesign.parallel: a batch mapped over chunks serially or on a local Dask cluster of two
processes — order, progress, errors, Ctrl-C (futures cancelled, a cluster made for the call closed,
no process or scratch folder left), the missing-Dask message and the bad inputs."""
import os
import subprocess
import sys
import tempfile
import time

import psutil
import pytest

import geardesign as gd
from geardesign import parallel
from geardesign.errors import GearDesignError
from tests.dask_cluster import client  # noqa: F401  (the module's cluster fixture)

pytestmark = pytest.mark.slow   # clusters, browsers, notebooks: seconds each (CONTRIBUTING.md)


def square_all(chunk):
    return [v * v for v in chunk]


def slow_first(chunk):
    """Early chunks take longest, so the cluster finishes them last."""
    time.sleep(0.05 * (10 - chunk[0]) if chunk[0] < 10 else 0)
    return [v * v for v in chunk]


def fail_on_seven(chunk):
    if 7 in chunk:
        raise GearDesignError("chunk with 7 refused")
    time.sleep(0.2)
    return list(chunk)


def die(chunk):
    os._exit(3)         # a worker process that dies (out of memory, killed): its nanny restarts it


def _scheduler_tasks(c) -> int:
    return c.run_on_scheduler(lambda dask_scheduler: len(dask_scheduler.tasks))


def _wait_until(test, seconds=20.0):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if test():
            return True
        time.sleep(0.1)
    return test()


def _scratch_dirs() -> set:
    return {n for n in os.listdir(tempfile.gettempdir()) if n.startswith("geardesign-dask-")}


def _children() -> set:
    """Live child processes, but multiprocessing's resource tracker: one per Python process, started
    by the first spawned child and leaving with this process."""
    out = set()
    for p in psutil.Process().children(recursive=True):
        try:
            if p.status() != psutil.STATUS_ZOMBIE and "resource_tracker" not in " ".join(p.cmdline()):
                out.add(p.pid)
        except psutil.NoSuchProcess:
            pass
    return out


def test_chunk_slices_cover_the_batch_in_order_within_the_sizes():
    for n, workers, lo, hi in [(1, 1, 1, 1), (1000, 2, 200, 5000), (1000, 64, 10, 20), (7, 3, 1, 100)]:
        sl = parallel.chunk_slices(n, workers, lo, hi)
        assert [i for s in sl for i in range(n)[s]] == list(range(n))
        sizes = [s.stop - s.start for s in sl]
        assert all(min(lo, n) <= k <= hi for k in sizes[:-1]) and 1 <= sizes[-1] <= hi
    # several chunks per worker when the batch is large enough
    assert len(parallel.chunk_slices(10_000, 4, 10, 10_000)) == 4 * parallel.CHUNKS_PER_WORKER


def test_serial_map_needs_no_dask_and_reports_progress():
    seen = []
    out = parallel.map_chunks(square_all, [[1, 2], [3], [4, 5, 6]], progress=lambda d, t: seen.append((d, t)))
    assert out == [[1, 4], [9], [16, 25, 36]]
    assert seen == [(2, 6), (3, 6), (6, 6)]
    code = ("import sys, geardesign as gd; gd.shift_atlas([17], [26]); gd.select_teeth(2.0, 0.0, z1_range=(20, 20));"
            "print('distributed' in sys.modules, 'dask' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.split() == ["False", "False"]


def test_results_come_back_in_chunk_order_with_progress(client):  # noqa: F811
    chunks = [[i] for i in range(12)]
    seen = []
    out = parallel.map_chunks(slow_first, chunks, client=client, progress=lambda d, t: seen.append((d, t)))
    assert out == [[i * i] for i in range(12)]
    assert [d for d, _ in seen] == list(range(1, 13)) and {t for _, t in seen} == {12}


def test_a_chunks_error_is_raised_and_the_other_futures_cancelled(client):  # noqa: F811
    with pytest.raises(GearDesignError, match="chunk with 7 refused"):
        parallel.map_chunks(fail_on_seven, [[i] for i in range(40)], client=client)
    assert _wait_until(lambda: _scheduler_tasks(client) == 0)


def test_ctrl_c_cancels_the_futures_and_leaves_the_given_client_working(client):  # noqa: F811
    def interrupt(done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        parallel.map_chunks(fail_on_seven, [[i] for i in range(100, 140)], client=client, progress=interrupt)
    assert _wait_until(lambda: _scheduler_tasks(client) == 0)
    assert parallel.map_chunks(square_all, [[2], [3]], client=client) == [[4], [9]]


def test_ctrl_c_closes_a_cluster_made_for_the_call_and_leaves_nothing(client):  # noqa: F811
    before, scratch = _children(), _scratch_dirs()

    def interrupt(done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        parallel.map_chunks(square_all, [[i] for i in range(20)], workers=2, progress=interrupt)
    assert _wait_until(lambda: _children() <= before), _children() - before
    assert _scratch_dirs() <= scratch


def test_a_cluster_made_for_the_call_is_closed_after_it(client):  # noqa: F811
    before, scratch = _children(), _scratch_dirs()
    assert parallel.map_chunks(square_all, [[1], [2], [3]], workers=2) == [[1], [4], [9]]
    assert _wait_until(lambda: _children() <= before), _children() - before
    assert _scratch_dirs() <= scratch


def test_a_worker_that_keeps_dying_is_one_error(monkeypatch):
    import dask
    before, scratch = _children(), _scratch_dirs()
    with dask.config.set({"distributed.scheduler.allowed-failures": 1}):
        with pytest.raises(GearDesignError, match="the Dask cluster lost the batch: KilledWorker"):
            parallel.map_chunks(die, [[1]], workers=1)
    assert _wait_until(lambda: _children() <= before), _children() - before
    assert _scratch_dirs() <= scratch


def test_slots_count_the_workers(client):  # noqa: F811
    assert parallel.slots() == 1
    assert parallel.slots(workers=2) == 2
    assert parallel.slots(client) == 2
    assert parallel.scaled_limit(100, client) == 200


@pytest.mark.parametrize("workers", [0, -1, 1.5, "two", [2], parallel.LOCAL_WORKERS_MAX + 1, True])
def test_bad_worker_counts_are_refused_by_name(workers):
    with pytest.raises(GearDesignError, match="workers"):
        parallel.map_chunks(square_all, [[1]], workers=workers)


def test_a_client_that_is_not_one_is_refused(client):  # noqa: F811
    with pytest.raises(GearDesignError, match="client must be a dask.distributed.Client, got str"):
        gd.shift_atlas([17], [26], client="tcp://127.0.0.1:8786")
    with pytest.raises(GearDesignError, match="not both"):
        gd.shift_atlas([17], [26], client=client, workers=2)


def test_an_unreachable_scheduler_is_one_error(monkeypatch):
    monkeypatch.setattr(parallel, "CONNECT_TIMEOUT_S", 1)
    with pytest.raises(GearDesignError, match=r"scheduler 'tcp://127.0.0.1:9': cannot connect within 1 s"):
        with parallel.cluster(address="tcp://127.0.0.1:9"):
            pass


def test_missing_dask_is_one_error_naming_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "distributed", None)     # import distributed -> ImportError
    for call in (lambda: parallel.map_chunks(square_all, [[1]], workers=2),
                 lambda: gd.shift_atlas([17], [26], workers=2),
                 lambda: gd.select_teeth(2.0, 0.0, z1_range=(20, 20), workers=2)):
        with pytest.raises(GearDesignError, match=r'pip install "geardesign\[dask\]"'):
            call()
    assert gd.shift_atlas([17], [26]).feasible.all()      # serial runs without it


@pytest.mark.parametrize("objective, sized", [("min_size", False), ("max_margin", False), ("min_size", True)])
def test_drive_optimize_on_two_workers_is_the_serial_optimum(objective, sized):
    """Drive.optimize(workers=2) sends the tooth pairs the walk solves together to a local cluster (max_margin:
    its batches of Chebyshev centres; a stage sized by its strength: its windows of sizing calls), the workers
    sharing the caller's cache of solved pairs: the same table, bit for bit, and the same number of shift solves
    as the serial run (issue 35 §5: 7,769 instead of 412 when each worker kept its own cache and every group
    was solved up front)."""
    import geardesign as gd
    from geardesign.drives.stage_kinds.gear import clear_shift_cache

    gear = gd.GearStage(m=None, material="42CrMo4") if sized else gd.GearStage(3)
    drive = gd.Drive(power_kw=4, n_in_rpm=1450, stages=[gear, gd.ChainStage()])
    clear_shift_cache()
    serial = drive.optimize(total_ratio=10, top=3, objective=objective)
    clear_shift_cache()
    spread = drive.optimize(total_ratio=10, top=3, objective=objective, workers=2)
    assert serial.table.equals(spread.table)
    assert serial.n_shift_solves > 0 and spread.n_shift_solves == serial.n_shift_solves
