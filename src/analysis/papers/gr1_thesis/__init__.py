"""The GR-1 handling-arm thesis as printed, transcribed as data (nothing corrected).

Chen Huihuang (陈辉煌), *搬运机械手控制系统的设计* (Design of a handling-manipulator control
system), undergraduate thesis, Xiangtan University, School of Mechanical Engineering,
2 June 2007; supervisor Mao Meijiao. The arm is the GR-1 teaching manipulator: five
revolute joints (waist, shoulder, elbow, wrist pitch, wrist/finger roll) driven by DC
motors with optical encoders, a Mitsubishi FX2N-64MR PLC counting encoder pulses, and a
Visual Basic 6 form that computes the joint angles of a start and an end pose (Tables
5-3, 5-4) and draws cubic joint trajectories (section 5.4).

What is here, each item with its ``location`` as printed (section, table, equation,
page footer) and the printed text where it helps:

- section 2.1-2.3: :data:`ARM`, :data:`MOTOR`, :data:`TABLE2_1`, :data:`TABLE2_2`,
  :data:`TABLE2_3`, :data:`ENCODER`, :data:`PLC`;
- chapter 3 and section 4.2: :data:`RPY`, :data:`MATRICES` (eqs. 3.5-3.7, 3.15, 3.19),
  :data:`EQUATIONS` (eqs. 3.17, 3.18, the unnumbered inverse-kinematics results of
  section 4.2, eqs. 5.1-5.4) as SymPy strings over :data:`SYMBOLS`, :data:`DH_TABLE`
  (not printed: section 4.1 is empty);
- chapter 5: :data:`TABLE5_3`, :data:`TABLE5_4` (the cells as assigned, with
  :data:`TABLE5_4_EXTRACTED` and the reasoning), :data:`CUBIC`;
- the appendix "程序清单": the VB6 listing (:data:`LISTING`, :data:`LISTING_EXTRACTED`,
  :data:`LISTING_RESTORATIONS`, :data:`LISTING_BLOCK_DIFFERENCES`), the FX2N ladder
  diagram as far as it survived (:data:`LADDER_EXTRACTED`, :data:`LADDER`), the GUI input
  check (:data:`GUI_CHECK`);
- :data:`TEXT_CLAIMS` (statements the audit checks), :data:`STRUCTURE` (numbering and
  cross-reference slips of the print), :data:`LOST` and :data:`UNCERTAIN`.

Notation of the SymPy strings: ``theta1 .. theta5`` joint angles, ``theta234`` the hand
pitch theta2 + theta3 + theta4, ``a2, a3, a4`` link lengths (section 2.1: 228, 228, 73 mm;
the symbols of section 4.2), ``px, py, pz`` the target, ``n_x .. a_z`` the columns of
eq. 3.16, ``phi, theta, psi`` the RPY angles about z, y, x (the extraction lost every
Greek letter of chapter 3 to ``?``; these names are the assumed reading, see
:data:`UNCERTAIN`). ``c1, s1, c3, s3, ...`` of section 4.2 are written out as
``cos(theta1)`` etc. Angles of section 4.2 are in degrees where the print adds 180.
Cubic trajectories use :data:`CUBIC_SYMBOLS` (``a0 .. a3`` there are polynomial
coefficients, not link lengths). Parse with :func:`parse`.

Source: a text extraction of the thesis's PDF (seed 004, ``004_cea62f71caa87fb1.txt``; the
thesis runs to its line 1042; the appended translation and foreign original are not
part of this transcription). The extraction joined lines, dropped table bodies and
turned symbol-font characters (Greek letters, +, -, =, brackets) into ``?``.

The items live in one module per part of the thesis: :mod:`~analysis.papers.gr1_thesis.symbols`
(:data:`SYMBOLS`, :func:`parse`), :mod:`~analysis.papers.gr1_thesis.chapter2`,
:mod:`~analysis.papers.gr1_thesis.chapter3` (with :func:`matrix`),
:mod:`~analysis.papers.gr1_thesis.equations`, :mod:`~analysis.papers.gr1_thesis.chapter5`,
:mod:`~analysis.papers.gr1_thesis.listing` and
:mod:`~analysis.papers.gr1_thesis.listing_extracted` (the appendix listing),
:mod:`~analysis.papers.gr1_thesis.ladder` and :mod:`~analysis.papers.gr1_thesis.text`; they
are imported here, and the rest of the code names them ``analysis.papers.gr1_thesis.<NAME>``.
"""

from __future__ import annotations

from analysis.papers.gr1_thesis.chapter2 import (
    ARM,
    ENCODER,
    MOTOR,
    PLC,
    TABLE2_1,
    TABLE2_2,
    TABLE2_3,
)
from analysis.papers.gr1_thesis.chapter3 import DH_TABLE, MATRICES, RPY, matrix
from analysis.papers.gr1_thesis.chapter5 import CUBIC, TABLE5_3, TABLE5_4, TABLE5_4_EXTRACTED
from analysis.papers.gr1_thesis.equations import EQUATIONS
from analysis.papers.gr1_thesis.ladder import LADDER, LADDER_EXTRACTED
from analysis.papers.gr1_thesis.listing import (
    GUI_CHECK,
    LISTING,
    LISTING_BLOCK_DIFFERENCES,
    LISTING_RESTORATIONS,
)
from analysis.papers.gr1_thesis.listing_extracted import LISTING_EXTRACTED
from analysis.papers.gr1_thesis.symbols import CUBIC_SYMBOLS, SYMBOLS, parse
from analysis.papers.gr1_thesis.text import LOST, STRUCTURE, TEXT_CLAIMS, UNCERTAIN

__all__ = [
    "ARM",
    "CUBIC",
    "CUBIC_SYMBOLS",
    "DH_TABLE",
    "ENCODER",
    "EQUATIONS",
    "GUI_CHECK",
    "LADDER",
    "LADDER_EXTRACTED",
    "LISTING",
    "LISTING_BLOCK_DIFFERENCES",
    "LISTING_EXTRACTED",
    "LISTING_RESTORATIONS",
    "LOST",
    "MATRICES",
    "MOTOR",
    "PLC",
    "RPY",
    "SOURCE",
    "STRUCTURE",
    "SYMBOLS",
    "TABLE2_1",
    "TABLE2_2",
    "TABLE2_3",
    "TABLE5_3",
    "TABLE5_4",
    "TABLE5_4_EXTRACTED",
    "TEXT_CLAIMS",
    "UNCERTAIN",
    "matrix",
    "parse",
]

SOURCE: dict[str, str] = {
    "title": "搬运机械手控制系统的设计",
    "author": "陈辉煌 (Chen Huihuang), student no. 2003070523",
    "institution": "湘潭大学 机械工程学院 (Xiangtan University, School of Mechanical Engineering)",
    "supervisor": "毛美姣 (Mao Meijiao)",
    "date": "2007-06-02",
    "kind": "undergraduate thesis (毕业设计说明书)",
    "extraction": "seed 004 (004_cea62f71caa87fb1.txt), lines 1-1042",
}
"""Bibliographic facts from the title page and task sheet."""
