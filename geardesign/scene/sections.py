"""The scene's sections, each run into a :class:`SceneReport`: tables, figures and Markdown in memory.
Each runner imports only the part of the library its section models."""
from __future__ import annotations

from dataclasses import dataclass, field

from ..results import Result
from .load import Scene, scene_kind
from .markdown import md_table, pyplot

__all__ = ["SceneReport", "RUNNERS", "run_study", "base_from_scene", "chain_kwargs"]


@dataclass
class SceneReport(Result):
    """Everything a scene produced, in memory: tables, figures, Markdown and a summary."""

    scene: Scene
    tables: dict = field(default_factory=dict)      # name -> DataFrame (written as name.csv)
    figures: dict = field(default_factory=dict)     # name -> matplotlib Figure (written as name.png)
    markdown: list = field(default_factory=list)
    summary: list = field(default_factory=list)
    results: dict = field(default_factory=dict)     # section -> result object(s)
    time_s: float = 0.0

    success = True   # a section that fails raises; a report exists only when all ran

    @property
    def failures(self) -> list:
        """What the scene's designs fail, one phrase each (empty when every design passes): an empty
        shift region, a given pair or planetary set failing a check, no tooth counts, no chain, a key
        that does not fit, a failing drive. The ``run`` command exits 1 when there is one."""
        out = []
        engine = self.results.get("engine")
        if engine is not None and not engine.success:
            out.append("engine: no work over the cycle")
        gear = self.results.get("gear")
        if gear is not None and not gear["optimum"].success:
            out.append("gear: no feasible shifts")
        given = self.tables.get("gear_given_checks")
        if given is not None and not given["ok"].all():
            out.append("gear: the given shifts fail " + ", ".join(given.loc[~given["ok"], "check"]))
        for name in ("teeth", "chain", "planetary"):
            r = self.results.get(name)
            if r is not None and hasattr(r, "status") and r.status != "success":
                out.append(f"{name}: nothing feasible")
        planetary = self.tables.get("planetary_checks")
        if planetary is not None and not planetary["ok"].all():
            out.append("planetary: the set fails " + ", ".join(planetary.loc[~planetary["ok"], "check"]))
        for sel in self.results.get("key", []):
            if not sel.feasible:
                out.append(f"key d = {sel.d_mm:g} mm: no key fits")
        drive = self.results.get("drive")
        if drive is not None:
            r = drive["optimum"] if drive["optimum"] is not None else drive["analysis"]
            if r is not None and not r.success:
                out.append("drive: fails")
        return out

    def __repr__(self) -> str:
        lines = [f"SceneReport({self.scene.title!r}: {len(self.tables)} table(s), {len(self.figures)} figure(s), "
                 f"{self.time_s:.2f} s; {'every design passes' if not self.failures else 'FAILS'})"]
        lines += [f"  {line}" for line in self.summary[:10]]
        lines += [f"  fails: {f}" for f in self.failures[:3]]
        return "\n".join(lines)

    def to_dict(self) -> dict:
        return {"ok": not self.failures, "failures": self.failures, "status": self.status, "scene": self.scene.path, "title": self.scene.title, "summary": list(self.summary),
                "tables": sorted(f"{k}.csv" for k in self.tables), "figures": sorted(f"{k}.png" for k in self.figures),
                "time_s": self.time_s}


def _checks_dict(spec: dict | None, section: dict | None = None) -> dict | None:
    """The section's [checks] as make_checks options, with its [load] (the strength checks' load case)."""
    out = dict(spec or {})
    load = (section or {}).get("load")
    if load:
        from ..gears.strength import Load
        from ..gears.strength.user_options import options_from_table

        strength, _ = options_from_table(load)
        # the [checks] limits are the strength result's S_Hmin, S_Fmin too (its sigma_HP, sigma_FP, verdict)
        strength.update({k: out[k] for k in ("S_Hmin", "S_Fmin") if out.get(k) is not None})
        out.update(load=Load(**{k: load.get(k) for k in ("torque_nm", "power_kw", "n_rpm", "on_gear",
                                                        "application_factor", "life_h")}),
                   material=load["material"], material2=load.get("material2"),
                   face_width_mm=section.get("face_width_mm"), **({"strength": strength} if strength else {}))
    spectrum = (section or {}).get("spectrum")
    if spectrum:   # the damage checks (ISO 6336-6): their own materials, the load's width and strength options
        out.update(spectrum=spectrum["_spectrum"], life_h=spectrum.get("life_h"), sn_curve=spectrum["sn_curve"],
                   **({"mean_stress_factor": spectrum["mean_stress_factor"]} if "mean_stress_factor" in spectrum
                      else {}))
        if not load:
            out.update(material=spectrum["material"], material2=spectrum.get("material2"),
                       face_width_mm=section.get("face_width_mm"))
    return out or None


