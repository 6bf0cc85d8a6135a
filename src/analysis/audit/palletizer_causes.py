"""Seed 001's register (Li & Hu 2021, the 4-axis palletizer): the findings of
:mod:`analysis.audit.palletizer_checks` grouped into root causes, in the schema of
:mod:`analysis.audit.schema`.

Every manifestation's ``verify(text)`` decides a text of the printed notation by a
derivation or a run, never by comparing strings with the correction:

* formulas (SymPy text in the symbols of :data:`analysis.papers.palletizer.SYMBOLS`) are
  held against the product of the printed matrices (eq. 11), Craig's modified D-H transform
  (eq. 8), the elbow angle and the direction of the shoulder-wrist line measured on the
  forward kinematics of the arm (eqs. 3, 4), atan2 on 360 azimuths and the axes (eqs. 1, 6),
  the level gripper (eq. 12);
* claims are put in a small checkable form (a condition, a count, a bound) and evaluated on
  targets of the arm: a grid of the workspace, the four quadrant targets, the initial pose.

Numbers that depend on the lengths use the arm of ``data/arms/palletizer.toml``, whose every
length is ASSUMED (the paper prints none; L1 = L2 is the default family); the evidence says
so. The verdicts do not depend on them (tests/audit/test_palletizer_checks.py runs the checks
with L1 != L2).
"""

from __future__ import annotations

import math
import re
from functools import cache

import numpy as np
import sympy as sp

from analysis.audit import palletizer_checks as chk
from analysis.audit.schema import Cause, Manifestation, Register
from analysis.kinematics.arm import Arm, Status, load_arm
from analysis.kinematics.dh import link_transform_sym
from analysis.papers import palletizer as paper

__all__ = ["register"]

S = paper.SYMBOLS
_FUNCS = {
    "atan": sp.atan,
    "atan2": sp.atan2,
    "asin": sp.asin,
    "acos": sp.acos,
    "sqrt": sp.sqrt,
    "sin": sp.sin,
    "cos": sp.cos,
    "Abs": sp.Abs,
    "pi": sp.pi,
    "Piecewise": sp.Piecewise,
}
ATOL = 1e-9
"""Numeric agreement [mm or rad] for a formula to count as right: float64 chains of a few
transcendental calls on lengths of a few hundred mm err by ~1e-13; every printed error
found is >= 1e-3 (most are degrees or millimetres)."""


# ---------------------------------------------------------------------------------------------
# parsing and evaluation
# ---------------------------------------------------------------------------------------------
def _parse(text: str) -> sp.Expr | None:
    """A SymPy expression of a text ("lhs = rhs" gives rhs), or None if it is not one."""
    rhs = text.split(" = ", 1)[1] if " = " in text else text
    try:
        expr = sp.parse_expr(rhs, local_dict={**S, **_FUNCS}, evaluate=True)
    except Exception:  # any parse failure means: not a formula of this notation
        return None
    if not isinstance(expr, sp.Basic) or {s.name for s in expr.free_symbols} - set(S):
        return None
    return expr


@cache
def _arm() -> Arm:
    return load_arm("palletizer")


@cache
def _targets() -> np.ndarray:
    """Grasp points [mm] the arm solves with its elbow stop: a 21-step grid of the workspace,
    the four quadrant targets, a point whose wrist is behind the base axis (rho < L3) and the
    initial pose (sec. 3)."""
    arm = _arm()
    L1, L2, L3, h = chk.lengths(arm)
    grid = chk.workspace_grid(arm, 21)
    extra = np.vstack([chk.QUADRANT_TARGETS, [[30.0, 10.0, 100.0], [L2 + L3, 0.0, L1 - h]]])
    G = np.vstack([grid, extra])
    return G[arm.solve(G).status == Status.OK]


@cache
def _values() -> dict[str, np.ndarray]:
    """Per target: the inputs, the lengths (primed = unprimed, sec. 3), and, measured on the
    forward kinematics of the shared solver's angles (theta1..theta4, also returned): the
    shoulder-wrist distance L4 (= L4'; eq. 2 is held against it in pal-eq2-holds), the
    included elbow angle beta1, the elevation of the shoulder-wrist line; alpha1 by the law
    of cosines from that L4 (not in dispute)."""
    arm = _arm()
    G = _targets()
    L1, L2, L3, h = chk.lengths(arm)
    q = arm.solve(G).branch("elbow-up")
    frames = arm.frames(q)
    shoulder, elbow, wrist = frames[:, 2], frames[:, 3], frames[:, 4]
    a, b = shoulder - elbow, wrist - elbow
    included = np.arccos(
        np.sum(a * b, -1) / np.linalg.norm(a, axis=-1) / np.linalg.norm(b, axis=-1)
    )
    sw = wrist - shoulder  # the shoulder-wrist line, measured on the arm
    radial = np.hypot(G[:, 0], G[:, 1])
    w_dir = (sw[:, 0] * G[:, 0] + sw[:, 1] * G[:, 1]) / radial
    L4 = np.linalg.norm(sw, axis=-1)
    a1 = np.arccos((L1**2 + L4**2 - L2**2) / (2 * L1 * L4))
    return {
        "X0": G[:, 0],
        "Y0": G[:, 1],
        "Z0": G[:, 2],
        "L1": L1,
        "L2": L2,
        "L3": L3,
        "h": h,
        "L1p": L1,
        "L2p": L2,
        "L3p": L3,
        "L4p": L4,
        "L4": L4,
        "alpha1": a1,
        "beta1": included,
        "elevation": np.arctan2(sw[:, 2], w_dir),
        **{f"theta{i + 1}": q[:, i] for i in range(4)},
    }


def _eval(expr: sp.Expr, values: dict) -> np.ndarray | None:
    """Evaluate ``expr`` on the target values (None if a symbol has no value or the result
    is not finite everywhere: a formula undefined at a target is not right there)."""
    names = sorted(s.name for s in expr.free_symbols)
    if any(n not in values for n in names):
        return None
    f = sp.lambdify([S[n] for n in names], expr, "numpy")
    n_pts = len(values["X0"]) if "X0" in values else 1
    with np.errstate(all="ignore"):
        out = np.broadcast_to(np.asarray(f(*(values[n] for n in names)), dtype=float), (n_pts,))
    return out if np.isfinite(out).all() else None


