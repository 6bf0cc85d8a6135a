"""The paper as printed, transcribed as data (Li Feng et al., Food & Machinery 2016).

Every printed statement the audit checks lives here, as close to the print as a
machine-readable form allows; nothing here is corrected. The derived counterparts come
from :mod:`analysis.kinematics.dh` / :mod:`analysis.kinematics.arm` and the verdicts from
:mod:`analysis.audit.register`.

Notation of the transcription (SymPy syntax)
--------------------------------------------
``theta1..theta3`` joint angles, ``L1..L3`` link lengths (Table 1), ``Px, Py, Pz`` the
target, ``n_x .. a_z`` the orientation columns of eq. 2, ``p_z`` the lowercase p printed
in eq. 10. ``atan`` stands for the printed single-argument ``tan^-1`` and ``acos`` for
``cos^-1``. Matrices are lists of rows of strings. Equations are ``(lhs, rhs)`` pairs.

Source: a text extraction of the paper's PDF (seed 000; the
equations survived as LaTeX, Figures 5-6 as scrambled multi-column text, see
:data:`FIGURE_STL_EXTRACTED` and :data:`FIGURE_STL`). Where the extraction leaves a
reading uncertain the item says so in :data:`UNCERTAIN`.
"""

from __future__ import annotations

import sympy as sp

from analysis.papers.grabber_stl import FIGURE_STL, FIGURE_STL_EXTRACTED

__all__ = [
    "CLAIMS",
    "EQ18_DEN",
    "EQ18_NUM",
    "EQUATIONS",
    "FIGURE_STL",
    "FIGURE_STL_EXTRACTED",
    "IMPLEMENTATION",
    "MATRICES",
    "SYMBOLS",
    "TABLE1",
    "TABLE2",
    "TABLE3",
    "TEXT_CLAIMS",
    "UNCERTAIN",
    "matrix",
    "parse",
]

# --- symbols ------------------------------------------------------------------------------
_theta = sp.symbols("theta1:4", real=True)
_L = sp.symbols("L1 L2 L3", positive=True)  # the same symbols as ArmParams.dh_table(symbolic=True)
_P = sp.symbols("Px Py Pz", real=True)
_orient = sp.symbols("n_x n_y n_z o_x o_y o_z a_x a_y a_z", real=True)
SYMBOLS: dict[str, sp.Symbol] = {
    s.name: s
    for s in (*_theta, *_L, *_P, *_orient, sp.Symbol("p_z", real=True), sp.Symbol("phi", real=True))
}
"""Every symbol the transcription uses, by name (``theta1`` ... ``p_z``, ``phi``)."""


def parse(text: str) -> sp.Expr:
    """Parse one transcribed expression with :data:`SYMBOLS` (``atan``, ``acos`` allowed).

    Raises ``ValueError`` naming the text if it does not parse or uses an unknown name.
    """
    local = dict(SYMBOLS)
    local.update({"atan": sp.atan, "acos": sp.acos, "cos": sp.cos, "sin": sp.sin, "pi": sp.pi})
    try:
        expr = sp.parse_expr(text, local_dict=local, evaluate=True)
    except Exception as exc:  # sympy raises many types for bad syntax
        raise ValueError(f"cannot parse transcribed expression {text!r}: {exc}") from None
    unknown = {s.name for s in expr.free_symbols} - set(SYMBOLS)
    if unknown:
        raise ValueError(f"expression {text!r} uses unknown name(s) {sorted(unknown)}")
    return expr


def matrix(name: str) -> sp.Matrix:
    """A printed matrix of :data:`MATRICES` as a SymPy matrix."""
    if name not in MATRICES:
        raise ValueError(f"unknown printed matrix {name!r}; expected one of {sorted(MATRICES)}")
    return sp.Matrix([[parse(e) for e in row] for row in MATRICES[name]["rows"]])


_C1, _S1 = "cos(theta1)", "sin(theta1)"
_C23, _S23 = "cos(theta2 + theta3)", "sin(theta2 + theta3)"

