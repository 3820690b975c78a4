"""Batches beyond one core: a function mapped over chunks of a batch, here or on a Dask cluster.

Every batch job of the library (the atlas, the tooth-count searches, the sweeps) is a list of
independent solves. :func:`map_chunks` runs them

* serially, in this process, when neither ``client`` nor ``workers`` is given (no Dask needed);
* on ``client``, a ``dask.distributed.Client`` of the user's cluster; or
* on a ``LocalCluster`` of ``workers`` processes (one thread each: the solves are numpy and Python
  code that holds the GIL between array calls), started for the call and closed after it.

Results come back in the order of the chunks whatever order the workers finish them in, and each
chunk is computed by the same code as a serial run, so the table is the serial one bit for bit.
One more thing must match for that: the number of BLAS threads. OpenBLAS rounds a few of the small
vector operations scipy's SLSQP makes (the least infeasible point of an infeasible pair) differently
with one thread than with several, and Dask starts its workers with one; each chunk therefore runs
with the BLAS thread counts of the calling process, library by library (threadpoolctl, part of the
extra), which stay set on the worker after it. The workers
must run the same versions of numpy, scipy and geardesign, as Dask itself requires.
``progress(done, total)`` is called as chunks finish. Ctrl-C (KeyboardInterrupt), or an error in
one chunk, cancels every future; a cluster started here is closed and its scratch folder removed
(its workers start with Ctrl-C ignored, so that this process alone handles it; a Ctrl-C during
their start is held back until the start ends, then acted on: see :func:`_ctrl_c_deferred`).

Dask is an optional extra (``pip install "geardesign[dask]"``); it is imported only when a batch
goes to a cluster, never by ``import geardesign``.
"""
from __future__ import annotations

import contextlib
import logging
import math
import os
import shutil
import signal
import tempfile
import threading

from .errors import GearDesignError
from .validate import require_count

__all__ = ["map_chunks", "cluster", "chunk_slices", "slots", "scaled_limit", "require_workers", "requested",
           "LOCAL_WORKERS_MAX", "CONNECT_TIMEOUT_S", "CHUNKS_PER_WORKER"]

# A local cluster gets at most one process per core (two at least, so a laptop can try it): more
# processes only share the same cores and memory. A bigger cluster is the scheduler's (client=).
LOCAL_WORKERS_MAX = max(2, os.cpu_count() or 1)
CONNECT_TIMEOUT_S = 10        # seconds to reach a scheduler before the address is refused
# Chunks per worker: several, so that a slow chunk (pairs near the limits of existence solve one
# by one) does not leave the other workers idle at the end, and progress moves in steps.
CHUNKS_PER_WORKER = 4

# A cluster made here starts its workers without the stack sampler of Dask's dashboard, which interrupts
# these Python-heavy solves every 10 ms. (Dask's worker environment, MALLOC_TRIM_THRESHOLD_ and BLAS pinned to
# one thread, reaches every worker whatever this config says, a user's cluster's too: the BLAS threads are set
# per chunk (_SameBlas), each library to the caller's count, and the heap's trim threshold raised once per worker
# (_heap_kept), see docs/scale.md.)
_LOCAL_CONFIG = {"distributed.worker.profile.enabled": False}

_INSTALL = 'install Dask with: pip install "geardesign[dask]"'


def requested(client=None, workers=None) -> bool:
    """True when the batch goes to a cluster (``client`` or ``workers`` given)."""
    return client is not None or workers is not None


def _distributed():
    """dask.distributed, imported on first use; a missing install is one clear error."""
    try:
        import distributed
    except ImportError:
        raise GearDesignError(f"client= / workers= run a batch on Dask, which is not installed: {_INSTALL}") from None
    return distributed


def require_workers(workers) -> int:
    """The number of local worker processes: a whole number in [1, LOCAL_WORKERS_MAX]."""
    return require_count("workers", workers, 1, LOCAL_WORKERS_MAX)


def _require_client(client):
    distributed = _distributed()
    if not isinstance(client, distributed.Client):
        raise GearDesignError(f"client must be a dask.distributed.Client, got {type(client).__name__}")
    if client.status != "running":
        raise GearDesignError(f"client must be a running dask.distributed.Client, got one with status "
                              f"{client.status!r}")
    return client


