"""Worm pair efficiency and rating speed, as ratios against a plain reference written here (this machine drifts):

* ``WormPair(...)`` (the DIN 3975 geometry, branch wormgeo) and its ``.rating(...)``: geometry, efficiency and
  rating of one pair, the issue's 200 µs;
* ``worm_rating`` of one pair (geometry from m_x, z1, z2, q; sliding speed, AGMA friction, efficiencies both ways,
  self-locking, forces, deflection, heat balance, the given-factor contact and root checks, the result object with
  its factor table rows) and ``load_capacity`` on it;
* the vectorised efficiency functions over N designs (sliding speed, friction, η both ways), in designs/s;
* the AGMA 6034 row alone: ``agma.agma_load_float`` (one design in floats) against the array functions chained;
* reference: the same quantities for one pair in plain-Python floats (math module), no validation, no result.

The issue's goal: one worm pair's geometry, efficiency and rating <= 200 µs.

Times are CPU times of this process (time.process_time). Run: python benchmarks/bench_worm_rating.py [N]
Prints figures; asserts nothing (speed is measured, not tested).
"""
import math
import sys

import numpy as np

from geardesign.gears.worm import efficiency as eff
from geardesign.gears.worm.rating import load_capacity, worm_rating


from functools import partial

import timing

best = partial(timing.best, repeat=5, number=200)    # CPU time per call, the best of several rounds (benchmarks/timing.py)


def plain_pair(T2=600.0, n1=1500.0, m_x=6.3, z1=2, z2=41, q=10.0, alpha=20.0, l_1=260.0, k=28.0, A=1.1, p0=60.0):
    """The rating's numbers for one pair in plain floats (reference for the ratio)."""
    d1, d2 = q * m_x, z2 * m_x
    g = math.atan(z1 / q)
    vg = d1 * n1 * math.pi / (60000 * math.cos(g))
    vs = vg * 60 / 0.3048
    mu = 0.103 * math.exp(-0.110 * vs ** 0.45) + 0.012 if vs > 10 else 0.124 * math.exp(-0.074 * vs ** 0.645)
    a = math.radians(alpha)
    rho = math.atan(mu / math.cos(a))
    eta = math.tan(g) / math.tan(g + rho)
    eta_r = math.tan(g - rho) / math.tan(g)
    Ft2 = 2000 * T2 / d2
    Ft1 = Ft2 * math.tan(g + rho)
    Fr = Ft2 * math.tan(a) * math.cos(rho) / math.cos(g + rho)
    df1 = d1 - 2.5 * m_x
    delta = math.hypot(Ft1, Fr) * l_1 ** 3 / (48 * 206000 * math.pi * df1 ** 4 / 64)
    P2 = T2 * n1 / (z2 / z1) * math.pi / 30
    PV = P2 / eta - P2 + p0
    return eta, eta_r, delta, 20 + PV / (k * A), k * A * 70 / PV


def main(n=100_000):
    kw = dict(l_1=260.0, k_heat=28.0, A_housing=1.1, P_V0=60.0, p_m_star=0.9, E_red=150000.0, sigma_HG=400.0,
              b_2=55.0, Y_root=1.2, tau_FG=90.0)
    t_ref = best(plain_pair, number=2000)
    t_rate = best(lambda: worm_rating(600.0, 1500.0, 6.3, 2, 41, 10.0, **kw))
    r = worm_rating(600.0, 1500.0, 6.3, 2, 41, 10.0, **kw)
    t_cap = best(lambda: load_capacity(r, P_const=60.0), number=2000)
    print(f"plain-float reference, one pair:        {t_ref * 1e6:8.1f} µs")
    print(f"worm_rating, one pair (all checks):     {t_rate * 1e6:8.1f} µs   ratio {t_rate / t_ref:6.1f}")
    print(f"load_capacity on a rating:              {t_cap * 1e6:8.1f} µs")
    from geardesign import WormPair

    def pair_and_rating():
        return WormPair(6.3, 2, 41, 10.0, face_width_mm=55.0).rating(
            600.0, 1500.0, **{k: v for k, v in kw.items() if k != "b_2"})
    t_pair = best(pair_and_rating)
    print(f"WormPair(...) + .rating(...), one pair: {t_pair * 1e6:8.1f} µs   ratio {t_pair / t_ref:6.1f}"
          "   (the issue's goal: geometry, efficiency and rating <= 200 µs)")

    def with_agma():
        return WormPair(6.3, 2, 41, 10.0, face_width_mm=55.0).rating(
            600.0, 1500.0, casting="centrifugal", **{k: v for k, v in kw.items() if k != "b_2"})
    t_agma = best(with_agma)
    print(f"  the same with the AGMA row (casting): {t_agma * 1e6:8.1f} µs   ratio {t_agma / t_ref:6.1f}")

    from geardesign.gears.worm import agma
    row = (160.0, 250.0, 62.5, 45.0, 12.5, 5.0, 17.7, 20.0, 0.03, 800.0, 0.9, "centrifugal", 1.0)

    def array_row(a, d_2, d_m1, b_2, u, v_g, g, al, mu, T2, eta, casting, K_A):
        C_s, C_m = agma.materials_factor(a, d_2, casting), agma.ratio_correction_factor(u)
        C_v, F_e = agma.velocity_factor(v_g), agma.effective_face_width(b_2, d_m1)
        W_f = agma.friction_force(2000.0 * T2 / d_2, mu, g, al)
        return (agma.allowable_tangential_load(C_s, d_2, F_e, C_m, C_v), agma.design_tangential_load(T2, d_2, eta, K_A),
                agma.friction_power(W_f, v_g))
    t_row_f = best(lambda: agma.agma_load_float(*row), number=2000)
    t_row_a = best(lambda: array_row(*row), number=2000)
    print(f"  its AGMA row alone: float path {t_row_f * 1e6:6.1f} µs, the array functions {t_row_a * 1e6:6.1f} µs")

    rng = np.random.default_rng(1)
    d, n1, g = rng.uniform(20, 200, n), rng.uniform(100, 3000, n), rng.uniform(2, 30, n)

    def vectorised():
        v = eff.sliding_speed(d, n1, g)
        mu = eff.friction_coefficient_agma(v)
        return eff.efficiency_worm_driving(g, mu, 20.0), eff.efficiency_wheel_driving(g, mu, 20.0)

    t_vec = best(vectorised, repeat=3, number=3)
    t_loop = best(lambda: [plain_pair(n1=float(n1[i]), q=float(d[i]) / 6.3) for i in range(1000)], repeat=3, number=1)
    print(f"vectorised efficiency, {n} designs:  {n / t_vec:12.3g} designs/s   "
          f"(plain-float loop: {1000 / t_loop:9.3g} pairs/s of the whole rating)")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 100_000)