# --- section 1.2 and 1.3: matrices --------------------------------------------------------
MATRICES: dict[str, dict] = {
    "A1": {
        "location": "sec. 1.2 A_1",
        "rows": [
            [_C1, "0", _S1, "0"],
            [_S1, "0", f"-{_C1}", "0"],
            ["0", "1", "0", "L1"],
            ["0", "0", "0", "1"],
        ],
    },
    "A1inv": {
        "location": "sec. 1.2 A_1^-1",
        "rows": [
            [_C1, _S1, "0", "0"],
            ["0", "0", "1", "-L1"],
            [_S1, f"-{_C1}", "0", "0"],
            ["0", "0", "0", "1"],
        ],
    },
    "A2": {
        "location": "sec. 1.2 A_2",
        "rows": [
            ["cos(theta2)", "-sin(theta2)", "0", "L2*cos(theta2)"],
            ["sin(theta2)", "cos(theta2)", "0", "L2*sin(theta2)"],
            ["0", "0", "1", "0"],
            ["0", "0", "0", "1"],
        ],
    },
    "A2inv": {
        "location": "sec. 1.2 A_2^-1",
        "rows": [
            ["cos(theta2)", "sin(theta2)", "0", "-L2"],
            ["-sin(theta2)", "cos(theta2)", "0", "0"],
            ["0", "0", "1", "0"],
            ["0", "0", "0", "1"],
        ],
    },
    "A3": {
        "location": "sec. 1.2 A_3",
        "rows": [
            ["cos(theta3)", "-sin(theta3)", "0", "L3*cos(theta3)"],
            ["sin(theta3)", "cos(theta3)", "0", "L3*sin(theta3)"],
            ["0", "0", "1", "0"],
            ["0", "0", "0", "1"],
        ],
    },
    "A3inv": {
        "location": "sec. 1.2 A_3^-1",
        "rows": [
            ["cos(theta3)", "sin(theta3)", "0", "-L3"],
            ["-sin(theta3)", "cos(theta3)", "0", "0"],
            ["0", "0", "1", "0"],
            ["0", "0", "0", "1"],
        ],
    },
    # eq. 2: the elements of T3 listed under "其中"
    "T3": {
        "location": "eq. 2",
        "rows": [
            [f"{_C1}*{_C23}", f"-{_C1}*{_S23}", "0", f"L3*{_C1}*{_C23} + L2*{_C1}*cos(theta2)"],
            [
                f"{_S1}*{_C23}",
                f"-{_S1}*{_S23}",
                f"-{_C1}",
                f"L3*{_S1}*{_C23} + L2*{_S1}*cos(theta2)",
            ],
            [_S23, _C23, "0", f"L3*{_S23} + L2*sin(theta2) + L1"],
            ["0", "0", "0", "1"],
        ],
        "names": [
            ["n_x", "o_x", "a_x", "P_x"],
            ["n_y", "o_y", "a_y", "P_y"],
            ["n_z", "o_z", "a_z", "P_z"],
        ],
    },
    # eq. 4: printed without its number, labelled "A_3 A_3 =" (the text calls it 式(4))
    "eq4": {
        "location": "eq. 4",
        "label": "A_3 A_3",
        "rows": [
            [_C23, f"-{_S23}", "0", "L3*cos(theta2 + theta3) + L2*cos(theta2)"],
            [_S23, _C23, "0", "L3*sin(theta2 + theta3) + L2*sin(theta2)"],
            ["0", "0", "1", "0"],
            ["0", "0", "0", "1"],
        ],
    },
    # eq. 12: the matrix printed for A3^-1 A2^-1 A1^-1 and the right-hand side
    "eq12": {
        "location": "eq. 12",
        "rows": [
            [f"{_C1}*{_C23}", f"{_S1}*{_C23}", _S23, f"-L1*{_S23} - L2*cos(theta3) - L3"],
            [f"-{_C1}*{_S23}", f"{_S1}*{_S23}", _C23, f"-L1*{_C23} + L2*sin(theta3)"],
            [_S1, f"-{_C1}", "1", "0"],
            ["0", "0", "0", "1"],
        ],
    },
    "eq12_rhs": {
        "location": "eq. 12 right-hand side",
        "rows": [
            ["1", "0", "0", "0"],
            ["0", "1", "1", "0"],
            ["0", "0", "0", "0"],
            ["0", "0", "0", "1"],
        ],
    },
}
"""Printed matrices: ``{"A1": {"location", "rows"}, ...}``; rows are 4 lists of 4 strings."""

