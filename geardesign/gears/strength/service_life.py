"""Service life under a load spectrum (ISO 6336-6:2019): each bin's stresses from the factor chain (its own K_v,
K_Hβ, K_Hα: the chain run once over all bins), the S-N curves of ISO 6336-2 and -3 (the life factors Z_NT, Y_NT
of :mod:`.life` and :mod:`.root_factors`), Miner's sum D = Σ n_i/N_i per gear, per flank and per tooth, the life in
hours and the safety factor for a required life (the factor on every bin's stress that makes D = 1).

The S-N curve of a gear is σ_lim(N) = σ_ref·f(N): σ_ref the stress limit with the life factor 1 (σ_HG, σ_FG of
the chain without a required life, each bin's own Z_v), f the life factor's curve; as in the chain, Z_L, Z_v,
Z_R, Z_W, Z_X (Y_δrelT, Y_RrelT, Y_X) scale the whole curve (the S-N curve of ISO 6336-6:2019 Figure C.1 does
the same: its static level is 1.6 times its knee level). N_i = sup{N : f(N) >= σ_i/σ_ref}. Beyond the
curve's knee four variants (``sn_curve``):

* ``"iso"``: the curves of ISO 6336-2:2019 Table 2 and ISO 6336-3:2019 clause 12 as they are (the gentle line to
  10^10 cycles, horizontal after it: no damage below the 10^10 strength);
* ``"original"``: horizontal at the knee (f = 1): no damage below the endurance limit (Miner's original rule);
* ``"elementary"``: the finite-life line continued beyond the knee without end (Miner's elementary rule);
* ``"haibach"``: beyond the knee a line of exponent 2k − 1, k the finite-life exponent (Haibach's rule,
  E. Haibach, *Betriebsfestigkeit*, 3rd ed., Springer 2006, §3.2).

A stress above the curve's static level has no N on the standard's curve: its first sloped line is continued
upward there and the result flags the bin (``static_exceeded``).

Alternating bending: a tooth whose flanks are both loaded (a spectrum with negative torques) bends its root
both ways; ISO 6336-3:2019 reduces its bending strength by a mean stress influence factor Y_M. Its formula was
not found in a source we could read, so Y_M is the caller's (``mean_stress_factor``, one per gear) and a
reversing spectrum without it is refused, never rated as one-sided. A gear whose teeth meet two mates on opposite
flanks (an idler, a planet) bends both ways whatever the spectrum's sign (``alternating``).
"""
from __future__ import annotations

import functools
import math
import weakref

import numpy as np

from ...errors import GearDesignError
from ...validate import one_number, require_choice, require_finite, require_range
from ..mesh import Mesh, mesh_of
from ..spectrum import MEAN_STRESS_FACTOR_RANGE, SN_CURVES, LoadSpectrum
from . import root_factors as rf
from .blocks import BLOCK
from .life import contact_life_curve
from .load import LIFE_RANGE_H, Load

__all__ = ["SN_CURVES", "MODES", "life_curve", "torque_exponent", "cycles_to_failure", "miner_damage",
           "safety_for_damage", "pair_life", "MEAN_STRESS_FACTOR_RANGE"]

MODES = ("H1", "H2", "F1", "F2")            # pitting of gear 1, 2; root of gear 1, 2
# what each mode reads of the chain: the stress, and the stress limit without a life factor
_CHAIN = {"H1": ("sigma_H1", "sigma_HG1"), "H2": ("sigma_H2", "sigma_HG2"),
          "F1": ("sigma_F1", "sigma_FG1"), "F2": ("sigma_F2", "sigma_FG2")}
_FIELDS = ("sigma_H1", "sigma_H2", "sigma_HG1", "sigma_HG2", "sigma_F1", "sigma_F2", "sigma_FG1", "sigma_FG2",
           "K_v", "K_Hbeta", "K_Halpha", "K_Fbeta", "K_Falpha")
_STRESS_FIELDS = _FIELDS[:8]                # what the damage sums read of the chain


def life_curve(mode: str, kind: str, pitting_permitted: bool = False, optimum: bool = False) -> tuple:
    """The (N, f) points of a gear's S-N curve as life factors: contact (``mode`` "H") Z_NT of ISO 6336-2:2019
    Table 2, root ("F") Y_NT of ISO 6336-3:2019 clause 12 (static value up to 10^4 or 10^3 cycles, 1.0 at
    3·10^6, 0.85 at 10^10, or 1.0 with ``optimum``).

    >>> life_curve("F", "Eh")
    ((1000.0, 2.5), (3000000.0, 1.0), (10000000000.0, 0.85))
    >>> life_curve("H", "Eh")
    ((100000.0, 1.6), (50000000.0, 1.0), (10000000000.0, 0.85))
    """
    if mode == "H":
        return contact_life_curve(kind, pitting_permitted, optimum)
    if mode != "F":
        raise GearDesignError(f"mode must be 'H' (contact) or 'F' (root), got {mode!r}")
    n_static, y_static = rf._LIFE_BY_KIND[rf._kind(kind)]
    return ((n_static, y_static), (rf.N_ENDURANCE, 1.0), (rf.N_LONG, 1.0 if optimum else 0.85))


