"""What the explorer's 3D view shows, read two ways, for the browser tests.

* :func:`close`: the figure's data (plotly's ``_fullData``) equals the expected joint
  positions. The view writes that data itself when it redraws the arm in place
  (``js/arm3d_view.js``), so on its own it would not catch a picture that stopped moving.
* :func:`assert_arm_on_screen`: the picture. Each link's midpoint (and quarter points),
  projected with the WebGL scene's own camera matrices (what the scene is drawn with, not the
  trace data), must be the arm's line colour in a screenshot of the canvas; and where the arm
  was before the change, away from every new link, the arm's colour must be gone. A frozen
  drawing fails both.
"""

from __future__ import annotations

import io
import os
from pathlib import Path

import numpy as np

SHOTS = Path(
    os.environ.get(
        "ANALYSIS_SCREENSHOTS", Path(__file__).resolve().parents[2] / "build" / "browser"
    )
)

ARM_RGB = (0x1F, 0x77, 0xB4)
"""The arm's line colour (``analysis.app.arm3d._arm_traces``: ``#1f77b4``, 9 px wide)."""
STALE_RGB = (0x8F, 0x96, 0x9E)
"""The line colour of a pose kept, greyed, while the target has no solution
(``js/arm3d_view.js``: ``STALE``)."""
COLOUR_TOL = 40  # max |channel difference| of an arm pixel (anti-aliased edges, none needed)
WINDOW = 2  # px each side of a sample point searched for the arm's colour (its half width: 4)
AWAY_PX = 14  # an old sample counts as vacated only this far from every new link [px]

# page coordinates [CSS px] of data points [mm], by the scene's camera (plotly's gl3d project)
_PROJECT = """([sel, pts]) => {
    const gd = document.querySelector(sel);
    const scene = gd && gd._fullLayout && gd._fullLayout.scene && gd._fullLayout.scene._scene;
    if (!scene || !scene.glplot) return null;
    const cam = scene.glplot.cameraParams, s = scene.dataScale;
    const mul = (m, v) => [0, 1, 2, 3].map(r => m[r] * v[0] + m[4 + r] * v[1] + m[8 + r] * v[2]
                                                + m[12 + r] * v[3]);
    let box = scene.glplot.canvas.getBoundingClientRect();
    if (box.top < 0 || box.left < 0 || box.bottom > innerHeight || box.right > innerWidth) {
        scene.glplot.canvas.scrollIntoView({block: "nearest", inline: "nearest"});
        box = scene.glplot.canvas.getBoundingClientRect();
    }
    return {box: [box.left, box.top, box.width, box.height], xy: pts.map(p => {
        const c = mul(cam.projection, mul(cam.view, mul(cam.model,
            [p[0] * s[0], p[1] * s[1], p[2] * s[2], 1])));
        return [box.left + (0.5 + 0.5 * c[0] / c[3]) * box.width,
                box.top + (0.5 - 0.5 * c[1] / c[3]) * box.height];
    })};
}"""


def close(drawn, expect, atol: float = 2e-3) -> bool:
    """Drawn joint positions equal ``expect`` (frame origins [mm]; coincident frames drawn
    once) within ``atol`` [mm] (the figure's coordinates are rounded to 1 um)."""
    e = np.asarray(expect, dtype=float).reshape(-1, 3)
    e = e[np.r_[True, np.any(np.abs(np.diff(e, axis=0)) > 1e-9, axis=1)]]
    d = np.asarray(drawn, dtype=float).reshape(-1, 3)
    return d.shape == e.shape and bool(np.all(np.abs(d - e) <= atol))


def _samples(frames) -> np.ndarray:
    """Points at 1/4, 1/2 and 3/4 of every link of non-zero length [mm] (never a joint, where
    a marker is drawn)."""
    f = np.asarray(frames, dtype=float).reshape(-1, 3)
    a, b = f[:-1], f[1:]
    keep = np.linalg.norm(b - a, axis=1) > 1.0
    a, b = a[keep], b[keep]
    return np.concatenate([a + t * (b - a) for t in (0.25, 0.5, 0.75)])


