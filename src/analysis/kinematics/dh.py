"""Denavit-Hartenberg link transforms, standard and modified, numeric and symbolic.

One formula per convention, written once (:func:`_link_elements`), serves both the numeric
path (NumPy, vectorized over any leading shape) and the symbolic path (SymPy matrices),
so the two cannot drift apart.

Conventions
-----------
Standard D-H (Denavit & Hartenberg; the paper's Table 1 and the matrices of section 1.2)::

    A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i)

Modified D-H (Craig; seed 001's palletizer, its eq. 8), each row holding
``(alpha_{i-1}, a_{i-1}, d_i, theta_i)``::

    A_i = Rx(alpha_{i-1}) Tx(a_{i-1}) Rz(theta_i) Tz(d_i)

A row's joint angle is ``theta_i = q_i + theta_offset_i`` for a revolute row; a
``prismatic`` row moves along its z axis, ``d_i + q_i`` [mm], at the fixed angle
``theta_offset``; a ``fixed`` row (a tool frame) has no joint variable and uses
``theta_offset`` alone. Angles are in radians, lengths in millimetres.

SymPy is imported inside the symbolic functions only: it takes half a second to import,
which the numeric paths (the command line among them) should not pay. Frames are named
``T_<to>_<from>`` where it matters:
``T_0_n = A_1 A_2 ... A_n`` maps points of frame n into the base frame 0.
"""

from __future__ import annotations

import csv
import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Literal

import numpy as np
import numpy.typing as npt

if TYPE_CHECKING:
    import sympy as sp

Convention = Literal["standard", "modified"]
JointKind = Literal["revolute", "prismatic", "fixed"]
MOVING = ("revolute", "prismatic")
CONVENTIONS: tuple[Convention, ...] = ("standard", "modified")

__all__ = [
    "CONVENTIONS",
    "DHRow",
    "DHTable",
    "chain_frames",
    "chain_transforms",
    "exact_cos_sin",
    "inverse_transform",
    "link_transform",
    "link_transform_sym",
]


def exact_mul(a, b):
    """a * b, exact for the structural zeros and ones of a D-H row (plain numbers)."""
    if isinstance(a, (int, float)):
        if a == 0:
            return 0.0
        if a == 1:
            return b
        if a == -1:
            return -b
    if isinstance(b, (int, float)):
        if b == 0:
            return 0.0
        if b == 1:
            return a
        if b == -1:
            return -a
    return a * b


def exact_add(a, b):
    """a + b, dropping plain-number zeros."""
    if isinstance(a, (int, float)) and a == 0:
        return b
    if isinstance(b, (int, float)) and b == 0:
        return a
    return a + b


def _link_elements(ct, st, ca, sa, a, d, convention: Convention) -> list[list]:
    """The 3x4 upper block of one link transform from cos/sin of theta and alpha.

    The one formula per convention. Works on any values supporting ``*``, ``+`` and unary
    minus: NumPy arrays, SymPy expressions, duals, traced nodes; plain-number zeros and
    ones (cos 90 deg, a = 0) are kept exact and dropped. The last row is ``[0, 0, 0, 1]``.
    """
    if convention == "standard":
        return [
            [ct, -exact_mul(st, ca), exact_mul(st, sa), exact_mul(a, ct)],
            [st, exact_mul(ct, ca), -exact_mul(ct, sa), exact_mul(a, st)],
            [0, sa, ca, d],
        ]
    if convention == "modified":
        return [
            [ct, -st, 0, a],
            [exact_mul(st, ca), exact_mul(ct, ca), -sa, -exact_mul(d, sa)],
            [exact_mul(st, sa), exact_mul(ct, sa), ca, exact_mul(d, ca)],
        ]
    raise ValueError(f"unknown D-H convention {convention!r}; expected one of {CONVENTIONS}")


def exact_cos_sin(angle: float) -> tuple[float, float]:
    """cos and sin of a constant angle [rad], exactly 0 or +-1 at multiples of 90 deg
    (``math.cos(pi / 2)`` is 6.1e-17, which would leave spurious terms in a chain)."""
    quarter = angle / (math.pi / 2)
    k = round(quarter)
    if abs(quarter - k) < 1e-12:
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[k % 4]
    return math.cos(angle), math.sin(angle)


