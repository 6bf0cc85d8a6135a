"""The item audit of seed 000: every printed statement of the paper checked by machine.

:func:`audit` holds each printed item of :mod:`analysis.papers.grabber` against its derivation
(:mod:`analysis.kinematics.dh`, the closed form of :mod:`analysis.kinematics.arms.grabber`,
:mod:`analysis.audit.table4`, :mod:`analysis.plc.stl_eval`; the checks are in
:mod:`analysis.audit.grabber_checks` and :mod:`analysis.audit.grabber_stl`) and returns one
:class:`Item` per printed statement with a computed verdict: ``simplify(printed - derived)
== 0`` for symbolic items, a numeric counterexample (or its absence over seeded samples) for
formulas with inverse trigonometric functions, recomputation for tables, evaluation for STL.
``data/errata/grabber_items.csv`` lists them all (items that hold too); the wrong ones are
grouped into root causes by :mod:`analysis.audit.grabber_causes`, with the builders here
(:func:`from_item`; causes are built by :func:`analysis.audit.schema.make_cause`).
"""

from __future__ import annotations

from functools import cache

import numpy as np
import sympy as sp

from analysis.audit.grabber_checks import all_items
from analysis.audit.grabber_items import KINDS, PXYZ, Item
from analysis.audit.grabber_items import S as S
from analysis.audit.schema import Cause, Manifestation, make_cause
from analysis.kinematics.params import paper_params

__all__ = [
    "AUDIT_COLUMNS",
    "Item",
    "audit",
    "audit_table",
    "closed_form_ik",
    "compare",
    "corrected_closed_form",
    "coverage",
    "item",
]

AUDIT_COLUMNS = ("id", "location", "verdict", "kind", "printed", "derived", "evidence", "check")


@cache
def audit() -> tuple[Item, ...]:
    """Every printed item with its verdict, in paper order (cached; takes seconds).

    See :mod:`analysis.audit.grabber_checks` for the checks; raises ``RuntimeError`` on duplicate
    ids.
    """
    items = all_items()
    ids = [it.id for it in items]
    if len(set(ids)) != len(ids):
        raise RuntimeError(
            "duplicate audit ids: " + ", ".join(sorted({i for i in ids if ids.count(i) > 1}))
        )
    return tuple(items)


def item(item_id: str) -> Item:
    """One audit item by id (raises ``ValueError`` for an unknown id)."""
    for it in audit():
        if it.id == item_id:
            return it
    raise ValueError(f"no audit item {item_id!r}")


def corrected_closed_form() -> dict[str, sp.Expr]:
    """The corrected IK (front-up, the paper's branch) as SymPy expressions in Px, Py, Pz and
    L1..L3: the arm's one closed form (:mod:`analysis.kinematics.arms.grabber`) evaluated
    with the SymPy namespace. The register's corrected eqs. 6, 10 and 19 are held against it.
    """
    from analysis.kinematics.arms import grabber
    from analysis.kinematics.symbolic import sympy_ops

    P = {k: S[k] for k in ("L1", "L2", "L3")}
    sol = grabber.ik(sympy_ops, PXYZ, P, tol=0)
    # the closed form's float literals (2.0 L2 L3, 1.0 - c) are exact: make them rationals
    t1, t2, t3 = (sp.nsimplify(e, rational=True) for e in sol["branches"]["front-up"])
    return {"theta1": t1, "theta2": t2, "theta3": t3}


def closed_form_ik(p, params=None) -> np.ndarray:
    """Evaluate :func:`corrected_closed_form` for targets (..., 3) [mm] -> (..., 3) [rad].

    theta2 is wrapped to (-pi, pi] like :meth:`analysis.kinematics.arm.Arm.solve`; NaN outside
    the reach (acos of a value beyond +-1). Vectorised through ``sympy.lambdify``: an
    evaluation independent of the numpy namespace's own.
    """
    prm = params or paper_params()
    p = np.asarray(p, dtype=float)
    cf = corrected_closed_form()
    args = (*PXYZ, S["L1"], S["L2"], S["L3"])
    vals = (p[..., 0], p[..., 1], p[..., 2], prm.L1, prm.L2, prm.L3)
    with np.errstate(invalid="ignore"):
        out = [
            np.asarray(sp.lambdify(args, cf[k], "numpy")(*vals), dtype=float)
            * np.ones(p.shape[:-1])
            for k in ("theta1", "theta2", "theta3")
        ]
    out[1] = np.mod(out[1] + np.pi, 2 * np.pi) - np.pi
    out[1] = np.where(out[1] == -np.pi, np.pi, out[1])
    return np.stack(out, axis=-1)


def compare(*selectors: str):
    """Printed beside derived, with verdict and evidence, as a DataFrame (for notebooks).

    Each selector is an item id or an id prefix (``"paper-eq12"`` selects all eq. 12 items).
    """
    import pandas as pd

    rows = [it for it in audit() if any(it.id == s or it.id.startswith(s + "-") for s in selectors)]
    if not rows:
        raise ValueError(f"no audit item matches {selectors!r}")
    return pd.DataFrame(
        [
            {
                "location": it.location,
                "printed": it.printed,
                "derived": it.derived,
                "verdict": it.verdict,
                "evidence": it.evidence,
            }
            for it in rows
        ],
        index=pd.Index([it.id for it in rows], name="id"),
    )


def coverage():
    """Counts of items per verdict and of wrong items per kind (two DataFrames)."""
    import pandas as pd

    items = audit()
    verdicts = (
        pd.Series([it.verdict for it in items])
        .value_counts()
        .reindex(["holds", "wrong", "undecidable"], fill_value=0)
    )
    kinds = (
        pd.Series([it.kind for it in items if it.verdict == "wrong"])
        .value_counts()
        .reindex(list(KINDS), fill_value=0)
    )
    return verdicts.rename("items").to_frame(), kinds.rename("wrong items").to_frame()


def audit_table() -> list[dict[str, str]]:
    """Every audited item as a row of ``data/errata/grabber_items.csv``."""
    return [
        {
            "id": it.id,
            "location": it.location,
            "verdict": it.verdict,
            "kind": it.kind,
            "printed": it.printed,
            "derived": it.derived,
            "evidence": it.evidence,
            "check": it.check,
        }
        for it in audit()
    ]


# ---------------------------------------------------------------------------------------------
# building causes from the wrong items (analysis.audit.grabber_causes)
# ---------------------------------------------------------------------------------------------
def from_item(cause: str, slug: str, item_id: str, **override) -> Manifestation:
    """Manifestation ``<cause>/<slug>`` of the wrong item ``item_id`` (its location, printed
    and corrected text, evidence and check; ``override`` replaces any of the first four)."""
    it = item(item_id)
    if it.verdict != "wrong":
        raise ValueError(f"{item_id} holds; it is no manifestation of {cause}")
    return Manifestation(
        f"{cause}/{slug}",
        override.get("location", it.location),
        override.get("printed", it.printed),
        override.get("corrected", it.corrected),
        override.get("evidence", it.evidence),
        it.verify,
        item_id,
    )


def single_cause(cid, title, status, kind, evidence, slug, item_id) -> Cause:
    """A cause with one manifestation, the wrong item ``item_id``."""
    return make_cause(cid, title, status, kind, evidence, [from_item(cid, slug, item_id)])
