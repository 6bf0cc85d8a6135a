"""What the explorer (JupyterLab and the static page) says about a target it cannot solve: one
sentence per situation, written once here (:data:`TEMPLATES`), and the nearest reachable target.

The sentences are templates with named fields. :func:`explain` fills them in Python (the
JupyterLab explorer, :func:`analysis.app.explore_logic.plain_message`); the static page has
no Python, so :func:`templates_js` prints the same templates into it and
``js/static_explorer.js`` fills them with the numbers the arm's printed kinematics compute
there (:mod:`analysis.app.explore_js`); the browser tests hold the page's sentence to
:func:`explain`'s for the same target.

The nearest reachable target (:func:`nearest_target`) lies on the line from the arm's reach
centre (the ``shoulder`` of its closed form's ``geometry``) through the target: of the
points ``c + s (p - c)`` that solve on the chosen branch, the one with ``s`` nearest 1, found
by scans of the line, finer at the boundary (:func:`line_search`). For the paper's arm,
whose reach is a shell around the shoulder, that is the nearest reachable point; for an arm
whose wrist, not its tool point, has the shell (the palletizer, the GR-1) it is the nearest
on that line, and the sentence says so. Only the position moves; an orientation stays.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from analysis.kinematics.status import STATUS_TEXT, Status

__all__ = [
    "TEMPLATES", "Explanation", "batch_reasons", "explain", "line_search", "nearest_target",
    "reach_sphere",
    "search_range", "target_text", "templates_js",
]  # fmt: skip

SCAN = 64
"""Points of one scan of the line (:func:`line_search`)."""
ROUNDS = 5
"""Scans of the interval at the reach boundary after the first: it shrinks to 64^-5 (1e-9)."""

TEMPLATES: dict[str, str] = {
    "out-of-reach": "{target} is {outside} mm beyond the reach; {nearest_sentence}",
    "inside-reach": "{target} is {outside} mm inside the inner reach; {nearest_sentence}",
    "base-axis": "{target} lies on the base axis, where the waist angle θ1 is undefined: {choose}",
    "joint-limits": "{target} is reachable, but no solution on {branch} is within the joint limits",
    "orientation": "{target} asks for an orientation this arm cannot take at that point",
    "degenerate": "{target} is a singular case of this arm's closed form",
    "invalid": "{target} is not a finite number",
    "branch": "{branch}: no solution on this branch ({why}); other solutions for this point are in "
    "the table",
    "nearest": "nearest reachable on the line from the shoulder at {center} mm: {nearest}",
    "no-nearest": "no reachable target on the line from the shoulder at {center} mm",
}
"""The explorer's sentences by situation (a status word of ``STATUS_TEXT``, ``branch`` for a
target whose chosen branch has no solution, ``nearest`` / ``no-nearest`` the clause that names
the nearest reachable target)."""
CHOOSE_THETA1 = "tick “allow θ1 on the base axis” to choose it"
"""The explorers' way to choose the waist angle on the axis (a box and a slider)."""


@dataclass(frozen=True)
class Explanation:
    """What the explorer says about a target: ``word`` (the status), ``sentence``, and the
    nearest reachable target in the arm's input units (mm, rad) or None."""

    word: str
    sentence: str
    nearest: tuple[float, ...] | None = None

    def __str__(self) -> str:
        return f"{self.word} — {self.sentence}"


def _g(v: float) -> str:
    return f"{v:g}"


def target_text(arm, p, decimals: int | None = None, *, word: bool = True) -> str:
    """``target (200, 500, 600) mm`` or ``pose (x, y, z) mm, RPY (a, b, c) deg``: the values
    as given (``%g``) or with ``decimals`` decimals; angles [rad] shown in degrees; without
    the first word (``target``, ``pose``) if not ``word``."""
    fmt = _g if decimals is None else (lambda v: f"{v:.{decimals}f}")
    mm = [fmt(float(v) + 0.0) for v, u in zip(p, arm.input_units, strict=True) if u == "mm"]
    deg = [fmt(math.degrees(float(v)) + 0.0)
           for v, u in zip(p, arm.input_units, strict=True) if u == "rad"]  # fmt: skip
    if deg:
        text = f"pose ({', '.join(mm)}) mm, RPY ({', '.join(deg)}) deg"
    else:
        text = f"target ({', '.join(mm)}) mm"
    return text if word else text.split(" ", 1)[1]


