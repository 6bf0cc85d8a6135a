"""Arm descriptions: one TOML file per arm in ``data/arms/``, the single source of its geometry.

A description holds the D-H rows as the paper prints them (numbers or parameter names), the
parameters' values with their provenance (``printed``, ``derived``, ``assumed`` or
``measured``; a value may be read from a table of the paper kept verbatim in ``data/``, or
next to the description), and the joints (limits; the drive, pulses per revolution, where
the description gives one: :mod:`analysis.kinematics.joints`). Everything
numeric in the project about an arm comes from here: the closed form
(:mod:`analysis.kinematics.arms`) receives the parameter values, the chain
(:class:`~analysis.kinematics.dh.DHTable`) is built from the rows, and Pinocchio is built
from that chain.

Format (``data/arms/grabber.toml`` is the commented example)::

    name = "grabber"; title = "..."; paper = "..."
    closed_form = "grabber"            # module analysis.kinematics.arms.<closed_form>, or
                                       # "my_arm.py": a file next to the description; without
                                       # it, one derived from the rows (analysis.kinematics.derive)
    convention = "standard"            # or "modified" (Craig)
    [parameters]
    L1 = { value = 660.0, unit = "mm", status = "printed", source = "Table 3" }
    L2 = { table = "table3.csv", match = { link = "shoulder" }, column = "a_mm", ... }
    [[rows]]                           # one per D-H row, in chain order
    link = "waist"; joint = "theta1"; alpha_deg = 90; a = 0; d = "L1"; theta_offset_deg = 0
    kind = "revolute"                  # "prismatic" (the joint value adds to d [mm]) or
                                       # "fixed" (a tool row without a joint)
    [[joints]]                         # one per joint variable, in chain order (optional
                                       # where every joint is revolute: the rows name them)
    name = "theta1"; pulses_per_rev = 4000; limits_deg = [-180, 180]
    # or pulses_per_rev = { value = 3200, status = "assumed" } (provenance as for parameters)
    # the drive (pulses_per_rev; lead_mm) is optional: a D-H table has none, and what needs
    #   one refuses naming the joint and the key (analysis.kinematics.joints)
    # a prismatic joint: kind = "prismatic"; limits_mm = [lo, hi] (required);
    #   lead_mm = 5.0 (travel per motor revolution; pulses = mm / lead_mm * pulses_per_rev;
    #   with pulses_per_rev, or neither)
    # motion limits and homing (optional; None where absent, JointSpec.require names them):
    max_velocity     = { value = 90.0,   unit = "deg/s",  status = "assumed", source = "..." }
    max_acceleration = { value = 360.0,  unit = "deg/s2", status = "assumed", source = "..." }
    max_jerk         = { value = 3600.0, unit = "deg/s3", status = "assumed", source = "..." }
    #   (rad/s...; a prismatic joint mm/s, mm/s2, mm/s3, or cm, m, in), kept in rad | mm per s^k
    home = { mode = "switch", position = 0.0, status = "assumed", source = "..." }
    #   mode "switch" (a reference switch) or "set"; position [deg | mm] within the limits
    [axes]                             # optional: axis directions of a screw model
    vertical_guide = { value = [0, 0, 1], status = "printed", note = "..." }

A description without ``[[rows]]`` names a closed form that gives the forward kinematics
itself (``fk``: a closed chain such as the picker's, by POE); the arm checks that when it
loads (:class:`analysis.kinematics.arm.Arm`). A table file named by a parameter is looked
for next to the description first, then in ``data/``, so a description kept in a user's own
folder can carry its own tables.

Why hand-written: the format is the project's own (TOML read by the standard library's
``tomllib``); no robot-description library (URDF, MJCF) keeps a paper's symbols and the
provenance of every number, which is what an audit needs.
"""

from __future__ import annotations

import math
import re
import tomllib
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

from analysis import validate
from analysis.kinematics import schema
from analysis.kinematics.dh import DHRow, DHTable
from analysis.kinematics.joints import (
    HOME_MODES,
    JOINT_KINDS,
    MOTION_KEYS,
    RATE_KEYS,
    JointSpec,
    read_joint,
    row_joints,
)
from analysis.kinematics.schema import (
    IDENTIFIER,
    STATUSES,
    DescriptionError,
    NoDrive,
    Reader,
    identifier_problem,
)
from analysis.kinematics.schema import source as _source
from analysis.kinematics.schema import status as _status
from analysis.kinematics.tables import table_path, table_value
from analysis.kinematics.urdf_in import description_text as urdf_description_text
from analysis.paths import data_dir
from analysis.safe_io import read_text

