"""One figure style and one way to save figures (SVG + PNG, named after the notebook).

Plot helpers in this package follow ``plot_*(..., ax=None) -> Axes``: they draw on the
given (or a new) Axes, never call ``plt.show()``, never touch global ``rcParams`` and never
save. Notebooks and the report builder apply :func:`style` as a context manager and save
through :func:`save_figure`.
"""

from __future__ import annotations

import contextlib
import json
import os
from collections.abc import Iterator
from pathlib import Path

import matplotlib as mpl
import matplotlib.pyplot as plt
import numpy as np
import numpy.typing as npt

__all__ = [
    "DENSE",
    "STYLE",
    "cjk_fonts",
    "equal_axes_3d",
    "figure_dir",
    "plot_arm",
    "plot_views",
    "rasterize_dense",
    "save_figure",
    "style",
]

STYLE: dict[str, object] = {
    "figure.figsize": (6.4, 4.8),
    "figure.dpi": 100,
    "savefig.dpi": 150,
    "savefig.bbox": "tight",
    "font.size": 10,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "legend.frameon": False,
    "image.cmap": "viridis",
    "svg.hashsalt": "analysis",  # stable element ids in SVG output
    "svg.fonttype": "none",
}


def cjk_fonts() -> list[str]:
    """The font families with Chinese glyphs (the paper's 无解), for a text's
    ``fontfamily=["DejaVu Sans", *cjk_fonts()]`` fallback list: the bundled Noto Sans SC
    only (:func:`analysis.fonts.register_cjk_font`), never a system font, so the figure is
    the same on every machine."""
    from analysis.fonts import register_cjk_font

    return [register_cjk_font()]


def equal_axes_3d(ax, points: npt.ArrayLike, *, ticks: int = 5, pad: float = 0.05):
    """Give a 3D Axes one scale on x, y and z: a cube around ``points`` (..., 3) [mm],
    padded by ``pad`` of its side, with at most ``ticks`` ticks per axis (no overlapping
    labels). Returns ``ax``."""
    from matplotlib.ticker import MaxNLocator

    pts = np.asarray(points, dtype=float).reshape(-1, 3)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    half = (1 + 2 * pad) * (hi - lo).max() / 2
    mid = (lo + hi) / 2
    for k, setter in enumerate((ax.set_xlim, ax.set_ylim, ax.set_zlim)):
        setter(mid[k] - half, mid[k] + half)
    ax.set_box_aspect((1, 1, 1))
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.set_major_locator(MaxNLocator(ticks))
    return ax


@contextlib.contextmanager
def style() -> Iterator[None]:
    """Apply the project's figure style for the duration of a ``with`` block."""
    with mpl.rc_context(STYLE):
        yield


def figure_dir() -> Path:
    """Where figures go: ``$ANALYSIS_FIGURE_DIR`` or ``<project>/build/figures``."""
    env = os.environ.get("ANALYSIS_FIGURE_DIR")
    return Path(env) if env else Path(__file__).resolve().parents[3] / "build" / "figures"


def save_figure(
    fig: mpl.figure.Figure,
    stem: str,
    folder: str | Path | None = None,
    *,
    caption: str | None = None,
) -> list[str]:
    """Save ``fig`` as ``<stem>.svg`` and ``<stem>.png`` in ``folder`` (default :func:`figure_dir`).

    ``stem`` starts with the notebook number (``"05-workspace-xz"``). Returns the file
    names (not absolute paths, so notebook outputs do not depend on the machine).
    SVGs carry no date, so re-running a notebook reproduces them byte for byte; dense artists
    are embedded as pixels in them (:func:`rasterize_dense`), the rest stays vector; text
    stays text, with its glyphs embedded (subsets of DejaVu Sans and, for CJK text, of the
    bundled Noto Sans SC), so that the SVG looks the same without those fonts installed.

    ``caption`` (what the figure shows and in which units) is written to a sidecar
    ``<stem>.json`` (``{"stem": ..., "caption": ...}``) beside the images; the report site
    prints it under the figure (:mod:`analysis.app.site_content`). The returned names are
    the same with or without it, so printed notebook outputs do not change.
    """
    if not stem[:2].isdigit():
        raise ValueError(
            f"figure stem {stem!r} must start with the notebook number, e.g. '05-workspace'"
        )
    if caption is not None and not caption.strip():
        raise ValueError(f"figure {stem!r}: empty caption")
    out = Path(folder) if folder is not None else figure_dir()
    out.mkdir(parents=True, exist_ok=True)
    rasterize_dense(fig)
    names = []
    for ext, meta in (("svg", {"Date": None}), ("png", {"Software": None})):
        name = f"{stem}.{ext}"
        with mpl.rc_context({"svg.hashsalt": "analysis"}):
            fig.savefig(out / name, format=ext, metadata=meta)
        if ext == "svg":  # text stays text; its glyphs travel with it
            _embed_cjk(out / name)
        names.append(name)
    if caption is not None:
        side = {"stem": stem, "caption": " ".join(caption.split())}
        (out / f"{stem}.json").write_text(
            json.dumps(side, ensure_ascii=False, indent=1) + "\n", encoding="utf-8"
        )
    return names


def _embed_cjk(svg: Path) -> None:
    """Embed the glyphs of the text of ``svg`` (``svg.fonttype = "none"``: the text is kept as
    text, so a viewer would draw it with its own fonts, or as empty boxes where it has no CJK
    font): DejaVu Sans and, for CJK text, :data:`analysis.fonts.CJK_FAMILY`
    (:func:`analysis.app.webfont.embed_fonts`)."""
    from analysis.app.webfont import embed_fonts
    from analysis.fonts import CJK_FAMILY

    text = svg.read_text(encoding="utf-8")
    embedded = embed_fonts(text, CJK_FAMILY)
    if embedded != text:
        svg.write_text(embedded, encoding="utf-8")


