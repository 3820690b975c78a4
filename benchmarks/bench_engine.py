"""Issue 38's goal: the torque curve of a four-cylinder engine over its 720° cycle at 720 points in ≤ 1 ms.

Timed (CPU, best of the repeats, this process):

* ``engine_torque(engine, 720)``: the library's whole job — the indicator diagram read, every cylinder's kinetostatics
  (joint forces of the piston, rod and crank with the rod's mass and moment of inertia, the weights), the firing
  phases, the journal and crank-pin torques, the mean, μ, the reversals and the excess work;
* a plain reference written here: the textbook torque of gas and reciprocating masses,
  M = (F_g − m_j·a)·r·sin(φ + β)/cos β for the four cylinders at their own angles (Kolchin & Demidov 1980 §10),
  straight-line numpy with no checks — the same numbers as the library's for a massless rod with no weights
  (``tests/test_benchmarks.py`` checks that).

The ratio library/plain says what the full model and its checks cost over the bare formula.

Run: python benchmarks/bench_engine.py [repeats]
Prints figures; asserts nothing (speed is measured, not tested).
"""
from __future__ import annotations

import sys

import numpy as np

from geardesign.mechanism.engine import Engine, engine_torque
from geardesign.mechanism.pressure import IndicatorDiagram
from geardesign.mechanism.slider_crank import SliderCrank

R, L, BORE, N_RPM = 45.0, 150.0, 86.0, 3000.0
PHASES = np.array([0.0, 540.0, 180.0, 360.0])          # the in-line four, 1-3-4-2


def diagram() -> IndicatorDiagram:
    return IndicatorDiagram.otto(R, L, 10.0, peak_pressure_mpa=7.0)


def engine() -> Engine:
    mech = SliderCrank(R, L, rod_cg_mm=45, piston_mass_kg=0.6, rod_mass_kg=0.7, rod_inertia_kg_m2=0.003,
                       crank_mass_kg=2.0, crank_cg_mm=10, cylinder_bore_mm=BORE)
    return Engine(mech, diagram(), N_RPM, cylinders=4, throws_deg=(0, 180, 180, 0), firing_order=(1, 3, 4, 2))


def plain_torque(phi_table, p_table, m_j, points=720, crankcase=0.101325):
    """The summed torque of four cylinders, M = (F_g − m_j·a)·r·sin(φ + β)/cos β, straight numpy (N·m)."""
    phi = np.arange(points) * (720.0 / points)
    own = phi[None, :] - PHASES[:, None]
    p = np.interp(np.mod(own, 720.0), phi_table, p_table, period=720.0)
    fg = (p - crankcase) * np.pi * BORE * BORE / 4
    t = np.radians(own)
    lam = R / L
    sp, cp = np.sin(t), np.cos(t)
    sb = lam * sp
    cb = np.sqrt(1 - sb * sb)
    w = np.pi * N_RPM / 30
    a = w * w * R / 1000 * (cp - sp * sb / cb + lam * cp * cp / cb ** 3)
    return ((fg - m_j * a) * R / 1000 * (sp * cb + cp * sb) / cb).sum(axis=0)


from functools import partial

import timing

best = partial(timing.best, repeat=7, number=50)    # CPU time per call, the best of several rounds (benchmarks/timing.py)


def main(repeat: int = 7) -> None:
    e = engine()
    d = e.diagram
    m_j = e.mechanism.piston_mass_kg
    lib = best(lambda: engine_torque(e, 720), repeat=repeat)
    ref = best(lambda: plain_torque(d.crank_angle_deg, d.pressure_mpa, m_j), repeat=repeat)
    print(f"engine_torque, 4 cylinders, 720 points: {lib * 1e6:8.1f} µs CPU  (goal ≤ 1000 µs: "
          f"{'met' if lib <= 1e-3 else 'NOT met'})")
    print(f"plain reference (gas + piston inertia, no checks): {ref * 1e6:8.1f} µs CPU")
    print(f"ratio library / plain: {lib / ref:.2f}x")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 7)
