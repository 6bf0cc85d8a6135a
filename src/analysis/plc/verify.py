"""Targets and comparison for executing the generated PLC programs against Python.

The Python reference is :meth:`analysis.kinematics.arm.Arm.solve` (float64) followed by
:func:`analysis.kinematics.pulses.angles_to_pulses` with the dialect's tie rule; both refuse
the same targets with the same status codes (the base axis included). A PLC pulse count may
differ from the reference only where the exact (float64) pulse value lies so close to a half
pulse that float32 arithmetic lands on the other side; :func:`compare` counts those cases
and explains each with the float32 model of the program (:mod:`analysis.plc.model`), which
must reproduce the PLC bit for bit.

The one other legitimate difference is a *wrap-cut straddle*. theta1 and theta2 are wrapped
to (-180, 180] deg (:mod:`analysis.kinematics.arms.grabber`, "Conventions at the boundaries"),
so where the exact angle lies within float32 error of +-180 deg the PLC may give -ppr/2 where
Python gives +ppr/2 (or the reverse): the same joint position, counted one revolution apart.
:func:`compare` tells the two kinds apart (``cut`` column) and measures the float32 error
modulo one revolution; :func:`analysis.plc.sweep.sweep_targets` includes targets on the cut
(kind ``cut``).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
import numpy.typing as npt
import pandas as pd

from analysis.kinematics.arm import Arm
from analysis.kinematics.status import Status
from analysis.plc.approx import PlcFloat32Ops
from analysis.plc.dialects import printer_class
from analysis.plc.generate import generate
from analysis.plc.memmap import MemoryMap
from analysis.plc.model import PLC_MARGIN_MM, PLC_MARGIN_RAD, predict
from analysis.plc.runner import RunResult, sweep
from analysis.plc.sweep import sweep_targets
from analysis.plc.targets import input_columns, table4_targets

__all__ = [
    "SENTINEL",
    "Comparison",
    "PlcRun",
    "compare",
    "input_columns",
    "plc_targets",
    "program",
    "real_errors",
    "reference_pulses",
    "run",
    "table4_targets",
]


SENTINEL = -999_999
"""Written to the outputs before each cycle by :func:`run`: a refused target must leave it."""


def plc_targets(targets: npt.ArrayLike) -> tuple[npt.NDArray, npt.NDArray]:
    """Targets as the PLC holds them (float32 REALs): ``finite`` (N,) and the targets with
    non-finite rows replaced by 0, as float64 (N, k)."""
    t32 = np.asarray(targets, dtype=float).astype(np.float32).astype(float)
    finite = np.isfinite(t32).all(axis=1)
    return finite, np.where(finite[:, None], t32, 0.0)


def reference_pulses(
    arm: Arm,
    targets: npt.ArrayLike,
    branch: str | None = None,
    rounding: str = "half-away",
    *,
    theta1_on_axis: float | None = None,
    band: float = 1.0,
) -> tuple[npt.NDArray, npt.NDArray, npt.NDArray, npt.NDArray]:
    """Python's answer (float64) for targets (N, k) given as float32 REALs, as the PLC sees
    them (k = the arm's inputs: 3 for a point, 6 for the GR-1's pose).

    ``theta1_on_axis`` as given to the program's generator (None: base axis refused).
    ``band`` scales the programs' refusal band (:data:`~analysis.plc.model.PLC_MARGIN_MM`,
    :data:`~analysis.plc.model.PLC_MARGIN_RAD`): 1 solves as the program does, 0 as Python
    does by default.

    Returns
    -------
    pulses : ndarray of int64, shape (N, n)   (0 where refused)
    ok : ndarray of bool, shape (N,)
    status : ndarray of int64, shape (N,)     (Status codes; 6 for NaN/inf)
    exact : ndarray, shape (N, n)
        Unrounded pulse values theta_deg / 360 * ppr (NaN where refused).
    """
    branch = branch or arm.branches[0]
    finite, safe = plc_targets(targets)
    sol = arm.solve(
        safe,
        [branch],
        theta1_on_axis=theta1_on_axis,
        margin_mm=band * PLC_MARGIN_MM,
        margin_rad=band * PLC_MARGIN_RAD,
    )
    ok = sol.ok[:, 0] & finite
    status = np.where(finite, sol.status, int(Status.INVALID)).astype(np.int64)
    theta = np.where(ok[:, None], sol.theta[:, 0, :], 0.0)
    exact = np.where(ok[:, None], arm.pulse_values(theta), np.nan)  # per joint kind
    pulses = np.where(ok[:, None], arm.pulses(theta, rounding=rounding), 0)
    return pulses, ok, status, exact


@dataclass(frozen=True)
class Comparison:
    """PLC vs Python (float64) and vs the float32 model of the program, over N targets."""

    n: int
    n_reachable: int
    status_mismatch: int
    unsafe: int
    band_refusals: int
    limit_straddles: int
    flag_mismatch: int
    unchanged_ok: bool
    pulse_mismatch: int
    max_abs_diff: int
    mismatch_table: pd.DataFrame
    max_real_error: float
    all_explained: bool
    model_exact: bool

    @property
    def cut_straddles(self) -> int:
        """Mismatches of one revolution at the wrap cut (same joint position)."""
        return int(self.mismatch_table["cut"].sum())

    @property
    def float32_ties(self) -> int:
        """Mismatches where the PLC's float32 count is exactly k + 1/2 (the tie rule decides)."""
        t = self.mismatch_table
        return int((t["plc_real"] - (np.minimum(t["python"], t["plc"]) + 0.5) == 0).sum())

    def summary(self) -> dict:
        return {
            "targets": self.n,
            "reachable": self.n_reachable,
            "status mismatches": self.status_mismatch,
            "accepted where Python refuses": self.unsafe,
            "refused in the band only": self.band_refusals,
            "decided across a joint limit by float32": self.limit_straddles,
            "reach-flag mismatches": self.flag_mismatch,
            "outputs unchanged when refused": self.unchanged_ok,
            "pulse mismatches": self.pulse_mismatch,
            "max |PLC - Python| [pulses]": self.max_abs_diff,
            "max |float32 - exact| before ROUND [pulses]": self.max_real_error,
            "mismatches all straddle a half pulse or the wrap cut": self.all_explained,
            "of which at the wrap cut (one revolution)": self.cut_straddles,
            "of which float32 value exactly k + 1/2": self.float32_ties,
            "float32 model = PLC, bit for bit": self.model_exact,
        }


