"""Feasible region of the shifts: its boundary, area, membership, plots and size limits."""
import numpy as np
import pytest

import geardesign as gd
from geardesign import checks as ck
from geardesign.gears.geometry import mesh_geometry
from geardesign.gears.mesh import Mesh


def test_region_boundary_lies_on_the_named_checks():
    reg = gd.feasible_region(17, 26)
    assert reg.feasible
    b = reg.boundary
    prob = reg.problem
    M = prob.margins(prob.geo(b.x1.to_numpy(), b.x2.to_numpy()))
    for i, name in enumerate(b.check):
        # every vertex sits on the curve of the check that limits its edge, and holds the others
        assert abs(M[prob.names.index(name), i]) < 1e-10 or abs(M[:, i].min()) < 1e-10
        assert M[:, i].min() > -1e-10


def test_region_area_matches_a_fine_grid_count():
    reg = gd.feasible_region(17, 26)
    g = np.linspace(-1.5, 3.0, 1201)
    X1, X2 = np.meshgrid(g, g)
    inside = reg.contains(X1, X2)
    # independent: cell count on a fine grid (error ~ perimeter × cell ≈ 1e-2 relative)
    area_count = inside.sum() * (g[1] - g[0]) ** 2
    assert reg.area == pytest.approx(area_count, rel=1e-2)


def test_region_contains_agrees_with_pair_checks():
    reg = gd.feasible_region(20, 45)
    rng = np.random.default_rng(3)
    pts = rng.uniform(-1.0, 2.0, (300, 2))
    inside = reg.contains(pts[:, 0], pts[:, 1])
    for (x1, x2), ins in zip(pts, inside):
        try:
            ok = gd.GearPair(1, 20, 45, x1, x2).checks(jamming=False)["ok"].all()
        except gd.GearDesignError:
            ok = False
        assert ok == ins


def test_region_checks_can_be_dropped_and_changed():
    base = gd.feasible_region(17, 26)
    loose = gd.feasible_region(17, 26, checks={"undercut": False, "eps_alpha_min": 1.1})
    assert loose.area > base.area
    assert "undercut1" not in loose.checks
    hard = gd.feasible_region(17, 26, checks={"sa_min": 0.4})
    assert hard.area < base.area


def test_empty_region_names_a_conflict():
    reg = gd.feasible_region(5, 5)
    assert not reg.feasible and reg.area == 0.0
    assert set(reg.conflict) <= set(reg.checks) and reg.conflict
    # that set alone admits no point of a fine grid
    sub = [c for c in ck.make_checks() if c.name in reg.conflict]
    g = np.linspace(-1.5, 3.0, 301)
    X1, X2 = np.meshgrid(g, g)
    geo = mesh_geometry(Mesh(5, 5, gd.BasicRack(), True), 1.0, X1, X2)
    assert not np.all([np.nan_to_num(c.margin(geo), nan=-1) >= 0 for c in sub], axis=0).any()


def test_region_plot(tmp_path):
    import matplotlib
    matplotlib.use("Agg")
    from matplotlib.colors import to_hex

    reg = gd.feasible_region(17, 26)
    ax = reg.plot(optimum=gd.optimize_shifts(17, 26), proposed=(0.898, 0.517), x_sum=1.0)
    leg = ax.get_legend()
    labels = [t.get_text() for t in leg.get_texts()]
    # each check by its name and what it asks, with the limit (issue 28, item 9)
    assert "contact_ratio: ε_α ≥ 1.2" in labels and "tip_thickness2: s_a2/m ≥ 0.25" in labels
    assert "feasible" in labels and "m = 1 mm" in ax.get_title()
    assert any(t.startswith("optimum (0.360, 0.977)") for t in labels)
    assert any(t.startswith("proposed (0.898, 0.517): fails") for t in labels)   # ε_α 1.153 < 1.2
    assert any(t.startswith("a_w = ") and "x1 + x2 = 1" in t for t in labels)
    # one colour per check, the same in every plot
    name = lambda t: t.get_text().split(":")[0]   # noqa: E731
    colours = {name(t): to_hex(h.get_color()) for t, h in zip(leg.get_texts(), leg.legend_handles)
               if name(t) in reg.problem.names}
    assert len(colours) >= 4
    other = gd.feasible_region(12, 31).plot().get_legend()
    for t, h in zip(other.get_texts(), other.legend_handles):
        if name(t) in colours:
            assert to_hex(h.get_color()) == colours[name(t)]
    ax.figure.savefig(tmp_path / "c.png")
    assert (tmp_path / "c.png").stat().st_size > 10_000


