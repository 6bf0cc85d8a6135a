"""Seed 001 (Li & Hu 2021, palletizer) checked: every printed item of
:mod:`analysis.papers.palletizer` against a derivation or a run, as :class:`Finding` records.

Derivations
-----------
* Symbolic: the product of the five printed matrices of section 4.2 (eq. 9) is the
  reference for eq. 11; eq. 8 is held against the modified D-H link transform of
  :mod:`analysis.kinematics.dh` (Craig), and each printed matrix against eq. 8.
* Numeric: the printed IK chain (eqs. 1-6, 12) evaluated with each formula as printed or
  corrected (:func:`ik_chain`), the four elbow/waist solutions of the arm (:func:`all_ik`),
  forward kinematics by the D-H chain of the one description of the arm,
  ``data/arms/palletizer.toml`` (``load_arm("palletizer")``). The paper prints no length:
  L1, L2, L3, h are parameters (every function takes an :class:`~analysis.kinematics.arm.Arm`,
  e.g. ``Arm(arm.params.with_(L2=150.0))``), their default values are ASSUMED, in the
  isosceles family L1 = L2 = 200, L3 = 50, h = 70 mm, and every evidence text says so.
* The corrected IK itself is the shared closed form (:mod:`analysis.kinematics.arms.
  palletizer`, via :meth:`Arm.solve`); :func:`ik_chain` with every item fixed is an
  independent coding of it (the tests hold the two together), and :func:`fk_ik_pinocchio`
  closes the loop through Pinocchio.

Corrected IK (elbow above the shoulder-wrist line, waist facing the target)::

    rho = hypot(X0, Y0);  gamma = atan2(Y0, X0)                      (eqs. 1, 6)
    L4 = hypot(rho - L3, Z0 + h)                                     (eq. 2)
    alpha1 = acos((L1^2 + L4^2 - L2^2) / (2 L1 L4))                  (eq. 3)
    alpha2 = atan2(Z0 + h, rho - L3)      (H = Z0 + h; eq. 3 prints arcsin(H/L4'))
    beta1  = acos((L1^2 + L2^2 - L4^2) / (2 L1 L2))  (eq. 3 prints no arccos)
    alpha = alpha1 + alpha2 - pi/2  (eq. 4 prints pi/2 - alpha1 + alpha2);  beta = pi/2 - beta1
    theta = -alpha + beta                                            (eq. 5)
    theta1..4 = gamma, -pi/2 - alpha, pi/2 + beta, pi/2 - (theta2 + theta3)  (eq. 12)
"""

from __future__ import annotations

from functools import cache

import numpy as np
import numpy.typing as npt
import sympy as sp

from analysis.audit.findings import Finding
from analysis.kinematics.arm import Arm, load_arm
from analysis.kinematics.dh import DHRow, DHTable, link_transform_sym
from analysis.papers import palletizer as paper

__all__ = [
    "FIXES",
    "QUADRANT_TARGETS",
    "all_ik",
    "assumed_lengths",
    "derived_tool_position",
    "eq11_printed_position",
    "eq11_residuals",
    "findings",
    "fk_ik_pinocchio",
    "gamma_eq6",
    "ik_chain",
    "lengths",
    "level_configurations",
    "symbolic_table",
    "uniqueness_counts",
]

S = paper.SYMBOLS
TH = tuple(S[f"theta{i}"] for i in range(1, 5))
FIXES = ("gamma", "H", "alpha2", "beta1", "alpha", "theta4")
"""Printed items of the IK chain that :func:`ik_chain` can take as printed or corrected."""

QUADRANT_TARGETS = np.array(
    [[200.0, 100.0, 50.0], [-200.0, 100.0, 80.0], [-200.0, -100.0, 80.0], [150.0, -120.0, 30.0]]
)
"""Four illustrative targets [mm], one per quadrant, Z > 0 (section 5's layout; the paper's
own four targets are in the lost Tables 2-3)."""


def lengths(arm: Arm) -> tuple[float, float, float, float]:
    """(L1, L2, L3, h) [mm] of an arm of the palletizer description."""
    P = arm.params
    return P["L1"], P["L2"], P["L3"], P["h"]


def assumed_lengths(arm: Arm) -> str:
    """The lengths in use, each marked ``assumed`` unless the description says otherwise
    (the paper prints none): the phrase every evidence text that depends on them carries."""
    desc = arm.description
    parts = []
    for k in ("L1", "L2", "L3", "h"):
        status = desc.parameters[k].status if arm.params[k] == desc.parameters[k].value else ""
        parts.append(f"{k} = {arm.params[k]:g} mm" + (" assumed" if status != "printed" else ""))
    return ", ".join(parts)


# --------------------------------------------------------------------------- symbolic
def symbolic_table() -> DHTable:
    """The modified D-H table implied by the five printed matrices (Table 1 is lost), with
    the paper's symbols L1, L2, L3, h: alpha_{i-1} = 0, -90, 0, 0, 90 deg; a_{i-1} = 0, 0,
    L1, L2, h; d_i = 0, 0, 0, 0, L3; the last row fixed (theta5 = 0)."""
    L1, L2, L3, h = S["L1"], S["L2"], S["L3"], S["h"]
    rows = (
        DHRow(0.0, 0, 0, name="theta1"),
        DHRow(-np.pi / 2, 0, 0, name="theta2"),
        DHRow(0.0, L1, 0, name="theta3"),
        DHRow(0.0, L2, 0, name="theta4"),
        DHRow(np.pi / 2, h, L3, kind="fixed", name="tool"),
    )
    return DHTable(rows, "modified", "seed 001, sec. 4.2 matrices")


