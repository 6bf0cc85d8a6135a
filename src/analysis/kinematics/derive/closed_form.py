"""The derived closed form: one object with the contract of :mod:`analysis.kinematics.arms`.

:class:`DerivedClosedForm` is what :func:`analysis.kinematics.derive.derive` returns for a
description of a supported family: ``BRANCHES``, ``INPUTS``, ``check``, ``geometry``,
``ik(m, p, P, ...)`` and ``refusal`` as a hand-written closed-form module has them, so the
shared solver, the compiled kernel, the float32 model, SymPy and the PLC programs run it
unchanged. ``ik`` is the subproblem decomposition of :mod:`analysis.kinematics.derive`
(its docstring gives the steps), written against the math namespace ``m``; the lengths come
from ``P`` through the description's D-H rows at every call, so a changed parameter
(``Arm.with_``) or a traced one (the compiled kernel) is used as it is.
"""

from __future__ import annotations

import math

import numpy as np

from analysis.kinematics.derive import subproblems as sp
from analysis.kinematics.derive.chain import home
from analysis.kinematics.derive.families import Structure
from analysis.kinematics.rpy import rpy_columns
from analysis.kinematics.status import Status

__all__ = ["BRANCHES", "DerivedClosedForm"]

BRANCHES = ("front-up", "front-down", "back-up", "back-down")
"""The waist facing the target (front) or turned by about pi (back), the elbow up or down
(:mod:`analysis.kinematics.derive`: how up is seen is the description's ``elbow``)."""
_POSE = ("px", "py", "pz", "alpha", "beta", "gamma")
PROJECTION_HINT = "orientation_tol=None gives the nearest reachable orientation"


def _mat_vec(M, v) -> tuple:
    """A numeric matrix times a vector of values."""
    return tuple(sp.dot(tuple(float(x) for x in row), v) for row in M)


def _fmt(p) -> str:
    return "(" + ", ".join(f"{float(v):g}" for v in p) + ")"


