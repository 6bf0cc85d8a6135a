"""Run the GR-1 thesis's Visual Basic 6 listing as printed, with VB6 semantics.

The thesis (``analysis.papers.gr1_thesis``, appendix "程序清单", pp. 36-46) computes Table 5-4
with the event procedure ``Command1_Click`` and draws the cubic trajectories of section
5.4 with ``Command3_Click``. This module executes that listing, not a cleaned-up copy, so
that every printed number can be traced to the statement that produced it.

Why a small interpreter of our own
----------------------------------
No maintained Python implementation of VB6 exists. The Rust crate ``vb6interpret`` is not
Python; ``vb2py`` (last release 2020) translates VB to Python source but maps every VB
number onto a Python float or int, so it cannot show the effects this audit is about
(``Dim a, b As Single`` declaring only ``b``, float32 rounding of Singles, Integer
division giving Single, Variant String arithmetic). Adding either would also add a
dependency. The listing uses a small subset of the language, so this module implements
exactly that subset (about 40 statements and functions) and refuses anything else with
:class:`VB6SyntaxError`.

Semantics modelled (each has a test in ``tests/audit/test_vb6.py``)
-------------------------------------------------------------------
- ``Dim a, b, c As Single`` declares only ``c`` as Single; ``a`` and ``b`` are Variant
  (Empty until assigned). Undeclared names are implicit local Variants (no
  ``Option Explicit`` in the listing).
- Values carry their VB type: Integer (16 bit), Long (32 bit), Single (IEEE float32),
  Double, String, Boolean, Empty. Assignment to a typed variable converts: Single rounds
  to float32, Integer/Long round half to even and raise error 6 (Overflow) out of range,
  a String that is not numeric raises error 13 (Type mismatch).
- ``+ - *``: the result has the type of the more precise operand (Integer < Long <
  Single < Double), Single with Long gives Double; a Variant result that overflows is
  promoted (Integer -> Long -> Double), a typed one raises error 6. ``/`` gives Double,
  or Single when both operands are Integer/Single, as the VB6 reference's "/ Operator"
  page states (some VBA write-ups report Double for Integer / Integer; in the listing
  only ``Command3_Click``'s ``3 / (c * c)`` and ``2 / (c * c * c)`` are affected, by
  less than 1e-4 deg, and Table 5-4 not at all); ``x/0`` raises error 11, ``0/0``
  error 6. A Variant String in ``-``, ``*``, ``/`` is converted to Double; in ``+`` a
  Variant String and a Variant number are added, two Strings are concatenated.
- ``Sin``, ``Cos``, ``Tan`` take radians, ``Atn`` takes one argument and returns radians
  in (-pi/2, pi/2); ``Sqr`` of a negative number raises error 5; ``Abs``, ``Fix``,
  ``Int`` keep their argument's type; ``Val`` reads the leading number of a string,
  ignoring blanks, and returns Double; ``Format(x, "####.###")`` rounds half away from
  zero after reducing ``x`` to 15 significant digits (VB's Double-to-text conversion) and
  shows nothing for zeros a ``#`` does not need (``0.5`` -> ``".5"``, ``0`` -> ``"."``).
- Controls: ``TextN`` (TextBox, default property ``Text``), ``CommandN`` (CommandButton,
  default property ``Value``, so ``Command3 = False`` sets ``Command3.Value``, not
  ``Enabled``), ``FrameN``, ``PictureN`` (PictureBox; ``Cls``, ``Scale``, ``Line``,
  ``PSet``, ``Print`` and property writes are recorded, nothing is drawn).

Not modelled (the listing does not use them): arrays, user functions, ``Select Case``,
``Do`` loops, ``GoTo``, ``On Error``, Currency, Decimal, Date, Null.

Two switches give counterfactual readings used by the audit (they are not VB6):
``dim_types_all=True`` applies a Dim list's ``As`` type to every name in the list, and
``trig_degrees=True`` makes ``Sin``/``Cos``/``Tan`` read their argument in degrees.

Example (Table 5-3 start and end poses; printed Table 5-4 start theta1 is 56.828)::

    >>> from analysis.audit.vb6 import run_command1
    >>> out = run_command1({"Text1": "151", "Text2": "231", "Text3": "250", "Text4": "32",
    ...                     "Text5": "45", "Text6": "60", "Text7": "200", "Text8": "300",
    ...                     "Text9": "178", "Text10": "20", "Text11": "50", "Text12": "80"})
    >>> out["text"]["Text13"], out["text"]["Text14"]
    ('56.828', '-66.006')
"""

