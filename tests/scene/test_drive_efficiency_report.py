"""Issue 37 §4: "the drive's overall efficiency and heat to dissipate in its report". The report of a reducer on
its shafts (studies/scenes/reducer_shafts.toml) states both; they must be what its own power flow and its
efficiency table say: heat = P_in − P_out = the sum of the stages' losses, overall = P_out/P_in = the product of
the stages' efficiencies."""
import csv
import math
import re
from pathlib import Path

from geardesign.cli import main

SCENE = Path(__file__).resolve().parents[2] / "studies" / "scenes" / "reducer_shafts.toml"


def _rows(path: Path) -> list:
    with path.open(encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def test_report_states_the_heat_and_efficiency_of_its_own_power_flow(tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["run", str(SCENE), "--out", str(out)]) == 0
    capsys.readouterr()
    text = (out / "report.md").read_text(encoding="utf-8")
    found = re.search(r"Overall efficiency ([0-9.]+); heat to dissipate ([0-9.]+) W\.", text)
    assert found, "the report states no overall efficiency and heat"
    eta, heat_w = float(found.group(1)), float(found.group(2))
    flow = _rows(out / "drive_flow.csv")
    p_in, p_out = float(flow[0]["power_kw"]), float(flow[-1]["power_kw"])
    assert math.isclose(heat_w, 1000 * (p_in - p_out), rel_tol=5e-5)            # printed to 5 digits
    assert math.isclose(eta, p_out / p_in, abs_tol=5e-6)
    # the efficiencies and the flow are a fixed point solved until no efficiency moves by more than 1e-6
    # (docs/shafts_in_drive.md): the stages' losses add up to the heat to that tolerance
    stages = _rows(out / "drive_efficiency.csv")
    assert math.isclose(sum(float(r["loss_w"]) for r in stages), 1000 * (p_in - p_out), rel_tol=1e-5)
    assert math.isclose(math.prod(float(r["efficiency"]) for r in stages), p_out / p_in, rel_tol=1e-6)
    # the computed stages are charged their mesh and bearing losses, the given one its (1 − η)·P_in
    for r in stages:
        if r["source"] == "computed":
            parts = float(r["mesh_loss_w"]) + float(r["bearing_loss_w"]) + float(r["no_load_loss_w"])
            assert math.isclose(float(r["loss_w"]), parts, rel_tol=1e-12)
        else:
            assert math.isclose(float(r["loss_w"]), (1 - float(r["efficiency"])) * float(r["power_in_w"]), rel_tol=1e-9)