def _angles_close(a, b, tol: float = ATOL) -> bool:
    return bool(
        np.all(np.abs(np.mod(np.asarray(a) - np.asarray(b) + np.pi, 2 * np.pi) - np.pi) < tol)
    )


def _safe(fn):
    """A verify predicate that answers False instead of raising on a malformed text."""

    def wrapped(text: str) -> bool:
        try:
            return bool(fn(text))
        except Exception:  # a text the predicate cannot read is not a right text
            return False

    return wrapped


def _all_fail(ms) -> bool:
    return all(not m.verify(m.printed) and m.verify(m.corrected) for m in ms)


def _cause(cid, title, status, kind, evidence, ms, demo=None) -> Cause:
    ms = tuple(ms)
    return Cause(cid, title, status, kind, evidence, ms, demo or (lambda: _all_fail(ms)))


@cache
def _found() -> dict:
    return {f.id: f for f in chk.findings(_arm())}


def _dims() -> str:
    return chk.assumed_lengths(_arm())


# ---------------------------------------------------------------------------------------------
# eq. 11 and eq. 8 (the D-H model, symbolic)
# ---------------------------------------------------------------------------------------------
_BAD, _GOOD = "(sin(theta4)*h - sin(theta4)*L3)", "(sin(theta4)*h - cos(theta4)*L3)"


def _residual(rhs: str, derived: sp.Expr) -> str:
    return sp.sstr(sp.factor(sp.expand(paper.parse(rhs) - derived)))


def _eq11() -> list[Cause]:
    derived = chk.derived_tool_position()
    res = chk.eq11_residuals()
    parts = paper.EQUATIONS["eq11"]["parts"]
    where = ("row 1 (t14)", "row 2 (printed label t34)", "row 3 (t34)")
    ms = []
    for k, part in enumerate(parts):

        def ok(text: str, k=k) -> bool:
            e = _parse(text)
            return e is not None and chk._zero(e - derived[k])

        ms.append(
            Manifestation(
                f"pal-eq11-s4l3/row{k + 1}",
                f"eq. 11, {where[k]}",
                f"{part['label']} = {part['rhs']}",
                f"{('t14', 't24', 't34')[k]} = {part['rhs'].replace(_BAD, _GOOD)}",
                f"against entry ({k + 1}, 4) of 0_1T 1_2T 2_3T 3_4T 4_5T (eq. 9, the printed "
                f"matrices): printed - product = {_residual(part['rhs'], derived[k])}",
                _safe(ok),
                "pal-eq11-s4L3",
            )
        )
    arm = _arm()
    L3 = arm.params["L3"]

    def demo() -> bool:
        q = np.random.default_rng(11).uniform(-np.pi, np.pi, (500, 4))
        err = np.linalg.norm(chk.eq11_printed_position(arm, q) - arm.fk(q), axis=-1)
        ref = L3 * np.abs(np.sin(q[:, 3]) - np.cos(q[:, 3]))
        return _all_fail(ms) and np.allclose(err, ref, atol=ATOL) and err.max() > 0.5 * L3

    s4l3 = _cause(
        "pal-eq11-s4l3",
        "eq. 11 prints (s4 h - s4 L3) in all three rows; the product of the printed matrices "
        "gives (s4 h - c4 L3).",
        "error",
        "transcription",
        _found()["pal-eq11-s4L3"].evidence
        + ". The run prints 's4h-s4L3' in every row, so one slip copied three times (or a "
        "shared typeset block), not three extraction accidents.",
        ms,
        demo,
    )

    def label_ok(text: str) -> bool:
        return text.strip() in res[1]["matches"] and text.strip() in ("t14", "t24", "t34")

    label = _cause(
        "pal-eq11-label",
        "eq. 11 labels its second row t34; it is t24 (the y coordinate), as the text after "
        "eq. 10 names the three.",
        "error",
        "label",
        _found()["pal-eq11-label"].evidence,
        [
            Manifestation(
                "pal-eq11-label/row2",
                "eq. 11, row 2 label",
                "t34",
                "t24",
                "Row 2 with c4L3 equals entry (2, 4) of the printed matrices' product "
                f"({res[1]['matches']}); rows 1 and 3 are {res[0]['matches']} and "
                f"{res[2]['matches']}.",
                _safe(label_ok),
                "pal-eq11-label",
            )
        ],
    )
    return [s4l3, label]


_EQ8_CELLS = ((1, 2), (1, 3), (2, 0), (2, 1), (2, 2), (2, 3))


def _eq8() -> Cause:
    craig = link_transform_sym(S["theta_i"], S["d_i"], S["a_im1"], S["alpha_im1"], "modified")
    printed = [paper.MATRICES["eq8"]["rows"][i][j] for i, j in _EQ8_CELLS]

    def ok(text: str) -> bool:
        cells = [c.strip() for c in text.split(",")]
        if len(cells) != len(_EQ8_CELLS):
            return False
        for (i, j), c in zip(_EQ8_CELLS, cells, strict=True):
            e = _parse(c)
            if e is None or not chk._zero(e - craig[i, j]):
                return False
        return True

    fixed = [c.replace("(a_im1)", "(alpha_im1)") for c in printed]
    e8 = chk.eq8_checks()
    return _cause(
        "pal-eq8-glyph",
        "eq. 8 takes sin and cos of the length a_{i-1} where the twist alpha_{i-1} belongs "
        "(rows 2-3); print or extraction cannot be told apart.",
        "uncertain",
        "transcription",
        _found()["pal-eq8-glyph"].evidence,
        [
            Manifestation(
                "pal-eq8-glyph/rows-2-3",
                "eq. 8, rows 2-3 (cells (2,3), (2,4), (3,1)-(3,4))",
                ", ".join(printed),
                ", ".join(fixed),
                "Against Craig's modified link transform Rx(alpha) Tx(a) Rz(theta) Tz(d): as "
                f"printed {e8['eq8 as printed == Craig']}, with alpha for a inside sin/cos "
                f"{e8['eq8 with alpha for a in sin/cos == Craig']}. The same run extracts "
                "'cosαi-1' in row 2, so the glyph can survive; a font-mapping loss of the "
                "others cannot be excluded.",
                _safe(ok),
                "pal-eq8-glyph",
            )
        ],
    )


