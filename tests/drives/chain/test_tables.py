"""The chain design's tables as arrays (geardesign.drives.chain.tables): read-only, read once per file version (an
edited CSV is read again), the strand factors of seed 002 section 1.9.5 (two strands: 2·0.85 = 1.7) and the
Russian course-design tables (1, 1.7, 2.5, 3), and a refusal for a catalog without the strands asked for."""
import os

import numpy as np
import pytest

from geardesign.catalogs import catalog_dir, load_catalog
from geardesign.drives.chain.inputs import validate_inputs
from geardesign.drives.chain.tables import load_chains, reference_tables, strand_index
from geardesign.errors import GearDesignError
from tests.drives.chain.test_inputs import BASE


def test_reference_tables_are_read_only_and_read_once():
    t = reference_tables(catalog_dir())
    assert t is reference_tables(catalog_dir())
    for a in (t.speed_pitch_mm, t.n1_max_rpm, t.strands, t.hinge_strand_factor):
        assert not a.flags.writeable
        with pytest.raises(ValueError):
            a[0] = 0


def test_strand_factors():
    t = reference_tables(catalog_dir())
    idx = strand_index(t, np.array([1, 2, 3, 4]))
    assert t.hinge_strand_factor[idx].tolist() == [1.0, 1.7, 2.5, 3.0]
    with pytest.raises(KeyError, match="strands"):
        strand_index(t, np.array([9]))


def test_the_chain_table_follows_its_file(tmp_path):
    frame = load_catalog("gost13568")
    path = tmp_path / "chains.csv"
    frame.head(6).to_csv(path, index=False)
    inp = validate_inputs(**{**BASE, "catalog": str(path)})
    first = load_chains(inp, catalog_dir())
    assert load_chains(inp, catalog_dir()) is first                   # read once
    frame.head(4).to_csv(path, index=False)
    st = path.stat()
    os.utime(path, ns=(st.st_atime_ns, st.st_mtime_ns + 10**9))         # a later edit of the file
    again = load_chains(inp, catalog_dir())
    assert again is not first and len(again.strands) == 4
    assert not again.floats("pitch_mm").flags.writeable


def test_a_catalog_without_the_strands_asked_for(tmp_path):
    frame = load_catalog("gost13568")
    path = tmp_path / "single.csv"
    frame[frame["strands"] == 1].to_csv(path, index=False)            # single-strand rows only
    inp = validate_inputs(**{**BASE, "strands": (2,), "catalog": str(path)})
    with pytest.raises(GearDesignError, match="no chain with strands in \\(2,\\)"):
        load_chains(inp, catalog_dir())
