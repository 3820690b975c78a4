"""The planet's service life as a check of the whole set (ISO 6336-6) when the sun's spectrum reverses.

A planet is an idler between the sun and the ring: with the sun's torque positive the sun loads one flank of a planet
tooth (A) and the ring the other (B); a reversed bin swaps them. ISO 6336-6 sums damage per flank, so flank A's sum
is the sun mesh's positive bins with the ring mesh's negative ones, B the others, each bin on its own mesh's
stress; the root's fillets pair the same way (the root bends both ways, its limit times Y_M). Per-mesh checks
cannot hold that sum (each would pair the flanks within its own mesh), so the planet gets one check of the set with
a part per flank: each part the sum of the damage checks of each mesh's one-sided bins
(:func:`~geardesign.gears.strength.planetary_meshes.planetary_life` rates the same sums from the bins).

The terms are the set's mesh checks (``MeshCheck`` of :mod:`geardesign.gears.planetary`, passed in by it: this module
does not import it), so their gradients come carried to the set's shifts.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from . import checks as _checks
from .checks.damage import PittingDamage, RootDamage

__all__ = ["PlanetDamage", "planet_damage_checks", "one_sided", "is_planet_damage"]

# the planet's gear number in each mesh's pair: the sun-planet pair's gear 2, the planet-ring pair's gear 1
PLANET_GEAR = {"sun-planet": 2, "planet-ring": 1}


@dataclass(frozen=True)
class PlanetDamage(_checks.Check):
    """The planet's Miner damage sum D <= D_max for ``mode`` "H" (pitting) or "F" (root) under a reversing spectrum,
    summed across its two meshes per flank: parts (1 − D_A/D_max, 1 − D_B/D_max); ``flanks`` holds each flank's
    terms (mesh checks of one-sided damage, see the module docstring)."""

    mode: str = "H"
    flanks: tuple = ((), ())
    case: int = 1
    n_parts = 2
    fd_gradient = True

    def __post_init__(self):
        kind = "pitting_damage" if self.mode == "H" else "root_damage"
        case = "" if self.case == 1 else f"case{self.case}_"
        object.__setattr__(self, "name", self.name or f"set:{case}{kind}_planet")
        what = "flanks" if self.mode == "H" else "fillets"
        object.__setattr__(self, "label", self.label or f"{'pitting' if self.mode == 'H' else 'root'} damage of the "
                                                        f"planet, its {what} summed over both meshes, D <= "
                                                        f"{self.limit:g} (ISO 6336-6)")

    @property
    def colour(self):
        return (PittingDamage if self.mode == "H" else RootDamage).colour

    @property
    def costly(self):
        return any(t.costly for terms in self.flanks for t in terms)

    def modelled_at(self, geo):
        if not self.costly:
            return self
        return replace(self, flanks=tuple(tuple(t.modelled_at(geo) for t in terms) for terms in self.flanks))

    def flank_damage(self, geo) -> list:
        """D of flank (fillet) A and B at the designs of ``geo``."""
        return [sum((t.value(geo) for t in terms), 0.0 * geo["_m"]) for terms in self.flanks]

    def flank_damage_gradients(self, geo) -> list:
        """∂D/∂(x_s, x_p) of flank (fillet) A and B: each term's margin gradient is −∂D/∂x / D_max."""
        out = []
        for terms in self.flanks:
            g1 = g2 = 0.0
            for t in terms:
                a, b = t.gradient(geo)
                g1, g2 = g1 - a * t.limit, g2 - b * t.limit
            out.append((g1, g2))
        return out

    def value(self, geo):
        a, b = self.flank_damage(geo)
        return np.maximum(a, b)

    def margin(self, geo):
        return 1.0 - self.value(geo) / self.limit

    def part_margins(self, geo) -> list:
        return [1.0 - d / self.limit for d in self.flank_damage(geo)]

    def part_gradients(self, geo) -> list:
        return [(-g1 / self.limit, -g2 / self.limit) for g1, g2 in self.flank_damage_gradients(geo)]

    def gradient(self, geo):
        (a, b), grads = self.flank_damage(geo), self.part_gradients(geo)
        return tuple(np.where(a >= b, ga, gb)[()] for ga, gb in zip(*grads))


def one_sided(spectrum, positive: bool, life_h):
    """The bins of ``spectrum`` with torque > 0 (``positive``) or < 0, as a spectrum of their own, and the required
    life that keeps their cycles what they are in the whole spectrum's required life ``life_h`` (None: its
    duration): (spectrum, life_h), or (None, None) when no bin has that sign.

    >>> from geardesign.gears.spectrum import LoadSpectrum
    >>> s = LoadSpectrum.from_bins([300, -150, 200], 1000, time_h=[10, 5, 25])
    >>> sub, life = one_sided(s, False, 8000.0)
    >>> sub.torque_nm.tolist(), sub.time_h.tolist(), life       # 8000 h × 5/40
    ([-150.0], [5.0], 1000.0)
    """
    from .spectrum import LoadSpectrum

    sel = spectrum.torque_nm > 0 if positive else spectrum.torque_nm < 0
    if not sel.any():
        return None, None
    sub = LoadSpectrum(spectrum.torque_nm[sel], spectrum.n_rpm[sel], spectrum.time_h[sel], spectrum.on_gear)
    return sub, (None if life_h is None else life_h * sub.duration_h / spectrum.duration_h)


def is_planet_damage(check) -> bool:
    """True for a mesh check of the planet's own damage (gear 2 of the sun mesh, gear 1 of the ring mesh)."""
    inner = getattr(check, "inner", None)
    return isinstance(inner, (PittingDamage, RootDamage)) and inner.gear == PLANET_GEAR[check.mesh]


def planet_damage_checks(mesh_opts: dict, wrap) -> list:
    """The planet's damage checks of a set whose spectrum reverses: ``mesh_opts`` {mesh: its checks options, with its
    spectrum (or list of them)}, ``wrap(check, mesh)`` the set's mesh check of a pair's check. One
    :class:`PlanetDamage` per mode and load case."""
    spectra = {tag: o["spectrum"] if isinstance(o["spectrum"], (list, tuple)) else [o["spectrum"]]
               for tag, o in mesh_opts.items()}
    out = []
    for case in range(len(spectra["sun-planet"])):
        # terms[mesh][sign]: the planet's damage checks of that mesh's one-sided bins
        terms = {tag: {} for tag in mesh_opts}
        for tag, opts in mesh_opts.items():
            for positive in (True, False):
                sub, life = one_sided(spectra[tag][case], positive, opts.get("life_h"))
                if sub is None:
                    terms[tag][positive] = []
                    continue
                built = _checks.resolve_checks({**opts, "spectrum": sub, "life_h": life},
                                               internal=tag == "planet-ring")
                terms[tag][positive] = [wrap(c, tag) for c in built if isinstance(c, (PittingDamage, RootDamage))
                                        and c.gear == PLANET_GEAR[tag]]
        for cls, mode in ((PittingDamage, "H"), (RootDamage, "F")):
            def of(tag, positive, cls=cls, terms=terms):
                return tuple(t for t in terms[tag][positive] if isinstance(t.inner, cls))

            # flank A: the sun mesh's positive bins and the ring mesh's negative ones; flank B the others
            flanks = (of("sun-planet", True) + of("planet-ring", False), of("sun-planet", False) + of("planet-ring", True))
            limit = next((t.inner.limit for f in flanks for t in f), None)
            if limit is not None:
                out.append(PlanetDamage(limit=limit, mode=mode, flanks=flanks, case=case + 1))
    return out
