"""Scene files: the parser's errors (one message naming file, key and expectation), and a user's
chain catalog read relative to the scene file."""
import pytest

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.scene import load_scene

from tests.scene_files import GOOD_GEAR, write


@pytest.mark.parametrize("text, key, expected", [
    # unknown section
    (GOOD_GEAR + "\n[gears]\nz1 = 3\n", "gears", "expected sections"),
    # unknown key
    (GOOD_GEAR + "modul = 8\n", "modul", "unknown key; expected one of module"),
    # unknown key in a sub-table
    (GOOD_GEAR + "[gear.checks]\neps_min = 1.2\n", "eps_min", "unknown key; expected one of undercut, interference"),
    # wrong type
    (GOOD_GEAR.replace("z1 = 17", 'z1 = "seventeen"'), "z1", "expected a whole number in [3, 100000]"),   # gears.mesh Z_MIN, Z_MAX
    (GOOD_GEAR.replace("z1 = 17", "z1 = 17.5"), "z1", "expected a whole number"),
    (GOOD_GEAR + "tip_shortening = 1\n", "tip_shortening", "expected true or false"),
    (GOOD_GEAR + 'objective = "max_xsum"\n', "objective", "expected one of 'max_x_sum'"),
    # missing required value
    (GOOD_GEAR.replace("z2 = 26\n", ""), "z2", "missing; expected a whole number"),
    ("[chain]\ntorque_nm = 380\nratio = 1\n", "n1_rpm", "missing"),
    (GOOD_GEAR + "x1 = 0.5\n", "x2", "give both x1 and x2"),
    # out of range
    (GOOD_GEAR.replace("module = 8", "module = -8"), "module", "expected a number in [0.0001, 10000]"),   # gears.geometry M_RANGE_MM
    (GOOD_GEAR + "[gear.rack]\nalpha_deg = 50\n", "alpha_deg", "expected a number in [1, 44]"),   # gears.rack ALPHA_RANGE_DEG
    ("[chain]\ntorque_nm = 380\nn1_rpm = 120\nratio = 0.5\n", "ratio", "expected a number in [1, 10]"),
    ("[key]\nd_mm = 60\ntorque_nm = 380\nhub_length_mm = 50\nmax_keys = 3\n", "max_keys", "[1, 2]"),
    (GOOD_GEAR + "[study]\nparameter = \"colour\"\nvalues = [1, 2]\n", "parameter", "expected one of sa_min, eps_alpha_min"),
    (GOOD_GEAR + "[study]\ntarget = \"chain\"\nparameter = \"k_e\"\nvalues = [1, 2]\n", "target", "[chain] is missing"),
])
def test_scene_errors_name_file_key_and_expectation(tmp_path, text, key, expected):
    p = write(tmp_path, text)
    with pytest.raises(GearDesignError) as info:
        load_scene(p)
    msg = str(info.value)
    assert str(p) in msg and key in msg and expected in msg
    assert "\n" not in msg


def test_not_toml_and_empty_scene(tmp_path):
    with pytest.raises(GearDesignError, match="not a valid TOML file"):
        load_scene(write(tmp_path, "[gear\nz1 = 17"))
    with pytest.raises(GearDesignError, match="expected at least one of the sections"):
        load_scene(write(tmp_path, 'title = "nothing"\n'))
    with pytest.raises(GearDesignError, match="cannot read"):
        load_scene(tmp_path / "missing.toml")


def test_scene_takes_a_users_chain_catalog_beside_it(tmp_path):
    """`catalog = "my_chains.csv"` is read relative to the scene file, as the CLI reads a path:
    the same rows give the same best chain as the built-in ISO 606 table they were copied from."""
    from geardesign.catalogs import catalog_dir

    (tmp_path / "my_chains.csv").write_bytes((catalog_dir() / "chains_iso606.csv").read_bytes())
    scene = tmp_path / "s.toml"
    scene.write_text('[chain]\ntorque_nm = 380\nn1_rpm = 120\nratio = 1\ncatalog = "my_chains.csv"\n')
    rep = gd.run_scene(scene, tmp_path / "out")
    ref = gd.chain.design(torque_nm=380, n1_rpm=120, ratio=1, catalog="iso606")
    assert any(ref.best["designation"] in line for line in rep.summary)
    bad = tmp_path / "bad.toml"
    bad.write_text('[chain]\ntorque_nm = 380\nn1_rpm = 120\nratio = 1\ncatalog = "keys"\n')
    with pytest.raises(gd.GearDesignError, match="or a .csv file of chains"):
        gd.load_scene(bad)


@pytest.mark.parametrize("text", [
    '[chain]\ntorque_nm = 100\nn1_rpm = 720\nratio = 2.5\ncatalog = "' + "x" * 100_000 + '"\n',   # issue 29 §3.14
    '[chain]\ntorque_nm = 100\nn1_rpm = 720\nratio = 2.5\n' + "k" * 100_000 + ' = 1\n',
    '[' + "s" * 100_000 + ']\nq = 1\n',
    '[gear]\nmodule = 2\nz1 = 17\nz2 = 26\nx1 = [' + ", ".join(["1"] * 30_000) + ']\n',
    '[study]\nparameter = "' + "p" * 100_000 + '"\nvalues = [1]\n' + GOOD_GEAR,
])
def test_scene_errors_cut_the_bad_value_like_the_validators(tmp_path, text):
    """A 100 000-character value or name gave one 100 kB stderr line; values are cut at 60 characters
    (validate._short) with their length said."""
    with pytest.raises(GearDesignError) as info:
        load_scene(write(tmp_path, text))
    msg = str(info.value)
    assert "\n" not in msg and len(msg) < 400 + len(str(tmp_path)) and "characters)" in msg, msg[:500]
