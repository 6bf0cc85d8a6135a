"""Seed 001's register, the IK chain: the causes found in eqs. 1-6 and 12 (the waist angle
against atan2 on 360 azimuths and the axes, the elbow triangle and the elevation of the
shoulder-wrist line measured on the arm's forward kinematics, the level gripper) and in the
signs of the motor angles; :func:`causes` in the register's order
(:mod:`analysis.audit.palletizer_causes`)."""

from __future__ import annotations

from functools import cache

import numpy as np
import sympy as sp

from analysis.audit import palletizer_checks as chk
from analysis.audit.palletizer_formulas import ATOL, S
from analysis.audit.palletizer_formulas import angles_close as _angles_close
from analysis.audit.palletizer_formulas import dims_text as _dims
from analysis.audit.palletizer_formulas import evaluate as _eval
from analysis.audit.palletizer_formulas import findings_by_id as _found
from analysis.audit.palletizer_formulas import palletizer_arm as _arm
from analysis.audit.palletizer_formulas import parse_formula as _parse
from analysis.audit.palletizer_formulas import target_values as _values
from analysis.audit.schema import Cause, Manifestation
from analysis.audit.schema import all_fail as _all_fail
from analysis.audit.schema import make_cause as _cause
from analysis.audit.schema import safe as _safe
from analysis.papers import palletizer as paper


# ---------------------------------------------------------------------------------------------
# the IK chain (eqs. 1-6, 12)
# ---------------------------------------------------------------------------------------------
@cache
def azimuths() -> dict[str, np.ndarray]:
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
    v = azimuths()
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
        m_s = chk.quadrant_misses(arm, set(chk.FIXES) - {"gamma"})
        m_a = chk.quadrant_misses(arm, set(chk.FIXES) - {"gamma"}, arctan_reading="acute")
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


def _eq3_h() -> Cause:
    """eq. 3's undefined H, read as the vertical leg Z0 + h of eq. 2's triangle."""
    f_h = _found()["pal-eq3-H"]
    v_front = _front(_values())

    def h_ok(text: str) -> bool:
        e = _parse(text)
        if e is None or S["H"] in e.free_symbols:
            return False  # H is used and never defined in the text
        got = _eval(e, v_front)
        return got is not None and _angles_close(got, v_front["elevation"])

    return _cause(
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


def _eq3_alpha2() -> Cause:
    """eq. 3's alpha2 = arcsin(H/L4') against the elevation measured on the arm."""
    f_a2 = _found()["pal-eq3-alpha2"]
    v = _values()
    behind = int((np.hypot(v["X0"], v["Y0"]) < v["L3"]).sum())
    return _cause(
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


def _eq3_beta1() -> Cause:
    """eq. 3's beta1 against the included elbow angle measured on the arm."""
    f_b1 = _found()["pal-eq3-beta1"]
    v = _values()

    def b1_ok(text: str) -> bool:
        e = _parse(text)
        got = None if e is None else _eval(e, v)
        return got is not None and bool(np.all(np.abs(got - v["beta1"]) < ATOL))

    return _cause(
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


def _eq3() -> list[Cause]:
    """The causes of eq. 3: the undefined H, alpha2's quadrant, beta1's missing arccos."""
    return [_eq3_h(), _eq3_alpha2(), _eq3_beta1()]


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


def causes() -> list[Cause]:
    """The causes of eqs. 6, 3, 4, 12 and of the signs, in the register's order."""
    return [_eq6(), *_eq3(), _eq4(), _eq12(), _signs()]