# ---------------------------------------------------------------------------------------------
# the IK chain (eqs. 1-6, 12)
# ---------------------------------------------------------------------------------------------
@cache
def _azimuths() -> dict[str, np.ndarray]:
    """360 azimuths at radius 200 mm plus the four half-axes (X0 = 0 or Y0 = 0)."""
    az = np.radians(np.arange(-179.5, 180.0, 1.0))
    x = np.concatenate([200 * np.cos(az), [0.0, 0.0, 150.0, -150.0]])
    y = np.concatenate([200 * np.sin(az), [150.0, -150.0, 0.0, 0.0]])
    return {"X0": x, "Y0": y}


def _gamma_ok(text: str, gammap: str | None = "atan(Y0/X0)") -> bool:
    """The waist angle of ``text`` equals atan2(Y0, X0) at 364 points (every quadrant, the
    axes); ``gammap`` is substituted for gamma' (eq. 1) first."""
    e = _parse(text)
    if e is None:
        return False
    if S["gammap"] in e.free_symbols:
        if gammap is None:
            return False
        e = e.subs(S["gammap"], _parse(gammap))
    v = _azimuths()
    names = sorted(s.name for s in e.free_symbols)
    if set(names) - {"X0", "Y0"}:
        return False
    f = sp.lambdify([S[n] for n in names], e, modules=[{"Piecewise": _np_piecewise}, "numpy"])
    with np.errstate(all="ignore"):
        g = np.broadcast_to(np.asarray(f(*(v[n] for n in names)), dtype=float), v["X0"].shape)
    return bool(np.isfinite(g).all()) and _angles_close(g, np.arctan2(v["Y0"], v["X0"]))


def _np_piecewise(*pairs):
    """numpy Piecewise for lambdify: NaN where no case applies (SymPy's own choice)."""
    out = None
    for value, cond in reversed(pairs):
        value = np.asarray(value, dtype=float)
        out = np.where(cond, value, np.nan if out is None else out)
    return out


def _eq6() -> Cause:
    rhs = paper.EQUATIONS["eq6"]["parts"][0]["rhs"]
    f = _found()["pal-eq6-quadrant"]
    signed = Manifestation(
        "pal-eq6-quadrant/eq6-signed",
        "eq. 6 (gamma' = arctan(Y0/X0) of eq. 1, signed)",
        f"gamma = {rhs}",
        "gamma = atan2(Y0, X0)",
        "Held against atan2 at 360 azimuths and on the four half-axes: wrong for X0 < 0 "
        "(quadrants 2 and 3: pi - gamma' and -pi/2 + gamma' with the signed arctan), "
        "undefined at X0 = 0 (eq. 1 divides by zero) and on the negative X axis (no case).",
        _safe(_gamma_ok),
        "pal-eq6-quadrant",
    )
    acute = Manifestation(
        "pal-eq6-quadrant/eq6-acute",
        "eq. 6 (gamma' read as the acute angle arctan|Y0/X0| of Figure 4)",
        f"gamma = {rhs.replace('gammap', 'atan(Abs(Y0/X0))')}",
        "gamma = atan2(Y0, X0)",
        "The reading Figure 4 (lost) may intend: quadrants 1-2 right, quadrants 3 and 4 wrong "
        "(-pi/2 + gamma' should be -pi + gamma' in quadrant 3, and the X0 > 0 case gives "
        "+gamma' in quadrant 4). Undefined on the axes as above.",
        _safe(lambda t: _gamma_ok(t, None)),
        "pal-eq6-quadrant",
    )
    eq1 = Manifestation(
        "pal-eq6-quadrant/eq1",
        "eq. 1",
        "gammap = atan(Y0/X0)",
        "gammap = atan2(Y0, X0)",
        "eq. 1's quotient is undefined at X0 = 0, which eq. 6's cases X0 <= 0 include, and "
        "loses the quadrant that eq. 6 then tries to restore; with atan2 eq. 6 is not needed.",
        _safe(lambda t: _gamma_ok(t.replace("gammap = ", "gamma = "), None)),
        "pal-eq6-quadrant",
    )
    ms = [eq1, signed, acute]
    arm = _arm()

    def demo() -> bool:
        m_s = chk._quadrant_misses(arm, set(chk.FIXES) - {"gamma"})
        m_a = chk._quadrant_misses(arm, set(chk.FIXES) - {"gamma"}, arctan_reading="acute")
        # quadrant 3 (third quadrant target) is missed under both readings
        return _all_fail(ms) and m_s[2] > 1.0 and m_a[2] > 1.0

    return _cause(
        "pal-eq6-quadrant",
        "eqs. 1 and 6 build the waist angle from a single-argument arctan and a case list "
        "that is wrong in quadrant 3 under every reading and misses the axes.",
        "error",
        "branch/quadrant",
        f.evidence + f" ({_dims()}). Corrected: gamma = atan2(Y0, X0).",
        ms,
        demo,
    )


def _elevation_ok(text: str, subs: dict | None = None) -> bool:
    """alpha2 of ``text`` equals the elevation of the shoulder-wrist line measured on the
    arm, at every target (eq. 2's L4' and L3' = L3 substituted)."""
    e = _parse(text)
    if e is None:
        return False
    if subs:
        e = e.subs({S[k]: _parse(v) for k, v in subs.items()})
    got = _eval(e, _values())
    return got is not None and _angles_close(got, _values()["elevation"])


