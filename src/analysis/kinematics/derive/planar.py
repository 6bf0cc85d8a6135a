"""Planar arms and SCARAs: parallel revolute axes (and a prismatic one along them), derived.

:class:`PlanarArm` is the closed form of the families ``2R-planar``, ``3R-planar`` and
``SCARA`` (:mod:`.families`), written once against the math namespace ``m``. All revolute
axes are parallel to ``u`` (along a base axis), a prismatic joint moves along ``u``, so the
problem splits (Murray, Li and Sastry, sec. 3.2; the subproblems of :mod:`.subproblems`):

1. **the turn** (three revolute joints): the tool's turn about ``u`` is the sum
   ``S = sum sigma_i q_i`` (``sigma_i = +-1``: the axis along or against ``u``), set by the
   input ``alpha`` (RPY, the turn about z: ``S = k (alpha - alpha0)``, ``k = +-1`` as ``u``
   points up or down, ``alpha0`` the tool's at q = 0; taken as ``atan2(sin, cos)``, so any
   alpha, as the RPY angles of a pose, is read by its sine and cosine); the point of the
   third axis is then
   the target less the tool's offset from it turned by ``S``;
2. **the elbow**: PK3 in the plane across ``u``, the law of cosines of the two links
   between the first two axes and the solved point, ``cos(bend) = (d^2 - La^2 - Lb^2) /
   (2 La Lb)``, the bend ``+-acos`` (the two branches); the first joint by PK1 from the arm at
   q1 = 0 onto the solved point (:func:`.subproblems.pk1`), the second from the bend;
3. the third revolute joint from the turn, ``q3 = sigma_3 (S - sigma_1 q1 - sigma_2 q2)``;
4. **the lift** (SCARA): the prismatic joint from the target's coordinate along ``u``,
   ``q_p = sigma_p u . (p - p0)`` (``p0``: the tool at q = 0).

Branches: ``righty`` (the elbow bends counter-clockwise seen from above: from the side ``u``
or ``-u`` points to, whichever has z >= 0, else x >= 0) and ``lefty`` (the other), as SCARA
makers name them. Refusals: beyond or inside the reach shells of the solved point
(``out-of-reach``, ``inside-reach``), on the first axis with equal links (``degenerate``:
q1 undefined); joint limits (a SCARA's stroke) are the shared solver's. A 2R arm's target is
its two coordinates across ``u`` (``px, py`` for vertical axes); its third coordinate is the
plane's.
"""

from __future__ import annotations

import math

import numpy as np

from analysis.kinematics.derive import subproblems as sp
from analysis.kinematics.derive.base import POINT, FamilyForm, fmt
from analysis.kinematics.derive.chain import home
from analysis.kinematics.derive.positioning import ZERO_MM
from analysis.kinematics.ops import numpy_ops
from analysis.kinematics.status import Status

__all__ = ["BRANCHES", "PlanarArm"]

BRANCHES = ("righty", "lefty")


