"""The papers of ``data/papers/``, found without reading them as papers: their names, in the
order of the seed texts they transcribe, and their files (the standard library only, so that a
question about which papers there are costs no SymPy import)."""

from __future__ import annotations

import tomllib
from functools import cache
from pathlib import Path

__all__ = ["names", "paper_path", "raw"]


def paper_path(name: str) -> Path:
    from analysis.paths import data_dir  # the one place the data folder is found

    return data_dir() / "papers" / f"{name}.toml"


@cache
def raw(path: Path) -> dict:
    """A paper's data file, parsed (cached)."""
    return tomllib.loads(path.read_text(encoding="utf-8"))


@cache
def names() -> tuple[str, ...]:
    """Every paper of ``data/papers/`` (a file ``<name>.toml`` whose ``[paper] id`` is its
    name), in the order of the seed texts they transcribe (``[paper] source``): a new paper
    is a new data file, no Python tuple to edit."""
    found = []
    for path in sorted(paper_path("x").parent.glob("*.toml")):
        meta = raw(path).get("paper", {})
        if meta.get("id") == path.stem:
            found.append((str(meta.get("source", "")), path.stem))
    return tuple(name for _, name in sorted(found))
