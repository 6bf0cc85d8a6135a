"""The mutation harness: texts every manifestation's ``verify`` must reject.

For a manifestation, :func:`nonsense` generates at least 20 texts that state nothing (the
corrected text's tokens shuffled or thinned, cut short, padded, words of the paper's and the
register's vocabulary, blanks) and :func:`mutants` the corrected text with one sign, one index
or one digit changed:

- sign: a '+' for a '-' or back, or a minus put before the text's right-hand side;
- index: the last digit of a name (theta1, L2, VD12) one up or one down;
- digit: the leading digit of a number one up or one down.

A generated text that says the same as the correction is not a counterexample: it is dropped
when it is the correction (blanks aside), one the register declares equivalent
(``equivalent = [...]``, e.g. another free double word), or, for the symbolic kinds, when both
sides agree with the correction's at random points (:func:`equivalent`). Seeded per
manifestation: a run tries the same texts every time.
"""

from __future__ import annotations

import random
import re
import zlib

__all__ = ["equivalent", "mutants", "nonsense"]

_NAME = re.compile(r"\b([A-Za-z_]+\w*?)(\d)\b")
_NUMBER = re.compile(r"(?<![\w.])(\d)(\d*(?:\.\d+)?)")
_WORDS = ("nonsense", "PLS", "SMD72", "I0.0", "EU", "主運動鏈", "unsupported", "computed",
          "resolution", "mm", "SUBROUTINE_BLOCK", "Q0.7", "Q0.2", "holds", "atan2", "theta1")  # fmt: skip  # noqa: E501


def _rng(key: str) -> random.Random:
    return random.Random(zlib.crc32(key.encode()))


def nonsense(text: str, key: str, vocabulary: list[str], n: int = 24) -> list[str]:
    """``n`` texts built from ``text`` and a vocabulary that state nothing."""
    rng = _rng("nonsense:" + key)
    toks = re.findall(r"\w+|[^\w\s]", text) or ["x"]
    out = ["", " ", "0", "1", "True", "nonsense", "PLS SMD72 nonsense", "主運動鏈 anything at all",
           text + " nonsense", "nonsense " + text, text[: max(1, len(text) // 2)], text[::-1]]  # fmt: skip  # noqa: E501
    out = list(dict.fromkeys(out))
    for _ in range(50 * n):  # until n distinct texts (bounded: a one-token text has few)
        if len(out) >= n:
            break
        k = rng.randrange(5)
        if k == 0:
            t = toks[:]
            rng.shuffle(t)
        elif k == 1:
            t = [x for x in toks if rng.random() < 0.5]
        elif k == 2:
            t = rng.sample(vocabulary or list(_WORDS), min(len(vocabulary or _WORDS), 4))
        elif k == 3:
            t = toks + rng.sample(list(_WORDS), 2)
        else:
            t = [rng.choice(toks) for _ in toks]
        t = " ".join(t)
        if t not in out:
            out.append(t)
    return out


def mutants(text: str, key: str, per_type: int = 1) -> dict[str, list[str]]:
    """The corrected text with one sign, one index or one digit changed: up to ``per_type``
    of each (seeded), as ``{"sign": [...], "index": [...], "digit": [...]}``."""
    rng = _rng("mutants:" + key)
    found: dict[str, list[str]] = {"sign": [], "index": [], "digit": []}
    for m in re.finditer(r"(?<=[\s(\w)])([+-])(?=[\s\w(])", text):
        other = "-" if m.group(1) == "+" else "+"
        found["sign"].append(text[: m.start()] + other + text[m.end() :])
    if "=" in text and text.count("=") == 1 and not re.search(r"[<>!]=", text):
        lhs, rhs = text.split("=")
        found["sign"].append(f"{lhs}= -({rhs.strip()})")
    for m in _NAME.finditer(text):
        d = int(m.group(2))
        for e in {(d + 1) % 10, (d - 1) % 10}:
            found["index"].append(text[: m.start(2)] + str(e) + text[m.end(2) :])
    for m in _NUMBER.finditer(text):
        if m.start() > 0 and (text[m.start() - 1].isalpha() or text[m.start() - 1] == "_"):
            continue  # a name's index, above
        d = int(m.group(1))
        for e in {(d + 1) % 10, (d - 1) % 10}:
            if e == 0 and m.group(2)[:1].isdigit():
                continue  # no leading zeros
            found["digit"].append(text[: m.start(1)] + str(e) + text[m.end(1) :])
    return {k: rng.sample(v, min(per_type, len(v))) for k, v in found.items()}


def _norm(text: str) -> str:
    return " ".join(text.split())


def equivalent(candidate: str, manifestation, ctx) -> bool:
    """Does ``candidate`` say what the correction says? Equal blanks aside, declared in the
    register, or (symbolic kinds) equal on both sides at three random points."""
    corrected = manifestation.corrected
    if _norm(candidate) == _norm(corrected) or _norm(candidate) in map(_norm, manifestation.equivalent):  # noqa: E501
        return True
    kind = manifestation.spec.get("kind")
    if kind == "stl":  # the same instructions, however punctuated
        from analysis.audit.kinds.listing import instructions

        try:
            a, b = (instructions(t) for t in (candidate, corrected))
        except Exception:  # not a listing
            return False
        return [(i.op, i.args) for i in a] == [(i.op, i.args) for i in b]
    if kind not in ("identity", "sampled", "matrix", "symbol"):
        return False
    import numpy as np
    import sympy as sp

    try:
        ns = manifestation.spec.get("namespace", "main")
        sides = []
        for t in (candidate, corrected):
            parts = t.split("=") if t.count("=") == 1 else [t]
            sides.append([ctx.paper.parse(p, ns) for p in parts])
        if len(sides[0]) != len(sides[1]):
            return False
        rng = np.random.default_rng(7)
        for a, b in zip(*sides, strict=True):
            names = sorted((a - b).free_symbols, key=str)
            f = sp.lambdify(names, a - b, "numpy")
            vals = rng.uniform(0.3, 1.3, (3, len(names)))
            if not np.allclose([complex(f(*v)) for v in vals], 0, atol=1e-9):
                return False
        return True
    except Exception:  # a candidate that does not parse says nothing
        return False