def _run_gear(rep: SceneReport, g: dict):
    """The gear section: the best shifts, the feasible region, the given shifts if any, and their pictures."""
    from ..gears.pair import GearPair

    checks = _checks_dict(g.get("checks"), g)
    kind = scene_kind(g)
    res, reg = _gear_solve(g, checks, kind)
    rep.results["gear"] = {"optimum": res, "region": reg}
    _gear_heading(rep, g, checks, kind, reg)
    _gear_optimum(rep, g, res, reg)
    pair_kw = dict(**({"rack": g["_rack"]} if g["_rack"] else {}), tip_shortening=g["tip_shortening"], **kind)
    geo_opt = GearPair(g["module"], g["z1"], g["z2"], res.x1, res.x2, **pair_kw).geometry().to_frame()
    rep.tables["gear_optimum_geometry"] = geo_opt
    given = _gear_given(rep, g, checks, pair_kw) if "x1" in g else None
    rep.markdown += ["Geometry at the optimum (mm, degrees):", "", md_table(geo_opt[["quantity", "value", "unit"]]),
                     ""]
    _gear_pictures(rep, g, res, reg, given, pair_kw)
    if checks and "load" in checks:
        _add_strength(rep, g, checks, res, given, pair_kw)
    if checks and "spectrum" in checks:
        _add_life(rep, g, checks, res, given, pair_kw)


def _gear_solve(g: dict, checks, kind: dict):
    """The optimum (optimize_shifts) and the feasible region (feasible_region) of the section's pair."""
    from ..shifts.optimize import optimize_shifts
    from ..shifts.region import feasible_region

    kw = dict(checks=checks, rack=g["_rack"], tip_shortening=g["tip_shortening"], bounds=tuple(g["bounds"]), **kind)
    res = optimize_shifts(g["z1"], g["z2"], objective=g.get("objective"), method=g["method"], m=g["module"],
                          a_w=g.get("a_w"), **kw)
    return res, feasible_region(g["z1"], g["z2"], m=g["module"], **kw)


def _gear_heading(rep: SceneReport, g: dict, checks, kind: dict, reg) -> None:
    """The section's title, its checks and limits, and the region's area or conflict, in Markdown."""
    from ..gears.mesh import kind_text

    md = rep.markdown
    md += [f"## Gear pair z1/z2 = {g['z1']}/{g['z2']}{kind_text(kind['beta_deg'], kind['internal'])}, m = {g['module']:g} mm", ""]
    # the limits and the load's names (a spectrum or a Load object shows in its own section)
    limits = {k: v for k, v in (checks or {}).items() if isinstance(v, (bool, int, float, str))}
    md += [f"Checks: {', '.join(reg.checks)}" + (f" (limits: {', '.join(f'{k} = {v}' for k, v in limits.items())})"
                                                  if limits else " (default limits: ε_α >= 1.2, s_a >= 0.25 m)"), ""]
    if reg.feasible:
        md += [f"Feasible region of (x1, x2): area {reg.area:.4f}, bounded by {', '.join(reg.limiting_checks())}.", ""]
    else:
        md += [f"The feasible region is **empty**: checks {', '.join(reg.conflict)} conflict.", ""]


