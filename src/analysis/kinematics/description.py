"""Arm descriptions: one TOML file per arm in ``data/arms/``, the single source of its geometry.

A description holds the D-H rows as the paper prints them (numbers or parameter names),
the parameters' values with their provenance (``printed``, ``derived`` or ``assumed``; a
value may be read from a table of the paper kept verbatim in ``data/``), and the joints'
drive (pulses per revolution, limits). Everything numeric in the project about an arm
comes from here: the closed form (:mod:`analysis.kinematics.arms`) receives the parameter
values, the chain (:class:`~analysis.kinematics.dh.DHTable`) is built from the rows, and
Pinocchio is built from that chain.

Format (``data/arms/grabber.toml`` is the commented example)::

    name = "grabber"; title = "..."; paper = "..."
    closed_form = "grabber"            # module analysis.kinematics.arms.<closed_form>; without
                                       # it, one derived from the rows (analysis.kinematics.derive)
    convention = "standard"            # or "modified" (Craig)
    [parameters]
    L1 = { value = 660.0, unit = "mm", status = "printed", source = "Table 3" }
    L2 = { table = "table3.csv", match = { link = "shoulder" }, column = "a_mm", ... }
    [[rows]]                           # one per D-H row, in chain order
    link = "waist"; joint = "theta1"; alpha_deg = 90; a = 0; d = "L1"; theta_offset_deg = 0
    kind = "revolute"                  # or "fixed" (a tool row without a joint)
    [[joints]]                         # one per joint variable, in chain order
    name = "theta1"; pulses_per_rev = 4000; limits_deg = [-180, 180]
    # or pulses_per_rev = { value = 3200, status = "assumed" } (provenance as for parameters)

Why hand-written: the format is the project's own (TOML read by the standard library's
``tomllib``); no robot-description library (URDF, MJCF) keeps a paper's symbols and the
provenance of every number, which is what an audit needs.
"""

from __future__ import annotations

import csv
import math
import tomllib
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

from analysis.kinematics.dh import DHRow, DHTable
from analysis.paths import data_dir

__all__ = [
    "MAX_PULSES_PER_REV",
    "ArmDescription",
    "JointSpec",
    "ParamSpec",
    "check_pulses_per_rev",
    "load_description",
]

STATUSES = ("printed", "derived", "assumed")
MAX_PULSES_PER_REV = 10_000_000
"""Upper bound of pulses (or encoder counts) per joint revolution: a 200-step motor at 256
microsteps gives 51,200 and a 24-bit encoder 16,777,216 per motor turn; 10^7 per joint
turn keeps every pulse count of a joint within +-5 x 10^6, far inside a DINT."""


@dataclass(frozen=True)
class ParamSpec:
    """One parameter: value, unit, provenance ("printed", "derived" or "assumed")."""

    name: str
    value: float
    unit: str
    status: str
    source: str


@dataclass(frozen=True)
class JointSpec:
    """One joint variable: drive resolution and limits [rad]."""

    name: str
    pulses_per_rev: int
    lower: float
    upper: float
    limits_status: str = ""
    pulses_status: str = "printed"
    """Provenance of ``pulses_per_rev`` ("printed", "derived" or "assumed")."""

    @property
    def unlimited(self) -> bool:
        """True if the limits allow every angle (a full turn or more)."""
        return self.lower <= -math.pi and self.upper >= math.pi


