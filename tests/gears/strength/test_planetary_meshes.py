"""The meshes of a planetary set under load (geardesign.gears.strength.planetary_meshes): the torque and the
speeds relative to the carrier by Willis' equation, written out here, and each mesh's strength equal to the
pair's own strength at that load."""
import numpy as np
import pytest

from geardesign.errors import GearDesignError
from geardesign.gears.planetary import PlanetarySet
from geardesign.gears.strength import Load, pair_strength
from geardesign.gears.spectrum import LoadSpectrum
from geardesign.gears.strength.planetary_meshes import mesh_loads, planetary_life, planetary_strength


@pytest.mark.parametrize("zs, zp, zr, n, arrangement", [(20, 31, 82, 3, "ring_fixed"), (21, 43, 108, 3, "ring_fixed"),
                                                       (18, 27, 72, 4, "carrier_fixed")])
def test_mesh_loads_by_willis(zs, zp, zr, n, arrangement):
    t_sun, n_sun = 300.0, 1020.0
    # Willis: (n_s − n_c)/(n_r − n_c) = −z_r/z_s; with the ring held, n_c = n_s z_s/(z_s + z_r)
    n_c = n_sun * zs / (zs + zr) if arrangement == "ring_fixed" else 0.0
    sp, pr = mesh_loads(zs, zp, zr, n, arrangement, Load(torque_nm=t_sun, n_rpm=n_sun, life_h=1000)).values()
    assert sp[0].torque_nm == pytest.approx(t_sun / n, rel=1e-15)            # the planets share the torque
    assert sp[0].n_rpm == pytest.approx(n_sun - n_c, rel=1e-15)
    # the planet: the same tangential force, so T_p = T_s z_p/z_s per planet, at (n_s − n_c) z_s/z_p
    assert pr[0].torque_nm == pytest.approx(t_sun / n * zp / zs, rel=1e-15)
    assert pr[0].n_rpm == pytest.approx((n_sun - n_c) * zs / zp, rel=1e-15)
    assert sp[1] == (n, 1) and pr[1] == (1, n)      # a sun tooth meets n planets, a ring tooth n planets
    assert sp[0].power_kw == pytest.approx(pr[0].power_kw, rel=1e-14)   # one mesh's power through the planet


def test_each_mesh_is_the_pairs_own_strength():
    s = PlanetarySet.coaxial(2, 20, 31, 82, 3)
    load = Load(torque_nm=100, n_rpm=1500, life_h=10_000)
    got = planetary_strength(s, load, "18CrNiMo7-6", face_width_mm=25)
    sp, pr = mesh_loads(20, 31, 82, 3, "ring_fixed", load).values()
    common = dict(beta_deg=s.beta_deg, rack=s.rack, tip_shortening=False, face_width_mm=25, material1="18CrNiMo7-6")
    own_sp = pair_strength(2, 20, 31, s.x_sun, s.x_planet, load=sp[0], cycles_per_rev=sp[1], **common)
    own_pr = pair_strength(2, 31, 82, s.x_planet, s.x_ring, load=pr[0], cycles_per_rev=pr[1], internal=True, **common)
    for key in ("S_H1", "S_H2", "S_F1", "S_F2"):
        assert getattr(got["sun-planet"], key) == pytest.approx(float(own_sp[key]), rel=1e-12)
        assert getattr(got["planet-ring"], key) == pytest.approx(float(own_pr[key]), rel=1e-12)


@pytest.mark.parametrize("call, words", [
    (lambda s, ld: mesh_loads(20, 31, 82, 3, "sun_fixed", ld), "arrangement"),
    (lambda s, ld: mesh_loads(20, 31, 82, 3, "ring_fixed", Load(torque_nm=10, n_rpm=100, on_gear=2)), "on_gear=1"),
    (lambda s, ld: planetary_strength(s, ld, None, face_width_mm=25), "material"),
    (lambda s, ld: planetary_strength(s, ld, "18CrNiMo7-6", face_width_mm=25, beta_deg=10), "beta_deg"),
])
def test_refusals_name_the_input(call, words):
    with pytest.raises(GearDesignError, match=words):
        call(PlanetarySet.coaxial(2, 20, 31, 82, 3), Load(torque_nm=100, n_rpm=1500))


