"""A solved stage's options spread over a Dask cluster with one cache of solved work.

The search's walk (:mod:`geardesign.drives.search`) decides which options it solves and when, the same with
a cluster as without: only the options it hands :meth:`~geardesign.drives.stage_kinds.StageKind.solve_many`
together go to the workers, in chunks. Each chunk carries what the calling process has already solved for
its options (:meth:`StageKind.solved_for`) and brings back what the worker newly solved
(:meth:`StageKind.solve_shared`), which joins the caller's cache (:meth:`StageKind.absorb`). The options
that share solved work (one tooth pair's: :meth:`StageKind.shared_by`) go to one chunk, so that no two workers
solve the same pair. A drive on two workers thus makes the serial run's shift solves, no more (issue 35 §5: every worker had kept its own cache, and the
walk's whole list of groups was solved up front: 7,769 shift solves instead of 412), and finds the serial
run's table bit for bit.
"""
from __future__ import annotations

import functools

from .. import parallel

__all__ = ["solve_spread"]


def solve_spread(client, kind, stage, options: list, objective: str, flows: list) -> list:
    """``kind.solve_many(stage, options, objective, flows)``, on ``client``'s workers when it is given
    (None: here), with the solved work shared as the module docstring says."""
    if client is None or len(options) < 2:
        return kind.solve_many(stage, options, objective, flows)
    groups: dict = {}      # options that share solved work (StageKind.shared_by) -> their positions
    for i, o in enumerate(options):
        share = kind.shared_by(o)
        groups.setdefault(("alone", i) if share is None else share, []).append(i)
    n = min(parallel.slots(client=client), len(groups))
    if n < 2:
        return kind.solve_many(stage, options, objective, flows)
    parts = [[] for _ in range(n)]
    for j, idx in enumerate(groups.values()):         # whole groups, dealt round the chunks
        parts[j % n].extend(idx)
    chunks = [([options[i] for i in p], [flows[i] for i in p], kind.solved_for([options[i] for i in p]))
              for p in parts]
    results = parallel.map_chunks(functools.partial(_solve_chunk, kind, stage, objective), chunks, client=client)
    out = [None] * len(options)
    for p, (sols, solved) in zip(parts, results):
        kind.absorb(solved)
        for i, sol in zip(p, sols):
            out[i] = sol
    return out


def _solve_chunk(kind, stage, objective, chunk) -> tuple:
    """What a worker runs: one chunk's options solved with the caller's known solutions."""
    options, flows, known = chunk
    return kind.solve_shared(stage, options, objective, flows, known)
