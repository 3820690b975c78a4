"""The [drive] scene section (geardesign.scene.drive): a TOML section loads into the same Drive one
builds by hand, its flow is the hand-worked one (T = P/ω, T_out = T_in·u·η), and every fault is one
GearDesignError naming the stage table."""
import math

import pytest

from geardesign.errors import GearDesignError
from geardesign.scene import load_scene
from geardesign.scene.drive import build_drive, compute_drive
from tests.scene_files import GIVEN_DRIVE, write

BODY = GIVEN_DRIVE + """name = 'gear motor'
[[drive.stage]]
kind = 'gear'
module = 2
z1 = 20
z2 = 50
efficiency = 0.97
[[drive.shaft]]
at = 2
name = 'out'
d_mm = 60
hub_length_mm = 80
"""


def _section(tmp_path, body=BODY):
    return load_scene(str(write(tmp_path, body))).sections["drive"]


def test_section_builds_the_drive_written_in_it(tmp_path):
    drive, motor = build_drive(_section(tmp_path))
    assert motor is None
    given, gear = drive.stages
    assert (given.kind, given.ratio, given.efficiency, given.name) == ("given", 12.5, 0.87, "gear motor")
    assert gear.kind == "gear" and gear.m == 2
    assert [(s.at, s.name, s.d_mm, s.hub_length_mm) for s in drive.shafts] == [(2, "out", 60, 80)]


def test_flow_is_the_hand_flow(tmp_path):
    _, _, opt, an = compute_drive(_section(tmp_path))
    assert opt is None
    t0 = 4000 / (2 * math.pi * 1500 / 60)
    t1 = t0 * 12.5 * 0.87
    t2 = t1 * 50 / 20 * 0.97
    assert an.flow["n_rpm"].tolist() == pytest.approx([1500, 120, 48], rel=1e-14)
    assert an.flow["torque_nm"].tolist() == pytest.approx([t0, t1, t2], rel=1e-13)


@pytest.mark.parametrize("old, new, words", [
    ("kind = 'gear'", "kind = 'belt'", "drive.stage #2"),
    ("z2 = 50", "z2 = 50\nwhatever = 1", "whatever"),
    ("at = 2", "at = 7", "at"),
    ("efficiency = 0.87", "efficiency = 1.5", "efficiency"),
])
def test_faults_are_one_named_error(tmp_path, old, new, words):
    with pytest.raises(GearDesignError, match=words):
        _section(tmp_path, BODY.replace(old, new))
