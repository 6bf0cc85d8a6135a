"""VB6 values for the interpreter of the GR-1 thesis's listing (:mod:`analysis.audit.vb6`):
the types, conversions (CStr, CDbl, assignment) and the operators, with the semantics listed
there."""

from __future__ import annotations

import math
import re
import struct
from dataclasses import dataclass
from typing import Any

# --------------------------------------------------------------------------- values

INTEGER, LONG, SINGLE, DOUBLE = "Integer", "Long", "Single", "Double"
STRING, BOOLEAN, EMPTY, VARIANT = "String", "Boolean", "Empty", "Variant"
_NUMERIC_RANK = {BOOLEAN: 0, INTEGER: 1, LONG: 2, SINGLE: 3, DOUBLE: 4}
TYPE_NAMES = {t.casefold(): t for t in (INTEGER, LONG, SINGLE, DOUBLE, STRING, BOOLEAN, VARIANT)}
_INT_RANGE = {INTEGER: (-32768, 32767), LONG: (-2147483648, 2147483647)}
_SINGLE_MAX = 3.4028234663852886e38


class VB6Error(Exception):
    """A VB6 run-time error (``number`` as in VB's ``Err.Number``) with the statement."""

    def __init__(self, number: int, description: str, where: str = "") -> None:
        self.number = number
        self.description = description
        self.where = where
        text = f"run-time error {number}: {description}"
        super().__init__(f"{text} (at {where})" if where else text)


class VB6SyntaxError(ValueError):
    """The source is not in the VB6 subset this module runs (names the line and text)."""


@dataclass(frozen=True, slots=True)
class Value:
    """A VB value: ``type`` (Integer, Long, Single, Double, String, Boolean, Empty), the
    Python value, and whether the expression that produced it is a Variant."""

    type: str
    value: Any
    variant: bool = False

    def as_variant(self) -> Value:
        return Value(self.type, self.value, True)


EMPTY_VALUE = Value(EMPTY, None, True)


def f32(x: float) -> float:
    if abs(x) > _SINGLE_MAX and math.isfinite(x):
        raise VB6Error(6, "Overflow")
    return struct.unpack("<f", struct.pack("<f", x))[0]


def _cstr_number(v: Value) -> str:
    """CStr of a number: 15 significant digits for Double, 7 for Single."""
    if v.type in (INTEGER, LONG):
        return str(v.value)
    if v.type == BOOLEAN:
        return "True" if v.value else "False"
    digits = 7 if v.type == SINGLE else 15
    x = float(v.value)
    if x == 0:
        return "0"
    text = f"{x:.{digits}G}"
    if "E" in text:
        mant, exp = text.split("E")
        if "." in mant:
            mant = mant.rstrip("0").rstrip(".")
        sign = "-" if int(exp) < 0 else "+"
        return f"{mant}E{sign}{abs(int(exp)):02d}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return text


def to_string(v: Value) -> str:
    """CStr: Empty -> "", numbers as VB prints them, Strings unchanged."""
    if v.type == STRING:
        return v.value
    if v.type == EMPTY:
        return ""
    return _cstr_number(v)


_NUMBER_RE = re.compile(r"\s*([+-]?(\d+\.?\d*|\.\d+)([eEdD][+-]?\d+)?)\s*$")


def _str_to_double(s: str) -> float:
    """CDbl of a String (Type mismatch, error 13, if it is not a number)."""
    m = _NUMBER_RE.match(s)
    if not m:
        raise VB6Error(13, f"Type mismatch: {s!r} is not a number")
    return float(m.group(1).replace("d", "e").replace("D", "e"))


def to_number(v: Value) -> Value:
    """The numeric value VB uses in arithmetic: Empty -> Integer 0, String -> Double."""
    if v.type == EMPTY:
        return Value(INTEGER, 0, v.variant)
    if v.type == STRING:
        return Value(DOUBLE, _str_to_double(v.value), v.variant)
    if v.type == BOOLEAN:
        return Value(INTEGER, -1 if v.value else 0, v.variant)
    return v


def coerce(v: Value, vtype: str) -> Value:
    """Convert for assignment to a variable declared ``As vtype`` (Variant keeps ``v``)."""
    if vtype == VARIANT:
        return v.as_variant()
    if vtype == STRING:
        return Value(STRING, to_string(v))
    if vtype == BOOLEAN:
        n = to_number(v)
        return Value(BOOLEAN, n.value != 0)
    n = to_number(v)
    if vtype == DOUBLE:
        return Value(DOUBLE, float(n.value))
    if vtype == SINGLE:
        return Value(SINGLE, f32(float(n.value)))
    lo, hi = _INT_RANGE[vtype]
    x = n.value
    if isinstance(x, float):
        if not math.isfinite(x):
            raise VB6Error(6, "Overflow")
        x = round(x)  # Python's round is round-half-to-even, as VB's CInt/CLng
    if not lo <= x <= hi:
        raise VB6Error(6, f"Overflow: {n.value!r} does not fit in {vtype}")
    return Value(vtype, int(x))


