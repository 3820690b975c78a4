"""The scene schema reads its ranges and defaults from the library."""
import geardesign as gd


def test_scene_schema_reads_the_library_ranges(tmp_path):
    """ε_α >= 5 is inside the library's range (0, 10); the old scene-only range stopped at 3."""
    from geardesign.gears.checks import EPS_ALPHA_MIN_RANGE
    from geardesign.scene.schema import section_schema
    spec = section_schema("gear")["checks"]["eps_alpha_min"]
    assert (spec.lo, spec.hi) == EPS_ALPHA_MIN_RANGE
    f = tmp_path / "s.toml"
    f.write_text("[gear]\nmodule = 2\nz1 = 20\nz2 = 40\n[gear.checks]\neps_alpha_min = 5.0\n")
    assert gd.load_scene(f).sections["gear"]["checks"]["eps_alpha_min"] == 5.0
