"""Reading a scene file (geardesign/scene/toml_file.py): what load_scene and load_engine share, refused by file."""
import pytest

from geardesign.errors import GearDesignError
from geardesign.scene.engine import load_engine
from geardesign.scene.load import load_scene
from geardesign.scene.toml_file import SCENE_DEPTH_MAX, SCENE_INT_MAX, read_scene_toml


def test_a_scene_is_parsed(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text("title = 't'\n[engine]\nn_rpm = 1700\n", encoding="utf-8")
    assert read_scene_toml(path) == {"title": "t", "engine": {"n_rpm": 1700}}


@pytest.mark.parametrize("text, expected", [
    ("[engine\n", "not a valid TOML file"),
    ("a = " + "[" * (SCENE_DEPTH_MAX + 2) + "1" + "]" * (SCENE_DEPTH_MAX + 2) + "\n", "is nested deeper than 8 levels"),
    (f"a = {SCENE_INT_MAX * 10}\n", "a = an integer of 17 digits"),
])
def test_both_loaders_refuse_the_same_file_the_same_way(tmp_path, text, expected):
    path = tmp_path / "s.toml"
    path.write_text(text, encoding="utf-8")
    for read in (read_scene_toml, load_scene, load_engine):
        with pytest.raises(GearDesignError) as exc:
            read(path)
        assert str(exc.value).startswith(f"{path}: ") and expected in str(exc.value), (read, str(exc.value))


def test_a_missing_file_or_a_folder_is_refused(tmp_path):
    with pytest.raises(GearDesignError, match="no such file"):
        read_scene_toml(tmp_path / "none.toml")
    with pytest.raises(GearDesignError, match="not a regular file"):
        read_scene_toml(tmp_path)