def _limit_straddles(arm, xyz, branch, theta32, theta1_on_axis) -> npt.NDArray[np.bool_]:
    """Targets where the float32 angles and the exact ones (joint limits not applied) fall on
    different sides of a joint limit: the exact ones against the limits, the float32 ones
    against the limits as REALs (as the program compares them)."""
    bounds = arm.limits
    if all(b is None for b in bounds):
        return np.zeros(len(xyz), dtype=bool)
    finite, safe = plc_targets(xyz)
    sol = arm.solve(
        safe,
        [branch],
        limits=False,
        theta1_on_axis=theta1_on_axis,
        margin_mm=PLC_MARGIN_MM,
        margin_rad=PLC_MARGIN_RAD,
    )

    def inside(theta, real=False):
        ok = np.ones(len(xyz), dtype=bool)
        for j, b in enumerate(bounds):
            if b is not None:
                lo, hi = np.float32(b) if real else b  # the program's limits are REALs
                ok &= (theta[:, j] >= lo) & (theta[:, j] <= hi)
        return ok

    exact = sol.theta[:, 0, :]
    solved = np.isfinite(exact).all(axis=1) & finite
    return solved & (inside(exact) != inside(np.asarray(theta32, dtype=np.float32), True))


def _status_counts(
    result: RunResult,
    arm: Arm,
    xyz: npt.NDArray[np.float64],
    branch: str,
    rounding: str,
    theta32: npt.NDArray,
    theta1_on_axis: float | None,
) -> tuple[int, int, int, int]:
    """(``status_mismatch``, ``unsafe``, ``band_refusals``, ``limit_straddles``) of
    :func:`compare`: the PLC's statuses against Python with 0, 0.5 and 2 times the program's
    band; ``theta32`` the model's float32 angles [rad]."""
    refs = {
        b: reference_pulses(arm, xyz, branch, rounding, theta1_on_axis=theta1_on_axis, band=b)
        for b in (0.0, 0.5, 2.0)
    }
    plc_ok = result.reachable
    unsafe = plc_ok & ~refs[0.0][1]
    missed = plc_ok & ~refs[0.5][1]
    extra = ~plc_ok & refs[2.0][1]
    # a refusal's code may be the band's: within the band of one boundary (the base axis)
    # and beyond another (a joint limit), Python with twice the band gives the PLC's code
    code = ~plc_ok & ~refs[0.5][1] & (result.status != refs[0.5][2])
    code &= result.status != refs[2.0][2]
    # near a joint limit the PLC decides with its float32 angle: a disagreement there is
    # explained where the float32 and the exact angle lie on opposite sides of the limit
    across = _limit_straddles(arm, xyz, branch, theta32, theta1_on_axis)
    limit_codes = (result.status == Status.JOINT_LIMITS) | (refs[0.5][2] == Status.JOINT_LIMITS)
    missed, extra = missed & ~across, extra & ~across
    code = code & ~(across & limit_codes)
    unsafe = unsafe & ~across
    return (
        int((missed | extra | code).sum()),
        int(unsafe.sum()),
        int((~plc_ok & refs[0.0][1]).sum()),
        int((across & (plc_ok != refs[0.0][1])).sum()),
    )


