"""The max_margin optimum of many tooth pairs at once (geardesign.shifts.centres).

References: the exact method's own active-set search (kkt.py, a different algorithm: a Newton solve per
candidate active set from the best node of a 31 × 31 grid, several starts), and a fine grid of the
window evaluated with Problem.fun (no solver at all): no node may beat the optimum, and the optimum is
within a node's reach of the best node.
"""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import geardesign as gd
from geardesign.drives.stage_kinds import gear as gear_kind
from geardesign.gears.checks import FEASIBILITY_TOL
from geardesign.gears.mesh import Mesh
from geardesign.shifts import centres
from geardesign.shifts.problem import DEFAULT_BOUNDS, Problem

# (z1, z2, m): vertices (three smallest normalised margins equal; the benchmark drive's pairs are all of
# this kind) and edges (tip thickness 1 and interference 1 opposite each other, common at ratios 2...10)
VERTICES = [(25, 116, 3.0), (24, 123, 3.0), (17, 26, 1.0), (20, 40, 1.0),
            (24, 26, 1.0)]   # 24/26: its first vertex (0.748, -0.024) has a negative multiplier; the gain lies
#                              past the five lowest pieces, which a smaller trust region brings into reach
EDGES = [(41, 146, 1.0), (34, 69, 1.0), (50, 102, 1.0)]


def _pieces_at(z1, z2, m, x1, x2):
    """The normalised pieces of one design, smallest first (Problem.evaluate_point: the float path)."""
    p = Problem(Mesh(z1, z2), None, "max_margin", m)
    P = p.evaluate_point(np.array([x1, x2]))[0]
    return np.sort(P)


def _one_pair(z1, z2, m):
    return centres.margin_centres([z1], [z2], m)


@pytest.mark.parametrize("z1, z2, m", VERTICES + EDGES)
def test_agrees_with_the_active_set_search(monkeypatch, z1, z2, m):
    r = _one_pair(z1, z2, m)
    assert r["ok"][0]
    monkeypatch.setattr(centres, "solve", lambda prob, bounds: None)      # the exact method's own search
    s = gd.optimize_shifts(z1, z2, "max_margin", m=m)
    assert "from a grid node" in s.message or "SLSQP" in s.message
    # a vertex is fixed by three equations (x to rounding); an edge's stationarity holds to the noise of
    # central-difference gradients (both methods stop at 1e-8 on it), while fun is flat there
    x_tol = 1e-11 if (z1, z2, m) in VERTICES else 1e-7
    assert r["x1"][0] == pytest.approx(s.x1, abs=x_tol)
    assert r["x2"][0] == pytest.approx(s.x2, abs=x_tol)
    assert r["fun"][0] == pytest.approx(s.fun, abs=1e-11)


@pytest.mark.parametrize("z1, z2, m, active", [v + (3,) for v in VERTICES[:2]] + [e + (2,) for e in EDGES[:2]])
def test_vertices_and_edges_are_certified_with_their_active_pieces(z1, z2, m, active):
    r = _one_pair(z1, z2, m)
    assert r["ok"][0]
    P = _pieces_at(z1, z2, m, r["x1"][0], r["x2"][0])
    assert P[:active] == pytest.approx(np.full(active, P[0]), abs=1e-10)
    assert P[active] > P[0] + 1e-3


@pytest.mark.parametrize("z1, z2, m", [(25, 116, 3.0), (41, 146, 1.0), (17, 26, 1.0)])
def test_no_node_of_a_fine_grid_beats_the_optimum(z1, z2, m):
    r = _one_pair(z1, z2, m)
    g = np.linspace(*DEFAULT_BOUNDS, 241)                 # spacing 0.01875
    x1, x2 = (a.ravel() for a in np.meshgrid(g, g, indexing="ij"))
    p = Problem(Mesh(z1, z2), None, "max_margin", m)
    with np.errstate(all="ignore"):
        fun = np.nan_to_num(p.fun(p.geo(x1, x2)), nan=-np.inf)
    best = fun.max()
    assert best <= r["fun"][0] + 1e-12
    assert best >= r["fun"][0] - 0.02                    # the best node lies within a spacing of the optimum