@cache
def derived_tool_position() -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """(t14, t24, t34) of ``0_1T 1_2T 2_3T 3_4T 4_5T`` (eq. 9) from the printed matrices."""
    T = sp.eye(4)
    for name in ("T01", "T12", "T23", "T34", "T45"):
        T = T * paper.matrix(name)
    return tuple(sp.expand(T[i, 3]) for i in range(3))


def _zero(e: sp.Expr) -> bool:
    """Exact zero test: polynomial expansion first (enough for products of the printed
    matrices), trigonometric simplification only if that leaves terms."""
    e = sp.expand(e)
    if e == 0:
        return True
    probe = {x: sp.Rational(3 + 7 * k, 11) for k, x in enumerate(sorted(e.free_symbols, key=str))}
    if abs(complex(e.subs(probe).evalf(30))) > 1e-20:  # a nonzero value decides at once
        return False
    return sp.simplify(sp.expand_trig(e)) == 0


@cache
def eq11_residuals() -> tuple[dict, ...]:
    """Each printed row of eq. 11 against t14, t24, t34 of the printed matrices' product.

    Returns one dict per printed row: its label, which derived entry it equals once
    ``s4L3`` in its second factor reads ``c4L3`` (``matches``), the residual as printed
    (simplified) and whether the single substitution removes it.
    """
    derived = dict(zip(("t14", "t24", "t34"), derived_tool_position(), strict=True))
    bad = "(sin(theta4)*h - sin(theta4)*L3)"
    good = "(sin(theta4)*h - cos(theta4)*L3)"
    out = []
    for part in paper.EQUATIONS["eq11"]["parts"]:
        printed = paper.parse(part["rhs"])
        fixed = paper.parse(part["rhs"].replace(bad, good))
        matches = [k for k, d in derived.items() if _zero(fixed - d)]
        target = derived[part["label"]]
        out.append(
            {
                "label": part["label"],
                "matches": matches,
                "residual": sp.factor(sp.expand(printed - target)),
                "residual_vs_match": sp.factor(sp.expand(printed - derived[matches[0]]))
                if matches
                else None,
                "fixed_by_c4L3": bool(matches),
            }
        )
    return tuple(out)


def eq8_checks() -> dict[str, bool]:
    """Eq. 8 as printed and with the glyph a_{i-1} -> alpha_{i-1} in sin/cos, against the
    modified D-H link transform; and each printed matrix against eq. 8 at its row."""
    th, al, a, d = S["theta_i"], S["alpha_im1"], S["a_im1"], S["d_i"]
    craig = link_transform_sym(th, d, a, al, "modified")
    printed = paper.matrix("eq8")
    glyph_fixed = printed.subs({sp.sin(a): sp.sin(al), sp.cos(a): sp.cos(al)})
    out = {
        "eq8 as printed == Craig": _zero_matrix(printed - craig),
        "eq8 with alpha for a in sin/cos == Craig": _zero_matrix(glyph_fixed - craig),
    }
    table = symbolic_table()
    q = [*TH]
    mats = table.transforms_sym(q)
    for name, M in zip(("T01", "T12", "T23", "T34", "T45"), mats, strict=True):
        out[f"{name} == modified D-H row"] = _zero_matrix(paper.matrix(name) - M)
    # eq. 8 exactly as printed, at the row of 1_2T (a_1 = 0, alpha_1 = -90 deg)
    row2 = printed.subs({th: TH[1], al: -sp.pi / 2, a: 0, d: 0})
    out["T12 from eq8 as printed"] = _zero_matrix(paper.matrix("T12") - row2)
    return out


def _zero_matrix(M: sp.Matrix) -> bool:
    return all(_zero(e) for e in M)


# --------------------------------------------------------------------------- numeric
@cache
def _eq11_functions():
    args = (*TH, S["L1"], S["L2"], S["L3"], S["h"])
    rows = [paper.parse(p["rhs"]) for p in paper.EQUATIONS["eq11"]["parts"]]
    return sp.lambdify(args, rows, "numpy")


