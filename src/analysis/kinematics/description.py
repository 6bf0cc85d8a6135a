"""Arm descriptions: one TOML file per arm in ``data/arms/``, the single source of its geometry.

A description holds the D-H rows as the paper prints them (numbers or parameter names), the
parameters' values with their provenance (``printed``, ``derived``, ``assumed`` or
``measured``; a value may be read from a table of the paper kept verbatim in ``data/``, or
next to the description), and the joints' drive (pulses per revolution, limits). Everything
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
    [[joints]]                         # one per joint variable, in chain order
    name = "theta1"; pulses_per_rev = 4000; limits_deg = [-180, 180]
    # or pulses_per_rev = { value = 3200, status = "assumed" } (provenance as for parameters)
    # a prismatic joint: kind = "prismatic"; limits_mm = [lo, hi] (required);
    #   lead_mm = 5.0 (travel per motor revolution; pulses = mm / lead_mm * pulses_per_rev)
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

import csv
import math
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

from analysis import validate
from analysis.kinematics.dh import DHRow, DHTable
from analysis.paths import data_dir

__all__ = [
    "DERIVED",
    "HOME_MODES",
    "JOINT_KINDS",
    "MAX_PULSES_PER_REV",
    "MOTION_KEYS",
    "RATE_KEYS",
    "STATUSES",
    "ArmDescription",
    "AxisSpec",
    "JointSpec",
    "ParamSpec",
    "check_pulses_per_rev",
    "load_description",
]

STATUSES = ("printed", "derived", "assumed", "measured")
"""Provenance of a value: printed in the paper, derived from printed values, assumed (not
printed: every figure and table that uses it says so), or measured (on the robot, for a
user's own arm)."""
JOINT_KINDS = ("revolute", "prismatic")
MAX_PULSES_PER_REV = validate.MAX_PULSES_PER_REV
DERIVED = "derived"
"""The ``closed_form`` of a description that asks for one derived from its rows (also what
a missing ``closed_form`` means where there are rows)."""
HOME_MODES = ("switch", "set")
"""How an axis is homed: "switch" (a reference switch is searched, MC_Home with a switch) or
"set" (the present position is declared to be the home position)."""
RATE_KEYS = ("max_velocity", "max_acceleration", "max_jerk")
MOTION_KEYS = (*RATE_KEYS, "home_mode", "home_position")
"""The joint values a machine program needs (:meth:`JointSpec.require`)."""
_RATE_UNIT = {"max_velocity": "/s", "max_acceleration": "/s2", "max_jerk": "/s3"}


def _rate_hint(key: str):
    return lambda j: (f'{key} = {{ value = ..., unit = "{"deg" if j.kind == "revolute" else "mm"}'
                      f'{_RATE_UNIT[key]}", status = ..., source = ... }}')  # fmt: skip


_MOTION_HINT = {
    **{k: _rate_hint(k) for k in RATE_KEYS},
    **dict.fromkeys(("home_mode", "home_position"), lambda j: 'home = { mode = "switch" | '
                    '"set", position = ..., status = ..., source = ... }'),
}  # fmt: skip


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


@dataclass(frozen=True)
class JointSpec:
    """One joint variable: its kind, drive resolution and limits [rad | mm].

    A revolute joint's pulse count is ``theta_deg / 360 * pulses_per_rev`` (eqs. 20-22 of
    seed 000); a prismatic joint's is ``q_mm / lead_mm * pulses_per_rev`` (a screw of lead
    ``lead_mm`` per motor revolution).
    """

    name: str
    pulses_per_rev: int
    lower: float
    upper: float
    limits_status: str = ""
    pulses_status: str = "printed"
    """Provenance of ``pulses_per_rev`` ("printed", "derived", "assumed" or "measured")."""
    kind: str = "revolute"
    lead_mm: float | None = None
    """Travel per motor revolution [mm] of a prismatic joint (None for a revolute one)."""
    lead_status: str = ""
    max_velocity: float | None = None
    """Largest speed [rad/s | mm/s], or None where the description gives none."""
    max_acceleration: float | None = None
    """Largest acceleration [rad/s^2 | mm/s^2], or None."""
    max_jerk: float | None = None
    """Largest jerk [rad/s^3 | mm/s^3], or None."""
    home_mode: str | None = None
    """How the axis finds its zero: "switch" (a reference switch, searched) or "set" (the
    present position is set to :attr:`home_position`), or None."""
    home_position: float | None = None
    """The joint value at home [rad | mm], or None."""
    max_velocity_status: str = ""
    max_acceleration_status: str = ""
    max_jerk_status: str = ""
    home_status: str = ""
    sources: Mapping[str, str] = field(default_factory=dict, compare=False)
    """Where each motion value comes from (``source`` or ``note`` of its entry), by key."""

    def require(self, key: str) -> float | str:
        """The motion value ``key`` (one of :data:`MOTION_KEYS`), or ValueError naming the
        joint and the key when the description gives none (a program that needs it refuses).

        >>> JointSpec("theta1", 4000, -1.0, 1.0).require("max_velocity")
        Traceback (most recent call last):
        ...
        ValueError: joint theta1 has no max_velocity: give max_velocity = { value = ...
        """
        if key not in MOTION_KEYS:
            raise ValueError(f"{key!r} is not a motion value ({', '.join(MOTION_KEYS)})")
        value = getattr(self, key)
        if value is None:
            raise ValueError(f"joint {self.name} has no {key}: give {_MOTION_HINT[key](self)} "
                             "in its [[joints]] entry")  # fmt: skip
        return value

    @property
    def unit(self) -> str:
        """The joint value's unit: "rad" (revolute) or "mm" (prismatic)."""
        return "rad" if self.kind == "revolute" else "mm"

    @property
    def unlimited(self) -> bool:
        """True if the limits allow every angle (a revolute joint turning a full turn or
        more; a prismatic joint always has a stroke)."""
        return self.kind == "revolute" and self.lower <= -math.pi and self.upper >= math.pi


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

    @property
    def statuses(self) -> dict[str, str]:
        """Provenance of every parameter and axis, by name."""
        return {**{k: p.status for k, p in self.parameters.items()},
                **{k: a.status for k, a in self.axes.items()}}  # fmt: skip
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


def check_pulses_per_rev(value, where: str) -> int:
    """A whole number of pulses per revolution in 1 .. :data:`MAX_PULSES_PER_REV`
    (:func:`analysis.validate.pulses_per_rev`)."""
    try:
        return validate.pulses_per_rev(value, "pulses_per_rev")
    except ValueError as exc:
        raise ValueError(f"{where}: {exc}") from None


def _table_path(name: str, folder: Path) -> Path:
    """A table named by a description: next to the description, else in ``data/``."""
    near = folder / name
    return near if near.is_file() else data_dir() / name


def _table_value(spec: dict, base: Path, tables: dict, where: str) -> float:
    name = spec["table"]
    path = Path(tables.get(name, _table_path(name, base)))
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
    return validate.parse_real(hits[0][col], f"{where}: {path} column {col}")


def _number(spec, base: Path, tables: dict, where: str) -> float:
    if isinstance(spec, dict) and "table" in spec:
        return _table_value(spec, base, tables, where)
    if isinstance(spec, dict):
        if "value" not in spec:
            raise ValueError(f"{where}: needs a value (a number, or a table to read it from)")
        spec = spec["value"]
    if isinstance(spec, (list, dict, str)):  # not a number at all (the words used before)
        raise ValueError(f"{where}: {spec!r} is not a finite number")
    return validate.real(spec, where)


def _text(d: dict, key: str, where: str, default: str) -> str:
    v = d.get(key, default)
    if not isinstance(v, str):
        raise ValueError(f"{where}: {key} = {v!r} must be a string")
    return v


def _table(d: dict, key: str, where: str) -> dict:
    """``[key]``: a table (a missing key is an empty one)."""
    v = d.get(key, {})
    if not isinstance(v, dict):
        raise ValueError(f"{where}: [{key}] must be a table, not {v!r}")
    return v


def _tables(d: dict, key: str, where: str) -> list[dict]:
    """``[[key]]``: an array of tables (a missing key is an empty one)."""
    v = d.get(key, [])
    if not isinstance(v, list) or not all(isinstance(t, dict) for t in v):
        raise ValueError(f"{where}: {key} must be an array of tables ([[{key}]]), not {v!r}")
    return v


def _row_value(v, where: str, key: str):
    """A D-H row's length: a number [mm] or the name of a parameter."""
    if isinstance(v, str):
        return v
    return validate.length_mm(v, f"{where} {key}")


def _row_angle(v, where: str, key: str) -> float:
    return validate.real(v, f"{where} {key}", "deg", lo=-validate.MAX_JOINT_DEG,
                         hi=validate.MAX_JOINT_DEG, what="ten turns")  # fmt: skip


def _check_rows(rows: list[dict], path: Path) -> tuple[dict, ...]:
    out = []
    for i, r in enumerate(rows, start=1):
        where = f"{path.name} row {i}"
        kind = r.get("kind", "revolute")
        if kind not in ("revolute", "prismatic", "fixed"):
            raise ValueError(f"{where}: kind {kind!r} is not 'revolute', 'prismatic' or 'fixed'")
        for key in ("link", "joint"):
            _text(r, key, where, "")
        row = dict(r)
        for key in ("alpha_deg", "theta_offset_deg"):
            if key in r:
                row[key] = _row_angle(r[key], where, key)
        for key in ("a", "d"):
            if key in r:
                row[key] = _row_value(r[key], where, key)
        out.append(row)
    return tuple(out)


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
        if not path.is_file():
            raise ValueError(f"no arm description {text!r}: no such file")
        return path
    path = data_dir() / "arms" / f"{text}.toml"
    if not path.is_file():
        known = sorted(p.stem for p in (data_dir() / "arms").glob("*.toml"))
        raise ValueError(
            f"no arm {text!r}: expected one of {', '.join(known)}, or the path of a "
            "description file (*.toml)"
        )
    return path


def load_description(name: str | Path, tables: dict | None = None) -> ArmDescription:
    """Read ``data/arms/<name>.toml`` (or the description file at path ``name``) once per
    version of it and of its tables; see :func:`_load` for the arguments."""
    path = description_path(name)
    near = [*path.parent.glob("*.csv"), *data_dir().glob("*.csv")]
    files = [path, *(Path(v) for v in (tables or {}).values()), *near]
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
        if path.suffix.lower() == ".urdf":  # converted to this format (no code run, bounded)
            from analysis.kinematics.urdf_in import description_text

            d = tomllib.loads(description_text(path))
        else:
            d = tomllib.loads(path.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"{path}: not valid TOML ({exc})") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise ValueError(f"{path}: cannot read ({exc})") from None
    tables = dict(tables or {})
    base = path.parent
    params = {}
    raw_params = d.get("parameters", {})
    if not isinstance(raw_params, dict):
        raise ValueError(f"{path.name}: [parameters] must be a table, not {raw_params!r}")
    for key, spec in raw_params.items():
        where = f"{path.name} parameter {key}"
        status = _status(spec, where)
        if isinstance(spec, dict):
            unit = _text(spec, "unit", where, "mm")
            source = _text(spec, "source", where, _text(spec, "note", where, ""))
        else:
            unit, source = "mm", ""
        value = _number(spec, base, tables, where)
        if unit == "mm":
            value = validate.length_mm(value, where)
        params[key] = ParamSpec(key, value, unit, status, source)
    raw_axes = d.get("axes", {})
    if not isinstance(raw_axes, dict):
        raise ValueError(f"{path.name}: [axes] must be a table, not {raw_axes!r}")
    axes = {}
    for key, spec in raw_axes.items():
        where = f"{path.name} axis {key}"
        value = spec.get("value") if isinstance(spec, dict) else spec
        ok = isinstance(value, list) and len(value) == 3
        ok = ok and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value)
        if not ok or not all(math.isfinite(v) for v in value) or not any(value):
            raise ValueError(f"{where}: {value!r} is not a direction (three finite numbers)")
        note = _text(spec, "note", where, _text(spec, "source", where, "")) if isinstance(
            spec, dict) else ""  # fmt: skip
        axes[key] = AxisSpec(key, tuple(float(v) for v in value), _status(spec, where), note)
    rows = _check_rows(_tables(d, "rows", path.name), path)
    if "rows" in d and not rows:
        raise ValueError(f"{path}: [[rows]] is empty")
    joints = tuple(
        _joint(j, path, base, tables, i)
        for i, j in enumerate(_tables(d, "joints", path.name), start=1)
    )
    if not joints:
        raise ValueError(f"{path}: no [[joints]] (one per joint variable)")
    names = [j.name for j in joints]
    if len(set(names)) != len(names):
        raise ValueError(f"{path}: [[joints]] repeat a name ({names})")
    if rows:
        moving = [r.get("kind", "revolute") for r in rows if r.get("kind", "revolute") != "fixed"]
        if len(joints) != len(moving):
            raise ValueError(
                f"{path}: {len(joints)} [[joints]] for {len(moving)} moving rows "
                "(revolute or prismatic)"
            )
        for j, kind in zip(joints, moving, strict=True):
            if j.kind != kind:
                raise ValueError(
                    f"{path} joint {j.name}: kind {j.kind!r}, but its D-H row is {kind!r}"
                )
    # none named: derived from the D-H rows (a description without rows names its own);
    # the loader (analysis.kinematics.loader) resolves it: a description is data
    cf_name = _text(d, "closed_form", path.name, DERIVED if rows else path.stem)
    if not cf_name:
        raise ValueError(f"{path}: closed_form = {cf_name!r} must name a closed form")
    convention = _text(d, "convention", path.name, "standard")
    if convention not in ("standard", "modified"):
        raise ValueError(f"{path.name}: convention {convention!r} is not 'standard' or 'modified'")
    desc = ArmDescription(
        _text(d, "name", path.name, path.stem),
        _text(d, "title", path.name, path.stem),
        _text(d, "paper", path.name, ""),
        cf_name,
        convention,
        params,
        rows,
        joints,
        path,
        axes,
        dict(_table(d, "derive", path.name)),
    )
    if rows:
        desc.dh_table()  # every row resolves
    return desc