# ---- a load spectrum on the sun: each mesh's damage checks (ISO 6336-6) ----------------------------------------
def test_a_one_bin_spectrum_gives_each_mesh_the_life_its_strength_has():
    """A one-bin spectrum on the sun: the set's damage checks give each gear's life L = t/D; planetary_strength with
    that required life (its own route: the torque shared over the planets, the speeds relative to the carrier,
    a sun tooth meeting 3 planets a turn, Z_NT at the life's cycles) finds S_H = 1 there."""
    import geardesign as gd

    s = PlanetarySet.coaxial(2, 20, 31, 82, 3, 0.3, 0.1)
    spec = gd.LoadSpectrum.from_bins([40.0], 1500, time_h=[10000.0])
    t = s.checks({"spectrum": spec, "material": "42CrMo4", "face_width_mm": 25.0, "mean_stress_factor": 0.7}
                 ).set_index("check")["value"]
    for gear, name in ((1, "sun-planet:pitting_damage_sun"), (2, "sun-planet:pitting_damage_planet")):
        D = float(t[name])
        assert 1.0 < D < 1e4
        r = planetary_strength(s, Load(torque_nm=40, n_rpm=1500, life_h=10000.0 / D), "42CrMo4", face_width_mm=25)
        assert getattr(r["sun-planet"], f"S_H{gear}") == pytest.approx(1.0, rel=1e-6), name


def test_mesh_spectra_refuse_what_a_set_cannot_take():
    import numpy as np

    import geardesign as gd
    from geardesign.gears.strength.planetary_meshes import mesh_spectra

    phi = np.linspace(0, 360, 361)
    curve = gd.LoadSpectrum.from_curve(100 + 0 * phi, angle_deg=phi, n_rpm=1000, teeth=(20, 31))
    with pytest.raises(GearDesignError, match="a spectrum counted per tooth belongs to the pair"):
        mesh_spectra(20, 31, 82, 3, "ring_fixed", curve)
    with pytest.raises(GearDesignError, match="given on the sun"):
        mesh_spectra(20, 31, 82, 3, "ring_fixed", gd.LoadSpectrum.from_bins([10.0], 100, time_h=[1.0], on_gear=2))


# ---- the planet over both its meshes (ISO 6336-6 per flank; alternating bending of its root) -----------------------
@pytest.mark.parametrize("torques, life_h", [([600.0, 450.0, 250.0], None), ([600.0, -450.0, 250.0], None),
                                             ([-600.0, 450.0, -250.0], 25000.0)])
def test_the_planets_damage_sums_both_meshes_per_flank(torques, life_h):
    """The planet is an idler between sun and ring: written out here, bin by bin, each mesh's chain stresses (the
    pair's own strength at the mesh's load, life factor 1), the planet's load cycles (one per revolution relative to
    the carrier in each mesh: 60·t·(n_s − n_c)·z_s/z_p), N on the S-N curve of cycles_to_failure (root: the limit
    times Y_M = 0.7, its tooth bends both ways) and Miner's sums per flank: flank A takes the sun mesh's positive
    bins and the ring mesh's negative ones, flank B the others."""
    from geardesign.gears.strength.service_life import cycles_to_failure, life_curve

    zs, zp, zr, n_pl = 20, 31, 82, 3
    s = PlanetarySet.coaxial(2, zs, zp, zr, n_pl)
    hours, n_sun, y_m = [2000.0, 5000.0, 3000.0], 1500.0, 0.7
    spec = LoadSpectrum.from_bins(torques, n_sun, time_h=hours)
    got = planetary_life(s, spec, "18CrNiMo7-6", face_width_mm=25.0, mean_stress_factor=y_m, life_h=life_h)
    repeat = 1.0 if life_h is None else life_h / sum(hours)       # the spectrum repeated over the required life
    n_rel = n_sun - n_sun * zs / (zs + zr)               # Willis, ring held
    common = dict(beta_deg=0.0, rack=s.rack, tip_shortening=False, face_width_mm=25.0, material1="18CrNiMo7-6")
    curve = {"H": life_curve("H", "Eh"), "F": life_curve("F", "Eh")}
    flanks = {"H": [0.0, 0.0], "F": [0.0, 0.0]}
    for T, t in zip(torques, hours):
        sp = pair_strength(2, zs, zp, s.x_sun, s.x_planet, load=Load(torque_nm=abs(T) / n_pl, n_rpm=n_rel),
                           cycles_per_rev=(n_pl, 1), **common)
        pr = pair_strength(2, zp, zr, s.x_planet, s.x_ring, internal=True, cycles_per_rev=(1, n_pl),
                           load=Load(torque_nm=abs(T) / n_pl * zp / zs, n_rpm=n_rel * zs / zp), **common)
        cycles = 60.0 * t * repeat * n_rel * zs / zp   # the planet's, in each mesh
        for mode in ("H", "F"):
            lim = y_m if mode == "F" else 1.0
            r_sp = float(sp[f"sigma_{mode}2"]) / (lim * float(sp[f"sigma_{mode}G2"]))
            r_pr = float(pr[f"sigma_{mode}1"]) / (lim * float(pr[f"sigma_{mode}G1"]))
            a, b = (0, 1) if T > 0 else (1, 0)
            flanks[mode][a] += cycles / float(cycles_to_failure(r_sp, curve[mode]))
            flanks[mode][b] += cycles / float(cycles_to_failure(r_pr, curve[mode]))
    for mode in ("H", "F"):
        assert got["planet_flanks"][mode] == pytest.approx(tuple(flanks[mode]), rel=1e-10)
        assert got[f"D_{mode}_planet"] == pytest.approx(max(flanks[mode]), rel=1e-10)
        assert got[f"life_h_{mode}_planet"] == pytest.approx((life_h or sum(hours)) / max(flanks[mode]), rel=1e-10)
    assert got["D_F_planet"] > 0.0 and min(got["planet_flanks"]["F"]) > 0.0    # both fillets are damaged here
    # a one-sided mesh check (no Y_M) rates the planet's root lighter: the gap the docs stated before
    one_sided = planetary_life(s, LoadSpectrum.from_bins(np.abs(torques), n_sun, time_h=hours), "18CrNiMo7-6",
                               face_width_mm=25.0, mean_stress_factor=1.0)
    if torques[1] > 0:
        assert one_sided["D_F_planet"] < got["D_F_planet"]


