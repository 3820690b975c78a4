"""The AGMA 6034-B92 worm rating (geardesign.gears.worm.agma) against Shigley's Example 15-4, every printed number
recomputed from the example's inputs in project units (tests/data/worm_agma_examples.md says where each comes
from); the branches of each factor; the rating's S_AGMA row and its load capacity; bad input."""
import csv
import math
from pathlib import Path

import numpy as np
import pytest

import geardesign as gd
from geardesign.errors import GearDesignError
from geardesign.gears.worm import agma
from geardesign.gears.worm import efficiency as eff
from geardesign.gears.worm.rating import load_capacity, mesh_forces, worm_rating

DATA = Path(__file__).resolve().parents[2] / "data" / "worm_agma_examples.csv"
IN = 25.4
HP = 745.69987158227022          # W per mechanical horsepower (550 ft·lbf/s)
FT_MIN = 0.3048 / 60.0           # m/s per ft/min
FT_LBF_MIN = 0.3048 * agma.N_PER_LBF / 60.0   # W per ft·lbf/min


def printed(symbol, example="15-4"):
    with open(DATA, encoding="utf-8") as f:
        for row in csv.DictReader(f):
            if row["example"] == example and row["symbol"] == symbol:
                return float(row["printed"])
    raise KeyError(symbol)


def digits(symbol):
    """The number of decimals the example prints for ``symbol``."""
    with open(DATA, encoding="utf-8") as f:
        for row in csv.DictReader(f):
            if row["example"] == "15-4" and row["symbol"] == symbol:
                text = row["printed"].lstrip("-")
                return len(text.split(".")[1]) if "." in text else 0
    raise KeyError(symbol)


def same(symbol, value):
    """``value`` equals the printed one to the printed digits (half a unit of the last digit)."""
    want = printed(symbol)
    assert abs(value - want) <= 0.5 * 10.0 ** -digits(symbol) + 1e-12, (symbol, value, want)


# Example 15-4 in project units: p_x = 1.5 in (m_x = p_x/π), d = 2.5 in (q = d/m_x), 2 threads, 22 teeth,
# α_n = 20° (φ_n of the book: the normal pressure angle, so a ZN worm), F_e = 1.5 in, 1720 rpm
M_X = printed("p_x") * IN / math.pi
Q = printed("d") * IN / M_X
N1 = printed("n_W")


@pytest.fixture(scope="module")
def pair():
    return gd.WormPair(M_X, 2, 22, Q, flank_form="ZN", face_width_mm=printed("F_e") * IN)


def test_example_15_4_geometry_and_speeds(pair):
    g = pair.geometry()
    same("D", g.d_2 / IN)
    same("C", g.a / IN)
    same("L", g.p_z / IN)
    same("lambda", g.gamma_m_deg)
    assert g.alpha_n_deg == 20.0
    v_s = eff.sliding_speed(g.d_m1, N1, g.gamma_m_deg)
    same("V_s", float(v_s) / FT_MIN)
    same("V_W", math.pi * g.d_m1 * N1 / 60000.0 / FT_MIN)
    same("V_G", math.pi * g.d_2 * N1 / printed("m_G") / 60000.0 / FT_MIN)


def test_example_15_4_factors_friction_and_efficiency(pair):
    g = pair.geometry()
    v_s = float(eff.sliding_speed(g.d_m1, N1, g.gamma_m_deg))
    same("C_s", float(agma.materials_factor(g.a, g.d_2, "sand")))
    same("C_m", float(agma.ratio_correction_factor(g.u)))
    same("C_v", float(agma.velocity_factor(v_s)))
    f = float(eff.friction_coefficient_agma(v_s))
    same("f", f)
    # the book's (cos φn − f tan λ)/(cos φn + f cot λ) is our tan γ/tan(γ + ρ'), tan ρ' = f/cos α_n
    same("e_W", float(eff.efficiency_worm_driving(g.gamma_m_deg, f, g.alpha_n_deg)))
    # wheel driving: the book evaluates it with its rounded f = 0.0191 and λ = 20.905° (0.93949; with the unrounded
    # f = 0.019072 it is 0.93957, which would print 0.940)
    same("e_G", float(eff.efficiency_wheel_driving(printed("lambda"), printed("f"), printed("phi_n"))))
    assert float(eff.efficiency_wheel_driving(g.gamma_m_deg, f, g.alpha_n_deg)) == pytest.approx(printed("e_G"), abs=1e-3)


