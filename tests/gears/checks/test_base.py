"""The check registry: one class registered is one check everywhere (make_checks, the CLI's options,
the scene schema, the contour's colours and legend), and the options' table is the one source of
each default and range."""
import contextlib
import io
from dataclasses import dataclass

import matplotlib
import pytest

matplotlib.use("Agg")

import geardesign as gd
from geardesign.cli import main
from geardesign.errors import GearDesignError
from geardesign.gears import checks as ck
from geardesign.gears.checks.base import Check, Option, register, unregister
from geardesign.scene.schema import section_schema

ROOT_GAP = Option("root_gap_min", "limit", None, "smallest tip thickness of gear 1 / module (a test's own check)",
                  source="test", range=(0.0, 1.0), sweep=True)


@dataclass(frozen=True)
class RootGap(Check):
    """Gear 1's tip thickness s_a1/m >= limit under a name of its own: a made-up check that registers
    itself as a built-in one would."""

    option, colour, order = ROOT_GAP, "gold", 65

    def __post_init__(self):
        object.__setattr__(self, "name", self.name or "root_gap")
        object.__setattr__(self, "label", self.label or "s_a1/m >= root_gap_min")

    def value(self, geo):
        return geo["san1"] / geo["_m"]

    def gradient(self, geo):
        return ck.TipThickness(gear=1).gradient(geo)


@pytest.fixture
def root_gap():
    register(RootGap)
    yield RootGap
    unregister(RootGap)


def test_registered_check_is_built_by_make_checks_only_when_asked(root_gap):
    assert "root_gap" not in [c.name for c in ck.make_checks()]            # its default None: off
    names = [c.name for c in ck.make_checks(root_gap_min=0.2)]
    assert names.index("root_gap") == names.index("contact_ratio") + 1     # its order, 65: after ε_α (60)
    with pytest.raises(GearDesignError, match=r"root_gap_min must be .*1"):
        ck.make_checks(root_gap_min=5.0)                                    # its declared range


def test_registered_check_appears_in_cli_help_and_works(root_gap):
    out = io.StringIO()
    with contextlib.redirect_stdout(out), pytest.raises(SystemExit):
        main(["pair", "--help"])
    text = " ".join(out.getvalue().split())
    assert "--root-gap-min" in text and "a test's own check" in text
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        main(["pair", "--module", "8", "--z1", "17", "--z2", "26", "--root-gap-min", "0.2", "--json"])
    assert '"root_gap"' in out.getvalue()


def test_registered_check_appears_in_the_scene_schema(root_gap):
    spec = section_schema("gear")["checks"]["root_gap_min"]
    assert (spec.kind, spec.lo, spec.hi) == ("float", 0.0, 1.0)


def test_registered_check_gets_its_colour_and_a_legend_entry(root_gap):
    region = gd.feasible_region(17, 26, checks={"root_gap_min": 0.2})
    ax = region.plot()
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any("root_gap" in t for t in labels)
    assert ck.check_colour("root_gap") == "gold"
    matplotlib.pyplot.close(ax.figure)


def test_unregistered_check_is_gone_everywhere(root_gap):
    unregister(RootGap)
    assert "root_gap_min" not in ck.options()
    assert "root_gap_min" not in section_schema("gear")["checks"]
    with pytest.raises(GearDesignError, match="unknown option 'root_gap_min'; allowed: undercut"):
        ck.make_checks(root_gap_min=0.2)
    register(RootGap)   # for the fixture's own clean-up


def test_registry_refuses_a_class_without_an_option():
    @dataclass(frozen=True)
    class NoOption(Check):
        pass

    with pytest.raises(GearDesignError, match="register takes a Check subclass with an Option"):
        register(NoOption)


def test_every_option_has_help_source_and_a_valid_default():
    for name, opt in ck.options().items():
        assert opt.help and opt.source, name
        assert opt.kind in ("limit", "flag"), name
        if opt.kind == "limit":
            lo, hi = opt.range
            assert opt.default is None or lo <= opt.default <= hi, name
        else:
            assert opt.default in (True, False), name


def test_resolve_checks_message_lists_every_option():
    with pytest.raises(GearDesignError) as info:
        ck.resolve_checks({"eps_min": 1.2})
    for name in list(ck.options()) + ["cutter", "extra"]:
        assert name in str(info.value)


def test_cli_switches_and_none_limits_reach_make_checks():
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        main(["pair", "--module", "8", "--z1", "17", "--z2", "26", "--no-undercut", "--eps-alpha-min", "none",
              "--json"])
    text = out.getvalue()
    assert '"undercut1"' not in text and '"contact_ratio"' not in text and '"interference1"' in text


def test_feasibility_has_one_tolerance():
    """A margin of −1e-15 (a boundary point to rounding) holds in the table, ok() and the solvers."""
    r = gd.optimize_shifts(28, 43, beta_deg=8)
    pair = gd.GearPair(1, 28, 43, r.x1, r.x2, beta_deg=8)
    table = pair.checks(jamming=False)
    assert r.success and pair.ok(jamming=False) and bool(table["ok"].all())
    assert ck.FEASIBILITY_TOL == 1e-12
