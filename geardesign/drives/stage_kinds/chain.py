"""The roller chain (:class:`~geardesign.drives.stages.ChainStage`) as a stage kind: sprocket pairs as
options times the catalog rows, every margin in one vectorised pass of chain.design's own
evaluation with one load per design; drawn as two sprockets and the strands."""
from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np

from ..limits import BATCH_BLOCK
from .. import chain as c
from ...catalogs.tables import catalog_dir
from ..chain import design as chain_design
from ..stages import EFFICIENCY_RANGE, ChainStage, disc_mass_kg, stage_area_mm2
from .base import Batch, ToothedKind

__all__ = ["ChainKind"]


def _check_names(stage: ChainStage) -> list:
    """The margins that decide a chain (as chain.design's evaluate): the method's, the centre distance's."""
    cd = ["margin_center_distance"] if stage.center_distance_mm is not None else []
    if stage.method == "hinge_pressure":
        return ["margin_pressure", "margin_safety", "margin_speed", "margin_impacts"] + cd
    return ["margin_power"] + cd + (["margin_safety"] if stage.allowable_safety_factor is not None else [])


def _batch(stage: ChainStage, rows, z1, z2, n1_rpm, torque_nm) -> dict:
    """Every margin, size and mass of chain candidates that each carry their own load."""
    from ..chain.candidates import Candidates
    from ..chain.checks import evaluate
    from ..chain.inputs import with_loads
    from ..chain.tables import reference_tables

    chains = stage.table()
    c = Candidates(chains, rows, z1, z2)
    checks, _ = evaluate(c, with_loads(stage._inputs, n1_rpm, torque_nm), reference_tables(catalog_dir()), summary=False)
    out = {k[len("margin_"):]: np.asarray(c[k], dtype=float) for k in checks}
    de1, de2 = c["sprocket1_tip_diameter_mm"], c["sprocket2_tip_diameter_mm"]
    width = c["width_mm"]
    size = stage_area_mm2(c["center_distance_mm"], de1, de2)
    mass = disc_mass_kg(de1, width) + disc_mass_kg(de2, width) + c["chain_mass_kg"]
    return dict(margins=out, size=size, mass=mass, designation=chains.take("designation", rows),
                strands=np.asarray(c["strands"]), pitch=np.asarray(c["pitch_mm"]), links=np.asarray(c["links"]),
                a=np.asarray(c["center_distance_mm"]))


def _joined(parts: list) -> dict:
    """The dicts of :func:`_batch` over consecutive blocks of designs, as one."""
    out = {k: np.concatenate([p[k] for p in parts]) for k in parts[0] if k != "margins"}
    out["margins"] = {k: np.concatenate([p["margins"][k] for p in parts]) for k in parts[0]["margins"]}
    return out