def eq11_printed_position(arm: Arm, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Gripper tip by eq. 11 as printed (rows 1-3 as x, y, z) [mm], (..., 3), for D-H
    angles (..., 4) [rad]."""
    q = np.asarray(q, dtype=float)
    f = _eq11_functions()
    rows = f(*np.moveaxis(q, -1, 0), *lengths(arm))
    return np.stack(np.broadcast_arrays(*rows), axis=-1)


def gamma_eq6(x0, y0, reading: str = "signed") -> npt.NDArray[np.float64]:
    """Eqs. 1 and 6 as printed [rad], NaN where they are undefined (X0 = 0 in eq. 1;
    X0 <= 0 with Y0 = 0 has no case in eq. 6). ``reading``: "signed" arctan(Y0/X0) or
    "acute" arctan|Y0/X0|."""
    x0, y0 = np.broadcast_arrays(np.asarray(x0, float), np.asarray(y0, float))
    if reading not in ("signed", "acute"):
        raise ValueError(f"unknown reading {reading!r}; expected 'signed' or 'acute'")
    with np.errstate(divide="ignore", invalid="ignore"):
        r = y0 / x0
        g = np.arctan(r) if reading == "signed" else np.arctan(np.abs(r))
    out = np.where(x0 > 0, g, np.where(y0 > 0, np.pi - g, np.where(y0 < 0, -np.pi / 2 + g, np.nan)))
    return np.where(x0 == 0, np.nan, out)


def ik_chain(
    arm: Arm,
    target: npt.ArrayLike,
    fixed=(),
    H_reading: str = "height",
    arctan_reading: str = "signed",
) -> dict[str, npt.NDArray[np.float64]]:
    """Eqs. 1-6 and 12, each printed item as printed unless named in ``fixed``.

    Parameters
    ----------
    arm : Arm
        The palletizer (lengths L1, L2, L3, h [mm]: parameters, assumed).
    target : array_like, shape (..., 3)
        G = (X0, Y0, Z0) [mm].
    fixed : iterable of str
        Items of :data:`FIXES` to take corrected: ``gamma`` (atan2 for eqs. 1, 6),
        ``H`` (no effect on its own: H = Z0 + h is the inferred reading), ``alpha2``
        (atan2(Z0 + h, rho - L3) for arcsin(H/L4)), ``beta1`` (arccos restored), ``alpha``
        (alpha1 + alpha2 - pi/2 for pi/2 - alpha1 + alpha2), ``theta4``
        (pi/2 - (theta2 + theta3)).
    H_reading : {"height", "depth"}
        Eq. 3's undefined H as Z0 + h or as -(Z0 + h).
    arctan_reading : {"signed", "acute"}
        Eq. 1's arctan.

    Returns
    -------
    dict
        ``motor`` (..., 4) = (gamma, alpha, beta, theta) [rad], ``q`` (..., 4) D-H angles by
        eq. 12 [rad]; NaN where a printed formula is undefined.
    """
    unknown = set(fixed) - set(FIXES)
    if unknown:
        raise ValueError(f"unknown item(s) {sorted(unknown)}; expected a subset of {FIXES}")
    if H_reading not in ("height", "depth"):
        raise ValueError(f"H_reading {H_reading!r}; expected 'height' or 'depth'")
    p = np.asarray(target, dtype=float)
    x0, y0, z0 = np.moveaxis(p, -1, 0)
    L1, L2, L3, h = lengths(arm)
    rho = np.hypot(x0, y0)
    with np.errstate(invalid="ignore", divide="ignore"):
        gamma = np.arctan2(y0, x0) if "gamma" in fixed else gamma_eq6(x0, y0, arctan_reading)
        L4 = np.sqrt((rho - L3) ** 2 + (z0 + h) ** 2)  # eq. 2 (inferred grouping)
        alpha1 = np.arccos((L1**2 + L4**2 - L2**2) / (2 * L1 * L4))
        H = (z0 + h) if (H_reading == "height" or "H" in fixed) else -(z0 + h)
        alpha2 = np.arctan2(z0 + h, rho - L3) if "alpha2" in fixed else np.arcsin(H / L4)
        cos_b = (L1**2 + L2**2 - L4**2) / (2 * L1 * L2)
        beta1 = np.arccos(cos_b) if "beta1" in fixed else cos_b
    alpha = alpha1 + alpha2 - np.pi / 2 if "alpha" in fixed else np.pi / 2 - alpha1 + alpha2
    beta = np.pi / 2 - beta1
    theta = -alpha + beta
    t1, t2, t3 = gamma, -np.pi / 2 - alpha, np.pi / 2 + beta
    t4 = np.pi / 2 - (t2 + t3) if "theta4" in fixed else np.pi / 2 - t2 + t3
    return {
        "motor": np.stack([gamma, alpha, beta, theta], axis=-1),
        "q": np.stack([t1, t2, t3, t4], axis=-1),
    }


def miss(arm: Arm, target, q, eq11: str = "product") -> npt.NDArray[np.float64]:
    """Distance [mm] from the target to the gripper tip at D-H angles q, by the D-H product
    (``"product"``) or by eq. 11 as printed (``"printed"``); NaN where q is NaN."""
    q = np.asarray(q, dtype=float)
    ok = np.isfinite(q).all(axis=-1)
    qq = np.where(ok[..., None], q, 0.0)
    tip = arm.fk(qq) if eq11 == "product" else eq11_printed_position(arm, qq)
    return np.where(ok, np.linalg.norm(tip - np.asarray(target, float), axis=-1), np.nan)


BRANCHES = ("front-up", "front-down", "back-up", "back-down")


def all_ik(arm: Arm, target: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """All D-H solutions (..., 4 branches, 4 angles) [rad] with the gripper level, NaN where
    a branch does not reach. Branches :data:`BRANCHES`: the waist facing the target
    (gamma = atan2) or turned by pi (the arm reaching back over its base), the elbow above
    ("up", theta3 > 0) or below the shoulder-wrist line."""
    p = np.asarray(target, dtype=float)
    x0, y0, z0 = np.moveaxis(p, -1, 0)
    L1, L2, L3, h = lengths(arm)
    rho, zw = np.hypot(x0, y0), z0 + h
    g = np.arctan2(y0, x0)
    out = []
    for waist, w in ((g, rho - L3), (g + np.pi, -rho - L3)):
        L4 = np.hypot(w, zw)
        with np.errstate(invalid="ignore", divide="ignore"):
            a1 = np.arccos((L1**2 + L4**2 - L2**2) / (2 * L1 * L4))
            b1 = np.arccos((L1**2 + L2**2 - L4**2) / (2 * L1 * L2))
        elev = np.arctan2(zw, w)
        for sign in (1.0, -1.0):
            t2 = -(elev + sign * a1)
            t3 = sign * (np.pi - b1)
            t4 = np.pi / 2 - (t2 + t3)
            t1 = np.mod(waist + np.pi, 2 * np.pi) - np.pi
            out.append(np.stack([t1, t2, t3, t4], axis=-1))
    return np.stack(out, axis=-2)


def uniqueness_counts(arm: Arm, targets: npt.ArrayLike) -> dict[str, npt.NDArray]:
    """Per target, how many of the four solutions satisfy each reading of the section 2
    limit "小臂和大臂之間的夾角小於90°", and the candidate joint limits.

    Returns counts (n,) for: ``reachable`` (all solutions), ``interior<90`` (elbow
    interior angle beta1 < 90 deg), ``between-directions<90`` (|theta3| < 90 deg, the angle
    between the link directions), ``elbow-up`` (theta3 in (0, pi), i.e. beta > -90 deg),
    ``elbow-up+front`` (and the waist facing the target, eq. 6), ``stop`` (theta3 within
    the description's limit of theta3, the signed stop of ``data/arms/palletizer.toml``:
    [90, 180] deg) and ``stop+front`` (and the waist facing the target).
    """
    q = all_ik(arm, targets)
    ok = np.isfinite(q).all(axis=-1)
    t3 = np.where(ok, q[..., 2], np.nan)
    beta1 = np.pi - np.abs(t3)
    lim = arm.limits[2] or (-np.inf, np.inf)
    with np.errstate(invalid="ignore"):
        stop = ok & (t3 >= lim[0]) & (t3 <= lim[1])
        return {
            "reachable": ok.sum(-1),
            "interior<90": (ok & (beta1 < np.pi / 2)).sum(-1),
            "between-directions<90": (ok & (np.abs(t3) < np.pi / 2)).sum(-1),
            "elbow-up": (ok & (t3 > 0)).sum(-1),
            "elbow-up+front": (ok[..., 0] & (t3[..., 0] > 0)).astype(int),
            "stop": stop.sum(-1),
            "stop+front": stop[..., 0].astype(int),
        }


def level_configurations(
    arm: Arm, n: int, rng: np.random.Generator, margin_deg: float = 2.0
) -> npt.NDArray[np.float64]:
    """n seeded D-H configurations (n, 4) [rad] the palletizer can take: gripper level
    (theta4 = pi/2 - theta2 - theta3, sec. 3), theta3 inside its limit by ``margin_deg``
    (for L1 = L2 the fold theta3 = 180 deg puts the wrist on the shoulder), theta1, theta2
    in (-180, 180) deg, and the grasp point at least 1 mm in front of the base axis in the
    arm's plane (its radius along the waist direction theta1 > 1 mm: the waist faces it,
    as eq. 6 has it; an upper arm leaning back over the base can put the point behind).

    The IK is unique on this set (the waist faces the target, theta3 is in the stop), so
    :meth:`Arm.solve` must return these very angles.
    """
    lo, hi = arm.limits[2] or (-np.pi, np.pi)
    m = np.radians(margin_deg)
    out = np.empty((0, 4))
    while len(out) < n:
        k = 2 * n
        t1 = rng.uniform(-np.pi, np.pi, k)
        t2 = rng.uniform(-np.pi, np.pi, k)
        t3 = rng.uniform(max(lo, 0.0) + m, min(hi, np.pi) - m, k)
        t4 = np.mod(np.pi / 2 - t2 - t3 + np.pi, 2 * np.pi) - np.pi
        q = np.stack([t1, t2, t3, t4], axis=-1)
        p = arm.fk(q)
        q = q[p[:, 0] * np.cos(t1) + p[:, 1] * np.sin(t1) > 1.0]
        out = np.concatenate([out, q])
    return out[:n]


def fk_ik_pinocchio(arm: Arm, n: int = 10_000, seed: int = 20210401) -> dict:
    """FK(IK(G)) = G with both forward kinematics by Pinocchio (built from the arm's D-H
    chain, :class:`~analysis.kinematics.pinocchio_model.PinocchioArm`) and the IK by the
    shared solver (:meth:`Arm.solve`, joint limits on).

    G = Pinocchio FK of :func:`level_configurations`; q = IK(G); G' = Pinocchio FK of q.

    Returns ``n``, ``max_err_mm`` (max |G' - G|), ``max_dq_rad`` (max |q - q0|, angles
    wrapped), ``all_ok`` (every target solved, status 0) and ``status`` counts.
    """
    from analysis.kinematics.pinocchio_model import PinocchioArm

    rng = np.random.default_rng(seed)
    q0 = level_configurations(arm, n, rng)
    pin_arm = PinocchioArm(arm.table)
    G = pin_arm.fk(q0)
    sol = arm.solve(G, arm.branches[0])
    q = sol.theta[:, 0]
    ok = sol.ok[:, 0]
    G2 = pin_arm.fk(np.where(ok[:, None], q, 0.0))
    err = np.linalg.norm(G2 - G, axis=-1)
    dq = np.abs(np.mod(q - q0 + np.pi, 2 * np.pi) - np.pi)
    return {
        "n": n,
        "max_err_mm": float(err[ok].max()) if ok.any() else float("nan"),
        "max_dq_rad": float(dq[ok].max()) if ok.any() else float("nan"),
        "all_ok": bool(ok.all()),
        "status": {
            int(s): int(c) for s, c in zip(*np.unique(sol.status, return_counts=True), strict=True)
        },
    }


def workspace_grid(arm: Arm, n: int = 41) -> npt.NDArray[np.float64]:
    """Targets [mm] on a regular grid (x, y in +-(L1 + L2 + L3), z in [0, L1 + L2]) that the
    front-up branch reaches (acos arguments strictly inside (-1, 1)), joint limits ignored."""
    P = arm.params
    r = P.L1 + P.L2 + P.L3
    xs = np.linspace(-r, r, n)
    zs = np.linspace(1.0, P.L1 + P.L2, (n + 1) // 2)
    G = np.stack(np.meshgrid(xs, xs, zs, indexing="ij"), axis=-1).reshape(-1, 3)
    q = all_ik(arm, G)[:, 0]
    L4 = np.hypot(np.hypot(G[:, 0], G[:, 1]) - P.L3, G[:, 2] + P.h)
    keep = np.isfinite(q).all(-1) & (L4 < 0.999 * (P.L1 + P.L2)) & (L4 > 1e-3)
    keep &= np.abs(P.L1 - P.L2) * 1.001 < L4
    return G[keep]


# --------------------------------------------------------------------------- findings
def _fmt(v) -> str:
    return np.array2string(np.asarray(v), precision=2, separator=", ", suppress_small=True)


def _quadrant_misses(arm, fixed, **kw) -> npt.NDArray[np.float64]:
    return miss(arm, QUADRANT_TARGETS, ik_chain(arm, QUADRANT_TARGETS, fixed, **kw)["q"])


def findings(arm: Arm | None = None) -> list[Finding]:
    """Every checked item of seed 001, wrong ones with a correction, from the runs above."""
    arm = arm if arm is not None else load_arm("palletizer")
    P = arm.params
    all_fix = set(FIXES)
    out: list[Finding] = []
    dims = assumed_lengths(arm)
    G = QUADRANT_TARGETS

    # sanity: everything corrected reaches every quadrant target
    base = _quadrant_misses(arm, all_fix)
    if not np.all(base < 1e-9):  # pragma: no cover - guarded by the tests
        raise AssertionError(f"corrected chain misses {base}")

    # eq. 11
    res = eq11_residuals()
    q_eq7 = np.array([0.0, -np.pi / 2, np.pi / 2, np.pi / 2])
    eq7_err = float(np.linalg.norm(eq11_printed_position(arm, q_eq7) - arm.fk(q_eq7)))
    q_g = ik_chain(arm, G, all_fix)["q"]
    m11 = miss(arm, G, q_g, eq11="printed")
    out.append(
        Finding(
            "pal-eq11-s4L3",
            "eq. 11, all three rows, second factor",
            "s4h - s4L3",
            "s4h - c4L3",
            "transcription",
            "against t14, t24, t34 of the product of the printed 0_1T..4_5T (eq. 9): "
            f"printed - derived = {sp.sstr(res[0]['residual'])} (row 1), "
            "zero in every row after s4L3 -> c4L3, i.e. an error of L3|s4 - c4| "
            f"in length: at eq. 7's pose {eq7_err:.3g} mm (= L3); at the corrected IK of the "
            f"four quadrant targets {_fmt(m11)} mm ({dims})",
        )
    )
    out.append(
        Finding(
            "pal-eq11-label",
            "eq. 11, row 2 label",
            "t34",
            "t24",
            "label",
            f"row 2 (s4L3 -> c4L3) equals derived {res[1]['matches']} of the printed "
            f"matrices' product; rows 1 and 3 equal {res[0]['matches']} and {res[2]['matches']}"
            "; the text after eq. 10 names t14, t24, t34 as the tip coordinates",
        )
    )

    # eq. 8
    e8 = eq8_checks()
    out.append(
        Finding(
            "pal-eq8-glyph",
            "eq. 8, rows 2-3: sin/cos of a_{i-1}",
            "-sin(a_im1), -d_i*sin(a_im1), sin(theta_i)*sin(a_im1), cos(theta_i)*sin(a_im1), "
            "cos(a_im1), d_i*cos(a_im1)",
            "the same with alpha_im1 for a_im1 inside sin/cos",
            "transcription",
            f"as printed == Craig's modified D-H: {e8['eq8 as printed == Craig']}; with alpha "
            f"for a: {e8['eq8 with alpha for a in sin/cos == Craig']}; 1_2T (a_1 = 0, "
            f"alpha_1 = -90 deg) from eq. 8 as printed: {e8['T12 from eq8 as printed']} "
            "(sin(a_1) = 0 would zero row 2 col 3, printed 1). Print or extraction: UNCERTAIN.",
        )
    )
    mats_ok = all(v for k, v in e8.items() if k.startswith("T") and "==" in k)
    out.append(
        Finding(
            "pal-matrices",
            "sec. 4.2, 0_1T .. 4_5T",
            "five matrices",
            "",
            "",
            f"each equals the modified D-H transform of the row alpha_(i-1) = 0, -90, 0, 0, 90 "
            f"deg, a_(i-1) = 0, 0, L1, L2, h, d_i = 0, 0, 0, 0, L3: {mats_ok} (Table 1 lost; "
            "the rows are read off these matrices)",
            "holds" if mats_ok else "wrong",
        )
    )

    # eq. 12 theta4 and eq. 7
    zero_motor = np.array([0.0, -np.pi / 2, np.pi / 2, np.pi / 2 - (-np.pi / 2) + np.pi / 2])
    home_tip = arm.fk(q_eq7)
    m_t4 = _quadrant_misses(arm, all_fix - {"theta4"})
    out.append(
        Finding(
            "pal-eq12-theta4",
            "eq. 12, theta4",
            "theta4 = pi/2 - theta2 + theta3",
            "theta4 = pi/2 - (theta2 + theta3)  (= pi/2 - theta, theta of eq. 5)",
            "sign",
            "gripper parallel to the base (sec. 3, theta5 = 0) needs theta2 + theta3 + theta4 "
            "= pi/2, the value at eq. 7; as printed the sum is 3 pi/2 + 2 beta. At zero motor "
            f"angles eq. 12 gives theta4 = {np.degrees(zero_motor[3]):.0f} deg, eq. 7 says 90 "
            f"deg; tip {_fmt(arm.fk(zero_motor))} mm instead of {_fmt(home_tip)} mm. Only this "
            f"item printed: misses {_fmt(m_t4)} mm at the four quadrant targets ({dims}). "
            "Lost parentheses in the extraction cannot be excluded (UNCERTAIN).",
        )
    )

    # eq. 4 / eq. 12 sign of alpha, both readings of H
    m_a_h = _quadrant_misses(arm, all_fix - {"alpha"}, H_reading="height")
    m_a_d = _quadrant_misses(arm, all_fix - {"alpha", "alpha2", "H"}, H_reading="depth")
    m_init = miss(arm, home_tip, ik_chain(arm, home_tip, all_fix - {"alpha"})["q"])
    m_init_d = miss(
        arm,
        home_tip,
        ik_chain(arm, home_tip, all_fix - {"alpha", "alpha2", "H"}, H_reading="depth")["q"],
    )
    out.append(
        Finding(
            "pal-eq4-alpha",
            "eq. 4 (alpha) with eq. 12 (theta2)",
            "alpha = pi/2 - alpha1 + alpha2",
            "alpha = alpha1 + alpha2 - pi/2 (alpha2 = atan2(Z0 + h, rho - L3))",
            "sign",
            "eq. 12's theta2 = -pi/2 - alpha puts the upper arm at elevation pi/2 + alpha, the "
            "law of cosines at alpha1 + alpha2 (elbow up): one sign is wrong. Eq. 4 as printed "
            f"misses {_fmt(m_a_h)} mm with H = Z0 + h and {_fmt(m_a_d)} mm with H = -(Z0 + h) "
            f"at the quadrant targets; at the initial pose {float(m_init):.2f} mm (H = Z0 + h) "
            f"and {float(m_init_d):.2g} mm (H = -(Z0 + h), right only where alpha1 + alpha2 = "
            "pi/2, as at the initial pose). "
            "Equivalent fix: theta2 = -pi/2 + alpha in eq. 12 with H = -(Z0 + h), which then "
            "needs theta = alpha + beta in eq. 5; the correction above changes one equation "
            "and keeps eqs. 5 and 12 (theta1-theta3). With it alpha > 0 tilts the upper arm "
            "backwards while beta > 0 folds the forearm down, opposite senses, so the text's "
            "'both clockwise about +Y2, +Y3' needs +Y2 = -Y3 (Figure 2 lost).",
        )
    )

    # eq. 3: H, alpha2 branch, beta1 arccos
    out.append(
        Finding(
            "pal-eq3-H",
            "eq. 3, alpha2",
            "alpha2 = asin(H/L4p)  (H never defined)",
            "H = Z0 + h (the vertical leg of eq. 2's triangle)",
            "undefined symbol",
            "H appears only in eq. 3; eq. 2's triangle has legs sqrt(X0^2+Y0^2) - L3' and "
            "Z0 + h. The depth reading -(Z0 + h) flips alpha2's sign (see pal-eq4-alpha).",
        )
    )
    behind = np.array([[30.0, 10.0, 100.0]])
    m_a2 = miss(arm, behind, ik_chain(arm, behind, all_fix - {"alpha2"})["q"])
    grid = workspace_grid(arm)
    m_grid = miss(arm, grid, ik_chain(arm, grid, all_fix - {"alpha2"})["q"])
    rho_g = np.hypot(grid[:, 0], grid[:, 1])
    wrong_a2 = m_grid > 1e-6
    out.append(
        Finding(
            "pal-eq3-alpha2",
            "eq. 3, alpha2",
            "alpha2 = asin(H/L4p)",
            "alpha2 = atan2(Z0 + h, sqrt(X0**2 + Y0**2) - L3)",
            "branch/quadrant",
            "arcsin returns the elevation of the shoulder-wrist line only while the wrist is in "
            "front of the base axis (rho > L3). On a grid of "
            f"{len(grid)} reachable targets it misses on {int(wrong_a2.sum())}, all with rho < "
            f"L3 (max rho there {rho_g[wrong_a2].max() if wrong_a2.any() else 0:.1f} mm); "
            f"e.g. G = (30, 10, 100) mm misses {float(m_a2[0]):.2f} mm ({dims})",
        )
    )
    m_b1 = _quadrant_misses(arm, all_fix - {"beta1"})
    chain_home = ik_chain(arm, home_tip, all_fix - {"beta1"})["motor"]
    out.append(
        Finding(
            "pal-eq3-beta1",
            "eq. 3, beta1",
            "beta1 = (L1p**2 + L2p**2 - L4p**2)/(2*L1p*L2p)",
            "beta1 = acos((L1p**2 + L2p**2 - L4p**2)/(2*L1p*L2p))",
            "missing term",
            "as printed beta1 is a cosine, not an angle: at the initial pose (forearm "
            "perpendicular, L4^2 = L1^2 + L2^2) it gives beta1 = 0 and beta = pi/2 = "
            f"{np.degrees(chain_home[..., 2]):.1f} deg instead of 0; misses {_fmt(m_b1)} mm at "
            "the quadrant targets. The same run keeps arccos for alpha1 (UNCERTAIN: print or "
            "extraction).",
        )
    )

    # eqs. 1 and 6
    az = np.radians(np.arange(-179.5, 180.0, 1.0))
    xs, ys = 200 * np.cos(az), 200 * np.sin(az)
    ref = np.arctan2(ys, xs)
    wrong = {
        r: ~np.isclose(np.mod(gamma_eq6(xs, ys, r) - ref + np.pi, 2 * np.pi) - np.pi, 0.0)
        for r in ("signed", "acute")
    }
    quad = np.floor(np.mod(np.degrees(az), 360) / 90).astype(int) + 1
    bad_q = {r: sorted({int(k) for k in quad[w]}) for r, w in wrong.items()}
    m_g = _quadrant_misses(arm, all_fix - {"gamma"})
    m_g_acute = _quadrant_misses(arm, all_fix - {"gamma"}, arctan_reading="acute")
    out.append(
        Finding(
            "pal-eq6-quadrant",
            "eqs. 1 and 6",
            "gamma = Piecewise((gammap, X0 > 0), (pi - gammap, X0 <= 0 & Y0 > 0), "
            "(-pi/2 + gammap, X0 <= 0 & Y0 < 0)), gammap = atan(Y0/X0)",
            "gamma = atan2(Y0, X0)",
            "branch/quadrant",
            f"over 360 azimuths: signed arctan wrong on {int(wrong['signed'].sum())} (quadrants "
            f"{bad_q['signed']}), acute arctan|Y0/X0| wrong on {int(wrong['acute'].sum())} "
            f"(quadrants {bad_q['acute']}); quadrant 3 is wrong under both (-pi/2 + gamma' "
            "should be -pi + gamma'). Undefined at X0 = 0 (eq. 1 divides by zero) and for "
            f"X0 < 0, Y0 = 0 (no case). Quadrant targets miss {_fmt(m_g)} mm (signed) and "
            f"{_fmt(m_g_acute)} mm (acute).",
        )
    )

    # claims
    counts = uniqueness_counts(arm, grid)
    c_int = np.bincount(counts["interior<90"], minlength=5)
    c_dir = np.bincount(counts["between-directions<90"], minlength=5)
    c_up = np.bincount(counts["elbow-up"], minlength=5)
    c_all = np.bincount(counts["reachable"], minlength=5)
    c_stop = np.bincount(counts["stop"], minlength=5)
    n_stop = int(counts["stop+front"].sum())
    lim = np.degrees(arm.limits[2]) if arm.limits[2] else (-180.0, 180.0)
    out.append(
        Finding(
            "pal-claim-unique",
            "sec. 2, third paragraph",
            "小臂和大臂之間的夾角小於90°, 所以其抓取時的位置狀態是唯一的",
            "the included angle bounds no sign: the elbow-down mirror pose has the same angle. "
            f"A stop on the signed elbow angle, theta3 in [{lim[0]:g}, {lim[1]:g}] deg "
            "(data/arms/palletizer.toml), makes the pose unique with the waist facing the "
            "target (eq. 6); '<= 90 deg', since the initial pose has exactly 90 deg",
            "reasoning",
            f"{len(grid)} grid targets reachable by the front elbow-up branch ({dims}): "
            f"number of solutions (0-4) reaching each: {c_all.tolist()}; of these satisfying "
            f"'interior angle < 90 deg': {c_int.tolist()} (the limit removes "
            f"{c_int[0] / len(grid):.0%} of the targets); '|theta3| < 90 deg': "
            f"{c_dir.tolist()}; 'theta3 > 0': {c_up.tolist()}; with theta3 > 0 and eq. 6's "
            f"waist: 1 for all {int(counts['elbow-up+front'].sum())}. Under either unsigned "
            "reading of the angle the count is even (0, 2 or 4), never 1. With the signed stop "
            f"theta3 in [{lim[0]:g}, {lim[1]:g}] deg: {c_stop.tolist()}, 1 with the waist "
            f"facing the target for all {n_stop} targets it keeps (the waist-reversed pose, "
            "upper arm leaning back over the base, satisfies the stop too for "
            f"{int((counts['stop'] == 2).sum())} of them: only eq. 6's waist, or a limit on "
            "theta2 that the paper does not print, excludes it). The paper's own initial pose "
            "(forearm perpendicular to the upper arm, sec. 3) sits at exactly 90 deg, outside "
            "'< 90 deg'.",
        )
    )
    unreachable = np.array([500.0, 0.0, 0.0])
    L4_u = float(np.hypot(500.0 - P.L3, P.h))
    out.append(
        Finding(
            "pal-claim-isosceles",
            "sec. 3, before eq. 1 and after eq. 2",
            "一定可以構成 ... 等腰三角形",
            "a triangle with sides L1', L2', L4' exists iff |L1 - L2| <= L4 <= L1 + L2; it is "
            "isosceles for every target iff L1 = L2",
            "claim",
            "eq. 3 is the general law of cosines and needs no isosceles triangle; isosceles "
            "for all targets forces L1 = L2, which the paper never states (no length is "
            f"printed; the audit's default family is L1 = L2, {dims}: it satisfies the claim "
            "by assumption, not by the paper). No reach "
            f"check precedes eq. 3: G = {_fmt(unreachable)} mm gives L4 = {L4_u:.1f} mm > "
            f"L1 + L2 = {P.L1 + P.L2:g} mm and arccos of "
            f"{(P.L1**2 + L4_u**2 - P.L2**2) / (2 * P.L1 * L4_u):.3f}.",
        )
    )
    m_printed = _quadrant_misses(arm, ())
    m_printed_11 = miss(arm, G, ik_chain(arm, G, ())["q"], eq11="printed")
    out.append(
        Finding(
            "pal-claim-exact",
            "sec. 5, last paragraph",
            "結果完全等於待抓取點Gi",
            "FK(IK(G)) = G holds only with eqs. 3, 4, 6, 11, 12 corrected (then to ~1e-13 mm in "
            "float64)",
            "claim",
            f"all formulas as printed: misses {_fmt(m_printed)} mm (D-H product) and "
            f"{_fmt(m_printed_11)} mm (eq. 11 as printed) at four quadrant targets (NaN: a "
            "printed formula undefined); corrected chain: "
            + (
                "below 1e-9 mm (float64 round-off)"
                if float(base.max()) < 1e-9
                else f"max {float(base.max()):.3g} mm"
            )
            + ". The paper's own targets and results are in the lost "
            "Tables 2-3, so its numbers cannot be recomputed.",
        )
    )
    out.append(
        Finding(
            "pal-claim-metres",
            "sec. 5, second paragraph",
            "表中Gi和Ti的單位為米(m)",
            "",
            "",
            "unit statement only: no length (L1, L2, L3, h) is printed in any unit, so metres "
            "vs millimetres cannot be checked against the arm (UNCERTAIN by LOST['lengths']).",
            "undecidable",
        )
    )
    out.append(
        Finding(
            "pal-xref-section",
            "sec. 5, third paragraph",
            "第2節中的逆向解算方法",
            "第3節中的逆向解算方法",
            "cross-reference",
            "section 2 is the model simplification; the IK (eqs. 1-6) is section 3 "
            "'3逆向運動學解算', as the conclusion says ('根據第三節提出的幾何法').",
        )
    )
    out.append(
        Finding(
            "pal-xref-reference",
            "sec. 4.1",
            "參照第5篇文獻簡述的方法[6]",
            "參照第6篇文獻簡述的方法[6]",
            "cross-reference",
            "[6] is Owen, Introduction to Robotics (a D-H source); [5] is a beetle-antennae "
            "search IK paper, not a D-H method.",
        )
    )
    # items that hold
    q0 = ik_chain(arm, home_tip, all_fix)["q"]
    out.append(
        Finding(
            "pal-eq7",
            "eq. 7",
            "theta = [0, -pi/2, pi/2, pi/2, 0]",
            "",
            "",
            f"FK at eq. 7 = {_fmt(home_tip)} mm = (L2 + L3, 0, L1 - h): upper arm vertical, "
            "forearm perpendicular, gripper level (sec. 3's initial pose); the corrected IK of "
            f"that point returns {_fmt(np.degrees(q0))} deg",
            "holds",
        )
    )
    out.append(
        Finding(
            "pal-eq2",
            "eq. 2",
            "L4p = sqrt((sqrt(X0**2 + Y0**2) - L3p)**2 + (Z0 + h)**2)",
            "",
            "",
            "with the inferred grouping it is the shoulder-wrist distance of the level gripper "
            "(the corrected chain reaches every quadrant target "
            + ("within 1e-9 mm" if float(base.max()) < 1e-9 else f"to {float(base.max()):.3g} mm")
            + " using it)",
            "holds",
        )
    )
    out.append(
        Finding(
            "pal-eq5",
            "eq. 5",
            "theta = -alpha + beta",
            "",
            "",
            "with eq. 12's theta2 = -pi/2 - alpha, theta3 = pi/2 + beta, theta2 + theta3 = "
            "beta - alpha = theta, so the corrected theta4 = pi/2 - theta keeps the gripper level",
            "holds",
        )
    )
    return out