def _status(spec, where: str) -> str:
    status = spec.get("status", "printed") if isinstance(spec, dict) else "printed"
    if status not in STATUSES:
        raise ValueError(f"{where}: status {status!r} is not one of {', '.join(STATUSES)}")
    return status


def _limits(j: dict, key: str, default, where: str, unit: str) -> tuple[float, float]:
    raw = j.get(key, default)
    if raw is None:
        raise ValueError(f"{where}: a prismatic joint needs its stroke, {key} = [lower, upper]")
    if not isinstance(raw, (list, tuple)) or len(raw) != 2:
        raise ValueError(f"{where}: {key} = {raw!r} must be two numbers [lower, upper]")
    if unit == "deg":
        lo, hi = (_row_angle(v, where, key) for v in raw)
    else:
        lo, hi = (validate.length_mm(v, f"{where} {key}") for v in raw)
    if not lo < hi:
        raise ValueError(f"{where}: {key} [{lo:g}, {hi:g}] must have lower < upper")
    return lo, hi


def _joint(j: dict, path: Path, base: Path, tables: dict, index: int) -> JointSpec:
    """One [[joints]] entry (the ``index``-th)."""
    name = j.get("name")
    if not isinstance(name, str) or not name:
        raise ValueError(f"{path.name} joint {index}: needs a name (a string), got {name!r}")
    where = f"{path.name} joint {name}"
    if "pulses_per_rev" not in j:
        raise ValueError(f"{where}: needs pulses_per_rev (a whole number, or a table)")
    kind = _text(j, "kind", where, "revolute")
    if kind not in JOINT_KINDS:
        raise ValueError(f"{where}: kind {kind!r} is not one of {', '.join(JOINT_KINDS)}")
    ppr = check_pulses_per_rev(_number(j["pulses_per_rev"], base, tables, where), where)
    pstatus = _status(j["pulses_per_rev"], f"{where} pulses_per_rev")
    lead = lead_status = None
    if kind == "revolute":
        if "limits_mm" in j or "lead_mm" in j:
            raise ValueError(f"{where}: limits_mm and lead_mm are for prismatic joints")
        lo, hi = (math.radians(v) for v in _limits(j, "limits_deg", [-180.0, 180.0], where, "deg"))
    else:
        if "limits_deg" in j:
            raise ValueError(f"{where}: a prismatic joint's stroke is limits_mm, not limits_deg")
        lo, hi = _limits(j, "limits_mm", None, where, "mm")
        if "lead_mm" not in j:
            raise ValueError(
                f"{where}: a prismatic joint needs lead_mm (travel per motor revolution)"
            )
        lead = _number(j["lead_mm"], base, tables, f"{where} lead_mm")
        lead_status = _status(j["lead_mm"], f"{where} lead_mm")
        if not lead > 0:
            raise ValueError(f"{where}: lead_mm = {lead:g} must be > 0 mm")
    return JointSpec(
        name,
        ppr,
        lo,
        hi,
        _text(j, "limits_status", where, ""),
        pstatus,
        kind,
        lead,
        lead_status or "",
        **_motion(j, where, kind, lo, hi),
    )


