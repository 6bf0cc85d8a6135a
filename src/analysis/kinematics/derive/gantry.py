"""Gantries: three prismatic axes spanning space, with no wrist, a vertical roll or a
spherical wrist, derived.

:class:`GantryArm` is the closed form of the families ``gantry``, ``gantry-roll`` and
``gantry-wrist`` (:mod:`.families`), written once against the math namespace ``m``. Prismatic
joints turn nothing, so the wrist is solved first and the slides after:

1. **the wrist** (``gantry-roll``): the roll ``q4 = k (alpha - alpha0)`` (``k = +-1`` as the
   roll axis points up or down, ``alpha0`` the tool's RPY alpha at q = 0); (``gantry-wrist``)
   the spherical wrist of :func:`.wrist.spherical` (PK2 and PK1, two branches) from the
   requested orientation alone;
2. **the slides**: the point the slides carry (the tool; the roll axis's point; the wrist
   centre) is where the target puts it, ``c = p - R R0^T (p0 - c0)``, and the slides are
   ``q = D^-1 (c - c0)`` with ``D`` the three directions (numbers of the D-H table's twists
   and offsets: exact).

The slides' strokes (``limits_mm``) bound the reachable set: a target whose slides would pass a
stroke end by more than ``tol`` is refused (``out-of-reach``; a negative ``tol``, the PLC's
band, refuses within it of an end), and one whose overshoot moves the carried point by more
than ``tol`` (a corner); within, each slide is put on its end. ``outside`` is that
displacement, or minus the distance to the nearest stroke face inside. Branches: ``single``
(no wrist, a roll) or the wrist's ``noflip`` and ``flip`` (:data:`.wrist.WRISTS`); a
spherical wrist on its flip (axes 4 and 6 aligned) is refused (``degenerate``).
"""

from __future__ import annotations

import math

import numpy as np

from analysis.kinematics.derive import subproblems as sp
from analysis.kinematics.derive import wrist as wr
from analysis.kinematics.derive.base import POINT, POSE, FamilyForm, fmt
from analysis.kinematics.derive.chain import home
from analysis.kinematics.derive.families import NotDerivable
from analysis.kinematics.derive.positioning import ZERO_MM, apply_columns, mat_vec, meet
from analysis.kinematics.ops import numpy_ops
from analysis.kinematics.rpy import rpy_columns
from analysis.kinematics.status import Status

__all__ = ["GantryArm"]