from __future__ import annotations

import math
import re
import struct
from dataclasses import dataclass, field
from decimal import ROUND_HALF_UP, Decimal
from typing import Any, ClassVar

from analysis.papers import gr1_thesis

__all__ = [
    "LISTING_REPAIRS",
    "VB6Error",
    "VB6Form",
    "VB6SyntaxError",
    "Value",
    "listing",
    "run",
    "run_command1",
    "vb_format",
    "vb_val",
]

# --------------------------------------------------------------------------- values

INTEGER, LONG, SINGLE, DOUBLE = "Integer", "Long", "Single", "Double"
STRING, BOOLEAN, EMPTY, VARIANT = "String", "Boolean", "Empty", "Variant"
_NUMERIC_RANK = {BOOLEAN: 0, INTEGER: 1, LONG: 2, SINGLE: 3, DOUBLE: 4}
_TYPE_NAMES = {t.casefold(): t for t in (INTEGER, LONG, SINGLE, DOUBLE, STRING, BOOLEAN, VARIANT)}
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


def _f32(x: float) -> float:
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
        return Value(SINGLE, _f32(float(n.value)))
    lo, hi = _INT_RANGE[vtype]
    x = n.value
    if isinstance(x, float):
        if not math.isfinite(x):
            raise VB6Error(6, "Overflow")
        x = round(x)  # Python's round is round-half-to-even, as VB's CInt/CLng
    if not lo <= x <= hi:
        raise VB6Error(6, f"Overflow: {n.value!r} does not fit in {vtype}")
    return Value(vtype, int(x))


def _result(vtype: str, x: float | int, variant: bool) -> Value:
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
            return Value(SINGLE, _f32(float(x)), variant)
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
    """Apply a VB binary operator to two values (see the module docstring for the rules)."""
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
        return _result(SINGLE if single else DOUBLE, x.value / y.value, variant)
    if op == "^":
        try:
            r = float(x.value) ** float(y.value)
        except (ZeroDivisionError, OverflowError):
            raise VB6Error(5, "Invalid procedure call or argument") from None
        if isinstance(r, complex):
            raise VB6Error(5, "Invalid procedure call or argument")
        return _result(DOUBLE, r, variant)
    if op in ("\\", "mod"):
        xi = coerce(x, LONG).value
        yi = coerce(y, LONG).value
        if yi == 0:
            raise VB6Error(11, "Division by zero")
        q = abs(xi) // abs(yi) * (1 if (xi >= 0) == (yi >= 0) else -1)
        r = q if op == "\\" else xi - q * yi
        t = LONG if LONG in (x.type, y.type) else INTEGER
        return _result(t, r, variant)
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
    return _result(t, r, variant)


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
    return _result(t, -x.value, a.variant)


def truthy(v: Value) -> bool:
    if v.type == BOOLEAN:
        return bool(v.value)
    return to_number(v).value != 0


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


def _builtin(name: str, args: list[Value], trig_degrees: bool) -> Value:
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
            return _result(INTEGER if x.type == BOOLEAN else x.type, r, args[0].variant)
        f = {"abs": abs, "fix": math.trunc, "int": math.floor}[key]
        return _result(x.type, float(f(x.value)), args[0].variant)
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


_BUILTINS = {
    "sin", "cos", "tan", "atn", "exp", "log", "sqr", "abs", "fix", "int", "val", "format",
    "cint", "clng", "csng", "cdbl", "cstr",
}  # fmt: skip
_CONSTANTS = {"vbred": Value(LONG, 255), "vbblack": Value(LONG, 0), "vbblue": Value(LONG, 16711680)}

# --------------------------------------------------------------------------- lexer

