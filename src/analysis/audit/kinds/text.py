"""Cross-references and symbols: ``xref`` and ``symbol``; and ``bespoke``, a predicate a paper
registers by name where no kind fits.

``xref``: the text is the printed sentence (``spec["frame"]``, a reference into the paper) with
the reference numbers as the text has them: the rest of the sentence must be the printed one,
and what the numbers point at must satisfy ``target``, decided from the paper's records:

- ``defines = "theta1"``: equation ``eq<N>`` has that symbol as its left-hand side;
- ``section = "逆向"``: the heading of section N contains the word;
- ``reference = "D-H method"``: reference [N] is about that topic, and where the sentence
  names a reference twice ("第5篇文獻 ... [6]") both numbers agree;
- ``display``: display N of the paper's count holds that (``@<value>``: a value the paper
  computes, e.g. the kind of twist its remaining joints have);
- ``agrees``: another printed sentence (and its ``pattern``) gives the same item the number N.

Example (seed 000): "结合工程实际, 取式(16)" fails (eq. 16 defines sin(theta2 + theta3)),
"结合工程实际, 取式(6)" passes.

``symbol``: the text is one symbol, spelled as the records ``used_in`` spell it.

``numbering``: the text is a list of captions or headings, one a line (``图 3-4 ...``,
``3.3 ...``, ``附录 A ...``): the titles of the printed list ``of``, in its order, numbers and
field errors aside; none may carry a word processor's field error (``错误!未找到引用源``,
``Error! Reference source not found``), and the numbers of each chapter (the letters of the
appendices) must run 1, 2, 3 ... (A, B, C ...) in order. Example (seed 004): chapter 3's
figures "3-1, 3-2, 3-3, 3-4, 3-4, 3-5" fail, "3-1 ... 3-6" pass.
"""

from __future__ import annotations

import re

from analysis.audit.kinds.base import Result, kind

__all__ = ["frame_numbers"]


def frame_numbers(text: str, frame: str, pattern: str) -> list[int] | None:
    """The numbers ``text`` has where ``frame`` (the printed sentence) has the groups of
    ``pattern``; None if the rest of the text differs from the frame."""
    m = re.search(pattern, frame)
    if not m:
        raise ValueError(f"pattern {pattern!r} is not in the printed sentence {frame!r}")
    parts, last = [], 0
    for g in range(1, (m.lastindex or 0) + 1):
        parts += [re.escape(frame[last : m.start(g)]), r"(\d+)"]
        last = m.end(g)
    found = re.fullmatch("".join(parts) + re.escape(frame[last:]), text.strip())
    return [int(v) for v in found.groups()] if found else None


def _points_at(n: int, target, ctx) -> bool:
    paper = ctx.paper
    if "defines" in target:
        rec = paper.records.get(f"eq{n}")
        return rec is not None and "lhs" in rec.fields and paper.parse(rec["lhs"]) == paper.parse(
            target["defines"]
        )
    if "section" in target:
        rec = paper.records.get(f"sections.{n}")
        return rec is not None and target["section"] in rec["text"]
    if "reference" in target:
        rec = paper.records.get(f"references.{n}")
        return rec is not None and rec.get("topic") == target["reference"]
    if "agrees" in target:  # the number another printed sentence gives the same item
        m = re.search(target["pattern"], paper.text(target["agrees"]))
        return m is not None and int(m[1]) == n
    if "display" in target:
        want = target["display"]
        want = ctx.value(want[1:]) if want.startswith("@") else want
        rec = paper.records.get(f"equation_numbers.{n - 1}")
        return rec is not None and rec["n"] == n and rec["holds"] == want
    raise ValueError(f"unknown xref target {target!r}")


@kind("xref")
def xref(text: str, spec, ctx) -> Result:
    frame = ctx.paper.text(spec["frame"])
    nums = frame_numbers(text, frame, spec["pattern"])
    if nums is None:
        return Result(False, {"why": "not the printed sentence"})
    if "reference" in spec["target"] and len(set(nums)) > 1:
        return Result(False, {"why": f"the sentence names two references {nums}"})
    target = spec["target"]
    if isinstance(target.get("defines"), list):  # one symbol per number, in order
        if len(nums) != len(target["defines"]):
            return Result(False, {"numbers": nums})
        ok = all(_points_at(n, {"defines": d}, ctx) for n, d in zip(nums, target["defines"], strict=True))  # noqa: E501
        return Result(ok, {"numbers": nums})
    ok = all(_points_at(n, target, ctx) for n in nums[-1:])
    return Result(ok, {"numbers": nums})


@kind("symbol")
def symbol(text: str, spec, ctx) -> Result:
    """A notation: the name as spelled (not the quantity it parses to: a paper may state two
    spellings equal) must be one the records ``used_in`` spell, and a symbol of the paper."""
    name = text.strip()
    spelled = {w for ref in spec["used_in"] for w in re.findall(r"[^\W\d]\w*", ctx.paper.text(ref))}
    return Result(name in ctx.paper.symbols() and name in spelled, {})


@kind("bespoke")
def bespoke(text: str, spec, ctx) -> Result:
    """A predicate the paper registers by name (``spec["predicate"]``), for what no kind
    expresses; it must decide by computation, as every kind does."""
    out = ctx.predicate(spec["predicate"])(text, ctx, **spec.get("args", {}))
    return out if isinstance(out, Result) else Result(bool(out))


FIELD_ERRORS = ("错误!未找到引用源", "Error! Reference source not found")
_CAPTION = re.compile(r"^(?:图\s*)?(\d+)[.-](\d+)\s*[^\d\s.-]")
_APPENDIX = re.compile(r"^附录\s*([A-Z])\s*\S")


@kind("numbering")
def numbering(text: str, spec, ctx) -> Result:
    lines = [ln.strip() for ln in text.splitlines() if ln.strip()]
    if len(lines) < spec.get("min", 2) or any(e in text for e in FIELD_ERRORS):
        return Result(False, {"why": "a field error, or not a list"})
    def title(ln: str) -> str:
        for e in FIELD_ERRORS:
            ln = ln.replace(e + "。", "").replace(e, "")
        return re.sub(r"^(?:图\s*)?\d+[.-]\d+\s*|^附录\s*[A-Z]?\s*", "", ln).strip()

    printed = [ln.strip() for ln in ctx.paper.text(spec["of"]).splitlines() if ln.strip()]
    if [title(ln) for ln in lines] != [title(ln) for ln in printed]:
        return Result(False, {"why": "not the printed list's titles"})
    groups: dict[str, list[int]] = {}
    for ln in lines:
        m, a = _CAPTION.match(ln), _APPENDIX.match(ln)
        if not (m or a):
            return Result(False, {"why": f"{ln!r} carries no number"})
        key, n = (m[1], int(m[2])) if m else ("appendix", ord(a[1]) - ord("A") + 1)
        groups.setdefault(key, []).append(n)
    bad = {k: v for k, v in groups.items() if v != list(range(1, len(v) + 1))}
    return Result(not bad, {"numbers": groups})
