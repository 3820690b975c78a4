"""The `geardesign shift` command: JSON, the contour plot, options, and exit 1 when infeasible."""
import json

from geardesign.cli import main


def test_cli_shift_json_and_plot(tmp_path, capsys):
    png = tmp_path / "contour.png"
    assert main(["shift", "--z1", "17", "--z2", "26", "--module", "8", "--plot", str(png), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["success"] and doc["active"] == ["contact_ratio"]
    assert doc["region"]["feasible"] and png.exists()


def test_cli_shift_infeasible_exit_1(capsys):
    assert main(["shift", "--z1", "5", "--z2", "5"]) == 1
    assert "conflict" in capsys.readouterr().out


def test_cli_shift_options(capsys):
    assert main(["shift", "--z1", "17", "--z2", "26", "--allow-undercut", "--eps-alpha-min", "1.1",
                 "--sa-min", "0.4", "--objective", "max_eps_alpha", "--method", "convex", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert "undercut1" not in doc["margins"] and doc["method"] == "convex"
