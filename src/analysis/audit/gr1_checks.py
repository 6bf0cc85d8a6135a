"""Checks of the GR-1 thesis (seed 004): its equations against the D-H chain, its VB6
statements run in the VB6 interpreter, each against the truth of a known configuration.

The truth is a configuration ``q`` of the GR-1 (``data/arms/gr1.toml``, model A) and the pose
its chain gives: every printed formula for an angle must return that angle, every printed
formula for a cosine that cosine. Three kinds of check:

- :func:`equation_holds`: a section 4.2 or chapter 3 equation (SymPy text over
  ``gr1_thesis.SYMBOLS``) evaluated on seeded configurations (:func:`configurations`);
- :func:`run_statement`: one VB6 statement of the listing (or its correction) run in
  :mod:`analysis.audit.vb6` with the listing's variables preset as the listing would hold
  them for a configuration (:func:`listing_env`: positions in mm, RPY and joint angles in
  degrees, ``PI = 3.141593``); ``trig_degrees=True`` makes Sin/Cos read degrees, which
  isolates every other defect from the unit one;
- the register's causes (:mod:`analysis.audit.gr1_causes`) combine them with the arm.

Witness configurations (degrees) are chosen so that the defect under test shows: a waist in
the second quadrant for ``Atn(Py0 / Px0)``, an elbow beyond 90 deg for ``Atn(s3 / c3)``, and
so on; :data:`PRINCIPAL` keeps every angle where a single-argument arctangent is right.
"""

from __future__ import annotations

import math
import re
from functools import cache

import numpy as np
import numpy.typing as npt
import sympy as sp

from analysis.audit import vb6
from analysis.kinematics.rpy import rpy_from_matrix
from analysis.papers import gr1_thesis as paper
from analysis.studies.gr1 import gr1_arm

__all__ = [
    "PI_LISTING",
    "PRINCIPAL",
    "cells_matching",
    "configurations",
    "equation_holds",
    "equation_values",
    "listing_env",
    "listing_statement",
    "numbers",
    "printed_run",
    "run_statement",
    "truth",
]

PI_LISTING = 3.141593
"""The listing's ``PI = 3.141593``."""
PRINCIPAL = (40.0, 30.0, 60.0, -50.0, 20.0)
"""A configuration [deg] where every single-argument arctangent of the thesis is right
(theta1, theta2, theta5, theta234 = 40 within +-90 deg, theta3 in (0, 90), the listing's own
elbow branch): only the defect under test shows."""


# --------------------------------------------------------------------------- the truth
def truth(q_deg) -> dict[str, float]:
    """The pose and angles of configuration ``q_deg`` (5,) [deg] as named in the thesis.

    Keys: ``px py pz`` [mm], ``alpha beta gamma`` [deg] (RPY, eq. 3.18), ``theta1`` ..
    ``theta5`` and ``theta234`` [deg] (theta234 wrapped to (-180, 180]), ``c3`` = cos theta3,
    and ``n_x`` .. ``a_z`` (the columns of the hand's rotation, eq. 3.16).
    """
    arm = gr1_arm()
    q = np.radians(np.asarray(q_deg, dtype=float))
    T = arm.table.fk(q)
    rpy = np.degrees(rpy_from_matrix(T[:3, :3]))
    t234 = math.degrees(math.remainder(float(q[1] + q[2] + q[3]), 2 * math.pi))
    out = {"px": T[0, 3], "py": T[1, 3], "pz": T[2, 3]}
    out.update(alpha=rpy[0], beta=rpy[1], gamma=rpy[2])
    out.update({f"theta{j + 1}": float(q_deg[j]) for j in range(5)}, theta234=t234)
    out["c3"] = math.cos(q[2])
    for k, col in enumerate("noa"):
        for i, ax in enumerate("xyz"):
            out[f"{col}_{ax}"] = T[i, k]
    return {k: float(v) for k, v in out.items()}


def configurations(n: int = 200, seed: int = 2007, front: bool = True) -> npt.NDArray:
    """``n`` seeded configurations (n, 5) [rad], every angle over a full turn except theta2
    (+-100 deg), that are the front solution of their own pose (the tool's radial coordinate
    along x1 > 1 mm, so atan2(py, px) is their theta1) when ``front``."""
    rng = np.random.default_rng(seed)
    arm = gr1_arm()
    P = arm.params
    q = rng.uniform(-np.pi, np.pi, (8 * n, 5))
    q[:, 1] = rng.uniform(-1.74, 1.74, 8 * n)
    if front:
        r = (
            P.a2 * np.cos(q[:, 1])
            + P.a3 * np.cos(q[:, 1] + q[:, 2])
            + P.a4 * np.cos(q[:, 1] + q[:, 2] + q[:, 3])
        )
        q = q[r > 1.0]
    return q[:n]