__all__ = [
    "DERIVED",
    "HOME_MODES",
    "JOINT_KINDS",
    "MAX_DESCRIPTION_BYTES",
    "MAX_PULSES_PER_REV",
    "MOTION_KEYS",
    "RATE_KEYS",
    "STATUSES",
    "ArmDescription",
    "AxisSpec",
    "DescriptionError",
    "JointSpec",
    "NoDrive",
    "ParamSpec",
    "description_toml",
    "load_description",
]

MAX_PULSES_PER_REV = validate.MAX_PULSES_PER_REV
MAX_DESCRIPTION_BYTES = 1 << 20
"""Largest description file read [bytes] (1 MiB: the seed arms' are 3-7 kB)."""
IDENTIFIER_RE = re.compile(r"[A-Za-z](?:_?[A-Za-z0-9])*")
DERIVED = "derived"
"""The ``closed_form`` of a description that asks for one derived from its rows (also what
a missing ``closed_form`` means where there are rows)."""


@dataclass(frozen=True)
class ParamSpec:
    """One parameter: value, unit, provenance ("printed", "derived" or "assumed")."""

    name: str
    value: float
    unit: str
    status: str
    source: str


@dataclass(frozen=True)
class AxisSpec:
    """One axis direction of a screw model (unit ``-``), with its provenance."""

    name: str
    value: tuple[float, float, float]
    status: str
    note: str


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
    axes: dict[str, AxisSpec] = field(default_factory=dict)

    @property
    def has_rows(self) -> bool:
        """True if the description gives D-H rows (else its closed form gives the FK)."""
        return bool(self.rows)

    derive: dict = field(default_factory=dict, compare=False)
    """The ``[derive]`` table: decisions for a closed form derived from the rows
    (:mod:`analysis.kinematics.derive.families`)."""
    files: tuple[Path, ...] = field(default=(), compare=False)
    """Every file read to build it: the description, then each table it read (resolved
    paths): an output may be none of them (:func:`analysis.safe_io.check_paths`)."""

    @property
    def statuses(self) -> dict[str, str]:
        """Provenance of every parameter and axis, by name."""
        return {**{k: p.status for k, p in self.parameters.items()},
                **{k: a.status for k, a in self.axes.items()}}  # fmt: skip

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
        if not self.rows:
            raise ValueError(
                f"arm {self.name} has no D-H rows: its closed form {self.closed_form!r} gives "
                "its forward kinematics"
            )
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


def description_path(name: str | Path) -> Path:
    """The file of arm ``name``: ``data/arms/<name>.toml`` for a name, or ``name`` itself
    for the path of a description file (anything ending in ``.toml`` or holding a folder
    separator) or of a URDF (``.urdf``: its serial chain, :mod:`analysis.kinematics.urdf_in`),
    anywhere on disk.

    Raises ValueError naming the arms that exist, or the file that does not.
    """
    text = str(name)
    urdf = text.lower().endswith(".urdf")  # a URDF's chain (analysis.kinematics.urdf_in)
    if isinstance(name, Path) or text.endswith(".toml") or urdf or "/" in text or "\\" in text:
        path = Path(text).expanduser()
        if not path.exists():
            raise ValueError(f"no arm description {text!r}: no such file")
        return path
    if not IDENTIFIER_RE.fullmatch(text):
        raise ValueError(f"no arm {text!r}: an arm name is {IDENTIFIER} (or give a *.toml path)")
    path = data_dir() / "arms" / f"{text}.toml"
    if not path.is_file():
        known = sorted(p.stem for p in (data_dir() / "arms").glob("*.toml"))
        raise ValueError(
            f"no arm {text!r}: expected one of {', '.join(known)}, or the path of a "
            "description file (*.toml)"
        )
    return path


def description_toml(name: str | Path) -> str:
    """The description of arm ``name`` as TOML text: the file itself, or for a URDF the
    description it is converted to (:func:`analysis.kinematics.urdf_in.description_text`:
    what a user copies to add what a URDF lacks, its drive)."""
    path = description_path(name)
    if path.suffix.lower() == ".urdf":
        return urdf_description_text(path)
    return read_text(path, MAX_DESCRIPTION_BYTES, "arm description")