_TOKEN_RE = re.compile(
    r"""
    (?P<ws>[ \t]+)
  | (?P<comment>'[^\n]*)
  | (?P<nl>\r?\n)
  | (?P<str>"(?:[^"\n]|"")*")
  | (?P<hex>&[hH][0-9a-fA-F]+&?)
  | (?P<num>(?:\d+\.\d*|\.\d+|\d+)(?:[eE][+-]?\d+)?[!#&%]?)
  | (?P<op><>|<=|>=|[-+*/\\^&=<>(),.:])
  | (?P<name>[^\W\d]\w*)
    """,
    re.VERBOSE,
)
_KEYWORDS = {
    "dim", "as", "private", "public", "sub", "end", "if", "then", "else", "elseif", "for",
    "to", "step", "next", "and", "or", "not", "mod", "true", "false",
}  # fmt: skip


@dataclass(slots=True)
class Token:
    kind: str  # num, str, name, kw, op, nl, eof
    text: str
    line: int


def tokenize(source: str) -> list[Token]:
    """Split VB source into tokens; raises :class:`VB6SyntaxError` on a stray character."""
    tokens: list[Token] = []
    line = 1
    pos = 0
    while pos < len(source):
        m = _TOKEN_RE.match(source, pos)
        if not m:
            raise VB6SyntaxError(f"line {line}: unexpected character {source[pos]!r}")
        kind = m.lastgroup
        text = m.group(0)
        pos = m.end()
        if kind in ("ws", "comment"):
            continue
        if kind == "nl":
            tokens.append(Token("nl", "\n", line))
            line += 1
            continue
        if kind == "name" and text.casefold() in _KEYWORDS:
            kind = "kw"
            text = text.casefold()
        tokens.append(Token(kind, text, line))
    tokens.append(Token("nl", "\n", line))
    tokens.append(Token("eof", "", line))
    return tokens


def _literal(tok: Token) -> Value:
    text = tok.text
    if tok.kind == "str":
        return Value(STRING, text[1:-1].replace('""', '"'))
    if tok.kind == "hex":
        n = int(text[2:].rstrip("&"), 16)
        if text.endswith("&") or n > 0xFFFF:
            return Value(LONG, n - (1 << 32) if n > 0x7FFFFFFF else n)
        return Value(INTEGER, n - (1 << 16) if n > 0x7FFF else n)
    suffix = text[-1] if text[-1] in "!#&%" else ""
    body = text.rstrip("!#&%")
    if suffix == "!":
        return Value(SINGLE, _f32(float(body)))
    if suffix == "#" or "." in body or "e" in body.lower():
        return Value(DOUBLE, float(body))
    n = int(body)
    if suffix == "&" or not -32768 <= n <= 32767:
        return Value(LONG, n) if -(2**31) <= n < 2**31 else Value(DOUBLE, float(n))
    return Value(INTEGER, n)


# --------------------------------------------------------------------------- parser
# Expressions are tuples: ("lit", Value) | ("name", name) | ("prop", obj, prop)
# | ("call", name, [args]) | ("bin", op, a, b) | ("neg", a) | ("not", a)
# Statements are tuples; see Parser.statement.

_BINARY_LEVELS: list = [
    ("or",),
    ("and",),
    "not",
    ("=", "<>", "<", ">", "<=", ">="),
    ("&",),
    ("+", "-"),
    ("mod",),
    ("\\",),
    ("*", "/"),
]
_GRAPHICS = {"cls", "scale", "line", "pset", "print"}


