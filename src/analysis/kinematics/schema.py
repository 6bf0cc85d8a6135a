"""The one schema of an arm description: every key known, every value typed, ranged and
converted, every refusal one line naming the file, the key and the rule (issue 27 item 1).

A description comes from anyone (``--arm PATH``): it is read as untrusted data. The schema is
data too (:data:`TOP`, :data:`PARAMETER`, :data:`ROW`, :data:`JOINT`, ...: the keys each table
may hold); :class:`Reader` walks a parsed description against it:

- **unknown keys** are refused, naming the key and the closest known one (``limit_deg``: did
  you mean ``limits_deg``?), so a misspelt key never silently drops a twist or a joint stop;
- **numbers** go through :mod:`analysis.validate` (real, finite, within the range the code
  supports; a boolean or a text is not a number); **lengths** carry a unit (:data:`analysis.
  validate.LENGTH_UNITS`: mm, cm, m, in) and are converted to millimetres, any other unit
  refused; a length read from a table column whose name ends in its unit (``d_mm``) takes that
  unit, and a ``unit`` that contradicts it is refused;
- **names that reach an output** (the arm's ``name``, parameter, axis and joint names: PLC
  identifiers, MAP.json keys, URDF joint names, the explorer's script) follow
  :data:`IDENTIFIER`, the IEC 61131-3 identifier rule, ASCII only; link names (URDF link
  names, drawn labels) follow :data:`LABEL`; free text (title, paper, sources, notes) is one
  line of printable characters, :data:`MAX_TEXT` at most;
- every error is a :class:`DescriptionError` (a ValueError): ``<file>: <where> <key>: <what>
  (<rule>)``, one line, never a traceback.

Why by hand: the rules are the project's (which units, which ranges, which identifier rule)
and its messages name the paper's keys; a JSON-Schema validator (``jsonschema``) would give
the structure checks but not the conversions, the closest-key hints or one-line messages
without a second translation layer.
"""

from __future__ import annotations

import difflib
import re
import unicodedata
from collections.abc import Iterable

from analysis import validate

__all__ = [
    "AXIS",
    "DERIVE",
    "HOME",
    "IDENTIFIER",
    "JOINT",
    "LABEL",
    "MAX_TEXT",
    "NUMBER_SPEC",
    "PARAMETER",
    "RATE",
    "ROW",
    "STATUSES",
    "TOP",
    "DescriptionError",
    "NoDrive",
    "Reader",
    "derive_decisions",
    "identifier_problem",
    "source",
    "status",
]

STATUSES = ("printed", "derived", "assumed", "measured")
"""Provenance of a value: printed in the paper, derived from printed values, assumed (not
printed: every figure and table that uses it says so), or measured (on the robot, for a
user's own arm)."""
TOP = ("name", "title", "paper", "closed_form", "convention", "parameters", "axes", "rows",
       "joints", "derive")  # fmt: skip
"""Keys of a description's top level."""
PARAMETER = ("value", "table", "match", "column", "unit", "status", "source", "note")
"""Keys of a ``[parameters]`` entry given as a table (or a bare number: millimetres)."""
AXIS = ("value", "status", "note", "source")
ROW = ("link", "joint", "kind", "alpha_deg", "a", "d", "theta_offset_deg")
JOINT = ("name", "kind", "pulses_per_rev", "limits_deg", "limits_mm", "limits_status", "lead_mm",
         "max_velocity", "max_acceleration", "max_jerk", "home")  # fmt: skip
NUMBER_SPEC = ("value", "table", "match", "column", "status", "source", "note", "resolution_deg")
"""Keys of a joint's ``pulses_per_rev`` or ``lead_mm`` given as a table."""
RATE = ("value", "unit", "status", "source", "note")
HOME = ("mode", "position", "status", "source", "note")
DERIVE = ("forward", "elbow", "keep", "orientation_tol_deg")
KEEP = ("tool_axis", "direction")

IDENTIFIER = (
    "an identifier: an ASCII letter, then ASCII letters and digits with single underscores "
    "between them (IEC 61131-3: no leading, doubled or trailing underscore), at most 32 "
    "characters"
)
_IDENTIFIER = re.compile(r"[A-Za-z](?:_?[A-Za-z0-9])*")
LABEL = (
    "a label: ASCII letters, digits, spaces, '-' and '_', starting with a letter or digit, at "
    "most 40 characters"
)
_LABEL = re.compile(r"[A-Za-z0-9][A-Za-z0-9 _-]*")
MAX_TEXT = 2000
"""Longest free text (a title, a source, a note) [characters]."""
TEXT = f"one line of printable characters, at most {MAX_TEXT}"


class DescriptionError(ValueError):
    """A description refused: one line naming the file, the key and the rule.

    Attributes: ``file`` (the description's file name), ``key`` (where in it, e.g.
    ``[[joints]] 2 limits_deg``), ``rule`` (what the value breaks)."""

    def __init__(self, file: str, key: str, rule: str) -> None:
        self.file, self.key, self.rule = file, key, " ".join(str(rule).split())
        super().__init__(f"{file}: {key}: {self.rule}" if key else f"{file}: {self.rule}")


