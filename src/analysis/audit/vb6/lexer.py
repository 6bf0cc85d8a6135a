"""The tokenizer of the VB6 subset that :mod:`analysis.audit.vb6` runs."""

from __future__ import annotations

import re
from dataclasses import dataclass

from analysis.audit.vb6.values import VB6SyntaxError

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
    "dim", "as", "private", "public", "sub", "end", "exit", "if", "then", "else", "elseif", "for",
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