class DerivedClosedForm:
    """A closed form derived from a D-H table (see the module docstring).

    Parameters
    ----------
    name : str
        ``"derived:<digest>"``, the name :func:`analysis.kinematics.arms.closed_form` finds
        it by (the compiled kernels are cached by it).
    description : ArmDescription
        The description it was derived from (its rows; its values decide the signs below).
    structure : Structure
        The family and its numbers (:func:`analysis.kinematics.derive.families.classify`).
    """

    BRANCHES = BRANCHES

    def __init__(self, name: str, description, structure: Structure) -> None:
        self.__name__ = name
        self.description = description
        self.structure = st = structure
        self.family = st.family
        self.INPUTS = _POSE if st.family == "5R" else ("px", "py", "pz")
        self.INPUT_UNITS = ("mm",) * 3 + (("rad",) * 3 if st.family == "5R" else ())
        self.STATUSES = (
            Status.OUT_OF_REACH,
            Status.INSIDE_REACH,
            Status.BASE_AXIS,
            Status.DEGENERATE,
            *((Status.ORIENTATION,) if st.family == "5R" else ()),
        )
        """The refusals ``ik`` can give (joint limits and non-finite inputs are the shared
        solver's)."""
        if st.family == "5R":
            self.ORIENTATION_TOL_RAD = st.orientation_tol
            self.PROJECTION_HINT = PROJECTION_HINT
            self.ik = self.ik_pose
        if st.family == "4R-kept":
            self.sample_q = self._sample_kept
        w1, u = st.waist, st.u
        self._w1, self._u = tuple(w1), tuple(u)
        self._uw1 = float(np.dot(u, w1))
        up = u - self._uw1 * w1
        self._nu = float(np.linalg.norm(up))
        self._e = tuple(up / self._nu)
        self._g1 = tuple(np.cross(up / self._nu, w1))
        if st.roll is not None:
            r = st.roll
            self._w5 = tuple(r)
            self._c5 = float(np.dot(u, r))
            self._w5x = tuple(r - self._c5 * u)  # the roll axis across the parallel axes
            n5 = np.cross(r, u)
            self._n5 = tuple(n5 / np.linalg.norm(n5))
            self._R0T = st.rotation.T
        # structural zeros of the home geometry and signs of the description's values
        self._decide()

    # --- the home geometry, in any namespace --------------------------------------------
    def _points(self, m, P) -> dict:
        """Points and lengths of the chain at q = 0 in namespace ``m`` [mm]."""
        st = self.structure
        h = home(m, self.description.dh_table(dict(P)))
        q1, q2, q3 = h.points[:3]
        u, w1 = self._u, self._w1
        w0 = sp.sub(q1, q2)
        t = (sp.dot(u, w0) - self._uw1 * sp.dot(w1, w0)) / (1.0 - self._uw1 * self._uw1)
        S = sp.add(q2, sp.scale(t, u))  # the point of axis 2 nearest the waist axis
        g = {"q1": q1, "S": S, "p0": h.position}
        if st.family == "3R":
            wrist = h.position
            g["wh"] = h.position
        else:
            wrist = h.points[3]
            if st.family == "5R":
                q5 = h.points[4]
                w5h = sp.add(q5, sp.scale(sp.dot(self._w5, sp.sub(h.position, q5)), self._w5))
                g["wh"] = w5h
                g["tool"] = sp.sub(h.position, w5h)  # tool point from the roll axis
            else:
                g["wh"] = h.position
            g["o"] = sp.sub(g["wh"], wrist)  # the solved point from axis 4 (turns with psi)
        a = sp.across(u, sp.sub(q3, S))
        b = sp.across(u, sp.sub(wrist, q3))
        g.update(a=a, b=b, la2=sp.norm_sq(a), lb2=sp.norm_sq(b))
        g["la"], g["lb"] = m.sqrt(g["la2"]), m.sqrt(g["lb2"])
        g["ab"], g["axb"] = sp.dot(a, b), sp.dot(u, sp.cross(a, b))
        g["h"] = sp.dot(u, sp.sub(g["wh"], S))  # the solved point's offset along the axes
        g["hq1"] = sp.dot(u, sp.sub(g["wh"], q1))
        return g

    def _decide(self) -> None:
        """Structural zeros and signs, decided once per description.

        A quantity is structurally zero when it vanishes for every value of the parameters
        (a shoulder on the waist axis because the table's offsets are 0, not because a
        parameter happens to be): it is evaluated at three seeded random sets of parameter
        values, and an expression in the lengths that is not identically zero vanishes at
        random points with probability 0 (the Schwartz-Zippel test); below 1e-6 mm at
        parameters of +-1000 mm counts as zero (literal numbers of the rows are not drawn:
        an offset written as 1e-7 mm is taken as 0). Signs (which way is
        forward, whether the forearm continues the upper arm) come from the description's
        values."""
        from analysis.kinematics.ops import numpy_ops

        rng = np.random.default_rng(20260101)
        names = list(self.description.parameters)
        draws = [rng.uniform(-1000.0, 1000.0, len(names)) for _ in range(3)]
        probes = [self._points(numpy_ops, dict(zip(names, v, strict=True))) for v in draws]

        def zero(fn) -> bool:
            return all(abs(float(fn(g))) <= 1e-9 * 1000.0 for g in probes)

        g = self._points(numpy_ops, self.description.values)
        st = self.structure
        self.lateral_zero = self._uw1 == 0.0 and zero(lambda q: q["hq1"])
        self.h_zero = zero(lambda q: q["h"])
        self.shoulder_on_axis = all(
            zero(lambda q, i=i: sp.cross(self._w1, sp.sub(q["S"], q["q1"]))[i]) for i in range(3)
        )
        self.bend_zero = zero(lambda q: q["axb"]) and float(g["ab"]) > 0
        self.global_reach = st.family == "3R" and self.shoulder_on_axis
        # the forward direction (its sign along g1 = e x w1): the description's; else where
        # the tool points from the waist axis at q = 0; else (a tool on the plane of the
        # waist and the parallel axes, an arm upright at q = 0) the x axis of D-H frame 1,
        # the common normal of axes 1 and 2 (theta1 = 0 faces it)
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
            from analysis.kinematics.derive.families import NotDerivable

            raise NotDerivable(
                f"{where}: no component along the arm's forward axis {_fmt(self._g1)} "
                "(across the waist and the parallel axes): say which way is front with "
                "[derive] forward = [x, y, z]"
            )
        self.kappa = 1.0 if f > 0 else -1.0
        k = self.kappa
        self.s_up = {"front": k, "back": k if st.elbow == "arm" else -k}
        self.orient_global = (
            st.family == "5R" and self.lateral_zero and self._uw1 == 0.0 and self._c5 == 0.0
        )

    # --- the contract ---------------------------------------------------------------------
    def _sample_kept(self, rng, n: int, P, bounds):
        """Candidate configurations (n, 4) [rad] of a 4R-kept arm (the contract's
        ``sample_q`` hook): joints 1-3 uniform within ``bounds`` (n_joints, 2), joint 4 the
        kept pitch, ``q4 = s4 (psi - s2 q2 - s3 q3)``, wrapped to (-pi, pi]."""
        b = np.asarray(bounds, dtype=float)
        q = b[:3, 0] + rng.random((n, 3)) * (b[:3, 1] - b[:3, 0])
        s, psi = self.structure.sigma, self.structure.keep[0]
        q4 = s[2] * (psi - s[0] * q[:, 1] - s[1] * q[:, 2])
        return np.concatenate([q, (np.mod(q4 + np.pi, 2 * np.pi) - np.pi)[:, None]], axis=1)

    @property
    def STARTUP_TARGET(self):
        """The example target a generated PLC program writes on its first scan: the tool
        at a seeded configuration within the joint limits that the default branch solves
        back, rounded (0.1 mm, 1e-6 rad); None if none of 200 does."""
        if not hasattr(self, "_startup"):
            self._startup = self._find_startup()
        return self._startup

    def _find_startup(self):
        from analysis.kinematics.ops import numpy_ops
        from analysis.kinematics.rpy import pose_from_transform
        from analysis.kinematics.solution import DEFAULT_TOL_MM

        desc = self.description
        lo = np.array([max(j.lower, -math.pi) for j in desc.joints])
        hi = np.array([min(j.upper, math.pi) for j in desc.joints])
        q = np.random.default_rng(0).uniform(lo, hi, (200, len(lo)))
        if self.family == "4R-kept":
            sig, psi = self.structure.sigma, self.structure.keep[0]
            q[:, 3] = sig[2] * (psi - sig[0] * q[:, 1] - sig[1] * q[:, 2])
        T = desc.dh_table().fk(q)
        if self.family == "5R":
            pose = pose_from_transform(T)
            p = np.concatenate([np.round(pose[:, :3], 1), np.round(pose[:, 3:], 6)], axis=1)
        else:
            p = np.round(T[:, :3, 3], 1)
        with np.errstate(all="ignore"):
            r = self.ik(numpy_ops, tuple(p.T), desc.values, tol=DEFAULT_TOL_MM)
        b = BRANCHES[0]
        refused = np.zeros(len(p), dtype=bool)
        for _, cond in (*r["refusals"], *r.get("branch_refusals", {}).get(b, ())):
            refused |= np.broadcast_to(np.asarray(cond, dtype=bool), refused.shape)
        q = np.stack([np.broadcast_to(v, refused.shape) for v in r["branches"][b]], axis=-1)
        inside = np.all((q >= lo - 1e-12) & (q <= hi + 1e-12), axis=-1)
        good = np.flatnonzero(~refused & inside)
        return tuple(float(v) for v in p[good[0]]) if good.size else None

    def check(self, P) -> None:
        """Reject lengths the closed form cannot use (ValueError naming the value)."""
        from analysis.kinematics.ops import numpy_ops

        g = self._points(numpy_ops, P)
        for key, what in (("la", "upper arm (axis 2 to axis 3)"), ("lb", "forearm")):
            v = float(g[key])
            if not v > 1e-9:
                raise ValueError(
                    f"arm {self.description.name}: the {what} has length {v:g} mm across the "
                    "parallel axes; the derived closed form needs it > 0 mm"
                )

    def geometry(self, P) -> dict:
        """The shoulder (axis 2 nearest the waist axis), the reach radii of the solved point
        in the arm plane and the largest distance of the tool from the box centre [mm]."""
        from analysis.kinematics.ops import numpy_ops

        g = self._points(numpy_ops, P)
        la, lb = float(g["la"]), float(g["lb"])
        centre, half = self._box(numpy_ops, g)
        out = {
            "shoulder": tuple(float(v) for v in g["S"]),
            "reach_outer": la + lb,
            "reach_inner": abs(la - lb),
            "reach_tool": max(float(v) for v in half),
            "box_centre": tuple(float(v) for v in centre),
            "box_half": tuple(float(v) for v in half),
        }
        if "tool" in g:  # 5R: the tool point's distance from the roll axis
            out["tool_offset"] = float(np.sqrt(float(sp.norm_sq(g["tool"]))))
        return out

    def _box(self, m, g):
        """Centre and half-sizes [mm] per base coordinate of a box the tool never leaves:
        an early refusal before any square (no REAL overflow in the PLC). The solved point
        lies within ``la + lb`` of the shoulder across the axes and ``|h|`` along them
        (a ball); what turns with the waist only (a shoulder off the waist axis, the tool
        offset of a kept pitch) sweeps a circle about the waist axis, which adds its radius
        times ``sqrt(1 - w1_k^2)`` to coordinate k and shifts the centre along the axis."""
        w1 = self._w1
        ball = (g["la"] + g["lb"]) + m.sqrt(g["h"] * g["h"])
        circle = 0.0
        rel = sp.sub(g["S"], g["q1"])
        along = sp.dot(w1, rel)
        circle = m.sqrt(sp.norm_sq(sp.sub(rel, sp.scale(along, w1))))
        if self.shoulder_on_axis:
            circle = 0.0
        if self.structure.family == "4R-kept":
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

    def ik(
        self, m, p, P, *, tol, axis_tol=None, margin_rad=0.0, theta1_on_axis=None, precise=False
    ):
        """The closed form of a point arm (3R, 4R-kept): :meth:`solve` (a 5R arm's ``ik`` is
        :meth:`ik_pose`, set in ``__init__``: the contract reads an arm's options off the
        signature of its ``ik``). ``margin_rad`` has no angular tolerance to narrow here."""
        return self.solve_target(m, p, P, tol=tol, axis_tol=axis_tol,
                                 theta1_on_axis=theta1_on_axis, precise=precise)  # fmt: skip

    def ik_pose(
        self,
        m,
        p,
        P,
        *,
        tol,
        axis_tol=None,
        margin_rad=0.0,
        theta1_on_axis=None,
        orientation_tol="default",
        precise=False,
    ):
        """The closed form of a 5R arm (a pose): :meth:`solve`."""
        return self.solve_target(
            m, p, P, tol=tol, axis_tol=axis_tol, margin_rad=margin_rad,
            theta1_on_axis=theta1_on_axis, orientation_tol=orientation_tol, precise=precise,
        )  # fmt: skip

    def solve_target(
        self,
        m,
        p,
        P,
        *,
        tol,
        axis_tol=None,
        margin_rad=0.0,
        theta1_on_axis=None,
        orientation_tol="default",
        precise=False,
    ):
        """All four branches for target ``p`` (a point [mm]; a 5R arm: a pose, position [mm]
        and RPY angles [rad] of seed 004's eq. 3.14), in namespace ``m``.

        Returns ``branches`` {name: (q1..qn)} [rad], ``refusals`` [(Status, condition)] in
        priority order, ``branch_refusals`` {name: [...]} where the front and back solutions
        differ, ``outside`` (signed distance outside the reach [mm]) and ``wrist``
        {"front"/"back": (forward, height) of the solved point in the arm plane}. ``tol``,
        ``axis_tol``, ``margin_rad`` and ``theta1_on_axis`` as for every closed form
        (:mod:`analysis.kinematics.arms`); ``orientation_tol`` (5R) [rad]: the largest
        accepted angle of the roll axis out of reach, None to project onto the nearest;
        ``precise``: the bend from 1 -/+ cos in factored form (:func:`.subproblems.pk3_cos`).
        """
        st = self.structure
        axis_tol = tol if axis_tol is None else axis_tol
        g = self._points(m, P)
        u, w1, e, g1 = self._u, self._w1, self._e, self._g1
        refusals, branch_refusals = [], {}
        pos = tuple(p[:3])
        if st.family == "5R":
            cols = rpy_columns(m, *p[3:6])

            def R(v):  # the requested orientation applied to a (numeric) vector
                return sp.add(sp.add(sp.scale(v[0], cols[0]), sp.scale(v[1], cols[1])),
                              sp.scale(v[2], cols[2]))  # fmt: skip

            # the point of the roll axis nearest the tool, where the pose puts it
            w = sp.add(pos, R(_mat_vec(self._R0T, sp.scale(-1.0, g["tool"]))))
            w = tuple(m.let(f"w{c}", v) for c, v in zip("xyz", w, strict=True))
        else:
            w = pos
        m.section("reach box: no configuration puts the tool farther from its centre")
        centre, half = self._box(m, g)
        rel = sp.sub(pos, centre)
        out_box = [m.gt(m.abs(c), half[k] + tol) for k, c in enumerate(rel)]
        refusals.append((Status.OUT_OF_REACH, m.any_(*out_box)))
        la, lb = g["la"], g["lb"]
        outer = m.let("outer", la + lb)
        inner = m.let("inner", m.abs(la - lb))
        d_global = None
        if self.global_reach:
            m.section("reach: |La - Lb| <= |P - S| <= La + Lb (the shoulder is on the waist axis)")
            ds = sp.sub(pos, g["S"])
            d2 = sp.norm_sq(ds) if self.h_zero else sp.norm_sq(ds) - g["h"] * g["h"]
            d2_global = m.let("d2", d2)
            d_global = m.let("d", m.sqrt(d2_global))
            beyond_g = m.let("beyond", d_global - outer)
            within_g = m.let("within", inner - d_global)
            refusals.append((Status.OUT_OF_REACH, m.gt(beyond_g, tol)))
            refusals.append((Status.INSIDE_REACH, m.gt(within_g, tol)))
        m.section("theta1: the waist turns the target into the arm plane (PK1 / PK3 on a plane)")
        x = sp.sub(w, g["q1"])
        X1 = m.let("x_fwd", sp.dot(x, g1))
        X2 = m.let("x_side", sp.dot(x, e))
        xa = m.let("x_axial", sp.dot(x, w1))
        rho2 = m.let("rho2", X1 * X1 + X2 * X2)
        rho = m.let("rho", m.sqrt(rho2))
        ell = 0.0
        cyl = None
        if not self.lateral_zero:
            ell = m.let("lateral", (g["hq1"] - self._uw1 * xa) / self._nu)
            cyl = m.let("inside_cylinder", m.abs(ell) - rho)
            refusals.append((Status.INSIDE_REACH, m.gt(cyl, tol)))
        on_axis = m.le(rho, axis_tol)
        if theta1_on_axis is None:
            refusals.append((Status.BASE_AXIS, on_axis))
        if self.global_reach:
            refusals.append((Status.DEGENERATE, m.le(d_global, axis_tol)))
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
        if st.family == "5R":
            a_req = R(_mat_vec(self._R0T, self._w5))  # where the pose puts the roll axis
            for side, v in sides.items():
                v["a"] = sp.rotate(w1, a_req, v["c1"], -v["s1"])
                v["off"] = m.let(f"off_{side}", sp.dot(u, v["a"]) - self._c5)
            tol_o = st.orientation_tol if orientation_tol == "default" else orientation_tol
            limit = None
            if tol_o is not None:
                narrowed = float(tol_o) - float(margin_rad)
                if not narrowed > 0:
                    raise ValueError(
                        f"orientation_tol = {tol_o} rad leaves nothing after the margin "
                        f"{margin_rad} rad"
                    )
                limit = math.sin(min(narrowed, math.pi / 2))
            if self.orient_global and limit is not None:
                m.section("orientation: the roll axis must lie in the arm plane")
                refusals.append((Status.ORIENTATION, m.gt(m.abs(sides["front"]["off"]), limit)))
        for side, v in sides.items():
            conds = []
            if st.family == "5R":
                m.section(f"{side}: the pitch about the parallel axes (PK1), the roll (PK1)")
                if limit is not None and not self.orient_global:
                    conds.append((Status.ORIENTATION, m.gt(m.abs(v["off"]), limit)))
                a1 = v["a"]
                yp = sp.dot(u, sp.cross(self._w5, a1))
                xp = sp.dot(self._w5x, a1)
                psi = m.let(f"psi_{side}", m.atan2(yp, xp))
                r5 = m.sqrt(yp * yp + xp * xp)
                safe5 = m.select(m.gt(r5, 0.0), r5, 1.0)
                cp, spsi = (
                    m.let(f"cos_psi_{side}", xp / safe5),
                    m.let(f"sin_psi_{side}", yp / safe5),
                )
                n_req = R(_mat_vec(self._R0T, self._n5))
                n1 = sp.rotate(u, sp.rotate(w1, n_req, v["c1"], -v["s1"]), cp, -spsi)
                v["q5"] = m.wrap(sp.pk1(m, self._w5, self._n5, n1))
                v["psi"] = psi
                v["r5"] = r5
            elif st.family == "4R-kept":
                psi, cp, spsi = st.keep
                v["psi"] = psi
            if st.family != "3R":
                target = sp.sub(v["w"], sp.rotate(u, g["o"], cp, spsi))
            else:
                target = v["w"]
            m.section(f"{side}: the elbow (PK3: law of cosines), the shoulder (PK1)")
            t = sp.across(u, sp.sub(target, g["S"]))
            if d_global is None:
                d2 = m.let(f"d2_{side}", sp.norm_sq(t))
                d = m.let(f"d_{side}", m.sqrt(d2))
                beyond = m.let(f"beyond_{side}", d - outer)
                within = m.let(f"within_{side}", inner - d)
                conds += [
                    (Status.OUT_OF_REACH, m.gt(beyond, tol)),
                    (Status.INSIDE_REACH, m.gt(within, tol)),
                    (Status.DEGENERATE, m.le(d, axis_tol)),
                ]
                v["outside"] = m.select(m.gt(beyond, within), beyond, within)
            else:
                d2 = d2_global
            if st.family == "5R":  # the roll axis along the parallel axes: no pitch
                conds.append((Status.DEGENERATE, m.le(v["r5"], 1e-12)))
            v["conds"] = conds
            c, gam, sg = sp.pk3_cos(m, d2, g["la2"], g["lb2"], la, lb, precise=precise)
            c = m.let(f"cos_bend_{side}", c)
            gam = m.let(f"bend_{side}", gam)
            for elbow in ("up", "down"):
                s = self.s_up[side] * (1.0 if elbow == "up" else -1.0)
                v[elbow] = self._elbow(m, g, t, c, gam, sg, s, v, side, elbow)
        if st.family == "5R" or d_global is None:
            for side, v in sides.items():
                for elbow in ("up", "down"):
                    branch_refusals[f"{side}-{elbow}"] = v["conds"]
        branches = {
            f"{side}-{elbow}": (v["theta1"], *v[elbow]) for side, v in sides.items()
            for elbow in ("up", "down")
        }  # fmt: skip
        if d_global is not None:
            outside = m.select(m.gt(beyond_g, within_g), beyond_g, within_g)
        else:
            of, ob = sides["front"]["outside"], sides["back"]["outside"]
            outside = m.select(m.lt(of, ob), of, ob)
        if cyl is not None:
            outside = m.select(m.gt(cyl, tol), cyl, outside)
        out = {"branches": branches, "refusals": refusals, "outside": outside}
        if branch_refusals:
            out["branch_refusals"] = branch_refusals
        out["wrist"] = {s: (v["w"]) for s, v in sides.items()}
        if st.family == "5R":
            out["off_plane"] = sides["front"]["off"]
        return out

    def _elbow(self, m, g, t, c, gam, sg, s, v, side, elbow):
        """Joints 2.. of one branch: the bend ``s * gamma`` (PK3's root), the shoulder by
        PK1 onto the solved point, the last parallel joint from the kept pitch, the roll."""
        st = self.structure
        u = self._u
        la, lb = g["la"], g["lb"]
        if self.bend_zero:  # the forearm continues the upper arm at q = 0
            cb, sb = c, s * sg
        else:
            c0, s0 = g["ab"] / (la * lb), g["axb"] / (la * lb)
            cb, sb = c * c0 + (s * sg) * s0, (s * sg) * c0 - c * s0
        vec = sp.add(g["a"], sp.rotate(u, g["b"], cb, sb))  # shoulder -> wrist at q2 = 0
        phi2 = sp.pk1(m, u, vec, t)
        sig = st.sigma
        q2 = m.let(f"theta2_{side}_{elbow}", m.wrap(sig[0] * phi2))
        if self.bend_zero:
            q3 = sig[1] * (s * gam)
        else:
            q3 = m.wrap(sig[1] * (s * gam - m.atan2(g["axb"], g["ab"])))
        q3 = m.let(f"theta3_{side}_{elbow}", q3)
        if st.family == "3R":
            return (q2, q3)
        q4 = m.wrap(sig[2] * ((v["psi"] - sig[0] * q2) - sig[1] * q3))
        if st.family == "4R-kept":
            return (q2, q3, q4)
        return (q2, q3, q4, v["q5"])

    def refusal(self, status: Status, p, P, *, tol: float, distance: float) -> tuple[str, float]:
        """The one-line reason a target is refused, naming it and the limit crossed, and
        the limit [mm] (NaN where no length is crossed)."""
        from analysis.kinematics.ops import numpy_ops

        geo = self.geometry(P)
        what = "pose" if self.family == "5R" else "target"
        pose = tuple(float(v) for v in p)
        where = f"{what} {_fmt(pose[:3])} mm"
        if self.family == "5R":
            where += f", RPY ({', '.join(f'{math.degrees(v):.4g}' for v in pose[3:])}) deg"
        sh = _fmt(geo["shoulder"])
        if status == Status.OUT_OF_REACH:
            rel = np.abs(np.subtract(pose[:3], geo["box_centre"]))
            over = rel - np.asarray(geo["box_half"])
            if over.max() > tol:
                k = int(np.argmax(over))
                return (
                    f"{where} is {over[k]:.3f} mm beyond the reach of {geo['box_half'][k]:g} mm "
                    f"in {'xyz'[k]} around {_fmt(geo['box_centre'])} mm: no configuration "
                    "reaches it"
                ), geo["box_half"][k]
            return (
                f"{where} puts the wrist {distance:.3f} mm beyond the reach of "
                f"{geo['reach_outer']:g} mm (the two links across the parallel axes) around "
                f"the shoulder at {sh} mm"
            ), geo["reach_outer"]
        if status == Status.INSIDE_REACH:
            if not self.lateral_zero:
                g = self._points(numpy_ops, P)
                x = np.subtract(pose[:3], [float(c) for c in g["q1"]])
                rho = float(np.hypot(np.dot(x, self._g1), np.dot(x, self._e)))
                lat = float(
                    abs((float(g["hq1"]) - self._uw1 * float(np.dot(x, self._w1))) / self._nu)
                )
                if rho < lat - tol:
                    return (
                        f"{where} is {lat - rho:.3f} mm inside the cylinder of radius "
                        f"{lat:g} mm around the waist axis that the arm's lateral offset "
                        "keeps every reachable point out of"
                    ), lat
            return (
                f"{where} puts the wrist {distance:.3f} mm inside the inner reach of "
                f"{geo['reach_inner']:g} mm (|La - Lb|) around the shoulder at {sh} mm"
            ), geo["reach_inner"]
        if status == Status.BASE_AXIS:
            return (
                f"{where} lies on the waist axis (within {tol:g} mm): theta1 is undefined "
                "there; choose the waist angle to use (theta1_on_axis)"
            ), float("nan")
        if status == Status.DEGENERATE:
            return (
                f"{where} puts the wrist on the shoulder axis (the two links are equal): "
                "theta2 is undefined"
            ), 0.0
        if status == Status.ORIENTATION:
            with np.errstate(all="ignore"):
                sol = self.solve_target(numpy_ops, pose, dict(P), tol=tol, orientation_tol=None)
            off = abs(float(sol["off_plane"]))
            return (
                f"{where} asks for a roll axis {math.degrees(math.asin(min(1.0, off))):.3f} deg "
                "out of the set a 5-DOF arm can turn it to (accepted: "
                f"{math.degrees(self.structure.orientation_tol):.2g} deg); {PROJECTION_HINT}"
            ), float("nan")
        raise ValueError(f"no message for status {status!r}")
