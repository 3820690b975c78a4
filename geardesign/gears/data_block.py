"""The gear drawing's data block (ISO 1340:1976 "Cylindrical gears — information to be given to the manufacturer by
the purchaser"; GOST 2.403-75 "Rules for drawing cylindrical gears", its table in the upper right corner): a table
``parameter, symbol, value, unit`` in the standard's three parts — the gear (module, teeth, helix angle and hand,
basic rack, pressure angle, profile shift, accuracy), the control sizes (span over k teeth, dimension over balls
with the ball, chordal thickness and height, each with its deviations from the tooth-thickness allowances; the
ISO 1328-1:2013 flank tolerances of the class) and the reference data (the mating gear's teeth, the centre
distance, the reference diameter). Values are the drawing's text (mm to 4 decimals, deviations as
``nominal (upper / lower)``).
"""
from __future__ import annotations

from ..errors import GearDesignError
from ..validate import ndim, one_number, require_choice, require_int, require_range
from .measurement import pair_measurements
from .tolerances import flank_tolerances

__all__ = ["data_block", "data_block_lines", "HANDS"]

HANDS = ("right", "left")


def _mm(v) -> str:
    return f"{float(v):.4f}"


def _dev(nominal, upper, lower) -> str:
    """``nominal (+upper / +lower)`` with the deviations of the sizes from the nominal."""
    return f"{float(nominal):.4f} ({float(upper) - float(nominal):+.4f} / {float(lower) - float(nominal):+.4f})"


def data_block(pair, gear: int = 1, accuracy_class=None, *, helix_hand: str | None = None,
               thickness_allowance_mm=0.0, ball_mm=None, k=None, center_distance_allowance_mm=None):
    """The data block of gear 1 or 2 of a :class:`~geardesign.gears.pair.GearPair` as a DataFrame
    ``parameter, symbol, value, unit`` (see the module docstring).

    ``accuracy_class``: the ISO 1328-1:2013 flank tolerance class (1 … 11; None: not stated); ``helix_hand``:
    "right" or "left" for a helical gear (its mate has the other hand; an internal pair's the same);
    ``thickness_allowance_mm``: (A_sne, A_sni) of this gear; ``ball_mm``, ``k``: override the choices of
    :func:`~geardesign.gears.measurement.tooth_measurements`; ``center_distance_allowance_mm``: (A_ai, A_ae) to
    print with a_w.

    >>> from geardesign import GearPair
    >>> t = data_block(GearPair(3, 12, 24, 0.6, 0.36), 1, 7, thickness_allowance_mm=(-0.05, -0.1))
    >>> t.set_index("symbol").loc["W_k", "value"]
    '23.8765 (-0.0470 / -0.0940)'
    """
    import pandas as pd

    if not (type(gear) is int and gear in (1, 2)):
        raise GearDesignError(f"gear must be 1 or 2, got {gear!r}")
    if accuracy_class is not None:
        accuracy_class = int(one_number("accuracy_class", require_int(
            "accuracy_class (ISO 1328-1:2013 flank tolerance class)", accuracy_class, 1, 11)))
    for name, v in (("ball_mm", ball_mm), ("k", k)):
        if v is not None and ndim(v) != 0:
            raise GearDesignError(f"{name} must be one number for a data block, got {v!r}")
    if center_distance_allowance_mm is not None:
        if not (isinstance(center_distance_allowance_mm, (tuple, list)) and len(center_distance_allowance_mm) == 2):
            raise GearDesignError("center_distance_allowance_mm must be the pair (A_ai, A_ae) in mm, got "
                                  f"{center_distance_allowance_mm!r}")
        center_distance_allowance_mm = tuple(one_number("center_distance_allowance_mm", require_range(
            "center_distance_allowance_mm", v, -pair.m, pair.m, unit="mm")) for v in center_distance_allowance_mm)
    if pair.beta_deg > 0 and helix_hand is not None:
        helix_hand = require_choice("helix_hand", helix_hand, HANDS)
    elif helix_hand is not None:
        raise GearDesignError("helix_hand is for a helical gear: this pair is spur (beta_deg = 0)")
    t = pair_measurements(pair, gear, thickness_allowance_mm=thickness_allowance_mm, ball_mm=ball_mm, k=k)
    rows = (_gear_rows(pair, t, gear, accuracy_class, helix_hand) + _control_rows(t)
            + _tolerance_rows(pair, gear, accuracy_class) + _reference_rows(pair, gear, center_distance_allowance_mm))
    return pd.DataFrame(rows, columns=["parameter", "symbol", "value", "unit"])