def _knee(points) -> int:
    """The index of the curve's knee: the first point with f = 1."""
    return next(j for j, (_, f) in enumerate(points) if f == 1.0)


def torque_exponent(mode: str, kind: str, pitting_permitted: bool = False) -> float:
    """The exponent p of the finite-life line of the S-N curve written in torque, N ∝ T^-p (ISO 6336-6:2019
    Annex A's T_eq): the stress exponent k = ln(N_knee/N_static)/ln(f_static) halved for contact (σ_H ∝ √T),
    itself for the root (σ_F ∝ T).

    >>> round(torque_exponent("H", "Eh"), 2), round(torque_exponent("F", "Eh"), 2)   # the 6.6 and 8.7 in use
    (6.61, 8.74)
    """
    pts = life_curve(mode, kind, pitting_permitted)
    j = _knee(pts)
    k = math.log(pts[j][0] / pts[j - 1][0]) / math.log(pts[j - 1][1] / pts[j][1])
    return k / 2.0 if mode == "H" else k


@functools.lru_cache(maxsize=256)
def _variant(points, sn_curve: str):
    """(log N, log f) of the points and the tail's exponent beyond the last (None: horizontal); once per curve
    (read-only arrays)."""
    require_choice("sn_curve", sn_curve, SN_CURVES)
    pts = points if sn_curve == "iso" else points[:_knee(points) + 1]
    x = np.log([p[0] for p in pts])
    y = np.log([p[1] for p in pts])
    j = _knee(points)
    k = math.log(points[j][0] / points[j - 1][0]) / math.log(points[j - 1][1] / points[j][1])
    tail = {"iso": None, "original": None, "elementary": k, "haibach": 2.0 * k - 1.0}[sn_curve]
    x.setflags(write=False)
    y.setflags(write=False)
    return x, y, tail


def cycles_to_failure(ratio, points, sn_curve: str = "iso"):
    """N, the load cycles a gear endures at ``ratio`` = σ/σ_ref (stress over the stress limit with life factor 1)
    on the S-N curve of the life-factor ``points`` (:func:`life_curve`): the largest N whose strength f(N) is
    at least the ratio, straight lines in log-log between the points; beyond the last point by ``sn_curve``
    (the module docstring); above the static level the first line continued (a stress the standard's curve
    does not cover).

    >>> pts = life_curve("H", "Eh")
    >>> [round(float(cycles_to_failure(r, pts)) / 1e7, 6) for r in (1.0, 0.86, 0.85)]   # 0.85 holds for ever
    [5.0, 682.969341, inf]
    >>> round(float(cycles_to_failure(1.6 ** 0.5, pts)) / 1e6, 4)    # halfway in log-log: √(1e5·5e7)
    2.2361
    >>> float(cycles_to_failure(float("nan"), pts))        # a stress not rated: no life, not an infinite one
    nan
    """
    x, y, tail, slopes = _segments(points, sn_curve)
    yr = np.log(np.asarray(ratio, dtype=float))
    # the last point with f_j >= ratio: j = (points not below the ratio) - 1, counted as the points the ratio does
    # not exceed (a NaN exceeds none: j = last, as numpy's sort puts NaN last); a comparison per point costs a
    # tenth of a binary search per ratio over three or four points
    last = len(x) - 1
    j = last - (yr > y[0]).astype(np.intp)
    for y_p in y[1:]:
        j -= yr > y_p
    jj = np.minimum(np.maximum(j, 0), last - 1)
    inside = x[jj] + (yr - y[jj]) * slopes[jj]
    beyond = np.inf if tail is None else x[last] + tail * (y[last] - yr)
    # a NaN ratio (a stress the chain could not rate: a root without a section where a caller's geometry is taken
    # unvalidated) endures NaN cycles, not the horizontal tail's infinity: no damage is not its answer
    with np.errstate(over="ignore"):
        return np.exp(np.where(j >= last, np.where(np.isnan(yr), np.nan, beyond), inside))


@functools.lru_cache(maxsize=256)
def _segments(points, sn_curve: str):
    """:func:`_variant`'s (log N, log f) and tail, with each segment's slope d ln N/d ln f between point j and j + 1
    (at j; a flat segment's, where no ratio falls, infinite): once per curve (read-only arrays)."""
    x, y, tail = _variant(points, sn_curve)
    with np.errstate(divide="ignore"):
        slopes = (x[1:] - x[:-1]) / (y[1:] - y[:-1])
    slopes.setflags(write=False)
    return x, y, tail, slopes