def reach_sphere(arm) -> tuple[tuple[float, float, float], float]:
    """The reach centre [mm] (the ``shoulder`` of the closed form's ``geometry``, else the
    base origin) and the largest reach radius [mm] (its ``reach*`` radii, else the farthest
    point of the arm's workspace box, :func:`analysis.app.arm3d.workspace_box`)."""
    geo = arm.closed_form.geometry(arm.params) if arm.closed_form is not None else {}
    center = tuple(float(v) for v in geo.get("shoulder", (0.0, 0.0, 0.0)))
    radii = [float(v) for k, v in geo.items() if k.startswith("reach")]
    if not radii:
        from analysis.app.arm3d import workspace_box

        box = workspace_box(arm)
        radii = [float(np.linalg.norm(np.maximum(np.abs(box.lo), np.abs(box.hi))))]
    return center, max(radii)


def _center(arm) -> tuple[float, float, float]:
    return reach_sphere(arm)[0]


def search_range(arm, p: npt.ArrayLike) -> float:
    """How far along the line from the reach centre through ``p`` the search goes, as a
    multiple ``s_max`` of the target's distance: past the largest reach radius of the arm's
    ``geometry`` on the far side, at least twice the distance."""
    reach = reach_sphere(arm)[1]
    p = np.asarray(p, dtype=float)
    pos = [k for k, u in enumerate(arm.input_units) if u == "mm"][:3]
    d = float(np.linalg.norm(p[pos] - np.asarray(_center(arm))[: len(pos)]))
    return 2.0 + 2.0 * reach / max(d, 1e-9)


def line_search(ok, s_max: float) -> float | None:
    """The ``s`` nearest 1 in (0, ``s_max``] for which ``ok(s)`` (vectorized) holds, where
    ``ok(1)`` does not: a scan of :data:`SCAN` points, then :data:`ROUNDS` scans of the
    interval between the reachable point found and the next one towards 1; None if the first
    scan finds none. The static page runs the same search (``js/static_explorer.js``)."""
    grid = s_max * np.arange(1, SCAN + 1) / SCAN
    good = np.asarray(ok(grid), dtype=bool)
    if not good.any():
        return None
    lo = float(grid[int(np.argmin(np.where(good, np.abs(grid - 1.0), np.inf)))])
    hi = 1.0
    for _ in range(ROUNDS):
        grid = lo + (hi - lo) * np.arange(1, SCAN) / SCAN
        good = np.flatnonzero(np.asarray(ok(grid), dtype=bool))
        if good.size:
            lo = float(grid[good[-1]])
            hi = float(grid[good[-1] + 1]) if good[-1] + 1 < len(grid) else hi
        else:
            hi = float(grid[0])
    return lo


def nearest_target(
    arm, p: npt.ArrayLike, branch: str, *, theta1_on_axis: float | None = None
) -> npt.NDArray[np.float64] | None:
    """The reachable target nearest ``p`` on the line from the reach centre through it, on
    ``branch`` (module docstring; :func:`line_search` over :func:`search_range`); None where
    no point of that line solves. Position inputs move, angle inputs stay."""
    p = np.asarray(p, dtype=float)
    pos = [k for k, u in enumerate(arm.input_units) if u == "mm"][:3]
    c = np.asarray(_center(arm))[: len(pos)]

    def at(s):
        s = np.asarray(s, dtype=float)
        out = np.broadcast_to(p, (*s.shape, len(p))).copy()
        out[..., pos] = c + s[..., None] * (p[pos] - c)
        return out

    def ok(s):
        return arm.solve(at(s), (branch,), theta1_on_axis=theta1_on_axis).ok[..., 0]

    s = line_search(ok, search_range(arm, p))
    return None if s is None else at(np.array(s))


