"""The engine's gear end to end (issue 38 §5): a scene with ``[engine]`` and ``[gear]`` whose ``[gear.spectrum]``
counts the engine's torque curve on the pair; the torque over the cycle, the spectrum, the service life (ISO 6336-6)
at the scene's shifts and at the shifts of the section's objective (``max_life`` by default). What
``geardesign engine scene.toml`` prints when the scene has the gear."""
from __future__ import annotations

from .schema import Where

__all__ = ["EngineGear", "engine_gear", "engine_gear_report_html", "engine_gear_report"]


class EngineGear:
    """The engine's gear end to end (:func:`engine_gear`): ``torque`` (the
    :class:`~geardesign.mechanism.engine.EngineTorque`), ``spectrum`` (its curve counted on the pair), ``optimum``
    (the :class:`~geardesign.shifts.result.ShiftResult` of the section's objective, ``max_life`` by default),
    ``life`` ({"given": ..., "optimum": ...}: :class:`~geardesign.gears.strength.life_result.LifeResult` at the
    scene's shifts and at the optimum), ``given_failed`` (the checks the scene's shifts fail) and ``failures``
    (what fails, one phrase each; empty: the engine does work and its gear reaches the required life at the
    optimal shifts, the given ones holding every check)."""

    def __init__(self, scene, torque, spectrum, optimum, life: dict, given_failed: list):
        self.scene, self.torque, self.spectrum, self.optimum = scene, torque, spectrum, optimum
        self.life, self.given_failed = life, given_failed

    @property
    def failures(self) -> list:
        out = [] if self.torque.success else ["the engine does no work over the cycle"]
        if not self.optimum.success:
            out.append("no shifts hold every check")
        best = self.life.get("optimum")
        if best is not None and not best.ok:
            mode = best.governing[0]
            out.append(f"at the best shifts the gear's life is {best.life_h:.4g} h < {best.required_life_h:.6g} h "
                       f"({'pitting' if mode[0] == 'H' else 'root'}, gear {mode[1]})")
        if self.given_failed:
            out.append("the given shifts fail " + ", ".join(self.given_failed))
        return out

    def to_dict(self) -> dict:
        from ..results import plain

        o = self.optimum
        return {"ok": not self.failures, "failures": self.failures, "title": self.scene.title,
                "engine": self.torque.to_dict(),
                "spectrum": {"bins": int(self.spectrum.torque_nm.size), "on_gear": self.spectrum.on_gear,
                             "per_tooth": self.spectrum.per_tooth, "reverses": self.spectrum.reverses,
                             "max_torque_nm": float(self.spectrum.torque_nm.max()),
                             "min_torque_nm": float(self.spectrum.torque_nm.min()),
                             "histogram": self.spectrum.histogram().to_dict(orient="records")},
                "optimum": {"objective": o.objective, "x1": o.x1, "x2": o.x2, "fun": o.fun, "success": o.success,
                            "active": list(o.active), "message": o.message},
                "life": {tag: {"x1": x[0], "x2": x[1], "ok": r.ok, "life_h": r.life_h,
                               "required_life_h": r.required_life_h,
                               "damage": plain(r.damage_table().to_dict(orient="records"))}
                         for tag, (x, r) in self._lives().items()},
                "given_failed": list(self.given_failed)}

    def _lives(self) -> dict:
        g = self.scene.sections["gear"]
        at = {"given": (g.get("x1"), g.get("x2")), "optimum": (self.optimum.x1, self.optimum.x2)}
        return {tag: (at[tag], r) for tag, r in self.life.items()}


def engine_gear(scene, points: int | None = None) -> EngineGear:
    """A loaded scene (:func:`geardesign.scene.load.load_scene`) with ``[engine]`` and ``[gear]`` whose
    ``[gear.spectrum]`` counts the engine's torque: the torque over the cycle, the spectrum on the pair, the shifts
    of the section's objective (``max_life``, the longest life, unless it names another) under its checks and the
    damage checks, and the life at the scene's shifts and at the optimum (ISO 6336-6). ``points``: the crank angles
    over the cycle (None: the scene's), the torque and the spectrum counted from them."""
    from ..gears.pair import GearPair
    from ..shifts.optimize import optimize_shifts
    from .load import scene_kind
    from .sections import _checks_dict

    where = Where(scene.path)
    g = scene.sections["gear"]
    if "spectrum" not in g:
        where.fail("gear", "spectrum", "missing; the engine's gear needs [gear.spectrum] (material, life_h, "
                                       "mean_stress_factor) to count the engine's torque on it")
    sp = g["spectrum"]
    if not sp.get("_engine"):
        where.fail("gear.spectrum", "file", "the engine command counts the [engine]'s torque on the gear: drop the "
                                            "file (geardesign run rates a file's spectrum)")
    e = scene.sections["engine"]
    if points is not None and points != e.points:      # the spectrum counted again from the curve at these points
        from .load import _engine_spectrum

        e.points = points
        _engine_spectrum(where, g, e)
    torque = e.engine.analyse(e.points)
    checks = _checks_dict(g.get("checks"), g)
    kind = scene_kind(g)
    pair_kw = dict(**({"rack": g["_rack"]} if g["_rack"] else {}), tip_shortening=g["tip_shortening"], **kind)
    opt = optimize_shifts(g["z1"], g["z2"], objective=g.get("objective") or "max_life", method=g["method"],
                          m=g["module"], a_w=g.get("a_w"), checks=checks, bounds=tuple(g["bounds"]),
                          rack=g["_rack"], tip_shortening=g["tip_shortening"], **kind)
    spectrum = checks["spectrum"]
    at = ([("given", g["x1"], g["x2"])] if "x1" in g else []) + ([("optimum", opt.x1, opt.x2)] if opt.success else [])
    life, given_failed = {}, []
    for tag, x1, x2 in at:
        pair = GearPair(g["module"], g["z1"], g["z2"], x1, x2, **pair_kw)
        life[tag] = pair.life(spectrum, sp["material"], material2=sp.get("material2"),
                              face_width_mm=checks["face_width_mm"], life_h=sp.get("life_h"), sn_curve=sp["sn_curve"],
                              mean_stress_factor=sp.get("mean_stress_factor"), **checks.get("strength", {}))
        if tag == "given":
            table = pair.checks(**checks, housing_a_w=g.get("a_w"))
            given_failed = table.loc[~table["ok"], "check"].tolist()
    return EngineGear(scene, torque, spectrum, opt, life, given_failed)


