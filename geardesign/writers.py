"""Writers that an upper layer registers for the objects of a lower one.

The layers import only downward (``geardesign/__init__.py``), so a lower object cannot reach the
code that writes its report: a pair's report draws the blocking contour (shifts) and the mesh
(profiles), which sit above the gears. The upper side registers its function here under a name
and the lower object asks for it by that name; nothing in the lower layer imports upward.
The package's name table registers the reports (loaded on their first call), so
``GearPair.report`` works after a plain ``import geardesign``.

>>> register("demo", lambda obj: f"written {obj}")
>>> writer("demo")(3)
'written 3'
>>> writer("nothing")
Traceback (most recent call last):
...
geardesign.errors.GearDesignError: no writer 'nothing' is registered (registered: demo, pair_report)
"""
from __future__ import annotations

__all__ = ["register", "writer"]

_WRITERS: dict = {}


def register(name: str, fn) -> None:
    """Register ``fn`` as the writer called ``name`` (replaces one registered before)."""
    if not callable(fn):
        from .errors import GearDesignError   # here: the package's own import loads nothing but this registry
        raise GearDesignError(f"the writer {name!r} must be callable, got {type(fn).__name__}")
    _WRITERS[name] = fn


def writer(name: str):
    """The writer registered as ``name``."""
    fn = _WRITERS.get(name)
    if fn is None:
        from .errors import GearDesignError
        raise GearDesignError(f"no writer {name!r} is registered (registered: {', '.join(sorted(_WRITERS)) or 'none'})")
    return fn