def slots(client=None, workers=None) -> int:
    """How many workers a batch runs on: 1 serially, ``workers`` for a local cluster, the number of
    workers the ``client``'s scheduler knows when the call starts. The size limits that protect one
    machine (a limit on pairs or solves, set for minutes of one core) are multiplied by it."""
    if client is not None and workers is not None:
        raise GearDesignError(f"give client= or workers=, not both (got workers={workers!r} and a client)")
    if client is not None:
        n = len(_require_client(client).nthreads())      # {worker address: threads}, every worker
        if n < 1:
            raise GearDesignError("client: its cluster has no workers (nothing would run): start workers first")
        return n
    return 1 if workers is None else require_workers(workers)


def scaled_limit(limit: int, client=None, workers=None) -> int:
    """``limit`` (set for one machine) times the workers the batch runs on (see :func:`slots`)."""
    return int(limit) * slots(client, workers)


def chunk_slices(n: int, n_workers: int, min_chunk: int, max_chunk: int) -> list[slice]:
    """``n`` items cut into consecutive slices: CHUNKS_PER_WORKER per worker, but no chunk smaller
    than ``min_chunk`` (the size whose work outweighs a task's scheduling cost, measured for each
    batch kind) nor larger than ``max_chunk`` (progress steps and the memory of one chunk)."""
    size = min(max(min_chunk, math.ceil(n / (CHUNKS_PER_WORKER * max(n_workers, 1)))), max_chunk)
    size = max(size, 1)
    return [slice(s, min(s + size, n)) for s in range(0, n, size)]


@contextlib.contextmanager
def cluster(client=None, workers=None, address: str | None = None):
    """A ``Client`` to run batches on, for the duration of a ``with`` block (None: serial).

    ``client``: the user's, used as it is and left open. ``address``: a scheduler's address
    (``tcp://host:8786``), connected within CONNECT_TIMEOUT_S and closed at the end.
    ``workers``: a ``LocalCluster`` of that many processes, one thread each, in a scratch folder
    of its own; the cluster is closed and the folder removed at the end, also on Ctrl-C.
    """
    given = [name for name, v in (("client", client), ("workers", workers), ("address", address)) if v is not None]
    if len(given) > 1:
        raise GearDesignError(f"give one of client=, workers= or a scheduler address, not {' and '.join(given)}")
    if client is not None:
        yield _require_client(client)
        return
    if address is not None:
        with _connected(address) as c:
            yield c
        return
    if workers is None:
        yield None
        return
    with _local_cluster(require_workers(workers)) as c:
        yield c


@contextlib.contextmanager
def _connected(address):
    distributed = _distributed()
    if not isinstance(address, str) or not address.strip():
        raise GearDesignError(f"scheduler address must be text such as 'tcp://host:8786', got {address!r}")
    try:
        c = distributed.Client(address, timeout=CONNECT_TIMEOUT_S, set_as_default=False)
    except (OSError, ValueError, TypeError) as exc:   # unreachable, refused, timed out, malformed
        reason = " ".join(str(exc).split())[:160]
        raise GearDesignError(f"scheduler {address!r}: cannot connect within {CONNECT_TIMEOUT_S} s ({reason})") \
            from None
    try:
        yield c
    finally:
        c.close()


@contextlib.contextmanager
def _local_cluster(n: int):
    distributed = _distributed()
    import dask
    scratch = tempfile.mkdtemp(prefix="geardesign-dask-")
    local = client = None
    try:
        # the scheduler's scratch folder too (Dask's default: $TMPDIR/dask-scratch-space, left behind)
        with _ctrl_c_deferred(), dask.config.set({**_LOCAL_CONFIG, "temporary-directory": scratch}):
            local = distributed.LocalCluster(n_workers=n, processes=True, threads_per_worker=1,
                                             dashboard_address=":0", local_directory=scratch,
                                             silence_logs=logging.CRITICAL)
            client = distributed.Client(local, set_as_default=False)
        yield client
    finally:
        with _ctrl_c_ignored():
            # each step on its own: a client that fails to close must not keep the workers alive
            for part in (client, local):
                if part is not None:
                    with contextlib.suppress(Exception):
                        part.close()
            shutil.rmtree(scratch, ignore_errors=True)


