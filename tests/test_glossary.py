"""One name per quantity (docs/glossary.md): every public signature uses the glossary's names, and each
renamed keyword still works for one release with a DeprecationWarning that names the new one."""
import inspect
import re
import warnings
from pathlib import Path

import numpy as np
import pytest

import geardesign as gd
from geardesign.errors import GearDesignError

GLOSSARY = Path(__file__).resolve().parents[1] / "docs" / "glossary.md"

# The deprecated aliases, explicitly: (old, new) -> where. Each is a row of the glossary's last table and is
# tested below to warn and to give the new name's result.
DEPRECATED = {("speed_rpm", "n_rpm"), ("m_n", "m"), ("m_mm", "m"), ("a_w_mm", "a_w"), ("color", "colour"),
              ("fr_n", "F_r_n"), ("fa_n", "F_a_n")}
# An old keyword that stays as a result's field (a key of its to_dict() and of a command's JSON; the glossary's
# "What stays" says why): where it may still appear.
FIELDS_THAT_STAY = {"m_n": {"FlankTolerances", "ToothMeasurements"}}


def _sections() -> dict:
    text = GLOSSARY.read_text(encoding="utf-8")
    parts = re.split(r"^## (.+)$", text, flags=re.M)
    return {parts[i].strip(): parts[i + 1] for i in range(1, len(parts), 2)}


def glossary_names() -> set:
    """The names in code of the glossary: the second column of its quantity tables and the list of
    arguments that are not quantities."""
    names = set()
    for title, body in _sections().items():
        if title == "Deprecated names":
            continue
        if title == "Arguments that are not quantities":
            names |= set(re.findall(r"`([A-Za-z_][A-Za-z0-9_]*)`", body))
            continue
        for line in body.splitlines():
            cells = line.split("|")
            if len(cells) > 3 and not set(cells[2].strip()) <= set("-"):
                names |= set(re.findall(r"`([A-Za-z_][A-Za-z0-9_]*)`", cells[2]))
    return names


def deprecated_rows() -> set:
    body = _sections()["Deprecated names"]
    return {tuple(re.findall(r"`([A-Za-z_][A-Za-z0-9_]*)`", line)[:2]) for line in body.splitlines()
            if line.startswith("| `")}


def public_parameters() -> dict:
    """parameter name -> where it appears, over the callables of ``geardesign.__all__`` and the public
    methods of its classes (dataclass fields are their constructors' parameters)."""
    seen = {}
    for name in gd.__all__:
        obj = getattr(gd, name)
        if inspect.ismodule(obj) or not callable(obj):
            continue
        targets = [(name, obj)]
        if inspect.isclass(obj):
            targets += [(f"{name}.{k}", v) for k, v in vars(obj).items()
                        if not k.startswith("_") and callable(getattr(obj, k, None))
                        and not inspect.isclass(v)]
        for where, target in targets:
            try:
                sig = inspect.signature(target)
            except (TypeError, ValueError):   # builtins without a signature
                continue
            for p in sig.parameters.values():
                if p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD) or p.name in ("self", "cls"):
                    continue
                seen.setdefault(p.name, []).append(where)
    return seen


def test_public_signatures_use_only_glossary_names():
    names = glossary_names()
    missing = {p: where[:3] for p, where in public_parameters().items() if p not in names and not p.startswith("_")}
    assert not missing, f"parameters not in docs/glossary.md: {missing}"


def test_no_deprecated_name_is_left_in_a_public_signature():
    old = {o for o, _ in DEPRECATED}
    left = {p: where for p, where in public_parameters().items()
            if p in old and not set(where) <= FIELDS_THAT_STAY.get(p, set())}
    assert not left


def test_the_glossarys_deprecated_table_is_the_tests_allow_list():
    assert deprecated_rows() == DEPRECATED
    # each new name is a glossary name
    assert {new for _, new in DEPRECATED} <= glossary_names() | {"colour"}


def test_the_check_can_fail():
    # a parameter the glossary does not know is reported (the test above is not vacuous)
    assert "speed_rpm" not in glossary_names() and "n_rpm" in glossary_names() and "z1" in glossary_names()
    assert len(public_parameters()) > 200


def _deprecated(call, new):
    with pytest.warns(DeprecationWarning, match=rf"\b{new}\b"):
        return call()


def test_renamed_keywords_still_work_for_one_release():
    stage = gd.GearStage(m=3, z1=20, z2=40, material="42CrMo4")
    assert _deprecated(lambda: stage.load(100.0, speed_rpm=1450.0), "n_rpm") == stage.load(100.0, n_rpm=1450.0)
    assert _deprecated(lambda: gd.motor.rated_torque_nm(4.0, speed_rpm=1410), "n_rpm") == \
        gd.motor.rated_torque_nm(4.0, n_rpm=1410)
    old = _deprecated(lambda: gd.motor.select(3.5, speed_rpm=1450), "n_rpm")
    assert old.motor["designation"] == gd.motor.select(3.5, n_rpm=1450).motor["designation"] == "AIR100L4"
    assert _deprecated(lambda: gd.flank_tolerances(m_n=3, z=40, accuracy_class=6), "m").f_pT == \
        gd.flank_tolerances(m=3, z=40, accuracy_class=6).f_pT == 9.0    # ISO 1328-1:2013, the module's doctest
    assert _deprecated(lambda: gd.ShaperCutter().teeth(m_mm=4.0, z2=90), "m") == gd.ShaperCutter().teeth(4.0, 90) == 25
    assert _deprecated(lambda: gd.gost1643_jn_min("C", a_w_mm=100), "a_w") == gd.gost1643_jn_min("C", a_w=100) == 0.087


