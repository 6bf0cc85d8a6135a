"""Listings executed: ``stl`` (S7-200 STL on :mod:`analysis.plc.stl_eval`, byte-accurate
float32) and ``vb6`` (Visual Basic 6 statements on :mod:`analysis.audit.vb6`), each against
expected outputs computed apart (the arm, the pulse rule).

``stl``: the text is an STL fragment (instructions on lines or separated by ';'). For every
sample of ``spec["domain"]`` the fragment runs on a V-memory image holding ``inputs``
(address -> expression of the domain's symbols, as REALs) and each address of ``expect``
(address -> expression) must read back its value: as a DINT exactly (``read = {addr = "dint"}``)
or as a REAL within ``tol`` (default 1e-4 relative: a few float32 ulps over a handful of
operations). ``wrong`` counts the samples (rows) at which any address reads wrong, ``n`` the
samples: both in rows. ``enter``: the instructions that precede a fragment in its network (``LD
SM0.0; LPS``: the logic stack it is printed inside), run before it, so that a fragment that pops
the stack (``LPP``) runs its next instruction as the whole network would. ``CALL ARCTAN, IN,
OUT`` / ``CALL ARCCOS`` are Siemens' library routines (radians, as the evaluator has them);
``CALL ATAN2, Y, X, OUT`` is the generated program's subroutine of that name
(:mod:`analysis.plc`: float32 atan2). ``mode = "order"``: the text is a network order
(``3, 4, 6, 5``, a permutation of the figures) and ``address`` must be written by an earlier
network before network ``reader`` reads it.

``vb6``: the text is one VB6 statement or several (':' or newlines, If blocks, ``Exit Sub``);
it runs with the variables the listing holds for the configuration ``config`` (and ``end``) of
the paper's ``vb6_env`` value (positions in mm, angles in degrees as the listing has them), the
variable it assigns last left unset, Sin/Cos reading degrees when ``trig = "degrees"`` (which
isolates every other defect from the unit one). The value it assigns must be ``expect``
within ``tol`` (modulo 360 unless ``angle = false``): a variable of the configuration
(``"θ2"``, the truth), ``{meant = "@ref"}`` the printed statement read with Sin/Cos in degrees,
or ``{atan2 = "@ref"}`` the angle of the printed ``Atn(y / x)``'s y and x. ``edges``: further
presets (``{Px0 = 0.0, Py0 = 50.0}``) and ``configs`` further configurations at which it
must hold too, without a run-time error (at an origin of atan2 any value passes);
``refuses``: presets (an unreachable ``c3 = 1.5``) at which it must stop without a run-time
error, assign nothing and grey the trajectory button (``Command3.Enabled = False``).
``mode = "controls"``: the text is a block deciding a button (``Command3``; in place of the
printed ``line`` of record ``within`` when given), run for each of ``cases`` (``set``: the
variables) with the button enabled and pressed before; the button must end ``enabled`` as
given, or the block must ``fire`` (Enabled or Value off) as given.
"""

from __future__ import annotations

import math
import re
from functools import cache

import numpy as np

from analysis.audit.kinds.base import Result, kind
from analysis.papers import FUNCTIONS
from analysis.validate import reduce_deg

__all__ = ["assigned", "atn_operands", "instructions", "run_statement", "stl_run"]


def instructions(text: str):
    from analysis.plc import stl_eval as stl

    code = "\n".join(ln.split("//")[0] for ln in text.splitlines())
    return stl.parse_stl(code.replace(";", "\n"))


def stl_run(text: str, memory, *, ftz: bool = False):
    """Run a fragment on ``memory`` (a :class:`analysis.plc.stl_eval.VMemory`); ``CALL ATAN2``
    lines are the generated program's atan2 (float32), the rest the evaluator's."""
    from analysis.plc import stl_eval as stl

    mem = memory
    block: list = []
    for ins in [*instructions(text), None]:
        if ins is None or ins.op == "CALL ATAN2":
            mem = stl.evaluate(block, mem, ftz=ftz) if block else mem
            block = []
            if ins is not None:
                y, x, out = ins.args
                val = np.arctan2(np.float32(mem.real(y)), np.float32(mem.real(x)))
                mem.set_real(out, np.float32(val))
        else:
            block.append(ins)
    return mem


def _order(text: str, spec, ctx) -> Result:
    from analysis.plc import stl_eval as stl

    m = re.fullmatch(r"network order (\d+(?:, \d+)*)", text.strip())
    order = [int(v) for v in m[1].split(", ")] if m else []
    figures = sorted(int(k[6:]) for k in ctx.paper.records if k.startswith("figure"))
    if sorted(order) != figures:
        return Result(False, {"why": f"not a permutation of figures {figures}"})
    written: set[str] = set()
    for f in order:
        for ins in stl.parse_stl(ctx.paper.text(f"figure{f}")):
            w, r = stl.defs_uses(ins)
            if f == spec["reader"] and spec["address"] in r and spec["address"] not in written:
                return Result(False, {"read_before_write": f"Figure {f}"})
            written |= w
    return Result(True, {})