# A watcher beside this process while a local cluster starts: it hears Ctrl-C for it (see _ctrl_c_deferred) and
# ends when its stdin closes (this process done with it, or gone).
_WATCHER = ("import os, signal, sys\n"
            "signal.signal(signal.SIGINT, lambda *_: os.kill(os.getppid(), signal.SIGUSR1))\n"
            "sys.stdin.read()\n")


@contextlib.contextmanager
def _ctrl_c_deferred():
    """Ctrl-C held back for the block and acted on when it ends (KeyboardInterrupt): around the start of a
    local cluster (main thread only; elsewhere Python delivers no signals).

    Ctrl-C goes to the terminal's whole process group, and workers it reaches mid-start print tracebacks
    while their nannies restart them; so SIGINT is ignored for the block, and the workers, which inherit the
    disposition, start deaf to it. An ignored signal is thrown away, though, and with it the user's Ctrl-C
    (issue 36 §1.3): a small watcher process in the same group hears it instead and tells this process
    (SIGUSR1); a watcher that died of it (hit before its handler was set) counts as heard too."""
    import subprocess
    import sys

    if (threading.current_thread() is not threading.main_thread() or not hasattr(signal, "SIGUSR1")
            or not sys.executable):   # no watcher to start (another thread, Windows, an embedded Python)
        with _ctrl_c_ignored():
            yield
        return

    caught = []
    old_usr1 = signal.signal(signal.SIGUSR1, lambda signum, frame: caught.append(signum))
    watcher = subprocess.Popen([sys.executable, "-I", "-S", "-c", _WATCHER], stdin=subprocess.PIPE,
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        with _ctrl_c_ignored():
            try:
                yield
            except Exception:
                if not (caught or watcher.poll() == -signal.SIGINT):
                    raise
    finally:
        watcher.stdin.close()
        try:
            watcher.wait(5)
        except subprocess.TimeoutExpired:
            watcher.kill()
            watcher.wait()
        signal.signal(signal.SIGUSR1, old_usr1)
    if caught or watcher.returncode == -signal.SIGINT:
        raise KeyboardInterrupt from None


@contextlib.contextmanager
def _ctrl_c_ignored():
    """SIGINT ignored for the block (in the main thread; elsewhere Python delivers no signals): around
    the clean-up of a local cluster, so that a second Ctrl-C does not cut its closing short."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    old = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, old)


def map_chunks(fn, chunks, *, client=None, workers=None, progress=None) -> list:
    """``[fn(chunk) for chunk in chunks]``: serially, on ``client``, or on a local cluster of
    ``workers`` processes (see the module docstring). ``chunks`` are sized sequences (a list, an
    array, a tuple of arrays counts as its first member's length for progress); ``fn`` must be
    picklable (a module-level function or a functools.partial of one) to go to a cluster.
    ``progress(done, total)`` counts items, called as each chunk finishes.

    >>> map_chunks(sum, [[1, 2], [3], [4, 5, 6]])           # serially: no Dask needed
    [3, 3, 15]
    """
    chunks = list(chunks)
    sizes = [_size(c) for c in chunks]
    total = sum(sizes)
    if not requested(client, workers):
        out, done = [], 0
        for chunk, size in zip(chunks, sizes):
            out.append(fn(chunk))
            done += size
            if progress is not None:
                progress(done, total)
        return out
    with cluster(client, workers) as c:
        return _gather_in_order(c, fn, chunks, sizes, total, progress)


class _SameBlas:
    """``fn`` run with the BLAS thread counts ``limits`` ({library file name: threads}) of the caller.
    The counts are set on the worker and left so, not restored after the chunk: chunks that run side
    by side in the threads of one worker must not undo each other's setting half-way."""

    def __init__(self, fn, limits: dict):
        self.fn, self.limits = fn, limits

    def __call__(self, chunk):
        from threadpoolctl import ThreadpoolController

        _load_blas()
        for lib in ThreadpoolController().lib_controllers:
            threads = self.limits.get(_library_name(lib.filepath))
            if threads is not None and lib.num_threads != threads:
                lib.set_num_threads(threads)
        _heap_kept()
        return self.fn(chunk)


# glibc's heap is trimmed (given back to the system) when more than this is free at its top
HEAP_TRIM_BYTES = 64 << 20
_HEAP_KEPT = []


def _heap_kept() -> None:
    """On a worker started with Dask's MALLOC_TRIM_THRESHOLD_ (65536: every Dask worker, a user's default cluster's
    too), glibc's trim threshold raised to HEAP_TRIM_BYTES, once per process; elsewhere nothing is done.

    With 64 kB, the solvers' temporaries freed at the heap's top are given back to the system at every block and
    their pages faulted in afresh by the next one: an atlas of 3 626 pairs made 21 079 brk calls (7 669 with
    glibc's defaults) and cost 3.4 CPU s against 1.7 s with the threshold at 64 MB (issue 36 §3). Only the trim
    threshold is set; the mapping threshold stays where Dask's environment fixed it (128 kB, above the solvers'
    blocks: geometry.BLOCK)."""
    if _HEAP_KEPT:
        return
    _HEAP_KEPT.append(True)
    try:
        if int(os.environ.get("MALLOC_TRIM_THRESHOLD_", "")) >= HEAP_TRIM_BYTES:
            return
    except ValueError:       # not set (not a Dask worker's environment), or not a number
        return
    import ctypes
    import ctypes.util

    try:
        mallopt = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6").mallopt
    except (OSError, AttributeError):      # not glibc
        return
    M_TRIM_THRESHOLD = -1                  # glibc's malloc.h
    mallopt(M_TRIM_THRESHOLD, HEAP_TRIM_BYTES)


def _load_blas() -> None:
    """Load scipy's BLAS now (SLSQP runs on it): a library loaded after the thread counts are read or set keeps its
    own default, and SLSQP's last bits then differed between the caller and a worker (a planetary search)."""
    import scipy.linalg  # noqa: F401


def _library_name(filepath) -> str:
    """A BLAS library's file name (``libscipy_openblas64_-32a4b2a6.so``): the same build on the caller and a worker,
    wherever each installed it."""
    return os.path.basename(filepath or "")


def _blas_threads() -> dict:
    """{library file name: threads} of the BLAS libraries loaded in this process (scipy's loaded first).

    By file, not by threadpoolctl's prefix: numpy's and scipy's OpenBLAS share the prefix ``libscipy_openblas``,
    and once a Dask cluster has started in this process they differ (Dask puts OPENBLAS_NUM_THREADS=1 into this
    process's environment, which scipy's library, loaded later, reads): keyed by prefix, whichever came last in
    threadpoolctl's listing (an order that follows the hash seed) set both on the workers, and the infeasible pairs'
    SLSQP points differed from the serial ones in the last bits in about half the runs."""
    try:
        from threadpoolctl import threadpool_info
    except ImportError:
        raise GearDesignError(f"client= / workers= need threadpoolctl (part of the Dask extra): {_INSTALL}") from None
    _load_blas()
    return {_library_name(lib["filepath"]): lib["num_threads"] for lib in threadpool_info()}


def _size(chunk) -> int:
    return len(chunk[0]) if isinstance(chunk, tuple) else len(chunk)


def _gather_in_order(client, fn, chunks, sizes, total, progress) -> list:
    """Submit every chunk, collect results as they finish into their own slots; on any exception
    (a chunk's error, Ctrl-C, the progress callback's) cancel every future before re-raising."""
    distributed = _distributed()
    futures = client.map(_SameBlas(fn, _blas_threads()), chunks, pure=False)
    where = {f.key: i for i, f in enumerate(futures)}
    out, done = [None] * len(chunks), 0
    try:
        for fut in distributed.as_completed(futures, loop=client.loop):
            i = where[fut.key]
            out[i] = fut.result()      # a chunk's exception (a GearDesignError, say) is raised here
            done += sizes[i]
            if progress is not None:
                progress(done, total)
    except BaseException as exc:
        with contextlib.suppress(Exception):     # the cluster may be gone already
            client.cancel(futures, force=True)
        if isinstance(exc, (distributed.KilledWorker, distributed.comm.CommClosedError)):
            # the cluster failed, not the input: still one line, not a traceback
            raise GearDesignError(f"the Dask cluster lost the batch: {type(exc).__name__}: "
                                  f"{' '.join(str(exc).split())[:200]}") from None
        raise
    finally:
        del futures
    return out
