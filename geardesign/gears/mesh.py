"""The description of one mesh, passed as one object through the stack.

A mesh is what stays fixed while the shifts move: the tooth counts, the basic rack that cuts
both gears, and whether the tips are shortened to keep the clearance. The geometry formulas,
the checks, the shift problem and its methods take a :class:`Mesh` instead of these as loose
arguments, so a new kind of mesh (internal, helical) is a new field here and a new case of
the formulas, not a new argument in every signature.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass, replace

import numpy as np

from ..errors import GearDesignError
from ..validate import one_number, require_bool, require_int, require_range
from .involute import _t_minus_atan
from .rack import STANDARD_RACK, BasicRack

__all__ = ["Mesh", "mesh_of", "Z_MIN", "Z_MAX", "BETA_RANGE_DEG", "FACE_WIDTH_RANGE_MM", "SectionConstants", "section_tuple"]

Z_MIN = 3        # smallest tooth count accepted
Z_MAX = 100_000  # largest tooth count accepted (the accuracy tests reach 10 000)
# Reference helix angle: spur (0) to 45°; double-helical and herringbone gears go up to ~45°,
# beyond it the axial force and the transverse pressure angle grow out of practical use. The hand
# (left/right) does not change the pair's geometry: give |β|.
BETA_RANGE_DEG = (0.0, 45.0)
FACE_WIDTH_RANGE_MM = (0.0, 1e6)   # open below: a positive face width


@dataclass(frozen=True)
class SectionConstants:
    """The rack's angles carried into the transverse section of a helical gear (ISO 21771:2007
    §4.2, eq. (9)–(17)): α_t = atan(tan α_n / cos β), m_t = m_n / cos β, β_b = atan(tan β cos α_t).
    For β = 0 every value is the spur one exactly (α_t is α itself, not atan(tan α))."""

    alpha_n: float          # normal pressure angle (the rack's), rad
    tan_n: float            # tan α_n: the profile shift moves the flank by x m_n tan α_n
    alpha_t: float          # transverse pressure angle, rad
    sin_t: float
    cos_t: float
    tan_t: float
    cos_beta: float         # m_t = m_n / cos β
    sin_beta: float
    cos_beta_b: float       # base helix: normal radii of curvature are ρ_t / cos β_b
    beta_b: float


@functools.lru_cache(maxsize=256)
def section_constants(alpha_n: float, beta: float) -> SectionConstants:
    """:class:`SectionConstants` of a rack angle α_n and a helix angle β (both in radians)."""
    if beta == 0.0:
        return SectionConstants(alpha_n, math.tan(alpha_n), alpha_n, math.sin(alpha_n), math.cos(alpha_n),
                                math.tan(alpha_n), 1.0, 0.0, 1.0, 0.0)
    cos_b = math.cos(beta)
    alpha_t = math.atan(math.tan(alpha_n) / cos_b)
    beta_b = math.atan(math.tan(beta) * math.cos(alpha_t))
    return SectionConstants(alpha_n, math.tan(alpha_n), alpha_t, math.sin(alpha_t), math.cos(alpha_t),
                            math.tan(alpha_t), cos_b, math.sin(beta), math.cos(beta_b), beta_b)


def kind_text(beta_deg: float, internal: bool) -> str:
    """The kind of pair in words, for titles: "" (external spur), " (internal, helical β = 12°)".

    >>> kind_text(12.0, True)
    ' (internal, helical β = 12°)'
    """
    words = (["internal"] if internal else []) + ([f"helical β = {beta_deg:g}°"] if beta_deg else [])
    return f" ({', '.join(words)})" if words else ""


@dataclass(frozen=True, eq=False)
class Mesh:
    """Tooth counts ``z1``, ``z2`` (whole numbers in [Z_MIN, Z_MAX]; integer arrays for a batch of
    pairs that share the rest), the basic ``rack`` of both gears, and ``tip_shortening``: both
    tips reduced by Δy·m so that the clearance stays c*·m (GOST 16532-70, Table 1, item 7;
    ISO 21771:2007 §5.4.6, k·m).

    ``beta_deg``: reference helix angle (0 = spur); the module and shifts are then normal ones and
    the geometry is transverse. ``internal``: gear 2 is a ring gear with z2 teeth (a positive
    count, z2 > z1). ``face_width_mm``: the face width b, for the overlap ratio ε_β (None: ε_β is
    unknown for a helical pair). Sign convention of internal pairs (GOST 19274-73, KHK): a positive
    x2 moves the ring's flanks away from its axis, so the tips and roots of the ring move outward,
    its teeth get thinner and the centre distance grows with x2 − x1.

    >>> Mesh(17, 26).ratio
    1.5294117647058822
    >>> Mesh(2, 26)
    Traceback (most recent call last):
    ...
    geardesign.errors.GearDesignError: z1 must be a whole number in [3, 100000], got 2
    >>> Mesh(24, 16, internal=True)
    Traceback (most recent call last):
    ...
    geardesign.errors.GearDesignError: an internal pair needs more teeth on the ring than on the pinion: z2 = 16 <= z1 = 24
    """

    z1: object
    z2: object
    rack: BasicRack = STANDARD_RACK   # None: the standard rack too
    tip_shortening: bool = True
    beta_deg: float = 0.0
    internal: bool = False
    face_width_mm: float | None = None

    def __post_init__(self):
        if self.rack is None:
            object.__setattr__(self, "rack", STANDARD_RACK)
        for name in ("z1", "z2"):
            v = getattr(self, name)
            if type(v) is int and Z_MIN <= v <= Z_MAX:   # the common case, without numpy's overhead
                continue
            z = require_int(name, v, Z_MIN, Z_MAX)
            object.__setattr__(self, name, int(z) if z.ndim == 0 else z)
        if not isinstance(self.rack, BasicRack):
            raise GearDesignError(f"rack must be a geardesign.BasicRack, got {type(self.rack).__name__}")
        if type(self.tip_shortening) is not bool:
            object.__setattr__(self, "tip_shortening", require_bool("tip_shortening", self.tip_shortening))
        if not (type(self.beta_deg) is float and BETA_RANGE_DEG[0] <= self.beta_deg <= BETA_RANGE_DEG[1]):
            object.__setattr__(self, "beta_deg", one_number("beta_deg", require_range(
                "beta_deg", self.beta_deg, *BETA_RANGE_DEG, unit="deg")))
        if type(self.internal) is not bool:
            object.__setattr__(self, "internal", require_bool("internal", self.internal))
        if self.face_width_mm is not None:
            object.__setattr__(self, "face_width_mm", one_number("face_width_mm", require_range(
                "face_width_mm", self.face_width_mm, *FACE_WIDTH_RANGE_MM, lo_open=True, unit="mm")))
        if self.internal and not (type(self.z1) is int and type(self.z2) is int and self.z2 > self.z1):
            z1, z2 = np.broadcast_arrays(np.asarray(self.z1), np.asarray(self.z2))
            short = np.atleast_1d(z2 <= z1)
            if short.any():
                i = int(np.flatnonzero(short)[0])
                where = f" (pair at index {i})" if z1.ndim else ""
                raise GearDesignError(f"an internal pair needs more teeth on the ring than on the pinion: "
                                      f"z2 = {int(z2.flat[i])} <= z1 = {int(z1.flat[i])}{where}")

    @property
    def section(self) -> SectionConstants:
        """The rack's angles in the transverse section (:class:`SectionConstants`)."""
        return section_constants(self.rack.alpha, math.radians(self.beta_deg))

    @property
    def sign(self) -> int:
        """+1 for an external pair, −1 for an internal one: z1 + sign·z2 and x1 + sign·x2 are the
        signed tooth and shift sums of ISO 21771 (where an internal gear has z < 0 and the
        opposite sign of x)."""
        return -1 if self.internal else 1

    @property
    def kind_text(self) -> str:
        """" (internal, helical β = 12°)" for the report titles; "" for an external spur pair."""
        return kind_text(self.beta_deg, self.internal)

    @property
    def ratio(self):
        """Gear ratio u = z2/z1."""
        return self.z2 / self.z1

    @property
    def is_batch(self) -> bool:
        """True when the tooth counts are arrays (many pairs, one rack)."""
        return not (type(self.z1) is int and type(self.z2) is int)   # validation made scalars ints

    def with_teeth(self, z1, z2) -> "Mesh":
        """The same rack and tips with other tooth counts."""
        return replace(self, z1=z1, z2=z2)

    def unchecked(self, z1, z2) -> "Mesh":
        """:meth:`with_teeth` for tooth counts that come from a validated mesh (floats or arrays
        of a geometry dict), without validating them again: finite differences call this often."""
        mesh = object.__new__(Mesh)
        mesh.__dict__.update(self.__dict__, z1=z1, z2=z2)
        return mesh