class PlanarArm(FamilyForm):
    """The closed form of a planar arm or a SCARA (module docstring)."""

    BRANCHES = BRANCHES
    STATUSES = (Status.OUT_OF_REACH, Status.INSIDE_REACH, Status.DEGENERATE)

    def __init__(self, name: str, description, structure) -> None:
        super().__init__(name, description, structure)
        st = structure
        self.rev = [i for i, k in enumerate(st.kinds) if k == "revolute"]
        self.pris = [i for i, k in enumerate(st.kinds) if k == "prismatic"]
        self._u = tuple(st.u)
        self.along = int(np.argmax(np.abs(st.u)))  # the base axis u lies along
        self._across = [k for k in range(3) if k != self.along]
        self._coords = self._across if st.family != "SCARA" else [0, 1, 2]
        self.INPUTS = tuple(POINT[k] for k in self._coords) + (("alpha",) if len(self.rev) == 3
                                                                else ())  # fmt: skip
        up = st.u if (st.u[2] > 0 or (st.u[2] == 0 and st.u[self.along] > 0)) else -st.u
        self.s_righty = 1.0 if float(np.dot(up, st.u)) > 0 else -1.0
        R0 = st.rotation
        self.alpha0 = float(np.arctan2(R0[1, 0], R0[0, 0]))
        self.k_up = float(np.sign(st.u[2])) if len(self.rev) == 3 else 1.0
        if len(self.rev) == 3 and np.hypot(R0[0, 0], R0[1, 0]) < 1e-6:
            from analysis.kinematics.derive.families import NotDerivable

            raise NotDerivable(
                "the tool's x axis lies along the parallel axes at q = 0: its turn about them "
                "(RPY alpha) is undefined; turn the tool frame (a theta offset on the last row)"
            )
        g = [self._points(numpy_ops, dict(zip(description.parameters, v, strict=True)))
             for v in np.random.default_rng(20260101).uniform(-1e3, 1e3, (3, len(
                 description.parameters)))]  # fmt: skip
        self.bend_zero = all(abs(float(x["axb"])) <= ZERO_MM for x in g) and float(
            self._points(numpy_ops, description.values)["ab"]) > 0  # fmt: skip

    @property
    def flags(self) -> tuple:
        return (self.bend_zero,)

    # --- geometry --------------------------------------------------------------------------
    def _points(self, m, P) -> dict:
        """The first two revolute axes' points, the solved point and the links across ``u``
        at q = 0 [mm], in namespace ``m``."""
        h = home(m, self.description.dh_table(dict(P)))
        u = self._u
        P0, P1 = h.points[self.rev[0]], h.points[self.rev[1]]
        wh = h.points[self.rev[2]] if len(self.rev) == 3 else h.position
        a, b = sp.across(u, sp.sub(P1, P0)), sp.across(u, sp.sub(wh, P1))
        g = {"P0": P0, "p0": h.position, "a": a, "b": b, "la2": sp.norm_sq(a), "lb2": sp.norm_sq(b)}
        g["la"], g["lb"] = m.sqrt(g["la2"]), m.sqrt(g["lb2"])
        g["ab"], g["axb"] = sp.dot(a, b), sp.dot(u, sp.cross(a, b))
        if len(self.rev) == 3:
            g["o"] = sp.across(u, sp.sub(h.position, wh))  # the tool from the third axis
        return g

    def check(self, P) -> None:
        """Reject links of zero length across the axes (ValueError naming them)."""
        g = self._points(numpy_ops, P)
        for key, what in (("la", "first link (axis 1 to axis 2)"), ("lb", "second link")):
            if not float(g[key]) > 1e-9:
                raise ValueError(
                    f"arm {self.description.name}: the {what} has length {float(g[key]):g} mm "
                    "across the parallel axes; the derived closed form needs it > 0 mm"
                )

    def _reach_tool(self, m, g):
        out = g["la"] + g["lb"]
        if "o" in g:
            out = out + m.sqrt(sp.norm_sq(g["o"]))
        return out

    def geometry(self, P) -> dict:
        """The first axis's point, the reach radii of the solved point and the tool's box
        across the axes [mm]."""
        g = self._points(numpy_ops, P)
        la, lb = float(g["la"]), float(g["lb"])
        reach = float(self._reach_tool(numpy_ops, g))
        out = {"shoulder": tuple(float(v) for v in g["P0"]), "reach_outer": la + lb,
               "reach_inner": abs(la - lb), "reach_tool": reach}  # fmt: skip
        if "o" in g:
            out["tool_offset"] = float(np.sqrt(float(sp.norm_sq(g["o"]))))
        return out

    # --- the closed form ---------------------------------------------------------------------
    def _point(self, p, g) -> tuple:
        """The target as a 3D point (a planar arm: its coordinates and the plane's)."""
        out = list(g["p0"])
        for i, k in enumerate(self._coords):
            out[k] = p[i]
        return tuple(out)

    def ik(self, m, p, P, *, tol, axis_tol=None, precise=False):
        """Both branches for target ``p`` (module docstring) in namespace ``m``: ``branches``,
        ``refusals`` (all the target's: both branches share the reach), ``outside``."""
        axis_tol = tol if axis_tol is None else axis_tol
        g = self._points(m, P)
        u, st = self._u, self.structure
        pos = self._point(p, g)
        m.section("reach box: no configuration puts the tool farther across the axes")
        reach = self._reach_tool(m, g)
        rel = sp.sub(pos, g["P0"])
        out_box = [m.gt(m.abs(rel[k]), reach + tol) for k in self._across]
        refusals = [(Status.OUT_OF_REACH, m.any_(*out_box))]
        turn, w = None, pos
        if len(self.rev) == 3:
            m.section("the turn about the parallel axes (alpha), the third axis's point")
            d = self.k_up * (p[-1] - self.alpha0)
            ct, st_ = m.cos(d), m.sin(d)  # any alpha: RPY angles are used by sine and cosine
            turn = m.let("turn", m.atan2(st_, ct))
            w = sp.sub(pos, sp.rotate(u, g["o"], ct, st_))
        m.section("the elbow (PK3: law of cosines), the first joint (PK1)")
        t = sp.across(u, sp.sub(w, g["P0"]))
        d2 = m.let("d2", sp.norm_sq(t))
        d = m.let("d", m.sqrt(d2))
        beyond = m.let("beyond", d - (g["la"] + g["lb"]))
        within = m.let("within", m.abs(g["la"] - g["lb"]) - d)
        refusals += [(Status.OUT_OF_REACH, m.gt(beyond, tol)),
                     (Status.INSIDE_REACH, m.gt(within, tol)),
                     (Status.DEGENERATE, m.le(d, axis_tol))]  # fmt: skip
        c, gam, sg = sp.pk3_cos(m, d2, g["la2"], g["lb2"], g["la"], g["lb"], precise=precise)
        c, gam = m.let("cos_bend", c), m.let("bend", gam)
        lift = None
        if self.pris:
            j = self.pris[0]
            lift = m.let(f"q{j + 1}", st.sigma[j] * sp.dot(u, sp.sub(pos, g["p0"])))
        branches = {}
        for name, s in (("righty", self.s_righty), ("lefty", -self.s_righty)):
            branches[name] = self._joints(m, g, t, c, gam, sg, s, turn, lift, name)
        outside = m.select(m.gt(beyond, within), beyond, within)
        return {"branches": branches, "refusals": refusals, "outside": outside}

    def _joints(self, m, g, t, c, gam, sg, s, turn, lift, name) -> tuple:
        """The joint values of one branch, in chain order."""
        st, u = self.structure, self._u
        la, lb = g["la"], g["lb"]
        if self.bend_zero:
            cb, sb = c, s * sg
        else:
            c0, s0 = g["ab"] / (la * lb), g["axb"] / (la * lb)
            cb, sb = c * c0 + (s * sg) * s0, (s * sg) * c0 - c * s0
        vec = sp.add(g["a"], sp.rotate(u, g["b"], cb, sb))
        r0, r1 = self.rev[0], self.rev[1]
        q = {r0: m.let(f"q{r0 + 1}_{name}", m.wrap(st.sigma[r0] * sp.pk1(m, u, vec, t)))}
        if self.bend_zero:
            q[r1] = st.sigma[r1] * (s * gam)
        else:
            q[r1] = m.wrap(st.sigma[r1] * (s * gam - m.atan2(g["axb"], g["ab"])))
        q[r1] = m.let(f"q{r1 + 1}_{name}", q[r1])
        if turn is not None:
            r2 = self.rev[2]
            sigma = st.sigma
            q[r2] = m.let(f"q{r2 + 1}_{name}",
                          m.wrap(sigma[r2] * ((turn - sigma[r0] * q[r0]) - sigma[r1] * q[r1])))
        if lift is not None:
            q[self.pris[0]] = lift
        return tuple(q[i] for i in range(len(st.kinds)))

    def refusal(self, status: Status, p, P, *, tol: float, distance: float) -> tuple[str, float]:
        """The one-line reason a target is refused, naming it and the limit crossed, and
        the limit [mm]."""
        geo = self.geometry(P)
        where = self.where(p)
        sh = fmt(geo["shoulder"])
        solved = "the third axis" if len(self.rev) == 3 else "the tool"
        if status == Status.OUT_OF_REACH:
            return (
                f"{where} puts {solved} {distance:.3f} mm beyond the reach of "
                f"{geo['reach_outer']:g} mm (the two links) around the first axis at {sh} mm"
            ), geo["reach_outer"]
        if status == Status.INSIDE_REACH:
            return (
                f"{where} puts {solved} {distance:.3f} mm inside the inner reach of "
                f"{geo['reach_inner']:g} mm (|La - Lb|) around the first axis at {sh} mm"
            ), geo["reach_inner"]
        if status == Status.DEGENERATE:
            return (
                f"{where} puts {solved} on the first axis (the two links are equal): the first "
                "joint is undefined there"
            ), 0.0
        raise ValueError(f"no message for status {status!r}")

    def where(self, p) -> str:
        """``target (x, y[, z]) mm[, alpha a deg]``."""
        p = [float(v) for v in p]
        n = len(self._coords)
        text = f"target {fmt(p[:n])} mm"
        return text + (f", alpha {math.degrees(p[n]):.4g} deg" if len(p) > n else "")
