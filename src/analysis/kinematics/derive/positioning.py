"""The waist families' geometry and the steps of their closed form, in any namespace ``m``.

:class:`WaistArm` holds what the families with a waist and parallel axes (3R, 4R-kept, 5R,
6R-wrist, 6R-parallel; :mod:`.families`) are solved with, one method per step of the
subproblem decomposition of :mod:`analysis.kinematics.derive` (its docstring names the
steps): the home geometry (:meth:`WaistArm._points`), the reach box and the reach shells
(:meth:`WaistArm._reach`), the waist (:meth:`WaistArm._waist`), the pitch of the parallel
axes (:meth:`WaistArm._pitch`), the reach of the solved point in the arm plane
(:meth:`WaistArm._plane`) and the elbow and shoulder (:meth:`WaistArm._elbow`). The six-axis
wrists are :mod:`.wrist`'s; :class:`~.closed_form.DerivedClosedForm` puts the steps together.

The solved point (``wh`` at q = 0) is what the parallel axes place: the tool point (3R,
4R-kept), the roll axis's point nearest the tool (5R), the wrist centre where axes 4, 5 and 6
meet (6R-wrist, Pieper's condition) or the point where axes 5 and 6 meet (6R-parallel). A
pose puts it at ``p + R R0^T (wh - p0)`` (``R`` the requested orientation, ``R0`` the tool's
at q = 0, ``p0`` its point): the tool point stays at the same place relative to it.
"""

from __future__ import annotations

import math

import numpy as np

from analysis.kinematics.derive import subproblems as sp
from analysis.kinematics.derive.base import FamilyForm, fmt
from analysis.kinematics.derive.chain import home
from analysis.kinematics.derive.families import NotDerivable, Structure
from analysis.kinematics.ops import numpy_ops
from analysis.kinematics.rpy import rpy_columns
from analysis.kinematics.status import Status

__all__ = ["WaistArm", "apply_columns", "mat_vec"]

ZERO_MM = 1e-9 * 1000.0
"""A length below which a quantity evaluated at parameters of +-1000 mm counts as zero
(:meth:`WaistArm._decide`)."""


def mat_vec(M, v) -> tuple:
    """A numeric matrix times a vector of values."""
    return tuple(sp.dot(tuple(float(x) for x in row), v) for row in M)


def apply_columns(cols, v) -> tuple:
    """The rotation with columns ``cols`` (values of ``m``) applied to a numeric vector."""
    return sp.add(sp.add(sp.scale(v[0], cols[0]), sp.scale(v[1], cols[1])),
                  sp.scale(v[2], cols[2]))  # fmt: skip


def transpose_apply(cols, v) -> tuple:
    """The transpose of the rotation with columns ``cols`` applied to a vector of values."""
    return tuple(sp.dot(c, v) for c in cols)


def meet(p1, a1, p2, a2):
    """The point of the line ``p1 + t a1`` nearest the line ``p2 + s a2`` (numeric unit
    directions, points values of ``m``): where the two axes meet if they do."""
    n = np.cross(a1, a2)
    t = sp.dot(tuple(np.cross(a2, n) / float(np.dot(n, n))), sp.sub(p2, p1))
    return sp.add(p1, sp.scale(t, tuple(a1)))


