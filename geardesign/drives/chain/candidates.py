"""The candidates of a chain design: every catalog row × small-sprocket teeth, and the layout of
each (speed, pull, loop, sprockets), vectorised."""
from __future__ import annotations

import numpy as np

from .. import sprocket
from ...errors import GearDesignError
from .inputs import CENTER_DISTANCE_PITCHES_MAX, Inputs
from .tables import _ChainTable


class Candidates:
    """The candidate table under construction: one entry per (chain row, z1) pair.

    ``rows`` indexes the chain table; ``columns`` maps a computed column to its numpy array in
    candidate order. A catalog column is read (as floats) only when a step asks for it, and
    taken in full only when the result table is built.
    """

    def __init__(self, chains: _ChainTable, rows: np.ndarray, z1: np.ndarray, z2: np.ndarray):
        self.chains = chains
        self.rows = rows
        self.columns: dict[str, np.ndarray] = {"z1": z1, "z2": z2}
        self._read: dict[str, np.ndarray] = {}

    def __len__(self) -> int:
        return len(self.rows)

    def __contains__(self, name) -> bool:
        return name in self.columns or name in self.chains.values

    def __getitem__(self, name) -> np.ndarray:
        if name in self.columns:
            return self.columns[name]
        if name not in self._read:
            self._read[name] = self.chains.floats(name)[self.rows]
        return self._read[name]

    def __setitem__(self, name, values) -> None:
        self.columns[name] = values


def candidate_table(chains: _ChainTable, inp: Inputs) -> Candidates:
    """Every chain row of the asked strand counts times every z1, z2 = round(u·z1) <= z2_max.

    Rows vary slowest (the catalog's order), z1 fastest; built with np.repeat / np.tile.
    """
    rows = np.flatnonzero(np.isin(chains.strands, inp.strands))
    nz = len(inp.z1_values)
    rows = np.repeat(rows, nz)
    z1 = np.tile(inp.z1_values, len(rows) // nz)
    z2 = np.round(inp.u * z1).astype(np.int64)
    keep = z2 <= inp.z2_max
    if not keep.any():
        raise GearDesignError(f"no small sprocket z1 in {[int(z) for z in inp.z1_values]} keeps z2 = u·z1 <= "
                              f"z2_max = {inp.z2_max} at ratio {inp.u:g}")
    return Candidates(chains, rows[keep], z1[keep], z2[keep])


def layout(c: Candidates, inp: Inputs) -> None:
    """Chain speed, pull, loop and sprocket geometry of every candidate (formulas in :mod:`.sprocket`).

    v = z1·t·n1/60 000, F_t = P/v; the loop is laid out at the asked centre distance (default
    ``center_distance_pitches``·t) where the sprockets clear each other, 0.5·(D_e1 + D_e2) + 30 mm,
    and the span is at most 80 pitches (ISO 10823 notes); otherwise at the nearest such distance,
    and the candidate fails the center_distance check by the shortfall or the excess. The link
    count is the nearest even number and the centre distance is exact for it. The chain width
    is the inner width A/d_pin plus (strands − 1) transverse pitches.
    """
    t, z1a, z2a = c["pitch_mm"], c["z1"].astype(float), c["z2"].astype(float)
    m = c["strands"]
    v = sprocket.chain_speed_m_s(z1a, t, inp.n1)
    de1 = sprocket.tip_diameter_mm(t, z1a)
    de2 = sprocket.tip_diameter_mm(t, z2a)
    clearance = 0.5 * (de1 + de2) + 30.0
    given = inp.center_distance_mm is not None
    a_asked = np.full(t.shape, inp.center_distance_mm) if given else inp.center_distance_pitches * t
    a_span_max = CENTER_DISTANCE_PITCHES_MAX * t
    a0 = np.clip(a_asked, clearance, np.maximum(a_span_max, clearance)) if given else np.maximum(a_asked, clearance)
    links = sprocket.even_links(sprocket.link_count(a0, t, z1a, z2a))
    roller = c["roller_d1_mm"]
    c["speed_m_s"] = v
    c["force_n"] = inp.power_w / v
    c["links"] = links
    c["center_distance_mm"] = sprocket.center_distance_for_links_mm(links, t, z1a, z2a)
    c["sprocket1_pitch_diameter_mm"] = sprocket.pitch_diameter_mm(t, z1a)
    c["sprocket1_tip_diameter_mm"] = de1
    c["sprocket1_root_diameter_mm"] = sprocket.root_diameter_mm(t, z1a, roller)
    c["sprocket2_pitch_diameter_mm"] = sprocket.pitch_diameter_mm(t, z2a)
    c["sprocket2_tip_diameter_mm"] = de2
    c["sprocket2_root_diameter_mm"] = sprocket.root_diameter_mm(t, z2a, roller)
    c["width_mm"] = c["hinge_area_mm2"] / c["pin_d_mm"] + (m - 1) * np.nan_to_num(c["transverse_pitch_mm"])
    c["chain_mass_kg"] = c["mass_kg_m"] * links * t / 1000.0
    c["impacts_per_s"] = sprocket.impacts_per_second(z1a, inp.n1, links)
    c["breaking_load_n"] = c["breaking_load_kn"] * 1000.0
    if given:
        c["margin_center_distance"] = np.minimum(a_asked / clearance, a_span_max / a_asked) - 1.0