def miner_damage(cycles, N):
    """Miner's sum D = Σ n_i/N_i (Palmgren 1924, Miner 1945; ISO 6336-6:2019 clause 5) over the last axis.

    >>> round(float(miner_damage([1e6, 2e6], [1e7, 4e7])), 12)
    0.15
    """
    n = np.asarray(cycles, dtype=float)
    return np.sum(np.where(n > 0, n / np.asarray(N, dtype=float), 0.0), axis=-1)


def safety_for_damage(damage_of, tol: float = 1e-10, lo: float = 1e-3, hi: float = 1e3, start: float = 1.0) -> float:
    """S with ``damage_of(S)`` = 1: the factor on every stress of a spectrum that uses up the required life
    (ISO 6336-6:2019: the safety factor for a required life). ``damage_of(S)`` returns D, or (D, d ln D/d ln S)
    for Newton steps; it rises with S. Newton on ln D over ln S from ``start``, inside a bracket that bisection
    keeps, to ``tol`` in ln S; S beyond [lo, hi]: that end.

    >>> round(safety_for_damage(lambda s: 0.5 * s ** 4), 9)       # 0.5 S^4 = 1
    1.189207115
    >>> round(safety_for_damage(lambda s: (0.5 * s ** 4, 4.0)), 9)
    1.189207115
    """
    a, b = math.log(lo), math.log(hi)
    known_a = known_b = False            # whether D was seen below 1 at a, at least 1 at b
    s = min(max(math.log(start), a), b)
    for _ in range(200):
        v = damage_of(math.exp(s))
        d, slope = v if isinstance(v, tuple) else (v, None)
        if d >= 1.0:
            b, known_b = s, True
        else:
            a, known_a = s, True
        if known_a and known_b and b - a <= tol:
            break
        step = None
        if 0 < d < math.inf:
            if slope is None:      # a secant slope from a nearby point
                d2 = damage_of(math.exp(s + 1e-7))
                d2 = d2[0] if isinstance(d2, tuple) else d2
                slope = (math.log(d2) - math.log(d)) / 1e-7 if d2 > 0 else None
            if slope:
                step = s - math.log(d) / slope
                if abs(step - s) <= tol and a <= step <= b:
                    return math.exp(step)
        if step is None or not a < step < b:
            if known_a and known_b:
                step = 0.5 * (a + b)
            elif known_b:          # D >= 1 everywhere seen: go down
                step = max(s - 1.0, a) if s > a else a
            else:
                step = min(s + 1.0, b) if s < b else b
            if step == s:          # at an end of [lo, hi] with D on the same side of 1: that end
                return hi if d < 1.0 else lo
        s = step
    return math.exp(b)


def _bins_load(spectrum: LoadSpectrum, sel) -> Load:
    """A :class:`Load` whose torque and speed are the bins' arrays (the chain runs them in one call; a Load is one
    case, so its fields are set past its one-number check: the bins were checked by the spectrum)."""
    load = Load(torque_nm=1.0, n_rpm=1.0, on_gear=spectrum.on_gear)
    object.__setattr__(load, "torque_nm", np.abs(spectrum.torque_nm[sel]))
    object.__setattr__(load, "n_rpm", spectrum.n_rpm[sel])
    return load


def _alternating(value) -> tuple:
    """``alternating`` of :func:`pair_life` checked: two booleans."""
    if not (isinstance(value, (tuple, list)) and len(value) == 2 and all(isinstance(v, (bool, np.bool_)) for v in value)):
        raise GearDesignError(f"alternating must be two booleans (gear 1, gear 2), got {value!r}")
    return (bool(value[0]), bool(value[1]))


def _mean_stress(value, reverses) -> tuple:
    if value is None:
        if reverses:
            raise GearDesignError("the spectrum's torque reverses (negative bins load the other flank), so the roots "
                                  "bend both ways: give mean_stress_factor=(Y_M1, Y_M2), the mean stress influence "
                                  "factor of ISO 6336-3:2019 for alternating bending, in "
                                  f"[{MEAN_STRESS_FACTOR_RANGE[0]:g}, {MEAN_STRESS_FACTOR_RANGE[1]:g}]")
        return (1.0, 1.0)
    pair = value if isinstance(value, (tuple, list)) else (value, value)
    if len(pair) != 2:
        raise GearDesignError(f"mean_stress_factor must be Y_M or (Y_M1, Y_M2), got {value!r}")
    return tuple(one_number("mean_stress_factor", require_range("mean_stress_factor", v, *MEAN_STRESS_FACTOR_RANGE)) for v in pair)


