"""The two-view figure (:func:`analysis.app.plotting.plot_views`, notebook 12's replay): one
scale in each view, no panel squeezed into a strip, no tick labels running into each other."""

from __future__ import annotations

import itertools

import matplotlib.pyplot as plt
import numpy as np

from analysis.app.plotting import plot_views, style


def _tick_boxes(fig, ax):
    renderer = fig.canvas.get_renderer()
    out = []
    for axis in (ax.xaxis, ax.yaxis):
        boxes = [
            t.get_window_extent(renderer)
            for t in axis.get_ticklabels()
            if t.get_visible() and t.get_text()
        ]
        out.append(boxes)
    return out


def test_two_views_keep_one_scale_fill_the_height_and_ticks_apart():
    # spans as in notebook 12's replay: x 620 mm, y 1850 mm (top view), z 650 mm
    t = np.linspace(0.0, 1.0, 50)[:, None]
    a = np.hstack([850 + 620 * t, -1800 + 1850 * t**2, 770 + 650 * t])
    b = a[:20] + np.array([5.0, 0.0, 0.0])
    with style():
        fig, axes = plot_views({"a": a, "b": b}, {"a": a[::10]})
        fig.canvas.draw()
        fig_h = fig.bbox.height
        for ax in axes:
            box = ax.get_window_extent()
            (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
            # the same mm per pixel along both axes (equal scale)
            assert abs((box.width / (x1 - x0)) / (box.height / (y1 - y0)) - 1) < 0.02
            assert box.height > 0.7 * fig_h, (ax.get_title(), box.height, fig_h)  # not squeezed
            for boxes in _tick_boxes(fig, ax):
                assert len(boxes) >= 3
                for p, q in itertools.combinations(boxes, 2):
                    assert not p.overlaps(q), (ax.get_title(), p, q)
        # both paths drawn, the first wider (paths that coincide stay visible)
        lines = [ln for ln in axes[0].get_lines() if ln.get_label() in "ab"]
        assert [ln.get_linewidth() for ln in lines] == [4.0, 1.5]
        plt.close(fig)