def test_example_15_4_loads_powers_and_face_width(pair):
    g = pair.geometry()
    v_s = float(eff.sliding_speed(g.d_m1, N1, g.gamma_m_deg))
    f = float(eff.friction_coefficient_agma(v_s))
    e = float(eff.efficiency_worm_driving(g.gamma_m_deg, f, g.alpha_n_deg))
    # the output power's torque on the wheel: 10 hp at n_W/m_G
    T2 = printed("H_0") * HP / (N1 / printed("m_G") * math.pi / 30.0)
    W_G = float(agma.design_tangential_load(T2, g.d_2, e, printed("K_a"))) * printed("n_d")
    same("W_G^t", W_G / agma.N_PER_LBF)
    rho = float(eff.friction_angle_deg(f, g.alpha_n_deg))
    _, W_W, _ = mesh_forces(W_G * g.d_2 / 2000.0, g.d_2, g.gamma_m_deg, g.alpha_n_deg, rho)
    # the book carries its rounded W_G^t = 1222 lbf, f = 0.0191 and λ = 20.905° on: from those, to its digits
    W_G_book = printed("W_G^t") * agma.N_PER_LBF
    rho_book = float(eff.friction_angle_deg(printed("f"), printed("phi_n")))
    _, W_W_book, _ = mesh_forces(W_G_book * g.d_2 / 2000.0, g.d_2, printed("lambda"), printed("phi_n"), rho_book)
    same("W_W^t", float(W_W_book) / agma.N_PER_LBF)
    assert float(W_W) / agma.N_PER_LBF == pytest.approx(printed("W_W^t"), rel=2e-4)
    W_f = float(agma.friction_force(W_G, f, g.gamma_m_deg, g.alpha_n_deg))
    same("W_f", -W_f / agma.N_PER_LBF)           # the book prints it signed, negative
    # H_f from the printed |W_f| = 26.8 lbf and V_s (0.979 hp); from the unrounded 26.76 lbf it is 0.977 hp
    same("H_f", float(agma.friction_power(-printed("W_f") * agma.N_PER_LBF, printed("V_s") * FT_MIN)) / HP)
    assert float(agma.friction_power(W_f, v_s)) / HP == pytest.approx(printed("H_f"), rel=3e-3)
    same("H_W", float(W_W_book) * printed("V_W") * FT_MIN / HP)
    assert float(W_W) * math.pi * g.d_m1 * N1 / 60000.0 / HP == pytest.approx(printed("H_W"), rel=2e-3)
    same("H_G", W_G * math.pi * g.d_2 * N1 / printed("m_G") / 60000.0 / HP)
    C_s = agma.materials_factor(g.a, g.d_2, "sand")
    C_m, C_v = agma.ratio_correction_factor(g.u), agma.velocity_factor(v_s)
    # the book goes on with its rounded C_s, C_m, C_v (702.8, 0.772, 0.232) and W_G^t: from those, to its digits
    book = dict(C_s=printed("C_s"), d_2=printed("D") * IN, C_m=printed("C_m"), C_v=printed("C_v"))
    per_width = float(agma.allowable_tangential_load(F_e=IN, **book))                 # W_t,all of 1 in of face
    same("F_e_req", printed("W_G^t") * agma.N_PER_LBF / per_width)
    F_e = float(agma.effective_face_width(g.b_2, g.d_m1))
    assert F_e == pytest.approx(printed("F_e") * IN, rel=1e-15)
    same("W_t_all", float(agma.allowable_tangential_load(F_e=F_e, **book)) / agma.N_PER_LBF)
    # the unrounded chain: within 0.2 % of the printed numbers
    W_all = float(agma.allowable_tangential_load(C_s, g.d_2, F_e, C_m, C_v))
    assert W_all / agma.N_PER_LBF == pytest.approx(printed("W_t_all"), rel=2e-3)
    assert W_G / (W_all / F_e * IN) == pytest.approx(printed("F_e_req"), rel=2e-3)