@cache
def _expected_fn(expr: str):
    """An expected value as a function of named values: the sample's symbols and V-memory
    double words (``VD72*VD92``: the REALs the run left there)."""
    import sympy as sp

    from analysis.papers import parse

    names = sorted(set(re.findall(r"[A-Za-z_]\w*", expr)) - set(FUNCTIONS))
    e = parse(expr, {k: sp.Symbol(k) for k in names})
    args = sorted(str(x) for x in e.free_symbols)
    return args, sp.lambdify(args, e, "math")


def _expected(expr: str, point, mem) -> float:
    args, fn = _expected_fn(expr)
    return float(fn(*(float(mem.real(a)) if re.fullmatch(r"VD\d+", a) else point[a] for a in args)))


@kind("stl")
def stl(text: str, spec, ctx) -> Result:
    from analysis.plc import stl_eval as stl

    if spec.get("mode") == "order":
        return _order(text, spec, ctx)
    values = ctx.domain(spec["domain"])
    n = len(next(iter(v for v in values.values() if np.ndim(v))))
    ins = {a: [_expected(e, {k: (v[i] if np.ndim(v) else v) for k, v in values.items()}, None)
               for i in range(n)] for a, e in spec.get("inputs", {}).items()}  # fmt: skip
    prefix = ctx.paper.text(spec["within"]) + "\n" if "within" in spec else ""
    prefix += spec["enter"].replace(";", "\n") + "\n" if "enter" in spec else ""
    out = instructions(text)[-1].args[-1]  # "@out": what the text's last instruction writes
    expect = {(out if a == "@out" else a): e for a, e in spec["expect"].items()}
    read = spec.get("read", {})
    got: dict[str, list] = {a: [] for a in expect}
    want: dict[str, list] = {a: [] for a in expect}
    for i in range(n):
        mem = stl.real_memory(**{a: float(v[i]) for a, v in ins.items()})
        mem = stl_run(prefix + text, mem, ftz=spec.get("ftz", False))
        point = {k: (v[i] if np.ndim(v) else v) for k, v in values.items()}
        for a, e in expect.items():
            got[a].append(mem.dint(a) if read.get(a) == "dint" else float(mem.real(a)))
            want[a].append(_expected(e, point, mem))
    wrong: set[int] = set()
    for a, w in want.items():
        g, w = np.asarray(got[a], dtype=float), np.asarray(w, dtype=float)
        if read.get(a) == "dint":
            bad = g != np.round(w)
        else:
            bad = ~(np.abs(g - w) <= spec.get("tol", 1e-4) * np.maximum(1.0, np.abs(w)))
        wrong |= {int(i) for i in np.flatnonzero(bad)}
    first = {a: got[a][0] for a in want}
    return Result(not wrong, {"n": n, "wrong": len(wrong), "first": first,
                              "want": {a: float(want[a][0]) for a in want}})  # fmt: skip


_ASSIGN = re.compile(r"^\s*([^\W\d][\w]*)\s*=(?!=)")


def assigned(text: str) -> str:
    """The variable a VB6 text assigns last (statements on lines or joined by ':')."""
    names = [m[1] for part in re.split(r"[:\n]", text) if (m := _ASSIGN.match(part))]
    if not names:
        raise ValueError(f"{text!r} assigns no variable")
    return names[-1]


def run_statement(text: str, env: dict[str, float], *, trig_degrees: bool = False,
                  target: str | None = None):
    """Run VB6 ``text`` with ``env`` preset as Double locals (``Command3.Enabled`` True
    before it); ``(value assigned to target or None, the form)``. Raises the interpreter's
    VB6SyntaxError / VB6Error (a run-time error)."""
    from analysis.audit import vb6

    target = target or assigned(text)
    src = "\n".join(["Private Sub T_Click()", "Command3.Enabled = True", text, "End Sub", ""])
    form = vb6.VB6Form(src, trig_degrees=trig_degrees)
    out = {k.casefold(): v for k, v in form.call("T_Click", env).items()}
    value = out.get(target.casefold())
    if value is None or value.type == vb6.EMPTY:
        return None, form
    return float(vb6.to_number(value).value), form


