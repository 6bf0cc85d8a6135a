"""The recursive-descent parser of the VB6 subset that :mod:`analysis.audit.vb6` runs."""

from __future__ import annotations

from analysis.audit.vb6.functions import BUILTINS
from analysis.audit.vb6.lexer import Token, tokenize
from analysis.audit.vb6.values import (
    BOOLEAN,
    DOUBLE,
    INTEGER,
    LONG,
    SINGLE,
    STRING,
    TYPE_NAMES,
    Value,
    VB6SyntaxError,
    f32,
)


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
        return Value(SINGLE, f32(float(body)))
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
                if tname.casefold() not in TYPE_NAMES:
                    raise self.error(f"type {tname!r} is not modelled")
                vtype = TYPE_NAMES[tname.casefold()]
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
        if self.accept("kw", "exit"):
            self.expect("kw", "sub")
            self.end_of_statement()
            return ("exit", line)
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
                if tok.text.casefold() not in BUILTINS:
                    raise self.error(f"function {tok.text!r} is not modelled", tok)
                self.next()
                args = [self.expr()]
                while self.accept("op", ","):
                    args.append(self.expr())
                self.expect("op", ")")
                return ("call", tok.text, args)
            return ("name", tok.text)
        raise self.error("expected an expression", tok)