def _gear_optimum(rep: SceneReport, g: dict, res, reg) -> None:
    """The optimum's table, its margins and sensitivities, the region's boundary and the summary line."""
    import pandas as pd

    opt = pd.DataFrame([{"objective": res.objective, "method": res.method, "x1": res.x1, "x2": res.x2,
                         "x_sum": res.x_sum, "fun": res.fun, "eps_alpha": res.eps_alpha,
                         "a_w_mm": res.a_w, "active": ", ".join(res.active) or "-", "success": res.success}])
    rep.tables["gear_optimum"] = opt
    rep.tables["gear_optimum_checks"] = res.to_frame()
    rep.tables["gear_region_boundary"] = reg.boundary
    rep.markdown += ["### Optimum", "", f"{res.message}.", "", md_table(opt), "",
                     "Margins of every check at the optimum, and d(fun)/d(limit) of the active ones:", "",
                     md_table(res.to_frame()), ""]
    sm = (f"gear {g['z1']}/{g['z2']} m={g['module']:g}: optimum ({res.objective}) x1 = {res.x1:.4f}, "
          f"x2 = {res.x2:.4f}, eps_alpha = {res.eps_alpha:.4f}, a_w = {res.a_w:.4f} mm, "
          f"active {', '.join(res.active) or '-'}; region area {reg.area:.4f}")
    rep.summary.append(sm if res.success else f"gear {g['z1']}/{g['z2']}: no feasible shifts: {res.message}")


def _gear_given(rep: SceneReport, g: dict, checks, pair_kw: dict) -> tuple:
    """The given shifts' checks and geometry (tables, Markdown, summary line); returns (x1, x2)."""
    from ..gears.pair import GearPair

    pair = GearPair(g["module"], g["z1"], g["z2"], g["x1"], g["x2"], **pair_kw)
    lim = {k: v for k, v in (checks or {}).items()}
    # with a housing a_w as well, the given shifts are checked against it (center_distance)
    chk = pair.checks(**lim, housing_a_w=g.get("a_w"))
    geo = pair.geometry().to_frame()
    rep.tables["gear_given_geometry"] = geo
    rep.tables["gear_given_checks"] = chk
    failed = chk.loc[~chk["ok"], "check"].tolist()
    verdict = ("passes every check" if not failed else f"**fails** {', '.join(failed)}")
    ga = pair.geometry()
    rep.markdown += [f"### Given shifts x1 = {g['x1']:g}, x2 = {g['x2']:g}", "",
                     f"This pair {verdict}: α_w = {ga.alpha_w_deg:.4f}°, a_w = {ga.a_w:.4f} mm, "
                     f"ε_α = {ga.eps_alpha:.4f}.", "", md_table(chk.drop(columns=["label"])), "",
                     "Geometry of the given pair (mm, degrees):", "", md_table(geo[["quantity", "value", "unit"]]), ""]
    rep.summary.append(f"given x1/x2 = {g['x1']:g}/{g['x2']:g}: eps_alpha = {ga.eps_alpha:.4f}, "
                       + ("all checks pass" if not failed else f"FAILS {', '.join(failed)}"))
    return g["x1"], g["x2"]


def _gear_pictures(rep: SceneReport, g: dict, res, reg, given, pair_kw: dict) -> None:
    """The blocking contour with the optimum and the given point, and on request the meshing drawings
    and the drawings' data blocks of both pairs."""
    from ..gears.pair import GearPair

    plt = pyplot()
    fig, ax = plt.subplots(figsize=(8.6, 6.2))
    reg.plot(ax=ax, optimum=res if res.success else None, proposed=given, x_sum=res.x_sum_fixed)
    rep.figures["gear_region"] = fig
    rep.markdown += ["![blocking contour](gear_region.png)", ""]
    # the optimum is drawn only where one was found, the given pair only where the scene gives one
    drawn = ([("optimum", res.x1, res.x2)] if res.success else []) + ([("given", *given)] if given else [])
    if g["mesh_drawing"]:
        for tag, x1, x2 in drawn:
            _add_mesh_drawing(rep, GearPair(g["module"], g["z1"], g["z2"], x1, x2, **pair_kw), tag)
    if g["data_block"]:
        for tag, x1, x2 in drawn:
            _add_data_blocks(rep, GearPair(g["module"], g["z1"], g["z2"], x1, x2, **pair_kw), tag, g.get("accuracy_class"))


