"""Hypothesis strategies shared by the property tests (tests/test_properties.py) and the float-path
tests (tests/gears/, tests/shifts/).

Random valid designs: z1, z2 in 5..400, x1, x2 in −0.8..2.5, m 0.5..20 mm, α 14.5..30°;
designs whose geometry does not exist (geardesign raises GearDesignError) are rejected with
``assume``. Reproducible: derandomize=True.
"""
from __future__ import annotations

import math

from hypothesis import assume, settings
from hypothesis import strategies as st

import geardesign as gd

SETTINGS = settings(max_examples=200, deadline=None, derandomize=True)


def _rack(alpha_deg: float) -> gd.BasicRack:
    """Standard rack at α; ρ_f* capped where 0.38 no longer fits on the cutter tip (steep α)."""
    a = math.radians(alpha_deg)
    land = math.pi / 2 - 2.0 * 1.25 * math.tan(a)
    rho_max = max(0.0, land * math.cos(a) / (2.0 * (1.0 - math.sin(a))))
    return gd.BasicRack(alpha_deg=alpha_deg, rho_f=min(0.38, 0.999 * rho_max))


@st.composite
def designs(draw, tip_shortening=None):
    d = dict(
        m=draw(st.floats(0.5, 20.0)),
        z1=draw(st.integers(5, 400)), z2=draw(st.integers(5, 400)),
        x1=draw(st.floats(-0.8, 2.5)), x2=draw(st.floats(-0.8, 2.5)),
        alpha_deg=draw(st.floats(14.5, 30.0)),
        ts=draw(st.booleans()) if tip_shortening is None else tip_shortening,
    )
    d["rack"] = _rack(d["alpha_deg"])
    try:
        d["geo"] = gd.pair_geometry(d["m"], d["z1"], d["z2"], d["x1"], d["x2"], rack=d["rack"],
                                    tip_shortening=d["ts"])
    except gd.GearDesignError:
        assume(False)
    return d


@st.composite
def kinds(draw):
    """Random valid helical and internal designs: β 0..45°, internal or not (the ring with 1..300
    teeth more than the pinion), a face width or none; otherwise as :func:`designs`."""
    internal = draw(st.booleans())
    z1 = draw(st.integers(5, 200))
    d = dict(
        m=draw(st.floats(0.5, 20.0)), z1=z1,
        z2=z1 + draw(st.integers(1, 300)) if internal else draw(st.integers(5, 400)),
        x1=draw(st.floats(-0.8, 2.5)), x2=draw(st.floats(-0.8, 2.5)),
        alpha_deg=draw(st.floats(14.5, 30.0)), ts=draw(st.booleans()),
        beta=draw(st.sampled_from([0.0, 8.0, 20.0, 45.0]) | st.floats(0.0, 45.0)),
        internal=internal, face=draw(st.none() | st.floats(1.0, 500.0)),
    )
    d["rack"] = _rack(d["alpha_deg"])
    d["mesh"] = gd.Mesh(d["z1"], d["z2"], d["rack"], d["ts"], d["beta"], internal, d["face"])
    try:
        d["geo"] = gd.pair_geometry(d["m"], d["z1"], d["z2"], d["x1"], d["x2"], rack=d["rack"],
                                    tip_shortening=d["ts"], beta_deg=d["beta"], internal=internal,
                                    face_width_mm=d["face"])
    except gd.GearDesignError:
        assume(False)
    return d