def _gear_rows(pair, t, gear: int, accuracy_class, helix_hand) -> list:
    """Part 1: the gear itself."""
    rack = pair.rack
    rows = [("Module", "m_n", f"{pair.m:g}", "mm"), ("Number of teeth", "z", f"{pair.z1 if gear == 1 else pair.z2}", "")]
    rows.append(("Helix angle", "β", f"{pair.beta_deg:g}", "deg"))
    if pair.beta_deg:
        rows.append(("Hand of helix", "", helix_hand or "(state the hand)", ""))
    return rows + [
        ("Basic rack profile", "", f"ISO 53 / GOST 13755 (h_a* {rack.ha:g}, c* {rack.c:g}, ρ_f* {rack.rho_f:g})", ""),
        ("Normal pressure angle", "α_n", f"{rack.alpha_deg:g}", "deg"),
        ("Profile shift coefficient", "x", f"{t.x:.4f}" + (" (ring, GOST 19274 sign)" if t.internal else ""), ""),
        ("Accuracy", "", "—" if accuracy_class is None else f"ISO 1328-1:2013 class {accuracy_class}", "")]


def _control_rows(t) -> list:
    """Part 2: the control sizes with their deviations."""
    ring = t.internal
    return [
        ("Number of teeth spanned" + (" (spaces)" if ring else ""), "k", f"{int(t.k)}", ""),
        ("Base tangent length" + (" (not measurable: use M_d)" if ring else ""), "W_k", _dev(t.w_k, *_order(t, "w_k")), "mm"),
        ("Ball diameter", "D_M", _mm(t.ball_mm), "mm"),
        ("Dimension " + ("between" if ring else "over") + " balls", "M_d", _dev(t.m_d, *_order(t, "m_d")), "mm"),
        ("Chordal tooth thickness", "s̄_c", _dev(t.s_chord, *_order(t, "s_chord")), "mm"),
        ("Chordal height", "h̄_c", _mm(t.h_chord), "mm")]


def _tolerance_rows(pair, gear: int, accuracy_class) -> list:
    """Part 2 (cont.): the class's ISO 1328-1:2013 tolerances (the helix one with a face width of 4 mm or more)."""
    if accuracy_class is None:
        return []
    geo = pair.geometry()
    b = pair.face_width_mm if pair.face_width_mm is not None and pair.face_width_mm >= 4.0 else None
    tol = flank_tolerances(pair.m, pair.z1 if gear == 1 else pair.z2, accuracy_class, beta_deg=pair.beta_deg,
                           face_width_mm=b, d_mm=float(geo.d1 if gear == 1 else geo.d2))
    names = (("f_pT", "Single pitch tolerance"), ("F_pT", "Cumulative pitch tolerance"),
             ("F_alphaT", "Total profile tolerance"), ("F_betaT", "Total helix tolerance"))
    return [(name, sym, f"{getattr(tol, sym):g}", "µm") for sym, name in names if getattr(tol, sym) is not None]


def _reference_rows(pair, gear: int, allowance) -> list:
    """Part 3: the mating gear and the reference data."""
    geo = pair.geometry()
    a_w = float(geo.a_w)
    a_text = _mm(a_w) if allowance is None else f"{a_w:.4f} ({allowance[1]:+.4f} / {allowance[0]:+.4f})"
    return [("Mating gear: number of teeth", "z_mate", f"{pair.z2 if gear == 1 else pair.z1}", ""),
            ("Centre distance", "a_w", a_text, "mm"),
            ("Reference diameter", "d", _mm(geo.d1 if gear == 1 else geo.d2), "mm")]


def _order(t, name):
    """(the largest, the smallest) size the allowances give: the upper and lower deviations of the drawing."""
    return getattr(t, name + "_max"), getattr(t, name + "_min")


def data_block_lines(table) -> list[str]:
    """The data block as text lines ``parameter  symbol  value unit`` (for a drawing's text block)."""
    width = max(len(p) for p in table["parameter"])
    return [f"{p:<{width}}  {s:<8} {v} {u}".rstrip() for p, s, v, u in table.itertuples(index=False)]