def _add_strength(rep: SceneReport, g: dict, checks: dict, res, given, pair_kw: dict):
    """ISO 6336 at the optimum and at the given shifts: the safety factors and the factor table."""
    from ..gears.pair import GearPair

    pairs = ([("optimum", res.x1, res.x2)] if res.success else []) + ([("given", *given)] if given else [])
    for tag, x1, x2 in pairs:
        r = GearPair(g["module"], g["z1"], g["z2"], x1, x2, **pair_kw).strength(
            checks["load"], checks["material"], material2=checks["material2"], face_width_mm=checks["face_width_mm"],
            **checks.get("strength", {}))
        rep.tables[f"gear_strength_{tag}"] = r.factors
        rep.markdown += [f"### Load capacity (ISO 6336) of the {tag} pair", "", "```", repr(r), "```", "",
                         md_table(r.factors), ""]
        rep.summary.append(f"{tag} pair: S_H = {min(r.S_H1, r.S_H2):.3f}, S_F = {r.S_F1:.3f} / {r.S_F2:.3f}"
                           f" ({'holds' if r.ok else 'FAILS'} S_Hmin {r.S_Hmin:g}, S_Fmin {r.S_Fmin:g})")


def _add_life(rep: SceneReport, g: dict, checks: dict, res, given, pair_kw: dict):
    """ISO 6336-6 service life at the optimum and at the given shifts: the verdict, the bins and the S-N diagram."""
    from ..gears.pair import GearPair

    sp = g["spectrum"]
    spectrum = checks["spectrum"]
    rep.tables["gear_spectrum"] = spectrum.histogram()
    fig = spectrum.plot().figure
    rep.figures["gear_spectrum"] = fig
    source = ("the [engine]'s torque curve counted at the mesh instants, per tooth and flank"
              if sp.get("_engine") else f"`{sp['file']}`")
    rep.markdown += ["### Load spectrum (ISO 6336-6)", "",
                     f"From {source}: {spectrum!r}; required life {sp.get('life_h', spectrum.duration_h):.6g} h, "
                     f"S-N curve {sp['sn_curve']!r}"
                     + (f", mean stress factor Y_M = {sp['mean_stress_factor']:g} on the teeth loaded on both flanks"
                        if "mean_stress_factor" in sp else "") + ".", "",
                     "![load spectrum: time share of each torque class](gear_spectrum.png)", ""]
    pairs = ([("optimum", res.x1, res.x2)] if res.success else []) + ([("given", *given)] if given else [])
    for tag, x1, x2 in pairs:
        r = GearPair(g["module"], g["z1"], g["z2"], x1, x2, **pair_kw).life(
            checks["spectrum"], sp["material"], material2=sp.get("material2"), face_width_mm=checks["face_width_mm"],
            life_h=sp.get("life_h"), sn_curve=sp["sn_curve"], mean_stress_factor=sp.get("mean_stress_factor"),
            **checks.get("strength", {}))
        rep.results.setdefault("life", {})[tag] = r
        rep.tables[f"gear_life_{tag}"] = r.bins
        rep.tables[f"gear_damage_{tag}"] = r.damage_table()
        rep.figures[f"gear_life_{tag}"] = r.plot()
        rep.markdown += [f"### Service life (ISO 6336-6) of the {tag} pair (x1/x2 = {x1:.4f}/{x2:.4f})", "",
                         "```", repr(r), "```", "", md_table(r.damage_table()), "",
                         f"![S-N diagrams with the spectrum]({f'gear_life_{tag}'}.png)", ""]
        rep.summary.append(f"{tag} pair: damage D_H = {r.D_H1:.3g} / {r.D_H2:.3g}, D_F = {r.D_F1:.3g} / {r.D_F2:.3g} "
                           f"over {r.required_life_h:.6g} h ({'holds' if r.ok else 'FAILS'})")