def pair_life(m, z1=None, z2=None, x1=0.0, x2=0.0, *, spectrum: LoadSpectrum, material1, material2=None,
              face_width_mm=None, life_h=None, sn_curve: str = "iso", mean_stress_factor=None, bins: bool = False,
              mesh: Mesh | None = None, alternating=(False, False), **options) -> dict:
    """ISO 6336-6 service life of gear pairs under ``spectrum`` (a :class:`~geardesign.gears.spectrum.LoadSpectrum`),
    vectorised over designs like :func:`~geardesign.gears.strength.chain.pair_strength` (m, z1, z2, x1, x2 and the
    face width broadcast; ``options`` are its options: accuracy grade, lubricant, given factors, ``geometry``, ...).
    The application factor is 1: the spectrum is the load.

    ``life_h``: the required life in hours (the spectrum repeated over it); None: the spectrum's own duration.
    ``sn_curve``: the variant beyond the knee (module docstring). ``mean_stress_factor``: Y_M of each gear for a
    spectrum whose torque reverses. Returns, per design, ``D_H1, D_H2, D_F1, D_F2`` (Miner's sums over the
    required life: the governing tooth and flank), ``life_h_H1`` … (hours to D = 1) and ``S_H1`` … (the safety
    factors for the required life: the factor on the stresses that makes D = 1; one design only); ``bins=True``
    adds the chain's per-bin fields (``bin_<field>``, shape designs × bins) and each bin's ``N_<mode>`` and
    ``n<gear>`` cycles.
    ``mesh``: a :class:`~geardesign.gears.mesh.Mesh` instead of z1, z2, ``rack``, ``tip_shortening``, ``beta_deg``,
    ``internal`` and ``face_width_mm``, as :func:`~geardesign.gears.strength.chain.pair_strength` takes it (giving
    both ways is refused by name).
    ``alternating``: (gear 1, gear 2), True for a gear whose root bends both ways whatever the spectrum's sign (an
    idler, a planet: its teeth meet two mates on opposite flanks): its root limit is times Y_M in every bin, as a
    reversing tooth's is, so it needs ``mean_stress_factor``.
    """
    from .chain import _material, pair_strength
    from .options import gathered

    if mesh is not None or z1 is None or z2 is None:
        mesh = mesh_of(mesh, z1, z2, options.get("rack"), options.get("tip_shortening", True),
                       options.get("beta_deg", 0.0), options.get("internal", False), face_width_mm)
        z1, z2, face_width_mm = mesh.z1, mesh.z2, mesh.face_width_mm
        options.update(rack=mesh.rack, tip_shortening=mesh.tip_shortening, beta_deg=mesh.beta_deg,
                       internal=mesh.internal)
    if face_width_mm is None:
        raise GearDesignError("face_width_mm (mm) is needed for the service life: give it, or a mesh= with its "
                              "face_width_mm")

    if not isinstance(spectrum, LoadSpectrum):
        raise GearDesignError(f"spectrum must be a geardesign LoadSpectrum, got {type(spectrum).__name__}")
    require_choice("sn_curve", sn_curve, SN_CURVES)
    if life_h is not None:
        life_h = one_number("life_h", require_range("life_h", life_h, *LIFE_RANGE_H, lo_open=True, unit="h"))
    prep = _prepared(spectrum)
    alternating = _alternating(alternating)
    if mean_stress_factor is None and any(alternating) and not prep.reverses:
        raise GearDesignError(f"gear {alternating.index(True) + 1}'s root bends both ways (alternating=True: its teeth "
                              f"meet two mates on opposite flanks): give mean_stress_factor=Y_M, the mean stress "
                              f"influence factor of ISO 6336-3:2019 for alternating bending, in "
                              f"[{MEAN_STRESS_FACTOR_RANGE[0]:g}, {MEAN_STRESS_FACTOR_RANGE[1]:g}]")
    y_m = _mean_stress(mean_stress_factor, prep.reverses)
    if options.get("root", True) is not True:
        raise GearDesignError("pair_life rates pitting and root together: root=False is not an option here")
    mats = (_material(material1, "material1"), _material(material1 if material2 is None else material2, "material2"))
    life_opts = (bool(options.get("pitting_permitted", False)), bool(options.get("optimum_life", False)))
    group = options.get("options")
    if group is not None:
        life_opts = (group.pitting_permitted, group.optimum_life)
    cpr = options.get("cycles_per_rev", (1, 1)) if group is None else group.cycles_per_rev
    loaded = prep.loaded                       # a bin of no torque does no damage
    if loaded.size == 0:
        raise GearDesignError("the spectrum has no bin with a torque: nothing to rate")
    # the designs' numbers by name before their shapes are read (a dict or a ragged list has none);
    # pair_strength checks their ranges
    shapes = {k: _shape(k, v) for k, v in dict(m=m, z1=z1, z2=z2, x1=x1, x2=x2, face_width_mm=face_width_mm).items()}
    try:
        shape = () if not any(shapes.values()) else np.broadcast_shapes(*shapes.values())
    except ValueError:
        raise GearDesignError("input shapes do not broadcast together: "
                              + ", ".join(f"{k} {s}" for k, s in shapes.items())) from None
    if (math.prod(shape) * loaded.size > _ELEMENTS or math.prod(shape) > BLOCK) and not bins:
        # many designs: in chunks, so that the chain's per-bin fields stay small (and it never splits the designs
        # into blocks of its own, which would part them from the bins)
        return _in_chunks(shape, loaded.size, dict(m=m, z1=z1, z2=z2, x1=x1, x2=x2, face_width_mm=face_width_mm),
                          dict(spectrum=spectrum, material1=material1, material2=material2, life_h=life_h,
                               sn_curve=sn_curve, mean_stress_factor=mean_stress_factor, alternating=alternating,
                               **options))
    zz = _teeth(spectrum, z1, z2)      # before the chain: a wrong spectrum costs nothing
    designs = [np.asarray(v, dtype=float) for v in (m, x1, x2)]
    # designs × bins; one design in Python floats, which the chain runs on math with the bins' arrays on numpy
    expand = (lambda v: np.asarray(v, dtype=float)[..., None]) if shape else float
    geometry = options.pop("geometry", None)
    if geometry is not None and shape:
        geometry = {k: (expand(v) if k not in ("_z1", "_z2") else v) for k, v in geometry.items()}
    width = expand(face_width_mm) if shape or type(face_width_mm) is not int else face_width_mm
    # only the fields read below: the chain's other ~90 are left at their own shapes (fields=)
    out = pair_strength(expand(designs[0]), expand(z1) if np.ndim(z1) else z1, expand(z2) if np.ndim(z2) else z2,
                        expand(designs[1]), expand(designs[2]), load=prep.load, material1=mats[0],
                        material2=mats[1], face_width_mm=width, geometry=geometry,
                        fields=_FIELDS if bins else _STRESS_FIELDS, **gathered(options))
    nb = loaded.size
    full = shape + (nb,)
    scale = 1.0 if life_h is None else life_h / spectrum.duration_h
    n = prep.cycles(spectrum, zz, cpr) * scale          # rows: the modes' gears (1, 2, 1, 2)
    required = spectrum.duration_h if life_h is None else life_h
    res = {"required_life_h": required}
    curves = {mode: _curve(mode[0], mats[int(mode[1]) - 1].kind, life_opts) for mode in MODES}
    # rows: the modes; the stress over its limit with life factor 1 (a reversing tooth's root limit times Y_M)
    ratio = np.empty((len(MODES),) + full)
    for r, mode in enumerate(MODES):
        g = int(mode[1])
        sig, ref = (out[k] for k in _CHAIN[mode])
        if mode[0] == "F" and alternating[g - 1]:
            ref = ref * y_m[g - 1]
        elif mode[0] == "F" and prep.reversing_any[g]:
            ref = ref * np.where(prep.reversing[g], y_m[g - 1], 1.0)
        np.divide(sig, ref, out=ratio[r])
    # N of the modes that share an S-N curve (both gears of one material) in one call
    N = np.empty_like(ratio)
    for pts in dict.fromkeys(curves.values()):
        rows = [r for r, mode in enumerate(MODES) if curves[mode] == pts]
        sel = slice(rows[0], rows[-1] + 1) if rows == list(range(rows[0], rows[-1] + 1)) else rows
        N[sel] = cycles_to_failure(ratio[sel], pts, sn_curve)
    static_level = np.array([curves[m][0][1] for m in MODES]).reshape((-1,) + (1,) * len(full))
    static = np.any(ratio > static_level, axis=-1).any(axis=0)
    d = n.reshape((len(MODES),) + (1,) * len(shape) + (nb,)) / N
    D = np.sum(d, axis=-1)
    for r, mode in enumerate(MODES):
        if prep.grouped[int(mode[1])]:
            D[r] = _grouped_max(d[r], prep.groups[int(mode[1])])
    if shape:
        with np.errstate(divide="ignore", over="ignore"):    # a subnormal D (n = 5e-324 rpm): an infinite life
            life = np.where(D > 0, required / D, np.inf)
        res.update(zip(("D_" + m for m in MODES), D))
        res.update(zip(("life_h_" + m for m in MODES), life))
        res["static_exceeded"] = static
    else:
        D = D.tolist()
        res.update(zip(("D_" + m for m in MODES), D))
        res.update(("life_h_" + m, required / v if v > 0 else math.inf) for m, v in zip(MODES, D))
        S = _safeties(tuple(curves.values()), sn_curve, np.log(ratio), n, [prep.groups[int(m[1])] for m in MODES],
                      [prep.grouped[int(m[1])] for m in MODES])
        res.update(zip(("S_" + m for m in MODES), S.tolist()))
        res["static_exceeded"] = float(static)     # (a number, as D and the life)
    if bins:
        res.update(("N_" + m, N[r]) for r, m in enumerate(MODES))
        res.update({"bin_" + k: np.broadcast_to(np.asarray(out[k], dtype=float), full) for k in _FIELDS})
        res.update(bin_index=loaded, n1=n[0], n2=n[1], bin_reversing1=prep.reversing[1] | alternating[0],
                   bin_reversing2=prep.reversing[2] | alternating[1], curves=curves, ratio=dict(zip(MODES, ratio)),
                   mean_stress_factor=y_m)
    return res