def _front(values: dict) -> dict:
    """The targets whose wrist is in front of the base axis (rho > L3 + 1 mm)."""
    keep = np.hypot(values["X0"], values["Y0"]) > values["L3"] + 1.0
    return {k: (v[keep] if np.ndim(v) else v) for k, v in values.items()}


def _eq3() -> list[Cause]:
    f_h, f_a2, f_b1 = (_found()[k] for k in ("pal-eq3-H", "pal-eq3-alpha2", "pal-eq3-beta1"))
    v_front = _front(_values())

    def h_ok(text: str) -> bool:
        e = _parse(text)
        if e is None or S["H"] in e.free_symbols:
            return False  # H is used and never defined in the text
        got = _eval(e, v_front)
        return got is not None and _angles_close(got, v_front["elevation"])

    h = _cause(
        "pal-eq3-h",
        "eq. 3 uses H, which the text never defines (the lost Figure 3 may have drawn it).",
        "uncertain",
        "undefined symbol",
        f_h.evidence,
        [
            Manifestation(
                "pal-eq3-h/alpha2",
                "eq. 3, alpha2",
                "alpha2 = asin(H/L4p)",
                "alpha2 = asin((Z0 + h)/L4p)",
                "Read as the vertical leg of eq. 2's triangle, H = Z0 + h, alpha2 is the "
                "elevation of the shoulder-wrist line (checked on the arm's forward kinematics "
                f"at {len(v_front['X0'])} targets with the wrist in front of the base axis, "
                f"{_dims()}); read as a depth, -(Z0 + h), it is its negative and eq. 4 would "
                "need the other sign (pal-eq4-alpha).",
                _safe(h_ok),
                "pal-eq3-H",
            )
        ],
    )
    v = _values()
    behind = int((np.hypot(v["X0"], v["Y0"]) < v["L3"]).sum())
    a2 = _cause(
        "pal-eq3-alpha2",
        "eq. 3's alpha2 = arcsin(H/L4') is the elevation of the shoulder-wrist line only while "
        "the wrist is in front of the base axis (rho > L3).",
        "error",
        "branch/quadrant",
        f_a2.evidence,
        [
            Manifestation(
                "pal-eq3-alpha2/alpha2",
                "eq. 3, alpha2",
                "alpha2 = asin((Z0 + h)/L4p)",
                "alpha2 = atan2(Z0 + h, sqrt(X0**2 + Y0**2) - L3p)",
                f"Held against the elevation measured on the arm at {len(v['X0'])} targets the "
                f"arm solves within its elbow stop, {behind} of them with the wrist behind the "
                f"base axis (rho < L3; {_dims()}): arcsin returns pi minus the elevation there.",
                _safe(_elevation_ok),
                "pal-eq3-alpha2",
            )
        ],
    )

    def b1_ok(text: str) -> bool:
        e = _parse(text)
        got = None if e is None else _eval(e, v)
        return got is not None and bool(np.all(np.abs(got - v["beta1"]) < ATOL))

    b1 = _cause(
        "pal-eq3-beta1",
        "eq. 3 prints beta1 as the cosine of the elbow angle, without the arccos that alpha1 "
        "has in the same run.",
        "error",
        "missing term",
        f_b1.evidence,
        [
            Manifestation(
                "pal-eq3-beta1/beta1",
                "eq. 3, beta1",
                paper.EQUATIONS["eq3"]["parts"][2]["lhs"]
                + " = "
                + paper.EQUATIONS["eq3"]["parts"][2]["rhs"],
                "beta1 = acos((L1p**2 + L2p**2 - L4p**2)/(2*L1p*L2p))",
                "Held against the included angle of upper arm and forearm measured on the "
                f"arm (frames 2-4 of the D-H chain) at {len(v['X0'])} targets ({_dims()}). The "
                "extraction keeps 'arccos' for alpha1 and 'arcsin' for alpha2 in the same run, "
                "so the missing arccos is most likely the print's.",
                _safe(b1_ok),
                "pal-eq3-beta1",
            )
        ],
    )
    return [h, a2, b1]


def _eq4() -> Cause:
    v = _values()

    def ok(text: str) -> bool:
        e = _parse(text)
        if e is None:
            return False
        vals = {**v, "alpha2": v["elevation"]}
        alpha = _eval(e, vals)
        # eq. 12: theta2 = -pi/2 - alpha, against the solver's theta2 (measured on the arm)
        return alpha is not None and _angles_close(-np.pi / 2 - alpha, v["theta2"])

    f = _found()["pal-eq4-alpha"]
    ms = [
        Manifestation(
            "pal-eq4-alpha/alpha",
            "eq. 4, alpha (with eq. 12's theta2 = -pi/2 - alpha)",
            "alpha = pi/2 - alpha1 + alpha2",
            "alpha = alpha1 + alpha2 - pi/2",
            f"alpha1, alpha2 (= the elevation) from the arm; theta2 = -pi/2 - alpha against "
            f"the shared solver's theta2 at {len(v['X0'])} targets ({_dims()}). As printed it "
            "misses even the initial pose.",
            _safe(ok),
            "pal-eq4-alpha",
        )
    ]
    return _cause(
        "pal-eq4-alpha",
        "eq. 4's alpha = pi/2 - alpha1 + alpha2 and eq. 12's theta2 = -pi/2 - alpha disagree "
        "in sign: the upper arm lands mirrored.",
        "error",
        "sign",
        f.evidence,
        ms,
    )