class NoDrive(DescriptionError):
    """A drive value (``pulses_per_rev``, a prismatic joint's ``lead_mm``) asked of a joint
    whose description gives none: what needs a drive (a pulse count, a PLC program, a pulse
    quantization study) refuses at the point of need, naming the joint and the key. Raised by
    :attr:`analysis.kinematics.joints.JointSpec.pulses_per_rev` (and ``lead_mm``) and by
    :attr:`analysis.kinematics.params.Params.pulses_per_rev` (built from them), the places
    a drive is read from."""

    def __init__(self, file: str, joint: str | None, key: str = "pulses_per_rev") -> None:
        hint = ("a whole number of pulses per motor revolution, or a table" if
                key == "pulses_per_rev" else "the travel per motor revolution [mm]")  # fmt: skip
        rule = (f"is missing: no drive given, and a pulse count or PLC program needs one "
                f"(give {key} = {hint}, in the joint's [[joints]] entry)")  # fmt: skip
        if file.lower().endswith(".urdf"):  # a URDF has no drive: the way to give one
            rule += (f"; a URDF has no drive: python -m analysis arms --arm {file} --toml > "
                     "arm.toml writes its description, to which you add it")  # fmt: skip
        super().__init__(file, f"joint {joint} {key}" if joint else key, rule)
        self.joint = joint
        if not file:  # no file to name: the key and the rule alone
            self.args = (f"{self.key}: {self.rule}",)


def identifier_problem(value: object) -> str | None:
    """Why ``value`` is not an :data:`IDENTIFIER`, or None."""
    if not isinstance(value, str):
        return f"{_show(value)} is not text"
    if not value:
        return "is empty"
    if len(value) > 32:
        return f"{_show(value)} is longer than 32 characters"
    if not _IDENTIFIER.fullmatch(value):
        return f"{_show(value)} is not an identifier"
    return None


def _show(value: object, n: int = 40) -> str:
    """A value quoted for a message: short, on one line, control characters escaped."""
    text = repr(value)
    return text if len(text) <= n else text[:n] + "...'"


def closest(key: str, known: Iterable[str]) -> str:
    """`` (did you mean 'x'?)`` for the known key most like ``key``, or the known keys."""
    known = list(known)
    near = difflib.get_close_matches(str(key), known, n=1, cutoff=0.6)
    if near:
        return f"did you mean {near[0]!r}? (known: {', '.join(known)})"
    return f"known: {', '.join(known)}"