def test_planetary_life_refusals_name_the_input():
    s = PlanetarySet.coaxial(2, 20, 31, 82, 3)
    spec = LoadSpectrum.from_bins([300.0], 1500.0, time_h=[1000.0])
    with pytest.raises(GearDesignError, match="mean_stress_factor"):
        planetary_life(s, spec, "18CrNiMo7-6", face_width_mm=25.0, mean_stress_factor=None)
    with pytest.raises(GearDesignError, match="alternating"):
        planetary_life(s, spec, "18CrNiMo7-6", face_width_mm=25.0, mean_stress_factor=0.7, alternating=(1, 1))
    with pytest.raises(GearDesignError, match="material is needed"):
        planetary_life(s, spec, face_width_mm=25.0, mean_stress_factor=0.7)


def test_the_sets_damage_checks_bend_the_planets_root_both_ways():
    """The set's damage checks (the solvers' route): with a one-sided spectrum each mesh loads one flank of the planet,
    so each mesh's root check is one fillet's sum, planetary_life's (alternating: the limit times Y_M); without Y_M
    the checks are refused by name (the planet always bends both ways), and alternating is the set's, not the
    caller's."""
    s = PlanetarySet.coaxial(2, 20, 31, 82, 3)
    spec = LoadSpectrum.from_bins([600.0, 450.0, 250.0], 1500.0, time_h=[2000.0, 5000.0, 3000.0])
    case = {"spectrum": spec, "material": "18CrNiMo7-6", "face_width_mm": 25.0}
    t = s.checks({**case, "mean_stress_factor": 0.7}).set_index("check")["value"]
    want = planetary_life(s, spec, "18CrNiMo7-6", face_width_mm=25.0, mean_stress_factor=0.7)["planet_flanks"]
    assert float(t["sun-planet:root_damage_planet"]) == pytest.approx(want["F"][0], rel=1e-9)
    assert float(t["planet-ring:root_damage_planet"]) == pytest.approx(want["F"][1], rel=1e-9)
    assert float(t["sun-planet:pitting_damage_planet"]) == pytest.approx(want["H"][0], rel=1e-9)
    with pytest.raises(GearDesignError, match="gear 2's root bends both ways .*mean_stress_factor"):
        s.checks(case)
    with pytest.raises(GearDesignError, match="alternating is the set's own"):
        s.checks({**case, "mean_stress_factor": 0.7, "alternating": (False, False)})
