"""The robot's parameters, read from data files (paper Table 3 and section 3).

No link length is written anywhere else in the code: :func:`load_table3` reads
``data/table3.csv`` and everything downstream takes an :class:`ArmParams`.
"""

from __future__ import annotations

import math
import numbers
import os
from dataclasses import dataclass
from pathlib import Path

import pandas as pd
import sympy as sp

from analysis.kinematics.dh import DHRow, DHTable

__all__ = ["ArmParams", "data_dir", "load_table3", "paper_params"]


def data_dir() -> Path:
    """The project's ``data/`` folder (``$ANALYSIS_DATA_DIR`` overrides)."""
    env = os.environ.get("ANALYSIS_DATA_DIR")
    path = Path(env) if env else Path(__file__).resolve().parents[3] / "data"
    if not path.is_dir():
        raise FileNotFoundError(
            f"data folder {path} not found; run from a checkout of the project "
            "or set ANALYSIS_DATA_DIR"
        )
    return path


@dataclass(frozen=True)
class ArmParams:
    """Geometry and drive of the paper's 3R arm (Table 3; standard D-H, Table 1).

    Attributes
    ----------
    L1 : float
        Waist-to-shoulder height d_1 [mm] (Table 3: 660). Must be >= 0.
    L2, L3 : float
        Upper-arm and forearm lengths a_2, a_3 [mm] (Table 3: 310, 200). Must be > 0.
    pulses_per_rev : tuple of 3 int
        Stepper pulses per joint revolution (section 3: 4000), used by eqs. 20-22.
    step_angle_deg, resolution_deg : tuple of 3 float
        As printed in Table 3 (1.8 deg full step, 0.09 deg resolution); informational.
    """

    L1: float
    L2: float
    L3: float
    pulses_per_rev: tuple[int, int, int] = (4000, 4000, 4000)
    step_angle_deg: tuple[float, float, float] = (1.8, 1.8, 1.8)
    resolution_deg: tuple[float, float, float] = (0.09, 0.09, 0.09)

    def __post_init__(self) -> None:
        for name in ("L1", "L2", "L3"):
            value = getattr(self, name)
            # numbers.Real admits NumPy scalars (pandas/NumPy reads); bool is not a length
            if not _is_real(value) or not math.isfinite(value):
                raise ValueError(f"{name} = {value!r} mm is not a finite number")
            object.__setattr__(self, name, float(value))
        if self.L1 < 0:
            raise ValueError(f"L1 = {self.L1} mm is negative; the waist height must be >= 0 mm")
        for name in ("L2", "L3"):
            if getattr(self, name) <= 0:
                raise ValueError(f"{name} = {getattr(self, name)} mm: link lengths must be > 0 mm")
        ppr = self.pulses_per_rev
        if hasattr(ppr, "tolist"):  # a NumPy array or scalar
            ppr = ppr.tolist()
        if isinstance(ppr, (list, tuple)):
            ppr = tuple(ppr)
        if (
            not isinstance(ppr, tuple)
            or len(ppr) != 3
            or not all(_is_positive_whole(p) for p in ppr)
        ):
            raise ValueError(f"pulses_per_rev = {ppr!r}: need three positive whole numbers")
        object.__setattr__(self, "pulses_per_rev", tuple(int(p) for p in ppr))

    @property
    def reach_outer(self) -> float:
        """Outer radius of the reachable shell around the shoulder, L2 + L3 [mm]."""
        return self.L2 + self.L3

    @property
    def reach_inner(self) -> float:
        """Inner radius of the reachable shell around the shoulder, |L2 - L3| [mm]."""
        return abs(self.L2 - self.L3)

    def dh_table(self, symbolic: bool = False) -> DHTable:
        """The standard D-H table of Table 1 / Table 3.

        With ``symbolic`` the lengths are the SymPy symbols ``L1, L2, L3`` (positive) and
        the twist is exactly pi/2, for the re-derivation of section 1.2 (use
        :meth:`DHTable.transforms_sym`); numeric methods need ``symbolic=False``.
        """
        if symbolic:
            L1, L2, L3 = sp.symbols("L1 L2 L3", positive=True)
            alpha1 = sp.pi / 2
        else:
            L1, L2, L3, alpha1 = self.L1, self.L2, self.L3, math.pi / 2
        return DHTable(
            (
                DHRow(alpha=alpha1, a=0.0, d=L1, name="waist"),
                DHRow(alpha=0.0, a=L2, d=0.0, name="shoulder"),
                DHRow(alpha=0.0, a=L3, d=0.0, name="elbow"),
            ),
            "standard",
            "Li et al. 2016, Table 3",
        )

    def with_(self, **changes) -> ArmParams:
        """A copy with some fields changed (validated again)."""
        return ArmParams(**{**self.__dict__, **changes})


def _is_real(value) -> bool:
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


def _is_positive_whole(p) -> bool:
    return _is_real(p) and math.isfinite(p) and p > 0 and int(p) == p


def load_table3(path: str | Path | None = None) -> ArmParams:
    """Read ``data/table3.csv`` (the paper's Table 3 verbatim plus pulses per rev).

    Checks that the table has the topology the closed-form IK assumes (Table 1:
    alpha = 90, 0, 0 deg; a_1 = 0; d_2 = d_3 = 0) and that the printed cos/sin columns
    agree with alpha.
    """
    path = Path(path) if path is not None else data_dir() / "table3.csv"
    df = pd.read_csv(path)
    need = [
        "link",
        "alpha_deg",
        "a_mm",
        "d_mm",
        "cos_alpha",
        "sin_alpha",
        "pulses_per_rev",
        "step_angle_deg",
        "resolution_deg",
    ]
    missing = [c for c in need if c not in df.columns]
    if missing:
        raise ValueError(f"{path}: missing column(s) {', '.join(missing)}")
    if len(df) != 3:
        raise ValueError(f"{path}: {len(df)} rows; the arm has 3 links (waist, shoulder, elbow)")
    alpha = df["alpha_deg"].astype(float).tolist()
    if alpha != [90.0, 0.0, 0.0]:
        raise ValueError(f"{path}: alpha_deg = {alpha}; the closed-form IK needs [90, 0, 0]")
    for _, row in df.iterrows():
        rad = math.radians(float(row["alpha_deg"]))
        if (
            abs(math.cos(rad) - row["cos_alpha"]) > 1e-12
            or abs(math.sin(rad) - row["sin_alpha"]) > 1e-12
        ):
            raise ValueError(f"{path}: link {row['link']}: cos/sin columns disagree with alpha")
    a, d = df["a_mm"].astype(float).tolist(), df["d_mm"].astype(float).tolist()
    if a[0] != 0.0 or d[1] != 0.0 or d[2] != 0.0:
        raise ValueError(f"{path}: need a_1 = 0 and d_2 = d_3 = 0 (Table 1), got a = {a}, d = {d}")
    return ArmParams(
        L1=d[0],
        L2=a[1],
        L3=a[2],
        pulses_per_rev=tuple(int(v) for v in df["pulses_per_rev"]),
        step_angle_deg=tuple(float(v) for v in df["step_angle_deg"]),
        resolution_deg=tuple(float(v) for v in df["resolution_deg"]),
    )


def paper_params() -> ArmParams:
    """The paper's arm as printed in Table 3 (L1 = 660, L2 = 310, L3 = 200 mm)."""
    return load_table3()
