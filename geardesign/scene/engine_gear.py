"""The engine's gear end to end (issue 38 §5): a scene with ``[engine]`` and ``[gear]`` whose ``[gear.spectrum]``
counts the engine's torque curve on the pair; the torque over the cycle, the spectrum, the service life (ISO 6336-6)
at the scene's shifts and at the shifts of the section's objective (``max_life`` by default). What
``geardesign engine scene.toml`` prints when the scene has the gear."""
from __future__ import annotations

from .schema import Where

__all__ = ["EngineGear", "engine_gear"]


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


def engine_gear(scene) -> EngineGear:
    """A loaded scene (:func:`geardesign.scene.load.load_scene`) with ``[engine]`` and ``[gear]`` whose
    ``[gear.spectrum]`` counts the engine's torque: the torque over the cycle, the spectrum on the pair, the shifts
    of the section's objective (``max_life``, the longest life, unless it names another) under its checks and the
    damage checks, and the life at the scene's shifts and at the optimum (ISO 6336-6)."""
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