# --------------------------------------------------------------------------- equations
@cache
def _chain_values(n: int = 200, seed: int = 2007) -> dict[str, npt.NDArray]:
    """Numeric values of every kinematic symbol on :func:`configurations` (radians)."""
    arm = gr1_arm()
    q = configurations(n, seed)
    T = arm.table.fk(q)
    rpy = rpy_from_matrix(T[:, :3, :3])
    vals = {f"theta{j + 1}": q[:, j] for j in range(5)}
    vals["theta234"] = np.remainder(q[:, 1] + q[:, 2] + q[:, 3] + np.pi, 2 * np.pi) - np.pi
    vals.update(px=T[:, 0, 3], py=T[:, 1, 3], pz=T[:, 2, 3])
    for k, col in enumerate("noa"):
        for i, ax in enumerate("xyz"):
            vals[f"{col}_{ax}"] = T[:, i, k]
    vals.update(phi=rpy[:, 0], theta=rpy[:, 1], psi=rpy[:, 2])
    vals.update({k: np.full(len(q), float(v)) for k, v in arm.params.items() if k != "d1"})
    return vals


def equation_values(text: str) -> tuple[npt.NDArray, npt.NDArray] | None:
    """``lhs = rhs`` (SymPy text over the thesis's symbols) evaluated on the configurations:
    (lhs, rhs) arrays, or None if the text is no such equation."""
    if text.count("=") != 1:
        return None
    try:
        lhs, rhs = (paper.parse(side.strip()) for side in text.split("="))
    except ValueError:
        return None
    vals = _chain_values()
    names = sorted({s.name for s in (lhs.free_symbols | rhs.free_symbols)})
    if not set(names) <= set(vals):
        return None
    syms = [paper.SYMBOLS[k] for k in names]
    f = sp.lambdify(syms, [lhs, rhs], modules=["numpy", {"atan2": np.arctan2}])
    with np.errstate(all="ignore"):
        a, b = f(*(vals[k] for k in names))
    n = len(vals["px"])
    return np.broadcast_to(np.asarray(a, float), (n,)), np.broadcast_to(np.asarray(b, float), (n,))


def equation_holds(text: str, *, angle: bool = False, atol: float = 1e-9) -> bool:
    """Does ``lhs = rhs`` hold on all 200 seeded configurations of the GR-1's chain (within
    ``atol``; modulo 2 pi if ``angle``)? False for text that is no equation."""
    v = equation_values(text)
    if v is None:
        return False
    d = v[0] - v[1]
    if angle:
        d = np.remainder(d + np.pi, 2 * np.pi) - np.pi
    return bool(np.all(np.abs(d) <= atol))


# --------------------------------------------------------------------------- the VB6 listing
def listing_statement(prefix: str, *, repaired: bool = False) -> str:
    """The one line of the listing (as printed, or with :data:`vb6.LISTING_REPAIRS`) that
    starts with ``prefix`` (e.g. ``"θ5 = "``)."""
    src = vb6.listing(repaired=repaired)
    lines = [ln for ln in src.splitlines() if ln.startswith(prefix)]
    if len(lines) != 1:
        raise ValueError(f"{len(lines)} listing lines start with {prefix!r}")
    return lines[0]


def listing_env(q_start_deg, q_end_deg=None) -> dict[str, float]:
    """The listing's variables for a start (and end) configuration, as it holds them:
    ``a2 a3 a4 PI``, ``Px0 Py0 Pz0`` [mm], ``α0 β0 γ0`` [deg], ``θ1 θ2 θ3 θ234`` [deg],
    ``c3``; and ``Px1 .. γ1, θf1 .. cf3`` for the end configuration (default: the start)."""
    P = gr1_arm().params
    env = {"a2": P.a2, "a3": P.a3, "a4": P.a4, "PI": PI_LISTING}
    for q, k, f in ((q_start_deg, "0", ""), (q_end_deg or q_start_deg, "1", "f")):
        t = truth(q)
        env.update({f"Px{k}": t["px"], f"Py{k}": t["py"], f"Pz{k}": t["pz"]})
        env.update({f"α{k}": t["alpha"], f"β{k}": t["beta"], f"γ{k}": t["gamma"]})
        env.update({f"θ{f}{j}": t[f"theta{j}"] for j in (1, 2, 3, 4, 5)})
        env.update({f"θ{f}234": t["theta234"], "cf3" if f else "c3": t["c3"]})
    return env


def _literal(v: float) -> str:
    text = f"{v:.17g}".replace("e", "E")
    return text if any(c in text for c in ".E") else text + ".0"