def _mismatch_table(
    targets: pd.DataFrame,
    cols: list[str],
    xyz: npt.NDArray[np.float64],
    exact: npt.NDArray[np.float64],
    ref: npt.NDArray,
    result: RunResult,
    counts: npt.NDArray,
    diff: npt.NDArray,
    ppr: npt.NDArray[np.float64],
) -> pd.DataFrame:
    """One row per joint value where the PLC's count differs from Python's (``diff`` != 0),
    with the exact count, its distance to the nearest half pulse, whether the two are a
    revolution apart (``cut``), the float32 count before ROUND (``counts``) and ``ppr``."""
    # the same joint position one revolution apart (wrap cut) is not a pulse error
    turns = np.round(diff / ppr)
    rows = []
    for i, j in zip(*np.nonzero(diff), strict=True):
        x = exact[i, j]
        rows.append(
            {
                "kind": targets["kind"].iloc[i],
                **{c: xyz[i, k] for k, c in enumerate(cols)},
                "joint": f"c{j + 1}",
                "python": int(ref[i, j]),
                "plc": int(result.pulses[i, j]),
                "exact": x,
                "dist_half": abs(abs(x - np.trunc(x)) - 0.5),
                "cut": bool(turns[i, j] != 0),
                "plc_real": float(counts[i, j]),
                "ppr": float(ppr[i, j]),
            }
        )
    columns = ["kind", *cols, "joint", "python", "plc", "exact", "dist_half"]
    return pd.DataFrame(rows, columns=[*columns, "cut", "plc_real", "ppr"])


