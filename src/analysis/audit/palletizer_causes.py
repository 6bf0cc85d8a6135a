"""Seed 001's register (Li & Hu 2021, the 4-axis palletizer): the findings of
:mod:`analysis.audit.palletizer_checks` grouped into root causes, in the schema of
:mod:`analysis.audit.schema`.

Every manifestation's ``verify(text)`` decides a text of the printed notation by a
derivation or a run, never by comparing strings with the correction:

* formulas (SymPy text in the symbols of :data:`analysis.papers.palletizer.SYMBOLS`) are
  held against the product of the printed matrices (eq. 11), Craig's modified D-H transform
  (eq. 8), the elbow angle and the direction of the shoulder-wrist line measured on the
  forward kinematics of the arm (eqs. 3, 4), atan2 on 360 azimuths and the axes (eqs. 1, 6),
  the level gripper (eq. 12);
* claims are put in a small checkable form (a condition, a count, a bound) and evaluated on
  targets of the arm: a grid of the workspace, the four quadrant targets, the initial pose.

Numbers that depend on the lengths use the arm of ``data/arms/palletizer.toml``, whose every
length is ASSUMED (the paper prints none; L1 = L2 is the default family); the evidence says
so. The verdicts do not depend on them (tests/audit/test_palletizer_checks.py runs the checks
with L1 != L2).

This module holds the causes of the D-H model (eqs. 8, 11) and builds the register;
:mod:`analysis.audit.palletizer_causes_ik` has the IK chain (eqs. 1-6, 12, the signs),
:mod:`analysis.audit.palletizer_causes_claims` the claims of the text, what the extraction lost
and what holds, :mod:`analysis.audit.palletizer_formulas` the parsing and evaluation they share.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from analysis.audit import palletizer_causes_claims, palletizer_causes_ik
from analysis.audit import palletizer_checks as chk
from analysis.audit.palletizer_derivations import is_zero as _zero
from analysis.audit.palletizer_formulas import ATOL, S
from analysis.audit.palletizer_formulas import findings_by_id as _found
from analysis.audit.palletizer_formulas import palletizer_arm as _arm
from analysis.audit.palletizer_formulas import parse_formula as _parse
from analysis.audit.schema import Cause, Manifestation, Register
from analysis.audit.schema import all_fail as _all_fail
from analysis.audit.schema import make_cause as _cause
from analysis.audit.schema import safe as _safe
from analysis.kinematics.dh import link_transform_sym
from analysis.papers import palletizer as paper

__all__ = ["register"]

# ---------------------------------------------------------------------------------------------
# eq. 11 and eq. 8 (the D-H model, symbolic)
# ---------------------------------------------------------------------------------------------
_BAD, _GOOD = "(sin(theta4)*h - sin(theta4)*L3)", "(sin(theta4)*h - cos(theta4)*L3)"


def _residual(rhs: str, derived: sp.Expr) -> str:
    return sp.sstr(sp.factor(sp.expand(paper.parse(rhs) - derived)))


def _eq11() -> list[Cause]:
    derived = chk.derived_tool_position()
    res = chk.eq11_residuals()
    parts = paper.EQUATIONS["eq11"]["parts"]
    where = ("row 1 (t14)", "row 2 (printed label t34)", "row 3 (t34)")
    ms = []
    for k, part in enumerate(parts):

        def ok(text: str, k=k) -> bool:
            e = _parse(text)
            return e is not None and _zero(e - derived[k])

        ms.append(
            Manifestation(
                f"pal-eq11-s4l3/row{k + 1}",
                f"eq. 11, {where[k]}",
                f"{part['label']} = {part['rhs']}",
                f"{('t14', 't24', 't34')[k]} = {part['rhs'].replace(_BAD, _GOOD)}",
                f"against entry ({k + 1}, 4) of 0_1T 1_2T 2_3T 3_4T 4_5T (eq. 9, the printed "
                f"matrices): printed - product = {_residual(part['rhs'], derived[k])}",
                _safe(ok),
                "pal-eq11-s4L3",
            )
        )
    arm = _arm()
    L3 = arm.params["L3"]

    def demo() -> bool:
        q = np.random.default_rng(11).uniform(-np.pi, np.pi, (500, 4))
        err = np.linalg.norm(chk.eq11_printed_position(arm, q) - arm.fk(q), axis=-1)
        ref = L3 * np.abs(np.sin(q[:, 3]) - np.cos(q[:, 3]))
        return _all_fail(ms) and np.allclose(err, ref, atol=ATOL) and err.max() > 0.5 * L3

    s4l3 = _cause(
        "pal-eq11-s4l3",
        "eq. 11 prints (s4 h - s4 L3) in all three rows; the product of the printed matrices "
        "gives (s4 h - c4 L3).",
        "error",
        "transcription",
        _found()["pal-eq11-s4L3"].evidence
        + ". The run prints 's4h-s4L3' in every row, so one slip copied three times (or a "
        "shared typeset block), not three extraction accidents.",
        ms,
        demo,
    )

    def label_ok(text: str) -> bool:
        return text.strip() in res[1]["matches"] and text.strip() in ("t14", "t24", "t34")

    label = _cause(
        "pal-eq11-label",
        "eq. 11 labels its second row t34; it is t24 (the y coordinate), as the text after "
        "eq. 10 names the three.",
        "error",
        "label",
        _found()["pal-eq11-label"].evidence,
        [
            Manifestation(
                "pal-eq11-label/row2",
                "eq. 11, row 2 label",
                "t34",
                "t24",
                "Row 2 with c4L3 equals entry (2, 4) of the printed matrices' product "
                f"({res[1]['matches']}); rows 1 and 3 are {res[0]['matches']} and "
                f"{res[2]['matches']}.",
                _safe(label_ok),
                "pal-eq11-label",
            )
        ],
    )
    return [s4l3, label]


_EQ8_CELLS = ((1, 2), (1, 3), (2, 0), (2, 1), (2, 2), (2, 3))


def _eq8() -> Cause:
    craig = link_transform_sym(S["theta_i"], S["d_i"], S["a_im1"], S["alpha_im1"], "modified")
    printed = [paper.MATRICES["eq8"]["rows"][i][j] for i, j in _EQ8_CELLS]

    def ok(text: str) -> bool:
        cells = [c.strip() for c in text.split(",")]
        if len(cells) != len(_EQ8_CELLS):
            return False
        for (i, j), c in zip(_EQ8_CELLS, cells, strict=True):
            e = _parse(c)
            if e is None or not _zero(e - craig[i, j]):
                return False
        return True

    fixed = [c.replace("(a_im1)", "(alpha_im1)") for c in printed]
    e8 = chk.eq8_checks()
    return _cause(
        "pal-eq8-glyph",
        "eq. 8 takes sin and cos of the length a_{i-1} where the twist alpha_{i-1} belongs "
        "(rows 2-3); print or extraction cannot be told apart.",
        "uncertain",
        "transcription",
        _found()["pal-eq8-glyph"].evidence,
        [
            Manifestation(
                "pal-eq8-glyph/rows-2-3",
                "eq. 8, rows 2-3 (cells (2,3), (2,4), (3,1)-(3,4))",
                ", ".join(printed),
                ", ".join(fixed),
                "Against Craig's modified link transform Rx(alpha) Tx(a) Rz(theta) Tz(d): as "
                f"printed {e8['eq8 as printed == Craig']}, with alpha for a inside sin/cos "
                f"{e8['eq8 with alpha for a in sin/cos == Craig']}. The same run extracts "
                "'cosαi-1' in row 2, so the glyph can survive; a font-mapping loss of the "
                "others cannot be excluded.",
                _safe(ok),
                "pal-eq8-glyph",
            )
        ],
    )


def register() -> Register:
    """Seed 001's register (cached by :func:`analysis.audit.register.register`)."""
    causes = [
        *_eq11(),
        _eq8(),
        *palletizer_causes_ik.causes(),
        *palletizer_causes_claims.causes(),
    ]
    return Register(
        "palletizer",
        "Li Zhaoxiang, Hu Jie, Computer Knowledge and Technology 2021 (seed 001): 4-axis "
        "palletizer",
        tuple(causes),
    )