class Parser:
    """Recursive-descent parser for the modelled VB6 subset."""

    def __init__(self, source: str) -> None:
        self.lines = source.splitlines()
        self.toks = tokenize(source)
        self.i = 0

    # -- helpers
    def peek(self, k: int = 0) -> Token:
        return self.toks[min(self.i + k, len(self.toks) - 1)]

    def next(self) -> Token:
        tok = self.toks[self.i]
        self.i += 1
        return tok

    def error(self, msg: str, tok: Token | None = None) -> VB6SyntaxError:
        tok = tok or self.peek()
        text = self.lines[tok.line - 1].strip() if 0 < tok.line <= len(self.lines) else ""
        return VB6SyntaxError(f"line {tok.line}: {msg} (near {tok.text!r}) in: {text[:160]}")

    def accept(self, kind: str, text: str | None = None) -> Token | None:
        tok = self.peek()
        if tok.kind == kind and (text is None or tok.text == text):
            self.i += 1
            return tok
        return None

    def expect(self, kind: str, text: str | None = None) -> Token:
        tok = self.accept(kind, text)
        if tok is None:
            raise self.error(f"expected {text or kind}")
        return tok

    def end_of_statement(self) -> None:
        if self.accept("op", ":"):
            return
        if self.peek().kind in ("nl", "eof"):
            while self.accept("nl"):
                pass
            return
        raise self.error("expected end of statement")

    def skip_newlines(self) -> None:
        while self.accept("nl") or self.accept("op", ":"):
            pass

    # -- module
    def module(self) -> tuple[list, dict]:
        module_dims: list = []
        subs: dict = {}
        self.skip_newlines()
        while self.peek().kind != "eof":
            if self.accept("kw", "dim"):
                module_dims.append(self.dim())
                self.end_of_statement()
            elif self.peek().kind == "kw" and self.peek().text in ("private", "public", "sub"):
                if self.peek().text != "sub":
                    self.next()
                self.expect("kw", "sub")
                name = self.expect("name").text
                self.expect("op", "(")
                self.expect("op", ")")
                self.end_of_statement()
                body = self.block(("end",))
                self.expect("kw", "end")
                self.expect("kw", "sub")
                self.end_of_statement()
                subs[name.casefold()] = (name, body)
            else:
                raise self.error("expected Dim or Sub at module level")
            self.skip_newlines()
        return module_dims, subs

    def dim(self) -> tuple:
        names: list[tuple[str, str | None]] = []
        while True:
            name = self.expect("name").text
            vtype = None
            if self.accept("kw", "as"):
                tname = self.expect("name").text
                if tname.casefold() not in _TYPE_NAMES:
                    raise self.error(f"type {tname!r} is not modelled")
                vtype = _TYPE_NAMES[tname.casefold()]
            names.append((name, vtype))
            if not self.accept("op", ","):
                break
        return ("dim", names)

    def block(self, stops: tuple[str, ...]) -> list:
        body: list = []
        self.skip_newlines()
        while True:
            tok = self.peek()
            if tok.kind == "eof":
                raise self.error("unexpected end of source")
            if tok.kind == "kw" and tok.text in stops:
                if tok.text == "end" and "end" in stops:
                    return body
                return body
            body.append(self.statement())
            self.skip_newlines()

    def statement(self) -> tuple:
        tok = self.peek()
        line = tok.line
        if self.accept("kw", "dim"):
            st = self.dim()
            self.end_of_statement()
            return (*st, line)
        if self.accept("kw", "if"):
            return self.if_statement(line)
        if self.accept("kw", "for"):
            var = self.expect("name").text
            self.expect("op", "=")
            start = self.expr()
            self.expect("kw", "to")
            stop = self.expr()
            step = self.expr() if self.accept("kw", "step") else None
            self.end_of_statement()
            body = self.block(("next",))
            self.expect("kw", "next")
            nvar = self.accept("name")
            if nvar and nvar.text.casefold() != var.casefold():
                raise self.error(f"Next {nvar.text} does not close For {var}", nvar)
            self.end_of_statement()
            return ("for", var, start, stop, step, body, line)
        if tok.kind == "name":
            return self.simple_statement(line)
        raise self.error("statement not in the modelled subset")

    def if_statement(self, line: int) -> tuple:
        cond = self.expr()
        self.expect("kw", "then")
        if self.peek().kind not in ("nl",):  # single-line If
            then = [self.simple_statement(line, single=True)]
            other: list = []
            if self.accept("kw", "else"):
                other = [self.simple_statement(line, single=True)]
            self.end_of_statement()
            return ("if", [(cond, then)], other, line)
        branches = [(cond, self.block(("elseif", "else", "end")))]
        other = []
        while True:
            if self.accept("kw", "elseif"):
                c = self.expr()
                self.expect("kw", "then")
                branches.append((c, self.block(("elseif", "else", "end"))))
                continue
            if self.accept("kw", "else"):
                other = self.block(("end",))
            self.expect("kw", "end")
            self.expect("kw", "if")
            self.end_of_statement()
            return ("if", branches, other, line)

    def simple_statement(self, line: int, single: bool = False) -> tuple:
        name = self.expect("name").text
        prop = None
        if self.accept("op", "."):
            prop = self.expect("name").text
        nxt = self.peek()
        is_assign = nxt.kind == "op" and nxt.text == "="
        if prop is not None and prop.casefold() in _GRAPHICS and not is_assign:
            st = self.graphics(name, prop.casefold(), line)
        else:
            self.expect("op", "=")
            st = ("assign", name, prop, self.expr(), line)
        if not single:
            self.end_of_statement()
        return st

    def point(self) -> tuple:
        self.expect("op", "(")
        x = self.expr()
        self.expect("op", ",")
        y = self.expr()
        self.expect("op", ")")
        return ("point", x, y)

    def graphics(self, obj: str, method: str, line: int) -> tuple:
        args: list = []
        if method in ("scale", "line"):
            args.append(self.point())
            self.expect("op", "-")
            args.append(self.point())
            if self.accept("op", ","):
                args.append(self.expr())
        elif method == "pset":
            args.append(self.point())
            if self.accept("op", ","):
                args.append(self.expr())
        elif method == "print":
            if self.peek().kind not in ("nl", "eof") and not (
                self.peek().kind == "op" and self.peek().text == ":"
            ):
                args.append(self.expr())
        return ("method", obj, method, args, line)

    # -- expressions (lowest precedence first; Not sits between And and the comparisons)
    def expr(self, level: int = 0) -> tuple:
        if level == len(_BINARY_LEVELS):
            return self.unary()
        ops = _BINARY_LEVELS[level]
        if ops == "not":
            if self.accept("kw", "not"):
                return ("not", self.expr(level))
            return self.expr(level + 1)
        left = self.expr(level + 1)
        while True:
            tok = self.peek()
            if tok.kind in ("op", "kw") and tok.text in ops:
                self.next()
                left = ("bin", tok.text, left, self.expr(level + 1))
            else:
                return left

    def unary(self) -> tuple:
        if self.accept("op", "-"):
            return ("neg", self.unary())
        if self.accept("op", "+"):
            return self.unary()
        return self.power()

    def power(self) -> tuple:
        base = self.primary()
        while self.accept("op", "^"):
            exp = self.unary_operand()
            base = ("bin", "^", base, exp)
        return base

    def unary_operand(self) -> tuple:
        if self.accept("op", "-"):
            return ("neg", self.unary_operand())
        return self.primary()

    def primary(self) -> tuple:
        tok = self.next()
        if tok.kind in ("num", "str", "hex"):
            return ("lit", _literal(tok))
        if tok.kind == "kw" and tok.text in ("true", "false"):
            return ("lit", Value(BOOLEAN, tok.text == "true"))
        if tok.kind == "op" and tok.text == "(":
            e = self.expr()
            self.expect("op", ")")
            return e
        if tok.kind == "name":
            if self.accept("op", "."):
                return ("prop", tok.text, self.expect("name").text)
            if self.peek().kind == "op" and self.peek().text == "(":
                if tok.text.casefold() not in _BUILTINS:
                    raise self.error(f"function {tok.text!r} is not modelled", tok)
                self.next()
                args = [self.expr()]
                while self.accept("op", ","):
                    args.append(self.expr())
                self.expect("op", ")")
                return ("call", tok.text, args)
            return ("name", tok.text)
        raise self.error("expected an expression", tok)