def test_example_15_4_heat_balance(pair):
    g = pair.geometry()
    same("h_CR", float(agma.heat_transfer_coefficient_agma(N1)) / agma.HCR_SI_PER_US)
    same("A_min", float(agma.housing_area_min_agma(g.a)) / (IN / 1000.0) ** 2)
    # the book rounds e to 0.942 and H_W to 16.9 hp before the loss: its 32 347 ft·lbf/min is of those
    loss = float(agma.heat_loss(printed("H_W") * HP, printed("e_W")))
    same("H_loss", loss / FT_LBF_MIN)
    t_s = gd.gears.worm.temperature.oil_sump_temperature(
        loss, agma.heat_transfer_coefficient_agma(N1), printed("A") * (IN / 1000.0) ** 2, (printed("t_a") - 32) / 1.8)
    same("t_s", float(t_s) * 1.8 + 32)


def test_the_rating_carries_the_agma_row_and_its_safety(pair):
    T2 = printed("H_0") * HP / (N1 / printed("m_G") * math.pi / 30.0)
    r = pair.rating(T2, N1, casting="sand", application_factor=printed("K_a"), minimums={"S_AGMA": printed("n_d")})
    f = r.factors.set_index("symbol")
    assert f.loc["W_t_all", "value"] / agma.N_PER_LBF == pytest.approx(printed("W_t_all"), rel=2e-3)
    assert "Eq. 15-28" in f.loc["W_t_all", "method"] and "sand" in f.loc["C_s", "method"]
    # the book: 1239 lbf allowed against 1222 lbf with n_d = 1.2, "a little excess capacity"
    assert r.S_AGMA == pytest.approx(r.W_t_all / r.W_t, rel=1e-15)
    assert r.S_AGMA * 1.0 == pytest.approx(printed("W_t_all") / (printed("W_G^t") / printed("n_d")), rel=2e-3)
    assert r.margins["S_AGMA"] > 0 and r.ok
    cap = load_capacity(r)
    assert cap["S_AGMA"] == pytest.approx(T2 * r.S_AGMA / printed("n_d"), rel=1e-12)
    at_cap = pair.rating(cap["S_AGMA"], N1, casting="sand", application_factor=printed("K_a"), minimums={"S_AGMA": printed("n_d")})
    assert at_cap.margins["S_AGMA"] == pytest.approx(0.0, abs=1e-12)


def test_the_rating_takes_shigleys_cooling_and_agma_area(pair):
    r = pair.rating(500.0, N1, k_heat="agma", A_housing="agma_min")
    f = r.factors.set_index("symbol")
    assert f.loc["k_heat", "value"] == pytest.approx(float(agma.heat_transfer_coefficient_agma(N1)), rel=1e-15)
    assert f.loc["A_housing", "value"] == pytest.approx(float(agma.housing_area_min_agma(pair.geometry().a)), rel=1e-15)
    fan = pair.rating(500.0, N1, k_heat="agma_fan", A_housing="agma_min")
    assert fan.theta_S < r.theta_S
    with pytest.raises(GearDesignError, match="k_heat"):
        pair.rating(500.0, N1, k_heat="agmaa", A_housing=1.0)
    with pytest.raises(GearDesignError, match="A_housing"):
        pair.rating(500.0, N1, k_heat=20.0, A_housing="min")


def test_without_a_casting_the_agma_safety_is_not_computed_and_says_so():
    r = worm_rating(300.0, 1500.0, 4, 2, 40, 10.0)
    assert math.isnan(r.S_AGMA) and any("casting" in n for n in r.notes)
    r = worm_rating(300.0, 1500.0, 4, 2, 40, 10.0, casting="sand")       # no b_2
    assert math.isnan(r.S_AGMA) and any("face width" in n for n in r.notes)


