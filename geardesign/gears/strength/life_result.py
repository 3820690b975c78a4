"""The service life of one gear pair under a load spectrum as a result object (ISO 6336-6:2019): Miner's sums, lives
and safety factors per gear for pitting and root, the per-bin table (each bin's K factors, stresses, endured and
applied cycles, damage) and the S-N diagram with the spectrum on it."""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ...errors import GearDesignError
from ...results import Result, frame_html
from .service_life import MODES, pair_life

__all__ = ["LifeResult", "service_life"]

_MODE_NAMES = {"H1": "pitting, gear 1", "H2": "pitting, gear 2", "F1": "root, gear 1", "F2": "root, gear 2"}


@dataclass(frozen=True)
class LifeResult(Result):
    """ISO 6336-6 service life of one pair under a spectrum. ``D_H1, D_H2`` (pitting) and ``D_F1, D_F2`` (root):
    Miner's sums over ``required_life_h`` (the governing tooth and flank); ``life_h_*`` the hours to D = 1;
    ``S_*`` the safety factors for the required life (the factor on every bin's stress that makes D = 1);
    ``bins`` a DataFrame of each loaded bin (columns in :attr:`bins`'s docstring); ``sn_curve`` the variant
    beyond the knee; ``mean_stress_factor`` the (Y_M1, Y_M2) applied to reversing teeth; ``notes`` what left a
    range. ``ok``: every D <= 1."""

    D_H1: float
    D_H2: float
    D_F1: float
    D_F2: float
    life_h_H1: float
    life_h_H2: float
    life_h_F1: float
    life_h_F2: float
    S_H1: float
    S_H2: float
    S_F1: float
    S_F2: float
    required_life_h: float
    sn_curve: str = "iso"
    mean_stress_factor: tuple = (1.0, 1.0)
    notes: tuple = ()
    title: str = ""
    _bins: object = field(default=None, repr=False, compare=False)   # the per-bin DataFrame, or what builds it
    _curves: dict = field(default=None, repr=False, compare=False)
    _success_field = "ok"
    _table_fields = ("bins",)

    @property
    def ok(self) -> bool:
        """True when every damage sum is at most 1 (the required life is reached)."""
        return all(getattr(self, "D_" + m) <= 1.0 for m in MODES)

    @property
    def life_h(self) -> float:
        """The pair's life (hours): the shortest of its gears' and modes' lives (the governing one's)."""
        return min(getattr(self, "life_h_" + m) for m in MODES)

    @property
    def governing(self) -> tuple:
        """(mode, D) of the largest damage sum: mode "H1", "H2" (pitting) or "F1", "F2" (root)."""
        mode = max(MODES, key=lambda m: getattr(self, "D_" + m))
        return mode, getattr(self, "D_" + mode)

    @property
    def bins(self):
        """Per loaded bin: torque_nm (signed), n_rpm, time_h, n1, n2 (load cycles of a tooth of each gear over the
        required life), K_v, K_Hbeta, K_Halpha, K_Fbeta, K_Falpha, sigma_H1, sigma_H2, sigma_F1, sigma_F2 (MPa),
        N_H1 … N_F2 (cycles endured at the bin's stress) and D_H1 … D_F2 (the bin's n/N)."""
        return self._table().copy()

    def _table(self):
        """The per-bin DataFrame, built on first use (see :class:`_BinTable`) and kept."""
        if callable(self._bins):
            object.__setattr__(self, "_bins", self._bins())
        return self._bins

    def damage_table(self):
        """One row per gear and mode: ``mode`` (pitting or root), ``gear``, Miner's sum ``D`` over the required
        life, ``life_h`` (hours to D = 1), the safety factor ``S`` for the required life and ``ok`` (D <= 1)."""
        import pandas as pd

        return pd.DataFrame([{"mode": "pitting" if m[0] == "H" else "root", "gear": int(m[1]),
                              "D": getattr(self, "D_" + m), "life_h": getattr(self, "life_h_" + m),
                              "S": getattr(self, "S_" + m), "ok": getattr(self, "D_" + m) <= 1.0} for m in MODES])

    def to_dict(self) -> dict:
        from ...results import plain

        out = super().to_dict()
        out.update(ok=self.ok, governing=self.governing[0], bins=plain(self._table()))
        return out

    def __repr__(self) -> str:
        mode, D = self.governing
        rows = "\n".join(f"  {_MODE_NAMES[m]:16s} D = {getattr(self, 'D_' + m):.4g}  life {getattr(self, 'life_h_' + m):.4g} h"
                         f"  S = {getattr(self, 'S_' + m):.4g}" for m in MODES)
        head = f"LifeResult {self.title}: {'ok' if self.ok else 'FAILS'} for {self.required_life_h:.6g} h"
        return f"{head} (governing {_MODE_NAMES[mode]}, D = {D:.4g}; S-N curve {self.sn_curve!r})\n{rows}"

    def _repr_html_(self) -> str:
        import html

        return f"<pre>{html.escape(repr(self))}</pre>" + frame_html(self._table())

    def plot(self, path=None, overwrite: bool = False):
        """The S-N diagram of each gear and mode with the spectrum on it (stress against the cumulative cycles of
        the bins, highest first, as ISO 6336-6:2019 Figure C.1 draws it) and the spectrum times the safety factor
        S (dashed): a matplotlib Figure, saved to ``path`` (PNG/SVG/PDF) when given."""
        import matplotlib

        if path is not None:
            matplotlib.use("Agg", force=False)
        import matplotlib.pyplot as plt

        if path is not None:
            from ...files import check_output_path

            target = check_output_path(path, overwrite=overwrite, suffixes=(".png", ".svg", ".pdf"))
        fig, axes = plt.subplots(2, 2, figsize=(10, 7), sharex=True)
        for ax, mode in zip(axes.ravel(), MODES):
            g = int(mode[1])
            b, which = self._governing_bins(mode)
            sigma = np.abs(b[f"sigma_{mode[0]}{g}"].to_numpy())
            ref = b[f"sigma_ref_{mode}"].to_numpy()
            n = b[f"n{g}"].to_numpy()
            order = np.argsort(-sigma)
            cum = np.cumsum(n[order])
            top = int(order[0])
            N = np.logspace(2, 11, 300)
            curve = self._curves[mode]
            f = _strength_factor(N, curve, self.sn_curve)
            ax.loglog(N, ref[top] * f, "k-", lw=1.8, label=f"S-N curve ({self.sn_curve})")
            stairs = np.concatenate([[1.0], cum])
            ax.stairs(sigma[order], stairs, color="tab:blue", lw=1.6, label="spectrum")
            S = getattr(self, "S_" + mode)
            if math.isfinite(S):
                ax.stairs(S * sigma[order], stairs, color="tab:red", lw=1.2, ls="--", label=f"spectrum × S = {S:.3g}")
            ax.set_title(f"{_MODE_NAMES[mode]}{which}: D = {getattr(self, 'D_' + mode):.3g}", fontsize=10)
            ax.set_ylabel("σ_H, MPa" if mode[0] == "H" else "σ_F, MPa")
            ax.grid(True, which="both", alpha=0.3)
            ax.set_xlim(1e2, 1e11)
            ax.legend(fontsize=7, loc="lower left")
        for ax in axes[1]:
            ax.set_xlabel("load cycles N")
        fig.suptitle(f"ISO 6336-6 service life {self.title} over {self.required_life_h:.6g} h")
        fig.tight_layout()
        if path is not None:
            from ...files import write_file_atomic

            write_file_atomic(target, lambda tmp: fig.savefig(tmp, dpi=110))
        return fig


    def _governing_bins(self, mode: str) -> tuple:
        """The bins whose cycles sum on one tooth flank of the mode's gear, and a phrase naming it: for a spectrum
        counted per tooth, the tooth and flank whose damage governs D (where none has damage, the one that governs
        at the stresses times the safety factor S, which reach D = 1 there); otherwise every bin (each stands for
        every tooth)."""
        from .service_life import cycles_to_failure

        b = self._table()
        g = int(mode[1])
        if f"tooth{g}" not in b.columns:
            return b, ""
        coast = (b["torque_nm"] < 0).to_numpy()
        group = b[f"tooth{g}"].to_numpy() * 2 + coast
        d = b["D_" + mode].to_numpy()
        S = getattr(self, "S_" + mode)
        if not d.max() > 0 and math.isfinite(S):
            ratio = S * np.abs(b[f"sigma_{mode[0]}{g}"].to_numpy()) / b["sigma_ref_" + mode].to_numpy()
            d = b[f"n{g}"].to_numpy() / cycles_to_failure(ratio, self._curves[mode], self.sn_curve)
        if d.max() > 0:
            top = int(np.argmax(np.bincount(group, weights=d)))
        else:
            top = int(group[np.argmax(np.abs(b[f"sigma_{mode[0]}{g}"].to_numpy()))])
        sel = group == top
        return b.loc[sel], f" (tooth {top // 2}, {'coast' if top % 2 else 'drive'} flank)"