# --------------------------------------------------------------------------- runtime


@dataclass
class Control:
    """A form control: its kind, properties and the ordered log of what the code did to it."""

    name: str
    kind: str  # TextBox, CommandButton, PictureBox, Frame
    props: dict[str, Value] = field(default_factory=dict)
    log: list[tuple] = field(default_factory=list)

    _DEFAULT_PROPERTY: ClassVar[dict[str, str]] = {
        "TextBox": "Text",
        "CommandButton": "Value",
        "PictureBox": "Picture",
        "Frame": "Caption",
    }

    @property
    def default_property(self) -> str:
        return self._DEFAULT_PROPERTY[self.kind]


_CONTROL_KINDS = (
    (re.compile(r"text\d+$", re.I), "TextBox", {"Text": Value(STRING, "")}),
    (
        re.compile(r"command\d+$", re.I),
        "CommandButton",
        {"Enabled": Value(BOOLEAN, True), "Value": Value(BOOLEAN, False)},
    ),
    (re.compile(r"picture\d+$", re.I), "PictureBox", {}),
    (re.compile(r"frame\d+$", re.I), "Frame", {"Visible": Value(BOOLEAN, True)}),
)


def _dims(body: list):
    """Every Dim list in a procedure body, nested blocks included."""
    for st in body:
        if st[0] == "dim":
            yield st[1]
        elif st[0] == "if":
            for _cond, block in st[1]:
                yield from _dims(block)
            yield from _dims(st[2])
        elif st[0] == "for":
            yield from _dims(st[5])


