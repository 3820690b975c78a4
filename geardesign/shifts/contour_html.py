"""The blocking contour as an interactive page (plotly), for a browser and offline.

The same data as :meth:`Region.plot <geardesign.shifts.region.Region.plot>` draws on a PNG: every
check's zero curve in its fixed colour and dash with ticks on its forbidden side, the feasible
region, isolines of ε_α, the optimum, a proposed pair and the line of a fixed centre distance.
On top, a transparent grid over the whole window whose hover box gives, at the node nearest the
cursor, every check's margin, the quantities the checks read (ε_α, s_a/m, a_w) and the verdict.
Each check is one legend entry: a click hides or shows it. The file carries plotly.js, so it
opens without a network.
"""
from __future__ import annotations

import numpy as np

from ..errors import GearDesignError
from ..files import check_output_path, write_file_atomic
from ..validate import require_count
from .looks import check_legend, check_style

__all__ = ["contour_figure", "write_contour_html", "HOVER_N_MAX"]

HOVER_N_MAX = 301      # hover nodes per axis: 90 k nodes × (checks + 4) numbers, ~10 MB of page at most
_DASH = {"-": "solid", "--": "dash", "-.": "dashdot", ":": "dot"}
_EPS_LEVELS = (1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.8)


def _hex(colour) -> str:
    from matplotlib.colors import to_hex   # the colour table is in matplotlib's names
    return to_hex(colour)


def _lines(g, Z, level: float = 0.0) -> list:
    """The contour lines of Z (indexed [x2, x1] over g × g) at ``level``, NaN cells left out."""
    import contourpy

    gen = contourpy.contour_generator(x=g, y=g, z=np.ma.masked_invalid(Z), line_type=contourpy.LineType.Separate)
    return [np.asarray(L, dtype=float) for L in gen.lines(level) if len(L) >= 2]


def _joined(lines) -> tuple[list, list]:
    """Polylines as one x, y pair of lists separated by None (one trace, one legend entry)."""
    xs, ys = [], []
    for L in lines:
        xs += L[:, 0].tolist() + [None]
        ys += L[:, 1].tolist() + [None]
    return xs, ys


def _ticks(lines, g, Z, length: float, every: int = 7) -> tuple[list, list]:
    """Short strokes from every ``every``-th vertex toward the forbidden side (the margin's
    decreasing direction, from the grid's gradient at the nearest node)."""
    d2, d1 = np.gradient(np.where(np.isfinite(Z), Z, np.nan), g, g)
    xs, ys = [], []
    for L in lines:
        for x, y in L[::every]:
            i, j = int(np.abs(g - y).argmin()), int(np.abs(g - x).argmin())
            v = np.array([d1[i, j], d2[i, j]])
            nv = np.hypot(*v)
            if not (np.isfinite(nv) and nv > 0):
                continue
            xs += [x, x - length * v[0] / nv, None]
            ys += [y, y - length * v[1] / nv, None]
    return xs, ys


def _quantities(geo: dict) -> list:
    """(label, values) the hover box shows besides the margins: those the checks read."""
    m = geo["_m"]
    if isinstance(geo.get("sun-planet"), dict):      # a planetary set: both meshes
        out = [(f"ε_α {tag}", geo[tag]["eps_alpha"]) for tag in ("sun-planet", "planet-ring")]
        return out + [("x_ring", geo["x_ring"]), ("a_w, mm", geo["a_w"])]
    sa = ("san1", "san2") if "san1" in geo else ("sa1", "sa2")
    return [("ε_α", geo["eps_alpha"]), ("s_a1/m", geo[sa[0]] / m), ("s_a2/m", geo[sa[1]] / m),
            ("a_w, mm", geo["a_w"])]