def _strength_factor(N, curve, sn_curve):
    """f(N) of the S-N curve variant: the life factor at N (the inverse of cycles_to_failure)."""
    from .service_life import _variant

    x, y, tail = _variant(curve, sn_curve)
    lnN = np.log(N)
    inside = np.interp(lnN, x, y)           # the static level before the first point, the last after the last
    if tail is not None:                    # a sloped tail: N ∝ f^-tail beyond the last point
        inside = np.where(lnN > x[-1], y[-1] - (lnN - x[-1]) / tail, inside)
    return np.exp(inside)


def service_life(pair, spectrum, material=None, *, material2=None, face_width_mm=None, life_h=None,
                 sn_curve: str = "iso", mean_stress_factor=None, **options) -> LifeResult:
    """ISO 6336-6 service life of one :class:`~geardesign.GearPair` under ``spectrum`` (a
    :class:`~geardesign.gears.spectrum.LoadSpectrum`) as a :class:`LifeResult`: ``material`` as
    :func:`~geardesign.gears.strength.chain.strength` takes it, ``life_h`` the required life (None: the spectrum's
    duration), ``sn_curve`` and ``mean_stress_factor`` as :func:`~.service_life.pair_life`, ``options`` those of
    :func:`~geardesign.gears.strength.chain.pair_strength`.

    >>> from geardesign import GearPair
    >>> from geardesign.gears.spectrum import LoadSpectrum
    >>> pair = GearPair(m=4, z1=20, z2=60, x1=0.3, x2=0.1, face_width_mm=40)
    >>> spec = LoadSpectrum.from_bins([300, 150], 1000, share=[0.2, 0.8], duration_h=20000)
    >>> r = service_life(pair, spec, "42CrMo4")
    >>> r.governing[0], r.ok
    ('H1', False)
    """
    from .chain import check_options

    if material is None:
        raise GearDesignError("material is needed (a geardesign Material or a name such as '42CrMo4')")
    check_options(options)
    b = pair.face_width_mm if face_width_mm is None else face_width_mm
    if b is None:
        raise GearDesignError("face_width_mm is needed: give it, or build the GearPair with face_width_mm=")
    options.setdefault("geometry", getattr(pair, "_geo", None))
    out = pair_life(np.float64(pair.m), pair.z1, pair.z2, pair.x1, pair.x2, spectrum=spectrum, material1=material,
                    material2=material2, face_width_mm=b, life_h=life_h, sn_curve=sn_curve,
                    mean_stress_factor=mean_stress_factor, bins=True, beta_deg=pair.beta_deg, internal=pair.internal,
                    rack=pair.rack, tip_shortening=pair.tip_shortening, **options)
    return _result(out, spectrum, sn_curve, title=f"{pair.z1}/{pair.z2} m={pair.m:g}")


