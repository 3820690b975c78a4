"""Helical and internal pairs through everything above the optimiser (issue 12): the tooth-count
search, the atlas, sensitivities, the CLI and scenes, with no special cases in the callers.

Reference values are hand formulas (a = m_n z_Σ/(2 cos β), z_Σ = z2 − z1 for a ring; ISO 21771
eq. (62)–(63)) and the independent 50-digit reference of tests/reference_mp.py."""
import json
import math
import subprocess
import sys

import pytest

import geardesign as gd
from geardesign.sensitivity import sweeps
from geardesign.cli import main
from tests.reference_mp import pair_reference
from tests.scene_files import write


def _reference(m, z1, z2, x1, x2, **kind) -> dict:
    fields, why = pair_reference(m, z1, z2, x1, x2, **kind)
    assert fields is not None, why
    return fields


def _reference_a_w(m, z1, z2, x1, x2, **kind):
    return float(_reference(m, z1, z2, x1, x2, **kind)["a_w"])


def test_select_teeth_internal_rows_follow_the_ring_formulas():
    sel = gd.select_teeth(3.0, m=2, z1_range=(18, 22), internal=True)
    t = sel.table
    assert len(t) and t["feasible"].all() and (t["z2"] > t["z1"]).all()
    for r in t.itertuples():
        assert r.a_mm == pytest.approx(2 * (r.z2 - r.z1) / 2, rel=1e-15)        # a = m (z2 − z1)/2
        assert r.x_sum == pytest.approx(r.x2 - r.x1, abs=1e-15)
        assert r.a_w_mm == pytest.approx(_reference_a_w(2.0, r.z1, r.z2, r.x1, r.x2, internal=True), rel=1e-12)


def test_select_teeth_internal_in_a_housing_hits_its_centre_distance():
    sel = gd.select_teeth(3.0, m=2, a_w=42.0, z1_range=(18, 22), internal=True)
    feas = sel.table[sel.table["feasible"]]
    assert len(feas) >= 1
    for r in feas.itertuples():
        assert _reference_a_w(2.0, r.z1, r.z2, r.x1, r.x2, internal=True) == pytest.approx(42.0, rel=1e-10)
    # pairs the housing cannot take are skipped with the ring's own reason (a cos α with z2 − z1)
    small = sel.skipped[sel.skipped["reason"].str.contains("a·cos")]
    for r in small.itertuples():
        assert 2 * (r.z2 - r.z1) / 2 * math.cos(math.radians(20)) >= 42.0


def test_select_teeth_helical_with_face_width_solves_each_module():
    sel = gd.select_teeth(2.5, m="series", m_range=(2, 3), z1_range=(18, 22), beta_deg=15, face_width_mm=30,
                          checks={"eps_gamma_min": 2.2})
    t = sel.table
    assert set(t["module_mm"]) == {2.0, 2.25, 2.5, 2.75, 3.0}       # ISO 54 series 1 and 2
    for r in t.head(6).itertuples():
        assert r.a_mm == pytest.approx(r.module_mm * (r.z1 + r.z2) / (2 * math.cos(math.radians(15))), rel=1e-14)
        ref = _reference(r.module_mm, r.z1, r.z2, r.x1, r.x2, beta_deg=15.0, face_width_mm=30.0)
        assert r.a_w_mm == pytest.approx(float(ref["a_w"]), rel=1e-12)
        if r.feasible:   # ε_γ = ε_α + b sin β/(π m_n) >= 2.2 holds at every feasible row
            assert float(ref["eps_gamma"]) >= 2.2 - 1e-9
    # ε_β = b sin β/(π m) depends on the module: where ε_γ limits the larger modules, their optima
    # differ from the smaller modules' (one shared solve would give five equal rows)
    first = t[(t.z1 == 20) & (t.z2 == 50)]
    assert len(first) == 5 and first["x_sum"].round(9).nunique() >= 2


