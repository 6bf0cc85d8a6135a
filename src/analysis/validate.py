"""The one validation layer for every number a user gives (interfaces item 3).

Every entry point checks user numbers here, at its boundary, and nowhere else: the command
line's positionals and options, the cells of a batch CSV, the values of an arm description
(TOML) and of a Table 3 file (``--params``), and the arguments of the Python API
(:class:`~analysis.kinematics.arm.Arm`, :class:`~analysis.kinematics.arm.Params`). Past it,
nothing downstream sees a NaN, an inf, a complex, masked or boolean value, or a number outside
the range the code supports (so no square overflows, no generated PLC program contains
``inf``, no JSON carries ``Infinity``). Every refusal is an :class:`InvalidValue` (a
``ValueError``) whose one-line message names the value and the limit it breaks.

The rules
---------
Type (:func:`real`, :func:`real_array`)
    Real numbers only: ``int``, ``float``, ``fractions.Fraction``, NumPy integer and floating
    scalars and arrays. Refused: ``bool`` (a flag is not a length), complex (even with a zero
    imaginary part), masked arrays (the mask would be dropped), text, ``None``, objects.
Finite
    NaN and inf are refused; so is an integer too large for a float (``10**400``).
Text (:func:`parse_real`: the command line and CSV cells, one rule for both)
    Optional sign, ASCII digits with an optional point, an optional exponent:
    ``[+-]? (d+ [. d*] | . d+) ([eE] [+-]? d+)?`` with surrounding blanks allowed. Refused,
    though Python's ``float()`` takes them: underscores (``1_000``), non-ASCII digits
    (``١٢٣``, fullwidth ``１``), ``nan``, ``inf``, ``infinity``; also ``1,5``, ``0x10``, the
    empty cell. A number that overflows to inf (``1e400``) is refused as beyond the float range.
Ranges (the physical range the code supports)
    lengths and offsets ``|L| <=`` :data:`MAX_LENGTH_MM` and a non-zero length at least
    :data:`MIN_LENGTH_MM` (signs are the closed form's ``check``); coordinates
    ``|x| <=`` :data:`MAX_COORD_MM` (the largest PLC REAL); tolerances in 0 ..
    :data:`MAX_TOL_MM`; pulses per revolution whole in 1 .. :data:`MAX_PULSES_PER_REV`;
    joint angles ``|q| <=`` :data:`MAX_JOINT_DEG`; a waist angle in radians ``|a| <=``
    :data:`MAX_ANGLE_RAD`; orientation angles in radians: finite.
Angles in degrees are reduced exactly (:func:`reduce_deg`)
    An orientation angle or a waist angle given in degrees (command line, CSV) is reduced to
    (-180, 180] deg *before* it is converted to radians: ``fmod`` by 360, which IEEE 754
    computes exactly, and at most one exact shift by 360 (Sterbenz). 1.0000000000031762e+17 deg
    is 16 deg, exactly; converting first would round it to a multiple of pi/180 off by about
    0.25 rad. A waist angle in radians (the API's ``theta1_on_axis``) is wrapped to
    (-pi, pi] (:func:`wrap_rad`), as the README documents.

Why by hand: the rules are the project's (which ranges, which texts); no validation library
(pydantic, cerberus) knows NumPy's dtypes, masked arrays or an exact degree reduction.
"""

from __future__ import annotations

import math
import numbers
import re
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

__all__ = [
    "LENGTH_UNITS",
    "MAX_ANGLE_RAD",
    "MAX_COORD_MM",
    "MAX_JOINT_DEG",
    "MAX_LENGTH_MM",
    "MAX_PULSES_PER_REV",
    "MAX_RATE",
    "MAX_TOL_MM",
    "MIN_LENGTH_MM",
    "InvalidValue",
    "angle_rad",
    "check_inputs",
    "coordinate_mm",
    "length_in_mm",
    "length_mm",
    "number_problem",
    "parse_real",
    "pulses_per_rev",
    "rate",
    "real",
    "real_array",
    "reduce_deg",
    "tolerance_mm",
    "wrap_rad",
]