def _eq12() -> Cause:
    v = _values()

    def ok(text: str) -> bool:
        e = _parse(text)
        t4 = None if e is None else _eval(e, v)
        if t4 is None:
            return False
        # the gripper stays level (sec. 3, theta5 = 0): theta2 + theta3 + theta4 = pi/2,
        # and the arm then reaches the target
        arm = _arm()
        q = np.stack([v["theta1"], v["theta2"], v["theta3"], t4], axis=-1)
        G = np.stack([v["X0"], v["Y0"], v["Z0"]], axis=-1)
        level = _angles_close(v["theta2"] + v["theta3"] + t4, np.pi / 2)
        return level and bool(np.linalg.norm(arm.fk(q) - G, axis=-1).max() < ATOL)

    f = _found()["pal-eq12-theta4"]
    return _cause(
        "pal-eq12-theta4",
        "eq. 12's theta4 = pi/2 - theta2 + theta3 tilts the gripper; the level gripper needs "
        "pi/2 - (theta2 + theta3): parentheses lost by the print or by the extraction.",
        "uncertain",
        "transcription",
        f.evidence
        + " Eq. 5 supports the parenthesised reading: with eq. 12, theta2 + theta3 = beta - "
        "alpha = theta, so theta4 = pi/2 - theta; and the extraction dropped parentheses "
        "elsewhere (eq. 11, rows 1-2).",
        [
            Manifestation(
                "pal-eq12-theta4/theta4",
                "eq. 12, theta4",
                "theta4 = pi/2 - theta2 + theta3",
                "theta4 = pi/2 - (theta2 + theta3)",
                f"theta2, theta3 of the shared solver at {len(v['X0'])} targets; the gripper "
                "must stay level (sec. 3) and the arm reach G (D-H forward kinematics, "
                f"{_dims()}).",
                _safe(ok),
                "pal-eq12-theta4",
            )
        ],
    )


def _signs() -> Cause:
    """Sec. 3's senses of alpha and beta against the corrected eqs. 4 and 12, measured on the
    arm: the rotation vector of the upper arm when alpha grows (eq. 12: theta2 = -pi/2 -
    alpha) and of the forearm when beta grows (theta3 = pi/2 + beta), at the initial pose."""
    arm = _arm()
    q0 = np.array([0.0, -np.pi / 2, np.pi / 2, np.pi / 2])
    eps = 1e-6

    def link(q, a, b):
        f = arm.frames(q)
        return f[b] - f[a]

    def turn(u, u2):  # rotation vector direction taking u to u2
        return np.cross(u, u2 - u)

    w_alpha = turn(link(q0, 2, 3), link(q0 + np.array([0, -eps, 0, 0]), 2, 3))
    w_beta = turn(link(q0, 3, 4), link(q0 + np.array([0, 0, eps, 0]), 3, 4))
    sense = float(np.sign(w_alpha @ w_beta))  # +1 same sense, -1 opposite
    way = "the same way" if sense > 0 else "opposite ways"

    def ok(text: str) -> bool:
        t = text.lower()
        if "opposite" in t:
            return sense < 0
        if "same" in t:
            return sense > 0
        return False

    return _cause(
        "pal-sign-senses",
        "Sec. 3 gives alpha > 0 and beta > 0 the same sense (clockwise about +Y2, +Y3); the "
        "corrected eqs. 4 and 12 turn them opposite ways about parallel axes.",
        "uncertain",
        "sign",
        _found()["pal-eq4-alpha"].evidence.split("With it ")[-1]
        + " Figure 2, where Y2 and Y3 are drawn, is lost: if +Y3 = -Y2 the text holds.",
        [
            Manifestation(
                "pal-sign-senses/sec3",
                "sec. 3, second paragraph (sign conventions)",
                "alpha > 0 and beta > 0: same sense (both clockwise, about +Y2 and +Y3)",
                "alpha > 0 and beta > 0: opposite senses about parallel axes Y2, Y3 (or +Y3 = -Y2)",
                "Measured on the arm at the initial pose: the upper arm's rotation vector for "
                "a growing alpha (eq. 12: theta2 = -pi/2 - alpha) and the forearm's for a "
                f"growing beta (theta3 = pi/2 + beta) point {way}: "
                "alpha > 0 leans the upper arm back, beta > 0 folds the forearm down.",
                _safe(ok),
                "pal-eq4-alpha",
            )
        ],
    )


# ---------------------------------------------------------------------------------------------
# claims
# ---------------------------------------------------------------------------------------------
@cache
def _claim_targets() -> np.ndarray:
    """Grid targets for the claims, the unreachable ones included (x, y in +-1.2 (L1 + L2 +
    L3), z in [-h, L1 + L2])."""
    arm = _arm()
    L1, L2, L3, h = chk.lengths(arm)
    r = 1.2 * (L1 + L2 + L3)
    xs = np.linspace(-r, r, 17)
    zs = np.linspace(-h, L1 + L2, 9)
    G = np.stack(np.meshgrid(xs, xs, zs, indexing="ij"), -1).reshape(-1, 3)
    return G[np.hypot(G[:, 0], G[:, 1]) > 1.0]


def _triangle() -> Cause:
    arm = _arm()
    G = _claim_targets()
    L1, L2, L3, h = chk.lengths(arm)
    L4 = np.hypot(np.hypot(G[:, 0], G[:, 1]) - L3, G[:, 2] + h)
    exists = ~np.isin(
        arm.solve(G, limits=False).status, [int(Status.OUT_OF_REACH), int(Status.INSIDE_REACH)]
    )

    def ok(text: str) -> bool:
        if "for every" in text:
            claimed = np.ones(len(G), bool)
        elif " iff " in text:
            e = sp.parse_expr(text.split(" iff ", 1)[1], local_dict={**S, **_FUNCS, "L4": S["L4"]})
            f = sp.lambdify([S["L1"], S["L2"], S["L4"]], e, "numpy")
            claimed = np.broadcast_to(np.asarray(f(L1, L2, L4), bool), exists.shape)
        else:
            return False
        return bool(np.array_equal(claimed, exists))

    f = _found()["pal-claim-isosceles"]
    return _cause(
        "pal-claim-triangle",
        "Sec. 3 says the triangle of upper arm, forearm and L4 'can always be formed'; it "
        "exists only for |L1 - L2| <= L4 <= L1 + L2, and no reach check precedes eq. 3.",
        "error",
        "claim",
        "No reach " + f.evidence.split("No reach ")[-1],
        [
            Manifestation(
                "pal-claim-triangle/sec3",
                "sec. 3, before eq. 1 ('一定可以構成')",
                "the triangle (L1', L2', L4') exists for every target G",
                "the triangle (L1', L2', L4') exists iff (Abs(L1 - L2) <= L4) & (L4 <= L1 + L2)",
                f"Held against the shared solver without joint limits on {len(G)} grid targets "
                f"(x, y within +-{1.2 * (L1 + L2 + L3):g} mm; {_dims()}): "
                f"{int((~exists).sum())} have no triangle.",
                _safe(ok),
                "pal-claim-isosceles",
            )
        ],
    )


