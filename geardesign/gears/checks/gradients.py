"""Derivatives of the path-of-contact quantities with respect to the shifts, shared by the checks and
the objectives: ∂ρ_a, ∂N1N2, ∂ρ_p and the specific sliding's gradient."""
from __future__ import annotations

__all__ = ["sliding_root_gradient"]


def _other(gear: int) -> int:
    return 2 if gear == 1 else 1


def _drho_a(geo: dict, gear: int):
    """∂ρ_a/∂x1, ∂ρ_a/∂x2 of the tip radius of curvature ρ_a = √(r_a² − r_b²) of ``gear``.

    ∂ρ_a/∂r_a = r_a/ρ_a and ∂r_a/∂x_j = m(δ_gear,j − ∂Δy/∂x_Σ).
    """
    f = geo[f"_ra{gear}"] / geo[f"_rho_a{gear}"] * geo["_m"]
    own = f * (1.0 - geo["_dk"])
    other = -f * geo["_dk"]
    return (own, other) if gear == 1 else (other, own)


def _dg(geo: dict):
    """(∂N1N2/∂x1, ∂N1N2/∂x2) of N1N2 = a_w sin α_w: m sin α_t / sin²α_w per unit of x_Σ, where
    x_Σ = x1 + x2 (x2 − x1 for an internal pair, so ∂x_Σ/∂x1 = ``_sgn`` = −1)."""
    g = geo["_m"] * geo["_sa"] / geo["_sin_w"] ** 2
    return geo["_sgn"] * g, g


def _drho_p(geo: dict, gear: int):
    """(∂ρ_p/∂x1, ∂ρ_p/∂x2) at the start of the active profile of ``gear``: ρ_p1 = N1N2 − ρ_a2 and
    ρ_p2 = N1N2 − ρ_a1 externally; ρ_p1 = ρ_a2 − N1N2 and ρ_p2 = N1N2 + ρ_a1 for a ring pair."""
    sgn = geo["_sgn"]
    dm = _drho_a(geo, _other(gear))
    dn = _dg(geo)
    if gear == 1:
        return sgn * (dn[0] - dm[0]), sgn * (dn[1] - dm[1])
    return dn[0] - sgn * dm[0], dn[1] - sgn * dm[1]


def sliding_root_gradient(geo: dict, gear: int):
    """∂ϑ/∂x1, ∂ϑ/∂x2 of the specific sliding of ``gear`` at the start of its active profile.

    ϑ1 = 1 − ρ_a2/(u ρ_p1) and ϑ2 = 1 − u ρ_a1/ρ_p2 with ρ_p = N1N2 − ρ_a,mate and
    ∂N1N2/∂x_j = :func:`_dg`; the quotient rule on each.
    """
    o = _other(gear)
    rho_m, rho_p = geo[f"_rho_a{o}"], geo[f"rho_p{gear}"]
    u = geo["_z2"] / geo["_z1"]
    out = []
    for dm, dp in zip(_drho_a(geo, o), _drho_p(geo, gear)):
        if gear == 1:
            out.append(-(dm * rho_p - rho_m * dp) / (u * rho_p * rho_p))
        else:
            out.append(-u * (dm * rho_p - rho_m * dp) / (rho_p * rho_p))
    return tuple(out)
