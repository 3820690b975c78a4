"""Life factor Z_NT for contact stress (ISO 6336-2:2019 clause 10, Table 2 and Figure 4): the S-N curves of
the reference test gears per material kind, straight lines between their table points in log-log scale."""
from __future__ import annotations

import functools
import math

from ...errors import GearDesignError
from .ops import ops_of

__all__ = ["contact_life_curve", "contact_life_factor", "load_cycles"]

# (N_L, Z_NT) points of ISO 6336-2:2019 Table 2. The last point is 0.85 at 10^10 cycles, or 1.0 with
# optimum lubrication, material, manufacturing and experience ("optimum").
_CURVES = {
    "pitting_permitted": ((6e5, 1.6), (1e7, 1.0), (1e9, 1.0), (1e10, 0.85)),   # St, V, GGG(perl), GTS, Eh, IF
    "no_pitting": ((1e5, 1.6), (5e7, 1.0), (1e10, 0.85)),                        # St, V, GGG(perl), GTS, Eh, IF
    "GG_NT_NV": ((1e5, 1.3), (2e6, 1.0), (1e10, 0.85)),                          # GG, GGG (ferr.), NT, NV
    "nitrocarburized": ((1e5, 1.1), (2e6, 1.0), (1e10, 0.85)),                   # NV (nitrocar.)
}
_KIND_CURVE = {"St": "no_pitting", "V": "no_pitting", "GGG(perl)": "no_pitting", "GTS": "no_pitting",
               "Eh": "no_pitting", "IF": "no_pitting", "GG": "GG_NT_NV", "GGG(ferr)": "GG_NT_NV", "NT": "GG_NT_NV",
               "NV(nitr)": "GG_NT_NV", "NV(nitrocar)": "nitrocarburized"}


def load_cycles(n_rpm, life_h, contacts_per_revolution=1):
    """N_L = 60·n·L_h·(meshes per revolution), the number of load cycles of a gear's tooth (ISO 6336-2:2019 3.2).

    >>> float(load_cycles(360, 50_000))          # ISO/TR 6336-30 ex. 1 pinion: 1.08e9
    1080000000.0
    """
    return 60.0 * ops_of(n_rpm).asarray(n_rpm) * life_h * contacts_per_revolution


def contact_life_curve(kind: str, pitting_permitted: bool = False, optimum: bool = False) -> tuple:
    """The (N_L, Z_NT) points of ISO 6336-2:2019 Table 2 for a material ``kind``; ``pitting_permitted``
    (St, V, GGG, GTS, Eh, IF only) moves the knee to 10^7 cycles; ``optimum`` ends the curve at 1.0 instead
    of 0.85.

    >>> contact_life_curve("Eh")
    ((100000.0, 1.6), (50000000.0, 1.0), (10000000000.0, 0.85))
    """
    if kind not in _KIND_CURVE:
        raise GearDesignError(f"kind must be one of {list(_KIND_CURVE)}, got {kind!r}")
    name = _KIND_CURVE[kind]
    if pitting_permitted and name == "no_pitting":
        name = "pitting_permitted"
    points = _CURVES[name]
    if optimum:
        points = points[:-1] + ((points[-1][0], 1.0),)
    return points


def contact_life_factor(N_L, kind: str, pitting_permitted: bool = False, optimum: bool = False):
    """Z_NT for N_L load cycles (ISO 6336-2:2019 Table 2): the static value below the first point, straight lines
    in log N_L – log Z_NT between the points, the 10^10 value beyond.

    >>> [round(float(z), 3) for z in contact_life_factor([1.08e9, 1.783e8], "Eh")]   # ISO/TR 6336-30 ex. 1: 0.91, 0.962
    [0.91, 0.962]
    """
    logs_n, logs_z = _log_curve(kind, pitting_permitted, optimum)
    xp = ops_of(N_L)
    return xp.exp(xp.interp(xp.log(xp.maximum(xp.asarray(N_L), 1.0)), logs_n, logs_z))


@functools.lru_cache(maxsize=None)
def _log_curve(kind, pitting_permitted, optimum):
    """The points of :func:`contact_life_curve` as (log N_L, log Z_NT) tuples."""
    pts = contact_life_curve(kind, bool(pitting_permitted), bool(optimum))
    return tuple(math.log(p[0]) for p in pts), tuple(math.log(p[1]) for p in pts)