def _isosceles() -> Cause:
    base = _arm()
    G = chk.QUADRANT_TARGETS

    def all_isosceles(arm: Arm) -> bool:
        L1, L2, L3, h = chk.lengths(arm)
        L4 = np.hypot(np.hypot(G[:, 0], G[:, 1]) - L3, G[:, 2] + h)
        sides = np.stack([np.full_like(L4, L1), np.full_like(L4, L2), L4], -1)
        d = np.abs(sides[:, [0, 0, 1]] - sides[:, [1, 2, 2]]).min(axis=-1)
        return bool((d < ATOL).all())

    arms = [base, Arm(base.params.with_(L2=150.0))]

    def ok(text: str) -> bool:
        if " iff " in text:
            cond = text.split(" iff ", 1)[1].strip()
            m = re.fullmatch(r"(L\d) = (L\d)", cond)
            if not m:
                return False
            claimed = [arm.params[m[1]] == arm.params[m[2]] for arm in arms]
        elif "for every" in text:
            claimed = [True for _ in arms]
        else:
            return False
        return claimed == [all_isosceles(a) for a in arms]

    return _cause(
        "pal-claim-isosceles",
        "Sec. 3 calls the triangle isosceles for any target; that needs L1 = L2, which the "
        "paper never states (no length is printed) and eq. 3 does not use.",
        "unsupported",
        "claim",
        _found()["pal-claim-isosceles"].evidence.split(" No reach")[0],
        [
            Manifestation(
                "pal-claim-isosceles/sec3",
                "sec. 3, before eq. 1 and after eq. 2 ('等腰三角形')",
                "the triangle (L1', L2', L4') is isosceles for every target",
                "the triangle (L1', L2', L4') is isosceles for every target iff L1 = L2",
                "Held on two arms, the assumed isosceles one and one with L2 = 150 mm "
                f"(assumed), at the four quadrant targets ({_dims()}).",
                _safe(ok),
                "pal-claim-isosceles",
            )
        ],
    )


def _unique() -> Cause:
    arm = _arm()
    grid = chk.workspace_grid(arm, 21)
    q = chk.all_ik(arm, grid)
    solved = np.isfinite(q).all(-1)
    t3 = np.where(solved, q[..., 2], np.nan)
    L1, L2, L3, h = chk.lengths(arm)
    initial_included = 90.0  # sec. 3: forearm perpendicular to the upper arm (eq. 7)
    num = r"(-?\d+(?:\.\d+)?)"

    def unique(text: str) -> bool:
        """One pose per target that keeps any, under the constraint the text names."""
        branches = slice(0, 2) if "waist facing" in text else slice(0, 4)
        m = re.search(rf"theta3 in \[{num}, {num}\] deg", text)
        with np.errstate(invalid="ignore"):
            if m:
                lo, hi = np.radians(float(m[1])), np.radians(float(m[2]))
                keep = solved & (t3 >= lo - 1e-12) & (t3 <= hi + 1e-12)
            else:
                m = re.search(rf"included angle .*(<=|<) {num} deg", text)
                if not m:
                    return False
                inc = np.degrees(np.pi - np.abs(t3))
                bound = float(m[2])
                keep = solved & ((inc <= bound) if m[1] == "<=" else (inc < bound))
        n = keep[:, branches].sum(axis=1)
        return bool((n[n > 0] == 1).all() and (n > 0).any())

    def admits_initial_pose(text: str) -> bool:
        m = re.search(rf"(<=|<) {num} deg", text)
        if not m:
            return False
        bound = float(m[2])
        return initial_included <= bound if m[1] == "<=" else initial_included < bound

    f = _found()["pal-claim-unique"]
    ms = [
        Manifestation(
            "pal-claim-unique/reasoning",
            "sec. 2, third paragraph ('所以其抓取時的位置狀態是唯一的')",
            "included angle of forearm and upper arm < 90 deg => one pose per target",
            "theta3 in [90, 180] deg, waist facing the target (eq. 6) => one pose per target",
            f"Count of the four solutions (waist facing / reversed, elbow up / down) that each "
            f"constraint keeps, at {len(grid)} grid targets ({_dims()}): the unsigned angle "
            "keeps the mirror pose too (2 or 4 per target, never 1); the signed stop with the "
            "waist facing the target keeps exactly 1 wherever it keeps any.",
            _safe(unique),
            "pal-claim-unique",
        ),
        Manifestation(
            "pal-claim-unique/initial-pose",
            "sec. 2 (the bound) against sec. 3 (the initial pose)",
            "included angle of forearm and upper arm < 90 deg",
            "included angle of forearm and upper arm <= 90 deg",
            "Sec. 3's initial pose has the forearm perpendicular to the upper arm (eq. 7: "
            "theta3 = 90 deg): a strict bound excludes the paper's own starting pose.",
            _safe(admits_initial_pose),
            "pal-claim-unique",
        ),
    ]
    lim = np.degrees(arm.limits[2])

    def demo() -> bool:
        sol = arm.solve(grid, "all")
        rho = np.hypot(grid[:, 0], grid[:, 1])
        beyond = (np.hypot(rho - L3, grid[:, 2] + h) > math.hypot(L1, L2) + 1e-6) & (rho > 0)
        return (
            _all_fail(ms)
            and tuple(lim) == (90.0, 180.0)
            and not sol.ok[:, 1].any()
            and (sol.status[beyond] == Status.JOINT_LIMITS).all()
        )

    return _cause(
        "pal-claim-unique",
        "Sec. 2 infers a unique pose from 'forearm-upper arm angle < 90 deg'; an angle bound "
        "keeps the mirror pose, only a signed stop (and the waist facing the target) does.",
        "error",
        "reasoning",
        f.evidence + f" Encoded as the stop theta3 in [{lim[0]:g}, {lim[1]:g}] deg in "
        "data/arms/palletizer.toml: enforced by the shared solver and the generated PLC "
        "program (status 'joint-limits'); it limits the wrist to sqrt(L1^2 + L2^2) from the "
        "shoulder.",
        ms,
        demo,
    )