def engine_gear_report_html(gear: EngineGear) -> str:
    """The engine's gear as one self-contained HTML page: the verdict, the torque over the cycle (summary and
    plot), the spectrum on the gear (histogram and its classes), the life at the scene's shifts and at the optimum
    (damage table and S-N diagrams with the spectrum on the governing tooth flank) and the optimal shifts."""
    import html

    from .html import _frame, _page, _png, _td

    failures = gear.failures
    o = gear.optimum
    verdict = (f'<div class="verdict ok">OK: the best shifts ({html.escape(o.objective)}) give '
               f"{gear.life['optimum'].life_h:.4g} h, the required life holds.</div>" if not failures else
               f'<div class="verdict fail">FAILS: {html.escape("; ".join(failures))}</div>')
    parts = [f"<h1>{html.escape(gear.scene.title)}</h1>", verdict, "<h2>The engine's torque over the cycle</h2>",
             "<ul>" + "".join(f"<li>{html.escape(line)}</li>" for line in gear.torque.summary()) + "</ul>",
             f'<figure><img alt="torque over the cycle" src="{_png(gear.torque.plot().figure)}"></figure>']
    s = gear.spectrum
    parts += ["<h2>Load spectrum on the gear (ISO 6336-6)</h2>",
              f"<p>{html.escape(repr(s))}: the torque counted at the mesh instants of gear {s.on_gear}, per tooth and "
              "flank; a negative class loads the coast flank.</p>",
              f'<figure><img alt="spectrum histogram" src="{_png(s.plot().figure)}"></figure>',
              _frame(s.histogram(), {"torque_nm": "{:.5g}", "time_h": "{:.4g}", "share": "{:.4f}"})]
    for tag, (x, r) in gear._lives().items():
        what = "the scene's shifts" if tag == "given" else f"the optimal shifts ({o.objective})"
        fails = (f" — they fail {html.escape(', '.join(gear.given_failed))}" if tag == "given" and gear.given_failed
                 else "")
        parts += [f"<h2>Service life at {what}: x<sub>1</sub> = {x[0]:.4f}, x<sub>2</sub> = {x[1]:.4f}</h2>",
                  f"<p>{r.life_h:.4g} h of {r.required_life_h:.6g} h required ({'holds' if r.ok else 'FAILS'}); "
                  f"S-N curve {html.escape(r.sn_curve)}; Y<sub>M</sub> = "
                  f"{'/'.join(f'{v:g}' for v in r.mean_stress_factor)}{fails}.</p>",
                  _frame(r.damage_table(), {"D": "{:.4g}", "life_h": "{:.4g}", "S": "{:.4g}"}),
                  f'<figure><img alt="S-N diagrams" src="{_png(r.plot())}"></figure>']
    g = gear.scene.sections["gear"]
    rows = [("objective", o.objective), ("x1, x2", f"{o.x1:.6f}, {o.x2:.6f}"), ("fun = ln(L/L_req)" if
            o.objective == "max_life" else "fun", f"{o.fun:.6g}"), ("a_w, mm", f"{o.a_w:.4f}"),
            ("eps_alpha", f"{o.eps_alpha:.4f}"), ("active checks", ", ".join(o.active) or "-"),
            ("message", o.message)]
    parts += [f"<h2>Optimal shifts of {g['z1']}/{g['z2']}, m = {g['module']:g} mm</h2>",
              "<table><tbody>" + "".join(f"<tr>{_td(html.escape(a))}{_td(html.escape(str(b)))}</tr>" for a, b in rows)
              + "</tbody></table>"]
    return _page(gear.scene.title, parts)


def engine_gear_report(gear: EngineGear, path, overwrite: bool = False):
    """Write :func:`engine_gear_report_html` to ``path`` (.html), whole or not at all; an existing file is replaced
    only with ``overwrite``. Returns the path."""
    from pathlib import Path

    from ..files import check_output_path, write_file_atomic

    p = check_output_path(path, overwrite=overwrite, suffixes=(".html", ".htm"), what="--html")
    page = engine_gear_report_html(gear)
    return write_file_atomic(p, lambda tmp: Path(tmp).write_text(page, encoding="utf-8"))