def run_statement(text: str, env: dict[str, float], *, trig_degrees: bool = False) -> float:
    """Run VB6 ``text`` (one statement, or several joined by ':' or newlines) after
    presetting ``env`` as Double variables; return the value assigned last.

    Raises :class:`analysis.audit.vb6.VB6SyntaxError` if the text does not parse and
    :class:`analysis.audit.vb6.VB6Error` for a run-time error (e.g. ``Sqr`` of a negative).
    """
    target = re.split(r"[:\n]", text.strip())[-1].split("=", 1)[0].strip()
    lines = ["Private Sub T_Click()"]
    lines += [f"Dim {k} As Double" for k in env]
    lines += [f"{k} = {_literal(v)}" for k, v in env.items()]
    lines += [text, "End Sub", ""]
    form = vb6.VB6Form("\n".join(lines), trig_degrees=trig_degrees)
    out = form.call("T_Click")
    value = {k.casefold(): v for k, v in out.items()}.get(target.casefold())
    if value is None:
        raise vb6.VB6SyntaxError(f"statement {text!r} assigns no variable")
    return float(vb6.to_number(value).value)


def statement_gives(
    text: str, q_deg, want: float, *, trig_degrees: bool, q_end_deg=None, atol: float = 1e-3
) -> bool:
    """Does VB6 ``text`` compute ``want`` (within ``atol``; angles in degrees) for the
    configuration? False if it does not parse or raises."""
    try:
        got = run_statement(text, listing_env(q_deg, q_end_deg), trig_degrees=trig_degrees)
    except (vb6.VB6Error, vb6.VB6SyntaxError, ValueError):
        return False
    return math.isfinite(got) and abs(got - want) <= atol


# --------------------------------------------------------------------------- repairs
def atn_parts(statement: str) -> tuple[str, str]:
    """The numerator and denominator of the ``Atn(A / B)`` in a listing statement (the
    top-level '/' inside Atn; outer parentheses of A and B removed)."""
    start = statement.index("Atn(") + 4
    depth, end = 1, start
    while depth:
        depth += {"(": 1, ")": -1}.get(statement[end], 0)
        end += 1
    inner = statement[start : end - 1]
    depth = 0
    for i, ch in enumerate(inner):
        depth += {"(": 1, ")": -1}.get(ch, 0)
        if ch == "/" and depth == 0:
            num, den = inner[:i].strip(), inner[i + 1 :].strip()
            break
    else:
        raise ValueError(f"no top-level '/' in Atn(...) of {statement!r}")

    def unwrap(s: str) -> str:
        if s.startswith("(") and s.endswith(")"):
            depth = 0
            for i, ch in enumerate(s):
                depth += {"(": 1, ")": -1}.get(ch, 0)
                if depth == 0 and i < len(s) - 1:
                    return s
            return s[1:-1]
        return s

    return unwrap(num), unwrap(den)


def atan2_statement(name: str, y: str, x: str) -> str:
    """A VB6 statement setting ``name`` [deg] to atan2(y, x), with the listing's functions
    only: ``2 Atn(y / (Sqr(x^2 + y^2) + x))`` (the half-angle form; x <= 0 with y = 0 is the
    one case it does not cover)."""
    return f"Yn = {y}: Xd = {x}: {name} = (180 / PI) * 2 * Atn(Yn / (Sqr(Xd * Xd + Yn * Yn) + Xd))"


def _replace_line(src: str, prefix: str, new: str) -> str:
    lines = src.splitlines()
    hits = [i for i, ln in enumerate(lines) if ln.startswith(prefix)]
    if len(hits) != 1:
        raise ValueError(f"{len(hits)} listing lines start with {prefix!r}")
    lines[hits[0]] = new
    return "\n".join(lines) + "\n"


def radians_in_trig(text: str) -> str:
    """``Sin(x)`` -> ``Sin(x * PI / 180)`` (and Cos) for every name x: degrees converted."""
    return re.sub(r"\b(Sin|Cos)\((\w+)\)", r"\1(\2 * PI / 180)", text)


def _units(src: str) -> str:
    head, sep, tail = src.partition("Private Sub Command3_Click()")
    return radians_in_trig(head) + sep + tail


def _sign(src: str) -> str:
    return re.sub(r"\+ Cos\((θf?234(?: \* PI / 180)?)\) \* a4", r"- Cos(\1) * a4", src)


def _end_orientation(src: str) -> str:
    for prefix in ("θf5 = ", "θf234 = "):
        line = next(ln for ln in src.splitlines() if ln.startswith(prefix))
        new = line.replace("α0", "α1").replace("β0", "β1").replace("γ0", "γ1")
        src = _replace_line(src, prefix, new)
    return src