def compose_blocks(T: list[list], A: list[list]) -> list[list]:
    """Product of two 3x4 blocks of homogeneous transforms (last rows [0 0 0 1])."""
    out = []
    for i in range(3):
        row = []
        for j in range(4):
            v = exact_add(
                exact_add(exact_mul(T[i][0], A[0][j]), exact_mul(T[i][1], A[1][j])),
                exact_mul(T[i][2], A[2][j]),
            )
            row.append(exact_add(v, T[i][3]) if j == 3 else v)
        out.append(row)
    return out


def chain_transforms(m, table: DHTable, q: Sequence | None = None) -> list[list[list]]:
    """The 3x4 blocks of ``T_0_i`` for the frames 1..n_rows of a chain, in namespace ``m``.

    The chain's product of link transforms (eq. 1 for the paper's arm, T_3 = A_1 A_2 A_3)
    composed element by element in ``m`` (numpy, duals, SymPy, the tracer): the one
    forward kinematics every backend derives from. ``q`` holds one value per joint; None is
    the home configuration q = 0, whose rotations are then plain numbers, exact at multiples
    of 90 deg (:func:`exact_cos_sin`): the joint axes and the home pose of
    :mod:`analysis.kinematics.derive` are read off them, the positions stay values of ``m``
    (the lengths may be symbols or traced parameters).
    """
    q = None if q is None else list(q)
    if q is not None and len(q) != table.n_joints:
        raise ValueError(f"{len(q)} joint values given; the chain has {table.n_joints} joints")
    it = iter(q or ())
    T = None
    out: list[list[list]] = []
    for row in table.rows:
        d = row.d
        if row.kind == "revolute" and q is not None:
            qi = next(it)
            theta = exact_add(qi, row.theta_offset) if row.theta_offset else qi
            ct, st = m.cos(theta), m.sin(theta)
        else:
            ct, st = exact_cos_sin(row.theta_offset)
            if row.kind == "prismatic" and q is not None:  # the joint value adds to d [mm]
                d = exact_add(next(it), d)
        ca, sa = exact_cos_sin(row.alpha)
        A = _link_elements(ct, st, ca, sa, row.a, d, table.convention)
        T = A if T is None else compose_blocks(T, A)
        out.append(T)
    return out


def chain_frames(m, table: DHTable, q: Sequence) -> list[tuple]:
    """Origins of the frames 0..n_rows of a chain, as ``(x, y, z)`` values of namespace ``m``
    (:func:`chain_transforms`' translations, the base origin first)."""
    frames = chain_transforms(m, table, list(q))
    return [(0.0, 0.0, 0.0), *((T[0][3], T[1][3], T[2][3]) for T in frames)]


def link_transform(
    theta: npt.ArrayLike,
    d: npt.ArrayLike,
    a: npt.ArrayLike,
    alpha: npt.ArrayLike,
    convention: Convention = "standard",
) -> npt.NDArray[np.float64]:
    """Numeric homogeneous transform of one D-H link (paper section 1.2, matrices A_i).

    Parameters
    ----------
    theta, d, a, alpha : array_like, broadcastable
        Joint angle [rad], offset along z [mm], length along x [mm], twist [rad].
    convention : {"standard", "modified"}

    Returns
    -------
    ndarray, shape (..., 4, 4)

    Examples
    --------
    The paper's A_1 at theta_1 = 45 deg (Table 1: alpha = 90 deg, a = 0, d = L1 = 660 mm)
    maps the origin of frame 1 to the shoulder point (0, 0, 660) mm:

    >>> T = link_transform(np.pi / 4, 660.0, 0.0, np.pi / 2)
    >>> T[:3, 3].round(9).tolist()
    [0.0, 0.0, 660.0]
    """
    theta, d, a, alpha = np.broadcast_arrays(
        *(np.asarray(v, dtype=float) for v in (theta, d, a, alpha))
    )
    rows = _link_elements(
        np.cos(theta), np.sin(theta), np.cos(alpha), np.sin(alpha), a, d, convention
    )
    out = np.zeros((*theta.shape, 4, 4))
    for i, row in enumerate(rows):
        for j, value in enumerate(row):
            out[..., i, j] = value
    out[..., 3, 3] = 1.0
    return out