# --- eq. 3: the f-functions ---------------------------------------------------------------
F_FUNCTIONS: dict[str, str] = {
    # f(i) with i_x, i_y, i_z written as ix, iy, iz
    "f11": "cos(theta1)*ix + sin(theta1)*iy",
    "f12": "iz - L1",
    "f13": "sin(theta1)*ix - cos(theta1)*iy",
}
"""eq. 3 as printed: ``f1k(i)`` for ``i = n, o, a, p`` (one formula for all four)."""

# --- scalar equations ----------------------------------------------------------------------
_R = "(cos(theta1)*Px + sin(theta1)*Py)"
_K = "(L2*cos(theta3) + L3)"
EQ18_NUM = f"(Pz - L1)*{_K} + {_R}*L2*sin(theta3)"
"""The numerator of eq. 18 as printed (also in eqs. 16, 17 and 19)."""
EQ18_DEN = f"-(Pz - L1)*L2*sin(theta3) + {_R}*{_K}"
"""The denominator of eq. 18 as printed (also in eqs. 15, 17 and 19)."""
_DEN2 = f"(Pz - L1)**2 + {_R}**2"

EQUATIONS: dict[str, dict] = {
    "eq5": {
        "location": "eq. 5",
        "lhs": "sin(theta1)*Px + cos(theta1)*Py",
        "rhs": "0",
        "printed": "f13(P) = sin θ1 Px + cos θ1 Py = 0",
    },
    "eq6_phi": {
        "location": "eq. 6 (φ)",
        "lhs": "phi",
        "rhs": "atan(Py/Px)",
        "printed": "Px = ρ cos φ, Py = ρ sin φ, φ = tan^-1(Py/Px)",
    },
    "eq6": {
        "location": "eq. 6",
        "lhs": "theta1",
        "rhs": "atan(Py/Px)",
        "printed": "θ1 = φ = tan^-1(Py/Px)",
    },
    "eq7": {
        "location": "eq. 7",
        "lhs": _R,
        "rhs": "L3*cos(theta2 + theta3) + L2*cos(theta2)",
        "printed": "cos θ1 Px + sin θ1 Py = L3 cos(θ2+θ3) + L2 cos θ2",
    },
    "eq8": {
        "location": "eq. 8",
        "lhs": "Pz - L1",
        "rhs": "L3*sin(theta2 + theta3) + L2*sin(theta2)",
        "printed": "Pz - L1 = L3 sin(θ2+θ3) + L2 sin θ2",
    },
    "eq9": {
        "location": "eq. 9",
        "lhs": "Px**2 + Py**2 + (Pz - L1)**2",
        "rhs": "L3**2 + L2**2 + 2*L3*L2*sin(theta2)*sin(theta2 + theta3)"
        " + 2*L3*L2*cos(theta2)*cos(theta2 + theta3)",
        "printed": "Px² + Py² + (Pz-L1)² = L3² + L2² + 2L3L2 sin θ2 sin(θ2+θ3) + 2L3L2 cos θ2 cos(θ2+θ3)",  # noqa: E501
    },
    "eq10": {
        "location": "eq. 10",
        "lhs": "theta3",
        "rhs": "acos(((p_z - L1)**2 + cos(theta1)**2*Px**2 + 2*cos(theta1)*sin(theta1)*Px*Py"
        " + sin(theta1)**2*Py**2 - L3**2 - L2**2)/(2*L3*L2))",
        "printed": "θ3 = cos^-1 1/(2L3L2)[(p_z-L1)² + cos²θ1 Px² + 2cosθ1 sinθ1 PxPy + sin²θ1 Py² - L3² - L2²]",  # noqa: E501
    },
    "eq13": {
        "location": "eq. 13",
        "lhs": "cos(theta1)*cos(theta2 + theta3)*Px + sin(theta1)*cos(theta2 + theta3)*Py"
        " + sin(theta2 + theta3)*Pz - sin(theta2 + theta3)*L1 - L2*cos(theta3) - L2",
        "rhs": "0",
        "printed": "cosθ1 cos(θ2+θ3) Px + sinθ1 cos(θ2+θ3) Py + sin(θ2+θ3) Pz - sin(θ2+θ3) L1 - L2 cosθ3 - L2 = 0",  # noqa: E501
    },
    "eq14": {
        "location": "eq. 14",
        "lhs": "-cos(theta1)*sin(theta2 + theta3)*Px + sin(theta1)*cos(theta2 + theta3)*Py"
        " + cos(theta2 + theta3)*Pz - cos(theta2 + theta3)*L1 + L2*sin(theta3)",
        "rhs": "0",
        "printed": "-cosθ1 sin(θ2+θ3) Px + sinθ1 cos(θ2+θ3) Py + cos(θ2+θ3) Pz - cos(θ2+θ3) L1 + L2 sinθ3 = 0",  # noqa: E501
    },
    "eq15": {
        "location": "eq. 15",
        "lhs": "cos(theta2 + theta3)",
        "rhs": f"({EQ18_DEN})/({_DEN2})",
        "printed": "cos(θ2+θ3) = [-(Pz-L1) L2 sinθ3 + (cosθ1 Px + sinθ1 Py)(L2 cosθ3 + L3)] / [(Pz-L1)² + (cosθ1 Px + sinθ1 Py)²]",  # noqa: E501
    },
    "eq16": {
        "location": "eq. 16",
        "lhs": "sin(theta2 + theta3)",
        "rhs": f"({EQ18_NUM})/({_DEN2})",
        "printed": "sin(θ2+θ3) = [(Pz-L1)(L2 cosθ3 + L3) + (cosθ1 Px + sinθ1 Py) L2 sinθ3] / [(Pz-L1)² + (cosθ1 Px + sinθ1 Py)²]",  # noqa: E501
    },
    "eq17": {
        "location": "eq. 17",
        "lhs": "sin(theta2 + theta3)/cos(theta2 + theta3)",
        "rhs": f"({EQ18_NUM})/({EQ18_DEN})",
        "printed": "tan(θ2+θ3) = [(Pz-L1)(L2 cosθ3 + L3) + (cosθ1 Px + sinθ1 Py) L2 sinθ3] / [-(Pz-L1) L2 sinθ3 + (cosθ1 Px + sinθ1 Py)(L2 cosθ3 + L3)]",  # noqa: E501
    },
    "eq18": {
        "location": "eq. 18",
        "lhs": "theta2 + theta3",
        "rhs": f"atan(({EQ18_NUM})/({EQ18_DEN}))",
        "printed": "θ23 = θ2 + θ3 = tan^-1 { [(Pz-L1)(L2 cosθ3 + L3) + (cosθ1 Px + sinθ1 Py) L2 sinθ3] / [...] }",  # noqa: E501
    },
    "eq19": {
        "location": "eq. 19",
        "lhs": "theta2",
        "rhs": f"atan(({EQ18_NUM})/({EQ18_DEN})) - theta3",
        "printed": "θ2 = θ23 - θ3 = tan^-1 {...} - θ3",
    },
}
"""Printed scalar equations of section 1.3, ``{"eq5": {"location", "lhs", "rhs", "printed"}}``."""

