"""A wrong catalog name is answered with the tables of the kind asked for (issue 28: a chain design
offered key, module and motor tables)."""
import pytest

import geardesign as gd
from geardesign.catalogs.tables import BUNDLED, CHAIN_CATALOGS
from geardesign.errors import GearDesignError


def test_chain_catalog_error_lists_only_chain_tables():
    with pytest.raises(GearDesignError) as exc:
        gd.chain.design(torque_nm=380, n1_rpm=120, ratio=1, catalog="iso")
    text = str(exc.value)
    for name in CHAIN_CATALOGS:
        assert name in text
    for name in BUNDLED:
        if name not in CHAIN_CATALOGS and not any(name in c for c in CHAIN_CATALOGS):
            assert name not in text, name