@functools.lru_cache(maxsize=64)
def section_tuple(rack: BasicRack, beta_deg: float) -> tuple:
    """α_t, sin α_t, cos α_t, tan α_t, inv α_t, sin²(α_t/2), h_l*, tan α_n, cos β, cos β_b of a rack
    and helix angle: the same floats on both backends, computed once (α_t = α for a spur pair)."""
    sc = section_constants(rack.alpha, math.radians(beta_deg))
    alpha = sc.alpha_t
    return (alpha, sc.sin_t, sc.cos_t, sc.tan_t, _t_minus_atan(sc.tan_t, math.sqrt), math.sin(alpha / 2.0) ** 2,
            rack.h_limit, sc.tan_n, sc.cos_beta, sc.cos_beta_b)


def mesh_of(mesh, z1, z2, rack=None, tip_shortening=True, beta_deg=0.0, internal=False, face_width_mm=None) -> Mesh:
    """The :class:`Mesh` of a call that takes either ``mesh=`` or the loose keywords (z1, z2 and the five
    of the mesh): a mesh given with any of them set is refused by name, rather than one silently winning.

    >>> m = mesh_of(Mesh(17, 26, beta_deg=12.0), None, None)
    >>> m.z1, m.beta_deg
    (17, 12.0)
    >>> mesh_of(Mesh(17, 26), None, None, internal=True)
    Traceback (most recent call last):
    ...
    geardesign.errors.GearDesignError: give the mesh either as mesh= or as internal, not both (mesh has internal=False)
    """
    if mesh is None:
        if z1 is None or z2 is None:
            raise GearDesignError("give the tooth counts z1 and z2, or a mesh= (a geardesign.Mesh)")
        return Mesh(z1, z2, rack, tip_shortening, beta_deg, internal, face_width_mm)
    if not isinstance(mesh, Mesh):
        raise GearDesignError(f"mesh must be a geardesign.Mesh, got {type(mesh).__name__}")
    given = [name for name, value, unset in (
        ("z1", z1, z1 is None), ("z2", z2, z2 is None), ("rack", rack, rack is None or rack == STANDARD_RACK),
        ("tip_shortening", tip_shortening, tip_shortening is True), ("beta_deg", beta_deg, beta_deg == 0.0),
        ("internal", internal, internal is False), ("face_width_mm", face_width_mm, face_width_mm is None))
        if not unset]
    if given:
        raise GearDesignError(f"give the mesh either as mesh= or as {', '.join(given)}, not both (mesh has "
                              + ", ".join(f"{k}={getattr(mesh, k)!r}" for k in given) + ")")
    return mesh