DENSE = 2000
"""Points (markers or line vertices) above which an artist is drawn as pixels inside the SVG."""


def rasterize_dense(fig: mpl.figure.Figure, dense: int = DENSE) -> int:
    """Mark the dense artists of ``fig`` (scatter clouds, long lines, meshes and images) as
    rasterized: in the SVG they become one embedded image at ``savefig.dpi`` while axes, ticks,
    labels and legends stay vector. Without it a scatter of 60,000 points is a 9-13 MB SVG
    (the report site's budget is 25 MB). Returns how many artists were marked."""
    from matplotlib.collections import Collection, QuadMesh
    from matplotlib.image import AxesImage
    from matplotlib.lines import Line2D

    n = 0
    for ax in fig.axes:
        for a in ax.get_children():
            if isinstance(a, (QuadMesh, AxesImage)):
                big = True
            elif isinstance(a, Collection):
                n_path = sum(len(p.vertices) for p in a.get_paths())
                big = len(a.get_offsets()) > dense or n_path > dense
            elif isinstance(a, Line2D):
                big = len(a.get_xdata()) > dense
            else:
                big = False
            if big and not a.get_rasterized():
                a.set_rasterized(True)
                n += 1
    return n


def plot_arm(
    arm,
    q: npt.ArrayLike,
    *,
    ax: mpl.axes.Axes | None = None,
    target: npt.ArrayLike | None = None,
    label: str | None = None,
    color: str = "C0",
) -> mpl.axes.Axes:
    """Draw the arm as a 3D stick figure: base axis, waist, upper arm, forearm.

    Parameters
    ----------
    arm : analysis.kinematics.arm.Arm
    q : array_like, shape (3,)
        Joint angles [rad].
    ax : 3D Axes, optional
        Created (``projection="3d"``) if not given.
    target : array_like, shape (3,), optional
        Drawn as a cross, to show where the gripper should be.
    """
    if ax is None:
        ax = plt.figure().add_subplot(projection="3d")
    q = np.asarray(q, dtype=float)
    base = np.zeros(3)
    pts = np.array([base, arm.shoulder, arm.elbow(q), arm.fk(q)])
    ax.plot(*pts.T, "-o", color=color, lw=3, ms=5, label=label)
    ax.plot([0, 0], [0, 0], [0, arm.params.L1], color="0.4", lw=6, alpha=0.5)
    if target is not None:
        t = np.asarray(target, dtype=float)
        ax.scatter(*t, marker="x", s=80, color="C3", label="target")
    ax.set_xlabel("x [mm]", labelpad=16)  # clear of the tick labels
    ax.set_ylabel("y [mm]", labelpad=16)
    ax.set_zlabel("z [mm]", labelpad=16)
    reach = arm.geometry["reach_outer"]
    ax.set_xlim(-reach, reach)
    ax.set_ylim(-reach, reach)
    ax.set_zlim(0, arm.params.L1 + reach)
    ax.set_box_aspect((1, 1, (arm.params.L1 + reach) / (2 * reach)))
    from matplotlib.ticker import MaxNLocator

    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):  # few ticks: 3D tick labels crowd otherwise
        axis.set_major_locator(MaxNLocator(3))
    return ax


def plot_views(
    paths: dict[str, npt.ArrayLike],
    dots: dict[str, npt.ArrayLike] | None = None,
    *,
    height: float = 4.4,
    width: float = 7.4,
) -> tuple[mpl.figure.Figure, tuple]:
    """A top view (x, y) and a side view (x, z) of 3D paths [mm], at one scale in both
    directions of each view and each panel as wide as its data at the same height (a view
    whose y spans three times its x gets that share of the width, not a squeezed strip), with
    at most 4 ticks along x and 6 along the other axis (no labels running into each other).
    ``width`` [in]: no wider than the site's text column, where a wider figure is shrunk and
    its 10 pt text falls under the 9 pt the site's layout test asks for.

    ``paths`` {label: (n, 3) points}, drawn in turn, each narrower than the one before (paths
    that coincide stay visible); ``dots`` {label: (m, 3) points} marked with dots in the same
    colour. Returns the figure and its two axes (call under :func:`style`, then save)."""
    from matplotlib.ticker import MaxNLocator

    pts = {k: np.asarray(v, dtype=float).reshape(-1, 3) for k, v in paths.items()}
    marks = {k: np.asarray(v, dtype=float).reshape(-1, 3) for k, v in (dots or {}).items()}
    every = np.concatenate([*pts.values(), *marks.values()])
    span = np.maximum(np.ptp(every, axis=0), 1.0) * 1.1  # [mm], with a margin
    fig, axes = plt.subplots(
        1, 2, figsize=(width, height), layout="constrained",
        width_ratios=[span[0] / span[1], span[0] / span[2]],
    )  # fmt: skip
    widths = np.linspace(4.0, 1.5, len(pts)) if len(pts) > 1 else [1.5]
    for k, (label, p) in enumerate(pts.items()):
        colour = f"C{k}"
        for ax, v in zip(axes, (1, 2), strict=True):
            ax.plot(p[:, 0], p[:, v], color=colour, lw=widths[k], label=label)
            if label in marks:
                ax.plot(marks[label][:, 0], marks[label][:, v], "o", color=colour)
    for ax, v, title in zip(axes, "yz", ("top view", "side view"), strict=True):
        ax.set_xlabel("x [mm]")
        ax.set_ylabel(f"{v} [mm]")
        ax.set_title(title, fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")
        ax.xaxis.set_major_locator(MaxNLocator(nbins=4))
        ax.yaxis.set_major_locator(MaxNLocator(nbins=6))
    return fig, tuple(axes)
