"""The mutation harness: texts every manifestation's ``verify`` must reject, and the printed
texts' edits every ``holds`` row's check must reject.

For every object of :func:`analysis.audit.manifestations` the harness builds probes:

- ``tautology``: statements true of anything in the text's notation (``X = X``, ``0 = 0``,
  ``forall D: Eq(1, 1)``, ``exists D: Eq(1, 1)``, ``max D: 0 = 0``, an empty listing);
- ``unrelated``: other rows' corrections (true statements of the same paper, about something
  else), the correction's own sides (``rhs = rhs``);
- ``comment``: the correction with a ``#`` comment appended;
- single edits of the correction: ``sign`` (a '+' for a '-' or back, the right-hand side
  negated), ``index`` (a digit inside a name one up or down: theta1, L4p, VD12), ``digit`` (a
  digit of a number one up or down), ``symbol`` (a name of the paper's for another), ``trig``
  (sin for cos, asin for acos and back), ``threshold`` (a comparison made strict or not, a
  number beside a comparison or after a claim's '=' scaled by ten).

Each probe is first held against the correction with SymPy (:func:`equivalent`: the same
expression, equation, claim, cell or instructions, proved, not sampled); a probe that says the
same is not a counterexample. Every other probe must fail ``verify``. For a ``holds`` row whose
printed text is what is checked (no reading), the same edits of the printed text must also fail
the check's computation alone (``holds``), and so must the edits of every other printed record
whose own check passes (:func:`run_records`): every printed symbol, cell and digit is pinned.

Edits are drawn seeded per object and per edit kind (``per_kind``), so that a run tries the
same texts every time and the whole harness fits the test budget.
"""

from __future__ import annotations

import json
import random
import re
import zlib
from collections import Counter
from dataclasses import dataclass, field

__all__ = ["Probe", "Report", "edits", "equivalent", "probes", "run"]

EDIT_KINDS = ("sign", "index", "digit", "symbol", "trig", "threshold")
_NAME = re.compile(r"(?<![\w.])([^\W\d]\w*)")
_NUMBER = re.compile(r"(?<![\w.])(\d+(?:\.\d+)?(?:[eE][-+]?\d+)?)")
_TRIG = {"sin": "cos", "cos": "sin", "asin": "acos", "acos": "asin", "Sin": "Cos", "Cos": "Sin",
         "SIN": "COS", "COS": "SIN", "ARCSIN": "ARCCOS", "ARCCOS": "ARCSIN"}  # fmt: skip
_FUNCTIONS = {"sin", "cos", "tan", "atan", "atan2", "asin", "acos", "sqrt", "Abs", "exp", "pi",
              "Piecewise", "Derivative", "Subs", "Eq", "forall", "exists", "count", "max",
              "min"}  # fmt: skip


@dataclass(frozen=True)
class Probe:
    """A text a check is held to: its ``kind``, what it was made from (``base``: the
    correction or the printed text) and the ``text``."""

    kind: str
    base: str
    text: str


def _rng(key: str) -> random.Random:
    return random.Random(zlib.crc32(key.encode()))


def _sub(text: str, start: int, end: int, new: str) -> str:
    return text[:start] + new + text[end:]


