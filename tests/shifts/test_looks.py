"""How a check looks (geardesign.shifts.looks): one colour per kind from the registry, solid for gear 1 and dashed
for gear 2, a planetary set's gears by their own styles, legends with the limit, and the margin bars of an
optimum (a value at each bar, the active ones outlined)."""
import matplotlib

import geardesign as gd
from geardesign.gears.checks import ContactRatio, TipThickness, check_colour
from geardesign.shifts.looks import PLANET_RING_COLOURS, check_legend, check_style, margin_bars

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)


def test_styles_by_kind_and_gear():
    assert check_style("undercut1") == (check_colour("undercut1"), "-")
    assert check_style("undercut2") == (check_colour("undercut2"), "--")
    assert check_style("undercut1")[0] == check_style("undercut2")[0]          # one colour per kind
    assert check_style("contact_ratio") == (check_colour("contact_ratio"), "-")
    assert check_style("planet-ring:interference_planet") == (PLANET_RING_COLOURS["interference"], "--")
    assert check_style("sun-planet:interference_sun")[1] == "-" and check_style("planet-ring:ring_tip")[1] == "--"
    # the set's own checks dotted, the planet's damage over both meshes too (it named the planet: dashed, as the
    # planet-ring mesh's pink interference_planet beside it)
    assert check_style("set:neighbours")[1] == ":" and check_style("set:pitting_damage_planet")[1] == ":"
    custom = check_style("my_check")
    assert custom[1] == "-." and custom == check_style("my_check")               # the same every time


def test_legends_say_the_limit():
    assert check_legend(ContactRatio(limit=1.3)) == "contact_ratio: ε_α ≥ 1.3"
    assert check_legend(TipThickness(gear=2, limit=0.4)) == "tip_thickness2: s_a2/m ≥ 0.4"
    # a set's mesh check of a kind without a legend line: its label, the mesh said once (in the name)
    from geardesign.gears.checks.damage import PittingDamage
    from geardesign.gears.planetary import MeshCheck

    text = check_legend(MeshCheck(inner=PittingDamage(gear=1), mesh="sun-planet"))
    assert text == "sun-planet:pitting_damage_sun: pitting damage of sun D_H <= 1 (ISO 6336-6)"


def test_margin_bars_of_an_optimum():
    r = gd.optimize_shifts(17, 26)
    fig, ax = plt.subplots()
    try:
        margin_bars(ax, r.margins, r.active, "17/26")
        labels = [t.get_text() for t in ax.get_yticklabels()]
        assert labels == [f"{k} (active)" if k in r.active else k for k in r.margins]
        texts = [t.get_text() for t in ax.texts]
        assert texts == [f"{v:+.3g}" for v in r.margins.values()]          # the value at each bar
        bars = ax.patches
        edges = [b.get_edgecolor()[3] for b in bars]
        assert edges == [1.0 if k in r.active else 0.0 for k in r.margins]  # only the active outlined
        assert ax.get_title() == "17/26"
    finally:
        plt.close(fig)
