"""The papers as data: every printed item of every paper in one schema (``data/papers/``).

A paper file holds ``[paper]`` (id, title, the seed text it transcribes, its symbols) and a
list of ``[[record]]``: one printed item each, with an ``id``, a ``type`` (:data:`TYPES`), the
``location`` where the paper prints it and the fields of its type (:data:`REQUIRED`). Nothing in
a paper file is corrected; where the extraction garbled an item, ``extracted`` holds the verbatim
run of the seed and the reading is said in the record (``garbled``, ``note``) or in an
``uncertain`` record. The audit's registers (``data/registers/``) refer to printed text by
reference into these records (:meth:`Paper.text`), never by retyping it.

References (:meth:`Paper.text`)::

    eq6                  the record's text in its notation ("lhs = rhs", a listing, a claim)
    eq3#2                part 2 of a multi-part equation (1-based)
    3.17#printed         a named field of the record (the extraction's run where the
                         record's text is its reading)
    eq12[2,3]            a matrix cell (row, column; 1-based)
    figure5:12-17        lines 12-17 of a listing (1-based, inclusive)
    table4[1].theta2_deg a table cell (row key, column)

Expressions are SymPy text over the paper's symbols, parsed by :meth:`Paper.parse` with one set of
functions for every paper (:data:`FUNCTIONS`). This module imports only the standard library and
SymPy: the papers are data, not analysis.
"""

from __future__ import annotations

import importlib

from analysis.papers.catalog import names, paper_path

__all__ = [
    "FUNCTIONS", "PAPERS", "PROVENANCE", "REQUIRED", "TYPES", "Paper", "Record", "legacy", "load",
    "load_file", "names", "paper_path", "parse", "validate",
]  # fmt: skip

_DATA = frozenset(__all__) - {"PAPERS", "names", "paper_path"}


def __getattr__(attr: str):
    """``PAPERS`` (every paper, by the name its data and register files carry) and, imported
    when first asked for, the data layer of :mod:`analysis.papers.data` (SymPy)."""
    if attr == "PAPERS":
        return names()
    if attr in _DATA:
        return getattr(importlib.import_module("analysis.papers.data"), attr)
    raise AttributeError(f"module {__name__!r} has no attribute {attr!r}")