def _add_data_blocks(rep: SceneReport, pair, tag: str, accuracy_class):
    """The drawing's data block of both gears of one pair (geardesign.gears.data_block), as tables."""
    from ..gears.data_block import data_block

    rep.markdown += [f"### Data blocks of the {tag} pair (x1/x2 = {pair.x1:.4f}/{pair.x2:.4f})", ""]
    for gear in (1, 2):
        table = data_block(pair, gear, accuracy_class)
        rep.tables[f"gear_data_block_{tag}_{gear}"] = table
        rep.markdown += [f"Gear {gear}:", "", md_table(table), ""]


def _add_mesh_drawing(rep: SceneReport, pair, tag: str):
    """The meshing drawing and the line-of-action diagrams of one pair, as two figures."""
    from ..profiles.drawing import plot_diagrams, plot_mesh

    rep.figures[f"gear_mesh_{tag}"] = plot_mesh(pair).figure
    rep.figures[f"gear_diagrams_{tag}"] = plot_diagrams(pair)[0].figure
    rep.markdown += [f"### The {tag} pair in mesh (x1/x2 = {pair.x1:.4f}/{pair.x2:.4f})", "",
                     f"![{tag} pair in mesh](gear_mesh_{tag}.png)", "",
                     f"![specific sliding and pressure along the line of action](gear_diagrams_{tag}.png)", ""]


def _run_engine(rep: SceneReport, e):
    """The [engine] section: the crankshaft's torque over the cycle (summary, table, plot)."""
    res = e.engine.analyse(e.points)
    rep.results["engine"] = res
    rep.tables["engine_torque"] = res.table()
    pyplot()
    rep.figures["engine_torque"] = res.plot().figure
    rep.markdown += [f"## Engine: {e.engine.cylinders} cylinder(s), {e.engine.n_rpm:g} rpm", "",
                     *[f"- {line}" for line in res.summary()], "",
                     "![the crankshaft's torque over the cycle](engine_torque.png)", ""]
    rep.summary.append(f"engine: mean torque M_i = {res.mean_torque_nm:.6g} N·m, "
                       f"{float(res.torque_nm.min()):.6g} … {float(res.torque_nm.max()):.6g} N·m, "
                       f"{len(res.reversal_angles_deg)} reversals per cycle"
                       + ("" if res.success else " (the engine does no work over the cycle)"))


def _run_teeth(rep: SceneReport, t: dict):
    from ..gears.mesh import kind_text
    from ..shifts.teeth import select_teeth

    kw = dict(ratio=t["ratio"], ratio_tol=t["ratio_tol"], m=t.get("module"), a_w=t.get("a_w"),
              z1_range=tuple(t["z1_range"]), z_sum_max=t.get("z_sum_max"), objective=t.get("objective"),
              checks=_checks_dict(t.get("checks"), t), rack=t["_rack"], method=t["method"], **scene_kind(t))
    sel = select_teeth(**kw, client=t.get("_client"))
    rep.results["teeth"] = sel
    rep.tables["teeth"] = sel.table
    cols = [c for c in ("rank", "z1", "z2", "ratio", "ratio_error", "module_mm", "a_w_mm", "x1", "x2", "eps_alpha",
                        "objective", "feasible", "reason") if c in sel.table.columns]
    rep.markdown += [f"## Tooth counts for u = {t['ratio']:g} (± {100 * t['ratio_tol']:g} %)"
                     f"{kind_text(t['beta_deg'], t['internal'])}", "", sel.choice, "",
                     md_table(sel.table[cols].head(t["top"])), ""]
    b = sel.best
    rep.summary.append("teeth: " + (f"z1/z2 = {int(b['z1'])}/{int(b['z2'])}, x1 = {b['x1']:.4f}, x2 = {b['x2']:.4f}"
                                    if b is not None else "no feasible tooth counts"))


