"""The VB6 built-in functions and constants the GR-1 thesis's listing calls (``Sin`` ...
``Format``), for the interpreter of :mod:`analysis.audit.vb6`."""

from __future__ import annotations

import math
import re
from decimal import ROUND_HALF_UP, Decimal

from analysis.audit.vb6.values import (
    BOOLEAN,
    DOUBLE,
    INTEGER,
    LONG,
    SINGLE,
    STRING,
    Value,
    VB6Error,
    VB6SyntaxError,
    coerce,
    numeric_result,
    to_number,
    to_string,
)

# --------------------------------------------------------------------------- built-ins


def vb_val(text: str) -> float:
    """VB's ``Val``: the leading number of ``text``, blanks ignored anywhere, else 0.

    ``Val("  12.5abc") == 12.5``, ``Val("1 2") == 12.0``, ``Val("") == 0.0``.
    """
    s = "".join(ch for ch in text if ch not in " \t\r\n")
    m = re.match(r"[+-]?(\d+\.?\d*|\.\d+)([eEdD][+-]?\d+)?", s)
    if not m:
        hx = re.match(r"&[hH]([0-9a-fA-F]+)", s)
        return float(int(hx.group(1), 16)) if hx else 0.0
    return float(m.group(0).replace("d", "e").replace("D", "e"))


def vb_format(x: float, fmt: str) -> str:
    """VB's ``Format`` for a number and a ``#``/``0``/``.`` style such as ``"####.###"``.

    Rounds half away from zero after reducing ``x`` to 15 significant digits; ``#``
    shows no leading or trailing zeros, ``0`` does. ``vb_format(56.3099, "####.###")``
    is ``"56.31"``, ``vb_format(0.5, "####.###")`` is ``".5"``, ``vb_format(0, "#.#")``
    is ``"."``.
    """
    if not re.fullmatch(r"[#0]*(\.[#0]*)?", fmt) or not fmt:
        raise ValueError(f"format {fmt!r} is outside the modelled subset (#, 0, one '.')")
    int_part, _, frac_part = fmt.partition(".")
    has_point = "." in fmt
    n_frac = len(frac_part)
    d = Decimal(f"{x:.15G}") if x != 0 else Decimal(0)
    q = d.quantize(Decimal(1).scaleb(-n_frac), rounding=ROUND_HALF_UP)
    negative = q < 0 or (q == 0 and x < 0)
    digits = f"{abs(q):f}"
    whole, _, frac = digits.partition(".")
    frac = frac.ljust(n_frac, "0")[:n_frac]
    min_int = int_part.count("0")
    whole = whole.lstrip("0")
    whole = whole.rjust(min_int, "0")
    min_frac = len(frac_part.rstrip("#")) if frac_part.startswith("0") else frac_part.count("0")
    frac = frac.rstrip("0")
    frac = frac.ljust(min_frac, "0")
    text = whole + ("." + frac if has_point else "")
    return ("-" if negative else "") + text


def _one_number(name: str, args: list[Value]) -> Value:
    if len(args) != 1:
        raise VB6SyntaxError(f"{name} takes one argument, got {len(args)}")
    return to_number(args[0])


def call_builtin(name: str, args: list[Value], trig_degrees: bool) -> Value:
    """Evaluate a built-in function; results are typed Double except where VB differs."""
    key = name.casefold()
    if key in ("sin", "cos", "tan", "atn", "exp"):
        x = float(_one_number(name, args).value)
        if key in ("sin", "cos", "tan") and trig_degrees:
            x = x * math.pi / 180
        return Value(DOUBLE, getattr(math, {"atn": "atan"}.get(key, key))(x))
    if key in ("sqr", "log"):
        x = _one_number(name, args).value
        if x < 0 or (key == "log" and x == 0):
            raise VB6Error(5, f"Invalid procedure call or argument: {name}({x})")
        return Value(DOUBLE, math.sqrt(x) if key == "sqr" else math.log(x))
    if key in ("abs", "fix", "int"):
        # the result has the argument's type (a Variant argument gives a Variant)
        x = _one_number(name, args)
        if x.type in (INTEGER, LONG, BOOLEAN):
            r = abs(x.value) if key == "abs" else x.value
            return numeric_result(INTEGER if x.type == BOOLEAN else x.type, r, args[0].variant)
        f = {"abs": abs, "fix": math.trunc, "int": math.floor}[key]
        return numeric_result(x.type, float(f(x.value)), args[0].variant)
    if key == "val":
        if len(args) != 1:
            raise VB6SyntaxError("Val takes one argument")
        return Value(DOUBLE, vb_val(to_string(args[0])))
    if key == "format":  # Format returns a Variant (String)
        if len(args) == 1:
            return Value(STRING, to_string(args[0]), True)
        if len(args) != 2 or args[1].type != STRING:
            raise VB6SyntaxError("Format(x, style) with a string style is the modelled form")
        x = to_number(args[0])
        return Value(STRING, vb_format(float(x.value), args[1].value), True)
    conv = {"cint": INTEGER, "clng": LONG, "csng": SINGLE, "cdbl": DOUBLE, "cstr": STRING}
    if key in conv:
        if len(args) != 1:
            raise VB6SyntaxError(f"{name} takes one argument")
        c = coerce(args[0], conv[key])
        return Value(c.type, c.value)
    raise VB6SyntaxError(f"function {name!r} is not in the modelled subset")


BUILTINS = {
    "sin", "cos", "tan", "atn", "exp", "log", "sqr", "abs", "fix", "int", "val", "format",
    "cint", "clng", "csng", "cdbl", "cstr",
}  # fmt: skip
CONSTANTS = {"vbred": Value(LONG, 255), "vbblack": Value(LONG, 0), "vbblue": Value(LONG, 16711680)}
