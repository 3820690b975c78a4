"""Layers import only downward (the order of /work/shared/DESIGN.md and geardesign/__init__.py): every import
statement of a module, at its top or inside a function (loaded on first use), reaches its own layer or those below.
Issue 36 §4: GearPair.report imported scene/html.py inside the method and closed a 12-file import circle; a lower
object now reaches an upper writer through the registry of geardesign.writers, filled by the package's name table."""
import ast
from pathlib import Path

PKG = Path(__file__).resolve().parents[2] / "geardesign"
LAYERS = [
    {"errors", "validate", "results", "files", "inline", "parallel", "progress", "catalog_files", "renamed", "writers"},
    {"catalogs", "mechanism"},     # DESIGN.md: catalogs and the slider-crank depend on nothing above validate
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


def _upward(module: Path, nodes) -> list[str]:
    own = _layer(_top(module))
    known = {n for names in LAYERS for n in names}
    return [f"{module.relative_to(PKG)}:{node.lineno} imports {top}" for node in nodes
            if isinstance(node, (ast.Import, ast.ImportFrom))
            for top in _imported(module, node) if top in known and _layer(top) > own]


def _modules():
    for module in sorted(PKG.rglob("*.py")):
        if module.name == "__init__.py" and module.parent == PKG:
            continue      # the package's lazy name table: above every layer
        yield module, ast.parse(module.read_text(encoding="utf-8"))


def test_module_level_imports_go_down():
    bad = [b for module, tree in _modules() for b in _upward(module, tree.body)]
    assert not bad, bad


def test_no_import_goes_up_even_inside_a_function():
    # issue 36 §4: the deferred imports count too (they close the same circle when called)
    bad = [b for module, tree in _modules() for b in _upward(module, ast.walk(tree))]
    assert not bad, bad


def test_every_module_has_a_layer():
    assert {_top(m) for m, _ in _modules()} <= {n for names in LAYERS for n in names}


def test_a_deferred_upward_import_is_seen():
    # the test above fails on the import GearPair.report had inside the method
    pair = PKG / "gears" / "pair.py"
    tree = ast.parse("class GearPair:\n    def report(self, path):\n        from ..scene.html import pair_report\n")
    assert _upward(pair, ast.walk(tree)) == ["gears/pair.py:3 imports scene"]
    assert _upward(pair, tree.body) == []


def test_an_upward_import_is_seen():
    pair = PKG / "gears" / "pair.py"
    node = ast.parse("from ..scene.html import pair_report").body[0]
    assert _imported(pair, node) == ["scene"] and _layer("scene") > _layer(_top(pair))
    assert _imported(pair, ast.parse("from . import checks").body[0]) == ["gears"]
    assert _imported(pair, ast.parse("import geardesign.cli.main").body[0]) == ["cli"]


def test_the_pair_report_method_is_deprecated_and_still_writes(tmp_path):
    import subprocess
    import sys

    import pytest

    import geardesign as gd
    pair = gd.GearPair(3, 12, 24, 0.6, 0.36)
    with pytest.warns(FutureWarning, match="geardesign.pair_report"):
        path = pair.report(tmp_path / "p.html")
    assert path.read_text(encoding="utf-8").startswith("<!DOCTYPE html>")
    # building and checking a pair loads no scene module (nor the report's plotting)
    code = ("import sys, geardesign as gd; p = gd.GearPair(3, 12, 24, 0.6, 0.36); p.checks(); "
            "print(sorted(m for m in sys.modules if m.startswith(('geardesign.scene', 'geardesign.profiles'))))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                         env={"PYTHONPATH": str(PKG.parent), "PATH": ""}).stdout
    assert out.strip() == "[]"


def _import_graph() -> dict:
    """module -> the package modules its import statements (anywhere in it) name, e.g. geardesign.gears.pair."""
    mods = {}
    for f in PKG.rglob("*.py"):
        parts = list(f.relative_to(PKG.parent).with_suffix("").parts)
        mods[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = f

    def resolve(name):
        while name and name not in mods:
            name = name.rsplit(".", 1)[0] if "." in name else ""
        return name

    graph = {}
    for m, f in mods.items():
        pkg = m if f.name == "__init__.py" else m.rsplit(".", 1)[0]
        found = set()
        for n in ast.walk(ast.parse(f.read_text(encoding="utf-8"))):
            if isinstance(n, ast.Import):
                names = [a.name for a in n.names]
            elif isinstance(n, ast.ImportFrom):
                base = (".".join(pkg.split(".")[: len(pkg.split(".")) - n.level + 1] + ([n.module] if n.module else []))
                        if n.level else n.module or "")
                names = [base] + [f"{base}.{a.name}" for a in n.names]
            else:
                continue
            found |= {resolve(t) for t in names if t.startswith("geardesign")}
        graph[m] = found - {m, "", "geardesign"}
    return graph


def _cycles(graph: dict) -> list:
    """The import circles: strongly connected components of more than one module (Tarjan)."""
    index, low, stack, on, out = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while not comp or comp[-1] != v:
                comp.append(stack.pop())
                on.discard(comp[-1])
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in list(graph):
        if v not in index:
            visit(v)
    return out


def test_no_import_circle():
    # issue 36 §4: GearPair.report's import of scene/html.py closed a circle of 12 modules (gears, drives, scene)
    assert _cycles(_import_graph()) == []
    # the finder sees such a circle: pair -> scene.html -> pair
    assert _cycles({"a.pair": {"a.html"}, "a.html": {"a.pair", "a.x"}, "a.x": set()}) == [["a.html", "a.pair"]]