MAX_LENGTH_MM = 1e6
"""Largest |length or offset| of an arm [mm] (1 km): ten thousand times any industrial arm,
and small enough that every square and sum of the closed forms stays far inside float32
(a PLC REAL, 3.4e38) together with :data:`MAX_COORD_MM`."""
MIN_LENGTH_MM = 1e-3
"""Smallest non-zero |length| [mm] (1 micrometre): the closed forms divide by products of
lengths; below this they lose the target to round-off (and 1e-200 would underflow to 0)."""
MAX_COORD_MM = float(np.finfo(np.float32).max)
"""Largest |target coordinate| [mm]: the largest PLC REAL (3.4e38), the largest target a
generated program can be given. Every closed form refuses a target beyond its reach box
before it squares anything, and in float64 the squares of such coordinates stay finite, so
every distance the code reports is a finite number."""
MAX_TOL_MM = 1.0
"""Largest accepted distance tolerance [mm]: a solution "on the shell" may miss the target by
up to the tolerance, and more than a millimetre would pass a visibly wrong pose as solved."""
MAX_PULSES_PER_REV = 10_000_000
"""Upper bound of pulses (or encoder counts) per joint revolution: a 200-step motor at 256
microsteps gives 51,200 and a 24-bit encoder 16,777,216 per motor turn; 10^7 per joint
turn keeps every pulse count of a joint within +-5 x 10^6, far inside a DINT."""
MAX_JOINT_DEG = 3600.0
"""Largest accepted |joint angle| [deg] (ten turns): beyond it an input is a mistake of unit
or of digits, not a pose."""
MAX_ANGLE_RAD = math.radians(MAX_JOINT_DEG)
"""Largest accepted |waist angle| given in radians through the API (``theta1_on_axis``: ten
turns, 62.8 rad), which is wrapped to (-pi, pi] (:func:`wrap_rad`). Orientation angles in
radians need no bound: the closed forms use only their sine and cosine, which libm (numpy and
the compiled kernel alike) reduces exactly for every finite argument. Angles in degrees at the
command line and in CSV files are reduced exactly first (:func:`reduce_deg`)."""

LENGTH_UNITS = {"mm": 1.0, "cm": 10.0, "m": 1000.0, "in": 25.4}
"""Units a length may be given in, with their size in millimetres (the inch exactly 25.4 mm);
every other unit is refused (:func:`length_in_mm`)."""
MAX_RATE = (1e6, 1e8, 1e10)
"""Largest joint velocity, acceleration and jerk [deg or mm per s, s^2, s^3]: 1e6 deg/s is
2,778 turns a second, a hundred times any servo; the bounds keep every motion quantity and
its products with a PLC cycle far inside a REAL (3.4e38)."""
_RATE_UNITS = {"deg": ("deg", 1.0), "rad": ("deg", 180.0 / math.pi),
               **{u: ("mm", f) for u, f in {"mm": 1.0, "cm": 10.0, "m": 1000.0,
                                             "in": 25.4}.items()}}  # fmt: skip

_NUMBER = re.compile(r"[ \t]*[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?[ \t]*")
_SHOW = 40  # characters of a text quoted in a message


class InvalidValue(ValueError):
    """A user value refused by :mod:`analysis.validate`; the message is one line naming the
    value and the limit.

    Attributes
    ----------
    name : str
        What the value is (``"L2"``, ``"--tol"``, ``"x_mm"``, ``"target"``).
    value : object
        The value as given (text for a parsed cell).
    """

    def __init__(self, message: str, name: str = "", value: object = None) -> None:
        super().__init__(" ".join(str(message).split()))
        self.name = name
        self.value = value


def _show(value: object) -> str:
    if isinstance(value, str):
        return repr(value if len(value) <= _SHOW else value[:_SHOW] + "...")
    text = repr(value)
    return text if len(text) <= _SHOW else text[:_SHOW] + "..."


