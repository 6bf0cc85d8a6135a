"""An arm's numbers: :class:`Params` (parameter values [mm] and pulses per revolution), and
the paper's arm's Table 3 (seed 000) read into them.

:class:`Params` is plain numbers, checked by :mod:`analysis.validate` when built: no file is
read, no closed form looked up, no geometry answered (the closed form's, on
:attr:`analysis.kinematics.arm.Arm.geometry`). The loader
(:func:`analysis.kinematics.loader.load_arm`) builds it from a description.

The grabber's description (``data/arms/grabber.toml``) reads its lengths and pulses per
revolution from ``data/table3.csv``, the paper's Table 3 verbatim. :func:`load_table3`
reads a Table-3-shaped file (the command line's ``--params``) with the checks that file
needs, and :func:`ArmParams` builds the grabber's parameters from numbers.
"""

from __future__ import annotations

import io
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

from analysis import validate
from analysis.kinematics.schema import NoDrive
from analysis.paths import data_dir
from analysis.safe_io import read_text

__all__ = ["ArmParams", "Params", "data_dir", "load_table3", "paper_params"]


@dataclass(frozen=True)
class Params(Mapping):
    """The numbers of one arm: parameter values [mm] by name and, where the description gives
    a drive, pulses per revolution per joint, checked by :mod:`analysis.validate` (lengths
    within its range, whole pulses).

    A read-only mapping of parameter names to values, which also allows attribute access to
    them (``P.L1``) and to the informational items of ``extra``.

    ``drive`` is None for an arm without a drive (an engineer's D-H table): then
    :attr:`pulses_per_rev` raises ``no_drive`` (a :class:`~analysis.kinematics.schema.
    NoDrive` naming the joint and the key), at the point of need.

    >>> P = Params({"L1": 660, "L2": 310.0}, (4000, 4000))
    >>> P.L1, dict(P.with_(L2=300)), P.pulses_per_rev
    (660.0, {'L1': 660.0, 'L2': 300.0}, (4000, 4000))
    >>> Params({"L1": 660}, None).pulses_per_rev  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    analysis.kinematics.schema.NoDrive: pulses_per_rev: is missing: no drive given, ...
    """

    data: Mapping[str, float]
    drive: tuple[int, ...] | None
    """Pulses per revolution per joint, or None (no drive given)."""
    extra: Mapping = field(default_factory=dict, compare=False)
    """Informational items of the paper's tables (e.g. Table 3's step angles)."""
    no_drive: NoDrive | None = field(default=None, compare=False, repr=False)
    """What :attr:`pulses_per_rev` raises where ``drive`` is None."""

    def __post_init__(self) -> None:
        if not isinstance(self.data, Mapping):
            raise ValueError(f"parameters {self.data!r} must map names to lengths [mm]")
        vals = {}
        for k, v in dict(self.data).items():
            if not isinstance(k, str):
                raise ValueError(f"parameter name {k!r} is not text")
            vals[k] = validate.length_mm(v, k)  # real, finite, in the supported range
        object.__setattr__(self, "data", vals)
        ppr = self.drive
        if ppr is None:
            return
        if hasattr(ppr, "tolist"):
            ppr = ppr.tolist()
        try:
            if not isinstance(ppr, (list, tuple)) or not ppr:
                raise ValueError
            ppr = tuple(validate.pulses_per_rev(v, "pulses_per_rev") for v in ppr)
        except ValueError:
            raise ValueError(
                f"pulses_per_rev = {self.drive!r}: need whole numbers in "
                f"1 .. {validate.MAX_PULSES_PER_REV:,}, one per joint"
            ) from None
        object.__setattr__(self, "drive", ppr)

    @property
    def pulses_per_rev(self) -> tuple[int, ...]:
        """Pulses per revolution per joint; ``no_drive`` (:class:`~analysis.kinematics.
        schema.NoDrive`) where the arm has no drive."""
        if self.drive is None:
            raise self.no_drive or NoDrive("", None)
        return self.drive

    @property
    def has_drive(self) -> bool:
        """True if every joint's drive is given (pulse counts are defined)."""
        return self.drive is not None

    def __getitem__(self, key: str) -> float:
        return self.data[key]

    def __iter__(self):
        return iter(self.data)

    def __len__(self) -> int:
        return len(self.data)

    def __getattr__(self, name: str):
        if name.startswith("_") or name in ("data", "drive", "pulses_per_rev", "extra",
                                            "no_drive"):  # fmt: skip
            raise AttributeError(name)
        if name in self.data:
            return self.data[name]
        if name in self.extra:
            return self.extra[name]
        raise AttributeError(f"no parameter {name!r} (parameters: {', '.join(self.data)})")

    def with_(self, **changes) -> Params:
        """A copy with some values (or ``pulses_per_rev``) changed, checked again; a name
        that is not a parameter is refused."""
        ppr = changes.pop("pulses_per_rev", self.drive)
        unknown = sorted(set(changes) - set(self.data))
        if unknown:
            raise ValueError(
                f"unknown parameter(s) {unknown}; the parameters are {', '.join(self.data)}"
            )
        return Params({**self.data, **changes}, ppr, self.extra, self.no_drive)