def _distance_to_segments(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distance [px] of each point ``p`` (m, 2) to the nearest segment ``a``-``b`` (k, 2)."""
    ab = b - a
    t = np.clip(
        np.einsum("mkj,kj->mk", p[:, None, :] - a[None], ab)
        / np.maximum(np.einsum("kj,kj->k", ab, ab), 1e-12),
        0.0,
        1.0,
    )
    nearest = a[None] + t[..., None] * ab[None]
    return np.linalg.norm(p[:, None, :] - nearest, axis=2).min(axis=1)


def _arm_coloured(img: np.ndarray, x: float, y: float, rgb=ARM_RGB) -> bool:
    h, w, _ = img.shape
    i, j = round(y), round(x)
    patch = img[
        max(i - WINDOW, 0) : min(i + WINDOW + 1, h), max(j - WINDOW, 0) : min(j + WINDOW + 1, w)
    ]
    return bool((np.abs(patch.astype(int) - rgb).max(axis=-1) <= COLOUR_TOL).any())


def assert_arm_on_screen(page, selector: str, frames, previous=None, rgb=ARM_RGB) -> None:
    """The arm through ``frames`` [mm] (None: no arm) is on screen in the plot ``selector``,
    in colour ``rgb`` (:data:`STALE_RGB`: the pose kept, greyed, for a target without a
    solution); if ``previous`` (the frames drawn before the change) is given, the arm has
    left the places of the old links that no new link covers. Link points that a joint axis or
    frame crosses in the picture are not asserted (at most half of them). Raises
    AssertionError naming the points."""
    from PIL import Image

    f = np.asarray(frames if frames is not None else [], dtype=float).reshape(-1, 3)
    new = _samples(f) if len(f) else np.zeros((0, 3))
    old = _samples(previous) if previous is not None else np.zeros((0, 3))
    got = page.evaluate(_PROJECT, [selector, [*f.tolist(), *new.tolist(), *old.tolist()]])
    assert got is not None, f"no WebGL scene in {selector}"
    left, top, width, height = got["box"]
    xy = np.asarray(got["xy"], dtype=float) - [left, top]
    joints, xy_new, xy_old = xy[: len(f)], xy[len(f) : len(f) + len(new)], xy[len(f) + len(new) :]
    shot = page.screenshot(clip={"x": left, "y": top, "width": width, "height": height})
    img = np.asarray(Image.open(io.BytesIO(shot)).convert("RGB"))
    # a link point under a joint axis or frame line (arm3d_frames) is not the arm's to show
    seen = xy_new[~_overlaid(page, selector, xy_new, got["box"])]
    assert len(seen) >= len(xy_new) // 2, f"{len(xy_new) - len(seen)} link points overlaid"
    missing = [_px(p) for p in seen if not _arm_coloured(img, *p, rgb=rgb)]
    if missing:
        _keep(img, xy_new, "missing")
    assert not missing, (
        f"the arm is not drawn at {missing} px (of {len(xy_new)} link points; canvas at "
        f"{[round(v) for v in got['box']]}; build/browser/arm-not-on-screen-missing.png)"
    )
    if len(xy_old):
        a, b = joints[:-1], joints[1:]
        away = xy_old[_distance_to_segments(xy_old, a, b) > AWAY_PX] if len(a) else xy_old
        stale = [_px(p) for p in away if _arm_coloured(img, *p)]
        if stale:
            _keep(img, away, "stale")
        assert not stale, (
            f"the old pose is still drawn at {stale} px (build/browser/arm-not-on-screen-stale.png)"
        )


# the joint axes and frames drawn (js/arm3d_view.js: traces with meta.arm3d, shown), as
# segments [[a, b], ...] [mm]: they may cross a link in the picture
_OVERLAYS = """sel => { const gd = document.querySelector(sel), out = [];
    for (const t of (gd && gd.data) || []) {
        if (!(t.meta && t.meta.arm3d) || (t.visible !== undefined && t.visible !== true)) continue;
        for (let i = 0; i + 1 < t.x.length; i++) {
            const a = [t.x[i], t.y[i], t.z[i]], b = [t.x[i + 1], t.y[i + 1], t.z[i + 1]];
            if (a.concat(b).every(v => v !== null)) out.push([a, b]);
        }
    }
    return out; }"""
OVER_PX = 7  # a link sample this near a drawn joint axis or frame may be hidden by it [px]


def _overlaid(page, selector: str, xy: np.ndarray, box) -> np.ndarray:
    """Mask of points ``xy`` (page px relative to the canvas) within :data:`OVER_PX` of a
    joint axis or frame drawn in the plot (those lines are drawn over the arm in places)."""
    seg = page.evaluate(_OVERLAYS, selector)
    if not seg or not len(xy):
        return np.zeros(len(xy), dtype=bool)
    got = page.evaluate(_PROJECT, [selector, [p for ab in seg for p in ab]])
    ends = np.asarray(got["xy"], dtype=float) - got["box"][:2]
    return _distance_to_segments(xy, ends[0::2], ends[1::2]) <= OVER_PX


def _px(p) -> tuple[int, int]:
    return round(p[0]), round(p[1])


def _keep(img: np.ndarray, xy: np.ndarray, what: str) -> None:
    """The screenshot that failed, with the sampled points marked, for the reader."""
    from PIL import Image, ImageDraw

    out = Image.fromarray(img)
    draw = ImageDraw.Draw(out)
    for x, y in xy:
        draw.ellipse((x - 4, y - 4, x + 4, y + 4), outline=(255, 0, 255))
    SHOTS.mkdir(parents=True, exist_ok=True)
    out.save(SHOTS / f"arm-not-on-screen-{what}.png")
