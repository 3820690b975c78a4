"""Re-checking what the solvers return, for the fuzzing (tests/fuzzcases.py): every optimum, and
every row a search marks feasible, is rebuilt as a ``GearPair`` / ``PlanetarySet`` and must exist,
mesh and hold the checks the solver held. A failure by more than FEASIBILITY_SLACK is a design that
fails its own checks; by less, it is issue 29 §2's tolerance (the solver and ``checks()`` do not
share one yet), counted apart.
"""
from __future__ import annotations

import geardesign as gd


class FailsChecks(Exception):
    """A returned optimum (or a row marked feasible) that its own checks refuse."""


class FeasibilityTol(Exception):
    """The same, by at most FEASIBILITY_SLACK: issue 29 §2's tolerance, counted apart."""


FEASIBILITY_SLACK = 1e-9
# GearPair.checks() takes these options of a checks dict; the others (radial_assembly, cutter, ...)
# are judged by the solver's own margins of the same names
_PAIR_OPTIONS = ("eps_alpha_min", "sa_min", "undercut", "interference", "eps_gamma_min")


def _judge(table, names, what: str) -> None:
    rows = table[table["check"].isin(names)] if names is not None else table
    worst = rows["margin"].min() if len(rows) else 0.0
    if worst < -FEASIBILITY_SLACK:
        bad = rows.loc[rows["margin"].idxmin()]
        raise FailsChecks(f"{what}: {bad['check']} margin {bad['margin']:.3g} on re-check")
    if len(rows) and not rows["ok"].all():
        raise FeasibilityTol(f"{what}: ok False at margin {worst:.3g} (issue 29 §2)")


def recheck_pair(m, z1, z2, x1, x2, checks=None, rack=None, what="optimum", margins=None, **kind) -> None:
    """Re-check one design with GearPair: it must exist and mesh (else FailsChecks), and hold
    the checks the solver held (those of ``margins``' names that GearPair.checks() has)."""
    try:
        pair = gd.GearPair(m, int(z1), int(z2), float(x1), float(x2), rack=rack, **kind)
    except gd.GearDesignError as exc:
        raise FailsChecks(f"{what} ({z1}/{z2} at x = {x1:.6g}, {x2:.6g}, m = {m:g}) refused: {exc}"[:300]) from None
    opts = {k: v for k, v in (checks or {}).items() if k in _PAIR_OPTIONS} if isinstance(checks, dict) else {}
    if isinstance(checks, (list, tuple)):
        opts = dict(eps_alpha_min=None, sa_min=None, undercut=False, interference=False)
    try:
        table = pair.checks(jamming=False, **opts)
    except gd.GearDesignError:
        return            # a checks dict the solver refused too
    _judge(table, None if margins is None else list(margins), what)


def recheck_shift_result(r, m, checks, rack, kind) -> None:
    if getattr(r, "success", False):
        recheck_pair(m if m is not None else 1.0, r.z1, r.z2, r.x1, r.x2, checks, rack, "optimum", r.margins, **kind)


def recheck_set(m, z_s, z_p, z_r, n, x_s, x_p, x_r, checks=None, rack=None, what="optimum", **kw) -> None:
    try:
        s = gd.PlanetarySet(m, int(z_s), int(z_p), int(z_r), int(n), float(x_s), float(x_p), float(x_r),
                            rack=rack, **kw)
        table = s.checks(checks if isinstance(checks, dict) else None)
    except gd.GearDesignError as exc:
        raise FailsChecks(f"{what} set {z_s}/{z_p}/{z_r} refused: {exc}"[:300]) from None
    _judge(table, None, what)


