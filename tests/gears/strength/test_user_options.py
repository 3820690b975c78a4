"""The user-facing strength options (geardesign.gears.strength.user_options): one definition that the command
line and the scenes read; each option names a keyword pair_strength takes, with its range as the model checks it."""
import inspect

import pytest

from geardesign.errors import GearDesignError
from geardesign.gears.strength import defaults as dflt
from geardesign.gears.strength.chain import GIVEN_FACTORS, pair_strength
from geardesign.gears.strength.options import GROUPED
from geardesign.gears.strength.user_options import (STRENGTH_OPTIONS, options_from_table, scene_keys,
                                                    strength_option)


def test_every_option_sets_a_keyword_or_a_given_factor_of_the_chain():
    # pair_strength's keywords and the options it takes in one StrengthOptions (options=)
    keywords = set(inspect.signature(pair_strength).parameters) | set(GROUPED)
    for o in STRENGTH_OPTIONS:
        assert (o.keyword in GIVEN_FACTORS) if o.factor else (o.keyword in keywords), o.keyword
        assert o.flag.startswith("--") and o.describe().startswith(o.help)


def test_the_defaults_are_the_models():
    assert strength_option("nu40").default == dflt.NU40_MM2_S
    assert strength_option("S_Hmin").default == dflt.S_HMIN and strength_option("S_Hmin").limit
    with pytest.raises(KeyError):
        strength_option("no_such_option")


def test_scene_keys_and_a_table_back_to_options():
    keys = scene_keys()
    assert {"accuracy_grade", "nu40", "S_Hmin", "factors"} <= set(keys)
    assert "S_Hmin" not in scene_keys(limits=False)
    options, rest = options_from_table({"nu40": 320.0, "f_ma": 0.0, "factors": {"K_A": 1.25}, "z1": 20})
    assert options == {"nu40": 320.0, "factors": {"K_A": 1.25, "f_ma": 0.0}} and rest == {"z1": 20}
    with pytest.raises(GearDesignError, match="f_ma given twice"):
        options_from_table({"f_ma": 0.0, "factors": {"f_ma": 1.0}})