MAX_TABLE3_BYTES = 1 << 16
"""Largest Table 3 file read [bytes] (64 KiB: the paper's is 500 bytes)."""
TABLE3_COLUMNS = (
    "link",
    "alpha_deg",
    "a_mm",
    "d_mm",
    "cos_alpha",
    "sin_alpha",
    "pulses_per_rev",
    "step_angle_deg",
    "resolution_deg",
)


def ArmParams(
    L1,
    L2,
    L3,
    pulses_per_rev=(4000, 4000, 4000),
    step_angle_deg=(1.8, 1.8, 1.8),
    resolution_deg=(0.09, 0.09, 0.09),
) -> Params:
    """Parameters of the paper's 3R arm from numbers (Table 3 layout; lengths in mm).

    ``step_angle_deg`` and ``resolution_deg`` are Table 3's informational columns.
    """
    extra = {
        "step_angle_deg": tuple(float(v) for v in step_angle_deg),
        "resolution_deg": tuple(float(v) for v in resolution_deg),
    }
    return Params({"L1": L1, "L2": L2, "L3": L3}, pulses_per_rev, extra)


def load_table3(path: str | Path | None = None) -> Params:
    """Read a Table 3 file (default ``data/table3.csv``: the paper's Table 3 verbatim plus
    pulses per revolution) into the grabber's parameters.

    Checks that the table has the topology the closed form assumes (Table 1: alpha = 90,
    0, 0 deg; a_1 = 0; d_2 = d_3 = 0) and that the printed cos/sin columns agree with
    alpha; raises ``ValueError`` naming the file, row and column otherwise.
    """
    path = (Path(path) if path is not None else data_dir() / "table3.csv").absolute()
    try:
        st = path.stat()
    except OSError as exc:
        raise ValueError(f"{path}: {exc.strerror or 'cannot read'}") from None
    return _load_table3(path, st.st_mtime_ns, st.st_size)


@cache
def _load_table3(path: Path, mtime_ns: int, size: int) -> Params:
    """Read once per file version (the audit asks for Table 3 hundreds of times). Every cell
    is read by the rules of :func:`analysis.validate.parse_real` (the command line's and the
    batch CSV's): an empty cell, ``nan``, ``inf`` or ``1_000`` is refused, naming the line
    and the column."""
    import csv

    text = read_text(path, MAX_TABLE3_BYTES, "Table 3 file")  # regular, bounded, UTF-8
    try:
        reader = csv.reader(io.StringIO(text, newline=""), strict=True)
        header = next(reader, None)
        body = [(reader.line_num, row) for row in reader if row]
    except csv.Error as exc:
        raise ValueError(f"{path}: cannot read as CSV ({exc})") from None
    header = [h.strip() for h in header or ()]
    missing = [c for c in TABLE3_COLUMNS if c not in header]
    if missing:
        raise ValueError(f"{path}: missing column(s) {', '.join(missing)}")
    if len(body) != 3:
        raise ValueError(f"{path}: {len(body)} rows; the arm has 3 links (waist, shoulder, elbow)")
    rows = []
    for line, cells in body:
        if len(cells) != len(header):
            raise ValueError(
                f"{path} line {line}: {len(cells)} fields, the header has {len(header)}"
            )
        raw = dict(zip(header, cells, strict=True))
        row = {"link": raw["link"]}
        for col in TABLE3_COLUMNS[1:]:
            row[col] = validate.parse_real(raw[col], f"{path} line {line} column {col}")
        for col in ("step_angle_deg", "resolution_deg"):
            if not 0 < row[col] <= 360:
                raise ValueError(
                    f"{path} line {line} column {col}: {row[col]:g} deg must be > 0 and "
                    "<= 360 deg"
                )
        rows.append(row)
    alpha = [r["alpha_deg"] for r in rows]
    if alpha != [90.0, 0.0, 0.0]:
        raise ValueError(f"{path}: alpha_deg = {alpha}; the closed-form IK needs [90, 0, 0]")
    for row in rows:
        rad = math.radians(row["alpha_deg"])
        if not (
            abs(math.cos(rad) - row["cos_alpha"]) <= 1e-12
            and abs(math.sin(rad) - row["sin_alpha"]) <= 1e-12
        ):
            raise ValueError(f"{path}: link {row['link']}: cos/sin columns disagree with alpha")
    a, d = [r["a_mm"] for r in rows], [r["d_mm"] for r in rows]
    if a[0] != 0.0 or d[1] != 0.0 or d[2] != 0.0:
        raise ValueError(f"{path}: need a_1 = 0 and d_2 = d_3 = 0 (Table 1), got a = {a}, d = {d}")
    return ArmParams(
        L1=d[0],
        L2=a[1],
        L3=a[2],
        pulses_per_rev=tuple(
            int(v) if float(v).is_integer() else v for v in (r["pulses_per_rev"] for r in rows)
        ),
        step_angle_deg=tuple(r["step_angle_deg"] for r in rows),
        resolution_deg=tuple(r["resolution_deg"] for r in rows),
    )


def paper_params() -> Params:
    """The paper's arm as printed in Table 3 (L1 = 660, L2 = 310, L3 = 200 mm)."""
    return load_table3()