def test_materials_factor_branches_meet_at_their_limits():
    # C <= 3 in: 720 + 10.37 C³ reaches 1000 at C = 3 in (the casting branches start at 1000)
    assert float(agma.materials_factor(3 * IN, 100.0)) == pytest.approx(720 + 10.37 * 27, rel=1e-15)
    for kind, d_lim, A, B in (("sand", 2.5, 1190, 477), ("chill", 8, 1412, 456), ("centrifugal", 25, 1251, 180)):
        D = np.array([d_lim * 0.99, d_lim, d_lim * 1.5]) * IN
        cs = agma.materials_factor(4 * IN, D, kind)
        assert cs[0] == cs[1] == 1000.0
        assert cs[2] == pytest.approx(A - B * math.log10(1.5 * d_lim), rel=1e-14)
    # the book's order: sand <= chill <= centrifugal at any size
    D = np.linspace(50, 2000, 50)
    s, c, z = (agma.materials_factor(200.0, D, k) for k in agma.CASTINGS)
    assert np.all(s <= c) and np.all(c <= z)


def test_ratio_and_velocity_factors_follow_their_branches():
    assert float(agma.ratio_correction_factor(30.0)) == pytest.approx(0.0107 * math.sqrt(-900 + 1680 + 5145), rel=1e-14)
    assert float(agma.ratio_correction_factor(100.0)) == pytest.approx(1.1483 - 0.658, rel=1e-14)
    for v_ft, want in ((500.0, 0.659 * math.exp(-0.55)), (2000.0, 13.31 * 2000 ** -0.571),
                       (4000.0, 65.52 * 4000 ** -0.774)):
        assert float(agma.velocity_factor(v_ft * FT_MIN)) == pytest.approx(want, rel=1e-12)


def test_capacity_over_arrays_is_the_scalar_chain():
    g = gd.gears.worm.geometry.worm_geometry(np.array([4.0, 5.0, 6.3]), 2, 40, 10.0)
    cap = agma.agma_capacity(g, 1450.0, "centrifugal", 1.25)
    for i, m in enumerate((4.0, 5.0, 6.3)):
        r = worm_rating(100.0, 1450.0, m, 2, 40, 10.0, b_2=float(g["b_2"][i]), casting="centrifugal", application_factor=1.25,
                        alpha_n_deg=float(g["alpha_n_deg"][i]))
        assert cap["W_t_all"][i] == pytest.approx(r.W_t_all, rel=1e-13)
        # T2_all is where S_AGMA = 1
        assert cap["T2_all"][i] == pytest.approx(100.0 * r.S_AGMA, rel=1e-12)


@pytest.mark.parametrize("call, word", [
    (lambda: agma.materials_factor(100.0, 200.0, "forged"), "casting"),
    (lambda: agma.ratio_correction_factor(2.5), "u (gear ratio)"),
    (lambda: agma.ratio_correction_factor(200.0), "u (gear ratio)"),
    (lambda: agma.velocity_factor(0.0), "v_g"),
    (lambda: agma.effective_face_width(-1.0, 50.0), "b_2"),
    (lambda: agma.heat_transfer_coefficient_agma(1500.0, fan="yes"), "fan"),
    (lambda: agma.design_tangential_load(100.0, 200.0, 0.9, 0.5), "K_A"),
    (lambda: agma.friction_force(1000.0, 1.0, 44.0, 20.0), "mu"),
    (lambda: worm_rating(300.0, 1500.0, 4, 4, 10, 10.0, b_2=30.0, casting="sand"), "u (gear ratio)"),   # u = 2.5
])
def test_bad_input_is_refused_by_name(call, word):
    with pytest.raises(GearDesignError, match=word.replace("(", r"\(").replace(")", r"\)")):
        call()


def test_the_torque_a_pair_carries_is_where_the_rating_reaches_its_minimum():
    p = gd.WormPair(4, 4, 50, 12.5)        # seed 002's ratio at a = 125 mm
    for casting in agma.CASTINGS:
        T = p.allowable_torque(1500.0, casting, application_factor=1.25)
        r = p.rating(T, 1500.0, casting=casting, application_factor=1.25)
        assert r.S_AGMA == pytest.approx(1.0, rel=1e-12)
    # chill and centrifugal share C_s = 1000 while D_m <= 8 in (d_2 = 200 mm): the same torque; sand-cast less
    assert p.allowable_torque(1500.0, "chill") == p.allowable_torque(1500.0, "centrifugal") > p.allowable_torque(1500.0)
    # slower, the velocity factor rises: more torque
    assert p.allowable_torque(500.0) > p.allowable_torque(1500.0)