def atn_operands(statement: str) -> tuple[str, str]:
    """The y and x of the ``Atn(y / x)`` in a statement (the top-level '/' inside Atn)."""
    start = statement.index("Atn(") + 4
    depth, i = 1, start
    while depth:
        depth += {"(": 1, ")": -1}.get(statement[i], 0)
        i += 1
    inner, depth = statement[start : i - 1], 0
    for k, ch in enumerate(inner):
        depth += {"(": 1, ")": -1}.get(ch, 0)
        if ch == "/" and depth == 0:
            return inner[:k].strip(), inner[k + 1 :].strip()
    raise ValueError(f"no top-level '/' in the Atn of {statement!r}")


def _want(expect, env, target: str, degrees: bool, ctx) -> float:
    """The value a statement must assign: a variable the configuration knows (``"θ2"``), the
    printed statement read with Sin/Cos in degrees (``{meant = "@ref"}``), or the angle
    atan2(y, x) of the printed ``Atn(y / x)`` (``{atan2 = "@ref"}``, in the listing's
    degrees 180 / PI)."""
    if isinstance(expect, str):
        return env[expect]
    ref = expect.get("meant") or expect.get("atan2")
    printed = ctx.paper.text(ref[1:]).split("//")[0].strip()
    if "meant" in expect:
        return run_statement(printed, env, trig_degrees=True, target=target)[0]
    y, x = atn_operands(printed)
    yv = run_statement(f"Yv = {y}", env, trig_degrees=degrees)[0]
    xv = run_statement(f"Xv = {x}", env, trig_degrees=degrees)[0]
    if yv == 0 and xv == 0:
        return math.nan  # the origin: every angle is a solution (any finite value passes)
    return math.atan2(yv, xv) * 180 / env["PI"]


def _controls(text: str, spec, ctx) -> Result:
    from analysis.audit import vb6

    if "line" in spec:
        printed = ctx.paper.text(spec["within"])
        if f"\n{spec['line']}\n" not in printed:
            raise ValueError(f"{spec['line']!r} is not a line of {spec['within']}")
        text = printed.replace(f"\n{spec['line']}\n", f"\n{text.strip()}\n")
    src = f"Private Sub T_Click()\nCommand3.Value = True\n{text}\nEnd Sub\n"
    for case in spec["cases"]:
        form = vb6.VB6Form(src)
        form.call("T_Click", case["set"])
        p = form.control("Command3").props
        enabled, value = p["Enabled"].value is True, p["Value"].value is True
        if "enabled" in case and enabled != case["enabled"]:
            return Result(False, {"why": f"enabled = {enabled} at {case['set']}"})
        if "fires" in case and (not (enabled and value)) != case["fires"]:
            return Result(False, {"why": f"fires = {not (enabled and value)} at {case['set']}"})
    return Result(True, {"cases": len(spec["cases"])})


@kind("vb6")
def vb6_statement(text: str, spec, ctx) -> Result:
    from analysis.audit import vb6

    if spec.get("mode") == "controls":
        return _controls(text, spec, ctx)

    env, _ = ctx.value("vb6_env", tuple(spec["config"]), tuple(spec.get("end", ())))
    degrees = spec.get("trig", "radians") == "degrees"
    exp = spec["expect"]  # the variable the statement must assign: the printed one's
    target = exp if isinstance(exp, str) else assigned(ctx.paper.text(next(iter(exp.values()))[1:]))
    tol = spec.get("tol", 1e-3)
    for over in spec.get("refuses", ()):  # out of reach: no run-time error, nothing assigned
        e = {k: v for k, v in {**env, **over}.items() if k != target}
        got, form = run_statement(text, e, trig_degrees=degrees, target=target)
        if got is not None or form.control("Command3").props["Enabled"].value is not False:
            return Result(False, {"why": f"no refusal with {over}"})
    got = first_want = None
    cases = [({}, env)] + [(over, env) for over in spec.get("edges", ())]
    for config in spec.get("configs", ()):  # further configurations (quadrants, 180 deg)
        cases.append(({}, ctx.value("vb6_env", tuple(config), tuple(spec.get("end", ())))[0]))
    for k, (over, base) in enumerate(cases):
        e = {k2: v for k2, v in {**base, **over}.items() if k2 != target}
        try:
            got_k = run_statement(text, e, trig_degrees=degrees, target=target)[0]
        except vb6.VB6Error as exc:
            return Result(False, {"why": str(exc), "at": over})
        want = _want(spec["expect"], {**base, **over}, target, degrees, ctx)
        ok = got_k is not None and math.isfinite(got_k)
        if ok and math.isnan(want):
            pass
        elif ok and spec.get("angle", True):
            ok = abs(reduce_deg(got_k - want)) <= tol
        elif ok:
            ok = abs(got_k - want) <= tol
        if k == 0:
            got, first_want = got_k, want
        if not ok:
            return Result(False, {"got": got_k, "want": want, "at": over or "the configuration",
                                  "first": got, "first_want": first_want})  # fmt: skip
    return Result(True, {"got": got, "want": first_want})
