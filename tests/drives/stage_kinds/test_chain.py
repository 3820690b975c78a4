"""A chain stage's checks over a drive's designs are evaluated block by block (drives.limits.BATCH_BLOCK): the
same ranked table as one evaluation of every design at once (the chain's formulas are elementwise)."""

import pytest

import geardesign as gd
from geardesign.drives.stage_kinds import chain as chain_kind


def _table(objective):
    drive = gd.Drive(power_kw=4.0, n_in_rpm=1440, stages=[gd.GearStage(3), gd.ChainStage(catalog="gost13568")])
    return drive.optimize(10, objective=objective).table


@pytest.mark.slow
def test_blocks_give_the_table_of_one_evaluation(monkeypatch):
    blocked = {obj: _table(obj) for obj in ("min_size", "min_mass")}
    monkeypatch.setattr(chain_kind, "BATCH_BLOCK", 10**9)     # every design in one evaluation
    for obj, table in blocked.items():
        whole = _table(obj)
        assert len(table) > 0 and table.equals(whole), obj
