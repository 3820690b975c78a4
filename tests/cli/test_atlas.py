"""The `geardesign atlas` command."""
from geardesign.cli import main


def test_cli_atlas(tmp_path, capsys):
    out = tmp_path / "atlas.csv"
    assert main(["atlas", "--z1", "12:13", "--z2", "20,30", "--out", str(out)]) == 0
    assert out.read_text().count("\n") == 5
    assert main(["atlas", "--z1", "x:y", "--z2", "20"]) == 2
