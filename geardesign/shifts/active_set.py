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