class VB6Form:
    """One form of the listing: module variables, controls, and the event procedures.

    ``VB6Form(source)`` parses ``source`` (raising :class:`VB6SyntaxError` naming the line
    if it is not in the modelled subset); :meth:`set_text` fills TextBoxes;
    :meth:`call` runs an event procedure such as ``"Command1_Click"``.
    """

    def __init__(
        self, source: str, *, dim_types_all: bool = False, trig_degrees: bool = False
    ) -> None:
        self.dim_types_all = dim_types_all
        self.trig_degrees = trig_degrees
        module_dims, self.subs = Parser(source).module()
        self.controls: dict[str, Control] = {}
        self.module_vars: dict[str, list] = {}  # key -> [display name, type, Value]
        self.writes: list[tuple[str, str, Any]] = []
        self.last_locals: dict[str, list] = {}
        for st in module_dims:
            self._declare(self.module_vars, st[1])

    # -- declarations and names
    def _declare(self, scope: dict, names: list[tuple[str, str | None]]) -> None:
        last_type = names[-1][1] if names else None
        for name, vtype in names:
            if vtype is None and self.dim_types_all and last_type is not None:
                vtype = last_type
            vtype = vtype or VARIANT
            initial = EMPTY_VALUE if vtype == VARIANT else coerce(Value(INTEGER, 0), vtype)
            if vtype == STRING:
                initial = Value(STRING, "")
            scope[name.casefold()] = [name, vtype, initial]

    def control(self, name: str) -> Control | None:
        key = name.casefold()
        if key in self.controls:
            return self.controls[key]
        for pattern, kind, props in _CONTROL_KINDS:
            if pattern.match(name):
                ctl = Control(name, kind, dict(props))
                self.controls[key] = ctl
                return ctl
        return None

    def set_text(self, values: dict[str, Any]) -> None:
        """Type into TextBoxes: ``{"Text1": "151", ...}`` (non-strings are converted)."""
        for name, text in values.items():
            ctl = self.control(name)
            if ctl is None or ctl.kind != "TextBox":
                raise ValueError(f"{name!r} is not a TextBox name (expected TextN)")
            ctl.props["Text"] = Value(STRING, str(text))

    def text(self) -> dict[str, str]:
        """Every TextBox's current Text, by control name."""
        return {
            c.name: c.props["Text"].value for c in self.controls.values() if c.kind == "TextBox"
        }

    def _lookup(self, locals_: dict, name: str) -> list | None:
        key = name.casefold()
        if key in locals_:
            return locals_[key]
        return self.module_vars.get(key)

    # -- execution
    def call(self, sub: str) -> dict[str, Any]:
        """Run the event procedure ``sub``; return its local variables (name -> Value)."""
        key = sub.casefold()
        if key not in self.subs:
            raise ValueError(f"no procedure {sub!r} in the listing; have {sorted(self.subs)}")
        display, body = self.subs[key]
        locals_: dict[str, list] = {}
        self.last_locals = locals_
        # Dim is not executable in VB: every local exists from procedure entry
        for names in _dims(body):
            self._declare(locals_, names)
        self._exec_block(body, locals_, display)
        return {v[0]: v[2] for v in locals_.values()}

    def _exec_block(self, body: list, locals_: dict, where: str) -> None:
        for st in body:
            try:
                self._exec(st, locals_, where)
            except VB6Error as exc:
                if not exc.where:
                    exc.where = f"{where}, listing line {st[-1]}"
                    exc.args = (f"{exc.args[0]} (at {exc.where})",)
                raise

    def _exec(self, st: tuple, locals_: dict, where: str) -> None:
        kind = st[0]
        if kind == "dim":
            return  # declared at procedure entry (see call)
        if kind == "assign":
            _, name, prop, expr, _line = st
            self._assign(locals_, name, prop, self._eval(expr, locals_))
        elif kind == "if":
            _, branches, other, _line = st
            for cond, body in branches:
                if truthy(self._eval(cond, locals_)):
                    self._exec_block(body, locals_, where)
                    return
            self._exec_block(other, locals_, where)
        elif kind == "for":
            self._for(st, locals_, where)
        elif kind == "method":
            _, obj, method, args, _line = st
            ctl = self.control(obj)
            if ctl is None:
                raise VB6SyntaxError(f"{obj}.{method}: {obj!r} is not a control")
            vals = [
                (self._eval(a[1], locals_).value, self._eval(a[2], locals_).value)
                if a[0] == "point"
                else self._eval(a, locals_).value
                for a in args
            ]
            ctl.log.append((method, *vals))
        else:  # pragma: no cover - the parser produces no other kinds
            raise VB6SyntaxError(f"statement kind {kind!r}")

    def _for(self, st: tuple, locals_: dict, where: str) -> None:
        _, var, start_e, stop_e, step_e, body, _line = st
        start = self._eval(start_e, locals_)
        stop = to_number(self._eval(stop_e, locals_))
        step = to_number(self._eval(step_e, locals_)) if step_e else Value(INTEGER, 1)
        self._assign(locals_, var, None, start)
        while True:
            cur = to_number(self._get(locals_, var))
            if (step.value >= 0 and cur.value > stop.value) or (
                step.value < 0 and cur.value < stop.value
            ):
                return
            self._exec_block(body, locals_, where)
            slot = self._lookup(locals_, var)
            self._assign(locals_, var, None, binary("+", slot[2], step))

    def _get(self, locals_: dict, name: str) -> Value:
        slot = self._lookup(locals_, name)
        if slot is not None:
            v = slot[2]
            return v if slot[1] == VARIANT else Value(v.type, v.value, False)
        if name.casefold() in _CONSTANTS:
            return _CONSTANTS[name.casefold()]
        ctl = self.control(name)
        if ctl is not None:
            return ctl.props.get(ctl.default_property, EMPTY_VALUE)
        # implicit declaration: a new local Variant (Empty)
        locals_[name.casefold()] = [name, VARIANT, EMPTY_VALUE]
        return EMPTY_VALUE

    def _assign(self, locals_: dict, name: str, prop: str | None, value: Value) -> None:
        if prop is None:
            slot = self._lookup(locals_, name)
            if slot is None and self.control(name) is not None:
                ctl = self.control(name)
                prop = ctl.default_property
            else:
                if slot is None:
                    slot = [name, VARIANT, EMPTY_VALUE]
                    locals_[name.casefold()] = slot
                slot[2] = coerce(value, slot[1])
                return
        ctl = self.control(name)
        if ctl is None:
            raise VB6SyntaxError(f"{name}.{prop} = ...: {name!r} is not a control")
        canonical = {"text": "Text", "enabled": "Enabled", "value": "Value", "visible": "Visible"}
        pname = canonical.get(prop.casefold(), prop)
        if pname == "Text":
            stored = Value(STRING, to_string(value))
        elif pname in ("Enabled", "Value", "Visible"):
            stored = Value(BOOLEAN, truthy(value))
        else:
            stored = value
        ctl.props[pname] = stored
        ctl.log.append(("set", pname, stored.value))
        self.writes.append((ctl.name, pname, stored.value))
        if ctl.kind == "CommandButton" and pname == "Value" and stored.value:
            click = f"{ctl.name}_Click".casefold()
            if click in self.subs:  # VB: setting Value to True fires Click
                self.call(click)

    def _eval(self, e: tuple, locals_: dict) -> Value:
        kind = e[0]
        if kind == "lit":
            return e[1]
        if kind == "name":
            return self._get(locals_, e[1])
        if kind == "bin":
            a = self._eval(e[2], locals_)
            b = self._eval(e[3], locals_)
            op = e[1]
            if op in ("and", "or"):
                x = coerce(a, LONG).value
                y = coerce(b, LONG).value
                r = (x & y) if op == "and" else (x | y)
                if a.type == BOOLEAN and b.type == BOOLEAN:
                    return Value(BOOLEAN, r != 0, a.variant or b.variant)
                return _result(LONG, r, a.variant or b.variant)
            return binary(op, a, b)
        if kind == "neg":
            return unary_minus(self._eval(e[1], locals_))
        if kind == "not":
            v = self._eval(e[1], locals_)
            if v.type == BOOLEAN:
                return Value(BOOLEAN, not v.value, v.variant)
            return _result(LONG, ~coerce(v, LONG).value, v.variant)
        if kind == "call":
            args = [self._eval(a, locals_) for a in e[2]]
            return _builtin(e[1], args, self.trig_degrees)
        if kind == "prop":
            ctl = self.control(e[1])
            if ctl is None:
                raise VB6SyntaxError(f"{e[1]}.{e[2]}: {e[1]!r} is not a control")
            pname = {"text": "Text", "enabled": "Enabled", "value": "Value"}.get(
                e[2].casefold(), e[2]
            )
            return ctl.props.get(pname, EMPTY_VALUE)
        raise VB6SyntaxError(f"expression kind {kind!r}")  # pragma: no cover


