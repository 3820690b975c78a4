"""The written contract of the geometry dict: every key the package reads from a geometry exists in
GEOMETRY_FIELDS or INTERNAL_FIELDS, and every key a geometry carries is in one of them."""
import pathlib
import re

import pytest

import geardesign
from geardesign.gears.fields import GEOMETRY_FIELDS, INTERNAL_FIELDS
from geardesign.gears.geometry import mesh_geometry, mesh_geometry_float
from geardesign.gears.mesh import Mesh

PACKAGE = pathlib.Path(geardesign.__file__).parent
# geo["_m"], geo[f"_ra{gear}"], geo.get("_sgn"), geo.setdefault("_cutting_meshes", ...)
_READ = re.compile(r"""\b(?:geo|g|geometry)(?:\[f?|\.get\(f?|\.setdefault\(f?)"(_[a-z0-9_]+)(\{\w+\})?"[\],]""")
# dicts of other kinds that use a leading underscore for their own keys (a scene's resolved rack)
_NOT_GEOMETRY = {"_rack", "_r", "_n"}


def _keys_read():
    out = {}
    for path in PACKAGE.rglob("*.py"):
        for key, fmt in _READ.findall(path.read_text(encoding="utf-8")):
            names = [key + "1", key + "2"] if fmt else [key]
            for name in names:
                out.setdefault(name, str(path.relative_to(PACKAGE)))
    return out


def test_every_internal_key_read_is_in_the_table():
    read = _keys_read()
    assert len(read) > 20                                     # the scan sees the package
    missing = {k: where for k, where in read.items() if k not in INTERNAL_FIELDS and k not in _NOT_GEOMETRY}
    assert not missing


@pytest.mark.parametrize("kind", [dict(), dict(internal=True), dict(beta_deg=15.0, face_width_mm=20.0)])
def test_every_key_a_geometry_carries_is_in_a_table(kind):
    mesh = Mesh(20, 61, **kind)
    for geo in (mesh_geometry(mesh, 2.0, 0.3, 0.2), mesh_geometry_float(mesh, 2.0, 0.3, 0.2)):
        extra = set(geo) - set(GEOMETRY_FIELDS) - set(INTERNAL_FIELDS)
        assert not extra
        assert set(GEOMETRY_FIELDS) <= set(geo)


def test_internal_fields_say_what_they_hold():
    assert all(isinstance(v, str) and len(v) >= 4 for v in INTERNAL_FIELDS.values())