class WaistArm(FamilyForm):
    """Geometry and steps of the waist families (module docstring)."""

    def __init__(self, name: str, description, structure: Structure) -> None:
        super().__init__(name, description, structure)
        st = structure
        self.pose_input = st.family in ("5R", "6R-wrist", "6R-parallel")
        self.n_parallel = 2 if st.family in ("3R", "6R-wrist") else 3
        w1, u = st.waist, st.u
        self._w1, self._u = tuple(w1), tuple(u)
        self._uw1 = float(np.dot(u, w1))
        up = u - self._uw1 * w1
        self._nu = float(np.linalg.norm(up))
        self._e = tuple(up / self._nu)
        self._g1 = tuple(np.cross(up / self._nu, w1))
        self._R0T = st.rotation.T
        if st.roll is not None:
            r = st.roll
            self._w5 = tuple(r)
            self._c5 = float(np.dot(u, r))
            self._w5x = tuple(r - self._c5 * u)  # the roll axis across the parallel axes
            n5 = np.cross(r, u)
            self._n5 = tuple(n5 / np.linalg.norm(n5))
        # structural zeros of the home geometry and signs of the description's values
        self._decide()

    @property
    def flags(self) -> tuple:
        """The structural decisions that make two descriptions' closed forms differ."""
        return (self.kappa, self.bend_zero, self.lateral_zero, self.h_zero)

    # --- the home geometry, in any namespace --------------------------------------------
    def _solved_home(self, m, h):
        """The solved point at q = 0 (module docstring) and the point of the last parallel
        axis it is placed from (3R, 6R-wrist: the solved point itself)."""
        fam = self.family
        if fam == "3R":
            return h.position, h.position
        ax = self.structure.axes
        if fam == "6R-wrist":
            W = meet(h.points[3], ax[3], h.points[4], ax[4])
            return W, W
        if fam == "5R":
            q5 = h.points[4]
            return sp.add(q5, sp.scale(sp.dot(self._w5, sp.sub(h.position, q5)), self._w5)), \
                h.points[3]  # fmt: skip
        if fam == "6R-parallel":
            return meet(h.points[4], ax[4], h.points[5], ax[5]), h.points[3]
        return h.position, h.points[3]

    def _points(self, m, P) -> dict:
        """Points and lengths of the chain at q = 0 in namespace ``m`` [mm]."""
        h = home(m, self.description.dh_table(dict(P)))
        q1, q2, q3 = h.points[:3]
        u, w1 = self._u, self._w1
        w0 = sp.sub(q1, q2)
        t = (sp.dot(u, w0) - self._uw1 * sp.dot(w1, w0)) / (1.0 - self._uw1 * self._uw1)
        S = sp.add(q2, sp.scale(t, u))  # the point of axis 2 nearest the waist axis
        g = {"q1": q1, "S": S, "p0": h.position, "home": h}
        g["wh"], wrist = self._solved_home(m, h)
        if self.pose_input:
            g["tool"] = sp.sub(h.position, g["wh"])  # the tool point from the solved point
        if self.n_parallel == 3:
            g["o"] = sp.sub(g["wh"], wrist)  # the solved point from axis 4 (turns with psi)
        a = sp.across(u, sp.sub(q3, S))
        b = sp.across(u, sp.sub(wrist, q3))
        g.update(a=a, b=b, la2=sp.norm_sq(a), lb2=sp.norm_sq(b))
        g["la"], g["lb"] = m.sqrt(g["la2"]), m.sqrt(g["lb2"])
        g["ab"], g["axb"] = sp.dot(a, b), sp.dot(u, sp.cross(a, b))
        g["h"] = sp.dot(u, sp.sub(g["wh"], S))  # the solved point's offset along the axes
        g["hq1"] = sp.dot(u, sp.sub(g["wh"], q1))
        return g

    def _probes(self) -> list[dict]:
        """The home geometry at three seeded random sets of parameter values."""
        rng = np.random.default_rng(20260101)
        names = list(self.description.parameters)
        draws = [rng.uniform(-1000.0, 1000.0, len(names)) for _ in range(3)]
        return [self._points(numpy_ops, dict(zip(names, v, strict=True))) for v in draws]

    def _decide(self) -> None:
        """Structural zeros and signs, decided once per description.

        A quantity is structurally zero when it vanishes for every value of the parameters
        (a shoulder on the waist axis because the table's offsets are 0, not because a
        parameter happens to be): it is evaluated at three seeded random sets of parameter
        values, and an expression in the lengths that is not identically zero vanishes at
        random points with probability 0 (the Schwartz-Zippel test); below 1e-6 mm at
        parameters of +-1000 mm counts as zero (literal numbers of the rows are not drawn:
        an offset written as 1e-7 mm is taken as 0). Signs (which way is forward, whether
        the forearm continues the upper arm) come from the description's values."""
        probes = self._probes()

        def zero(fn) -> bool:
            return all(abs(float(fn(g))) <= ZERO_MM for g in probes)

        self._check_meeting(probes)
        g = self._points(numpy_ops, self.description.values)
        st = self.structure
        self.lateral_zero = self._uw1 == 0.0 and zero(lambda q: q["hq1"])
        self.h_zero = zero(lambda q: q["h"])
        self.shoulder_on_axis = all(
            zero(lambda q, i=i: sp.cross(self._w1, sp.sub(q["S"], q["q1"]))[i]) for i in range(3)
        )
        self.bend_zero = zero(lambda q: q["axb"]) and float(g["ab"]) > 0
        self.global_reach = st.family == "3R" and self.shoulder_on_axis
        self.kappa = self._forward_sign(g)
        k = self.kappa
        self.s_up = {"front": k, "back": k if st.elbow == "arm" else -k}
        self.orient_global = (
            st.family == "5R" and self.lateral_zero and self._uw1 == 0.0 and self._c5 == 0.0
        )

    def _check_meeting(self, probes) -> None:
        """6R-wrist: axes 4, 5 and 6 meet in one point; 6R-parallel: axes 5 and 6 meet
        (structurally: at every parameter value). The solved point is where the first two
        meet (:meth:`_solved_home`); it must lie on each of the axes."""
        fam = self.family
        if fam not in ("6R-wrist", "6R-parallel"):
            return
        ax = self.structure.axes
        for g in probes:
            h = g["home"]
            W = np.array([float(v) for v in g["wh"]])
            for i in ((3, 4, 5) if fam == "6R-wrist" else (4, 5)):
                off = np.cross(W - np.array([float(v) for v in h.points[i]]), ax[i])
                dist = float(np.linalg.norm(off))
                if dist > ZERO_MM:
                    raise NotDerivable(
                        f"axis {i + 1} passes {dist:.4g} mm from where axes "
                        + ("4 and 5 meet (at some parameter values): no spherical wrist "
                           "(Pieper's condition)" if fam == "6R-wrist" else
                           "5 and 6 are nearest (at some parameter values): axis 6 must meet "
                           "axis 5 (the Universal Robots geometry)")
                    )  # fmt: skip

    def _forward_sign(self, g) -> float:
        """+1 or -1: the sign along ``g1 = e x w1`` of the direction the front branches
        face: the description's ``forward``; else where the tool points from the waist axis
        at q = 0; else (a tool on the plane of the waist and the parallel axes, an arm
        upright at q = 0) the x axis of D-H frame 1, the common normal of axes 1 and 2
        (theta1 = 0 faces it)."""
        st = self.structure
        scale = max(1.0, float(np.sqrt(g["la2"] + g["lb2"])))
        if st.forward is not None:
            f = float(np.dot(st.forward, self._g1))
            where = f"[derive] forward = {list(st.forward)}"
        else:
            f = float(sp.dot(sp.sub(g["p0"], g["q1"]), self._g1)) / scale
            where = "the tool at q = 0"
            if abs(f) < 1e-9:
                from analysis.kinematics.dh import chain_transforms

                T1 = chain_transforms(numpy_ops, self.description.dh_table())[0]
                f = float(np.dot([T1[i][0] for i in range(3)], self._g1))
                where = "the tool at q = 0 and the x axis of D-H frame 1"
        if abs(f) < 1e-9:
            raise NotDerivable(
                f"{where}: no component along the arm's forward axis {fmt(self._g1)} "
                "(across the waist and the parallel axes): say which way is front with "
                "[derive] forward = [x, y, z]"
            )
        return 1.0 if f > 0 else -1.0

    def _box(self, m, g):
        """Centre and half-sizes [mm] per base coordinate of a box the tool never leaves:
        an early refusal before any square (no REAL overflow in the PLC). The solved point
        lies within ``la + lb`` of the shoulder across the axes and ``|h|`` along them
        (a ball); what turns with the waist only (a shoulder off the waist axis, the tool
        offset of a kept pitch) sweeps a circle about the waist axis, which adds its radius
        times ``sqrt(1 - w1_k^2)`` to coordinate k and shifts the centre along the axis."""
        w1 = self._w1
        ball = (g["la"] + g["lb"]) + m.sqrt(g["h"] * g["h"])
        rel = sp.sub(g["S"], g["q1"])
        along = sp.dot(w1, rel)
        circle = m.sqrt(sp.norm_sq(sp.sub(rel, sp.scale(along, w1))))
        if self.shoulder_on_axis:
            circle = 0.0
        if self.family == "4R-kept":
            _, c, s = self.structure.keep
            o = sp.rotate(self._u, g["o"], c, s)  # fixed in the arm plane
            o_along = sp.dot(w1, o)
            along = along + o_along
            circle = circle + m.sqrt(sp.norm_sq(sp.sub(o, sp.scale(o_along, w1))))
        elif "o" in g:
            ball = ball + m.sqrt(sp.norm_sq(g["o"]))
        if "tool" in g:
            ball = ball + m.sqrt(sp.norm_sq(g["tool"]))
        centre = sp.add(g["q1"], sp.scale(along, w1))
        half = tuple(
            ball if isinstance(circle, float) and circle == 0.0 else
            ball + circle * math.sqrt(max(0.0, 1.0 - w1[k] * w1[k]))
            for k in range(3)
        )  # fmt: skip
        return centre, half

    # --- the steps -----------------------------------------------------------------------
    def _solved_point(self, m, p, g):
        """The target's point, where the target puts the solved point and, for a pose, the
        columns of its rotation (RPY, seed 004's eq. 3.15; None for a point)."""
        pos = tuple(p[:3])
        if not self.pose_input:
            return pos, pos, None
        cols = rpy_columns(m, *p[3:6])
        w = sp.add(pos, apply_columns(cols, mat_vec(self._R0T, sp.scale(-1.0, g["tool"]))))
        return pos, tuple(m.let(f"w{c}", v) for c, v in zip("xyz", w, strict=True)), cols

    def _reach(self, m, g, pos, w, tol):
        """The reach box of the tool point and, with the shoulder on the waist axis (3R),
        the reach shells of the solved point: the refusals and the context of the later
        steps (``outer``, ``inner``; ``d2``, ``d``, ``beyond``, ``within`` if global)."""
        m.section("reach box: no configuration puts the tool farther from its centre")
        centre, half = self._box(m, g)
        rel = sp.sub(pos, centre)
        out_box = [m.gt(m.abs(c), half[k] + tol) for k, c in enumerate(rel)]
        refusals = [(Status.OUT_OF_REACH, m.any_(*out_box))]
        la, lb = g["la"], g["lb"]
        ctx = {"outer": m.let("outer", la + lb), "inner": m.let("inner", m.abs(la - lb)),
               "d": None}  # fmt: skip
        if self.global_reach:
            m.section("reach: |La - Lb| <= |P - S| <= La + Lb (the shoulder is on the waist axis)")
            ds = sp.sub(w, g["S"])
            d2 = sp.norm_sq(ds) if self.h_zero else sp.norm_sq(ds) - g["h"] * g["h"]
            ctx["d2"] = m.let("d2", d2)
            ctx["d"] = m.let("d", m.sqrt(ctx["d2"]))
            ctx["beyond"] = m.let("beyond", ctx["d"] - ctx["outer"])
            ctx["within"] = m.let("within", ctx["inner"] - ctx["d"])
            refusals.append((Status.OUT_OF_REACH, m.gt(ctx["beyond"], tol)))
            refusals.append((Status.INSIDE_REACH, m.gt(ctx["within"], tol)))
        return refusals, ctx

    def _waist(self, m, g, w, tol, axis_tol, theta1_on_axis, refusals, ctx):
        """theta1 per side (PK1, or PK3 against a plane with a lateral offset): ``{side:
        {theta1, c1, s1, w}}`` with ``w`` the solved point turned back to theta1 = 0, and
        the signed distance inside the cylinder of a lateral offset (None without)."""
        m.section("theta1: the waist turns the target into the arm plane (PK1 / PK3 on a plane)")
        w1, e, g1 = self._w1, self._e, self._g1
        x = sp.sub(w, g["q1"])
        X1 = m.let("x_fwd", sp.dot(x, g1))
        X2 = m.let("x_side", sp.dot(x, e))
        xa = m.let("x_axial", sp.dot(x, w1))
        rho2 = m.let("rho2", X1 * X1 + X2 * X2)
        rho = m.let("rho", m.sqrt(rho2))
        ell, cyl = 0.0, None
        if not self.lateral_zero:
            ell = m.let("lateral", (g["hq1"] - sp.mul(self._uw1, xa)) / self._nu)
            cyl = m.let("inside_cylinder", m.abs(ell) - rho)
            refusals.append((Status.INSIDE_REACH, m.gt(cyl, tol)))
        on_axis = m.le(rho, axis_tol)
        if theta1_on_axis is None:
            refusals.append((Status.BASE_AXIS, on_axis))
        if self.global_reach:
            refusals.append((Status.DEGENERATE, m.le(ctx["d"], axis_tol)))
        safe_rho = m.select(on_axis, 1.0, rho)
        k = self.kappa
        sides = {}
        for side, sign in (("front", k), ("back", -k)):
            if self.lateral_zero:
                F = sign * rho
                if side == "front":
                    th = m.atan2(X2 if k > 0 else -X2, X1 if k > 0 else -X1)
                else:
                    th = sides["front"]["theta1"] + m.pi
                c1, s1 = sign * X1 / safe_rho, sign * X2 / safe_rho
            else:
                F = sign * sp.waist_offset(m, rho2, ell)
                Y, X = F * X2 - ell * X1, F * X1 + ell * X2
                th = m.atan2(Y, X)
                c1, s1 = X / (safe_rho * safe_rho), Y / (safe_rho * safe_rho)
            if theta1_on_axis is not None:
                t_axis = theta1_on_axis if side == "front" else theta1_on_axis + m.pi
                th = m.select(on_axis, t_axis, th)
                F = m.select(on_axis, 0.0, F)
                c1 = m.select(on_axis, m.cos(t_axis), c1)
                s1 = m.select(on_axis, m.sin(t_axis), s1)
            th = m.let(f"theta1_{side}", m.wrap(th))
            F = m.let(f"forward_{side}", F)
            c1, s1 = m.let(f"cos_theta1_{side}", c1), m.let(f"sin_theta1_{side}", s1)
            # the solved point with the waist turned back to q1 = 0
            w1p = sp.add(g["q1"], sp.add(sp.scale(F, g1), sp.scale(xa, w1)))
            if not self.lateral_zero:
                w1p = sp.add(w1p, sp.scale(ell, e))
            sides[side] = {"theta1": th, "c1": c1, "s1": s1, "w": w1p}
        return sides, cyl

    def _pitch(self, m, a1, tag: str):
        """The pitch ``psi`` about the parallel axes that turns the roll axis (axis 5; at
        q = 0 ``w5``) onto ``a1`` (PK1), with its cosine and sine and the length of
        ``a1``'s part across the parallel axes (0: no pitch turns it)."""
        u = self._u
        yp = sp.dot(u, sp.cross(self._w5, a1))
        xp = sp.dot(self._w5x, a1)
        psi = m.let(f"psi_{tag}", m.atan2(yp, xp))
        r5 = m.sqrt(yp * yp + xp * xp)
        safe5 = m.select(m.gt(r5, 0.0), r5, 1.0)
        cp, spsi = m.let(f"cos_psi_{tag}", xp / safe5), m.let(f"sin_psi_{tag}", yp / safe5)
        return psi, cp, spsi, r5

    def _plane(self, m, g, v, tag: str, ctx, tol, axis_tol, precise):
        """The solved point of the arm plane for pitch ``v["cp"], v["sp"]`` (axis 4's point;
        3R, 6R-wrist: the solved point), its reach (PK3's shells) and the bend at the elbow:
        ``v["conds"]`` (what only this branch cannot do) and ``v["outside"]`` are added,
        and the elbow's ``(t, c, gamma, sin gamma)``, returned."""
        u = self._u
        if self.n_parallel == 3:
            target = sp.sub(v["w"], sp.rotate(u, g["o"], v["cp"], v["sp"]))
        else:
            target = v["w"]
        m.section(f"{tag}: the elbow (PK3: law of cosines), the shoulder (PK1)")
        t = sp.across(u, sp.sub(target, g["S"]))
        conds = v.setdefault("conds", [])
        if ctx["d"] is None:
            d2 = m.let(f"d2_{tag}", sp.norm_sq(t))
            d = m.let(f"d_{tag}", m.sqrt(d2))
            beyond = m.let(f"beyond_{tag}", d - ctx["outer"])
            within = m.let(f"within_{tag}", ctx["inner"] - d)
            conds += [
                (Status.OUT_OF_REACH, m.gt(beyond, tol)),
                (Status.INSIDE_REACH, m.gt(within, tol)),
                (Status.DEGENERATE, m.le(d, axis_tol)),
            ]
            v["outside"] = m.select(m.gt(beyond, within), beyond, within)
        else:
            d2 = ctx["d2"]
        if self.family == "5R":  # the roll axis along the parallel axes: no pitch
            conds.append((Status.DEGENERATE, m.le(v["r5"], 1e-12)))
        c, gam, sg = sp.pk3_cos(m, d2, g["la2"], g["lb2"], g["la"], g["lb"], precise=precise)
        return t, m.let(f"cos_bend_{tag}", c), m.let(f"bend_{tag}", gam), sg

    def _elbow(self, m, g, t, c, gam, sg, s, v, tag, elbow, turns=None):
        """Joints 2.. of one branch: the bend ``s * gamma`` (PK3's root), the shoulder by
        PK1 onto the solved point, the last parallel joint from the pitch. A list ``turns``
        receives the cosines and sines of joints 2 and 3 (for a wrist that follows), from
        PK1's arguments and the bend's own cosine and sine: no trigonometry."""
        st = self.structure
        u = self._u
        la, lb = g["la"], g["lb"]
        if self.bend_zero:  # the forearm continues the upper arm at q = 0
            cb, sb = c, s * sg
        else:
            c0, s0 = g["ab"] / (la * lb), g["axb"] / (la * lb)
            cb, sb = c * c0 + (s * sg) * s0, (s * sg) * c0 - c * s0
        vec = sp.add(g["a"], sp.rotate(u, g["b"], cb, sb))  # shoulder -> wrist at q2 = 0
        sig = st.sigma
        if turns is None:
            phi2 = sp.pk1(m, u, vec, t)
        else:
            phi2, c2, s2 = sp.pk1_cs(m, u, vec, t)
            # cos/sin of q3 = sig3 (s gamma - beta0), beta0 = atan2(axb, ab): (cb, -sb) the
            # bend's cos and sin seen from the upper arm turned back by beta0
            turns += [(c2, sp.mul(sig[0], s2)), (cb, sp.mul(sig[1], sb))]
        q2 = m.let(f"theta2_{tag}_{elbow}", m.wrap(sig[0] * phi2))
        if self.bend_zero:
            q3 = sig[1] * (s * gam)
        else:
            q3 = m.wrap(sig[1] * (s * gam - m.atan2(g["axb"], g["ab"])))
        q3 = m.let(f"theta3_{tag}_{elbow}", q3)
        if self.n_parallel == 2:
            return (q2, q3)
        return (q2, q3, m.wrap(sig[2] * ((v["psi"] - sig[0] * q2) - sig[1] * q3)))