def _hover_trace(region, g, M, geo):
    """A transparent heatmap over the window; its hover box lists every margin and quantity."""
    import plotly.graph_objects as go

    prob = region.problem
    quantities = _quantities(geo)
    cols = [M[k] for k in range(len(prob.names))] + [np.broadcast_to(v, M.shape[1:]) for _, v in quantities]
    data = np.stack(cols, axis=-1).astype(float)
    data = np.where(np.isfinite(data), np.round(data, 4), np.nan)
    custom = [[[None if v != v else float(v) for v in cell] for cell in row] for row in data]
    ok = np.isfinite(M).all(axis=0) & (M >= 0).all(axis=0) if M.size else np.ones(M.shape[1:], bool)
    lines = ["<b>x1 = %{x:.4f}, x2 = %{y:.4f}</b> (nearest grid node): %{text}"]
    lines += [f"{check_legend(c)}: margin %{{customdata[{k}]:+.4f}}" for k, c in enumerate(prob.checks)]
    lines += [f"{label} = %{{customdata[{len(prob.names) + j}]:.4g}}" for j, (label, _) in enumerate(quantities)]
    exists = np.isfinite(M).all(axis=0) if M.size else np.ones(M.shape[1:], bool)
    text = np.where(ok, "every check holds", np.where(exists, "fails", "no gear pair here (a tip or root past "
                                                                       "its base circle, or no contact)"))
    return go.Heatmap(x=g, y=g, z=np.where(ok, 1.0, 0.0), customdata=custom, text=text,
                      colorscale=[[0, "rgba(0,0,0,0)"], [1, "rgba(0,0,0,0)"]], showscale=False,
                      hovertemplate="<br>".join(lines) + "<extra></extra>", name="margins (hover)",
                      showlegend=False, hoverongaps=True)


def _check_traces(region, g, M, tick_len: float) -> list:
    import plotly.graph_objects as go

    out = []
    for k, c in enumerate(region.problem.checks):
        Z = M[k]
        if not (np.isfinite(Z).any() and np.nanmin(np.where(np.isfinite(Z), Z, np.nan)) < 0
                < np.nanmax(np.where(np.isfinite(Z), Z, np.nan))):
            continue    # no curve in the window (the PNG leaves it out too)
        colour, style = check_style(c.name)
        lines = _lines(g, np.where(np.isfinite(Z), Z, np.nan))
        xs, ys = _joined(lines)
        tx, ty = _ticks(lines, g, Z, tick_len)
        group = dict(legendgroup=c.name, hoverinfo="skip")
        out.append(go.Scatter(x=xs, y=ys, mode="lines", name=check_legend(c),
                              line=dict(color=_hex(colour), dash=_DASH.get(style, "solid"), width=2), **group))
        out.append(go.Scatter(x=tx, y=ty, mode="lines", showlegend=False, name=f"{c.name} (forbidden side)",
                              line=dict(color=_hex(colour), width=1.2), **group))
    return out