def edits(text: str, symbols: list[str]) -> dict[str, list[str]]:
    """Every single edit of ``text`` of each kind of :data:`EDIT_KINDS` (``symbols``: names a
    ``symbol`` edit may put in)."""
    out: dict[str, list[str]] = {k: [] for k in EDIT_KINDS}
    for m in re.finditer(r"(?<=[\s(\w)*])([+-])(?=[\s\w(.])", text):
        out["sign"].append(_sub(text, m.start(), m.end(), "-" if m[1] == "+" else "+"))
    eq = [m.start() for m in re.finditer(r"(?<![<>!=])=(?!=)", text)]
    if len(eq) == 1:
        out["sign"].append(f"{text[: eq[0]]}= -({text[eq[0] + 1 :].strip()})")
    names = [(m.start(1), m.end(1), m[1]) for m in _NAME.finditer(text)]
    for a, b, name in names:
        for k, ch in enumerate(name):
            if ch.isdigit() and k:
                for d in {(int(ch) + 1) % 10, (int(ch) - 1) % 10}:
                    out["index"].append(_sub(text, a + k, a + k + 1, str(d)))
        if name in _TRIG:
            out["trig"].append(_sub(text, a, b, _TRIG[name]))
        if name not in _FUNCTIONS and name in symbols:
            for other in symbols:
                if other != name and other not in _FUNCTIONS:
                    out["symbol"].append(_sub(text, a, b, other))
    for m in _NUMBER.finditer(text):
        for k in range(m.start(1), m.end(1)):
            ch = text[k]
            if not ch.isdigit():
                continue
            for d in {(int(ch) + 1) % 10, (int(ch) - 1) % 10}:
                if d == 0 and k == m.start(1) and m.end(1) - k > 1 and text[k + 1].isdigit():
                    continue  # no leading zero
                out["digit"].append(_sub(text, k, k + 1, str(d)))
    for m in re.finditer(r"(<=|>=|<|>)", text):
        out["threshold"].append(_sub(text, m.start(), m.end(), {"<=": "<", ">=": ">", "<": "<=", ">": ">="}[m[1]]))  # noqa: E501
    for m in re.finditer(r"(?:(?:<=|>=|<|>)\s*|:.*?=\s*)(-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?)", text):
        v = m[1]
        if "e" in v.lower():
            mant, _, exp = v.lower().partition("e")
            new = f"{mant}e{-int(exp):+d}"
        else:
            new = repr(float(v) * 10) if "." in v else str(int(v) * 10 or 1)
        out["threshold"].append(_sub(text, m.start(1), m.end(1), new))
    return {k: list(dict.fromkeys(t for t in v if t != text)) for k, v in out.items()}


def _tautologies(m, ctx) -> list[str]:
    kind, text = m.spec.get("kind"), m.corrected
    out = ["0 = 0", "1 = 1", "True", "Eq(1, 1)"]
    lhs = text.split("=")[0].strip() if text.count("=") == 1 else ""
    if lhs:
        out += [f"{lhs} = {lhs}", f"{lhs} = {lhs} + 0"]
    claim = re.match(r"^(forall|exists|count|max|min) ([\w-]+):", text.strip())
    if claim:
        d = claim[2]
        out += [f"exists {d}: Eq(1, 1)", f"forall {d}: Eq(1, 1)", f"max {d}: 0 = 0",
                f"min {d}: 0 = 0", f"count {d}: Eq(1, 0) = 0"]  # fmt: skip
        try:
            names = list(ctx.domain(d))
        except Exception:
            names = []
        out += [f"forall {d}: Eq({n}, {n})" for n in names[:4]]
    if kind == "stl":
        out += ["NOP 0", "MOVR VD0, VD0"]
    if kind == "vb6":
        out += ["x = x", "Command3.Enabled = True"]
    return list(dict.fromkeys(out))


def _unrelated(m, others: list[str]) -> list[str]:
    out = [t for t in others if t and t != m.corrected]
    text = m.corrected
    if text.count("=") == 1 and not re.search(r"[<>!]=", text):
        rhs = text.split("=")[1].strip()
        out.append(f"{rhs} = {rhs}")
    return out


def probes(m, ctx, others: list[str], per_kind: int = 2) -> list[Probe]:
    """The probes of manifestation ``m`` (see the module docstring); ``others``: corrections
    of other rows to try as unrelated true statements."""
    rng = _rng(m.id)
    symbols = sorted(k for k, v in ctx.paper.symbols().items() if not callable(v)) if hasattr(
        ctx.paper, "symbols") else []  # fmt: skip
    out = [Probe("tautology", "correction", t) for t in _tautologies(m, ctx)]
    pool = _unrelated(m, others)
    out += [Probe("unrelated", "correction", t) for t in rng.sample(pool, min(4, len(pool)))]
    out += [Probe("comment", "correction", f"{m.corrected}  # {w}") for w in ("holds", "x")]
    bases = [("correction", m.corrected)]
    if m.status == "holds" and not m.reading:
        bases.append(("printed", m.printed))
    for base, text in bases:
        for kind, ts in edits(text, symbols).items():
            out += [Probe(kind, base, t) for t in rng.sample(ts, min(per_kind, len(ts)))]
    return out


