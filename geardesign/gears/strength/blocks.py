"""A large batch of the vectorised factor chain, evaluated block by block.

The chain makes a few hundred array temporaries. Over 10⁶ designs each is 8 MB: a fresh allocation that the kernel
pages in on first touch (numpy asks for huge pages from 4 MB up, each zeroed when first touched) and that no cache
holds. The chain then ran at half its speed per design at 2·10⁵ designs. In blocks of :data:`BLOCK` designs the
temporaries are 128 kB, taken again and again from the allocator's heap and kept in the caches; only the results
are full size (one array per dtype, each field a row of it). Every formula of the chain is elementwise (where it
branches on ``any``/``all`` over the designs, each branch gives a design the value it has alone), so the blocks give
the unblocked call's values bit for bit.
"""
from __future__ import annotations

import math
import mmap

import numpy as np

__all__ = ["BLOCK", "batch_shape", "in_blocks"]

BLOCK = 16_000     # designs per block: 125 kB a temporary, under glibc's mmap threshold (as geometry.BLOCK)


def batch_shape(values) -> tuple | None:
    """The shape ``values`` broadcast to (None ignored), or None when they do not broadcast."""
    try:
        return np.broadcast_shapes(*(np.shape(v) for v in values if v is not None))
    except ValueError:
        return None


def in_blocks(evaluate, values, shape, block=BLOCK) -> dict | None:
    """``evaluate(values of one block)`` over the designs of ``shape`` (``values`` broadcast to it; numbers and
    None passed as they are), block by block, and its dict at full size: each field an array of ``shape`` where
    a block gave an array (fields that are one array in each block share one; see :func:`_rows`), else the first
    block's number. None when the blocks' dicts differ in their keys or in which fields they share (then the caller
    evaluates the batch whole)."""
    n = math.prod(shape)
    flat = [v if v is None or np.ndim(v) == 0 else np.broadcast_to(np.asarray(v), shape).reshape(-1)
            for v in values]
    out, full, same = {}, set(), {}
    for s in range(0, n, block):
        part = evaluate([v if v is None or np.ndim(v) == 0 else v[s:s + block] for v in flat])
        if not s:
            same = _shared(part)
            rows = _rows(part, same, n)
        elif part.keys() != out.keys() or any(part[k] is not part[j] for k, j in same.items()):
            return None
        for k, v in part.items():
            if k in same:
                out[k] = None           # its place in the dict's order; the array it shares comes at the end
                continue
            if k not in full and isinstance(v, np.ndarray) and v.ndim:
                arr = rows.pop(k) if k in rows else np.empty(n, dtype=v.dtype)
                if k in out:            # a number in the blocks before (a shortcut taken over those designs)
                    arr[:s] = out[k]
                out[k] = arr
                full.add(k)
            if k in full:
                out[k][s:s + block] = v
            elif k not in out:
                out[k] = v
    out.update({k: v.reshape(shape) for k, v in out.items() if k in full})
    out.update({k: out[j] for k, j in same.items()})
    return out


def _shared(part: dict) -> dict:
    """{field: the earlier field whose array it is} of one block's dict (f_ma is f_Hbeta, say)."""
    first = {}
    return {k: first[id(v)] for k, v in part.items()
            if isinstance(v, np.ndarray) and v.ndim and first.setdefault(id(v), k) != k}


def _rows(part: dict, same: dict, n: int) -> dict:
    """{field: a row of one (fields, n) array per dtype} for the fields a block gives as arrays: one allocation
    instead of ~70, its pages mapped at once (:func:`_mapped`; page faults were a fifth of the call at 2·10⁵
    designs); a field kept alone keeps its dtype's array alive."""
    keys = {}
    for k, v in part.items():
        if k not in same and isinstance(v, np.ndarray) and v.ndim:
            keys.setdefault(v.dtype, []).append(k)
    rows = {}
    for dtype, names in keys.items():
        rows.update(zip(names, _mapped((len(names), n), dtype)))
    return rows


_POPULATE = getattr(mmap, "MAP_POPULATE", 0)      # Linux: the pages mapped at once


def _mapped(shape, dtype) -> np.ndarray:
    """An array to be written in full, on anonymous memory whose pages the kernel maps in one call (Linux's
    MAP_POPULATE): ~1.4x cheaper than a page fault per 4 kB page on first touch, and without the huge pages numpy
    asks for from 4 MB up, which a virtual machine that hands freed memory back to its host backs afresh on each
    first touch (measured: 10⁶ designs' results mapped and written in 0.2 s this way, 0.1 to 1.2 s on huge pages).
    Elsewhere (or when the mapping fails) np.empty."""
    nbytes = math.prod(shape) * np.dtype(dtype).itemsize
    if _POPULATE and nbytes:
        try:
            mem = mmap.mmap(-1, nbytes, flags=mmap.MAP_PRIVATE | mmap.MAP_ANONYMOUS | _POPULATE)
        except OSError:
            pass
        else:
            return np.frombuffer(mem, dtype=dtype).reshape(shape)
    return np.empty(shape, dtype=dtype)
