"""Scene text and a writer shared by the scene tests (tests/scene/) and the `geardesign run` tests
(tests/cli/test_run.py)."""

GOOD_GEAR = """
[gear]
module = 8
z1 = 17
z2 = 26
"""

# seed 002's bought gear motor after a 4 kW, 1500 rpm input: every figure by hand, T = P/ω·u·η
GIVEN_DRIVE = """
[drive]
power_kw = 4
n_in_rpm = 1500
[[drive.stage]]
kind = 'given'
ratio = 12.5
efficiency = 0.87
"""


def write(tmp_path, text, name="case.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p