class _BinTable:
    """The per-bin DataFrame of a :class:`LifeResult`, built when first read (a result the solvers, scenes and
    commands only rank or print needs no pandas frame): the chain's per-bin arrays and the spectrum it came from."""

    def __init__(self, out: dict, spectrum):
        self.out, self.spectrum = out, spectrum

    def __call__(self):
        import pandas as pd

        out, spectrum = self.out, self.spectrum
        i = out["bin_index"]
        cols = {"torque_nm": spectrum.torque_nm[i], "n_rpm": spectrum.n_rpm[i], "time_h": spectrum.time_h[i]}
        if spectrum.per_tooth:
            cols.update(tooth1=spectrum.tooth1[i], tooth2=spectrum.tooth2[i])
        cols.update(n1=out["n1"], n2=out["n2"])
        for k in ("K_v", "K_Hbeta", "K_Halpha", "K_Fbeta", "K_Falpha", "sigma_H1", "sigma_H2", "sigma_F1",
                  "sigma_F2"):
            cols[k] = out["bin_" + k]
        for m in MODES:
            cols["sigma_ref_" + m] = out["bin_" + ("sigma_HG" if m[0] == "H" else "sigma_FG") + m[1]] * (
                1.0 if m[0] == "H" else np.where(out[f"bin_reversing{m[1]}"], out["mean_stress_factor"][int(m[1]) - 1],
                                                 1.0))
        for m in MODES:
            cols["N_" + m] = out["N_" + m]
            with np.errstate(invalid="ignore"):
                cols["D_" + m] = np.where(out[f"n{m[1]}"] > 0, out[f"n{m[1]}"] / out["N_" + m], 0.0)
        return pd.DataFrame(cols)


def _result(out: dict, spectrum, sn_curve, title) -> LifeResult:
    notes = []
    if out["static_exceeded"]:
        notes.append("a bin's stress exceeds the S-N curve's static level: its first line was continued upward "
                     "(ISO 6336 does not cover it)")
    if np.any(np.asarray(out["bin_K_v"]) > 3.0):
        notes.append("K_v > 3 in some bin: a light bin's line load lies far below the range of ISO 6336-1's method B")
    return LifeResult(**{k: float(out[k]) for k in (*(f"{q}_{m}" for q in ("D", "life_h", "S") for m in MODES),
                                                    "required_life_h")},
                      sn_curve=sn_curve, mean_stress_factor=tuple(out["mean_stress_factor"]), notes=tuple(notes),
                      title=title, _bins=_BinTable(out, spectrum), _curves=out["curves"])