# --------------------------------------------------------------------------- the listing

LISTING_REPAIRS: list[dict[str, str]] = [
    {
        "location": "appendix 程序清单 p. 37, Command1_Click, the cf3 statement",
        "printed": "Py1 * Sin(θf1) Cos(θf234) * a4",
        "repaired": "Py1 * Sin(θf1) - Cos(θf234) * a4",
        "why": (
            "as printed the statement is a VB6 syntax error (two operands with no operator), "
            "so the form would not compile; the same statement for the start pose (c3) has "
            "'- Cos(θ234) * a4' at this place, and with '-' the listing reproduces the printed "
            "Table 5-4 end-pose theta3 = -45.244 (tests/audit/test_vb6.py)"
        ),
    }
]
"""The one edit needed to run the printed listing; everything else runs as printed."""


def listing(*, repaired: bool = True) -> str:
    """The thesis's VB6 listing (``gr1_thesis.LISTING``), with :data:`LISTING_REPAIRS`
    applied when ``repaired`` (the default; as printed it does not compile)."""
    src = gr1_thesis.LISTING
    if repaired:
        for rep in LISTING_REPAIRS:
            if src.count(rep["printed"]) != 1:
                raise ValueError(f"repair target {rep['printed']!r} not found exactly once")
            src = src.replace(rep["printed"], rep["repaired"])
    return src


