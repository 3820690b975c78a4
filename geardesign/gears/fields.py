"""The fields of a pair's geometry: the reported ones with unit and meaning, and the internal ones the
checks, objectives and drawings read (the written contract of the geometry dict's keys: a test
holds every key read anywhere in the package to this table)."""
from __future__ import annotations

__all__ = ["GEOMETRY_FIELDS", "INTERNAL_FIELDS", "REPORT_FIELDS", "CONTACT_FIELDS", "TIP_FIELDS"]


# name -> (unit, description); the order is the order of reports.
GEOMETRY_FIELDS: dict[str, tuple[str, str]] = {
    "alpha_w_deg": ("deg", "transverse operating pressure angle α_w (α_wt)"),
    "inv_alpha_w": ("-", "involute of α_w"),
    "a": ("mm", "reference centre distance m_t(z1 + z2)/2 (internal: m_t(z2 − z1)/2)"),
    "a_w": ("mm", "operating centre distance"),
    "y": ("-", "centre distance modification coefficient (a_w − a)/m_n"),
    "dy": ("-", "tip shortening coefficient Δy = x_Σ − y (x_Σ = x1 + x2; internal x2 − x1)"),
    "d1": ("mm", "reference diameter, gear 1"),
    "d2": ("mm", "reference diameter, gear 2"),
    "db1": ("mm", "base diameter, gear 1"),
    "db2": ("mm", "base diameter, gear 2"),
    "dw1": ("mm", "operating pitch diameter, gear 1"),
    "dw2": ("mm", "operating pitch diameter, gear 2"),
    "da1": ("mm", "tip diameter, gear 1"),
    "da2": ("mm", "tip diameter, gear 2"),
    "df1": ("mm", "root diameter, gear 1"),
    "df2": ("mm", "root diameter, gear 2"),
    "s1": ("mm", "transverse tooth thickness on the reference circle, gear 1"),
    "s2": ("mm", "transverse tooth thickness on the reference circle, gear 2"),
    "sw1": ("mm", "tooth thickness on the operating pitch circle, gear 1"),
    "sw2": ("mm", "tooth thickness on the operating pitch circle, gear 2"),
    "sa1": ("mm", "tooth thickness on the tip circle, gear 1"),
    "sa2": ("mm", "tooth thickness on the tip circle, gear 2"),
    "p_b": ("mm", "transverse base pitch π m_t cos α_t"),
    "p_w": ("mm", "circular pitch on the operating pitch circle"),
    "g_alpha": ("mm", "length of the path of contact (active line of action)"),
    "eps_alpha": ("-", "transverse contact ratio g_α/p_b"),
    "alpha_a1_deg": ("deg", "pressure angle at the tip, gear 1"),
    "alpha_a2_deg": ("deg", "pressure angle at the tip, gear 2"),
    "clearance1": ("mm", "tip-to-root clearance at the tip of gear 1"),
    "clearance2": ("mm", "tip-to-root clearance at the tip of gear 2"),
    "x_min1": ("-", "smallest shift of gear 1 without undercut"),
    "x_min2": ("-", "smallest shift of gear 2 without undercut (NaN for a ring gear)"),
    "rho_l1": ("mm", "involute radius of curvature at the limit (form) point, gear 1; < 0 = undercut"),
    "rho_l2": ("mm", "involute radius of curvature at the limit (form) point, gear 2; < 0 = undercut"),
    "rho_p1": ("mm", "radius of curvature at the start of the active profile, gear 1"),
    "rho_p2": ("mm", "radius of curvature at the start of the active profile, gear 2"),
    "d_l1": ("mm", "limit (form) circle diameter d_Ff, gear 1 (base circle if undercut)"),
    "d_l2": ("mm", "limit (form) circle diameter d_Ff, gear 2 (base circle if undercut)"),
    "d_p1": ("mm", "start-of-active-profile diameter d_Nf, gear 1"),
    "d_p2": ("mm", "start-of-active-profile diameter d_Nf, gear 2"),
    "o2n1": ("mm", "distance O2N1 from gear 2's centre to gear 1's interference point"),
    "o1n2": ("mm", "distance O1N2 from gear 1's centre to gear 2's interference point"),
    "sliding1_root": ("-", "specific sliding of gear 1 at the start of its active profile"),
    "sliding1_tip": ("-", "specific sliding of gear 1 at its tip"),
    "sliding2_root": ("-", "specific sliding of gear 2 at the start of its active profile"),
    "sliding2_tip": ("-", "specific sliding of gear 2 at its tip"),
    "spec_pressure_pitch": ("-", "specific pressure coefficient m_n/ρ_red at the pitch point (normal section)"),
    "eps_beta": ("-", "overlap ratio ε_β = b sin β/(π m_n); 0 for spur pairs, NaN without a face width"),
    "eps_gamma": ("-", "total contact ratio ε_γ = ε_α + ε_β (NaN when ε_β is)"),
    "san1": ("mm", "tooth thickness on the tip cylinder in the normal section, gear 1 (= sa1 for spur)"),
    "san2": ("mm", "tooth thickness on the tip cylinder in the normal section, gear 2 (= sa2 for spur)"),
    "alpha_t_deg": ("deg", "transverse pressure angle α_t = atan(tan α_n / cos β)"),
    "beta_b_deg": ("deg", "base helix angle β_b"),
    "m_t": ("mm", "transverse module m_n / cos β"),
    "z_n1": ("-", "virtual tooth count z/(cos²β_b cos β), gear 1"),
    "z_n2": ("-", "virtual tooth count z/(cos²β_b cos β), gear 2"),
}