def _exact() -> Cause:
    arm = _arm()
    G = chk.QUADRANT_TARGETS
    f = _found()["pal-claim-exact"]
    pin = chk.fk_ik_pinocchio(arm, 10_000)

    def ok(text: str) -> bool:
        if "as printed" in text:
            for H in ("height", "depth"):
                for a in ("signed", "acute"):
                    q = chk.ik_chain(arm, G, (), H_reading=H, arctan_reading=a)["q"]
                    m = chk.miss(arm, G, q, eq11="printed")
                    if np.all(m < ATOL):  # NaN (a formula undefined) counts as a miss
                        return True
            return False
        if "corrected" in text:
            m = chk.miss(arm, G, chk.ik_chain(arm, G, chk.FIXES)["q"])
            return bool(np.all(m < ATOL))
        return False

    return _cause(
        "pal-claim-exact",
        "Sec. 5 reports that the IK angles put into the D-H formula 'exactly equal' the "
        "targets; with the equations as printed no target in any quadrant comes back.",
        "error",
        "claim",
        f.evidence + f" Corrected and through Pinocchio: {pin['n']:,} seeded level configurations, "
        f"max |FK(IK(G)) - G| below {ATOL:g} mm (float64 round-off; the digits depend on the "
        "machine).",
        [
            Manifestation(
                "pal-claim-exact/sec5",
                "sec. 5, last paragraph ('結果完全等於待抓取點Gi')",
                "FK by eq. 11 as printed of the IK by eqs. 1-6, 12 as printed = G_i, four "
                "quadrants, Z > 0",
                "FK by eq. 11 corrected of the IK by eqs. 1-6, 12 corrected = G_i, four "
                "quadrants, Z > 0",
                "Evaluated at four quadrant targets with Z > 0 (the paper's are in the lost "
                f"Tables 2-3; {_dims()}) under both readings of H and of eq. 1's arctan: the "
                "best printed reading still misses every target by millimetres.",
                _safe(ok),
                "pal-claim-exact",
            )
        ],
    )


def _exact_demo(cause: Cause) -> Cause:
    pin = chk.fk_ik_pinocchio(_arm(), 10_000)
    ms = cause.manifestations
    return Cause(
        cause.id,
        cause.title,
        cause.status,
        cause.kind,
        cause.evidence,
        ms,
        lambda: pin["all_ok"] and pin["max_err_mm"] < ATOL and _all_fail(ms),
    )


def _xrefs() -> list[Cause]:
    def section_ok(text: str) -> bool:
        m = re.search(r"第(\d)節", text)
        return bool(m) and "逆向" in paper.SECTIONS.get(int(m[1]), "")

    def reference_ok(text: str) -> bool:
        m = re.search(r"第(\d+)篇文獻.*\[(\d+)\]", text)
        if not m or m[1] != m[2]:
            return False
        return paper.REFERENCES.get(int(m[2]), {}).get("topic") == "D-H method"

    f_s, f_r = _found()["pal-xref-section"], _found()["pal-xref-reference"]
    return [
        _cause(
            "pal-xref-section",
            "Sec. 5 says the IK method is in section 2; it is section 3.",
            "error",
            "cross-reference",
            f_s.evidence,
            [
                Manifestation(
                    "pal-xref-section/sec5",
                    "sec. 5, third paragraph",
                    "第2節中的逆向解算方法",
                    "第3節中的逆向解算方法",
                    f"Sections as printed: 2 '{paper.SECTIONS[2]}', 3 '{paper.SECTIONS[3]}'.",
                    _safe(section_ok),
                    "pal-xref-section",
                )
            ],
        ),
        _cause(
            "pal-xref-reference",
            "Sec. 4.1 cites 'the 5th reference' as [6]; [6] (Owen) is the D-H source, [5] a "
            "search-based IK paper.",
            "error",
            "cross-reference",
            f_r.evidence,
            [
                Manifestation(
                    "pal-xref-reference/sec4-1",
                    "sec. 4.1",
                    "參照第5篇文獻簡述的方法[6]",
                    "參照第6篇文獻簡述的方法[6]",
                    f"[5] {paper.REFERENCES[5]['printed']}; [6] {paper.REFERENCES[6]['printed']}.",
                    _safe(reference_ok),
                    "pal-xref-reference",
                )
            ],
        ),
    ]


