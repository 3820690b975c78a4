"""Stage kinds: one object per kind of drive stage implementing :class:`StageKind` (its ratio span,
its options for the search, its margins in a batch, its part of ``analyse``, its scene keys and its
drawing), found by the drive, the search, the scenes and the diagram through the registry.

The built-in kinds, registered here in this order: ``given`` (a bought unit), ``gear`` (an external
gear pair), ``chain`` (a roller chain), ``worm`` (a worm gear pair). docs/extending.md shows how to add one.
"""
from .base import Batch, Designs, StageFlow, StageKind, kind_named, kind_names, kind_of, kinds, register, unregister
from .chain import ChainKind
from .gear import GearKind, set_sizing
from .given import GivenKind
from .worm import WormKind, WormStage, set_worm_efficiency

__all__ = ["StageKind", "StageFlow", "Designs", "Batch", "register", "unregister", "kind_of", "kind_named", "kind_names", "kinds",
           "GivenKind", "GearKind", "ChainKind", "set_sizing", "WormKind", "WormStage", "set_worm_efficiency"]

for _kind in (GivenKind(), GearKind(), ChainKind(), WormKind()):
    register(_kind)