def test_old_and_new_keyword_together_are_refused_by_name():
    with pytest.raises(GearDesignError, match="n_rpm.*speed_rpm"):
        gd.motor.rated_torque_nm(4.0, n_rpm=1410, speed_rpm=1410)


def test_a_stage_kind_with_the_old_color_attribute_draws_in_it_with_a_warning():
    from geardesign.drives.stage_kinds.base import StageKind

    with pytest.warns(DeprecationWarning, match="colour"):
        class Old(StageKind):
            color = "#123456"
    assert Old().colour == "#123456"
    with warnings.catch_warnings():
        warnings.simplefilter("error")

        class New(StageKind):
            colour = "#654321"
    assert New().colour == "#654321"
    with pytest.warns(DeprecationWarning, match="colour"):
        assert New().color == "#654321"     # the old name read on a new kind


def test_a_scenes_old_motor_speed_key_loads_with_a_warning(tmp_path):
    body = ('[drive]\ntotal_ratio = 10\n[drive.motor]\npower_kw = 3.5\n{key} = 1450\n'
            '[[drive.stage]]\nkind = "given"\nratio = 10\nefficiency = 0.95\n')
    new, old = tmp_path / "new.toml", tmp_path / "old.toml"
    new.write_text(body.format(key="n_rpm"), encoding="utf-8")
    old.write_text(body.format(key="speed_rpm"), encoding="utf-8")
    with pytest.warns(DeprecationWarning, match="n_rpm"):
        scene_old = gd.load_scene(old)
    assert scene_old.sections == gd.load_scene(new).sections
    assert scene_old.sections["drive"]["motor"]["n_rpm"] == 1450.0


def test_a_mesh_replaces_the_loose_keywords():
    mesh = gd.Mesh(17, 26, beta_deg=12.0, internal=False, face_width_mm=40.0)
    loose = dict(beta_deg=12.0, face_width_mm=40.0)
    assert gd.pair_geometry(8, x1=0.3, x2=0.2, mesh=mesh).a_w == gd.pair_geometry(8, 17, 26, 0.3, 0.2, **loose).a_w
    assert gd.optimize_shifts(mesh=mesh, m=8).x1 == gd.optimize_shifts(17, 26, m=8, **loose).x1
    assert gd.feasible_region(mesh=mesh).area == gd.feasible_region(17, 26, **loose).area
    assert gd.GearPair.from_mesh(8, mesh, 0.3, 0.2) == gd.GearPair(8, 17, 26, 0.3, 0.2, **loose)
    # the engine pair: a_w 181.6016 mm (README, seed 000's 17/26, m = 8, x = 0.898/0.517)
    assert round(gd.pair_geometry(8, x1=0.898, x2=0.517, mesh=gd.Mesh(17, 26)).a_w, 4) == 181.6016


def test_pair_strength_takes_a_mesh_too():
    # issue 36 §4: pair_strength restated the mesh keywords without taking a Mesh; the mesh's face width is the
    # pair's, and its results are the loose call's bit for bit (spur and helical, one design and arrays)
    load = gd.Load(torque_nm=200, n_rpm=1000)
    for beta in (0.0, 12.0):
        mesh = gd.Mesh(20, 60, beta_deg=beta, face_width_mm=30.0)
        for m, x1 in ((3.0, 0.3), (np.array([2.5, 3.0]), np.array([0.2, 0.4]))):
            loose = gd.pair_strength(m, 20, 60, x1, 0.1, load=load, material1="42CrMo4", face_width_mm=30.0,
                                     beta_deg=beta)
            meshed = gd.pair_strength(m, x1=x1, x2=0.1, load=load, material1="42CrMo4", mesh=mesh)
            for k in ("S_H1", "S_H2", "S_F1", "S_F2", "K_Hbeta", "eps_beta" if beta else "eps_alpha"):
                assert np.array_equal(np.asarray(meshed[k]), np.asarray(loose[k])), k


@pytest.mark.parametrize("kw, words", [
    (dict(mesh=gd.Mesh(20, 60)), "face_width_mm .* is needed"),
    (dict(z1=20, z2=60), "face_width_mm .* is needed"),
    (dict(mesh=gd.Mesh(20, 60, face_width_mm=30.0), face_width_mm=30.0), "face_width_mm, not both"),
    (dict(mesh=gd.Mesh(20, 60, face_width_mm=30.0), beta_deg=10.0), "beta_deg, not both"),
    (dict(mesh=(20, 60)), "mesh must be a geardesign.Mesh"),
    (dict(face_width_mm=30.0), "z1 and z2"),
])
def test_pair_strength_mesh_refusals_name_the_input(kw, words):
    with pytest.raises(GearDesignError, match=words):
        gd.pair_strength(3.0, x1=0.3, x2=0.1, load=gd.Load(torque_nm=200, n_rpm=1000), material1="42CrMo4", **kw)


@pytest.mark.parametrize("call, words", [
    (lambda m: gd.optimize_shifts(17, mesh=m), "z1"),
    (lambda m: gd.feasible_region(mesh=m, internal=True), "internal"),
    (lambda m: gd.pair_geometry(8, x1=0.1, x2=0.1, mesh=m, beta_deg=10.0), "beta_deg"),
    (lambda m: gd.optimize_shifts(mesh=(17, 26)), "mesh must be a geardesign.Mesh"),
    (lambda m: gd.optimize_shifts(), "z1 and z2"),
])
def test_a_mesh_and_loose_keywords_together_are_refused_by_name(call, words):
    with pytest.raises(GearDesignError, match=words):
        call(gd.Mesh(17, 26))