def _shape(name: str, value) -> tuple:
    """The shape of a design's number, refused by name when not finite (:func:`require_finite`; a float without
    numpy)."""
    if isinstance(value, float) and math.isfinite(value) or type(value) is int and -1e308 < value < 1e308:
        return ()
    return require_finite(name, value).shape


@functools.lru_cache(maxsize=256)
def _curve(mode: str, kind: str, life_opts: tuple) -> tuple:
    """:func:`life_curve` of a mode ("H" or "F") as the chain's options choose it (the root's curve has no
    pitting_permitted), once per material kind and options."""
    return life_curve(mode, kind, *(life_opts if mode == "H" else (False, life_opts[1])))


class _Prepared:
    """What :func:`pair_life` reads of a spectrum besides the chain, once per spectrum (whose arrays are read-only):
    the loaded bins, the chain's load over them, each gear's groups of bins (tooth and flank) and its reversing
    teeth, and the bins' cycles per pair of tooth counts."""

    def __init__(self, spectrum: LoadSpectrum):
        self.loaded = np.flatnonzero(spectrum.torque_nm != 0.0)
        self.load = _bins_load(spectrum, self.loaded) if self.loaded.size else None
        sign = np.sign(spectrum.torque_nm[self.loaded])
        self.groups = {g: _groups(spectrum, self.loaded, g, sign) for g in (1, 2)}
        self.grouped = {g: bool(v.size and v.max() > 0) for g, v in self.groups.items()}
        self.reversing = {g: (_reversing_teeth(spectrum, self.loaded, g, sign) if self.loaded.size
                              else np.zeros(0, dtype=bool)) for g in (1, 2)}
        self.reversing_any = {g: bool(v.any()) for g, v in self.reversing.items()}
        self.reverses = spectrum.reverses
        for v in (self.loaded, sign, *self.groups.values(), *self.reversing.values()) + (
                (self.load.torque_nm, self.load.n_rpm) if self.load else ()):
            v.setflags(write=False)
        self._cycles = {}

    def cycles(self, spectrum: LoadSpectrum, teeth: tuple, cycles_per_rev) -> np.ndarray:
        """:meth:`LoadSpectrum.cycles` of the loaded bins for the gear of each of :data:`MODES` (rows × bins,
        read-only)."""
        key = (teeth, tuple(cycles_per_rev))
        if key not in self._cycles:
            if len(self._cycles) >= 256:       # a tooth search's many pairs: kept bounded
                self._cycles.clear()
            v = np.stack([spectrum.cycles(int(mode[1]), teeth, cycles_per_rev[int(mode[1]) - 1])[self.loaded]
                          for mode in MODES])
            v.setflags(write=False)
            self._cycles[key] = v
        return self._cycles[key]