def _provenance(spec: dict, where: str) -> tuple[str, str]:
    status = _status(spec, where)
    return status, _text(spec, "source", where, _text(spec, "note", where, ""))


def _motion(j: dict, where: str, kind: str, lo: float, hi: float) -> dict:
    """The joint's motion limits and homing (``max_velocity``, ``max_acceleration``,
    ``max_jerk``, ``home``), converted to the joint's units (rad | mm) by
    :mod:`analysis.validate`; absent keys stay None."""
    out: dict = {"sources": {}}
    for order, key in enumerate(RATE_KEYS, start=1):
        if key not in j:
            continue
        spec = j[key]
        if not isinstance(spec, dict) or "value" not in spec or "unit" not in spec:
            raise ValueError(f"{where}: {key} must be {{ value = ..., unit = ..., status = ..., "
                             "source = ... }}")  # fmt: skip
        out[key] = validate.rate(spec["value"], spec["unit"], f"{where} {key}", order=order,
                                 kind=kind)  # fmt: skip
        out[f"{key}_status"], out["sources"][key] = _provenance(spec, f"{where} {key}")
    if "home" in j:
        spec = j["home"]
        if not isinstance(spec, dict) or "mode" not in spec or "position" not in spec:
            raise ValueError(f"{where}: home must be {{ mode = \"switch\" | \"set\", "
                             "position = ..., status = ..., source = ... }}")  # fmt: skip
        mode = spec["mode"]
        if mode not in HOME_MODES:
            raise ValueError(f"{where} home: mode {mode!r} is not one of {', '.join(HOME_MODES)}")
        if kind == "revolute":
            deg = _row_angle(spec["position"], where, "home position")
            pos = math.radians(deg)
        else:
            pos = validate.length_mm(spec["position"], f"{where} home position")
        if not lo <= pos <= hi:
            unit = "deg" if kind == "revolute" else "mm"
            show = math.degrees if kind == "revolute" else float
            raise ValueError(
                f"{where} home: position {show(pos):g} {unit} is outside the joint's limits "
                f"[{show(lo):g}, {show(hi):g}] {unit}"
            )
        out["home_mode"], out["home_position"] = mode, pos
        out["home_status"], out["sources"]["home"] = _provenance(spec, f"{where} home")
    return out
