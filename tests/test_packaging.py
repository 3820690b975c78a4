"""Every subpackage ships: CI installs the project non-editable, from pyproject's explicit package list."""
import pathlib
import tomllib

ROOT = pathlib.Path(__file__).resolve().parents[1]


def test_every_subpackage_is_in_pyprojects_package_list():
    listed = set(tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["packages"])
    found = {".".join(p.parent.relative_to(ROOT).parts) for p in (ROOT / "geardesign").rglob("__init__.py")}
    assert found - listed == set()