# --- equivalence, proved with SymPy -------------------------------------------------------------
def _proved_equal(a, b, angle: bool = False) -> bool:
    """``a`` and ``b`` proved the same function: a difference at a point disproves it at once
    (:func:`~analysis.audit.equivalence.expressions_agree`, which shares its compiled
    functions with ``verify``); agreement there is proved by SymPy
    (:func:`~analysis.audit.kinds.symbolic.is_zero`: a trigonometric normal form, else
    ``sympy.simplify``), modulo 2 pi for an angle."""
    import sympy as sp

    from analysis.audit.equivalence import expressions_agree
    from analysis.audit.kinds.symbolic import is_zero

    if not expressions_agree(a, b, angle=angle):
        return False
    d = sp.sympify(a) - sp.sympify(b)
    return any(is_zero(d - k) for k in ((0, -2 * sp.pi, 2 * sp.pi) if angle else (0,)))


def _proved_equation(a: str, b: str, m, ctx) -> bool:
    from analysis.audit.kinds.symbolic import equation

    ns = m.spec.get("namespace", "main")
    if "defines" in m.spec:
        return _proved_equal(ctx.paper.parse(a, ns), ctx.paper.parse(b, ns))
    (la, ra), (lb, rb) = equation(a, ctx, ns), equation(b, ctx, ns)
    da, db = la - ra, lb - rb
    angle = m.spec.get("kind") == "sampled" and m.spec.get("angle", True)
    return _proved_equal(da, db, angle) or _proved_equal(da, -db, angle)


def _proved_claim(a: str, b: str, m, ctx) -> bool:
    import sympy as sp

    from analysis.audit.kinds.claim import parse_claim
    from analysis.papers import parse

    (qa, da, ba, na), (qb, db, bb, nb) = parse_claim(a), parse_claim(b)
    if (qa, da) != (qb, db) or (na is None) != (nb is None):
        return False
    if na is not None and abs(float(na) - float(nb)) > float(m.spec.get("tol", 0.0)):
        return False
    names = {k: sp.Symbol(k) for k in ctx.domain(da)}
    ea, eb = parse(ba, names), parse(bb, names)
    if isinstance(ea, sp.logic.boolalg.Boolean) or isinstance(eb, sp.logic.boolalg.Boolean):
        from sympy.logic.inference import satisfiable

        return not satisfiable(sp.Xor(ea, eb))  # no assignment of the comparisons tells them apart
    return _proved_equal(ea, eb)


def equivalent(candidate: str, base: str, m, ctx) -> bool:
    """Does ``candidate`` say what ``base`` says? Proved with SymPy in the notation of the
    row's kind (expressions, equations, claims), or the same cell, instructions, tokens or
    text; a candidate that cannot be read says something else."""
    from analysis.audit import equivalence as eq

    if eq.normalized(candidate) in {eq.normalized(t) for t in (base, *m.equivalent)}:
        return True  # the same text, blanks aside, or one the register declares equivalent
    kind = m.spec.get("kind")
    try:
        if kind in ("identity", "sampled"):
            return _proved_equation(candidate, base, m, ctx)
        if kind == "matrix":
            from analysis.audit.kinds.symbolic import cells

            if "of_column" in m.spec:
                return _proved_equal(ctx.paper.parse(candidate), ctx.paper.parse(base))
            if "label" in m.spec:
                (la, _, candidate), (lb, _, base) = candidate.partition("="), base.partition("=")
                if eq.normalized(la) != eq.normalized(lb):
                    return False
            n = len(m.spec["cells"])
            pairs = zip(cells(candidate, n), cells(base, n), strict=True)
            return all(_proved_equal(ctx.paper.parse(x), ctx.paper.parse(y)) for x, y in pairs)
        if kind == "claim":
            return _proved_claim(candidate, base, m, ctx)
        if kind in ("table", "stl", "vb6"):
            return eq.same(candidate, base, m.spec, ctx)
    except Exception:
        return False
    return False