def _all_explained(table: pd.DataFrame) -> bool:
    """Every mismatch of :func:`_mismatch_table` is a straddle of one half pulse, and every
    one-revolution difference lies at the wrap cut (+-ppr/2)."""
    if table.empty:  # nothing to explain (most calls: pandas would cost more than compare)
        return True
    # in one revolution: the PLC's count and float32 value moved by the whole turns between them
    shift = (table["ppr"] * np.round((table["plc"] - table["python"]) / table["ppr"])).to_numpy()
    plc = table["plc"].to_numpy() - shift
    real = table["plc_real"].to_numpy(dtype=float) - shift
    half = np.minimum(table["python"].to_numpy(), plc) + 0.5
    straddle = (table["exact"].to_numpy(dtype=float) - half) * (real - half) <= 0
    one_step = np.abs(plc - table["python"].to_numpy()) <= 1
    at_cut = np.abs(np.abs(table["exact"].to_numpy(dtype=float)) - table["ppr"] / 2) < 0.05
    return bool(
        (one_step & np.where(plc != table["python"], straddle, True)).all()
        and (at_cut | ~table["cut"]).all()
    )


def compare(
    result: RunResult,
    targets: pd.DataFrame,
    arm: Arm,
    branch: str | None = None,
    dialect: str = "s7-200",
    sentinel: int = -999_999,
    trig: str | None = None,
    *,
    theta1_on_axis: float | None = None,
) -> Comparison:
    """Compare PLC results (run with ``sentinel`` in the outputs) with Python and the model.

    ``targets`` has a ``kind`` column and the target columns :func:`input_columns` names.

    The Python reference is float64 (:func:`reference_pulses`, with the dialect's tie rule);
    the model is :func:`analysis.plc.model.predict` with the dialect's REAL arithmetic
    (``trig`` "native" only on the S7-300; ``theta1_on_axis`` as the program was generated
    with), which gives the float32 value each count had
    before ROUND (``plc_real``). The mismatch table lists each joint value where PLC and
    Python differ, with the exact value and its distance to the nearest half pulse
    (``dist_half``); ``all_explained`` says whether every mismatch is a straddle: the
    float32 value and the exact value lie on opposite sides of the same half pulse, or (``cut``)
    the two counts are one revolution apart and the exact value lies within float32 error of
    +-ppr/2 (the wrap cut of theta1/theta2). Errors before ROUND are taken modulo one revolution.

    Statuses: the programs refuse a band around the reach shells, the singular sets and the
    arm's angular tolerance (:mod:`analysis.plc.model`). ``unsafe`` counts targets the PLC
    accepts and Python (default tolerances) refuses, other than at a joint limit that the
    float32 angle and the exact one straddle (``limit_straddles``; joint limits get no
    band): it must be 0. ``band_refusals`` counts targets only the band refuses.
    ``status_mismatch`` counts what neither explains: a target the PLC accepts that Python
    with half the band refuses, one it refuses that Python with twice the band accepts, or a
    refusal whose code differs from Python's with half the band and with twice the band.
    Pulses are compared with Python solving as the program does (band 1).
    """
    branch = branch or arm.branches[0]
    rounding = printer_class(dialect).rounding
    cols = input_columns(arm)
    xyz = targets[cols].to_numpy(dtype=float)
    ref, ok, _, exact = reference_pulses(arm, xyz, branch, rounding, theta1_on_axis=theta1_on_axis)
    model = predict(
        arm, xyz, branch, ops=PlcFloat32Ops(dialect, trig), theta1_on_axis=theta1_on_axis
    )
    model_exact = bool(
        (model.status == result.status).all()
        and (model.pulses[model.reachable] == result.pulses[model.reachable]).all()
    )
    status_mismatch, unsafe, band_refusals, limit_straddles = _status_counts(
        result, arm, xyz, branch, rounding, model.theta, theta1_on_axis
    )
    flag_mm = int((result.reachable != (result.status == 0)).sum())
    unchanged = bool((result.pulses[~result.reachable] == sentinel).all())
    both = ok & result.reachable
    diff = np.where(both[:, None], result.pulses - ref, 0)
    ppr = np.broadcast_to(np.asarray(arm.params.pulses_per_rev, dtype=float), exact.shape)
    table = _mismatch_table(targets, cols, xyz, exact, ref, result, model.counts, diff, ppr)
    lap = ppr * np.round((model.counts.astype(float) - exact) / ppr)
    err = np.abs(model.counts.astype(float) - lap - exact)[both]
    explained = _all_explained(table)
    return Comparison(
        len(xyz),
        int(ok.sum()),
        status_mismatch,
        unsafe,
        band_refusals,
        limit_straddles,
        flag_mm,
        unchanged,
        int((diff != 0).sum()),
        int(np.abs(diff).max()) if diff.size else 0,
        table,
        float(err.max()) if err.size else 0.0,
        explained,
        model_exact,
    )