# Fields that no check or objective of the library needs: computed only when asked for.
REPORT_FIELDS = frozenset({"alpha_w_deg", "s1", "s2", "sw1", "sw2", "p_w", "alpha_a1_deg", "alpha_a2_deg", "clearance1",
                           "clearance2", "d_l1", "d_l2", "d_p1", "d_p2", "o2n1", "o1n2", "sliding1_tip",
                           "sliding2_tip", "alpha_t_deg", "beta_b_deg", "m_t", "z_n1", "z_n2"})


# Fields of the path of contact: computed unless only fields without them are asked for
CONTACT_FIELDS = frozenset({"p_b", "g_alpha", "eps_alpha", "rho_p1", "rho_p2", "sliding1_root", "sliding2_root",
                            "spec_pressure_pitch", "eps_gamma"})


# Fields of the tooth tips (their thicknesses) and of the ends of the path of contact: computed unless only fields
# without them (and the validation's) are asked for, as the strength chain's geometry is
TIP_FIELDS = frozenset({"sa1", "sa2", "san1", "san2", "_t_a1", "_t_a2", "_inv_a1", "_inv_a2", "rho_p1", "rho_p2",
                        "sliding1_root", "sliding2_root", "spec_pressure_pitch", "eps_gamma"})


# name -> meaning (units: lengths mm, angles rad, the rest dimensionless). Not reported; the checks'
# gradients, the objectives and the drawings read them from the dict of :func:`mesh_geometry`.
INTERNAL_FIELDS: dict[str, str] = {
    "_m": "normal module m_n (mm)",
    "_face_width_mm": "face width per design (mm), set by a drive's sizing grid for its load checks (absent elsewhere)",
    "_z1": "tooth count of gear 1", "_z2": "tooth count of gear 2",
    "_x1": "profile shift coefficient of gear 1", "_x2": "profile shift coefficient of gear 2",
    "_sgn": "∂x_Σ/∂x1: +1 for an external pair, −1 for an internal one (x_Σ = x2 − x1)",
    "_sa": "sin α_t", "_ta": "tan α_t", "_tn": "tan α_n", "_tan_beta": "tan β",
    "_sin_w": "sin α_wt", "_cos_w": "cos α_wt", "_t_w": "tan α_wt",
    "_k": "tip shortening in modules (Δy with tip shortening of an external pair, else 0)",
    "_dk": "∂Δy/∂x_Σ = 1 − sin α_t/sin α_wt with tip shortening of an external pair, else 0",
    "_ra1": "tip radius r_a1 (mm)", "_ra2": "tip radius r_a2 (mm)",
    "_rho_a1": "radius of curvature at the tip ρ_a1 = √(r_a1² − r_b1²) (mm)",
    "_rho_a2": "radius of curvature at the tip ρ_a2 = √(r_a2² − r_b2²) (mm)",
    "_t_a1": "tan α_a1 at the tip of gear 1", "_t_a2": "tan α_a2 at the tip of gear 2",
    "_inv_a1": "inv α_a1", "_inv_a2": "inv α_a2",
    "_psi1": "s/d + inv α_t of gear 1 (a tooth's half angle on the base circle)",
    "_psi2": "s/d + inv α_t of gear 2 (a ring: s/d − inv α_t)",
    "_gap1": "r_a1 − r_b1 (mm): > 0 where the tip lies outside the base circle",
    "_gap2": "r_a2 − r_b2 (mm)",
    "_mesh": "the Mesh the geometry was computed for (rack, helix angle, kind, face width)",
    "_strength": "memo of the strength checks' safety factors of this design by load case",
    "_damage": "memo of the damage checks' Miner sums of this design by load case (gears/checks/damage.py)",
    "_cutting_meshes": "memo of the cutter–ring meshes of this design by cutter (the ring checks add it)",
}
