"""Seed 001 (Li & Hu 2021, the 4-axis palletizer): its printed method as a model, for the
register's checks (``data/registers/palletizer.toml``) and notebook 11.

Symbolic: the modified D-H table read off the five printed matrices of section 4.2
(:func:`symbolic_table`), their product (eq. 9) as the reference of eq. 11, eq. 8 against
Craig's link transform. Numeric: the printed IK chain (eqs. 1-6, 12) with each item as printed
or corrected (:func:`ik_chain`), the four elbow/waist solutions (:func:`all_ik`), the counts
behind the uniqueness claim of section 2, Pinocchio's forward kinematics. Every function takes
an :class:`~analysis.kinematics.arm.Arm` of ``data/arms/palletizer.toml``, whose lengths are
ASSUMED (the paper prints none).

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

from analysis.audit.kinds.symbolic import is_zero
from analysis.kinematics.arm import Arm
from analysis.kinematics.dh import DHRow, DHTable, link_transform_sym
from analysis.papers import palletizer as paper
from analysis.validate import wrap_rad

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
        matches = [k for k, d in derived.items() if is_zero(fixed - d)]
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
    return all(is_zero(e) for e in M)


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


def all_ik(arm: Arm, target: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """All solutions (..., 4 branches, 4 angles) [rad] with the gripper level, NaN where a
    branch does not reach, joint limits not applied: the arm's own closed form
    (:mod:`analysis.kinematics.arms.palletizer`, branches ``arm.branches``: the waist facing
    the target or turned by pi, the elbow above or below the shoulder-wrist line)."""
    return arm.solve(np.asarray(target, dtype=float), "all", limits=False).theta


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
    front = arm.branches.index("front-up")  # the waist facing the target (eq. 6)
    with np.errstate(invalid="ignore"):
        stop = ok & (t3 >= lim[0]) & (t3 <= lim[1])
        return {
            "reachable": ok.sum(-1),
            "interior<90": (ok & (beta1 < np.pi / 2)).sum(-1),
            "between-directions<90": (ok & (np.abs(t3) < np.pi / 2)).sum(-1),
            "elbow-up": (ok & (t3 > 0)).sum(-1),
            "elbow-up+front": (ok[..., front] & (t3[..., front] > 0)).astype(int),
            "stop": stop.sum(-1),
            "stop+front": stop[..., front].astype(int),
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
        t4 = wrap_rad(np.pi / 2 - t2 - t3)
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
    dq = np.abs(wrap_rad(q - q0))
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


def quadrant_misses(arm: Arm, fixed, **kw) -> npt.NDArray[np.float64]:
    """Misses [mm] at :data:`QUADRANT_TARGETS` of :func:`ik_chain` with ``fixed`` corrected."""
    return miss(arm, QUADRANT_TARGETS, ik_chain(arm, QUADRANT_TARGETS, fixed, **kw)["q"])

# --------------------------------------------------------------------------- the register's domains
def _arm(**changes) -> Arm:
    """The palletizer of data/arms/palletizer.toml, with lengths changed where asked."""
    from analysis.kinematics.arm import load_arm

    arm = load_arm("palletizer")
    return arm.with_(**changes) if changes else arm


def claim_grid() -> dict[str, np.ndarray]:
    """Grid targets, reachable or not, on the assumed arm and on one with L2 = 150 mm: does the
    triangle (L1, L2, L4) of eq. 2 (the waist facing the target) exist? The arm's solver, joint
    limits off, on its front branches."""
    out = []
    for arm in (_arm(), _arm(L2=150.0)):
        L1, L2, L3, h = lengths(arm)
        xs, zs = np.linspace(-540, 540, 13), np.linspace(-h, L1 + L2, 7)
        G = np.stack(np.meshgrid(xs, xs, zs, indexing="ij"), -1).reshape(-1, 3)
        G = G[np.hypot(G[:, 0], G[:, 1]) > 1.0]
        front = [b for b in arm.branches if b.startswith("front")]
        exists = arm.solve(G, front, limits=False).ok.any(axis=-1)
        L4 = np.hypot(np.hypot(G[:, 0], G[:, 1]) - L3, G[:, 2] + h)
        out.append({"L1": np.full(len(G), L1), "L2": np.full(len(G), L2), "L4": L4,
                    "triangle_exists": exists})  # fmt: skip
    return {k: np.concatenate([o[k] for o in out]) for k in out[0]}


def arm_family() -> dict[str, np.ndarray]:
    """The assumed arm and one with L2 = 150 mm: is the triangle isosceles at every quadrant
    target?"""
    rows = []
    for arm in (_arm(), _arm(L2=150.0)):
        L1, L2, L3, h = lengths(arm)
        G = QUADRANT_TARGETS
        L4 = np.hypot(np.hypot(G[:, 0], G[:, 1]) - L3, G[:, 2] + h)
        sides = np.stack([np.full_like(L4, L1), np.full_like(L4, L2), L4], -1)
        d = np.abs(sides[:, [0, 0, 1]] - sides[:, [1, 2, 2]]).min(axis=-1)
        rows.append((L1, L2, bool((d < 1e-9).all())))
    return {k: np.array(v) for k, v in zip(("L1", "L2", "isosceles_everywhere"), zip(*rows, strict=True), strict=True)}  # noqa: E501


def wrong_models() -> dict[str, np.ndarray]:
    """Models with one length wrong (each by 25 %): the round trip FK(IK(G)) through the wrong
    model, and the same angles on the arm, at 200 seeded targets."""
    arm = _arm()
    q = level_configurations(arm, 200, np.random.default_rng(5))
    G, rt, miss = arm.fk(q), [], []
    for k in ("L1", "L2", "L3", "h"):
        model = _arm(**{k: 1.25 * arm.params[k]})
        qm = model.solve(G).branch(model.branches[0])
        ok = np.isfinite(qm).all(-1)
        rt.append(np.linalg.norm(model.fk(qm[ok]) - G[ok], axis=-1).max())
        miss.append(np.linalg.norm(arm.fk(qm[ok]) - G[ok], axis=-1).max())
    return {"round_trip_mm": np.array(rt), "arm_miss_mm": np.array(miss)}


def target_pairs() -> dict[str, np.ndarray]:
    """Consecutive quadrant targets sent to steppers that count from where they stand: the
    angles sent as computed (relative to the initial pose) and as the difference of two IKs."""
    arm = _arm()
    G = QUADRANT_TARGETS
    q0 = np.array([0.0, -np.pi / 2, np.pi / 2, np.pi / 2])  # eq. 7, where the motors start
    q = arm.solve(G).branch(arm.branches[0]) - q0  # motor moves from the initial pose
    a, b = q[:-1], q[1:]
    sent = np.linalg.norm(arm.fk(q0 + a + b) - G[1:], axis=-1)
    diff = np.linalg.norm(arm.fk(q0 + a + (b - a)) - G[1:], axis=-1)
    return {"miss_as_computed_mm": sent, "miss_as_difference_mm": diff}


def senses() -> dict[str, np.ndarray]:
    """At the initial pose: do the rotation vectors of a growing alpha (theta2 = -pi/2 - alpha)
    and a growing beta (theta3 = pi/2 + beta) point the same way?"""
    arm, eps = _arm(), 1e-6
    q0 = np.array([0.0, -np.pi / 2, np.pi / 2, np.pi / 2])

    def turn(i, j, dq):
        u, v = (arm.frames(q)[j] - arm.frames(q)[i] for q in (q0, q0 + dq))
        return np.cross(u, v - u)

    wa = turn(2, 3, np.array([0, -eps, 0, 0]))
    wb = turn(3, 4, np.array([0, 0, eps, 0]))
    return {"same_sense": np.array([float(wa @ wb) > 0])}
