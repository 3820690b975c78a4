"""The description of one mesh, passed as one object through the stack.

A mesh is what stays fixed while the shifts move: the tooth counts, the basic rack that cuts
both gears, and whether the tips are shortened to keep the clearance. The geometry formulas,
the checks, the shift problem and its methods take a :class:`Mesh` instead of these as loose
arguments, so a new kind of mesh (internal, helical) is a new field here and a new case of
the formulas, not a new argument in every signature.
"""
from __future__ import annotations

from dataclasses import dataclass, replace


from ..errors import GearDesignError
from ..validate import require_bool, require_int
from .rack import STANDARD_RACK, BasicRack

__all__ = ["Mesh", "Z_MIN", "Z_MAX"]

Z_MIN = 3        # smallest tooth count accepted
Z_MAX = 100_000  # largest tooth count accepted (the accuracy tests reach 10 000)


@dataclass(frozen=True, eq=False)
class Mesh:
    """Tooth counts ``z1``, ``z2`` (whole numbers in [Z_MIN, Z_MAX]; integer arrays for a batch of
    pairs that share the rest), the basic ``rack`` of both gears, and ``tip_shortening``: both
    tips reduced by Δy·m so that the clearance stays c*·m (GOST 16532-70, Table 1, item 7;
    ISO 21771:2007 §5.4.6, k·m).

    >>> Mesh(17, 26).ratio
    1.5294117647058822
    >>> Mesh(2, 26)
    Traceback (most recent call last):
    ...
    geardesign.errors.GearDesignError: z1 must be a whole number in [3, 100000], got 2
    """

    z1: object
    z2: object
    rack: BasicRack = STANDARD_RACK   # None: the standard rack too
    tip_shortening: bool = True

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