@dataclass(frozen=True, eq=False)
class ArmDescription:
    """A parsed ``data/arms/<name>.toml`` (see the module docstring).

    Compared and hashed by identity: :func:`load_description` returns one object per file
    version, which the compiled kernels are cached by."""

    name: str
    title: str
    paper: str
    closed_form: str
    convention: str
    parameters: dict[str, ParamSpec]
    rows: tuple[dict, ...]
    joints: tuple[JointSpec, ...]
    path: Path | None = field(default=None, compare=False)
    derive: dict = field(default_factory=dict, compare=False)
    """The ``[derive]`` table: decisions for a closed form derived from the rows
    (:mod:`analysis.kinematics.derive.families`)."""

    @property
    def values(self) -> dict[str, float]:
        """Parameter values by name."""
        return {k: p.value for k, p in self.parameters.items()}

    @property
    def assumed(self) -> tuple[str, ...]:
        """Names of parameters whose values are assumed (not printed in the paper)."""
        return tuple(k for k, p in self.parameters.items() if p.status == "assumed")

    def dh_table(self, values: dict | None = None, symbolic: bool = False) -> DHTable:
        """The chain with parameter ``values`` (default: the description's), or with SymPy
        symbols of the parameter names (positive reals) if ``symbolic``."""
        vals = dict(self.values if values is None else values)
        angle = math.radians
        if symbolic:
            import sympy as sp

            vals = {k: sp.Symbol(k, positive=True) for k in self.parameters}

            def angle(deg):
                return sp.nsimplify(deg) * sp.pi / 180

        rows = []
        for r in self.rows:
            rows.append(
                DHRow(
                    alpha=angle(float(r.get("alpha_deg", 0.0))),
                    a=_resolve(r.get("a", 0.0), vals, self.name),
                    d=_resolve(r.get("d", 0.0), vals, self.name),
                    theta_offset=angle(float(r.get("theta_offset_deg", 0.0))),
                    kind=r.get("kind", "revolute"),
                    name=r.get("link", r.get("joint", "")),
                )
            )
        return DHTable(tuple(rows), self.convention, self.title)


def _resolve(v, values: dict, arm: str):
    if isinstance(v, str):
        if v not in values:
            raise ValueError(f"arm {arm}: D-H row uses {v!r}, which is not a parameter")
        return values[v]
    return float(v)


def check_pulses_per_rev(value, where: str) -> int:
    """A whole number of pulses per revolution in 1 .. :data:`MAX_PULSES_PER_REV`."""
    ok = isinstance(value, (int, float)) and not isinstance(value, bool)
    if ok and math.isfinite(value) and value == int(value) and 1 <= value <= MAX_PULSES_PER_REV:
        return int(value)
    raise ValueError(
        f"{where}: pulses_per_rev = {value!r} must be a whole number in 1 .. {MAX_PULSES_PER_REV:,}"
    )


def _table_value(spec: dict, base: Path, tables: dict, where: str) -> float:
    name = spec["table"]
    path = Path(tables.get(name, base / name))
    try:
        with path.open(newline="", encoding="utf-8") as fh:
            reader = csv.DictReader(fh)
            header = reader.fieldnames or []
            if len(set(header)) != len(header):
                raise ValueError(f"{path}: duplicate column names in the header {header}")
            rows = list(reader)
    except FileNotFoundError:
        raise ValueError(f"{where}: table {path} not found") from None
    col = spec["column"]
    for key in [*spec.get("match", {}), col]:
        if key not in header:
            raise ValueError(f"{where}: {path} has no column {key!r} (columns: {header})")
    for n, row in enumerate(rows, start=2):
        if None in row or None in row.values():
            raise ValueError(f"{path} line {n}: {len(header)} columns expected")
    hits = [r for r in rows if all(r[k] == str(v) for k, v in spec.get("match", {}).items())]
    if len(hits) != 1:
        raise ValueError(f"{where}: {len(hits)} rows of {path} match {spec.get('match')}")
    text = hits[0][col]
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f"{where}: {path} column {col}: {text!r} is not a number") from None
    if not math.isfinite(value):
        raise ValueError(f"{where}: {path} column {col}: {text!r} is not finite")
    return value


def _number(spec, base: Path, tables: dict, where: str) -> float:
    if isinstance(spec, dict) and "table" in spec:
        return _table_value(spec, base, tables, where)
    if isinstance(spec, dict):
        spec = spec.get("value")
    if not isinstance(spec, (int, float)) or isinstance(spec, bool) or not math.isfinite(spec):
        raise ValueError(f"{where}: {spec!r} is not a finite number")
    return float(spec)