PULSE_EQUATIONS: dict[str, dict] = {
    f"eq{n}": {"location": f"eq. {n}", "joint": j, "text": f"c = θ{j}/360 × 4000"}
    for n, j in ((20, 1), (21, 2), (22, 3))
}
"""eqs. 20-22 as printed: ``c = theta_j / 360 * 4000`` (theta in degrees, no rounding rule)."""

# --- statements in running text --------------------------------------------------------------
TEXT_CLAIMS: dict[str, dict] = {
    "eq4_label": {"location": "eq. 4 label", "printed": "A_3 A_3 =", "product": ("A3", "A3")},
    "eq4_row3col4": {
        "location": "text after eq. 4",
        "printed": "式(4)中第3行第4列的元素为常数 (row 3 col 4 of eq. 4 is a constant)",
        "row": 2,
        "col": 3,
    },
    "eq6_xref": {
        "location": "text before eq. 6",
        "printed": "结合工程实际, 取式(16)",
        "refers_to": 16,
        "must_define": "theta1",
    },
    "sec14_xref": {
        "location": "sec. 1.4",
        "printed": "选取式(6)、(10)和(19)确定导航定位解",
        "refers_to": (6, 10, 19),
        "must_define": ("theta1", "theta3", "theta2"),
    },
    "theta1_two_solutions": {
        "location": "text after eq. 5",
        "printed": "sin(θ1 - φ) = 0, θ1 = φ or π + φ",
    },
    "sec3_lengths": {
        "location": "sec. 3 text",
        "printed": "臂长分别为 660, 310, 200 mm",
        "values": (660.0, 310.0, 200.0),
    },
    "sec3_resolution": {
        "location": "sec. 3 text",
        "printed": "细分数为 4 000, 则各关节旋转精度 ... 可达到 0.09°",
        "pulses_per_rev": 4000,
        "resolution_deg": 0.09,
    },
    "sec241_target": {
        "location": "sec. 2.4.1 text",
        "printed": "取 (100, 100, 600) 为例",
        "target": (100.0, 100.0, 600.0),
    },
}
"""Checkable claims made in the running text (labels, cross-references, numbers)."""