def _label(name: str) -> str:
    """``"L2 = "`` for a name, ``"<file> line 3 column x: "`` for a place."""
    if not name:
        return ""
    return f"{name} = " if " " not in name.strip() else f"{name}: "


def _fmt(v: float) -> str:
    return f"{v:g}"


# --------------------------------------------------------------------------------------------
# text
# --------------------------------------------------------------------------------------------
def number_problem(text: str) -> str | None:
    """Why ``text`` is not a number by the rules of :func:`parse_real`, or None."""
    if not isinstance(text, str):
        return f"{_show(text)} is not text"
    if not text.strip():
        return "empty; a number is required"
    if not _NUMBER.fullmatch(text):
        low = text.strip().lower().lstrip("+-")
        if low in ("nan", "inf", "infinity"):
            return f"{_show(text)} is not a finite number"
        if "_" in text:
            return f"{_show(text)} is not a number (no underscores: write 1000, not 1_000)"
        if any(c.isdigit() and not c.isascii() for c in text):
            return f"{_show(text)} is not a number (digits must be ASCII 0-9)"
        if "," in text:
            return f"{_show(text)} is not a number (the decimal mark is '.')"
        return f"{_show(text)} is not a number"
    if not math.isfinite(float(text)):
        return f"{_show(text)} is beyond the float range (+-1.8e308)"
    return None


def parse_real(text: str, name: str = "") -> float:
    """A number from the command line or a CSV cell (one rule for both; see the module).

    >>> parse_real(" -1e3 ")
    -1000.0
    >>> parse_real("1_000", "x_mm")
    Traceback (most recent call last):
    ...
    analysis.validate.InvalidValue: x_mm = '1_000' is not a number (no underscores: ...)
    """
    problem = number_problem(text)
    if problem:
        raise InvalidValue(f"{_label(name)}{problem}", name, text)
    return float(text)


# --------------------------------------------------------------------------------------------
# type and finiteness
# --------------------------------------------------------------------------------------------
def _type_problem(value: object) -> str | None:
    if isinstance(value, (bool, np.bool_)):
        return f"{value!r} is a boolean, not a number"
    if isinstance(value, np.ma.MaskedArray):
        return "a masked array is refused (the mask would be dropped): fill it first"
    if isinstance(value, (complex, np.complexfloating)):
        return f"{value!r} is complex; only real numbers are accepted"
    if isinstance(value, str | bytes):
        return f"{_show(value)} is text, not a number (parse it first)"
    if not isinstance(value, numbers.Real):
        return f"{_show(value)} ({type(value).__name__}) is not a real number"
    return None


def real(
    value: object,
    name: str = "",
    unit: str = "",
    *,
    lo: float | None = None,
    hi: float | None = None,
    what: str = "",
) -> float:
    """A real, finite scalar within [``lo``, ``hi``] as a float, else :class:`InvalidValue`.

    ``what`` says what the range is ("the largest length the code supports"), for the message.

    >>> real(2, "L2", "mm", lo=0)
    2.0
    >>> real(True, "L2")
    Traceback (most recent call last):
    ...
    analysis.validate.InvalidValue: L2 = True is a boolean, not a number
    >>> real(1e7, "L2", "mm", hi=1e6, what="the largest length the code supports")
    Traceback (most recent call last):
    ...
    analysis.validate.InvalidValue: L2 = 1e+07 mm is beyond 1e+06 mm, the largest length ...
    """
    if isinstance(value, np.ndarray) and value.ndim == 0 and not isinstance(
        value, np.ma.MaskedArray
    ):
        value = value[()]
    problem = _type_problem(value)
    if problem:
        raise InvalidValue(f"{_label(name)}{problem}", name, value)
    try:
        v = float(value)  # type: ignore[arg-type]
    except OverflowError:
        raise InvalidValue(
            f"{_label(name)}{_show(value)} is beyond the float range (+-1.8e308)", name, value
        ) from None
    u = f" {unit}" if unit else ""
    if not math.isfinite(v):
        raise InvalidValue(f"{_label(name)}{v!r}{u} is not finite", name, value)
    tail = f", {what}" if what else ""
    if lo is not None and v < lo:
        raise InvalidValue(f"{_label(name)}{_fmt(v)}{u} is below {_fmt(lo)}{u}{tail}", name, value)
    if hi is not None and v > hi:
        raise InvalidValue(f"{_label(name)}{_fmt(v)}{u} is beyond {_fmt(hi)}{u}{tail}", name, value)
    return v


