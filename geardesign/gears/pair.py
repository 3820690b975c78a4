"""One gear pair as an object: inputs, geometry, checks."""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from . import checks as _checks
from ..errors import GearDesignError
from ..validate import hint_unknown_arguments, ndim, one_number, require_positive, require_range
from ..writers import writer
from .geometry import (X_ABS_MAX, Geometry, center_distance_from_x_sum, mesh_geometry,
                       mesh_geometry_float, min_center_distance, validate_geometry, validate_inputs,
                       x_sum_from_center_distance)
from .inputs import plain_inputs_ok
from .mesh import Mesh
from .rack import STANDARD_RACK, BasicRack

__all__ = ["GearPair", "balanced_sliding_split", "PAIR_CHECK_COLUMNS"]

# the columns of GearPair.checks: margin and ok first, a plain session shows the columns that fit its width
PAIR_CHECK_COLUMNS = ("check", "margin", "ok", "value", "limit", "label")

def balanced_sliding_split(m, z1, z2, x_sum, rack: BasicRack = BasicRack(), tip_shortening: bool = True,
                           mesh: Mesh | None = None) -> float:
    """x1 of the split of ``x_sum`` that equalises the specific sliding at the roots of both gears.

    Equal ϑ at the two ends of the path of contact is the classic distribution rule for
    closed gearing (GOST 16532-70 appendix; Kudryavtsev's blocking-contour practice). Solved
    with Brent's method on ϑ1,root(x1) − ϑ2,root(x_sum − x1), increasing in x1.
    Falls back to the split in inverse proportion to z (x1 = x_Σ z2/(z1+z2)) when no such
    point exists for this x-sum. ``mesh`` (helical, internal) overrides the tooth counts, rack and
    tip rule; for an internal pair x_Σ = x2 − x1, so x2 = x_Σ + x1.
    """
    from scipy.optimize import brentq   # here: importing scipy.optimize costs more than a GearPair

    mesh = Mesh(z1, z2, rack, tip_shortening) if mesh is None else mesh
    sgn = mesh.sign

    def f(x1):
        geo = mesh_geometry_float(mesh, m, x1, x_sum - sgn * x1)
        return geo["sliding1_root"] - geo["sliding2_root"]

    grid = x_sum / 2.0 + np.linspace(-3.0, 3.0, 1201) if sgn > 0 else np.linspace(-3.0, 3.0, 1201)
    geo = mesh_geometry(mesh, m, grid, x_sum - sgn * grid)
    ok = (geo["rho_p1"] > 0) & (geo["rho_p2"] > 0) & (geo["_gap1"] > 0) & (geo["_gap2"] > 0)
    diff = geo["sliding1_root"] - geo["sliding2_root"]
    idx = np.flatnonzero(ok[:-1] & ok[1:] & (np.sign(diff[:-1]) != np.sign(diff[1:])))
    if idx.size == 0:
        return float(x_sum * z2 / (z1 + z2)) if sgn > 0 else 0.0
    i = idx[0]
    return float(brentq(f, grid[i], grid[i + 1], xtol=1e-14, rtol=1e-15))


def _exists(geo: dict) -> bool:
    """The conditions :func:`validate_geometry` checks with contact, on one float design."""
    return (geo["inv_alpha_w"] > 0 and geo["_gap1"] > 0 and geo["_gap2"] > 0 and geo["df1"] > 0
            and geo["df2"] > 0 and geo["g_alpha"] > 0)