def test_a_batch_gives_each_pair_the_bits_of_its_own_solve():
    rng = np.random.default_rng(5)
    z1, z2 = rng.integers(12, 60, 40), rng.integers(20, 250, 40)
    r = centres.margin_centres(z1, z2, 2.0)
    assert r["ok"].sum() >= 36
    for i in range(0, 40, 4):
        s = gd.optimize_shifts(int(z1[i]), int(z2[i]), "max_margin", m=2.0)
        if r["ok"][i]:
            assert (r["x1"][i], r["x2"][i]) == (s.x1, s.x2)
            assert {k: float(v[i]) for k, v in r["margins"].items()} == s.margins
            geo = gd.GearPair(2.0, int(z1[i]), int(z2[i]), s.x1, s.x2).geometry()
            assert (r["a_w"][i], r["da1"][i], r["da2"][i]) == (geo.a_w, geo.da1, geo.da2)


def test_helical_pairs_and_other_checks():
    checks = {"sa_min": 0.4, "eps_alpha_min": 1.1}
    r = centres.margin_centres([23, 31], [77, 95], 2.5, checks, beta_deg=15.0)
    assert r["ok"].all()
    for i, (z1, z2) in enumerate([(23, 77), (31, 95)]):
        s = gd.optimize_shifts(z1, z2, "max_margin", checks, m=2.5, beta_deg=15.0)
        assert (r["x1"][i], r["x2"][i]) == (s.x1, s.x2)


def test_a_pair_without_a_design_is_left_uncertified():
    # 8/8 with the default checks: no shifts hold them all (optimize_shifts names the conflict)
    r = centres.margin_centres([8, 20], [8, 40])
    assert not r["ok"][0] and r["ok"][1]
    assert np.isnan(r["x1"][0]) and np.isnan(r["margins"]["undercut1"][0])
    assert gd.optimize_shifts(8, 8, "max_margin").conflict


def test_feasible_nodes_in_several_pieces_are_told_apart():
    f = np.zeros((3, 5, 5), bool)
    f[0, 0, 0] = f[0, 4, 4] = True           # two pieces
    f[1, 0, 0] = f[1, 1, 1] = f[1, 2, 2] = True   # one piece, through diagonal neighbours
    f[2, 1:4, 2] = True                       # one piece
    best = np.array([0, 0, 7])
    assert centres._one_piece(f.reshape(3, -1), best, 5).tolist() == [False, True, True]


@pytest.mark.parametrize("z1, z2, match", [
    ([17, 20], [26], "same number"), ([2], [30], "z1"), ([17], [1e308], "z2"), ([], [], "same number")])
def test_inputs_are_refused_by_name(z1, z2, match):
    with pytest.raises(gd.GearDesignError, match=match):
        centres.margin_centres(z1, z2)


def test_the_number_of_pairs_is_limited_up_front():
    n = centres.PAIRS_MAX + 1
    with pytest.raises(gd.GearDesignError, match=f"at most {centres.PAIRS_MAX}"):
        centres.margin_centres(np.full(n, 17), np.full(n, 26))


def test_a_max_margin_drive_solves_its_pairs_in_batches_with_the_same_result(monkeypatch):
    gear = gd.GearStage(2, z1_range=(17, 22), z2_max=90, ratio_range=(1.0, 5.0))
    chain = gd.ChainStage(ratio_range=(1.0, 3.0), z2_max=40, strands=(1, 2))
    drive = gd.Drive(power_kw=3.0, n_in_rpm=1410, stages=[gear, chain])
    gear_kind.clear_shift_cache()
    batched = drive.optimize(6.0, 0.03, objective="max_margin", top=8)
    calls = []
    monkeypatch.setattr(gear_kind, "margin_solutions", lambda stage, pairs: calls.append(len(pairs)))
    gear_kind.clear_shift_cache()
    alone = drive.optimize(6.0, 0.03, objective="max_margin", top=8)
    assert calls and batched.n_shift_solves == alone.n_shift_solves > 2
    assert batched.table.equals(alone.table)


@settings(max_examples=15, deadline=None, derandomize=True, database=None)
@given(z1=st.integers(8, 80), z2=st.integers(8, 300), beta=st.sampled_from([0.0, 15.0, 30.0]),
       checks=st.sampled_from([None, {"sa_min": 0.4}, {"undercut": False}, {"eps_alpha_min": 1.1}]))