def _nested_problem(obj: object, depth: int = 0) -> str | None:
    """Why a nested list/tuple cannot be taken as numbers although NumPy would convert it:
    a bool (to 0/1) or a masked value (to NaN, with a warning); None if neither."""
    if isinstance(obj, (bool, np.bool_)):
        return "a boolean is not a number"
    if isinstance(obj, np.ma.MaskedArray):
        return "a masked value is refused (the mask would be dropped): fill it first"
    if isinstance(obj, (list, tuple)) and depth < 32:
        for v in obj:
            problem = _nested_problem(v, depth + 1)
            if problem:
                return problem
    return None


def _fits_float(v: object) -> bool:
    try:
        float(v)  # type: ignore[arg-type]
    except OverflowError:
        return False
    return True


def real_array(
    value: npt.ArrayLike, name: str = "array", *, finite: bool = True
) -> npt.NDArray[np.float64]:
    """``value`` as a float64 array of real, finite numbers, else :class:`InvalidValue`.

    An array that is float64 already is returned as it is (no copy). Refused: complex, boolean
    and text dtypes, masked arrays, nested lists holding a bool, integers beyond the float
    range, NaN and inf (the message gives the first bad index and value; ``finite=False``
    leaves the values to the caller).
    """
    def refuse(reason: str, shown: object = value) -> InvalidValue:
        return InvalidValue(f"{name} {_show(shown)} is not numeric: {reason}", name, shown)

    if isinstance(value, np.ma.MaskedArray):
        raise InvalidValue(
            f"{name}: a masked array is refused (the mask would be dropped): fill it first", name
        )
    if isinstance(value, (bool, np.bool_, complex, np.complexfloating, str, bytes)):
        raise refuse(_type_problem(value) or "")
    if isinstance(value, np.ndarray):
        arr = value
    else:
        problem = _nested_problem(value) if isinstance(value, (list, tuple)) else None
        if problem:
            raise refuse(problem)
        try:
            arr = np.asarray(value)
        except (TypeError, ValueError) as exc:
            raise refuse(str(exc)) from None
    kind = arr.dtype.kind
    if kind == "f" and arr.dtype != np.float64:
        arr = arr.astype(np.float64)
    elif kind in "iu":
        arr = arr.astype(np.float64)
    elif kind == "O":
        flat = arr.reshape(-1)
        for v in flat:
            problem = _type_problem(v)
            if problem:
                raise refuse(problem)
        try:
            arr = arr.astype(np.float64)
        except OverflowError:
            big = next(v for v in flat if not _fits_float(v))
            raise refuse(f"{_show(big)} is beyond the float range (+-1.8e308)") from None
    elif kind != "f":
        what = {"b": "boolean", "c": "complex", "U": "text", "S": "bytes", "M": "dates",
                "m": "time spans", "V": "records"}.get(kind, arr.dtype.name)  # fmt: skip
        raise refuse(f"it holds {what}, not real numbers (dtype {arr.dtype})")
    # one pass (an overflowing sum is checked below)
    if finite and arr.size and not np.isfinite(arr.sum()):
        bad = ~np.isfinite(arr)
        if bad.any():
            idx = tuple(int(i) for i in np.argwhere(bad)[0])
            where = f" at index {idx}" if arr.ndim else ""
            raise InvalidValue(f"{name}{where} is {float(arr[idx])!r}: not a finite number", name)
    return arr