class GantryArm(FamilyForm):
    """The closed form of a gantry (module docstring)."""

    def __init__(self, name: str, description, structure) -> None:
        super().__init__(name, description, structure)
        st = structure
        fam = st.family
        self.BRANCHES = wr.WRISTS if fam == "gantry-wrist" else ("single",)
        self.INPUTS = POSE if fam == "gantry-wrist" else POINT + (
            ("alpha",) if fam == "gantry-roll" else ())  # fmt: skip
        self.STATUSES = (Status.OUT_OF_REACH,) + (
            (Status.DEGENERATE,) if fam == "gantry-wrist" else ())  # fmt: skip
        D = np.stack(st.axes[:3], axis=1)
        self._D = D
        self._Dinv = np.linalg.inv(D)
        # distance [mm] from a stroke face per unit of its slide: 1 / |row of D^-1|
        self._face = 1.0 / np.linalg.norm(self._Dinv, axis=1)
        self._R0T = st.rotation.T
        joints = description.joints[:3]
        self._lo = tuple(float(j.lower) for j in joints)
        self._hi = tuple(float(j.upper) for j in joints)
        if fam == "gantry-roll":
            R0 = st.rotation
            if np.hypot(R0[0, 0], R0[1, 0]) < 1e-6:
                raise NotDerivable(
                    "the tool's x axis is vertical at q = 0: its turn about the roll axis (RPY "
                    "alpha) is undefined; turn the tool frame (a fixed row)"
                )
            self.alpha0 = float(np.arctan2(R0[1, 0], R0[0, 0]))
            self.k_up = float(np.sign(st.axes[3][2]))
        if fam == "gantry-wrist":
            for v in np.random.default_rng(20260101).uniform(-1e3, 1e3, (3, len(
                    description.parameters))):  # fmt: skip
                g = self._points(numpy_ops, dict(zip(description.parameters, v, strict=True)))
                h, c = g["home"], np.array([float(x) for x in g["c0"]])
                dist = float(np.linalg.norm(np.cross(c - np.array(
                    [float(x) for x in h.points[5]]), st.axes[5])))  # fmt: skip
                if dist > ZERO_MM:
                    raise NotDerivable(
                        f"axis 6 passes {dist:.4g} mm from where axes 4 and 5 meet (at some "
                        "parameter values): no spherical wrist"
                    )

    @property
    def flags(self) -> tuple:
        return ()

    def _points(self, m, P) -> dict:
        """The carried point at q = 0 (``c0``) and the tool's offset from it (``o``)."""
        h = home(m, self.description.dh_table(dict(P)))
        ax = self.structure.axes
        if self.family == "gantry":
            c0 = h.position
        elif self.family == "gantry-roll":
            c0 = h.points[3]
        else:
            c0 = meet(h.points[3], ax[3], h.points[4], ax[4])
        return {"home": h, "c0": c0, "o": sp.sub(h.position, c0)}

    def check(self, P) -> None:
        """Nothing to reject: any lengths make a gantry."""

    def geometry(self, P) -> dict:
        """The carried point at q = 0 and the tool's offset from it [mm]."""
        g = self._points(numpy_ops, P)
        return {"shoulder": tuple(float(v) for v in g["c0"]),
                "tool_offset": float(np.sqrt(float(sp.norm_sq(g["o"]))))}  # fmt: skip

    def ik(self, m, p, P, *, tol, axis_tol=None, margin_rad=0.0):
        """Every branch for target ``p`` (module docstring) in namespace ``m``."""
        g = self._points(m, P)
        pos = tuple(p[:3])
        fam = self.family
        refusals, wrists, conds = [], {"single": ()}, {}
        if fam == "gantry-roll":
            m.section("the roll (alpha)")
            d = self.k_up * (p[3] - self.alpha0)
            c4, s4 = m.cos(d), m.sin(d)  # any alpha: read by its sine and cosine
            q4 = m.let("q4", m.atan2(s4, c4))
            c = sp.sub(pos, sp.rotate(tuple(self.structure.axes[3]), g["o"], c4, s4))
            wrists = {"single": (q4,)}
        elif fam == "gantry-wrist":
            m.section("the spherical wrist (PK2, PK1)")
            cols = rpy_columns(m, *p[3:6])
            c = sp.add(pos, apply_columns(cols, mat_vec(self._R0T, sp.scale(-1.0, g["o"]))))
            wrists, flip = wr.spherical(m, self.structure.axes, self._R0T, cols, (), "w")
            band = wr.wrist_band(margin_rad)
            conds = {w: [(Status.DEGENERATE, m.le(flip, band))] for w in wr.WRISTS}
        else:
            c = pos
        m.section("the slides: q = D^-1 (c - c0), within their strokes")
        q = mat_vec(self._Dinv, sp.sub(c, g["c0"]))
        q = [m.let(f"q{j + 1}", v) for j, v in enumerate(q)]
        excess = [m.select(m.gt(v - hi, lo - v), v - hi, lo - v)  # signed: < 0 inside
                  for v, lo, hi in zip(q, self._lo, self._hi, strict=True)]  # fmt: skip
        refusals.append((Status.OUT_OF_REACH, m.any_(*(m.gt(e, tol) for e in excess))))
        over = [m.select(m.gt(v, hi), v - hi, m.select(m.lt(v, lo), v - lo, 0.0))
                for v, lo, hi in zip(q, self._lo, self._hi, strict=True)]  # fmt: skip
        moved = mat_vec(self._D, over)
        moved2 = m.let("overshoot2", sp.norm_sq(moved))
        refusals.append((Status.OUT_OF_REACH, m.gt(moved2, tol * tol)))
        inner = None
        for v, lo, hi, f in zip(q, self._lo, self._hi, self._face, strict=True):
            margin = m.select(m.lt(v - lo, hi - v), v - lo, hi - v) * float(f)
            inner = margin if inner is None else m.select(m.lt(margin, inner), margin, inner)
        outside = m.select(m.gt(moved2, 0.0), m.sqrt(moved2), -inner)
        slides = tuple(m.clip(v, lo, hi) for v, lo, hi in zip(q, self._lo, self._hi, strict=True))
        out = {"branches": {b: (*slides, *wrists[b]) for b in self.BRANCHES},
               "refusals": refusals, "outside": outside}  # fmt: skip
        if conds:
            out["branch_refusals"] = conds
        return out

    def refusal(self, status: Status, p, P, *, tol: float, distance: float) -> tuple[str, float]:
        """The one-line reason a target is refused and the limit crossed [mm]."""
        where = self.where(p)
        if status == Status.OUT_OF_REACH:
            name = [j.name for j in self.description.joints[:3]]
            return (
                f"{where} takes the slides {distance:.3f} mm past their strokes ("
                + ", ".join(f"{n} [{lo:g}, {hi:g}] mm"
                            for n, lo, hi in zip(name, self._lo, self._hi, strict=True))
                + ")"
            ), float("nan")  # fmt: skip
        if status == Status.DEGENERATE:
            return (
                f"{where} puts the wrist at its flip (axes 4 and 6 aligned): the pose sets only "
                "the sum of their turns, not each"
            ), 0.0
        raise ValueError(f"no message for status {status!r}")

    def where(self, p) -> str:
        p = [float(v) for v in p]
        if len(p) == 4:
            return f"target {fmt(p[:3])} mm, alpha {math.degrees(p[3]):.4g} deg"
        return super().where(p)