def run(
    source: str,
    sub: str,
    inputs: dict[str, Any] | None = None,
    *,
    form: VB6Form | None = None,
    **options: bool,
) -> dict[str, Any]:
    """Run event procedure ``sub`` of ``source`` after typing ``inputs`` into TextBoxes.

    Returns ``{"locals", "module", "text", "writes", "controls", "form"}``: the
    procedure's local variables and the module variables as ``{name: Value}``, every
    TextBox's Text, the ordered property writes ``(control, property, value)``, each
    control's properties and log, and the :class:`VB6Form` (pass it back as ``form`` to
    run another procedure on the same state, e.g. ``Command3_Click`` after
    ``Command1_Click``). ``options`` are :class:`VB6Form`'s switches.
    """
    form = form or VB6Form(source, **options)
    n_writes = len(form.writes)
    form.set_text(inputs or {})
    locals_ = form.call(sub)
    return {
        "locals": locals_,
        "module": {v[0]: v[2] for v in form.module_vars.values()},
        "text": form.text(),
        "writes": form.writes[n_writes:],
        "controls": {
            c.name: {"props": dict(c.props), "log": c.log} for c in form.controls.values()
        },
        "form": form,
    }


def run_command1(inputs: dict[str, Any], **options: bool) -> dict[str, Any]:
    """Run ``Command1_Click`` (the "计算" button) of the repaired listing on ``inputs``.

    ``inputs`` maps ``Text1`` ... ``Text12`` (start px, py, pz, alpha, beta, gamma, then the
    end pose, the order of Table 5-3) to what is typed. Returns :func:`run`'s dict.
    """
    return run(listing(), "Command1_Click", inputs, **options)