# -- the one-design float path against the array functions ------------------------------------------------------
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


def _array_chain(a, d_2, d_m1, b_2, u, v_g, gamma, alpha, mu, T2, eta, casting, K_A):
    """The AGMA row from the public array functions, one after another as the rating chained them before."""
    C_s = agma.materials_factor(a, d_2, casting)
    C_m = agma.ratio_correction_factor(u)
    C_v = agma.velocity_factor(v_g)
    F_e = agma.effective_face_width(b_2, d_m1)
    F_t2 = mesh_forces(T2, d_2, gamma, alpha, 0.0)[0]
    W_f = agma.friction_force(F_t2, mu, gamma, alpha)
    return {"C_s": C_s, "C_m": C_m, "C_v": C_v, "F_e": F_e,
            "W_t_all": agma.allowable_tangential_load(C_s, d_2, F_e, C_m, C_v),
            "W_t": agma.design_tangential_load(T2, d_2, eta, K_A), "W_f": W_f, "P_f": agma.friction_power(W_f, v_g)}


@settings(max_examples=300, deadline=None)
@given(m_x=st.floats(0.5, 25.0), q=st.floats(5.0, 20.0), z1=st.integers(1, 4), u=st.floats(3.0, 170.0),
       x2=st.floats(-1.0, 1.0), b_ratio=st.floats(0.3, 1.5), v_g=st.floats(0.001, 40.0),
       alpha=st.floats(0.0, 30.0), mu=st.floats(0.0, 0.2), T2=st.floats(0.0, 1e5), eta=st.floats(0.3, 1.0),
       casting=st.sampled_from(agma.CASTINGS), K_A=st.floats(1.0, 3.0))
def test_the_float_path_is_the_array_path_on_random_designs(m_x, q, z1, u, x2, b_ratio, v_g, alpha, mu, T2, eta,
                                                            casting, K_A):
    """agma_load_float (math) and the public array functions (numpy) on one design agree to 1e-12 relative
    (they share the factors' code; numpy's and the C library's exp/log10/cos may differ by an ulp), and a design
    the array functions refuse the float path refuses by the same name."""
    z2 = z1 * u
    d_m1, d_2 = q * m_x, z2 * m_x
    a = (d_m1 + d_2) / 2.0 + x2 * m_x
    gamma = math.degrees(math.atan2(z1, q))
    args = (a, d_2, d_m1, b_ratio * d_m1, u, v_g, gamma, alpha, mu, T2, eta, casting, K_A)
    try:
        want = _array_chain(*args)
    except GearDesignError as refused:      # e.g. C_s <= 0 on a wheel of several metres: refused the same way
        with pytest.raises(GearDesignError, match=str(refused).split(" must ")[0]):
            agma.agma_load_float(*args)
        return
    got = agma.agma_load_float(*args)
    assert set(got) == set(agma.LOAD_FIELDS) and all(type(v) is float for v in got.values())
    for k in agma.LOAD_FIELDS:
        assert got[k] == pytest.approx(float(want[k]), rel=1e-12, abs=1e-300), k


@pytest.mark.parametrize("bad, word", [({"u": 2.0}, "u (gear ratio)"), ({"v_g": 0.0}, "v_g"),
                                       ({"casting": "die"}, "casting"), ({"mu": 2.0}, "mu"),
                                       ({"application_factor": 0.5}, "application_factor"),
                                       ({"T2": math.nan}, "T2"), ({"a": -1.0}, "a (center distance)")])
def test_the_float_path_refuses_what_the_array_functions_refuse(bad, word):
    kw = dict(a=160.0, d_2=250.0, d_m1=62.5, b_2=45.0, u=12.5, v_g=5.0, gamma_m_deg=17.7, alpha_n_deg=20.0,
              mu=0.03, T2=800.0, eta=0.9, casting="sand", application_factor=1.0) | bad
    with pytest.raises(GearDesignError, match=word.replace("(", r"\(").replace(")", r"\)")):
        agma.agma_load_float(**kw)