def test_empty_region_plot_says_so():
    import matplotlib
    matplotlib.use("Agg")
    reg = gd.feasible_region(5, 5)
    assert not reg.feasible
    texts = [t.get_text() for t in reg.plot().texts]
    assert any("no feasible x1, x2" in t and all(c in t for c in reg.conflict) for t in texts)


@pytest.mark.slow
def test_thin_region_is_found_and_its_area_is_honest():
    # 8/44: a sliver ~0.02 wide that no node of the default grid falls in, yet the optimum is
    # feasible there; the area agrees with a 1601-node trace within the stated error
    reg = gd.feasible_region(8, 44)
    r = gd.optimize_shifts(8, 44)
    assert r.success and reg.feasible and bool(reg.contains(r.x1, r.x2) or min(r.margins.values()) >= -1e-9)
    fine = gd.feasible_region(8, 44, n=1601)
    assert abs(reg.area - fine.area) <= reg.area_error + 1e-12


@pytest.mark.slow
@pytest.mark.parametrize("z1,z2", [(33, 123), (17, 26), (40, 120)])
def test_area_within_its_stated_error(z1, z2):
    """Against an independent count: the fraction of a fine grid's cell centres where every
    check holds (error ~ perimeter × cell size), within the region's stated error plus that."""
    reg = gd.feasible_region(z1, z2)
    n = 3000
    h = 4.5 / n
    g = -1.5 + h * (np.arange(n) + 0.5)
    inside = 0
    for rows in np.array_split(g, 30):
        X1, X2 = np.meshgrid(rows, g, indexing="ij")
        with np.errstate(all="ignore"):
            geo = mesh_geometry(Mesh(z1, z2, gd.BasicRack(), True), 1.0, X1, X2)
            ok = np.ones(X1.shape, bool)
            for c in ck.make_checks():
                ok &= np.nan_to_num(c.margin(geo), nan=-1) >= 0
        inside += int(ok.sum())
    counted = inside * h * h
    perimeter = float(np.hypot(*np.diff(reg.boundary[["x1", "x2"]].to_numpy(), axis=0).T).sum())
    assert abs(reg.area - counted) <= reg.area_error + perimeter * h


def test_region_sizes_are_bounded_up_front():
    with pytest.raises(gd.GearDesignError, match=r"n must be .* \[11, 2001\]"):
        gd.feasible_region(17, 26, n=10**5)
    reg = gd.feasible_region(17, 26, checks=[])
    # with every check dropped the region is where the pair exists and meshes (issue 29 §3.1): the
    # window less its corner of large shifts whose tips no longer overlap on the line of action
    g = np.linspace(-1.5, 3.0, 601)
    X1, X2 = np.meshgrid(g, g, indexing="ij")
    with np.errstate(all="ignore"):
        eps = mesh_geometry(Mesh(17, 26, gd.BasicRack(), True), 1.0, X1, X2)["eps_alpha"]
    counted = float(np.mean(np.nan_to_num(eps, nan=-1.0) >= 1e-3)) * 4.5 ** 2
    assert reg.feasible and 15.0 < reg.area < 4.5 ** 2
    assert reg.area == pytest.approx(counted, abs=reg.area_error + 4 * 4.5 * (g[1] - g[0]))


def test_contains_on_a_helical_ring_pair_is_quiet():
    """Issue 29 §3.13: contains(0.5, 0.5) of a helical internal region warned 'invalid value in sqrt':
    the cutter–ring mesh took its one-design float path with cos β a 0-d array (numpy scalars)."""
    import warnings
    reg = gd.feasible_region(7, 11, beta_deg=15.0, internal=True)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        inside = reg.contains(0.5, 0.5)
    # the ring's tip is inside its base circle there (a failing margin), so the point is outside
    assert not inside
    with pytest.raises(gd.GearDesignError, match="inside its base circle"):
        gd.GearPair(1, 7, 11, 0.5, 0.5, beta_deg=15.0, internal=True)


def test_planetary_checks_look_apart():
    # issue 28 item 9: three planet-ring checks were one dark red, dashed; now no two checks of a
    # set share both colour and line style
    from matplotlib.colors import to_hex
    from geardesign.shifts.region import check_style

    reg = gd.planetary_region(21, 43, 108, 3, 1.75, n=61, method="grid")
    looks = [(to_hex(check_style(n)[0]), check_style(n)[1]) for n in reg.problem.names]
    assert len(set(looks)) == len(looks)
