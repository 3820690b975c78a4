"""The exact method: a pair whose objective the checks do not bound says there is no optimum."""
import numpy as np

import geardesign as gd


def test_a_pair_with_no_bounded_optimum_says_so():
    r = gd.optimize_shifts(80, 56, objective="max_eps_alpha", checks={"interference": False})
    assert not r.success and "no optimum" in r.message
    assert np.isfinite([r.fun, r.a_w, r.eps_alpha, *r.margins.values()]).all()