def link_transform_sym(theta, d, a, alpha, convention: Convention = "standard") -> sp.Matrix:
    """Symbolic (SymPy) homogeneous transform of one D-H link; same formula as
    :func:`link_transform`. Pass exact angles (``sp.pi / 2``) to get exact 0 and 1."""
    import sympy as sp

    theta, d, a, alpha = (sp.sympify(v) for v in (theta, d, a, alpha))
    rows = _link_elements(
        sp.cos(theta), sp.sin(theta), sp.cos(alpha), sp.sin(alpha), a, d, convention
    )
    return sp.Matrix([*[[sp.sympify(v) for v in r] for r in rows], [0, 0, 0, 1]])


def inverse_transform(T: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Inverse of homogeneous transforms, ``[R p; 0 1]^-1 = [R^T  -R^T p; 0 1]``.

    The closed form behind the paper's A_i^-1 (section 1.2). Shape (..., 4, 4).
    """
    T = np.asarray(T, dtype=float)
    R_t = np.swapaxes(T[..., :3, :3], -1, -2)
    out = np.zeros_like(T)
    out[..., :3, :3] = R_t
    out[..., :3, 3] = -np.einsum("...ij,...j->...i", R_t, T[..., :3, 3])
    out[..., 3, 3] = 1.0
    return out


@dataclass(frozen=True)
class DHRow:
    """One row of a D-H table. Angles in radians, lengths in mm.

    For the modified convention ``alpha`` and ``a`` are the row's ``alpha_{i-1}`` and
    ``a_{i-1}`` (Craig's table layout).
    """

    alpha: float
    a: float
    d: float
    theta_offset: float = 0.0
    kind: JointKind = "revolute"
    name: str = ""

    def __post_init__(self) -> None:
        for label in ("alpha", "a", "d", "theta_offset"):
            value = getattr(self, label)
            if isinstance(value, (int, float)) and not math.isfinite(value):
                raise ValueError(f"D-H row {self.name or '?'}: {label} = {value} is not finite")
        if self.kind not in ("revolute", "prismatic", "fixed"):
            raise ValueError(
                f"D-H row {self.name or '?'}: kind {self.kind!r} is not 'revolute', "
                "'prismatic' or 'fixed'"
            )


@dataclass(frozen=True)
class DHTable:
    """An ordered D-H table of one convention: the single source of the chain geometry.

    The same rows feed :meth:`fk` (NumPy), :meth:`transforms_sym` (SymPy) and
    :func:`analysis.kinematics.pinocchio_model.build_model` (Pinocchio).
    """

    rows: tuple[DHRow, ...]
    convention: Convention = "standard"
    name: str = field(default="", compare=False)

    def __post_init__(self) -> None:
        if self.convention not in CONVENTIONS:
            raise ValueError(
                f"unknown D-H convention {self.convention!r}; expected one of {CONVENTIONS}"
            )
        if not self.rows:
            raise ValueError("a D-H table needs at least one row")
        object.__setattr__(self, "rows", tuple(self.rows))

    @property
    def n_joints(self) -> int:
        """Number of joint variables (revolute and prismatic rows)."""
        return sum(row.kind in MOVING for row in self.rows)

    @property
    def joint_kinds(self) -> tuple[str, ...]:
        """ "revolute" or "prismatic" per joint variable, in chain order."""
        return tuple(row.kind for row in self.rows if row.kind in MOVING)

    def _rows_of(self, q: npt.ArrayLike, kind: str, base: str) -> npt.NDArray[np.float64]:
        q = np.asarray(q, dtype=float)
        if q.ndim == 0 or q.shape[-1] != self.n_joints:
            raise ValueError(f"joint array has shape {q.shape}; expected (..., {self.n_joints})")
        out = np.broadcast_to(
            np.array([getattr(row, base) for row in self.rows]), (*q.shape[:-1], len(self.rows))
        ).copy()
        moving = [i for i, row in enumerate(self.rows) if row.kind in MOVING]
        for j, i in enumerate(moving):
            if self.rows[i].kind == kind:
                out[..., i] += q[..., j]
        return out

    def joint_angles(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Per-row theta for joint values ``q`` of shape (..., n_joints) -> (..., n_rows)."""
        return self._rows_of(q, "revolute", "theta_offset")

    def joint_offsets(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Per-row d [mm] for joint values ``q`` (..., n_joints) -> (..., n_rows): a
        prismatic row's d plus its joint value."""
        return self._rows_of(q, "prismatic", "d")

    def transforms(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Link transforms A_1..A_n, shape (..., n_rows, 4, 4), for joints (..., n_joints)."""
        theta = self.joint_angles(q)
        d = self.joint_offsets(q)
        a = np.array([r.a for r in self.rows])
        alpha = np.array([r.alpha for r in self.rows])
        return link_transform(theta, d, a, alpha, self.convention)

    def fk(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Base-to-last-frame transform ``T_0_n = A_1 ... A_n`` (paper eq. 1), (..., 4, 4)."""
        A = self.transforms(q)
        T = A[..., 0, :, :]
        for i in range(1, len(self.rows)):  # loop over links, never over points
            T = T @ A[..., i, :, :]
        return T

    def transforms_sym(self, q: Sequence | None = None, exact: bool = True) -> list[sp.Matrix]:
        """Symbolic link transforms A_1..A_n.

        ``q`` defaults to symbols theta1..thetan. With ``exact`` the twist angles are
        rationalised to multiples of pi (90 deg -> pi/2), so cos/sin become exact 0/1.
        """
        import sympy as sp

        if q is None:
            q = sp.symbols(f"theta1:{self.n_joints + 1}", real=True)
        q = list(q)
        if len(q) != self.n_joints:
            raise ValueError(f"{len(q)} joint symbols given; the table has {self.n_joints} joints")
        it = iter(q)
        out = []
        for row in self.rows:
            alpha = _exact_angle(row.alpha) if exact else row.alpha
            offset = _exact_angle(row.theta_offset) if exact else row.theta_offset
            theta = offset + next(it) if row.kind == "revolute" else offset
            d = _exact(row.d, exact)
            if row.kind == "prismatic":
                d = d + next(it)
            out.append(link_transform_sym(theta, d, _exact(row.a, exact), alpha, self.convention))
        return out

    @classmethod
    def from_csv(cls, path: str | Path, convention: Convention, name: str = "") -> DHTable:
        """Read a D-H table CSV with columns ``alpha_deg, a_mm, d_mm`` and optional
        ``theta_offset_deg``, ``kind`` (revolute|fixed) and ``joint`` (row name)."""
        path = Path(path)
        with path.open(newline="", encoding="utf-8") as fh:
            reader = csv.DictReader(fh)
            missing = {"alpha_deg", "a_mm", "d_mm"} - set(reader.fieldnames or ())
            if missing:
                raise ValueError(f"{path}: missing column(s) {', '.join(sorted(missing))}")
            rows = []
            for lineno, rec in enumerate(reader, start=2):
                try:
                    rows.append(
                        DHRow(
                            alpha=math.radians(float(rec["alpha_deg"])),
                            a=float(rec["a_mm"]),
                            d=float(rec["d_mm"]),
                            theta_offset=math.radians(float(rec.get("theta_offset_deg") or 0.0)),
                            kind=(rec.get("kind") or "revolute").strip(),
                            name=(rec.get("joint") or "").strip(),
                        )
                    )
                except ValueError as exc:
                    raise ValueError(f"{path} line {lineno}: {exc}") from None
        return cls(tuple(rows), convention, name or path.stem)


def _exact(value, exact: bool):
    import sympy as sp

    if isinstance(value, sp.Basic) or not exact:
        return sp.sympify(value)
    return sp.nsimplify(value)


def _exact_angle(value):
    """Radians -> exact multiple of pi where the angle is a whole number of degrees."""
    import sympy as sp

    if isinstance(value, sp.Basic):
        return value
    deg = math.degrees(value)
    if abs(deg - round(deg)) < 1e-9:
        return sp.Rational(round(deg), 180) * sp.pi
    return sp.Float(value)