def _isoline_traces(g, geo, checks) -> list:
    """ε_α isolines, grey and dotted, labelled once each; one legend entry for all. A level at a
    contact-ratio check's limit is left to that check's curve."""
    import plotly.graph_objects as go

    limits = [c.limit for c in checks if c.name.split(":")[-1] == "contact_ratio"]

    eps = geo["eps_alpha"] if "eps_alpha" in geo else None
    if eps is None or np.ndim(eps) != 2:
        return []
    xs, ys, lx, ly, lt = [], [], [], [], []
    for level in (v for v in _EPS_LEVELS if all(abs(v - lim) > 1e-9 for lim in limits)):
        lines = _lines(g, eps, level)
        a, b = _joined(lines)
        xs += a
        ys += b
        if lines:
            L = max(lines, key=len)
            lx.append(float(L[len(L) // 2, 0]))
            ly.append(float(L[len(L) // 2, 1]))
            lt.append(f"ε={level:g}")
    group = dict(legendgroup="isolines", hoverinfo="skip")
    return [go.Scatter(x=xs, y=ys, mode="lines", name="isolines of ε_α", line=dict(color="#666", width=0.8, dash="dot"),
                       **group),
            go.Scatter(x=lx, y=ly, mode="text", text=lt, textfont=dict(size=10, color="#444"), showlegend=False,
                       **group)]


def _marks(region, optimum, proposed, x_sum) -> list:
    import plotly.graph_objects as go

    out = []
    if x_sum is not None:
        line = region.x_sum_line(float(x_sum))
        if line is not None:
            t, x2, inside, _, label = line
            out.append(go.Scatter(x=t, y=x2, mode="lines", name=label, legendgroup="a_w", hoverinfo="skip",
                                  line=dict(color="black", width=1, dash="dash")))
            out.append(go.Scatter(x=t, y=np.where(inside, x2, np.nan), mode="lines", legendgroup="a_w",
                                  name="its feasible part", hoverinfo="skip", line=dict(color="black", width=4)))
    if optimum is not None:
        ox, oy = (optimum.x1, optimum.x2) if hasattr(optimum, "x1") else optimum
        out.append(go.Scatter(x=[ox], y=[oy], mode="markers", name=f"optimum ({ox:.3f}, {oy:.3f})",
                              marker=dict(symbol="star", size=16, color="black")))
    if proposed is not None:
        px, py = proposed
        ok = bool(region.contains(px, py))
        out.append(go.Scatter(x=[px], y=[py], mode="markers",
                              name=f"proposed ({px:.3f}, {py:.3f}){'' if ok else ': fails'}",
                              marker=dict(symbol="x", size=14, color="#1f77b4" if ok else "#d62728",
                                          line=dict(color="white", width=1))))
    return out


def contour_figure(region, optimum=None, proposed=None, x_sum=None, n: int = 121):
    """The plotly Figure of a region's blocking contour (see the module docstring). ``n`` nodes
    per axis for the hover grid and the curves (11..HOVER_N_MAX); the marks as in
    :meth:`Region.plot <geardesign.shifts.region.Region.plot>`."""
    import plotly.graph_objects as go

    if not (hasattr(region, "problem") and hasattr(region, "bounds")):   # a Region (this module is below it)
        raise GearDesignError(f"region must be a geardesign Region, got {type(region).__name__}")
    n = require_count("n", n, 11, HOVER_N_MAX)
    prob = region.problem
    lo, hi = region.bounds
    g = np.linspace(lo, hi, n)
    X1, X2 = np.meshgrid(g, g)        # [x2, x1]: plotly's and contourpy's row-major order
    with np.errstate(all="ignore"):
        geo = prob.geo(X1, X2)
        M = prob.margins(geo)
    traces = [_hover_trace(region, g, M, geo)]
    if region.feasible:
        for comp, frame in region.boundary.groupby("component"):
            traces.append(go.Scatter(x=frame["x1"].tolist() + [frame["x1"].iloc[0]],
                                     y=frame["x2"].tolist() + [frame["x2"].iloc[0]], fill="toself",
                                     fillcolor="rgba(44,160,44,0.22)", line=dict(width=0), mode="lines",
                                     name="feasible region", legendgroup="feasible", showlegend=comp == 0,
                                     hoverinfo="skip"))
    traces += _check_traces(region, g, M, tick_len=(hi - lo) / 90)
    traces += _isoline_traces(g, geo, prob.checks)
    traces += _marks(region, optimum, proposed, x_sum)
    verdict = "" if region.feasible else (" — empty: checks " + ", ".join(region.conflict) + " conflict"
                                          if region.conflict else " — empty")
    fig = go.Figure(traces)
    fig.update_layout(
        title=dict(text=f"Blocking contour {prob.title}, m = {prob.m:g} mm{verdict}<br><sup>hover: every check's "
                        "margin (≥ 0 holds) at the nearest grid node; click a legend entry to hide or show it; "
                        "ticks on the forbidden side</sup>", x=0.01),
        xaxis=dict(title=prob.axis_labels[0], range=[lo, hi], constrain="domain", showgrid=True),
        yaxis=dict(title=prob.axis_labels[1], range=[lo, hi], scaleanchor="x", scaleratio=1, constrain="domain"),
        legend=dict(x=1.02, y=1.0, xanchor="left", font=dict(size=11)), hovermode="closest",
        plot_bgcolor="white", width=1200, height=760, margin=dict(l=70, r=20, t=80, b=60))
    fig.update_xaxes(gridcolor="#e5e5e5", zeroline=False, mirror=True, showline=True, linecolor="#444")
    fig.update_yaxes(gridcolor="#e5e5e5", zeroline=False, mirror=True, showline=True, linecolor="#444")
    return fig


def write_contour_html(region, path, optimum=None, proposed=None, x_sum=None, n: int = 121,
                       overwrite: bool = False):
    """Write the interactive contour to ``path`` (.html), plotly.js inside (works offline); the
    file appears whole or not at all, an existing one is replaced only with ``overwrite``."""
    p = check_output_path(path, overwrite=overwrite, suffixes=(".html", ".htm"), what="html file")
    fig = contour_figure(region, optimum, proposed, x_sum, n)
    write_file_atomic(p, lambda tmp: fig.write_html(tmp, include_plotlyjs=True, full_html=True,
                                                   config={"displaylogo": False, "responsive": True}))
    return p
