"""The algebra of one active set: its gradient rows in w = (v, t), a small dense solve in Python
floats, and the multipliers of the stationarity e_t + Σ λ_j ∇c_j = 0.

These systems have at most three unknowns; Python floats beat a numpy call (~10 µs for
np.linalg.solve) here.
"""
from __future__ import annotations

import numpy as np

from .problem import Problem

__all__ = ["active_rows", "solve_small", "multipliers"]


def active_rows(GP, GM, act_p, act_m) -> list:
    """Gradients in w = (v, t) of the active constraints piece_k − t and margin_i, as rows."""
    return [GP[k].tolist() + [-1.0] for k in act_p] + [GM[i].tolist() + [0.0] for i in act_m]


def solve_small(A: list, b: list) -> list:
    """x with A x = b for a square system of a few rows: Gaussian elimination with partial
    pivoting. Raises LinAlgError when A is singular to working precision."""
    n = len(b)
    if n == 3:
        return _solve3(A, b)
    rows = [row[:n] + [bi] for row, bi in zip(A, b)]
    tiny = 1e-14 * max(max(map(abs, row[:n])) for row in rows) if n else 0.0
    for c in range(n):
        p = c
        for r in range(c + 1, n):
            if abs(rows[r][c]) > abs(rows[p][c]):
                p = r
        piv = rows[p]
        if abs(piv[c]) <= tiny:
            raise np.linalg.LinAlgError("singular active-set system")
        rows[c], rows[p] = piv, rows[c]
        for r in range(c + 1, n):
            row = rows[r]
            f = row[c] / piv[c]
            if f:
                rows[r] = [a - f * ac for a, ac in zip(row, piv)]
    x = [0.0] * n
    for c in range(n - 1, -1, -1):
        row = rows[c]
        acc = row[n]
        for k in range(c + 1, n):
            acc -= row[k] * x[k]
        x[c] = acc / row[c]
    return x


def _solve3(A: list, b: list) -> list:
    """:func:`solve_small` for three rows, unrolled (the KKT systems of two shifts and t): the same
    pivots and the same floating-point operations in the same order, ~2.5x faster."""
    r0, r1, r2 = (*A[0][:3], b[0]), (*A[1][:3], b[1]), (*A[2][:3], b[2])
    tiny = 1e-14 * max(map(abs, r0[:3] + r1[:3] + r2[:3]))
    # column 0: the first row with the largest |a_r0| pivots
    if abs(r1[0]) > abs(r0[0]):
        if abs(r2[0]) > abs(r1[0]):
            r0, r2 = r2, r0
        else:
            r0, r1 = r1, r0
    elif abs(r2[0]) > abs(r0[0]):
        r0, r2 = r2, r0
    r1, r2 = _cleared(r1, r0, 0, tiny), _cleared(r2, r0, 0, tiny)
    if abs(r2[1]) > abs(r1[1]):
        r1, r2 = r2, r1
    r2 = _cleared(r2, r1, 1, tiny)
    if abs(r2[2]) <= tiny:
        raise np.linalg.LinAlgError("singular active-set system")
    x2 = r2[3] / r2[2]
    x1 = (r1[3] - r1[2] * x2) / r1[1]
    acc = r0[3] - r0[1] * x1
    return [(acc - r0[2] * x2) / r0[0], x1, x2]


def _cleared(row: tuple, piv: tuple, c: int, tiny: float) -> tuple:
    """``row`` less the multiple of the pivot row that clears its column c (itself when that is 0)."""
    if abs(piv[c]) <= tiny:
        raise np.linalg.LinAlgError("singular active-set system")
    f = row[c] / piv[c]
    return (row[0] - f * piv[0], row[1] - f * piv[1], row[2] - f * piv[2], row[3] - f * piv[3]) if f else row


def multipliers(prob: Problem, w, act_p, act_m, ev):
    """λ of the active constraints from e_t + Σ λ_j ∇c_j = 0 (least squares)."""
    nv = prob.nvar
    _, _, GP, GM = ev(w[:nv])
    rows = active_rows(GP, GM, act_p, act_m)
    if not rows:
        return np.zeros(0), np.zeros(0)
    try:
        if len(rows) == nv + 1:   # a vertex: Rᵀ λ = −e_t is square
            lam = np.array(solve_small([list(col) for col in zip(*rows)], [0.0] * nv + [-1.0]))
        else:   # an edge (or a degenerate corner): least squares by the normal equations R Rᵀ λ = −R e_t
            A = [[sum(a * b for a, b in zip(r1, r2)) for r2 in rows] for r1 in rows]
            lam = np.array(solve_small(A, [-r[-1] for r in rows]))
    except np.linalg.LinAlgError:
        lam, *_ = np.linalg.lstsq(np.array(rows).T, -np.append(np.zeros(nv), 1.0), rcond=None)
    return lam[:len(act_p)], lam[len(act_p):]