class Reader:
    """Typed access to one parsed table of a description, every error a
    :class:`DescriptionError` naming ``file`` and ``where`` (``[[joints]] 2``) and the key.

    >>> r = Reader({"limit_deg": [0, 90]}, "arm.toml", "[[joints]] 1")
    >>> r.check_keys(("name", "limits_deg"))
    Traceback (most recent call last):
    ...
    analysis.kinematics.schema.DescriptionError: arm.toml: [[joints]] 1 limit_deg: unknown \
key; did you mean 'limits_deg'? (known: name, limits_deg)
    """

    def __init__(self, data: object, file: str, where: str = "") -> None:
        if not isinstance(data, dict):
            raise DescriptionError(file, where, f"{_show(data)} must be a table")
        self.data, self.file, self.where = data, file, where

    def key(self, key: str) -> str:
        return f"{self.where} {key}".strip()

    def error(self, key: str, rule: str) -> DescriptionError:
        return DescriptionError(self.file, self.key(key), rule)

    def check_keys(self, known: tuple[str, ...]) -> None:
        """Refuse a key that is not in ``known``, naming the closest known one."""
        for k in self.data:
            if k not in known:
                raise self.error(str(k), f"unknown key; {closest(k, known)}")

    def __contains__(self, key: str) -> bool:
        return key in self.data

    def raw(self, key: str, default=None):
        return self.data.get(key, default)

    def sub(self, key: str, known: tuple[str, ...] | None = None) -> Reader:
        """The table at ``key`` (a missing key is an empty one), its keys checked."""
        r = Reader(self.data.get(key, {}), self.file, self.key(key))
        if known is not None:
            r.check_keys(known)
        return r

    def tables(self, key: str) -> list[Reader]:
        """The array of tables at ``key`` (``[[key]]``; missing: none), one reader each."""
        v = self.data.get(key, [])
        if not isinstance(v, list) or not all(isinstance(t, dict) for t in v):
            raise self.error(key, f"must be an array of tables ([[{key}]]), not {_show(v)}")
        return [Reader(t, self.file, f"[[{key}]] {i}") for i, t in enumerate(v, start=1)]

    # --- text ------------------------------------------------------------------------------
    def text(self, key: str, default: str = "") -> str:
        """Free text: one line of printable characters (:data:`TEXT`)."""
        v = self.data.get(key, default)
        if not isinstance(v, str):
            raise self.error(key, f"{_show(v)} must be text ({TEXT})")
        if len(v) > MAX_TEXT:
            raise self.error(key, f"is {len(v)} characters long ({TEXT})")
        bad = next((c for c in v if unicodedata.category(c)[0] in "CZ" and c != " "), None)
        if bad is not None:
            raise self.error(key, f"holds the character U+{ord(bad):04X} ({TEXT})")
        return v

    def ident(self, key: str, default: str | None = None) -> str:
        """A name that reaches generated code: an :data:`IDENTIFIER`."""
        v = self.data.get(key, default)
        problem = identifier_problem(v)
        if problem:
            raise self.error(key, f"{problem} (a name is {IDENTIFIER})")
        return v

    def label(self, key: str, default: str = "") -> str:
        """A link name: a :data:`LABEL` (or empty)."""
        v = self.data.get(key, default)
        if not isinstance(v, str) or (v and (len(v) > 40 or not _LABEL.fullmatch(v))):
            raise self.error(key, f"{_show(v)} is not {LABEL}")
        return v

    def choice(self, key: str, choices: tuple[str, ...], default: str | None = None) -> str:
        v = self.data.get(key, default)
        if v not in choices:
            raise self.error(key, f"{_show(v)} is not one of {', '.join(choices)}")
        return v

    # --- numbers ---------------------------------------------------------------------------
    def number(self, key: str, value=None, **ranges) -> float:
        """A real number by :func:`analysis.validate.real` (``lo``, ``hi``, ``unit``,
        ``what``); ``value`` instead of the key's own."""
        v = self.data.get(key) if value is None else value
        try:
            return validate.real(v, "", ranges.pop("unit", ""), **ranges)
        except ValueError as exc:
            raise self.error(key, str(exc)) from None

    def length(self, key: str, value=None, unit: str = "mm") -> float:
        """A length [mm] given in ``unit`` (:func:`analysis.validate.length_in_mm`)."""
        v = self.data.get(key) if value is None else value
        try:
            return validate.length_in_mm(v, unit, "")
        except ValueError as exc:
            raise self.error(key, str(exc).lstrip(": ")) from None

    def angle_deg(self, key: str, value=None) -> float:
        """An angle [deg] within :data:`analysis.validate.MAX_JOINT_DEG` (ten turns)."""
        return self.number(key, value, unit="deg", lo=-validate.MAX_JOINT_DEG,
                           hi=validate.MAX_JOINT_DEG, what="ten turns")  # fmt: skip

    def pair(self, key: str, item) -> tuple[float, float]:
        """``[lower, upper]`` with lower < upper, each read by ``item(key, value)``."""
        raw = self.data.get(key)
        if not isinstance(raw, list) or len(raw) != 2:
            raise self.error(key, f"{_show(raw)} must be two numbers [lower, upper]")
        lo, hi = (item(key, v) for v in raw)
        if not lo < hi:
            raise self.error(key, f"[{lo:g}, {hi:g}] must have lower < upper")
        return lo, hi

    def vector3(self, key: str, value=None, *, nonzero: bool = True) -> tuple[float, ...]:
        """Three finite numbers (not all zero where ``nonzero``)."""
        v = self.data.get(key) if value is None else value
        if not isinstance(v, list) or len(v) != 3:
            raise self.error(key, f"{_show(v)} must be three numbers [x, y, z]")
        out = tuple(self.number(key, c, lo=-validate.MAX_LENGTH_MM, hi=validate.MAX_LENGTH_MM,
                                what="the largest value the code supports") for c in v)  # fmt: skip
        if nonzero and not any(out):
            raise self.error(key, "[0, 0, 0] is not a direction")
        return out


def derive_decisions(r: Reader) -> dict:
    """The ``[derive]`` decisions, typed (their meaning: :mod:`analysis.kinematics.derive.
    families`)."""
    out = dict(r.data)
    if "elbow" in r:
        r.choice("elbow", ("target", "arm"))
    if "forward" in r:
        r.vector3("forward")
    if "orientation_tol_deg" in r:
        r.number("orientation_tol_deg", unit="deg", lo=0.0, hi=90.0)
    if "keep" in r:
        k = r.sub("keep", KEEP)
        if isinstance(k.raw("tool_axis"), str):
            k.choice("tool_axis", ("x", "y", "z"))
        else:
            k.vector3("tool_axis")
        k.vector3("direction")
    return out


def length_unit(r: Reader, column) -> str:
    """A parameter's ``unit`` (mm by default); a table ``column`` whose name ends in a unit
    (``d_mm``) gives that unit, and a ``unit`` that contradicts it is refused."""
    named = column.rsplit("_", 1)[1] if isinstance(column, str) and "_" in column else None
    named = named if named in validate.LENGTH_UNITS else None
    unit = r.choice("unit", tuple(validate.LENGTH_UNITS), named or "mm")
    if named and unit != named:
        raise r.error("unit", f"{unit!r} contradicts column {column!r}, whose name says "
                      f"{named} (give the column's unit or none)")  # fmt: skip
    return unit


def status(r: Reader, key: str = "status", default: str = "printed") -> str:
    """A value's provenance, one of :data:`STATUSES`."""
    return r.choice(key, STATUSES, default)


def source(r: Reader) -> str:
    """Where a value comes from: its ``source``, else its ``note``."""
    return r.text("source", r.text("note", ""))
