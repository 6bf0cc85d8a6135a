"""Table 4 recomputed, forward-checked and explained (paper section 3).

For every printed row: the corrected front-up angles and all four branches
(:meth:`analysis.kinematics.arm.Arm.solve`), where the printed angles actually put the gripper
(:meth:`analysis.kinematics.arm.Arm.fk`), how far that is from the target, and which evaluation of
the paper's own formulas reproduces each printed cell (:func:`evaluations`). A printed
cell "holds" when the recomputed angle rounds to it at the number of decimals printed.

Example: row 1, target (100, 100, 600) mm, prints theta2 = 190.20 deg; the corrected
value is 10.21 deg; eq. 18's single-argument tan^-1 gives 190.2087 deg (the quadrant is
lost: the denominator of eq. 18 is negative), whose rounding is 190.21, not 190.20.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt
import pandas as pd

from analysis.audit.kinds.table import cell_matches, decimals
from analysis.kinematics.arm import BRANCHES, Arm, paper_arm
from analysis.kinematics.params import data_dir
from analysis.kinematics.pulses import angles_to_pulses, pulses_to_angles

__all__ = [
    "EVALUATIONS",
    "evaluations",
    "load_printed",
    "printed_formulas",
    "report_table",
    "summary",
]

EVALUATIONS: tuple[str, ...] = (
    "corrected (atan2), rounded",
    "corrected (atan2), truncated",
    "printed eqs. 6/10/18-19 (single-argument tan^-1), rounded",
    "printed eqs. 6/10/18-19 (single-argument tan^-1), truncated",
    "printed eqs. in float32, rounded",
    "printed eqs. with theta23 and theta3 rounded to 0.01 deg first",
    "corrected, quantized to whole pulses (eqs. 20-22)",
)
"""Names of the ways a printed cell could have been produced, tried on every cell."""


def load_printed(path=None) -> pd.DataFrame:
    """Table 4 exactly as printed (``data/table4.csv``, all columns as text)."""
    path = path if path is not None else data_dir() / "table4.csv"
    df = pd.read_csv(path, dtype=str, keep_default_na=False)
    need = ["row", "x_mm", "y_mm", "z_mm", "theta1_deg", "theta2_deg", "theta3_deg", "status"]
    missing = [c for c in need if c not in df.columns]
    if missing:
        raise ValueError(f"{path}: missing column(s) {', '.join(missing)}")
    return df


def printed_formulas(
    p: npt.ArrayLike, arm: Arm | None = None, *, dtype=np.float64, elbow_sign: float = -1.0
) -> npt.NDArray[np.float64]:
    """Angles [deg] from the paper's formulas evaluated literally: eq. 6 and eq. 18 with the
    single-argument tan^-1, eq. 10 with the sign ``elbow_sign`` (Table 4 prints theta3 < 0).

    Parameters
    ----------
    p : array_like, shape (..., 3)
        Targets [mm] with Px != 0.
    dtype : numpy float type
        float64, or float32 to mimic the S7-200's REAL arithmetic.

    Returns
    -------
    ndarray, shape (..., 3)
        (theta1, theta2, theta3) [deg]; NaN where eq. 10's argument leaves [-1, 1].
    """
    arm = arm or paper_arm()
    p = np.asarray(p, dtype=float)
    if np.any(p[..., 0] == 0):
        raise ValueError("eq. 6 divides by Px; a target has Px = 0")
    L1, L2, L3 = (dtype(v) for v in (arm.params.L1, arm.params.L2, arm.params.L3))
    x, y, z = (p[..., i].astype(dtype) for i in range(3))
    with np.errstate(invalid="ignore"):
        t1 = np.arctan(y / x)  # eq. 6
        r = np.cos(t1) * x + np.sin(t1) * y
        zz = z - L1
        c3 = (zz**2 + r**2 - L3**2 - L2**2) / (dtype(2) * L3 * L2)  # eq. 10
        t3 = dtype(elbow_sign) * np.arccos(c3)
        k = L2 * np.cos(t3) + L3
        num = zz * k + r * L2 * np.sin(t3)
        den = -zz * L2 * np.sin(t3) + r * k
        t23 = np.arctan(num / den)  # eq. 18
        t2 = t23 - t3  # eq. 19
    return np.degrees(np.stack([t1, t2, t3], axis=-1).astype(np.float64))


def evaluations(p: npt.ArrayLike, arm: Arm | None = None) -> dict[str, tuple[npt.NDArray, str]]:
    """Every evaluation of :data:`EVALUATIONS` for targets (..., 3): ``{name: (deg, mode)}``.

    ``deg`` has shape (..., 3); ``mode`` is how a cell is compared ("round"/"truncate").
    """
    arm = arm or paper_arm()
    p = np.asarray(p, dtype=float)
    corr = np.degrees(arm.solve(p, ("front-up",)).branch("front-up"))
    lit = printed_formulas(p, arm)
    lit32 = printed_formulas(p, arm, dtype=np.float32)
    t23 = np.round(lit[..., 1] + lit[..., 2], 2)
    t3r = np.round(lit[..., 2], 2)
    inter = np.stack([lit[..., 0], t23 - t3r, lit[..., 2]], axis=-1)
    quant = np.full_like(corr, np.nan)
    ok = np.isfinite(corr).all(axis=-1)
    quant[ok] = np.degrees(pulses_to_angles(angles_to_pulses(np.radians(corr[ok]))))
    return {
        EVALUATIONS[0]: (corr, "round"),
        EVALUATIONS[1]: (corr, "truncate"),
        EVALUATIONS[2]: (lit, "round"),
        EVALUATIONS[3]: (lit, "truncate"),
        EVALUATIONS[4]: (lit32, "round"),
        EVALUATIONS[5]: (inter, "round"),
        EVALUATIONS[6]: (quant, "round"),
    }


def _cause(row: pd.Series, j: int, repro: list[str], holds: bool) -> str:
    if holds:
        k = decimals(row[f"theta{j}_deg"])
        return "holds" + (f" (printed to {k} decimal)" if k == 1 else "")
    if not repro:
        return "undecidable: no evaluation tried reproduces it (transcription slip?)"
    if any("single-argument" in r and "rounded" in r for r in repro):
        return "eq. 18 single-argument tan^-1: quadrant lost, +180 deg"
    if any("single-argument" in r for r in repro):
        return (
            "eq. 18 single-argument tan^-1 (+180 deg); last digit only by truncation, "
            "which other cells contradict: undecidable"
        )
    return "reproduced by: " + "; ".join(repro)


def summary(arm: Arm | None = None) -> pd.DataFrame:
    """One row per Table 4 row: printed, recomputed, forward-checked, explained.

    Columns: ``row, x_mm, y_mm, z_mm``; ``printed_theta{1,2,3}`` (text as printed);
    ``theta{1,2,3}_deg`` (corrected front-up, float); ``<branch>_theta{1,2,3}_deg`` for
    all branches; ``reachable``, ``outside_mm`` (> 0: beyond reach by that much);
    ``fk_printed_{x,y,z}_mm`` and ``fk_error_mm`` (where the printed angles put the
    gripper and how far from the target, NaN for 无解); ``cell{1,2,3}_ok``;
    ``cause{1,2,3}``; ``verdict`` ("holds", "wrong", "unreachable (无解 holds)").
    """
    arm = arm or paper_arm()
    df = load_printed()
    p = df[["x_mm", "y_mm", "z_mm"]].astype(float).to_numpy()
    sol = arm.solve(p, BRANCHES)
    out = pd.DataFrame(
        {"row": df["row"].astype(int), "x_mm": p[:, 0], "y_mm": p[:, 1], "z_mm": p[:, 2]}
    )
    for j in (1, 2, 3):
        out[f"printed_theta{j}"] = df[f"theta{j}_deg"]
    front = np.degrees(sol.branch("front-up"))
    for j in (1, 2, 3):
        out[f"theta{j}_deg"] = front[:, j - 1]
    for b in BRANCHES:
        ang = np.degrees(sol.branch(b))
        for j in (1, 2, 3):
            out[f"{b}_theta{j}_deg"] = ang[:, j - 1]
    out["reachable"] = sol.reachable
    out["outside_mm"] = sol.outside_mm
    # theta1 alone is defined for every target off the base axis (eq. 6), reachable or not
    out["theta1_atan2_deg"] = np.degrees(np.arctan2(p[:, 1], p[:, 0]))
    printed = (
        df[["theta1_deg", "theta2_deg", "theta3_deg"]]
        .replace("", np.nan)
        .apply(pd.to_numeric, errors="coerce")
        .to_numpy()
    )
    solved = np.isfinite(printed).all(axis=1)
    fk = np.full_like(p, np.nan)
    fk[solved] = arm.fk(np.radians(printed[solved]))
    for i, ax in enumerate("xyz"):
        out[f"fk_printed_{ax}_mm"] = fk[:, i]
    out["fk_error_mm"] = np.linalg.norm(fk - p, axis=1)
    evs = evaluations(p, arm)
    verdicts = []
    for j in (1, 2, 3):
        oks, causes, repros = [], [], []
        for i, row in df.iterrows():
            text = row[f"theta{j}_deg"]
            if text == "":  # 无解 printed for theta2/theta3
                ok = not bool(sol.reachable[i])
                oks.append(ok)
                causes.append(
                    "无解 holds: target beyond reach"
                    if ok
                    else "无解 printed for a reachable target"
                )
                repros.append("")
                continue
            ref = out.loc[i, "theta1_atan2_deg"] if j == 1 else front[i, j - 1]
            ok = cell_matches(text, ref)
            repro = [n for n, (v, mode) in evs.items() if cell_matches(text, v[i, j - 1], mode)]
            oks.append(ok)
            causes.append(_cause(row, j, repro, ok))
            repros.append("; ".join(repro))
        out[f"cell{j}_ok"] = oks
        out[f"cause{j}"] = causes
        out[f"reproduced_by{j}"] = repros
    for i in range(len(df)):
        if not sol.reachable[i]:
            verdicts.append(f"unreachable by {sol.outside_mm[i]:.2f} mm (无解 holds)")
        elif all(out.loc[i, f"cell{j}_ok"] for j in (1, 2, 3)):
            verdicts.append("holds")
        else:
            verdicts.append("wrong")
    out["verdict"] = verdicts
    return out


def report_table(s: pd.DataFrame | None = None) -> pd.DataFrame:
    """The compact Table 4 audit a report reuses: one line per row, degrees to 2 decimals.

    Columns: target, printed angles, corrected front-up angles, where the printed angles
    put the gripper (distance from the target [mm]), verdict and cause.
    """
    s = summary() if s is None else s
    fmt = lambda v: "" if not np.isfinite(v) else f"{v:.2f}"  # noqa: E731
    out = pd.DataFrame(
        {
            "row": s["row"],
            "target (mm)": [
                f"({x:g}, {y:g}, {z:g})" for x, y, z in s[["x_mm", "y_mm", "z_mm"]].to_numpy()
            ],
            "printed θ1, θ2, θ3 (deg)": [
                ", ".join(t or "无解" for t in r)
                for r in s[["printed_theta1", "printed_theta2", "printed_theta3"]].to_numpy()
            ],
            "corrected θ1, θ2, θ3 (deg)": [
                ", ".join(fmt(v) for v in r) or ""
                for r in s[["theta1_deg", "theta2_deg", "theta3_deg"]].to_numpy()
            ],
            "FK error of printed (mm)": [fmt(v) for v in s["fk_error_mm"]],
            "verdict": s["verdict"],
            "cause": [
                "; ".join(
                    f"θ{j}: {s.loc[i, f'cause{j}']}"
                    for j in (1, 2, 3)
                    if not s.loc[i, f"cell{j}_ok"]
                )
                or ""
                for i in s.index
            ],
        }
    )
    out.loc[~s["reachable"], "corrected θ1, θ2, θ3 (deg)"] = [
        f"{v:.2f}, 无解, 无解" for v in s.loc[~s["reachable"], "theta1_atan2_deg"]
    ]
    return out.set_index("row")
