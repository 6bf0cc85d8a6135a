"""The addresses and values of ``stl-run --set/--read`` on the S7 dialects (:mod:`.cli_plc`,
whose module docstring gives the rules): an address's kind and type, a value typed by its
address, its form or its suffix, within the type's range (:mod:`analysis.validate`'s number
rule)."""

from __future__ import annotations

import re

from analysis import validate

__all__ = ["FLT_MAX", "TYPES", "parse_read", "parse_set"]

TYPES = ("BOOL", "BYTE", "INT", "WORD", "DINT", "DWORD", "REAL")
_S7200_AREAS = "SM|V|M|I|Q|S"
_S7300_AREAS = "M|I|Q"
_LIMITS = {
    "BYTE": (0, 255),
    "INT": (-32768, 32767),
    "WORD": (0, 65535),
    "DINT": (-(2**31), 2**31 - 1),
    "DWORD": (0, 2**32 - 1),
}
FLT_MAX = 3.4028234663852886e38


def _address_kind(addr: str, dialect: str) -> str:
    """The width an address names: X (bit), B, W, D or AC (an accumulator)."""
    areas = _S7200_AREAS if dialect == "s7-200" else _S7300_AREAS
    a = addr.upper()
    if dialect == "s7-200" and re.fullmatch(r"AC[0-3]", a):
        return "AC"
    if re.fullmatch(rf"({areas})\d+\.[0-7]", a):
        return "X"
    m = re.fullmatch(rf"({areas})([BWD])\d+", a)
    if m:
        return m.group(2)
    example = "VD0, VW2, VB4, V112.0, AC1" if dialect == "s7-200" else "MD0, MW2, MB4, M112.0"
    raise ValueError(f"{addr!r} is not an {dialect} address (e.g. {example})")


_TYPES_OF = {
    "X": ("BOOL",),
    "B": ("BYTE",),
    "W": ("INT", "WORD"),
    "D": ("DINT", "DWORD", "REAL"),
    "AC": ("BYTE", "INT", "WORD", "DINT", "DWORD", "REAL"),
}


def parse_read(text: str, dialect: str) -> tuple[str, str]:
    """``"VD100:DINT"`` -> ("VD100", "DINT"); ValueError naming the problem."""
    addr, sep, typ = text.partition(":")
    if not sep or not typ:
        raise ValueError(f"--read {text!r}: expected ADDRESS:TYPE (e.g. VD100:DINT, V112.0:BOOL)")
    typ = typ.strip().upper()
    if typ not in TYPES:
        raise ValueError(f"--read {text!r}: type {typ} is not one of {', '.join(TYPES)}")
    kind = _address_kind(addr.strip(), dialect)
    if typ not in _TYPES_OF[kind]:
        raise ValueError(
            f"--read {text!r}: a {_WORD[kind]} holds {' or '.join(_TYPES_OF[kind])}, not {typ}"
        )
    return addr.strip().upper(), typ


_WORD = {"X": "bit", "B": "byte", "W": "word", "D": "double word", "AC": "accumulator"}


def parse_set(text: str, dialect: str) -> tuple[str, str, object, bool]:
    """``"VD0=100.0"`` -> (address, type, value, explicit type?); ValueError naming the
    value and the limit."""
    addr, sep, value = text.partition("=")
    if not sep or not addr.strip():
        raise ValueError(f"--set {text!r}: expected ADDRESS=VALUE (e.g. VD0=100.0)")
    if not value.strip():
        raise ValueError(f"--set {text!r}: the value is empty; a number is required")
    # only ASCII blanks around the value: a no-break space is not one (analysis.validate)
    addr, value = addr.strip().upper(), value.strip(" \t")
    kind = _address_kind(addr, dialect)
    typ = None
    m = re.fullmatch(r"(.*?):([A-Za-z]+)", value)
    if m:
        value, typ = m.group(1).strip(), m.group(2).upper()
        if typ not in TYPES:
            raise ValueError(f"--set {text!r}: type {typ} is not one of {', '.join(TYPES)}")
        if typ not in _TYPES_OF[kind]:
            raise ValueError(
                f"--set {text!r}: a {_WORD[kind]} holds {' or '.join(_TYPES_OF[kind])}, not {typ}"
            )
    explicit = typ is not None
    is_int = re.fullmatch(r"[+-]?[0-9]+", value) is not None  # ASCII digits (validate's rule)
    if typ is None:
        if kind == "X":
            typ = "BOOL"
        elif kind == "B":
            typ = "BYTE"
        elif kind == "W":
            typ = "INT"
        else:
            typ = "DINT" if is_int else "REAL"
    if typ == "BOOL":
        v = {"0": False, "1": True, "false": False, "true": True}.get(value.lower())
        if v is None:
            raise ValueError(f"--set {text!r}: a BOOL is 0, 1, true or false")
        return addr, typ, v, explicit
    if typ == "REAL":
        if value.lower().lstrip("+-") in ("nan", "inf", "infinity"):
            # a NaN or inf only on purpose (to see what the program does with one): typed
            if not explicit:
                raise ValueError(
                    f"--set {text!r}: {value!r} is not a finite number; to store a REAL "
                    f"{value} on purpose write {addr}={value}:REAL"
                )
            return addr, typ, float(value), explicit
        problem = validate.number_problem(value)  # one rule for every number a user types
        if problem:
            raise ValueError(f"--set {text!r}: {problem}")
        x = float(value)
        if abs(x) > FLT_MAX:
            raise ValueError(
                f"--set {text!r}: {value} is beyond {FLT_MAX:.4g}, the largest REAL "
                "(|x| <= 3.402823E+38)"
            )
        return addr, typ, x, explicit
    if not is_int:
        problem = validate.number_problem(value)
        why = problem if problem else f"a {typ} is a whole number, not {value!r}"
        raise ValueError(f"--set {text!r}: {why}")
    v = int(value)
    lo, hi = _LIMITS[typ]
    if not lo <= v <= hi:
        raise ValueError(f"--set {text!r}: {v} is outside the {typ} range {lo}..{hi}")
    return addr, typ, v, explicit