def _run_planetary(rep: SceneReport, p: dict):
    """A set's best shifts (region and drawing), the checks of given shifts, or tooth counts for a ratio."""
    from ..gears.planetary import PlanetarySet

    checks = dict(p.get("checks") or {})
    spectrum = p.get("spectrum")
    if spectrum:   # the damage checks of both meshes (ISO 6336-6), the sun's bins shared over the planets
        checks.update(spectrum=spectrum["_spectrum"], material=spectrum["material"],
                      face_width_mm=spectrum["face_width_mm"], life_h=spectrum.get("life_h"),
                      sn_curve=spectrum["sn_curve"], mean_stress_factor=spectrum["mean_stress_factor"],
                      **{k: spectrum[k] for k in ("planet_material", "ring_material") if k in spectrum})
    kw = dict(rack=p["_rack"], beta_deg=p["beta_deg"])
    if "ratio" in p:
        from ..shifts.planetary_teeth import DEFAULT_OBJECTIVE, select_planetary_teeth

        sel = select_planetary_teeth(p["ratio"], p["n_planets"], p["module"], ratio_tol=p["ratio_tol"],
                                     z_sun_range=tuple(p["z_sun_range"]), nonstandard_max=p["nonstandard_max"],
                                     arrangement=p["arrangement"], objective=p.get("objective") or DEFAULT_OBJECTIVE,
                                     checks=checks, method=p["method"], client=p.get("_client"), **kw)
        rep.results["planetary"] = sel
        rep.tables["planetary_teeth"] = sel.table
        rep.markdown += [f"## Planetary tooth counts for ratio {p['ratio']:g} (± {100 * p['ratio_tol']:g} %), "
                         f"{p['n_planets']} planets", "", sel.message, "", md_table(sel.table.head(p["top"])), ""]
        rep.summary.append("planetary: " + sel.message)
        return
    sizes = (p["module"], p["z_sun"], p["z_planet"], p["z_ring"], p["n_planets"])
    if "x_sun" in p:
        s = (PlanetarySet(*sizes, p["x_sun"], p["x_planet"], p["x_ring"], arrangement=p["arrangement"], **kw)
             if "x_ring" in p else PlanetarySet.coaxial(*sizes, p["x_sun"], p["x_planet"], arrangement=p["arrangement"], **kw))
        table = s.checks(checks)
        rep.results["planetary"] = s
        rep.tables["planetary_checks"] = table
        failed = table.loc[~table["ok"], "check"].tolist()
        head = (f"x = {s.x_sun:.4f}/{s.x_planet:.4f}/{s.x_ring:.4f}, a_w {s.a_w:.6g} mm: "
                + ("every check holds" if not failed else f"fails {', '.join(failed)}"))
    else:
        from ..shifts.planetary import optimize_planetary_shifts, planetary_region

        r = optimize_planetary_shifts(*sizes[1:], sizes[0], a_w=p.get("a_w"), objective=p.get("objective"),
                                      checks=checks, method=p["method"], arrangement=p["arrangement"], **kw)
        rep.results["planetary"] = r
        table = r.to_frame()
        rep.tables["planetary_optimum"] = table
        reg = planetary_region(*sizes[1:], sizes[0], checks=checks, **kw)
        pyplot()
        rep.figures["planetary_region"] = reg.plot(optimum=(r.x_sun, r.x_planet) if r.success else None,
                                                   x_sum=(r.x_sun + r.x_planet) if "a_w" in p else None).figure
        head = (f"{r.objective}: x = {r.x_sun:.4f}/{r.x_planet:.4f}/{r.x_ring:.4f}, a_w {r.a_w:.6g} mm"
                if r.success else r.message)
        s = PlanetarySet(*sizes, r.x_sun, r.x_planet, r.x_ring, arrangement=p["arrangement"], **kw) if r.success else None
    rep.markdown += [f"## Planetary set z_s/z_p/z_r = {p['z_sun']}/{p['z_planet']}/{p['z_ring']}, "
                     f"{p['n_planets']} planets, m = {p['module']:g} mm", "", head, "", md_table(table), ""]
    if "planetary_region" in rep.figures:
        rep.markdown += ["![feasible (x_sun, x_planet) region](planetary_region.png)", ""]
    if spectrum and s is not None:
        _planetary_life(rep, s, spectrum)
    if s is not None and p["drawing"]:
        from ..profiles.planetary import plot_planetary

        pyplot()
        rep.figures["planetary_set"] = plot_planetary(s).figure
        rep.markdown += ["![the set along its axis](planetary_set.png)", ""]
    rep.summary.append("planetary: " + head)