def load_description(name: str | Path, tables: dict | None = None) -> ArmDescription:
    """Read ``data/arms/<name>.toml`` (or the description file at path ``name``) once per
    version of it and of the tables it may read; see :func:`_load` for the arguments.

    Raises ValueError (:class:`~analysis.kinematics.schema.DescriptionError`, or
    :class:`analysis.safe_io.InputError` for a file that cannot be read) in one line naming
    the file, the key and the rule."""
    path = description_path(name)
    near = [*path.parent.glob("*.csv"), *data_dir().glob("*.csv")]
    files = [path, *(Path(v) for v in (tables or {}).values()), *near]
    stamp = tuple((str(f.resolve()), *_version(f)) for f in files)
    return _load(str(path), tuple(sorted((tables or {}).items())), stamp)


def _version(path: Path) -> tuple[int, int]:
    try:
        st = path.stat()
    except OSError:
        return (-1, -1)
    return (st.st_mtime_ns, st.st_size)


@cache
def _load(name: str, tables: tuple, stamp: tuple) -> ArmDescription:
    """Read and check the description file ``name`` against the schema
    (:mod:`analysis.kinematics.schema`).

    Parameters
    ----------
    name : str
        The description's path.
    tables : tuple of (str, str)
        Replacement paths for the tables a description reads, by file name (e.g.
        ``{"table3.csv": "my_table3.csv"}``), chosen by the caller.
    """
    path = Path(name)
    file = path.name
    if path.suffix.lower() == ".urdf":  # a URDF's serial chain, converted (bounded, no DTD)
        text = urdf_description_text(path)
    else:
        text = read_text(path, MAX_DESCRIPTION_BYTES, "arm description")
    try:
        d = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise DescriptionError(file, "", f"not valid TOML ({exc})") from None
    except RecursionError:
        raise DescriptionError(file, f"line {_deep_line(text)}", "arrays or tables nested "
                               "deeper than the TOML reader follows") from None  # fmt: skip
    r = Reader(d, file)
    r.check_keys(schema.TOP)
    ctx = _Context(path, file, dict(tables))
    params = {k: _parameter(r.sub("parameters"), k, ctx) for k in r.sub("parameters").data}
    axes = {k: _axis(r.sub("axes"), k) for k in r.sub("axes").data}
    rows = tuple(_row(t, params) for t in r.tables("rows"))
    if "rows" in d and not rows:
        raise DescriptionError(file, "[[rows]]", "is empty")
    joints = tuple(read_joint(t, ctx.number, file) for t in r.tables("joints"))
    if "joints" not in d and rows:  # an engineer's D-H table: the rows name the joints
        joints = row_joints(file, rows)
    _check_chain(file, rows, joints)
    closed_form = r.text("closed_form", DERIVED if rows else _stem(path))
    if not closed_form:
        raise DescriptionError(file, "closed_form", "must name a closed form")
    desc = ArmDescription(
        r.ident("name", _stem(path)),
        r.text("title", path.stem),
        r.text("paper", ""),
        closed_form,
        r.choice("convention", ("standard", "modified"), "standard"),
        params,
        rows,
        joints,
        path,
        axes,
        schema.derive_decisions(r.sub("derive", schema.DERIVE)),
        (path.resolve(), *dict.fromkeys(ctx.read)),
    )
    if rows:
        desc.dh_table()  # every row resolves
    return desc


def _deep_line(text: str, depth: int = 256) -> int:
    """The line where brackets first open ``depth`` deep (where a TOML reader's recursion
    ends), or the last line."""
    level, n = 0, 1
    for c in text:
        level += (c in "[{") - (c in "]}")
        n += c == "\n"
        if level > depth:
            break
    return n