def load_description(name: str, tables: dict | None = None) -> ArmDescription:
    """Read ``data/arms/<name>.toml`` once per version of it and of its tables; see
    :func:`_load` for the arguments."""
    path = Path(name) if name.endswith(".toml") else data_dir() / "arms" / f"{name}.toml"
    if not path.is_file():
        known = sorted(p.stem for p in (data_dir() / "arms").glob("*.toml"))
        raise ValueError(f"no arm {name!r}: expected one of {', '.join(known)}")
    files = [path, *(Path(v) for v in (tables or {}).values()), *path.parent.parent.glob("*.csv")]
    stamp = tuple((str(f.resolve()), *_version(f)) for f in files)
    return _load(str(path), tuple(sorted((tables or {}).items())), stamp)


def _version(path: Path) -> tuple[int, int]:
    try:
        st = path.stat()
    except FileNotFoundError:
        return (-1, -1)
    return (st.st_mtime_ns, st.st_size)


@cache
def _load(name: str, tables: tuple, stamp: tuple) -> ArmDescription:
    """Read ``data/arms/<name>.toml``.

    Parameters
    ----------
    name : str
        Arm name (file stem), or a path to a TOML file.
    tables : dict, optional
        Replacement paths for the tables a description reads, by file name (e.g.
        ``{"table3.csv": "my_table3.csv"}`` for the command line's ``--params``).

    Raises ``ValueError`` naming the file and the entry for anything malformed.
    """
    path = Path(name)
    try:
        d = tomllib.loads(path.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"{path}: not valid TOML ({exc})") from None
    tables = dict(tables or {})
    base = path.parent.parent
    params = {}
    for key, spec in d.get("parameters", {}).items():
        where = f"{path.name} parameter {key}"
        status = spec.get("status", "printed") if isinstance(spec, dict) else "printed"
        if status not in STATUSES:
            raise ValueError(f"{where}: status {status!r} is not one of {STATUSES}")
        params[key] = ParamSpec(
            key,
            _number(spec, base, tables, where),
            spec.get("unit", "mm") if isinstance(spec, dict) else "mm",
            status,
            spec.get("source", spec.get("note", "")) if isinstance(spec, dict) else "",
        )
    rows = tuple(d.get("rows", ()))
    if not rows:
        raise ValueError(f"{path}: no [[rows]]")
    joints = []
    for j in d.get("joints", ()):
        where = f"{path.name} joint {j.get('name', '?')}"
        ppr = check_pulses_per_rev(_number(j["pulses_per_rev"], base, tables, where), where)
        spec = j["pulses_per_rev"]
        pstatus = spec.get("status", "printed") if isinstance(spec, dict) else "printed"
        if pstatus not in STATUSES:
            raise ValueError(f"{where}: pulses_per_rev status {pstatus!r} is not one of {STATUSES}")
        lo, hi = (float(v) for v in j.get("limits_deg", (-180.0, 180.0)))
        if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
            raise ValueError(f"{where}: limits_deg [{lo}, {hi}] must be finite with lower < upper")
        joints.append(
            JointSpec(
                j["name"],
                ppr,
                math.radians(lo),
                math.radians(hi),
                j.get("limits_status", ""),
                pstatus,
            )
        )
    n_rev = sum(r.get("kind", "revolute") == "revolute" for r in rows)
    if len(joints) != n_rev:
        raise ValueError(f"{path}: {len(joints)} [[joints]] for {n_rev} revolute rows")
    desc = ArmDescription(
        d.get("name", path.stem),
        d.get("title", path.stem),
        d.get("paper", ""),
        d.get("closed_form") or "derived",
        d.get("convention", "standard"),
        params,
        rows,
        tuple(joints),
        path,
        dict(d.get("derive", {})),
    )
    desc.dh_table()  # every row resolves
    if desc.closed_form == "derived":  # none named: derived from the rows where it can be
        from analysis.kinematics.derive import attach

        desc = attach(desc)
    return desc