_PREPARED = weakref.WeakKeyDictionary()      # spectrum -> _Prepared (a spectrum is frozen, hashed by identity)


def _prepared(spectrum: LoadSpectrum) -> _Prepared:
    prep = _PREPARED.get(spectrum)
    if prep is None:
        prep = _PREPARED[spectrum] = _Prepared(spectrum)
    return prep


_PAD = 5.0   # ln-units between the padding points of a curve (any positive step: they lie on its first line)


def _padded(curves) -> tuple:
    """The curves (:func:`_variant`'s) as rows of one length: each padded at its front with points on its first
    sloped line (what a stress above the static level reads anyway), the last point last in every row; and the
    rows' tail exponents (NaN: horizontal)."""
    P = max(len(c[0]) for c in curves)
    X, Y = np.empty((len(curves), P)), np.empty((len(curves), P))
    for r, (x, y, _) in enumerate(curves):
        extra = P - len(x)
        slope = (x[1] - x[0]) / (y[1] - y[0])
        dy = _PAD * np.arange(extra, 0, -1)
        X[r] = np.concatenate([x[0] + slope * dy, x])
        Y[r] = np.concatenate([y[0] + dy, y])
    tails = np.array([np.nan if c[2] is None else c[2] for c in curves])
    return X, Y, tails


@functools.lru_cache(maxsize=256)
def _padded_curves(points: tuple, sn_curve: str) -> tuple:
    """What :func:`_safeties` reads of the rows' S-N curves (the life-factor ``points`` of each row), once per set
    of curves: :func:`_padded`'s X, Y and tails, each segment's slope d ln N/d ln f, the last point (ln N of a
    horizontal row's end: +inf, so that its tail line gives N = inf), the tail exponents (0: horizontal) and the
    segment of a count of points at or above a stress, and the row numbers as a column (read-only arrays)."""
    X, Y, tails = _padded([_variant(p, sn_curve) for p in points])
    R, P = X.shape
    horizontal = np.isnan(tails)
    seg = np.full((R, P), np.nan)             # the segment from point j to j + 1 at j (the last column unused)
    with np.errstate(divide="ignore"):         # a flat segment's (never read: no stress falls inside it)
        seg[:, :-1] = (X[:, 1:] - X[:, :-1]) / (Y[:, 1:] - Y[:, :-1])
    last_x = np.where(horizontal[:, None], np.inf, X[:, -1:])
    tail = np.where(horizontal, 0.0, tails)[:, None]
    # a stress below c of a row's P points lies on segment c - 1 (the first for c = 0, the last for c = P):
    # its index in the rows' flattened points
    rows = np.arange(R)[:, None]
    segment = np.clip(np.arange(P + 1) - 1, 0, P - 2) + P * rows
    out = (X.ravel(), Y, seg.ravel(), last_x, Y[:, -1:], tail, horizontal, segment, rows)
    for v in out:
        v.setflags(write=False)
    return out


