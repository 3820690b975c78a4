"""Results in a notebook: the text view with a picture inline (a PNG inside the HTML).

A result's ``_repr_html_`` hands its text and a function that draws on a matplotlib Axes to
:func:`html_view`; Jupyter shows the text and the picture together. The picture never stops the
view: if drawing fails, the text is shown with the reason.
"""
from __future__ import annotations

import base64
import html
import io

__all__ = ["figure_data_uri", "html_view"]

INLINE_DPI = 90      # a notebook cell's picture: ~700 px wide at the default sizes, ~60 kB
TEXT_LINES_MAX = 20


def figure_data_uri(fig, dpi: int = INLINE_DPI) -> str:
    """A matplotlib figure as a ``data:image/png;base64,...`` URL; the figure is closed."""
    import matplotlib.pyplot as plt

    buf = io.BytesIO()
    try:
        fig.savefig(buf, format="png", dpi=dpi, bbox_inches="tight")
    finally:
        plt.close(fig)
    return "data:image/png;base64," + base64.b64encode(buf.getvalue()).decode("ascii")


def html_view(text: str, draw=None, figsize=(7.5, 5.2), tables=(), alt: str = "picture", dpi: int = INLINE_DPI) -> str:
    """``text`` (preformatted), then each (caption, DataFrame) of ``tables``, then the picture that
    ``draw(ax)`` makes on a new Axes of ``figsize`` inches."""
    lines = text.splitlines()
    if len(lines) > TEXT_LINES_MAX:   # a picture says the rest; a text view is never a wall
        lines = lines[:TEXT_LINES_MAX] + [f"… ({len(lines) - TEXT_LINES_MAX} more lines)"]
    parts = [f"<pre style='margin:0 0 6px; white-space:pre-wrap'>{html.escape(chr(10).join(lines))}</pre>"]
    for caption, frame in tables:
        parts.append(f"<div><b>{html.escape(caption)}</b>{frame.to_html(index=False, float_format=_short)}</div>")
    if draw is not None:
        try:
            import matplotlib.pyplot as plt

            fig, ax = plt.subplots(figsize=figsize)
            try:
                draw(ax)
            except BaseException:
                plt.close(fig)
                raise
            parts.append(f"<img alt='{html.escape(alt)}' src='{figure_data_uri(fig, dpi)}' style='max-width:100%'>")
        except Exception as exc:     # the text view stands without the picture
            parts.append(f"<p><i>(no picture: {html.escape(str(exc))})</i></p>")
    return "<div>" + "".join(parts) + "</div>"


def _short(v) -> str:
    return f"{v:.6g}"