def program(arm: Arm, dialect: str = "s7-200", branch: str | None = None) -> tuple[str, str]:
    """The program text and its MAP.json, exactly as ``python -m analysis stl --arm <arm>
    --dialect <dialect>`` writes them (default trigonometry of the dialect)."""
    return tuple(generate(arm, dialect, branch))


class PlcRun(NamedTuple):
    """One program executed on awlsim over a target set, and its comparison with Python."""

    comparison: Comparison
    result: RunResult
    targets: pd.DataFrame
    stopped: bool
    """True if a REAL compare saw a NaN (an S7-200 CPU would stop)."""

    def status_table(self) -> pd.DataFrame:
        """Targets per kind and PLC status code (rows: kind; columns: status)."""
        t = self.targets.assign(status=self.result.status)
        return pd.crosstab(t["kind"], t["status"])


def run(
    arm: Arm,
    dialect: str = "s7-200",
    targets: pd.DataFrame | None = None,
    branch: str | None = None,
    text: tuple[str, str] | None = None,
) -> PlcRun:
    """Execute the arm's program on awlsim (S7-200 STL through the project's translation to
    AWL; S7-300 AWL as is) over ``targets`` (default
    :func:`analysis.plc.sweep.sweep_targets` of the branch) and compare.

    ``text`` may pass ``(program text, MAP.json text)`` as written by the command line;
    by default :func:`program` generates them.
    """
    branch = branch or arm.branches[0]
    targets = sweep_targets(arm, branch=branch) if targets is None else targets
    src, map_text = text if text is not None else program(arm, dialect, branch)
    mmap = MemoryMap.from_dict(json.loads(map_text))
    awl = printer_class(dialect).awlsim_source(src)
    xyz = targets[input_columns(arm)].to_numpy(dtype=float)
    done = sweep(awl, mmap, xyz, sentinel=SENTINEL)
    trig = "subroutine" if "ATAN2/ACOS: generated subroutines" in src else "native"
    cmp = compare(done.result, targets, arm, branch, dialect, SENTINEL, trig)
    return PlcRun(cmp, done.result, targets, done.stopped)


def real_errors(arm: Arm, targets: pd.DataFrame, dialect: str = "s7-200") -> pd.DataFrame:
    """Largest |float32 value handed to ROUND - exact pulse value| [pulses] per target kind
    and joint, modulo one revolution (at the wrap cut the two may be a turn apart), over the
    targets both Python and the program solve (the float32 model of the program,
    :func:`analysis.plc.model.predict`, which reproduces awlsim bit for bit)."""
    xyz = targets[input_columns(arm)].to_numpy(dtype=float)
    rounding = printer_class(dialect).rounding
    _, ok, _, exact = reference_pulses(arm, xyz, arm.branches[0], rounding)
    model = predict(arm, xyz, arm.branches[0], ops=PlcFloat32Ops(dialect))
    both = ok & model.reachable
    ppr = np.asarray(arm.params.pulses_per_rev, dtype=float)
    diff = model.counts.astype(float) - exact
    err = np.abs(diff - ppr * np.round(diff / ppr))  # modulo one revolution (the wrap cut)
    cols = [f"c{j + 1}" for j in range(err.shape[1])]
    df = pd.DataFrame(err[both], columns=cols).assign(kind=targets["kind"].to_numpy()[both])
    return df.groupby("kind").max()