@dataclass(frozen=True)
class GearPair:
    """A spur or helical, external or internal gear pair.

    Parameters
    ----------
    m : module, mm (the normal module of a helical pair).  z1, z2 : tooth counts (whole numbers >= 3).
    x1, x2 : profile shift coefficients (normal).  rack : the :class:`BasicRack` (standard by default).
    tip_shortening : reduce both tips by Δy·m so the clearance stays c*·m (GOST 16532-70);
        ``False`` keeps d_a = d + 2(h_a* + x)m. Internal pairs keep their tips either way.
    beta_deg : reference helix angle, 0..45° (0: spur).  internal : gear 2 is a ring with z2 > z1
        teeth (GOST 19274-73 sign convention: a positive x2 moves the ring's flanks outward).
    face_width_mm : face width b, mm, for the overlap ratio ε_β (None: ε_β unknown for a helical pair).

    >>> p = GearPair(8, 17, 26, 0.898, 0.517)          # seed 000's engine pair
    >>> round(p.geometry().alpha_w_deg, 2)             # the seed prints 26°08'; inv α_w gives 27.13°
    27.13
    >>> bool(p.checks().set_index("check").loc["contact_ratio", "ok"])   # ε_α = 1.153 < 1.2
    False
    """

    m: float
    z1: int
    z2: int
    x1: float = 0.0
    x2: float = 0.0
    rack: BasicRack = STANDARD_RACK
    tip_shortening: bool = True
    beta_deg: float = 0.0
    internal: bool = False
    face_width_mm: float | None = None

    def __post_init__(self):
        if not plain_inputs_ok(self.m, self.x1, self.x2):   # anything but plain numbers in range: by name
            for name in ("m", "z1", "z2", "x1", "x2"):
                if ndim(getattr(self, name)) != 0:
                    raise GearDesignError(f"{name} must be a single number for GearPair (use pair_geometry for arrays)")
            m, _, _, x1, x2 = validate_inputs(self.m, 3, 3, self.x1, self.x2)
            object.__setattr__(self, "m", float(m))
            object.__setattr__(self, "x1", float(x1))
            object.__setattr__(self, "x2", float(x2))
        mesh = Mesh(self.z1, self.z2, self.rack, self.tip_shortening, self.beta_deg, self.internal, self.face_width_mm)
        if mesh.is_batch:
            raise GearDesignError("z1 and z2 must be single numbers for GearPair (use pair_geometry for arrays)")
        for name in ("z1", "z2", "rack", "tip_shortening", "beta_deg", "internal"):
            object.__setattr__(self, name, getattr(mesh, name))
        object.__setattr__(self, "face_width_mm", mesh.face_width_mm)
        geo = mesh_geometry_float(mesh, self.m, self.x1, self.x2)
        if not _exists(geo):   # the array path names what is wrong, and where
            validate_geometry(mesh_geometry(mesh, self.m, self.x1, self.x2), mesh, contact=True)
        object.__setattr__(self, "_geo", geo)
        object.__setattr__(self, "mesh", mesh)

    @classmethod
    def from_mesh(cls, m, mesh: Mesh, x1: float = 0.0, x2: float = 0.0) -> "GearPair":
        """The pair of module ``m`` (mm) and shifts ``x1``, ``x2`` on a :class:`~geardesign.gears.mesh.Mesh` (its tooth
        counts, rack, tips, helix angle, kind and face width): the mesh is described once and passed on.

        >>> GearPair.from_mesh(8, Mesh(17, 26), 0.898, 0.517) == GearPair(8, 17, 26, 0.898, 0.517)
        True
        """
        if not isinstance(mesh, Mesh):
            raise GearDesignError(f"mesh must be a geardesign.Mesh, got {type(mesh).__name__}")
        if mesh.is_batch:
            raise GearDesignError("z1 and z2 must be single numbers for GearPair (use pair_geometry for arrays)")
        return cls(m, mesh.z1, mesh.z2, x1, x2, mesh.rack, mesh.tip_shortening, mesh.beta_deg, mesh.internal,
                   mesh.face_width_mm)

    @classmethod
    def from_center_distance(cls, m, z1, z2, a_w, x1=None, rack: BasicRack | None = None,
                             tip_shortening: bool = True, beta_deg: float = 0.0, internal: bool = False,
                             face_width_mm: float | None = None) -> "GearPair":
        """The pair whose x-sum gives the operating centre distance ``a_w`` (mm) at zero backlash.

        ``x1`` fixes the split (x2 = x_Σ − x1; for an internal pair x2 = x_Σ + x1, x_Σ = x2 − x1);
        with ``x1=None`` the split equalises the specific sliding at both roots
        (:func:`balanced_sliding_split`).

        >>> p = GearPair.from_center_distance(3, 12, 24, 56.4999, x1=0.6)   # KHK: x_Σ = 0.960013
        >>> round(p.x1 + p.x2, 6)
        0.960013
        """
        rack = BasicRack() if rack is None else rack
        if not isinstance(rack, BasicRack):
            raise GearDesignError(f"rack must be a geardesign.BasicRack, got {type(rack).__name__}")
        for name, value in (("m", m), ("z1", z1), ("z2", z2)):
            if ndim(value) != 0:
                raise GearDesignError(f"{name} must be one number for GearPair.from_center_distance, got {value!r}")
        m_arr, z1_arr, z2_arr, _, _ = validate_inputs(m, z1, z2, 0.0, 0.0)
        a_w = one_number("a_w (center distance)", require_positive("a_w (center distance)", a_w, unit="mm"))
        m, z1, z2 = float(m_arr), int(z1_arr), int(z2_arr)
        mesh = Mesh(z1, z2, rack, tip_shortening, beta_deg, internal, face_width_mm)
        a_min = float(min_center_distance(m, z1, z2, rack, mesh.beta_deg, mesh.internal))
        if a_w <= a_min:
            raise GearDesignError(
                f"a_w = {a_w:g} mm is too small: it must be > a·cos(alpha) = {a_min:.6g} mm "
                f"for m = {m:g}, " + (f"z2 - z1 = {z2 - z1}" if mesh.internal else f"z1 + z2 = {z1 + z2}"))
        # beyond the a_w of x_Σ = 2·X_ABS_MAX no pair of gears exists; refused before inv α_w overflows
        a_max = float(center_distance_from_x_sum(m, z1, z2, 2 * X_ABS_MAX, mesh.rack, mesh.beta_deg, mesh.internal))
        if not a_w < a_max:
            raise GearDesignError(
                f"a_w = {a_w:g} mm is too large: it must be < {a_max:.6g} mm (the a_w of a shift sum "
                f"{2 * X_ABS_MAX:g}, each |x| <= {X_ABS_MAX:g}) for m = {m:g}, z1/z2 = {z1}/{z2}")
        xs = float(x_sum_from_center_distance(m, z1, z2, a_w, rack, mesh.beta_deg, mesh.internal))
        if x1 is None:
            x1 = balanced_sliding_split(m, z1, z2, xs, mesh=mesh)
        x1 = one_number("x1", require_range("x1", x1, -X_ABS_MAX, X_ABS_MAX))
        x2 = xs + x1 if mesh.internal else xs - x1
        return cls(m, z1, z2, x1, x2, rack, tip_shortening, mesh.beta_deg, mesh.internal, mesh.face_width_mm)

    def geometry(self) -> Geometry:
        """All geometry of the pair (mm, degrees); see :data:`geardesign.gears.geometry.GEOMETRY_FIELDS`."""
        return Geometry.from_float(self._geo)

    def checks(self, *, housing_a_w: float | None = None, housing_tol_mm: float | None = None, extra=(),
               cutter=None, **limits):
        """Table of checks: ``check, value, limit, margin, ok`` (and ``label``), one row per check.

        ``limits``: the options of :func:`~geardesign.gears.checks.make_checks` (``eps_alpha_min``,
        ``sa_min``, ``undercut``, ...; :func:`geardesign.gears.checks.options` lists them with their
        defaults); a report shows seed 000's jamming rows too unless ``jamming=False``.
        Margins are dimensionless and >= 0 where the check holds (see :mod:`geardesign.gears.checks`);
        a margin within :data:`~geardesign.gears.checks.FEASIBILITY_TOL` of zero holds and shows as 0.
        ``housing_a_w`` (mm) adds the ``center_distance`` check of the pair's own a_w against the
        housing's, labelled with the x-sum it needs.

        >>> t = GearPair(8, 17, 26, 0.898, 0.517).checks(housing_a_w=180)
        >>> row = t.set_index("check").loc["center_distance"]
        >>> round(float(row["value"]), 4), bool(row["ok"])   # a_w = 181.6016 mm (seed 000), not 180 mm
        (181.6016, False)
        """
        rows = self.check_rows(housing_a_w=housing_a_w, housing_tol_mm=housing_tol_mm, extra=extra, cutter=cutter,
                               **limits)
        return _checks.check_table(rows, PAIR_CHECK_COLUMNS)

    def check_rows(self, *, housing_a_w: float | None = None, housing_tol_mm: float | None = None, extra=(),
                   cutter=None, **limits) -> list[tuple]:
        """The rows of :meth:`checks` as tuples ``check, margin, ok, value, limit, label``
        (:data:`PAIR_CHECK_COLUMNS`) of plain Python values, without pandas (what ``geardesign pair`` prints).

        >>> [(name, ok) for name, margin, ok, *_ in GearPair(8, 17, 26, 0.898, 0.517).check_rows()][-1]
        ('contact_ratio', False)
        """
        extra = tuple(extra) if not isinstance(extra, _checks.Check) else (extra,)
        if housing_a_w is not None:
            extra += (self._housing_check(housing_a_w, housing_tol_mm),)
        cs = _checks.make_checks(**{"jamming": True, **limits}, extra=extra, cutter=cutter, internal=self.internal)
        tol = _checks.FEASIBILITY_TOL
        return [(name, margin if abs(margin) > tol else 0.0, ok, value, limit, label)
                for name, label, value, limit, margin, ok in _checks.check_rows(self._geo, cs)]

    def _housing_check(self, housing_a_w, housing_tol_mm) -> _checks.CenterDistance:
        """The ``center_distance`` check against the housing's a_w, labelled with the x-sum it needs."""
        kind = dict(beta_deg=self.beta_deg, internal=self.internal)
        a_housing = one_number("housing_a_w", require_positive("housing_a_w", housing_a_w, unit="mm"))
        need = (float(x_sum_from_center_distance(self.m, self.z1, self.z2, a_housing, self.rack, **kind))
                if a_housing > min_center_distance(self.m, self.z1, self.z2, self.rack, **kind) else math.nan)
        xs_name = "x2 - x1" if self.internal else "x1 + x2"
        here = self.x2 - self.x1 if self.internal else self.x1 + self.x2
        label = (f"a_w of {xs_name} = housing a_w {float(housing_a_w):.10g} mm "
                 + (f"(needs {xs_name} = {need:.6g}; here {here:.6g})" if math.isfinite(need)
                    else "(unreachable: housing a_w <= a cos alpha)"))
        return _checks.CenterDistance(limit=a_housing, tol_mm=housing_tol_mm, label=label)

    def report(self, path, overwrite: bool = False, **limits):
        """Deprecated: use :func:`geardesign.pair_report` (``gd.pair_report(pair, path, ...)``), which this calls.

        The report draws on the layers above the gears (the contour, the mesh), and a layer imports only
        downward: the report is a function of the scene layer taking a pair. This method reaches it through
        the writer the package registers (:mod:`geardesign.writers`), with a FutureWarning."""
        warnings.warn("GearPair.report(path, ...) is deprecated; use geardesign.pair_report(pair, path, ...)",
                      FutureWarning, stacklevel=2)
        return writer("pair_report")(self, path, overwrite=overwrite, **limits)

    def ok(self, **limits) -> bool:
        """True when every check of :meth:`checks` holds."""
        return bool(self.checks(**limits)["ok"].all())

    def strength(self, load, material=None, **options):
        """ISO 6336 load capacity of this pair (:func:`geardesign.gears.strength.strength`): ``load`` a
        :class:`~geardesign.gears.strength.Load`, ``material`` a :class:`~geardesign.gears.strength.Material` or
        a catalog name; ``options`` as :func:`~geardesign.gears.strength.pair_strength` (``material2``,
        ``face_width_mm``, accuracy grade, lubricant, roughness, given factors, root method)."""
        from .strength import strength   # here: the chain loads the materials catalog (pandas)
        return strength(self, load, material, **options)

    def life(self, spectrum, material=None, **options):
        """ISO 6336-6 service life of this pair under ``spectrum`` (a :class:`~geardesign.LoadSpectrum`):
        :func:`geardesign.gears.strength.life_result.service_life` (``life_h`` the required life, ``sn_curve``,
        ``mean_stress_factor``, the options of :func:`~geardesign.gears.strength.pair_strength`); a
        :class:`~geardesign.gears.strength.life_result.LifeResult`."""
        from .strength.life_result import service_life   # here: ~30 modules a pair without a spectrum never needs
        return service_life(self, spectrum, material, **options)

    def forces(self, load, circle: str = "operating"):
        """The mesh forces F_t, F_r, F_a (N) and where they act (:func:`~geardesign.gears.forces.pair_forces`):
        ``load`` a :class:`~geardesign.gears.strength.Load` or gear 1's torque in N·m; ``circle`` "operating"
        (the pitch circle the pair runs on; default) or "reference" (ISO 6336-1's F_t = 2000 T/d)."""
        from .forces import pair_forces   # here: loaded on first use, a pair is built without it
        return pair_forces(self, load, circle)

    def measurements(self, gear: int | None = None, **options):
        """The measuring sizes of gear 1, gear 2 or (``gear=None``) both as a tuple
        (:func:`~geardesign.gears.measurement.tooth_measurements`, with this pair's module, shifts, rack, helix,
        tip circles, face width and ring); ``options`` go to it (k, ball_mm, pin_mm, thickness_allowance_mm, ...)."""
        from .measurement import pair_measurements   # here: loaded on first use, a pair is built without it
        return pair_measurements(self, gear, **options)

    def backlash(self, thickness_allowance1_mm=0.0, thickness_allowance2_mm=0.0, center_distance_allowance_mm=0.0):
        """Least and most backlash from the allowances (:func:`~geardesign.gears.backlash.pair_backlash`)."""
        from .backlash import pair_backlash   # here: loaded on first use, a pair is built without it
        return pair_backlash(self, thickness_allowance1_mm, thickness_allowance2_mm, center_distance_allowance_mm)

# Names a user may reach for that belong elsewhere: the hint the error gives.
_ARGUMENT_HINTS = {
    "alpha": "the pressure angle belongs to the basic rack: rack=BasicRack(alpha_deg={value!r})",
    "alpha_deg": "the pressure angle belongs to the basic rack: rack=BasicRack(alpha_deg={value!r})",
    "ha": "the addendum belongs to the basic rack: rack=BasicRack(ha={value!r})",
    "c": "the clearance belongs to the basic rack: rack=BasicRack(c={value!r})",
    "rho_f": "the fillet radius belongs to the basic rack: rack=BasicRack(rho_f={value!r})",
    "beta": "the helix angle is beta_deg={value!r}",
    "module": "the module is m={value!r}",
    "a_w": "for a centre distance use GearPair.from_center_distance(m, z1, z2, a_w)",
    "b": "the face width is face_width_mm={value!r} (mm)",
    "face_width": "the face width is face_width_mm={value!r} (mm)",
}
hint_unknown_arguments(GearPair, _ARGUMENT_HINTS)
