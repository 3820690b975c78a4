"""The exact method: a pair whose objective the checks do not bound says there is no optimum."""
import numpy as np

import geardesign as gd


def test_a_pair_with_no_bounded_optimum_says_so():
    r = gd.optimize_shifts(80, 56, objective="max_eps_alpha", checks={"interference": False})
    assert not r.success and "no optimum" in r.message
    assert np.isfinite([r.fun, r.a_w, r.eps_alpha, *r.margins.values()]).all()


def test_a_start_node_that_misses_a_check_does_not_bar_the_kkt_point(monkeypatch):
    """The ring 27/89's second start node lies just outside the region (undercut1 and interference2 missed by
    ~0.03) and scores above the optimum there; Newton from it reaches the undercut1/interference2 vertex, which was
    refused for scoring below that infeasible start, so the solve fell back to SLSQP (issue 36 §3: internal
    pairs 2.1x spur's time). Now no SLSQP runs, and the vertex is the one-start answer."""
    from geardesign.shifts import kkt

    def no_slsqp(*args, **kwargs):
        raise AssertionError("SLSQP ran")

    monkeypatch.setattr(kkt, "slsqp", no_slsqp)
    r = gd.optimize_shifts(27, 89, internal=True)
    assert r.success and set(r.active) == {"undercut1", "interference2"}
    assert "best of 2 starts" in r.message