# --- the run -------------------------------------------------------------------------------------
@dataclass
class Report:
    """What a run tried and what it found."""

    objects: int = 0
    probes: Counter = field(default_factory=Counter)
    equivalent: Counter = field(default_factory=Counter)
    accepted: list[tuple[str, str, str, str]] = field(default_factory=list)
    """(manifestation, probe kind, base, text) of every probe wrongly accepted."""
    demonstrations: int = 0
    demonstrated_with_corrections: list[str] = field(default_factory=list)

    def to_dict(self) -> dict:
        acc = Counter(k for _, k, _, _ in self.accepted)
        return {
            "objects": self.objects, "probes": sum(self.probes.values()),
            "by_kind": dict(self.probes), "equivalent_skipped": dict(self.equivalent),
            "tautologies_accepted": acc["tautology"], "unrelated_accepted": acc["unrelated"],
            "comments_accepted": acc["comment"],
            "non_equivalent_edits_accepted": sum(acc[k] for k in EDIT_KINDS),
            "accepted": [list(a) for a in self.accepted],
            "causes_demonstrated": self.demonstrations,
            "demonstrated_with_corrections_printed": self.demonstrated_with_corrections,
        }  # fmt: skip


def run_paper(reg, ctx, per_kind: int = 2, report: Report | None = None) -> Report:
    """The harness over one paper's register ``reg`` (context ``ctx``)."""
    report = report or Report()
    ms = reg.manifestations
    corrections = [x.corrected for x in ms]
    for m in ms:
        report.objects += 1
        same_kind = [c for x, c in zip(ms, corrections, strict=True)
                     if x.id != m.id and x.spec.get("kind") == m.spec.get("kind")]  # fmt: skip
        for p in probes(m, ctx, same_kind, per_kind):
            report.probes[p.kind] += 1
            base = m.corrected if p.base == "correction" else m.printed
            if equivalent(p.text, base, m, ctx):
                report.equivalent[p.kind] += 1
                continue
            wrong = m.verify(p.text) if p.base == "correction" else m.holds(p.text)
            if wrong:
                report.accepted.append((m.id, p.kind, p.base, p.text))
    for c in reg.causes:
        report.demonstrations += 1
        if c.status != "holds" and c.manifestations:
            if c.demonstrate({m.id: m.corrected for m in c.manifestations}):
                report.demonstrated_with_corrections.append(c.id)
    return report


def run_records(reg, ctx, per_kind: int = 2, report: Report | None = None) -> Report:
    """The printed records whose checks pass and that no ``holds`` row already probes (every
    record unit the register does not name as what holds): each single edit of the printed text
    that SymPy does not prove equivalent must fail the record's check (each printed symbol,
    cell and digit pinned by the paper's own check)."""
    from types import SimpleNamespace

    from analysis.audit import records
    from analysis.audit.kinds import check

    report = report or Report()
    probed = {m.source for m in reg.manifestations if m.status == "holds" and not m.reading}
    symbols = sorted(k for k, v in ctx.paper.symbols().items() if not callable(v))
    for u in records.units(ctx.paper):
        if u.spec is None or u.ref in probed or "reading" in (ctx.paper.record(u.record).get("check") or {}):  # noqa: E501
            continue
        if not check(u.spec, u.text, ctx).ok:
            continue  # a failing record is its causes' (run_paper probes their corrections)
        report.objects += 1
        m = SimpleNamespace(id=u.ref, spec=u.spec, equivalent=(), corrected=u.text)
        rng = _rng("record:" + u.ref)
        for kind, ts in edits(u.text, symbols).items():
            for t in rng.sample(ts, min(per_kind, len(ts))):
                report.probes[kind] += 1
                if equivalent(t, u.text, m, ctx):
                    report.equivalent[kind] += 1
                elif check(u.spec, t, ctx).ok:
                    report.accepted.append((u.ref, kind, "record", t))
    return report


def run(papers=None, per_kind: int = 2) -> Report:
    """The harness over every object of :func:`analysis.audit.manifestations` (or the
    registers of ``papers``)."""
    from analysis.audit import register as r
    from analysis.audit.context import context

    report = Report()
    for p in papers or r.available():
        run_paper(r.register(p), context(p), per_kind, report)
        run_records(r.register(p), context(p), per_kind, report)
    return report


def main() -> int:  # pragma: no cover - python -m analysis.audit.harness
    rep = run().to_dict()
    rep.pop("accepted") if not rep["accepted"] else None
    print(json.dumps(rep, indent=1, ensure_ascii=False))
    return 0


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
