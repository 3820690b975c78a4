"""Layers import only downward at load time (geardesign/__init__.py lists them): a module's
top-level imports of the package reach its own layer or those below. Imports inside functions are
the documented way up (GearPair.report draws on the scene layer only when called)."""
import ast
from pathlib import Path

PKG = Path(__file__).resolve().parents[2] / "geardesign"
LAYERS = [
    {"errors", "validate", "results", "files", "inline", "parallel", "progress", "catalog_files"},
    {"catalogs"},
    {"gears"},
    {"shifts", "profiles"},
    {"drives"},
    {"sensitivity"},
    {"scene"},
    {"cli", "__main__"},
]


def _layer(top: str) -> int:
    return next(i for i, names in enumerate(LAYERS) if top in names)


def _top(module: Path) -> str:
    return module.relative_to(PKG).parts[0].removesuffix(".py")


def _imported(module: Path, node) -> list[str]:
    """The geardesign top-level names a module-level import statement reaches."""
    parts = module.relative_to(PKG).with_suffix("").parts
    if isinstance(node, ast.ImportFrom):
        if node.level == 0:
            mod = node.module or ""
            return [mod.split(".")[1]] if mod.startswith("geardesign.") else []
        base = list(parts[: len(parts) - node.level])
        target = base + (node.module.split(".") if node.module else [])
        if target:
            return [target[0]]
        return [a.name for a in node.names]          # from .. import x (x a top-level module)
    return [a.name.split(".")[1] for a in node.names if a.name.startswith("geardesign.")]


def test_module_level_imports_go_down():
    bad = []
    for module in sorted(PKG.rglob("*.py")):
        if module.name == "__init__.py" and module.parent == PKG:
            continue      # the package's lazy name table
        own = _layer(_top(module))
        for node in ast.parse(module.read_text(encoding="utf-8")).body:
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                for top in _imported(module, node):
                    if top in {n for names in LAYERS for n in names} and _layer(top) > own:
                        bad.append(f"{module.relative_to(PKG)} imports {top}")
    assert not bad, bad


def test_an_upward_import_is_seen():
    pair = PKG / "gears" / "pair.py"
    node = ast.parse("from ..scene.html import pair_report").body[0]
    assert _imported(pair, node) == ["scene"] and _layer("scene") > _layer(_top(pair))
    assert _imported(pair, ast.parse("from . import checks").body[0]) == ["gears"]
    assert _imported(pair, ast.parse("import geardesign.cli.main").body[0]) == ["cli"]