def _planetary_life(rep: SceneReport, s, spectrum: dict):
    """The set's life under [planetary.spectrum] (ISO 6336-6; the planet over both its meshes): a table of each
    gear's damage sums and lives."""
    import pandas as pd

    from ..gears.strength.planetary_meshes import planetary_life

    r = planetary_life(s, spectrum["_spectrum"], spectrum["material"], face_width_mm=spectrum["face_width_mm"],
                       mean_stress_factor=spectrum["mean_stress_factor"], life_h=spectrum.get("life_h"),
                       sn_curve=spectrum["sn_curve"], planet_material=spectrum.get("planet_material"),
                       ring_material=spectrum.get("ring_material"))
    table = pd.DataFrame([{"gear": gear, "mode": "pitting" if mode == "H" else "root", "D": r[f"D_{mode}_{gear}"],
                           "life_h": r[f"life_h_{mode}_{gear}"]}
                          for gear in ("sun", "planet", "ring") for mode in ("H", "F")])
    rep.tables["planetary_life"] = table
    rep.markdown += [f"### Service life under the sun's spectrum (ISO 6336-6), required {r['required_life_h']:.6g} h",
                     "", "The planet's pitting summed per flank over both meshes, its root as alternating bending "
                     f"(Y_M = {spectrum['mean_stress_factor']:g}).", "", md_table(table), ""]


def chain_kwargs(c: dict) -> dict:
    kw = {k: c[k] for k in ("torque_nm", "power_kw", "n1_rpm", "ratio", "catalog", "k_e", "allowable_pressure_mpa",
                            "allowable_safety_factor", "z1", "center_distance_mm", "objective", "method",
                            "sag_factor") if k in c}
    kw["strands"] = tuple(c["strands"])
    if c.get("conditions"):
        kw["conditions"] = dict(c["conditions"])
    return kw


def _run_chain(rep: SceneReport, c: dict):
    from ..drives.chain import design

    res = design(**chain_kwargs(c))
    rep.results["chain"] = res
    rep.tables["chain_candidates"] = res.candidates
    rep.tables["chain_blocking"] = res.blocking
    load = f"T1 = {c['torque_nm']:g} N·m" if "torque_nm" in c else f"P = {c['power_kw']:g} kW"
    md = rep.markdown
    md += [f"## Roller chain: {load}, n1 = {c['n1_rpm']:g} rpm, u = {c['ratio']:g} ({res.catalog}, {res.method})", "",
           f"{res.message}. K_e = {res.k_e:.4g}.", ""]
    if res.pitch_estimate_mm:
        md += ["Classic pitch estimate: " + ", ".join(f"{k} strand(s) t >= {v:.2f} mm"
                                                      for k, v in res.pitch_estimate_mm.items()) + ".", ""]
    show = [col for col in ("designation", "pitch_mm", "strands", "z1", "z2", "links", "center_distance_mm",
                            "speed_m_s", "force_n", "pressure_mpa", "allowable_pressure_mpa", "safety_factor",
                            "sprocket1_pitch_diameter_mm", "sprocket2_tip_diameter_mm", "mass_kg_m", "margin_pressure", "margin_safety", "min_margin", "feasible")
            if col in res.candidates.columns]
    md += ["Best candidates:", "", md_table(res.candidates[show].head(c["top"])), ""]
    for note in res.notes:
        md += [f"- {note}"]
    if res.notes:
        md += [""]
    b = res.best
    rep.summary.append("chain: " + (f"{b['designation']} x{int(b['strands'])}, z1/z2 = {int(b['z1'])}/{int(b['z2'])}, "
                                    f"{int(b['links'])} links, a = {b['center_distance_mm']:.2f} mm, "
                                    f"limiting {b['limiting_check']} (margin {b['min_margin']:+.3f})"
                                    if b is not None else f"no chain passes: {res.message}"))


