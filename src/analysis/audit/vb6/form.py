"""The run-time of :mod:`analysis.audit.vb6`: a form's controls, variables and event procedures,
executed statement by statement."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any, ClassVar

from analysis.audit.vb6.functions import CONSTANTS, call_builtin
from analysis.audit.vb6.parser import Parser
from analysis.audit.vb6.values import (
    BOOLEAN,
    DOUBLE,
    EMPTY_VALUE,
    INTEGER,
    LONG,
    STRING,
    VARIANT,
    Value,
    VB6Error,
    VB6SyntaxError,
    binary,
    coerce,
    numeric_result,
    to_number,
    to_string,
    truthy,
    unary_minus,
)

# --------------------------------------------------------------------------- runtime


class _ExitSub(Exception):
    """``Exit Sub``: leaves the procedure (caught by :meth:`VB6Form.call`)."""


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


@lru_cache(maxsize=512)
def _parse(source: str) -> tuple[list, dict]:
    """The parsed module (the statements are never changed by running them: shared)."""
    return Parser(source).module()


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
        module_dims, subs = _parse(source)
        self.subs = dict(subs)
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
    def call(self, sub: str, preset: dict[str, float] | None = None) -> dict[str, Any]:
        """Run the event procedure ``sub``; return its local variables (name -> Value).
        ``preset``: locals declared Double with these values on entry (what a statement
        under test reads, without parsing a Dim and an assignment for each)."""
        key = sub.casefold()
        if key not in self.subs:
            raise ValueError(f"no procedure {sub!r} in the listing; have {sorted(self.subs)}")
        display, body = self.subs[key]
        locals_: dict[str, list] = {}
        self.last_locals = locals_
        # Dim is not executable in VB: every local exists from procedure entry
        for names in _dims(body):
            self._declare(locals_, names)
        for name, v in (preset or {}).items():
            locals_[name.casefold()] = [name, DOUBLE, Value(DOUBLE, float(v))]
        try:
            self._exec_block(body, locals_, display)
        except _ExitSub:
            pass
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
        if kind == "exit":
            raise _ExitSub
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
        if name.casefold() in CONSTANTS:
            return CONSTANTS[name.casefold()]
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
                return numeric_result(LONG, r, a.variant or b.variant)
            return binary(op, a, b)
        if kind == "neg":
            return unary_minus(self._eval(e[1], locals_))
        if kind == "not":
            v = self._eval(e[1], locals_)
            if v.type == BOOLEAN:
                return Value(BOOLEAN, not v.value, v.variant)
            return numeric_result(LONG, ~coerce(v, LONG).value, v.variant)
        if kind == "call":
            args = [self._eval(a, locals_) for a in e[2]]
            return call_builtin(e[1], args, self.trig_degrees)
        if kind == "prop":
            ctl = self.control(e[1])
            if ctl is None:
                raise VB6SyntaxError(f"{e[1]}.{e[2]}: {e[1]!r} is not a control")
            pname = {"text": "Text", "enabled": "Enabled", "value": "Value"}.get(
                e[2].casefold(), e[2]
            )
            return ctl.props.get(pname, EMPTY_VALUE)
        raise VB6SyntaxError(f"expression kind {kind!r}")  # pragma: no cover