# --- Tables 1 and 3 -------------------------------------------------------------------------
TABLE1: list[dict] = [
    {
        "link": "腰部 waist",
        "theta": "theta1",
        "alpha_deg": 90,
        "a": "0",
        "d": "L1",
        "cos_alpha": 0,
        "sin_alpha": 1,
    },
    {
        "link": "肩部 shoulder",
        "theta": "theta2",
        "alpha_deg": 0,
        "a": "L2",
        "d": "0",
        "cos_alpha": 1,
        "sin_alpha": 0,
    },
    {
        "link": "肘部 elbow",
        "theta": "theta3",
        "alpha_deg": 0,
        "a": "L3",
        "d": "0",
        "cos_alpha": 1,
        "sin_alpha": 0,
    },
]
"""Table 1 (D-H parameters) as printed."""

TABLE3: list[dict] = [
    {
        "link": "腰部 waist",
        "alpha_deg": 90,
        "a_mm": 0,
        "d_mm": 660,
        "cos_alpha": 0,
        "sin_alpha": 1,
        "step_angle_deg": 1.8,
        "resolution_deg": 0.09,
    },
    {
        "link": "肩部 shoulder",
        "alpha_deg": 0,
        "a_mm": 310,
        "d_mm": 0,
        "cos_alpha": 1,
        "sin_alpha": 0,
        "step_angle_deg": 1.8,
        "resolution_deg": 0.09,
    },
    {
        "link": "肘部 elbow",
        "alpha_deg": 0,
        "a_mm": 200,
        "d_mm": 0,
        "cos_alpha": 1,
        "sin_alpha": 0,
        "step_angle_deg": 1.8,
        "resolution_deg": 0.09,
    },
]
"""Table 3 as printed (also in ``data/table3.csv``; a test holds the two equal)."""


# --- section 2: the implementation as described --------------------------------------------
TABLE2: dict[str, list[tuple[str, str, str]]] = {
    "inputs": [("运行按钮", "SB1", "I0.0"), ("停止按钮", "SB2", "I0.1")],
    "outputs": [
        ("脉冲信号", "", "Q0.0"),
        ("脉冲信号", "", "Q0.1"),
        ("方向信号", "", "Q0.2"),
        ("继电器", "KM1", "Q0.3"),
        ("继电器", "KM2", "Q0.4"),
        ("方向信号", "", "Q0.5"),
        ("方向信号", "", "Q0.7"),
    ],
}
"""Table 2 (I/O allocation) as printed: (name, code, address) for inputs and outputs."""