def _safeties(points, sn_curve, lr, n, groups, grouped, tol: float = 1e-10, lo: float = 1e-3,
              hi: float = 1e3) -> np.ndarray:
    """S of each row (a gear and mode): the factor on its log stress ratios ``lr`` (rows × bins) that makes its
    Miner sum over ``n`` cycles (rows × bins; the governing group of ``groups``, where ``grouped``) equal 1, on the
    S-N curve of the life-factor ``points`` of each row (``sn_curve``). Newton on ln D over ln S for every row at
    once, kept inside each row's bracket by bisection; :func:`safety_for_damage` of one row. The sums over the
    bins in numpy, the steps of the four rows in Python floats (ln D from numpy, the arithmetic IEEE's in both)."""
    Xf, Y, seg, last_x, last_y, tail, horizontal, segment, rows = _padded_curves(points, sn_curve)
    R, P = Y.shape
    Yf = Y.ravel()
    loaded = n > 0
    every = bool(loaded.all())
    grouped_rows = [r for r in range(R) if grouped[r]]
    Ycol = Y[:, :, None]

    def at(s):
        yr = lr + s[:, None]
        c = (Ycol >= yr[:, None, :]).sum(axis=1)        # points at or above the stress: its segment
        i = segment[rows, c]
        beyond = c >= P                                 # below the last point: the tail (inf: horizontal)
        slope = seg[i]
        lnN = np.where(beyond, last_x + tail * (last_y - yr), Xf[i] + (yr - Yf[i]) * slope)
        k = np.where(beyond, tail, -slope)
        d = n * np.exp(-lnN)
        if not every:
            d = np.where(loaded, d, 0.0)
        D, dk = d.sum(axis=1), (d * k).sum(axis=1)
        for r in grouped_rows:            # per tooth or flank: the governing group's sum
            sums = np.bincount(groups[r], weights=d[r])
            g = int(np.argmax(sums))
            sel = groups[r] == g
            D[r], dk[r] = sums[g], d[r, sel] @ k[r, sel]
        return D, dk

    la, lb = math.log(lo), math.log(hi)
    a, b = [la] * R, [lb] * R
    seen_a, seen_b = [False] * R, [False] * R
    # start at S = 1, or where the largest stress reaches a horizontal curve's end (no damage below it)
    s0 = np.where(horizontal, np.maximum(0.0, last_y[:, 0] - lr.max(axis=1) + 1e-9), 0.0)
    s = np.minimum(np.maximum(s0, la), lb).tolist()
    done = [False] * R
    found = {}                   # row -> (ln S, None) or (None, S at an end of [lo, hi])
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for _ in range(200):
            D, dk = at(np.array(s))
            lnD = np.log(D).tolist()
            D, dk = D.tolist(), dk.tolist()
            nxt = list(s)
            for r in range(R):
                d, k, x = D[r], dk[r], s[r]
                below = d < 1.0
                if below:
                    a[r], seen_a[r] = x, True
                else:
                    b[r], seen_b[r] = x, True
                # Newton's step s - ln D/(dk/D), read only where D and dk are > 0 and it is finite (as numpy's float64
                # gives it: a quotient dk/D that overflows reads ln D/inf = 0; one that underflows to 0 is no step)
                ok = False
                if 0.0 < d < math.inf and 0.0 < k:
                    q = k / d                              # (a float quotient overflows to inf)
                    if q != 0.0:
                        newton = x - lnD[r] / q
                        ok = math.isfinite(newton) and a[r] <= newton <= b[r]
                both = seen_a[r] and seen_b[r]
                conv = ok and abs(newton - x) <= tol or (both and b[r] - a[r] <= tol)
                fallback = 0.5 * (a[r] + b[r]) if both else min(x + 1.0, b[r]) if below else max(x - 1.0, a[r])
                stuck = not ok and fallback == x           # at an end of [lo, hi] with D on one side of 1
                if not done[r] and (conv or stuck):
                    found[r] = ((newton if ok else b[r]), None) if conv else (None, hi if below else lo)
                    done[r] = True
                nxt[r] = newton if ok and not (newton == a[r] or newton == b[r]) else fallback
            if all(done):
                break
            s = nxt
    found = [found.get(r, (b[r], None)) for r in range(R)]
    S = np.exp(np.array([math.nan if v is None else v for v, _ in found]))     # the ln S found, in one call
    return np.array([S[r] if v is not None else fixed for r, (v, fixed) in enumerate(found)])


