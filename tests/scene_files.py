"""Scene text and a writer shared by the scene-loader tests (tests/scene/test_load.py) and the
`geardesign run` tests (tests/cli/test_run.py)."""

GOOD_GEAR = """
[gear]
module = 8
z1 = 17
z2 = 26
"""


def write(tmp_path, text, name="case.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p