def numeric_result(vtype: str, x: float | int, variant: bool) -> Value:
    """A numeric result of type ``vtype``; a Variant overflow is promoted, a typed one raises."""
    while True:
        if vtype in _INT_RANGE:
            lo, hi = _INT_RANGE[vtype]
            if lo <= x <= hi:
                return Value(vtype, int(x), variant)
            if not variant:
                raise VB6Error(6, f"Overflow: {x} does not fit in {vtype}")
            vtype = LONG if vtype == INTEGER else DOUBLE
            if vtype == DOUBLE:
                x = float(x)
            continue
        if vtype == SINGLE:
            if abs(x) > _SINGLE_MAX and math.isfinite(x):
                if not variant:
                    raise VB6Error(6, "Overflow")
                return Value(DOUBLE, float(x), variant)
            return Value(SINGLE, f32(float(x)), variant)
        if not math.isfinite(x):
            raise VB6Error(6, "Overflow")
        return Value(DOUBLE, float(x), variant)


def _arith_type(a: Value, b: Value) -> str:
    ta, tb = a.type, b.type
    ranks = sorted((_NUMERIC_RANK[ta], _NUMERIC_RANK[tb]))
    if ranks == [_NUMERIC_RANK[LONG], _NUMERIC_RANK[SINGLE]]:
        return DOUBLE
    t = ta if _NUMERIC_RANK[ta] >= _NUMERIC_RANK[tb] else tb
    return INTEGER if t == BOOLEAN else t


def binary(op: str, a: Value, b: Value) -> Value:
    """Apply a VB binary operator to two values (the rules: :mod:`analysis.audit.vb6`)."""
    variant = a.variant or b.variant
    if op == "&":
        return Value(STRING, to_string(a) + to_string(b), variant)
    if op == "+":
        if a.type == EMPTY and b.type == EMPTY:
            return Value(INTEGER, 0, variant)
        if a.type == EMPTY:
            return b
        if b.type == EMPTY:
            return a
        if a.type == STRING and b.type == STRING:
            return Value(STRING, a.value + b.value, variant)
        if (a.type == STRING) != (b.type == STRING) and not (a.variant and b.variant):
            # VB's table for + with one String: typed String + typed number -> Type
            # mismatch; typed String + Variant -> concatenate; String Variant + typed
            # number -> add. Two Variants (one String, one number) -> add.
            s, other = (a, b) if a.type == STRING else (b, a)
            if not s.variant and not other.variant:
                raise VB6Error(13, "Type mismatch: String + number")
            if not s.variant:
                return Value(STRING, to_string(a) + to_string(b), variant)
    if op in ("=", "<>", "<", ">", "<=", ">="):
        return _compare(op, a, b, variant)
    x, y = to_number(a), to_number(b)
    if op == "/":
        if y.value == 0:
            if x.value == 0:
                raise VB6Error(6, "Overflow (0 / 0)")
            raise VB6Error(11, "Division by zero")
        single = {x.type, y.type} <= {INTEGER, SINGLE, BOOLEAN}
        return numeric_result(SINGLE if single else DOUBLE, x.value / y.value, variant)
    if op == "^":
        try:
            r = float(x.value) ** float(y.value)
        except (ZeroDivisionError, OverflowError):
            raise VB6Error(5, "Invalid procedure call or argument") from None
        if isinstance(r, complex):
            raise VB6Error(5, "Invalid procedure call or argument")
        return numeric_result(DOUBLE, r, variant)
    if op in ("\\", "mod"):
        xi = coerce(x, LONG).value
        yi = coerce(y, LONG).value
        if yi == 0:
            raise VB6Error(11, "Division by zero")
        q = abs(xi) // abs(yi) * (1 if (xi >= 0) == (yi >= 0) else -1)
        r = q if op == "\\" else xi - q * yi
        t = LONG if LONG in (x.type, y.type) else INTEGER
        return numeric_result(t, r, variant)
    t = _arith_type(x, y)
    if op == "+":
        r = x.value + y.value
    elif op == "-":
        r = x.value - y.value
    elif op == "*":
        r = x.value * y.value
    else:
        raise VB6SyntaxError(f"operator {op!r} is not in the modelled subset")
    if t in (SINGLE, DOUBLE):
        r = float(r)
    return numeric_result(t, r, variant)


def _compare(op: str, a: Value, b: Value, variant: bool) -> Value:
    if a.type == STRING and b.type == STRING:
        x, y = a.value, b.value
    elif (a.type == STRING) != (b.type == STRING) and a.variant and b.variant:
        # two Variants, one numeric, one String: the number is less than the String
        x, y = (0, 1) if b.type == STRING else (1, 0)
    else:
        x, y = to_number(a).value, to_number(b).value
    r = {
        "=": x == y,
        "<>": x != y,
        "<": x < y,
        ">": x > y,
        "<=": x <= y,
        ">=": x >= y,
    }[op]
    return Value(BOOLEAN, r, variant)


def unary_minus(a: Value) -> Value:
    x = to_number(a)
    t = INTEGER if x.type == BOOLEAN else x.type
    return numeric_result(t, -x.value, a.variant)


def truthy(v: Value) -> bool:
    if v.type == BOOLEAN:
        return bool(v.value)
    return to_number(v).value != 0