def approach_theta234(f: str = "", k: str = "0") -> str:
    """theta234 = atan2(c1 a_x + s1 a_y, -a_z) as a VB6 statement of the listing's
    variables (eq. 3.15's approach vector from alpha, beta, gamma)."""
    c1, s1 = f"Cos(θ{f}1)", f"Sin(θ{f}1)"
    a, b, g = f"α{k}", f"β{k}", f"γ{k}"
    ax = f"Cos({a}) * Sin({b}) * Cos({g}) + Sin({a}) * Sin({g})"
    ay = f"Sin({a}) * Sin({b}) * Cos({g}) - Cos({a}) * Sin({g})"
    return atan2_statement(f"θ{f}234", f"{c1} * ({ax}) + {s1} * ({ay})", f"-Cos({b}) * Cos({g})")


def _quadrants(src: str) -> str:
    for f, k in (("", "0"), ("f", "1")):
        s1 = next(ln for ln in src.splitlines() if ln.startswith(f"θ{f}1 = "))
        src = _replace_line(src, f"θ{f}1 = ", atan2_statement(f"θ{f}1", *atn_parts(s1)))
        for j in ("5", "2"):
            line = next(ln for ln in src.splitlines() if ln.startswith(f"θ{f}{j} = "))
            new = atan2_statement(f"θ{f}{j}", *atn_parts(line))
            src = _replace_line(src, f"θ{f}{j} = ", new)
        c3 = "cf3" if f else "c3"
        new = f"θ{f}3 = (180 / PI) * 2 * Atn(Sqr(Abs(1 - {c3} * {c3})) / (1 + {c3}))"
        src = _replace_line(src, f"θ{f}3 = ", new)
        src = _replace_line(src, f"θ{f}234 = ", radians_in_trig(approach_theta234(f, k)))
    return src


REPAIRS: dict[str, object] = {
    "printed": lambda s: s,
    "+ radians into Sin/Cos": _units,
    "+ '-' before Cos(θ234) * a4 in θ2": _sign,
    "+ end orientation α1, β1, γ1": _end_orientation,
    "+ atan2 quadrants, θ234 from a": _quadrants,
}
"""The listing's defects repaired one after another (cumulative), in the order of the
errata register's causes gr1-trig-degrees, gr1-r-sign, gr1-end-orientation, gr1-atan (the
cf3 operator, gr1-cf3-operator, is restored in every step: as printed nothing runs)."""


def repaired_listing(upto: str) -> str:
    """The listing with the repairs of :data:`REPAIRS` applied up to and including ``upto``."""
    if upto not in REPAIRS:
        raise ValueError(f"unknown repair {upto!r}; expected one of {list(REPAIRS)}")
    src = vb6.listing()
    for name, fn in REPAIRS.items():
        src = fn(src)
        if name == upto:
            return src
    raise AssertionError("unreachable")  # pragma: no cover


def table5_3_inputs() -> dict[str, str]:
    """Table 5-3 typed into Text1 .. Text12 (start px, py, pz, alpha, beta, gamma, end)."""
    rows = paper.TABLE5_3["rows"]
    return {f"Text{i + 1}": str(v) for i, v in enumerate(rows["start"] + rows["end"])}


def table5_4_cascade():
    """Table 5-4 as the listing computes it, after each cumulative repair of
    :data:`REPAIRS`: one row per step, columns ``start theta1`` .. ``end theta5`` [deg]."""
    import pandas as pd

    rows = []
    for step in REPAIRS:
        out = vb6.run(repaired_listing(step), "Command1_Click", table5_3_inputs())
        loc = {k: float(vb6.to_number(v).value) for k, v in out["locals"].items()
               if k.startswith("θ") and v.type != vb6.EMPTY}  # fmt: skip
        row = {"step": step}
        row.update({f"start theta{j}": loc[f"θ{j}"] for j in range(1, 6)})
        row.update({f"end theta{j}": loc[f"θf{j}"] for j in range(1, 6)})
        rows.append(row)
    return pd.DataFrame(rows).set_index("step")


# --------------------------------------------------------------------------- register helpers


def numbers(text: str) -> list[float]:
    """The numbers in a text, in order."""
    return [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?", text)]


@cache
def printed_run() -> dict:
    """The listing (cf3 repaired) on Table 5-3: what the 计算 button displays."""
    return vb6.run(vb6.listing(), "Command1_Click", table5_3_inputs())


def printed_cells() -> tuple[float, ...]:
    """Table 5-4 as printed, start theta1 .. theta5 then end (gr1_thesis.TABLE5_4)."""
    rows = paper.TABLE5_4["rows"]
    return (*rows["start"], *rows["end"])


def cells_matching(src: str, **options) -> int:
    """How many of Table 5-4's ten printed cells the listing ``src`` displays for Table 5-3."""
    out = vb6.run(src, "Command1_Click", table5_3_inputs(), **options)["text"]
    cells = dict(zip([f"Text{i}" for i in range(13, 23)], printed_cells(), strict=True))
    return sum(out[b] == vb6.vb_format(v, "####.###") for b, v in cells.items())
