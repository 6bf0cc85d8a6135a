"""Seed 001 as printed: Li Zhaoxiang, Hu Jie (2021), *Reverse Solution of Palletizing
Manipulator Based on Geometric Method* (a 4-axis palletizer, geometric IK, modified D-H).

Data only: every printed statement the audit checks, as close to the print as a
machine-readable form allows; nothing here is corrected (the checks live in
:mod:`analysis.audit.palletizer_checks`). Imports only the standard library and SymPy.

Source: the seed's text extraction of the PDF (:data:`SOURCE`, kept outside the
repository), in which each displayed equation survived as one bracketed run of glyphs with
fraction bars, radicals, superscripts and most parentheses lost, e.g. ``[γ‘'=arctanY0X0]``
for eq. 1. Each equation below keeps that run verbatim (``extracted``), a reading in plain
notation (``printed``), a SymPy-parsable transcription of that reading (``parts``) and what
had to be inferred (``garbled``). Where two readings survive, the second is in
``alternatives``. Tables 1-3 and Figures 1-7 lost their bodies: :data:`LOST`.

Notation of the transcription (SymPy syntax, :data:`SYMBOLS`)
-------------------------------------------------------------
``theta1..theta5`` D-H joint angles (eqs. 7-12); ``gamma, alpha, beta, theta`` the motor
angles of M1..M4 (section 3: "(γ、α、β、θ)"; ``theta`` without index is M4's); ``gammap``
is γ'; ``alpha1, alpha2, beta1`` the triangle angles of eq. 3; ``X0, Y0, Z0`` the target G;
``L1, L2, L3, h`` upper arm, forearm, gripper length and gripper height; ``L1p .. L4p`` the
primed L1'..L4' of eqs. 2-3; ``H`` the undefined symbol of eq. 3; ``theta_i, alpha_im1,
a_im1, d_i`` the row symbols of eq. 8. ``atan, asin, acos, sqrt`` as usual. Lengths carry no
unit in the paper; section 5 gives the targets in metres.

The items live in :mod:`~analysis.papers.palletizer.symbols` (:data:`SYMBOLS`, :func:`parse`),
:mod:`~analysis.papers.palletizer.equations` (:data:`MATRICES`, :data:`EQUATIONS`) and
:mod:`~analysis.papers.palletizer.text` (the claims, sections, references, what was lost and
what is uncertain); they are imported here, and the rest of the code names them
``analysis.papers.palletizer.<NAME>``.
"""

from __future__ import annotations

from analysis.papers.palletizer.equations import EQUATIONS, MATRICES, equation, matrix
from analysis.papers.palletizer.symbols import SYMBOLS, parse
from analysis.papers.palletizer.text import CLAIMS, LOST, REFERENCES, SECTIONS, UNCERTAIN

__all__ = [
    "CLAIMS",
    "EQUATIONS",
    "LOST",
    "MATRICES",
    "REFERENCES",
    "SECTIONS",
    "SOURCE",
    "SYMBOLS",
    "UNCERTAIN",
    "equation",
    "matrix",
    "parse",
]

SOURCE = "001_d07c5622ca21ee76.txt"
"""The text extraction this module transcribes (outside the repository, read-only)."""