_ELEMENTS = 65536     # designs × bins of one chain call: ~100 fields of 0.5 MB


def _in_chunks(shape, nb, per_design: dict, rest: dict) -> dict:
    """:func:`pair_life` of many designs, a chunk of them at a time (flattened), its arrays put back in ``shape``."""
    flat = {k: np.broadcast_to(np.asarray(v), shape).ravel() for k, v in per_design.items()}
    geometry = rest.pop("geometry", None)
    if geometry is not None:
        geometry = {k: (v if k in ("_z1", "_z2") else np.broadcast_to(np.asarray(v, dtype=float), shape).ravel())
                    for k, v in geometry.items()}
    step = max(1, min(BLOCK, _ELEMENTS // nb))
    parts = []
    for i in range(0, math.prod(shape), step):
        part = {k: v[i:i + step] for k, v in flat.items()}
        part["z1"], part["z2"] = int(part["z1"][0]), int(part["z2"][0])   # one pair of tooth counts per call
        if geometry is not None:
            rest["geometry"] = {k: (v if k in ("_z1", "_z2") else v[i:i + step]) for k, v in geometry.items()}
        parts.append(pair_life(**part, **rest))
    out = {}
    for k, v in parts[0].items():
        out[k] = np.concatenate([p[k] for p in parts]).reshape(shape) if np.ndim(v) == 1 else v
    return out


def _groups(spectrum: LoadSpectrum, loaded, gear: int, sign) -> np.ndarray:
    """Each loaded bin's group: one flank of one tooth of ``gear`` (every tooth alike: one group per flank)."""
    tooth = np.zeros(loaded.size, dtype=np.int64) if not spectrum.per_tooth else \
        (spectrum.tooth1 if gear == 1 else spectrum.tooth2)[loaded]
    return tooth * 2 + (sign < 0)


def _teeth(spectrum: LoadSpectrum, z1, z2) -> tuple:
    """The one pair of tooth counts (z1, z2) of the designs, which the spectrum's cycles depend on (the ratio) and,
    counted per tooth, its bins (the teeth they were counted for)."""
    if type(z1) is int and type(z2) is int:          # one pair in plain numbers (the spectrum checks their range)
        zz = (z1, z2)
        require_teeth_of(spectrum, zz)
        return zz
    if np.size(z1) == 0 or np.size(z2) == 0:
        raise GearDesignError(f"z1 and z2 must each give a tooth count, got {np.size(z1)} and {np.size(z2)} values")
    zz = (int(np.max(z1)), int(np.max(z2)))
    if np.ndim(z1) or np.ndim(z2):
        if np.unique(np.asarray(z1)).size > 1 or np.unique(np.asarray(z2)).size > 1:
            raise GearDesignError("pair_life takes one pair of tooth counts per call (the spectrum's cycles depend "
                                  "on the ratio); vary m, x1, x2 and the width")
    require_teeth_of(spectrum, zz)
    return zz


def require_teeth_of(spectrum: LoadSpectrum, teeth: tuple) -> None:
    """A spectrum counted per tooth rates only the pair it was counted for."""
    if spectrum.per_tooth and spectrum.teeth != teeth:
        raise GearDesignError(f"the spectrum was counted per tooth for teeth {spectrum.teeth}, the pair has {teeth}: "
                              f"count the curve again for this pair (LoadSpectrum.from_curve(..., teeth={teeth}))")


def _reversing_teeth(spectrum: LoadSpectrum, loaded, gear: int, sign) -> np.ndarray:
    """True for the bins of a tooth of ``gear`` whose flanks are both loaded in the spectrum (its root bends both
    ways)."""
    tooth = np.zeros(loaded.size, dtype=np.int64) if not spectrum.per_tooth else \
        (spectrum.tooth1 if gear == 1 else spectrum.tooth2)[loaded]
    pos = np.zeros(int(tooth.max()) + 1, dtype=bool)
    neg = pos.copy()
    pos[tooth[sign > 0]] = True
    neg[tooth[sign < 0]] = True
    return (pos & neg)[tooth]


def _grouped_max(d, groups) -> np.ndarray:
    """The largest of the groups' damage sums (over the last axis, bins)."""
    if groups.max() == 0:
        return np.sum(d, axis=-1)
    # the bins ordered by group and summed per run of one group (no product with a 0/1 matrix: 0·inf would be NaN,
    # and a matrix product over hundreds of per-tooth bins costs ~100 times this)
    order = np.argsort(groups, kind="stable")
    g = groups[order]
    starts = np.flatnonzero(np.concatenate([[True], g[1:] != g[:-1]]))
    return np.max(np.add.reduceat(np.asarray(d)[..., order], starts, axis=-1), axis=-1)
