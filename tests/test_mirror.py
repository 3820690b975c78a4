"""The tests mirror the package: geardesign/a/b.py is tested in tests/a/test_b.py, and a package's
``__init__.py`` (geardesign/a/b/__init__.py) in tests/a/test_b.py. A module without its file is a failure,
except the two explicit lists below."""
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "geardesign"

# Pure re-exports: these files only import names from their package's modules (and list them in __all__, or
# load them on first use); the modules they name have their own test files.
PURE_REEXPORTS = {
    "geardesign/__main__.py",               # `python -m geardesign` calls cli.main (tests/test_cli.py)
    "geardesign/catalogs/__init__.py",      # catalogs.tables' names
    "geardesign/drives/__init__.py",        # a docstring only
    "geardesign/drives/chain/__init__.py",  # chain.inputs, .design and .formulas names
    "geardesign/gears/__init__.py",         # a docstring only
    "geardesign/mechanism/__init__.py",     # a docstring only
    "geardesign/gears/strength/__init__.py",  # the strength modules' names, loaded on first use (PEP 562)
    "geardesign/profiles/__init__.py",      # a docstring only
    "geardesign/scene/__init__.py",         # scene.load, .report, .schema, .sections names
    "geardesign/sensitivity/__init__.py",   # a docstring only
    "geardesign/shifts/__init__.py",        # a docstring only
}

# Modules with code whose tests still live in files named for what they test across modules, not yet in a
# mirror file of their own: each entry is a gap to close (add the file, then remove the entry; the test
# below fails when an entry's file exists, so this list only shrinks).
NOT_YET_MIRRORED: dict = {}   # empty since cli/__init__.py's tests moved to tests/test_cli.py (issue 36 §4)


def mirror(module: Path) -> Path:
    """The test file of a module of the package."""
    rel = module.relative_to(PACKAGE)
    if rel.name == "__init__.py":
        rel = rel.parent.with_suffix(".py")
    return ROOT / "tests" / rel.parent / f"test_{rel.name}"


def modules() -> list:
    return sorted(p for p in PACKAGE.rglob("*.py") if p != PACKAGE / "__init__.py" and "__pycache__" not in p.parts)


def _name(p: Path) -> str:
    return p.relative_to(ROOT).as_posix()


def test_every_module_has_its_test_file():
    missing = [f"{_name(m)} -> {_name(mirror(m))}" for m in modules()
               if not mirror(m).exists() and _name(m) not in PURE_REEXPORTS and _name(m) not in NOT_YET_MIRRORED]
    assert not missing, "modules without their mirror test file:\n" + "\n".join(missing)


def test_the_lists_hold_only_modules_without_a_file():
    for name in [*PURE_REEXPORTS, *NOT_YET_MIRRORED]:
        module = ROOT / name
        assert module.exists(), f"{name} is listed but does not exist"
        assert not mirror(module).exists(), f"{name} has {_name(mirror(module))} now: take it off the list"


def test_pure_reexports_define_nothing():
    # a listed file that grows a function or a class is no longer a re-export: it needs its tests
    for name in PURE_REEXPORTS:
        text = (ROOT / name).read_text(encoding="utf-8")
        defined = [line for line in text.splitlines() if line.startswith(("def ", "class "))
                   and not line.startswith(("def __getattr__", "def __dir__"))]
        assert not defined, f"{name} defines {defined}"


def test_the_mapping():
    assert mirror(PACKAGE / "gears" / "checks" / "ring.py") == ROOT / "tests" / "gears" / "checks" / "test_ring.py"
    assert mirror(PACKAGE / "gears" / "checks" / "__init__.py") == ROOT / "tests" / "gears" / "test_checks.py"
    assert mirror(PACKAGE / "inline.py") == ROOT / "tests" / "test_inline.py"