IMPLEMENTATION: dict[str, dict] = {
    "cpu": {"location": "sec. 2.3", "printed": "选择了 S7-200-CPU224", "cpu": "CPU 224"},
    "motors": {
        "location": "sec. 2.3",
        "printed": "腰部和肩部电机选用 86HS45 步进电机, 驱动器采用 DM556 驱动器, "
        "肘部采用雷赛 57HS09 步进电机, 驱动器采用 DM442 驱动器",
        "steppers": 3,
    },
    "start": {
        "location": "sec. 2.1",
        "printed": "按下启动按钮 SB1, 程序自动计算每个臂的旋转角度, 并将旋转角度给到对应关节中",
        "start_input": "I0.0",
    },
    "pto": {
        "location": "sec. 2.4.2",
        "printed": "在求出 θ1 后, 还需要将角度转换成 PTO 脉冲数, 才能使步进电机完成相应动作",
    },
    "input": {
        "location": "sec. 3",
        "printed": "目标坐标的输入可采用人机界面或 PC 机输入, 输入后按下启动, 则机器人自动导航",
    },
}
"""What section 2 says the program and the hardware do (checked by the implementation audit)."""

CLAIMS: dict[str, dict] = {
    "accuracy": {
        "location": "sec. 3; conclusion (4)",
        "printed": "各关节旋转精度在没有扰动的情况下可达到 0.09°; "
        "本导航系统导航精度高, 导航精度每关节可达到 0.09°",
    },
    "table4_measured": {
        "location": "sec. 3, before Table 4",
        "printed": "经过实际操作, 试验用机器人实际导航参数见表 4",
    },
    "efficient_stable": {
        "location": "abstract; sec. 3; conclusion (3)",
        "printed": "验证了物料抓取机器人导航系统的高效性和稳定性; 试验工作状况良好; "
        "响应速度快, 导航效果好, 降低了操作工人的工作量, 提高了生产效率",
        "measurements": (),
    },
}
"""The paper's claims about its results, verbatim (the claims audit gives each a verdict).
``measurements`` lists the data the paper reports for a claim: none."""


UNCERTAIN: dict[str, str] = {
    "eq. 4 number": "eq. 4 is printed without a number; the text refers to it as 式(4).",
    "eq. 12 right-hand side": "the printed [[1,0,0,0],[0,1,1,0],[0,0,0,0],[0,0,0,1]] may be a "
    "misplaced 1 in the typesetting or in the extraction; either way it is not E (eq. 11).",
    "eqs. 15-19": "the extraction repeats eqs. 15-19 twice (two-column reflow); both copies are identical.",  # noqa: E501
    "eq. 10 p_z": "lowercase p_z in eq. 10 may be the extraction's, not the print's.",
    "Figure 5": "three printed columns interleaved line by line; reading order, AENO counts and "
    "the placement of 'MOVR 310.0, VD68' and 'MOVR VD88, VD96' are inferred; the CALL ARCTAN "
    "output operand and one MOVR mnemonic are lost.",
    "Figure 6": "five interleaved columns; the load of VD44, the cos^2 theta1 Px^2 term, the "
    "operands of '/R' and any '/R 360.0' are not in the extraction; whether VDD0 is a typo "
    "for VD0 (Px) or VD12 (theta1) cannot be decided from the text.",
    "Table 4 row 1 theta2 last digit": "190.20 vs 190.21 from the reproduced formula: truncation "
    "reproduces it but contradicts other cells (71.565 printed as 71.57).",
    "Table 4 row 9 theta3": "-91.20 is reproduced by no evaluation tried "
    "(see analysis.audit.table4).",
}
"""What the text extraction leaves undecidable, by item."""