# ---------------------------------------------------------------------------------------------
# what the extraction lost
# ---------------------------------------------------------------------------------------------
def _lost() -> Cause:
    arm = _arm()
    desc = arm.description

    def lengths_ok(text: str) -> bool:
        vals = dict(re.findall(r"\b(L1|L2|L3|h) = (\d+(?:\.\d+)?) mm", text))
        if set(vals) != {"L1", "L2", "L3", "h"} or "assumed" not in text:
            return False
        v = {k: float(x) for k, x in vals.items()}
        if any(
            v[k] != desc.parameters[k].value or desc.parameters[k].status != "assumed" for k in v
        ):
            return False
        # the constraints the paper does state: isosceles (sec. 3), the initial pose and a
        # target in each quadrant with Z > 0 within reach and the elbow stop (secs. 3, 5)
        other = Arm(arm.params.with_(**v))
        G = np.vstack([chk.QUADRANT_TARGETS, [[v["L2"] + v["L3"], 0.0, v["L1"] - v["h"]]]])
        return v["L1"] == v["L2"] and bool((other.solve(G).status == Status.OK).all())

    def targets_ok(text: str) -> bool:
        pts = re.findall(r"\((-?\d+(?:\.\d+)?), (-?\d+(?:\.\d+)?), (-?\d+(?:\.\d+)?)\)", text)
        if len(pts) != 4 or "assumed" not in text:
            return False
        G = np.array(pts, dtype=float)
        quad = {(int(x > 0), int(y > 0)) for x, y, _ in G}
        return (
            len(quad) == 4
            and bool((G[:, 2] > 0).all())
            and bool((arm.solve(G).status == Status.OK).all())
        )

    q = ", ".join(f"({x:g}, {y:g}, {z:g})" for x, y, z in chk.QUADRANT_TARGETS)
    L1, L2, L3, h = chk.lengths(arm)
    return _cause(
        "pal-extraction-lost",
        "The extraction lost Tables 1-3 and Figures 1-7: no length, target, angle or result "
        "of the paper survives; the audit's numbers are assumed.",
        "extraction",
        "extraction",
        "analysis.papers.palletizer.LOST: "
        + "; ".join(f"{k}: {v}" for k, v in list(paper.LOST.items())[:5]),
        [
            Manifestation(
                "pal-extraction-lost/table1",
                "Table 1 (D-H parameters) and every length",
                "Table 1: body lost; L1, L2, L3, h never printed as numbers",
                f"L1 = {L1:g} mm, L2 = {L2:g} mm, L3 = {L3:g} mm, h = {h:g} mm: assumed "
                "(data/arms/palletizer.toml), isosceles family L1 = L2",
                "The assumed values must be the description's, marked assumed, isosceles (the "
                "paper's sec. 3 argument) and admit the initial pose and a target per quadrant "
                "within the elbow stop.",
                _safe(lengths_ok),
            ),
            Manifestation(
                "pal-extraction-lost/tables2-3",
                "Tables 2-3 (targets G1-G4, angles, FK results T1-T4, in m)",
                "Tables 2-3: bodies lost (four targets, one per quadrant, Z > 0)",
                f"four targets [mm], one per quadrant, Z > 0: {q}: assumed",
                "Sec. 5's layout (four quadrants, Z > 0) is all that survives; the stand-ins "
                "must follow it and be reachable within the stop.",
                _safe(targets_ok),
            ),
        ],
    )


# ---------------------------------------------------------------------------------------------
# what holds
# ---------------------------------------------------------------------------------------------
def _holds() -> list[Cause]:
    found = _found()
    arm = _arm()
    e8 = chk.eq8_checks()
    mats = all(v for k, v in e8.items() if k.startswith("T") and "==" in k)
    v = _values()

    def eq2() -> bool:
        e = paper.equation("eq2")[0][1]
        got = _eval(e, v)
        return got is not None and bool(np.abs(got - v["L4"]).max() < ATOL)

    def eq5() -> bool:
        t2, t3 = -sp.pi / 2 - S["alpha"], sp.pi / 2 + S["beta"]  # eq. 12
        theta = paper.equation("eq5")[0][1]
        return sp.simplify(theta - (t2 + t3)) == 0

    def eq7() -> bool:
        q = np.array([0.0, -np.pi / 2, np.pi / 2, np.pi / 2])
        L1, L2, L3, h = chk.lengths(arm)
        tip = arm.fk(q)
        back = arm.ik(tip)
        return bool(
            np.allclose(tip, [L2 + L3, 0, L1 - h], atol=ATOL) and np.allclose(back, q, atol=ATOL)
        )

    def quadrant_rule() -> bool:
        az = _azimuths()
        g = np.arctan2(az["Y0"], az["X0"])
        upper = az["Y0"] > 0
        lower = az["Y0"] < 0
        return bool((g[upper] > 0).all() and (g[lower] < 0).all())

    return [
        Cause(
            "pal-matrices-hold",
            "The five matrices 0_1T..4_5T (sec. 4.2) and their product order (eq. 9) are "
            "modified D-H transforms of one row set; data/arms/palletizer.toml is read off them.",
            "holds",
            "transcription",
            found["pal-matrices"].evidence,
            (),
            lambda: mats,
        ),
        Cause(
            "pal-eq2-holds",
            "eq. 2 (radicals restored) is the shoulder-wrist distance of the level gripper.",
            "holds",
            "transcription",
            found["pal-eq2"].evidence
            + f"; equal to the distance measured on the arm at {len(v['X0'])} targets.",
            (),
            eq2,
        ),
        Cause(
            "pal-eq5-holds",
            "eq. 5, theta = -alpha + beta, is theta2 + theta3 of eq. 12: the gripper angle that "
            "keeps it level.",
            "holds",
            "transcription",
            found["pal-eq5"].evidence,
            (),
            eq5,
        ),
        Cause(
            "pal-eq7-holds",
            "eq. 7's angles (0, -90, 90, 90, 0 deg) are the initial pose of sec. 3, and the "
            "corrected IK returns them.",
            "holds",
            "transcription",
            found["pal-eq7"].evidence + f" ({_dims()})",
            (),
            eq7,
        ),
        Cause(
            "pal-quadrant-rule-holds",
            "Sec. 3: M1 turns left (gamma > 0) for targets in quadrants 1-2 and right in "
            "quadrants 3-4, as atan2 gives.",
            "holds",
            "claim",
            "atan2(Y0, X0) > 0 for all 180 azimuths with Y0 > 0 and < 0 for all 180 with "
            "Y0 < 0 (the rule of the text; eq. 6 breaks it, pal-eq6-quadrant).",
            (),
            quadrant_rule,
        ),
    ]


def register() -> Register:
    """Seed 001's register (cached by :func:`analysis.audit.register.register`)."""
    causes = [
        *_eq11(),
        _eq8(),
        _eq6(),
        *_eq3(),
        _eq4(),
        _eq12(),
        _signs(),
        _triangle(),
        _isosceles(),
        _unique(),
        _exact_demo(_exact()),
        *_xrefs(),
        _lost(),
        *_holds(),
    ]
    return Register(
        "palletizer",
        "Li Zhaoxiang, Hu Jie, Computer Knowledge and Technology 2021 (seed 001): 4-axis "
        "palletizer",
        tuple(causes),
    )