def test_every_certified_optimum_holds_its_checks_and_no_node_beats_it(z1, z2, beta, checks):
    r = centres.margin_centres([z1], [z2], 1.0, checks, beta_deg=beta)
    if not r["ok"][0]:
        return
    assert min(v[0] for v in r["margins"].values()) >= -FEASIBILITY_TOL
    p = Problem(Mesh(z1, z2, beta_deg=beta), checks, "max_margin", 1.0)
    g = np.linspace(*DEFAULT_BOUNDS, 61)
    x1, x2 = (a.ravel() for a in np.meshgrid(g, g, indexing="ij"))
    with np.errstate(all="ignore"):
        geo = p.geo(x1, x2)
        feasible = (p.margins(geo) >= 0).all(axis=0)
        fun = np.where(feasible, np.nan_to_num(p.fun(geo), nan=-np.inf), -np.inf)
    assert fun.max() <= r["fun"][0] + 1e-12


def test_a_max_margin_atlas_gives_each_pair_its_own_solve():
    df = gd.shift_atlas([17, 24, 41], [26, 69, 146], objective="max_margin")
    assert df.feasible.all()
    assert centres.margin_centres(df.z1, df.z2)["ok"].all()
    for _, row in df.iterrows():
        s = gd.optimize_shifts(int(row.z1), int(row.z2), "max_margin")
        assert (row.x1, row.x2) == (s.x1, s.x2)
        assert row.objective == pytest.approx(s.fun, abs=1e-12)


@pytest.mark.parametrize("z1, z2, edge", [(41, 146, True), (34, 69, True), (25, 116, False), (17, 26, False)])
def test_the_result_states_an_edges_accuracy(z1, z2, edge):
    r = gd.optimize_shifts(z1, z2, "max_margin")
    assert ("x to ~1e-8 along the edge" in r.accuracy) == edge
    assert ("x to ~1e-12" in r.accuracy) == (not edge)


def _edge_maximum(z1, z2, x0, h=1e-4, n=21):
    """An independent reference for an edge optimum from values alone: points of the edge (the two lowest
    pieces equal, found by secant steps along its normal) at arc offsets within ±h of x0, a quadratic
    fitted to their smallest piece, and the edge's point at the fit's top: (x, smallest piece there). The
    fit's bias grows as h² (7e-7 in x at h = 2e-3, 1e-9 at 1e-4); rounding enters as ~1e-16/h."""
    p = Problem(Mesh(z1, z2), None, "max_margin", 1.0)
    pieces = lambda v: p.evaluate_point(np.asarray(v, dtype=float))[0]
    a, b = np.argsort(pieces(x0))[:2]
    f = lambda v: pieces(v)[a] - pieces(v)[b]
    e = 1e-6
    g = np.array([f(x0 + [e, 0]) - f(x0 - [e, 0]), f(x0 + [0, e]) - f(x0 - [0, e])])
    normal = g / np.linalg.norm(g)
    along = np.array([-normal[1], normal[0]])

    def on_edge(s):
        y, q0, q1 = x0 + s * along, 0.0, 1e-7
        f0, f1 = f(y), f(y + q1 * normal)
        for _ in range(30):
            if f1 == f0 or abs(f1) < 1e-15:
                break
            q0, q1, f0 = q1, q1 - f1 * (q1 - q0) / (f1 - f0), f1
            f1 = f(y + q1 * normal)
        return y + q1 * normal

    s = np.linspace(-h, h, n)
    c2, c1, _ = np.polyfit(s, [pieces(on_edge(si)).min() for si in s], 2)
    x = on_edge(-c1 / (2 * c2))
    return x, pieces(x).min()


@pytest.mark.parametrize("z1, z2", [e[:2] for e in EDGES])
def test_an_edge_optimum_is_the_top_of_its_edge_found_from_values_alone(z1, z2):
    r = gd.optimize_shifts(z1, z2, "max_margin")
    x_ref, t_ref = _edge_maximum(z1, z2, np.array([r.x1, r.x2]))
    assert np.abs(np.array([r.x1, r.x2]) - x_ref).max() <= 1e-8      # what r.accuracy states
    assert r.fun == pytest.approx(t_ref, abs=1e-13)