# --------------------------------------------------------------------------------------------
# ranges
# --------------------------------------------------------------------------------------------
def length_mm(value: object, name: str) -> float:
    """A length or offset of an arm [mm]: real, finite, ``|v| <=`` :data:`MAX_LENGTH_MM`, and
    0 or ``|v| >=`` :data:`MIN_LENGTH_MM` (the closed form's ``check`` decides the signs)."""
    v = real(value, name, "mm", lo=-MAX_LENGTH_MM, hi=MAX_LENGTH_MM,
             what="the largest length the code supports")  # fmt: skip
    if v != 0 and abs(v) < MIN_LENGTH_MM:
        raise InvalidValue(
            f"{name} = {v:g} mm: a non-zero length must be at least {MIN_LENGTH_MM:g} mm "
            "(1 micrometre)",
            name,
            value,
        )
    return v


def length_in_mm(value: object, unit: object, name: str) -> float:
    """A length given in ``unit`` (one of :data:`LENGTH_UNITS`: mm, cm, m, in) converted to
    millimetres and checked by :func:`length_mm`; any other unit is refused, naming it.

    >>> length_in_mm(0.66, "m", "L1")
    660.0
    >>> length_in_mm(660, "ft", "L1")
    Traceback (most recent call last):
    ...
    analysis.validate.InvalidValue: L1: unit 'ft' is not a length unit (mm, cm, m, in)
    """
    if not isinstance(unit, str) or unit not in LENGTH_UNITS:
        raise InvalidValue(
            f"{name}: unit {_show(unit)} is not a length unit ({', '.join(LENGTH_UNITS)})",
            name,
            unit,
        )
    v = real(value, name, unit)
    return length_mm(v * LENGTH_UNITS[unit] if unit != "mm" else v, name)


def rate(value: object, unit: object, name: str, *, order: int, kind: str) -> float:
    """A joint's largest velocity (``order`` 1), acceleration (2) or jerk (3), given in
    ``unit`` ("deg/s", "deg/s2", "deg/s3" or rad/... for a ``kind="revolute"`` joint;
    "mm/s", "mm/s2", ... or cm, m, in for a prismatic one), returned in the joint's units
    per second: rad/s^k (revolute) or mm/s^k (prismatic). Positive, finite, at most
    :data:`MAX_RATE` [deg | mm per s^k].

    >>> round(rate(90, "deg/s", "max_velocity", order=1, kind="revolute"), 6)
    1.570796
    >>> rate(0.5, "m/s2", "max_acceleration", order=2, kind="prismatic")
    500.0
    """
    suffix = "/s" if order == 1 else f"/s{order}"
    base = "deg" if kind == "revolute" else "mm"
    allowed = [u + suffix for u, (b, _) in _RATE_UNITS.items() if b == base]
    if not isinstance(unit, str) or unit not in allowed:
        raise InvalidValue(
            f"{name}: unit {_show(unit)} is not one of {', '.join(allowed)} "
            f"(a {kind} joint's {('velocity', 'acceleration', 'jerk')[order - 1]})",
            name,
            unit,
        )
    _, factor = _RATE_UNITS[unit[: -len(suffix)]]
    hi = MAX_RATE[order - 1]
    v = real(value, name, unit) * factor
    if not v > 0:
        raise InvalidValue(f"{_label(name)}{_fmt(v)} {base}{suffix} must be > 0", name, value)
    real(v, name, f"{base}{suffix}", hi=hi, what="the largest rate the code supports")
    return math.radians(v) if kind == "revolute" else v


def coordinate_mm(value: object, name: str) -> float:
    """A target coordinate [mm]: real, finite, ``|v| <=`` :data:`MAX_COORD_MM`."""
    return real(value, name, "mm", lo=-MAX_COORD_MM, hi=MAX_COORD_MM,
                what="the largest coordinate the code supports")  # fmt: skip