class _Context:
    """Where a description is and which tables its caller replaced."""

    def __init__(self, path: Path, file: str, tables: dict) -> None:
        self.path, self.file, self.tables = path, file, tables
        self.read: list[Path] = []

    def number(self, r: Reader, key: str) -> float:
        """A number given bare, as ``{ value = ... }`` or read from a table."""
        spec = r.raw(key)
        if isinstance(spec, dict):
            sub = r.sub(key)
            if "table" in spec:
                name = spec["table"]
                where = sub.key("table")
                path = (Path(self.tables[name]) if name in self.tables else
                        table_path(name, self.path, self.file, where))  # fmt: skip
                self.read.append(path.resolve())
                return table_value(spec, path, self.file, where)
            if "value" not in spec:
                raise r.error(key, "needs a value (a number, or a table to read it from)")
            return sub.number("value")
        return r.number(key)


def _stem(path: Path) -> str:
    """The file's stem as a name: other characters than letters and digits become single
    underscores (``my-arm.toml`` is ``my_arm``)."""
    return "_".join(p for p in re.split(r"[^A-Za-z0-9]+", path.stem) if p) or "arm"


def _parameter(params: Reader, key: str, ctx: _Context) -> ParamSpec:
    """One ``[parameters]`` entry: a length [mm], bare or ``{ value | table, unit, ... }``."""
    if identifier_problem(key):
        raise params.error(key, f"{identifier_problem(key)} (a parameter name is "
                           f"{IDENTIFIER})")  # fmt: skip
    spec = params.raw(key)
    if not isinstance(spec, dict):
        return ParamSpec(key, params.length(key), "mm", "printed", "")
    r = params.sub(key, schema.PARAMETER)
    unit = schema.length_unit(r, spec.get("column"))
    value = ctx.number(params, key)
    return ParamSpec(key, r.length("value", value, unit), "mm", _status(r), _source(r))


def _axis(axes: Reader, key: str) -> AxisSpec:
    if identifier_problem(key):
        raise axes.error(key, f"{identifier_problem(key)} (an axis name is {IDENTIFIER})")
    spec = axes.raw(key)
    if not isinstance(spec, dict):
        return AxisSpec(key, axes.vector3(key), "printed", "")
    r = axes.sub(key, schema.AXIS)
    return AxisSpec(key, r.vector3("value"), _status(r), r.text("note", r.text("source", "")))


def _row(r: Reader, params: dict) -> dict:
    """One D-H row, as written, its values checked: angles [deg], lengths [mm] or the name
    of a parameter."""
    r.check_keys(schema.ROW)
    r.choice("kind", ("revolute", "prismatic", "fixed"), "revolute")
    r.label("link")
    if "joint" in r:
        r.ident("joint")
    row = dict(r.data)
    for key in ("alpha_deg", "theta_offset_deg"):
        if key in r:
            row[key] = r.angle_deg(key)
    for key in ("a", "d"):
        v = r.raw(key)
        if isinstance(v, str):
            if v not in params:
                raise r.error(key, f"{v!r} is not a parameter (parameters: "
                              f"{', '.join(params) or 'none'})")  # fmt: skip
        elif key in r:
            row[key] = r.length(key)
    return row


def _check_chain(file: str, rows: tuple, joints: tuple) -> None:
    if not joints:
        raise DescriptionError(file, "[[joints]]", "is missing (one per joint variable)" if
                               rows else "is missing: a description without D-H [[rows]] "
                               "names its joints in [[joints]], one per joint variable")
    names = [j.name for j in joints]
    dup = next((n for n in names if names.count(n) > 1), None)
    if dup:
        raise DescriptionError(file, "[[joints]]", f"repeat the name {dup!r} (names: {names})")
    if not rows:
        return
    moving = [r for r in rows if r.get("kind", "revolute") != "fixed"]
    if len(joints) != len(moving):
        raise DescriptionError(file, "[[joints]]", f"{len(joints)} joints for {len(moving)} "
                               "moving rows (revolute or prismatic)")  # fmt: skip
    for i, (j, row) in enumerate(zip(joints, moving, strict=True), 1):
        kind = row.get("kind", "revolute")
        if j.kind != kind:
            raise DescriptionError(file, f"[[joints]] ({j.name}) kind",
                                   f"{j.kind!r}, but its D-H row is {kind!r}")  # fmt: skip
        if row.get("joint", j.name) != j.name:  # entries out of order: limits on the wrong axis
            raise DescriptionError(file, f"[[joints]] {i} name", f"{j.name!r}, but moving D-H "
                                   f"row {i} names its joint {row['joint']!r} (the joints "
                                   "follow the moving rows, in order)")  # fmt: skip
