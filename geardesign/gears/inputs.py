"""The ranges a pair's inputs may take, their validation, and the conditions for a design to exist
(each failure named with the input, its value and the range, or the design's index)."""
from __future__ import annotations

import numpy as np

from ..errors import GearDesignError
from ..validate import require_int, require_positive, require_range
from .mesh import Z_MAX, Z_MIN, Mesh, section_tuple

__all__ = ["M_RANGE_MM", "A_W_RANGE_MM", "X_ABS_MAX", "DESIGNS_MAX", "validate_inputs", "plain_inputs_ok", "require_module",
           "validate_geometry"]

M_RANGE_MM = (1e-4, 1e4)   # module: watch gears to mill gears with room to spare; outside, results overflow
# a centre distance: open below; above, past the largest pair the module and tooth-count ranges allow
# (1e4 mm · 2·1e5 teeth / 2 / cos 60° = 2e9 mm), so a value beyond it is a slip, refused before any formula overflows
A_W_RANGE_MM = (0.0, 1e10)
X_ABS_MAX = 10.0           # |x|: beyond a few units the tip or root crosses the base circle anyway
DESIGNS_MAX = 20_000_000   # designs in one vectorised call: ~1.5 GB of fields per million, so ~30 GB


def validate_inputs(m, z1, z2, x1, x2):
    """Check the raw inputs; return them as arrays (z as integers)."""
    m = require_module(m)
    z1 = require_int("z1", z1, Z_MIN, Z_MAX)
    z2 = require_int("z2", z2, Z_MIN, Z_MAX)
    x1 = require_range("x1", x1, -X_ABS_MAX, X_ABS_MAX)
    x2 = require_range("x2", x2, -X_ABS_MAX, X_ABS_MAX)
    return m, z1, z2, x1, x2


def plain_inputs_ok(m, x1, x2) -> bool:
    """True for Python floats/ints inside their ranges: the common case of one design, checked without numpy
    (the tooth counts are :class:`~geardesign.gears.mesh.Mesh`'s to check; anything else goes to
    :func:`validate_inputs`, which names what is wrong)."""
    return (type(m) in (float, int) and M_RANGE_MM[0] <= m <= M_RANGE_MM[1]
            and type(x1) in (float, int) and -X_ABS_MAX <= x1 <= X_ABS_MAX
            and type(x2) in (float, int) and -X_ABS_MAX <= x2 <= X_ABS_MAX)


def require_module(m):
    """The module in mm, inside :data:`M_RANGE_MM`."""
    return require_range("m (module)", require_positive("m (module)", m, unit="mm"), *M_RANGE_MM, unit="mm")


def _first(mask: np.ndarray) -> tuple[str, tuple]:
    idx = tuple(int(i) for i in np.argwhere(np.atleast_1d(mask))[0])
    where = "" if mask.ndim == 0 else f" (design at index {idx if len(idx) > 1 else idx[0]})"
    return where, idx if mask.ndim else ()


# the fields :func:`validate_geometry` reads (g_alpha and eps_alpha with ``contact``)
_VALIDATION_FIELDS = frozenset({"_z1", "_z2", "_x1", "_x2", "inv_alpha_w", "_gap1", "_gap2", "_k", "da1", "da2",
                                "db1", "db2", "df1", "df2"})


def validate_geometry(geo: dict, mesh: Mesh, contact: bool = False) -> None:
    """Raise a GearDesignError for designs whose geometry does not exist and, with ``contact``,
    for gears that do not mesh (path of contact <= 0: the tips do not reach across the line of
    action). :class:`~geardesign.GearPair` asks for contact; the vectorised
    :func:`pair_geometry` reports such designs with g_alpha <= 0 (and ε_α <= 0), as the
    regions and atlases need every design of a grid."""
    rack = mesh.rack
    alpha_t, sin_t, _, _, inv_t, s2h, _, tan_n, cos_b, _ = section_tuple(rack, mesh.beta_deg)
    internal = mesh.internal
    zs = geo["_z2"] - geo["_z1"] if internal else geo["_z1"] + geo["_z2"]
    xs_all = geo["_x2"] - geo["_x1"] if internal else geo["_x1"] + geo["_x2"]
    xs_name, zs_name = ("x2 - x1", "z2 - z1") if internal else ("x1 + x2", "z1 + z2")
    bad = ~(geo["inv_alpha_w"] > 0)
    if bad.any():
        where, i = _first(bad)
        lo = -float(zs[i]) * inv_t / (2.0 * tan_n)
        raise GearDesignError(
            f"{xs_name} = {xs_all[i]:.6g}{where} is too negative: inv alpha_w must be > 0, "
            f"so {xs_name} must be > {lo:.6g} for {zs_name} = {int(zs[i])}")
    for j in (1, 2):
        ring = internal and j == 2
        bad = ~(geo[f"_gap{j}"] > 0)
        if bad.any():
            where, i = _first(bad)
            z, x = geo[f"_z{j}"][i], geo[f"_x{j}"][i]
            k = geo["_k"][i]
            # gap = m(z sin²(α_t/2)/cos β ± (h_a* ± x − k)) > 0, solved for x
            limit = (rack.ha - k - z * s2h / cos_b) if ring else (k - rack.ha - z * s2h / cos_b)
            raise GearDesignError(
                f"x{j} = {x:.6g}{where}: the tip circle of gear {j} (d_a{j} = {geo[f'da{j}'][i]:.6g}) "
                f"is inside its base circle (d_b{j} = {geo[f'db{j}'][i]:.6g}); x{j} must be > "
                f"{float(limit):.6g} for z{j} = {int(z)}")
        bad = ~(geo[f"df{j}"] > 0)
        if bad.any():
            where, i = _first(bad)
            z, x = geo[f"_z{j}"][i], geo[f"_x{j}"][i]
            raise GearDesignError(
                f"x{j} = {x:.6g}{where}: the root diameter of gear {j} is not positive; "
                f"x{j} must be > {rack.ha + rack.c - z / cos_b / 2.0:.6g} for z{j} = {int(z)}")
    bad = ~(geo["g_alpha"] > 0) if contact else None
    if contact and bad.any():
        where, i = _first(bad)
        raise GearDesignError(
            f"the gears do not mesh{where}: their tip circles do not overlap along the line of action "
            f"(path of contact {float(np.asarray(geo['g_alpha'])[i]):.6g} mm, "
            f"eps_alpha {float(np.asarray(geo['eps_alpha'])[i]):.4g}); "
            f"{xs_name} = {float(xs_all[i]):.6g} is too large for these tips")
