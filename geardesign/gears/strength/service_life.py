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
reversing spectrum without it is refused, never rated as one-sided.
"""
from __future__ import annotations

import functools
import math
import numpy as np

from ...errors import GearDesignError
from ...validate import one_number, require_choice, require_finite, require_range
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
    """
    x, y, tail = _variant(points, sn_curve)
    yr = np.log(np.asarray(ratio, dtype=float))
    j = np.searchsorted(-y, -yr, side="right") - 1        # the last point with f_j >= ratio
    last = len(x) - 1
    jj = np.clip(j, 0, last - 1)
    slope = (x[jj + 1] - x[jj]) / (y[jj + 1] - y[jj])     # d ln N / d ln f of the segment (finite: f falls there)
    inside = x[jj] + (yr - y[jj]) * slope
    beyond = np.inf if tail is None else x[last] + tail * (y[last] - yr)
    with np.errstate(over="ignore"):
        return np.exp(np.where(j >= last, beyond, inside))


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


def pair_life(m, z1, z2, x1, x2, *, spectrum: LoadSpectrum, material1, material2=None, face_width_mm,
              life_h=None, sn_curve: str = "iso", mean_stress_factor=None, bins: bool = False, **options) -> dict:
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
    """
    from .chain import _material, pair_strength

    if not isinstance(spectrum, LoadSpectrum):
        raise GearDesignError(f"spectrum must be a geardesign LoadSpectrum, got {type(spectrum).__name__}")
    require_choice("sn_curve", sn_curve, SN_CURVES)
    if life_h is not None:
        life_h = one_number("life_h", require_range("life_h", life_h, *LIFE_RANGE_H, lo_open=True, unit="h"))
    y_m = _mean_stress(mean_stress_factor, spectrum.reverses)
    if options.get("root", True) is not True:
        raise GearDesignError("pair_life rates pitting and root together: root=False is not an option here")
    mats = (_material(material1, "material1"), _material(material1 if material2 is None else material2, "material2"))
    life_opts = (bool(options.get("pitting_permitted", False)), bool(options.get("optimum_life", False)))
    group = options.get("options")
    if group is not None:
        life_opts = (group.pitting_permitted, group.optimum_life)
    cpr = options.get("cycles_per_rev", (1, 1)) if group is None else group.cycles_per_rev
    loaded = np.flatnonzero(spectrum.torque_nm != 0.0)        # a bin of no torque does no damage
    if loaded.size == 0:
        raise GearDesignError("the spectrum has no bin with a torque: nothing to rate")
    # the designs' numbers by name before their shapes are read (a dict or a ragged list has none);
    # pair_strength checks their ranges
    shapes = {k: require_finite(k, v).shape for k, v in dict(m=m, z1=z1, z2=z2, x1=x1, x2=x2,
                                                              face_width_mm=face_width_mm).items()}
    try:
        shape = np.broadcast_shapes(*shapes.values())
    except ValueError:
        raise GearDesignError("input shapes do not broadcast together: "
                              + ", ".join(f"{k} {s}" for k, s in shapes.items())) from None
    if (math.prod(shape) * loaded.size > _ELEMENTS or math.prod(shape) > BLOCK) and not bins:
        # many designs: in chunks, so that the chain's per-bin fields stay small (and it never splits the designs
        # into blocks of its own, which would part them from the bins)
        return _in_chunks(shape, loaded.size, dict(m=m, z1=z1, z2=z2, x1=x1, x2=x2, face_width_mm=face_width_mm),
                          dict(spectrum=spectrum, material1=material1, material2=material2, life_h=life_h,
                               sn_curve=sn_curve, mean_stress_factor=mean_stress_factor, **options))
    zz = _teeth(spectrum, z1, z2)      # before the chain: a wrong spectrum costs nothing
    designs = [np.asarray(v, dtype=float) for v in (m, x1, x2)]
    expand = (lambda v: np.asarray(v, dtype=float)[..., None]) if shape else (lambda v: np.asarray(v, dtype=float))
    geometry = options.pop("geometry", None)
    if geometry is not None and shape:
        geometry = {k: (expand(v) if k not in ("_z1", "_z2") else v) for k, v in geometry.items()}
    width = face_width_mm if np.ndim(face_width_mm) == 0 else expand(face_width_mm)
    out = pair_strength(expand(designs[0]), expand(z1) if np.ndim(z1) else z1, expand(z2) if np.ndim(z2) else z2,
                        expand(designs[1]), expand(designs[2]), load=_bins_load(spectrum, loaded),
                        material1=mats[0], material2=mats[1], face_width_mm=width, geometry=geometry, **options)
    nb = loaded.size
    scale = 1.0 if life_h is None else life_h / spectrum.duration_h
    n = {g: spectrum.cycles(g, zz, cpr[g - 1])[loaded] * scale for g in (1, 2)}
    sign = np.sign(spectrum.torque_nm[loaded])
    groups = {g: _groups(spectrum, loaded, g, sign) for g in (1, 2)}
    reversing = {g: _reversing_teeth(spectrum, loaded, g, sign) for g in (1, 2)}
    res = {"required_life_h": spectrum.duration_h if life_h is None else life_h}
    curves, ratio, static = {}, {}, {}
    for mode in MODES:
        g = int(mode[1])
        sig, ref = (np.broadcast_to(np.asarray(out[k], dtype=float), shape + (nb,)) for k in _CHAIN[mode])
        if mode[0] == "F":
            ref = ref * np.where(reversing[g], y_m[g - 1], 1.0)
        pts = life_curve(mode[0], mats[g - 1].kind, *(life_opts if mode[0] == "H" else (False, life_opts[1])))
        curves[mode] = pts
        ratio[mode] = sig / ref
        N = cycles_to_failure(ratio[mode], pts, sn_curve)
        static[mode] = ratio[mode] > pts[0][1]
        D = _grouped_max(n[g] / N, groups[g])
        res["D_" + mode] = D
        with np.errstate(divide="ignore", over="ignore"):    # a subnormal D (n = 5e-324 rpm): an infinite life
            res["life_h_" + mode] = np.where(D > 0, res["required_life_h"] / D, np.inf)
        if bins:
            res["N_" + mode] = N
    res["static_exceeded"] = np.any(np.stack([np.any(v, axis=-1) for v in static.values()]), axis=0)
    if not shape:
        S = _safeties([_variant(curves[m], sn_curve) for m in MODES], np.stack([np.log(ratio[m]) for m in MODES]),
                      np.stack([n[int(m[1])] for m in MODES]), [groups[int(m[1])] for m in MODES])
        res.update({"S_" + m: float(v) for m, v in zip(MODES, S)})
        res = {k: (float(v) if np.ndim(v) == 0 and k.startswith(("D_", "life_h_", "static")) else v)
               for k, v in res.items()}
    if bins:
        res.update({"bin_" + k: np.broadcast_to(np.asarray(out[k], dtype=float), shape + (nb,)) for k in _FIELDS})
        res.update(bin_index=loaded, n1=n[1], n2=n[2], bin_reversing1=reversing[1], bin_reversing2=reversing[2],
                   curves=curves, ratio=ratio, mean_stress_factor=y_m)
    return res


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


def _safeties(curves, lr, n, groups, tol: float = 1e-10, lo: float = 1e-3, hi: float = 1e3) -> np.ndarray:
    """S of each row (a gear and mode): the factor on its log stress ratios ``lr`` (rows × bins) that makes its
    Miner sum over ``n`` cycles (rows × bins; the governing group of ``groups``) equal 1. Newton on ln D over ln S
    for every row at once, kept inside each row's bracket by bisection; :func:`safety_for_damage` of one row."""
    X, Y, tails = _padded(curves)
    R, P = X.shape
    rows = np.arange(R)[:, None]
    grouped = [g.max() > 0 for g in groups]
    horizontal = np.isnan(tails)
    tail = np.where(horizontal, 0.0, tails)[:, None]
    last_x, last_y = X[:, -1:], Y[:, -1:]

    def at(s):
        yr = lr + s[:, None]
        j = (Y[:, :, None] >= yr[:, None, :]).sum(axis=1) - 1
        jj = np.clip(j, 0, P - 2)
        x0, y0 = X[rows, jj], Y[rows, jj]
        slope = (X[rows, jj + 1] - x0) / (Y[rows, jj + 1] - y0)
        beyond = j >= P - 1
        with np.errstate(invalid="ignore", over="ignore"):
            lnN = np.where(beyond, np.where(horizontal[:, None], np.inf, last_x + tail * (last_y - yr)),
                           x0 + (yr - y0) * slope)
            k = np.where(beyond, tail, -slope)
            d = np.where(n > 0, n * np.exp(-lnN), 0.0)
        D, dk = d.sum(axis=1), (d * k).sum(axis=1)
        for r in np.flatnonzero(grouped):            # per tooth or flank: the governing group's sum
            sums = np.bincount(groups[r], weights=d[r])
            g = int(np.argmax(sums))
            sel = groups[r] == g
            D[r], dk[r] = sums[g], d[r, sel] @ k[r, sel]
        return D, dk

    a, b = np.full(R, math.log(lo)), np.full(R, math.log(hi))
    seen_a, seen_b = np.zeros(R, bool), np.zeros(R, bool)
    # start at S = 1, or where the largest stress reaches a horizontal curve's end (no damage below it)
    s = np.where(horizontal, np.maximum(0.0, last_y[:, 0] - lr.max(axis=1) + 1e-9), 0.0)
    s = np.clip(s, a, b)
    done = np.zeros(R, bool)
    out = np.exp(s)
    for _ in range(200):
        D, dk = at(s)
        below = D < 1.0
        a, seen_a = np.where(below, s, a), seen_a | below
        b, seen_b = np.where(below, b, s), seen_b | ~below
        with np.errstate(divide="ignore", invalid="ignore"):
            newton = s - np.log(D) / (dk / D)
        ok = np.isfinite(newton) & (newton >= a) & (newton <= b) & (D > 0) & (dk > 0)
        conv = ok & (np.abs(newton - s) <= tol) | (seen_a & seen_b & (b - a <= tol))
        fallback = np.where(seen_a & seen_b, 0.5 * (a + b), np.where(below, np.minimum(s + 1.0, b),
                                                                     np.maximum(s - 1.0, a)))
        stuck = ~ok & (fallback == s)                # at an end of [lo, hi] with D on one side of 1
        new = ~done & (conv | stuck)
        out[new] = np.where(conv, np.where(ok, np.exp(newton), np.exp(b)), np.where(below, hi, lo))[new]
        done |= new
        if done.all():
            break
        s = np.where(ok & ~((newton == a) | (newton == b)), newton, fallback)
    out[~done] = np.exp(b[~done])
    return out


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
