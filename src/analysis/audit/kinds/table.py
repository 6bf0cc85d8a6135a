"""``table``: a printed table cell against its recomputation.

``spec``: ``table`` (a record of the paper), ``row``, ``column``, ``value`` (the name of the
paper's recomputation, ``fn(row, column) -> float``, NaN where there is no value, e.g. a target
out of reach). A text is a cell in the table's notation: a number, held at the number of
decimals the paper prints in that cell (read from the record, never typed: a cell printed as
"190.20" is held at two decimals, so "10.21" passes for 10.2087 and "10.2" or "10" do not), or
the paper's word for "no solution" (``none``, e.g. 无解), right exactly where the recomputation
has no value. ``mode = "truncate"`` holds a cell against the value truncated instead of rounded.

Example (seed 000, Table 4 row 1, theta2): printed "190.20", recomputed 10.2087 deg: "190.20"
fails, "10.21" passes.
"""

from __future__ import annotations

from decimal import Decimal, InvalidOperation

import numpy as np

from analysis.audit.kinds.base import Result, kind

__all__ = ["cell_matches", "decimals"]


def decimals(text: str) -> int:
    """Decimals printed in a cell ("190.20" -> 2, "45" -> 0); ValueError if not a number."""
    try:
        d = Decimal(text.strip())
    except InvalidOperation:
        raise ValueError(f"{text!r} is not a number") from None
    if not d.is_finite():
        raise ValueError(f"{text!r} is not a finite number")
    return max(0, -d.as_tuple().exponent)


def cell_matches(text: str, value: float, mode: str = "round", places: int | None = None) -> bool:
    """Does ``value`` print as ``text`` at ``places`` decimals (default: the text's own)? A text
    that is not a number (无解) never matches a number; ``mode`` "round" (to nearest) or
    "truncate" (toward zero), else ValueError. The one cell matcher of the project."""
    if mode not in ("round", "truncate"):
        raise ValueError(f"mode {mode!r}: expected 'round' or 'truncate'")
    try:
        own = decimals(text)
    except ValueError:
        return False
    k = own if places is None else places
    if own != k or not np.isfinite(value):
        return False
    printed, scale = float(text), 10.0**k
    if mode == "round":  # 1e-9: the binary representation of the printed decimal
        return abs(value - printed) <= 0.5 / scale + 1e-9
    return abs(np.trunc(value * scale) / scale - printed) <= 1e-9


@kind("table")
def table(text: str, spec, ctx) -> Result:
    row, col = str(spec["row"]), spec["column"]
    printed = ctx.paper.cell(ctx.paper.record(spec["table"]), row, col)
    value = float(ctx.value(spec["value"], row, col))
    none = spec.get("none")
    if none is not None and text.strip() == none:
        return Result(not np.isfinite(value), {"value": value})
    if none is not None and printed.strip() in ("", none):
        places = None  # an empty printed cell fixes no precision
    else:
        places = decimals(printed)
    ok = cell_matches(text, value, spec.get("mode", "round"), places)
    return Result(ok, {"value": value, "places": places})