def _run_keys(rep: SceneReport, keys: list):
    from ..drives.key import select

    rows, results = [], []
    for i, k in enumerate(keys):
        sel = select(k["d_mm"], k["torque_nm"], k["hub_length_mm"], k["allowable_crush_mpa"], k["allowable_shear_mpa"],
                     k["end"], k["max_keys"])
        results.append(sel)
        row = {"name": k.get("name", f"key {i + 1}")}
        row.update(sel.to_dict())
        rows.append(row)
        rep.summary.append(f"key '{row['name']}': {sel.message}"
                           + (f", crush {sel.crush_mpa:.1f}/{sel.allowable_crush_mpa:g} MPa" if sel.feasible else ""))
    rep.results["key"] = results
    import pandas as pd

    frame = pd.DataFrame(rows)
    rep.tables["keys"] = frame
    show = ["name", "d_mm", "torque_nm", "hub_length_mm", "b_mm", "h_mm", "t1_mm", "length_mm", "working_length_mm",
            "n_keys", "crush_mpa", "allowable_crush_mpa", "shear_mpa", "allowable_shear_mpa", "margin_crush",
            "margin_shear", "feasible"]
    rep.markdown += ["## Parallel keys", "", *[f"- {r['name']}: {r['message']}" for r in rows], "",
                     md_table(frame[show]), ""]


def run_study(rep: SceneReport, st: dict, sections: dict):
    plt = pyplot()
    from ..sensitivity import sweeps

    target = st["target"]
    base = base_from_scene(target, sections[target])
    frame = sweeps.sweep(st["parameter"], list(st["values"]), st.get("parameter2"),
                         None if "values2" not in st else list(st["values2"]), target=target,
                         client=st.get("_client"), **base)
    rep.tables["study_sweep"] = frame
    rep.results["study"] = {"sweep": frame}
    md = rep.markdown
    what = st["parameter"] + (f" × {st['parameter2']}" if "parameter2" in st else "")
    md += [f"## Study: {target} sweep over {what}", "", md_table(frame.drop(columns=[c for c in frame.columns
                                                                                   if c.startswith("sens_")])), ""]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    sweeps.plot_margins(frame, st["parameter"], ax=ax, by=st.get("parameter2"))
    rep.figures["study_margins"] = fig
    md += ["![margins along the sweep](study_margins.png)", ""]
    if target == "gear" and st["parameter"] in sweeps.LIMIT_PARAMETERS and "parameter2" not in st:
        fig, ax = plt.subplots(figsize=(7, 6))
        sweeps.plot_region_motion(st["parameter"], list(st["values"]), ax=ax, **base)
        rep.figures["study_region_motion"] = fig
        md += ["![the region moving with the limit](study_region_motion.png)", ""]
    if target == "gear" and st["tornado"]:
        tor = sweeps.local_sensitivities(step=st["step"], **base)
        rep.tables["study_sensitivities"] = tor
        rep.results["study"]["sensitivities"] = tor
        fig, ax = plt.subplots(figsize=(7, 4.5))
        sweeps.plot_tornado(tor, ax=ax)
        rep.figures["study_tornado"] = fig
        md += ["### Local sensitivities of the optimum", "",
               f"Each input moved by ±{100 * st['step']:g} % (limits: the convex method's duals give the slope "
               "d fun/d limit; the bars re-solve):", "", md_table(tor), "",
               "![tornado chart](study_tornado.png)", ""]
    rep.summary.append(f"study: {len(frame)} sweep points over {what}")


def base_from_scene(target: str, section: dict) -> dict:
    """The keyword arguments of :func:`geardesign.sensitivity.sweeps.sweep` for a validated section."""
    if target == "gear":
        out = {k: section[k] for k in ("z1", "z2", "objective", "method", "tip_shortening") if k in section}
        out.update(scene_kind(section))
        out.update(m=section["module"], checks=dict(section.get("checks") or {}) or None,
                   rack=section.get("_rack"), bounds=tuple(section["bounds"]), a_w=section.get("a_w"))
        return out
    return chain_kwargs(section)


def _run_drive(rep: SceneReport, d: dict):
    from .drive import run_drive
    run_drive(rep, d)


# the sections in the order they run; [study] runs last, over the others
RUNNERS = (("engine", _run_engine), ("gear", _run_gear), ("teeth", _run_teeth), ("planetary", _run_planetary), ("chain", _run_chain),
           ("key", _run_keys), ("drive", _run_drive))
