"""A load spectrum (ISO 6336-6:2019): the torque a gear pair carries as bins of torque, speed and time, from a
table, a CSV file or a torque curve counted at the mesh instants, per tooth and per flank; its equivalent torque
and application factor (ISO 6336-6:2019 Annex A).

A bin's torque is signed: a negative torque loads the other flank (the coast flank), and a tooth whose root sees
both signs bends alternately (see :mod:`geardesign.gears.strength.service_life`). A spectrum from a curve keeps
which teeth meet at each mesh (``tooth1``, ``tooth2``, for the pair ``teeth`` it was counted for; a spectrum of
bins stands for every tooth alike): a gear on a crankshaft whose teeth meet the firing peak at the same mesh
every cycle does not "hunt", and its most loaded tooth governs.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import GearDesignError
from ..files import read_text_bounded
from ..validate import one_number, require_finite, require_range

__all__ = ["LoadSpectrum", "equivalent_torque", "application_factor_from_spectrum", "SPECTRUM_COLUMNS",
           "TORQUE_RANGE_NM", "SPEED_RANGE_RPM", "TIME_RANGE_H", "BINS_MAX", "SN_CURVES", "MEAN_STRESS_FACTOR_RANGE"]

TORQUE_RANGE_NM = (-1e9, 1e9)       # as a Load's, signed (the other flank)
SPEED_RANGE_RPM = (0.0, 1e6)        # open below (a Load's)
TIME_RANGE_H = (0.0, 1e9)
SPECTRUM_BYTES_MAX = 16 << 20       # a spectrum file: BINS_MAX rows of a few numbers, with room to spare
BINS_MAX = 100_000                  # rows of a spectrum: a measured history's levels × teeth, with room to spare
# the columns of a spectrum's CSV file: torque_nm and n_rpm, and one of time_h, cycles, share
SPECTRUM_COLUMNS = ("torque_nm", "n_rpm", "time_h", "cycles", "share")
# the S-N curve variants beyond the knee and the range of Y_M (their meaning: strength.service_life; here, where
# the scene schema and the command line read them without loading the strength model)
SN_CURVES = ("iso", "original", "elementary", "haibach")
MEAN_STRESS_FACTOR_RANGE = (0.3, 1.0)       # Y_M: 1 one-sided; a fully alternating root far below 1


@dataclass(frozen=True, eq=False)      # arrays: compared by identity (== of two spectra would be element-wise)
class LoadSpectrum:
    """Bins of a load spectrum: ``torque_nm`` (N·m, signed: negative loads the other flank) at ``n_rpm`` (rpm),
    both of the gear ``on_gear`` (1 or 2) they are given on, for ``time_h`` hours each. ``tooth1``, ``tooth2``:
    the tooth of each gear a bin belongs to (a spectrum counted per tooth, see :meth:`from_curve`), with
    ``meshes`` the load cycles of that tooth in the bin and ``teeth`` the pair's (z1, z2) they were counted for.

    Build one with ``LoadSpectrum.from_bins`` (cycles, time or time shares), :meth:`from_curve` or
    :meth:`from_csv`; the arrays are checked by name.

    >>> s = LoadSpectrum.from_bins([500, 1000], 1500, cycles=[9e6, 1e6])
    >>> round(s.duration_h, 3), [round(float(t), 1) for t in s.time_h]
    (111.111, [100.0, 11.1])
    >>> round(s.equivalent_torque(6.6), 1)       # 1000·(0.1 + 0.9·0.5^6.6)^(1/6.6), ISO 6336-6 Annex A
    715.0
    """

    torque_nm: np.ndarray
    n_rpm: np.ndarray
    time_h: np.ndarray
    on_gear: int = 1
    tooth1: np.ndarray | None = field(default=None, repr=False)
    tooth2: np.ndarray | None = field(default=None, repr=False)
    meshes: np.ndarray | None = field(default=None, repr=False)
    teeth: tuple | None = None

    def __post_init__(self):
        t = require_range("torque_nm", self.torque_nm, *TORQUE_RANGE_NM, unit="N·m").astype(float).ravel()
        n = require_range("n_rpm", self.n_rpm, *SPEED_RANGE_RPM, lo_open=True, unit="rpm").astype(float).ravel()
        h = require_range("time_h", self.time_h, *TIME_RANGE_H, unit="h").astype(float).ravel()
        if t.size == 0 or t.size > BINS_MAX:
            raise GearDesignError(f"torque_nm must have 1 to {BINS_MAX} bins, got {t.size}")
        try:
            n, h = np.broadcast_to(n, t.shape).copy(), np.broadcast_to(h, t.shape).copy()
        except ValueError:
            raise GearDesignError(f"n_rpm and time_h must be one number or one per bin ({t.size} bins), got "
                                  f"{np.size(self.n_rpm)} and {np.size(self.time_h)}") from None
        if not h.sum() > 0:
            raise GearDesignError("time_h (or cycles, share) must give the spectrum some time: all bins are 0")
        if not _gear_number(self.on_gear):
            raise GearDesignError(f"on_gear must be 1 or 2 (the gear the torque and speed are given on), "
                                  f"got {self.on_gear!r}")
        teeth = (self.tooth1, self.tooth2, self.meshes)
        if any(v is not None for v in teeth):
            if any(v is None for v in teeth):
                raise GearDesignError("tooth1, tooth2 and meshes go together (a spectrum counted per tooth)")
            t1, t2 = (np.array(v).ravel() for v in teeth[:2])     # copies: made read-only below, as the rest
            if t1.shape != t.shape or t2.shape != t.shape or not (np.issubdtype(t1.dtype, np.integer)
                                                                   and np.issubdtype(t2.dtype, np.integer)):
                raise GearDesignError(f"tooth1 and tooth2 must be whole numbers, one per bin ({t.size})")
            m = require_range("meshes", self.meshes, 0.0, 1e18).astype(float).ravel()
            if m.shape != t.shape:
                raise GearDesignError(f"meshes must be one per bin ({t.size}), got {m.size}")
            if self.teeth is None:
                raise GearDesignError("a spectrum counted per tooth needs teeth=(z1, z2), the pair it was counted for")
            z = _teeth(self.teeth)
            if t1.min() < 0 or t2.min() < 0 or t1.max() >= z[0] or t2.max() >= z[1]:
                raise GearDesignError(f"tooth1 and tooth2 must be in [0, z) of teeth={z}")
            for name, v in (("tooth1", t1), ("tooth2", t2), ("meshes", m), ("teeth", z)):
                if name != "teeth":
                    v.setflags(write=False)
                object.__setattr__(self, name, v)
        for name, v in (("torque_nm", t), ("n_rpm", n), ("time_h", h)):
            v.setflags(write=False)
            object.__setattr__(self, name, v)

    # -- constructors ---------------------------------------------------------------------------------------
    @classmethod
    def from_bins(cls, torque_nm, n_rpm, *, cycles=None, time_h=None, share=None, duration_h=None,
                  on_gear: int = 1) -> "LoadSpectrum":
        """Bins given as ``torque_nm`` and ``n_rpm`` (one number or one per bin) with exactly one of ``cycles``
        (load cycles of the gear the load is given on, i.e. its revolutions), ``time_h`` (hours per bin) or
        ``share`` (time shares, summing to 1, with the spectrum's ``duration_h``)."""
        given = [k for k, v in (("cycles", cycles), ("time_h", time_h), ("share", share)) if v is not None]
        if len(given) != 1:
            raise GearDesignError(f"give exactly one of cycles, time_h or share, got {given or 'none'}")
        t = require_finite("torque_nm", torque_nm).ravel()
        n = require_range("n_rpm", n_rpm, *SPEED_RANGE_RPM, lo_open=True, unit="rpm").ravel()
        if n.size not in (1, t.size):
            raise GearDesignError(f"n_rpm must be one number or one per bin ({t.size} bins), got {n.size}")
        if cycles is not None:
            c = require_range("cycles", cycles, 0.0, 1e18).ravel()
            if c.size != t.size:
                raise GearDesignError(f"cycles must be one per bin ({t.size}), got {c.size}")
            with np.errstate(over="ignore"):     # a vanishing speed: hours beyond the range, refused by name
                time_h = c / (60.0 * np.asarray(n, dtype=float))
            long = ~(time_h <= TIME_RANGE_H[1])
            if long.any():
                i = int(np.flatnonzero(long)[0])
                raise GearDesignError(f"cycles at n_rpm must give time_h = cycles/(60·n_rpm) in [0, {TIME_RANGE_H[1]:g}] "
                                      f"h, got {time_h[i]:g} h ({c[i]:g} cycles at {n[min(i, n.size - 1)]:g} rpm, "
                                      f"bin {i})")
        elif share is not None:
            q = require_range("share", share, 0.0, 1.0).ravel()
            if not math.isclose(float(q.sum()), 1.0, rel_tol=1e-6):
                raise GearDesignError(f"share must sum to 1, got {float(q.sum()):.9g}")
            if duration_h is None:
                raise GearDesignError("share needs duration_h (the hours the shares divide)")
            d = one_number("duration_h", require_range("duration_h", duration_h, *TIME_RANGE_H, lo_open=True, unit="h"))
            time_h = q * d
        return cls(t, n, time_h, on_gear)

    @classmethod
    def from_csv(cls, path, *, n_rpm=None, duration_h=None, on_gear: int = 1) -> "LoadSpectrum":
        """A spectrum from a CSV file with a header: ``torque_nm``, ``n_rpm`` (or the ``n_rpm`` argument for
        all bins) and one of ``time_h``, ``cycles``, ``share`` (with ``duration_h``). A bad cell is refused
        naming its row (the header is row 1) and column."""
        text = read_text_bounded(path, "spectrum file", SPECTRUM_BYTES_MAX)
        rows = list(csv.reader(line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#")))
        if len(rows) < 2:
            raise GearDesignError(f"spectrum file {str(path)!r} needs a header and at least one row")
        header = [h.strip() for h in rows[0]]
        unknown = [h for h in header if h not in SPECTRUM_COLUMNS]
        if unknown:
            raise GearDesignError(f"spectrum file {str(path)!r}: unknown column {unknown[0]!r}; allowed: "
                                  f"{', '.join(SPECTRUM_COLUMNS)}")
        if "torque_nm" not in header:
            raise GearDesignError(f"spectrum file {str(path)!r} needs a 'torque_nm' column")
        amounts = [h for h in header if h in ("time_h", "cycles", "share")]
        if len(amounts) != 1:
            raise GearDesignError(f"spectrum file {str(path)!r} needs exactly one of the columns 'time_h', 'cycles', "
                                  f"'share', got {amounts or 'none'}")
        if ("n_rpm" in header) == (n_rpm is not None):
            raise GearDesignError(f"spectrum file {str(path)!r}: give the speed either as an 'n_rpm' column or "
                                  f"apart (n_rpm=), not {'both' if n_rpm is not None else 'neither'}")
        cols = {h: [] for h in header}
        limits = {"torque_nm": TORQUE_RANGE_NM, "n_rpm": SPEED_RANGE_RPM, "time_h": TIME_RANGE_H,
                  "cycles": (0.0, 1e18), "share": (0.0, 1.0)}
        for i, row in enumerate(rows[1:], start=2):
            if len(row) != len(header):
                raise GearDesignError(f"spectrum file {str(path)!r} row {i}: {len(row)} cells, the header has "
                                      f"{len(header)}")
            for h, cell in zip(header, row):
                try:
                    v = float(cell)
                except ValueError:
                    raise GearDesignError(f"spectrum file {str(path)!r} row {i}, column {h!r}: {cell.strip()!r} is "
                                          f"not a number") from None
                lo, hi = limits[h]
                if not (math.isfinite(v) and lo <= v <= hi) or (h == "n_rpm" and v <= 0):
                    raise GearDesignError(f"spectrum file {str(path)!r} row {i}, column {h!r}: {v:g} is outside "
                                          f"{'(' if h == 'n_rpm' else '['}{lo:g}, {hi:g}]")
                cols[h].append(v)
        speed = cols["n_rpm"] if n_rpm is None else n_rpm
        return cls.from_bins(cols["torque_nm"], speed, on_gear=on_gear, duration_h=duration_h,
                             **{amounts[0]: cols[amounts[0]]})

    @classmethod
    def from_curve(cls, torque_nm, *, angle_deg=None, time_s=None, n_rpm, teeth, on_gear: int = 1,
                   levels: int = 48, period_deg=None) -> "LoadSpectrum":
        """Level counting of a periodic torque curve of the gear ``on_gear`` (N·m, signed), given over its angle
        ``angle_deg`` (a crank angle: one period, e.g. 0-720° of a four-stroke engine) or over ``time_s`` at the
        constant speed ``n_rpm`` (then the angle is 6·n·t degrees). ``teeth``: (z1, z2) of the pair.

        The torque is read (linear interpolation, periodic) at the mesh instants, every 360/z degrees of the
        gear it is given on, over the shortest run after which both gears' teeth meet again at the same point
        of the curve; each mesh loads one tooth of each gear, and its torque is put in one of ``levels`` equal
        classes per sign, counted at the class's end farthest from zero (conservative: the upper class limit,
        as ISO 6336-6 Annex C's table counts). Bins keep the two teeth that met (``tooth1``, ``tooth2``) and
        how often (``meshes`` per run); ``time_h`` is the run's time shared by the meshes.

        >>> s = LoadSpectrum.from_curve([100.0, 100.0], angle_deg=[0.0, 360.0], n_rpm=600, teeth=(20, 40))
        >>> # a run of 40 meshes (two turns of gear 1) meets every pair of teeth that can meet once
        >>> len(s.torque_nm), float(s.torque_nm[0]), sorted(set(s.meshes.tolist()))
        (40, 100.0, [1.0])
        """
        T = require_finite("torque_nm", torque_nm).ravel()
        if T.size < 2:
            raise GearDesignError(f"torque_nm must have at least 2 points of the curve, got {T.size}")
        n = one_number("n_rpm", require_range("n_rpm", n_rpm, *SPEED_RANGE_RPM, lo_open=True, unit="rpm"))
        if (angle_deg is None) == (time_s is None):
            raise GearDesignError("give the curve over angle_deg or over time_s, one of them")
        x = require_finite("angle_deg" if time_s is None else "time_s",
                           angle_deg if time_s is None else time_s).ravel()
        if x.size != T.size:
            raise GearDesignError(f"the curve's abscissa and torque_nm must have the same length, got {x.size} and "
                                  f"{T.size}")
        if np.any(np.diff(x) <= 0):
            raise GearDesignError("the curve's angle_deg (or time_s) must increase strictly")
        phi = x if time_s is None else 6.0 * n * x
        span = float(phi[-1] - phi[0]) if period_deg is None else float(require_range(
            "period_deg", period_deg, 0.0, 1e7, lo_open=True, unit="°"))
        z = _teeth(teeth)
        z_on = z[int(on_gear) - 1] if _gear_number(on_gear) else None
        if z_on is None:
            raise GearDesignError(f"on_gear must be 1 or 2, got {on_gear!r}")
        levels = int(one_number("levels", require_range("levels", levels, 1, 10_000)))
        pitch = 360.0 / z_on
        per_period = span / pitch             # meshes in one period of the curve
        m_per = round(per_period)
        if not math.isclose(per_period, m_per, rel_tol=0, abs_tol=1e-9 * max(1.0, per_period)) or m_per < 1:
            raise GearDesignError(f"the curve's period ({span:g}°) must hold a whole number of mesh pitches "
                                  f"(360/{z_on} = {pitch:g}°), got {per_period:.6g}")
        run = math.lcm(m_per, z[0], z[1])      # meshes until the same teeth meet at the same point again
        if run > 10_000_000:
            raise GearDesignError(f"the teeth meet at the same point of the curve only every {run} meshes (more than "
                                  f"10^7): give a curve whose period holds fewer mesh pitches")
        k = np.arange(run)
        at = phi[0] + np.mod(k * pitch, span)
        # a period given apart: the curve wraps (its last point need not repeat its first)
        Tk = np.interp(at, phi, T, period=span) if period_deg is not None else np.interp(at, phi, T)
        level_T = _upper_levels(Tk, levels)
        t1, t2 = np.mod(k, z[0]), np.mod(k, z[1])
        keys, counts = np.unique(np.stack([level_T, t1, t2]), axis=1, return_counts=True)
        run_h = run * pitch / (6.0 * n) / 3600.0      # hours of the run at n rpm
        return cls(keys[0], n, counts * run_h / run, on_gear, keys[1].astype(np.int64), keys[2].astype(np.int64),
                   counts.astype(float), z)

    # -- quantities -----------------------------------------------------------------------------------------
    @property
    def duration_h(self) -> float:
        """The hours the bins cover (their sum)."""
        return float(self.time_h.sum())

    @property
    def per_tooth(self) -> bool:
        """True for a spectrum counted per tooth (:meth:`from_curve`)."""
        return self.tooth1 is not None

    @property
    def reverses(self) -> bool:
        """True when some bin loads the other flank (a negative torque)."""
        return bool(np.any(self.torque_nm < 0))

    def cycles(self, gear: int, teeth, cycles_per_rev: int = 1) -> np.ndarray:
        """The load cycles of one tooth of ``gear`` (1 or 2) in each bin over the spectrum's duration, for a pair
        of ``teeth`` (z1, z2): 60·n·t·(cycles per revolution) with the gear's own speed, or the bin's meshes for a
        spectrum counted per tooth."""
        if self.per_tooth:
            return self.meshes * cycles_per_rev
        z = _teeth(teeth)
        n = self.n_rpm * (z[self.on_gear - 1] / z[gear - 1])
        return 60.0 * n * self.time_h * cycles_per_rev

    def equivalent_torque(self, p: float) -> float:
        """T_eq of the bins' magnitudes weighted by their cycles for the S-N exponent ``p`` in torque
        (:func:`equivalent_torque`)."""
        return equivalent_torque(np.abs(self.torque_nm), 60.0 * self.n_rpm * self.time_h, p)

    def application_factor(self, torque_nm: float, p: float) -> float:
        """K_A = T_eq/T_n for the nominal torque ``torque_nm`` (:func:`application_factor_from_spectrum`)."""
        return application_factor_from_spectrum(self.equivalent_torque(p), torque_nm)

    def to_frame(self):
        """The bins as a DataFrame: torque_nm, n_rpm, time_h (and tooth1, tooth2, meshes when counted per
        tooth)."""
        import pandas as pd

        cols = {"torque_nm": self.torque_nm, "n_rpm": self.n_rpm, "time_h": self.time_h}
        if self.per_tooth:
            cols.update(tooth1=self.tooth1, tooth2=self.tooth2, meshes=self.meshes)
        return pd.DataFrame(cols)

    def histogram(self):
        """The time share of each torque class, summed over the teeth (a DataFrame: ``torque_nm`` signed, the
        class's value; ``time_h``; ``share`` of the duration; ``flank`` "drive" or "coast"), largest torque
        first."""
        import pandas as pd

        levels, inverse = np.unique(self.torque_nm, return_inverse=True)
        hours = np.bincount(inverse.ravel(), weights=self.time_h, minlength=levels.size)
        out = pd.DataFrame({"torque_nm": levels, "time_h": hours, "share": hours / hours.sum(),
                            "flank": np.where(levels < 0, "coast", "drive")})
        return out.iloc[::-1].reset_index(drop=True)

    def plot(self, ax=None):
        """The spectrum as a histogram: each torque class's share of the time (%), summed over the teeth, the
        drive flank's classes (positive torque) and the coast flank's (negative: the torque reversed) in two
        colours. Returns the Axes."""
        from ..validate import require_axes

        if ax is None:
            import matplotlib.pyplot as plt

            _, ax = plt.subplots(figsize=(8, 4.2), constrained_layout=True)
        else:
            require_axes("ax", ax)
        h = self.histogram()
        T = h["torque_nm"].to_numpy()
        gaps = np.diff(np.unique(T))
        width = 0.8 * (float(gaps.min()) if gaps.size else max(abs(float(T[0])), 1.0) * 0.05)
        for flank, colour, label in (("drive", "tab:blue", "drive flank (T > 0)"),
                                     ("coast", "tab:orange", "coast flank (T < 0: the torque reversed)")):
            sel = (h["flank"] == flank).to_numpy()
            if sel.any():
                ax.bar(T[sel], 100.0 * h["share"].to_numpy()[sel], width=width, color=colour, label=label)
        ax.axvline(0.0, color="grey", lw=0.6)
        ax.set_xlabel(f"torque on gear {self.on_gear}, N·m (class value: its end farthest from zero)")
        ax.set_ylabel("share of the time, %")
        kind = "counted per tooth at the mesh instants" if self.per_tooth else "bins"
        span = f"{self.duration_h:.4g} h" if self.duration_h >= 0.1 else f"{3600.0 * self.duration_h:.4g} s"
        ax.set_title(f"load spectrum: {self.torque_nm.size} bins ({kind}), {span}", fontsize=10)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
        return ax

    def __repr__(self) -> str:
        t = np.abs(self.torque_nm)
        kind = ", per tooth" if self.per_tooth else ""
        return (f"LoadSpectrum({self.torque_nm.size} bins{kind}, |T| {t.min():.4g}..{t.max():.4g} N·m on gear "
                f"{self.on_gear}, {self.duration_h:.4g} h{', reversing' if self.reverses else ''})")


def _teeth(teeth) -> tuple:
    if not isinstance(teeth, (tuple, list)) or len(teeth) != 2:
        raise GearDesignError(f"teeth must be the pair's (z1, z2), got {teeth!r}")
    z = tuple(int(v) for v in (require_range("teeth", v, 3, 1e5) for v in teeth))
    if any(v != float(w) for v, w in zip(z, teeth)):
        raise GearDesignError(f"teeth must be whole numbers, got {teeth!r}")
    return z


def _upper_levels(T, levels: int) -> np.ndarray:
    """Each torque of ``T`` as the end farthest from zero of its class: ``levels`` equal classes from 0 to the
    largest torque of each sign."""
    out = np.zeros_like(T)
    for sign in (1.0, -1.0):
        sel = sign * T > 0
        if sel.any():
            top = float(np.max(sign * T[sel]))
            width = top / levels
            out[sel] = sign * np.minimum(np.ceil(sign * T[sel] / width), levels) * width
    return out


def _gear_number(value) -> bool:
    """True for the gear 1 or 2 (an int, or a float 1.0 or 2.0), False for anything else (an array, a bool)."""
    return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool) \
        and value in (1, 2)


def equivalent_torque(torque_nm, cycles, p: float) -> float:
    """The equivalent torque T_eq = (Σ n_i T_i^p / Σ n_i)^(1/p) (N·m) of torques ``torque_nm`` (magnitudes) with
    ``cycles`` n_i each, for the exponent ``p`` of the S-N curve written in torque (ISO 6336-6:2019 Annex A):
    for contact stress σ_H ∝ √T, so p is half the stress exponent; for root stress σ_F ∝ T, the stress
    exponent itself (:func:`~geardesign.gears.strength.service_life.torque_exponent`).

    >>> round(equivalent_torque([400.0], [1e6], 6.6), 9)        # one bin: its torque
    400.0
    >>> round(equivalent_torque([1000.0, 500.0], [1e6, 9e6], 6.6), 1)
    715.0
    """
    T = require_range("torque_nm", torque_nm, 0.0, 1e9, unit="N·m").ravel()
    n = require_range("cycles", cycles, 0.0, 1e18).ravel()
    p = one_number("p", require_range("p", p, 0.0, 100.0, lo_open=True))
    if T.shape != n.shape or not n.sum() > 0:
        raise GearDesignError(f"torque_nm and cycles must be one per bin with some cycles, got {T.size} and {n.size}")
    top = float(T.max())
    if top == 0.0:
        return 0.0
    return top * float((n @ (T / top) ** p) / n.sum()) ** (1.0 / p)    # scaled: T^p overflows at p ~ 100


def application_factor_from_spectrum(equivalent_torque_nm: float, torque_nm: float) -> float:
    """K_A = T_eq/T_n, the application factor a spectrum stands for at the nominal torque T_n (ISO 6336-6:2019
    Annex A; ISO 6336-1:2019 6.3 takes K_A from a measured spectrum this way).

    >>> round(application_factor_from_spectrum(715.0, 500.0), 4)
    1.43
    """
    T_n = one_number("torque_nm", require_range("torque_nm", torque_nm, 0.0, 1e9, lo_open=True, unit="N·m"))
    return one_number("equivalent_torque_nm", require_range("equivalent_torque_nm", equivalent_torque_nm, 0.0, 1e9, unit="N·m")) / T_n