def tolerance_mm(value: object, name: str = "tol") -> float:
    """A distance tolerance [mm] in 0 .. :data:`MAX_TOL_MM`."""
    return real(value, name, "mm", lo=0.0, hi=MAX_TOL_MM,
                what="the largest tolerance accepted")  # fmt: skip


def pulses_per_rev(value: object, name: str = "pulses_per_rev") -> int:
    """A whole number of pulses per revolution in 1 .. :data:`MAX_PULSES_PER_REV`."""
    v = real(value, name, lo=1, hi=MAX_PULSES_PER_REV,
             what="the pulses per revolution the code supports")  # fmt: skip
    if v != int(v):
        raise InvalidValue(f"{name} = {v:g} is not a whole number of pulses", name, value)
    return int(v)


def angle_rad(value: object, name: str) -> float:
    """An angle given in radians through the API: real, finite, ``|v| <=``
    :data:`MAX_ANGLE_RAD` (ten turns)."""
    return real(value, name, "rad", lo=-MAX_ANGLE_RAD, hi=MAX_ANGLE_RAD,
                what="ten turns (angles in degrees are reduced exactly: reduce_deg)")  # fmt: skip


def reduce_deg(deg: npt.ArrayLike) -> npt.NDArray[np.float64] | float:
    """Angles [deg] reduced *exactly* to (-180, 180] (scalars stay scalars).

    ``fmod(x, 360)`` is exact in IEEE 754 (the remainder of two floats is a float), and the
    one shift by 360 that follows is exact too (Sterbenz: both operands within a factor 2).
    So the result is x minus an exact multiple of 360, with no rounding at all.

    >>> reduce_deg(1.0000000000031762e+17)
    16.0
    >>> reduce_deg([540.0, -180.0, 3600.0, -190.0]).tolist()
    [180.0, 180.0, 0.0, 170.0]
    """
    scalar = np.ndim(deg) == 0
    x = np.asarray(deg, dtype=np.float64)
    r = np.fmod(x, 360.0)  # exact, in (-360, 360), sign of x
    r = np.where(r > 180.0, r - 360.0, r)
    r = np.where(r <= -180.0, r + 360.0, r)
    r = r + 0.0  # no -0.0
    return float(r) if scalar else r


def wrap_rad(rad: npt.ArrayLike) -> npt.NDArray[np.float64] | float:
    """Angles [rad] wrapped to (-pi, pi] (the API's waist angle on the base axis).

    ``remainder`` by the float 2 pi is exact for that modulus; 2 pi itself is 2.4e-16 off the
    true value, so an angle of k turns moves by k x 2.4e-16 rad (6e-15 rad at ten turns)."""
    scalar = np.ndim(rad) == 0
    x = np.asarray(rad, dtype=np.float64)
    inside = (x > -math.pi) & (x <= math.pi)  # kept exactly
    r = np.where(inside, x, np.remainder(x, 2 * math.pi))  # else [0, 2 pi)
    r = np.where(r > math.pi, r - 2 * math.pi, r) + 0.0
    return float(r) if scalar else r


def check_inputs(
    arr: npt.NDArray[np.float64],
    units: Sequence[str],
    names: Sequence[str],
    what: str = "target",
) -> None:
    """Range-check the last axis of finite inputs: "mm" columns within :data:`MAX_COORD_MM`
    ("rad" columns: any finite value); the message names the first bad value, its index and
    the limit."""
    limits = np.array([np.inf if u == "rad" else MAX_COORD_MM for u in units])
    if not arr.size:
        return
    bad = ~(np.abs(arr) <= limits)
    if not bad.any():
        return
    idx = tuple(int(i) for i in np.argwhere(bad)[0])
    j = idx[-1]
    where = f" at index {idx[:-1]}" if arr.ndim > 1 else ""
    limit = f"{MAX_COORD_MM:.4g} mm, the largest coordinate the code supports (a PLC REAL)"
    raise InvalidValue(
        f"{what}{where}: {names[j]} = {arr[idx]:g} {units[j]} is beyond +-{limit}", names[j]
    )