def explain(arm, p, status: Status | int, outside: float, branch: str, *,
            why: str = "", theta1_on_axis: float | None = None) -> Explanation:  # fmt: skip
    """What the explorer says about target ``p`` (the arm's inputs, angles in rad) whose
    solve gave ``status`` and ``outside`` [mm], with ``branch`` chosen: for a target without a
    solution its status word, the sentence of :data:`TEMPLATES` and the nearest reachable
    target; for a target whose chosen branch alone has none (``status`` OK, ``why`` that
    branch's own status word), the ``branch`` sentence.

    >>> from analysis.kinematics.arm import paper_arm
    >>> e = explain(paper_arm(), [200, 500, 600], 1, 31.849, "front-up")
    >>> print(e)  # Table 4 row 8, which the paper marks 无解
    out-of-reach — target (200, 500, 600) mm is 31.849 mm beyond the reach; nearest reachable on the line from the shoulder at (0, 0, 660) mm: (188.244, 470.611, 603.527) mm
    """  # noqa: E501
    status = Status(int(status))
    fields = {"target": target_text(arm, p), "branch": branch, "why": why,
              "outside": f"{abs(outside):.3f}", "choose": CHOOSE_THETA1}  # fmt: skip
    nearest = None
    if status == Status.OK:
        return Explanation("ok", TEMPLATES["branch"].format_map(fields))
    word = STATUS_TEXT[status]
    if status in (Status.OUT_OF_REACH, Status.INSIDE_REACH):
        nearest = nearest_target(arm, p, branch, theta1_on_axis=theta1_on_axis)
        center = "(" + ", ".join(_g(v + 0.0) for v in _center(arm)) + ")"
        clause = "no-nearest" if nearest is None else "nearest"
        fields["nearest_sentence"] = TEMPLATES[clause].format_map(
            {"center": center,
             "nearest": "" if nearest is None else target_text(arm, nearest, 3, word=False)}
        )  # fmt: skip
    sentence = TEMPLATES[word].format_map(fields)
    return Explanation(word, sentence, None if nearest is None else tuple(map(float, nearest)))


BATCH_CHOOSE = "give --theta1-on-axis DEG"
"""The CLI's way to choose the waist angle on the axis (the explorers': :data:`CHOOSE_THETA1`)."""


def batch_reasons(words: list[str], outside: npt.ArrayLike, branches: list[str]) -> list[str]:
    """The ``reason`` cells of batch rows (:func:`analysis.app.batch.solve_csv`) by their
    status ``words``, distances ``outside`` [mm] and ``branches``: the explorers' sentence
    (:data:`TEMPLATES`) about "the target" (its coordinates are in the row), without the
    nearest reachable target (a search per row) and with the CLI's way to choose θ1; ""
    for an "ok" row.

    >>> batch_reasons(["ok", "out-of-reach", "base-axis"], [0.0, 12.5, 0.0], ["a", "a", "a"])[1:]
    ['the target is 12.500 mm beyond the reach', 'the target lies on the base axis, where the \
waist angle θ1 is undefined: give --theta1-on-axis DEG']
    """
    out = []
    for word, d, b in zip(words, np.asarray(outside, dtype=float).tolist(), branches, strict=True):
        if word == "ok":
            out.append("")
            continue
        fields = {"target": "the target", "outside": f"{abs(d):.3f}", "branch": b,
                  "choose": BATCH_CHOOSE}  # fmt: skip
        out.append(TEMPLATES[word].replace("; {nearest_sentence}", "").format_map(fields))
    return out


def templates_js() -> str:
    """The templates as a JavaScript object literal, for the static page."""
    return json.dumps(TEMPLATES | {"choose": CHOOSE_THETA1}, ensure_ascii=False)