@pytest.mark.parametrize("kind", [{"beta_deg": 20.0}, {"internal": True}, {"beta_deg": 15.0, "internal": True}])
def test_atlas_rows_are_the_single_pair_optima(kind):
    df = gd.shift_atlas([15, 18], [40, 60], **kind)
    assert len(df) == 4 and df["feasible"].all()
    for r in df.itertuples():
        one = gd.optimize_shifts(r.z1, r.z2, **kind)
        assert (r.x1, r.x2) == pytest.approx((one.x1, one.x2), abs=1e-9)


def test_atlas_of_rings_keeps_only_rings_larger_than_the_pinion():
    assert gd.shift_atlas([15, 17], [16, 40], internal=True)[["z1", "z2"]].values.tolist() == \
        [[15, 16], [15, 40], [17, 40]]


def test_sensitivities_of_an_internal_pair_match_the_kkt_multipliers():
    t = sweeps.local_sensitivities(20, 60, internal=True, step=0.01)
    row = t.set_index("input").loc["eps_alpha_min"]
    assert row["slope_kkt"] < 0
    assert row["slope_dual"] == pytest.approx(row["slope_kkt"], rel=1e-5)
    assert row["slope_fd"] == pytest.approx(row["slope_kkt"], rel=1e-3)


def test_cli_shift_teeth_atlas_take_the_kind(capsys):
    assert main(["shift", "--z1", "20", "--z2", "60", "--internal", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["internal"] is True
    assert d["fun"] == pytest.approx(d["x2"] - d["x1"], abs=1e-12)     # max_x_sum of a ring pair: x2 − x1
    assert main(["teeth", "--ratio", "2.5", "-m", "2", "--z1-min", "18", "--z1-max", "20", "--beta", "15",
                 "--face-width", "30", "--eps-gamma-min", "2.0", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)["table"]
    assert rows and all("margin_total_contact_ratio" in r for r in rows)
    assert main(["atlas", "--z1", "15:16", "--z2", "16", "--internal", "--json"]) == 0
    assert [(r["z1"], r["z2"]) for r in json.loads(capsys.readouterr().out)["rows"]] == [(15, 16)]


SCENE = """
[gear]
module = 2.0
z1 = 20
z2 = 60
internal = true
beta_deg = 12.0
face_width_mm = 25.0
a_w = 42.0
[gear.checks]
eps_gamma_min = 2.0

[teeth]
ratio = 3.0
module = 2.0
z1_range = [18, 20]
internal = true
"""


def test_scene_with_an_internal_helical_pair(tmp_path):
    rep = gd.run_scene(write(tmp_path, SCENE), tmp_path / "out")
    res = rep.results["gear"]["optimum"]
    assert res.success and res.internal and res.beta_deg == 12.0
    assert _reference_a_w(2.0, 20, 60, res.x1, res.x2, internal=True, beta_deg=12.0) == pytest.approx(42.0, rel=1e-10)
    md = (tmp_path / "out" / "report.md").read_text(encoding="utf-8")
    assert "(internal, helical β = 12°)" in md and "total_contact_ratio" in md


@pytest.mark.parametrize("extra, words", [
    ("", ["z2", "z2 > z1"]),
])
def test_scene_refuses_what_an_internal_pair_cannot_do(tmp_path, extra, words):
    """(A ring pair's mesh_drawing is drawn now: tests/scene/test_sections.py.)"""
    z2 = "18"
    text = f"[gear]\nmodule = 2.0\nz1 = 20\nz2 = {z2}\ninternal = true\n{extra}"
    proc = subprocess.run([sys.executable, "-m", "geardesign", "run", str(write(tmp_path, text)),
                           "--out", str(tmp_path / "o")], capture_output=True, text=True)
    assert proc.returncode == 2 and proc.stderr.count("\n") == 1, proc.stderr
    assert all(w in proc.stderr for w in words), proc.stderr