class ChainKind(ToothedKind):
    name = "chain"
    stage_class = ChainStage
    colour = "#fdd0a2"


    def rows(self, stage):
        return stage.rows()

    def cost_grows_with_load(self, stage) -> bool:
        """The cheapest catalog row that carries the load grows with it (the chain force F_t = 2T/d)."""
        return True

    def batch(self, stage, designs) -> Batch:
        z1, z2 = designs.option["z1"], designs.option["z2"]
        cols = (designs.rows, z1, z2, designs.n_in_rpm, designs.torque_in_nm)
        parts = [_batch(stage, *(c[s:s + BATCH_BLOCK] for c in cols))
                 for s in range(0, max(len(designs.n_in_rpm), 1), BATCH_BLOCK)]
        ch = parts[0] if len(parts) == 1 else _joined(parts)
        return Batch(margins=ch["margins"], size_mm2=ch["size"], mass_kg=ch["mass"], info=dict(ch, z1=z1, z2=z2))

    def design_columns(self, stage, option: dict, info, c: int) -> dict:
        p = stage.name
        return {f"{p}.designation": str(info["designation"][c]), f"{p}.strands": int(info["strands"][c]),
                f"{p}.pitch_mm": float(info["pitch"][c]), f"{p}.z1": int(info["z1"][c]),
                f"{p}.z2": int(info["z2"][c]), f"{p}.links": int(info["links"][c]),
                f"{p}.center_distance_mm": float(info["a"][c])}

    def fix(self, stage, option: dict, info, c: int, objective: str, flow=None):
        return replace(stage, z1=int(info["z1"][c]), z2=int(info["z2"][c]), designation=str(info["designation"][c]),
                       strands=(int(info["strands"][c]),))

    def analyse(self, stage, flow, objective: str) -> dict:
        """A chain stage by chain.design with the flow's load (its designation, when fixed, picks the row)."""
        st = stage
        res = chain_design(torque_nm=float(flow.torque_in_nm), n1_rpm=float(flow.n_in_rpm), ratio=st.z2 / st.z1,
                           z1=st.z1, **st.design_kwargs())
        cand = res.candidates
        if st.designation is not None:
            cand = cand[cand["designation"] == st.designation]
        row = cand.iloc[0]   # ranked: the best feasible, or the closest when none passes
        de1, de2, w = row["sprocket1_tip_diameter_mm"], row["sprocket2_tip_diameter_mm"], row["width_mm"]
        return dict(stage=st, design=res, row=row, margins={k[len("margin_"):]: float(row[k]) for k in _check_names(st)},
                    size=float(stage_area_mm2(row["center_distance_mm"], de1, de2)),
                    mass=float(disc_mass_kg(de1, w) + disc_mass_kg(de2, w) + row["chain_mass_kg"]),
                    summary=dict(name=st.name, kind="chain", designation=row["designation"],
                                 strands=int(row["strands"]), pitch_mm=float(row["pitch_mm"]), z1=st.z1, z2=st.z2,
                                 links=int(row["links"]), center_distance_mm=float(row["center_distance_mm"]),
                                 ratio=st.z2 / st.z1, efficiency=st.efficiency))

    # -- scenes
    def scene_keys(self) -> dict:
        f = "float"
        return {"catalog": dict(kind="str", default="gost13568"), "z1": dict(kind="int", lo=c.Z1_RANGE[0], hi=c.Z1_RANGE[1]),
                "z2": dict(kind="int", lo=c.Z1_RANGE[0], hi=c.Z2_MAX_LIMIT), "designation": dict(kind="str"),
                "strands": dict(kind="ints", lo=c.STRANDS_RANGE[0], hi=c.STRANDS_RANGE[1]),
                "efficiency": dict(kind=f, default=0.96, lo=EFFICIENCY_RANGE[0], hi=EFFICIENCY_RANGE[1], lo_open=True),
                "k_e": dict(kind=f, lo=c.K_E_RANGE[0], hi=c.K_E_RANGE[1]),
                "allowable_pressure_mpa": dict(kind=f, lo=0.0, lo_open=True),
                "allowable_safety_factor": dict(kind=f, lo=c.SAFETY_FACTOR_RANGE[0], hi=c.SAFETY_FACTOR_RANGE[1]),
                "method": dict(kind="choice", default=c.METHODS[0], choices=c.METHODS),
                "center_distance_mm": dict(kind=f, lo=c.CENTER_DISTANCE_MIN_MM, hi=c.CENTER_DISTANCE_MAX_MM),
                "sag_factor": dict(kind=f, default=6.0, lo=c.SAG_FACTOR_RANGE[0], hi=c.SAG_FACTOR_RANGE[1]),
                "z2_max": dict(kind="int", default=120, lo=9, hi=c.Z2_MAX_LIMIT),
                "ratio_range": dict(kind="floats", lo=c.RATIO_RANGE[0], hi=c.RATIO_RANGE[1], length=2),
                "objective": dict(kind="choice", default=c.OBJECTIVES[0], choices=c.OBJECTIVES),
                "conditions": {key: dict(kind="float_or_str", lo=c.FACTOR_RANGE[0], hi=c.FACTOR_RANGE[1], choices=())
                               for key in c.FACTOR_NAMES}}

    def scene_spec(self, spec: dict, folder) -> dict:
        if spec["catalog"].lower().endswith(".csv"):   # a user's catalog sits beside the scene
            spec["catalog"] = str(Path(folder) / spec["catalog"])
        return spec

    def from_scene(self, spec: dict):
        kw = dict(spec)
        if kw.get("conditions"):
            kw["conditions"] = dict(kw["conditions"])
        for k in ("strands", "ratio_range"):
            if k in kw:
                kw[k] = tuple(kw[k])
        return ChainStage(**kw)

    # -- diagram
    wheels = True

    def first_offset(self, summary: dict) -> float:
        return 0.35

    def last_offset(self, summary: dict) -> float:
        return min(0.35 * summary["ratio"], 0.9)

    def draw(self, canvas, x: float, summary: dict) -> tuple:
        """Two sprockets and the chain's strands between them."""
        s = summary
        r1 = 0.35
        r2 = min(r1 * s["ratio"], 0.9)
        x2 = x + r1 + r2 + 0.8
        for xc, r in ((x, r1), (x2, r2)):
            canvas.circle(xc, r, self.colour)
        canvas.line([x, x2], [r1, r2])
        canvas.line([x, x2], [-r1, -r2])
        return x2, f"{s['name']}: {s['designation']}\nz {s['z1']}/{s['z2']}, {s['links']} links"
