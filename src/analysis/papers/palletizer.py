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
"""

from __future__ import annotations

import sympy as sp

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

# --- symbols ------------------------------------------------------------------------------
_NAMES_REAL = (
    "theta1 theta2 theta3 theta4 theta5 gamma gammap alpha beta theta alpha1 alpha2 beta1 "
    "X0 Y0 Z0 H theta_i alpha_im1"
)
_NAMES_POSITIVE = "L1 L2 L3 L4 h L1p L2p L3p L4p"
_NAMES_ANY = "a_im1 d_i"  # lengths of eq. 8 may be zero
SYMBOLS: dict[str, sp.Symbol] = {
    s.name: s
    for s in (
        *sp.symbols(_NAMES_REAL, real=True),
        *sp.symbols(_NAMES_POSITIVE, positive=True),
        *sp.symbols(_NAMES_ANY, real=True),
    )
}
"""Every symbol the transcription uses, by name."""

_FUNCTIONS = {
    "atan": sp.atan,
    "asin": sp.asin,
    "acos": sp.acos,
    "sqrt": sp.sqrt,
    "cos": sp.cos,
    "sin": sp.sin,
    "pi": sp.pi,
    "Piecewise": sp.Piecewise,
}


def parse(text: str) -> sp.Expr:
    """Parse one transcribed expression with :data:`SYMBOLS` (``atan``, ``asin``, ``acos``,
    ``sqrt``, ``Piecewise`` allowed).

    Raises ``ValueError`` naming the text if it does not parse or uses an unknown name.
    """
    local = {**SYMBOLS, **_FUNCTIONS}
    try:
        expr = sp.parse_expr(text, local_dict=local, evaluate=True)
    except Exception as exc:  # sympy raises many types for bad syntax
        raise ValueError(f"cannot parse transcribed expression {text!r}: {exc}") from None
    unknown = {s.name for s in expr.free_symbols} - set(SYMBOLS)
    if unknown:
        raise ValueError(f"expression {text!r} uses unknown name(s) {sorted(unknown)}")
    return expr


# --- section 4.2: the five printed matrices (and eq. 8) -------------------------------------
_C = {i: f"cos(theta{i})" for i in range(1, 5)}
_S = {i: f"sin(theta{i})" for i in range(1, 5)}

MATRICES: dict[str, dict] = {
    "eq8": {
        "location": "eq. 8 (general link transform i-1_iT)",
        "extracted": "[i-1iT=cosθi-sinθi0ai-1sinθicosαi-1cosθicosαi-1-sinai-1-disinai-1"
        "sinθisinai-1cosθisinai-1cosai-1dicosai-10001]",
        "garbled": "α_{i-1} survives in row 2 col 1-2 ('cosαi-1') but reads 'a' in rows 2-3 "
        "('-sinai-1', 'cosai-1'); transcribed as printed with a_im1 there (see UNCERTAIN).",
        "rows": [
            ["cos(theta_i)", "-sin(theta_i)", "0", "a_im1"],
            [
                "sin(theta_i)*cos(alpha_im1)",
                "cos(theta_i)*cos(alpha_im1)",
                "-sin(a_im1)",
                "-d_i*sin(a_im1)",
            ],
            [
                "sin(theta_i)*sin(a_im1)",
                "cos(theta_i)*sin(a_im1)",
                "cos(a_im1)",
                "d_i*cos(a_im1)",
            ],
            ["0", "0", "0", "1"],
        ],
    },
    "T01": {
        "location": "sec. 4.2, 0_1T",
        "extracted": "[01T=cosθ1-sinθ100sinθ1cosθ10000100001]",
        "rows": [
            [_C[1], f"-{_S[1]}", "0", "0"],
            [_S[1], _C[1], "0", "0"],
            ["0", "0", "1", "0"],
            ["0", "0", "0", "1"],
        ],
    },
    "T12": {
        "location": "sec. 4.2, 1_2T",
        "extracted": "[12T=cosθ2-sinθ2000010-sinθ2-cosθ2000001]",
        "rows": [
            [_C[2], f"-{_S[2]}", "0", "0"],
            ["0", "0", "1", "0"],
            [f"-{_S[2]}", f"-{_C[2]}", "0", "0"],
            ["0", "0", "0", "1"],
        ],
    },
    "T23": {
        "location": "sec. 4.2, 2_3T",
        "extracted": "[23T=cosθ3-sinθ30L1sinθ3cosθ30000100001]",
        "rows": [
            [_C[3], f"-{_S[3]}", "0", "L1"],
            [_S[3], _C[3], "0", "0"],
            ["0", "0", "1", "0"],
            ["0", "0", "0", "1"],
        ],
    },
    "T34": {
        "location": "sec. 4.2, 3_4T",
        "extracted": "[34T=cosθ4-sinθ40L2sinθ4cosθ40000100001]",
        "rows": [
            [_C[4], f"-{_S[4]}", "0", "L2"],
            [_S[4], _C[4], "0", "0"],
            ["0", "0", "1", "0"],
            ["0", "0", "0", "1"],
        ],
    },
    "T45": {
        "location": "sec. 4.2, 4_5T (after 'θ5=0')",
        "extracted": "[45T=100h00-1-L301000001]",
        "rows": [
            ["1", "0", "0", "h"],
            ["0", "0", "-1", "-L3"],
            ["0", "1", "0", "0"],
            ["0", "0", "0", "1"],
        ],
    },
}
"""Printed matrices: eq. 8 and the five link transforms of section 4.2 (lists of 4 rows of 4
strings), each with its verbatim extracted run."""


def matrix(name: str) -> sp.Matrix:
    """A printed matrix of :data:`MATRICES` as a SymPy matrix."""
    if name not in MATRICES:
        raise ValueError(f"unknown printed matrix {name!r}; expected one of {sorted(MATRICES)}")
    return sp.Matrix([[parse(e) for e in row] for row in MATRICES[name]["rows"]])


# --- eqs. 1-12 ----------------------------------------------------------------------------
_A = "(c4h + s4L3 + L2)"
_B = "(s4h - s4L3)"


def _c(i: int) -> str:
    return f"cos(theta{i})"


def _s(i: int) -> str:
    return f"sin(theta{i})"


_F1 = f"({_c(4)}*h + {_s(4)}*L3 + L2)"
_F2 = f"({_s(4)}*h - {_s(4)}*L3)"

EQUATIONS: dict[str, dict] = {
    "eq1": {
        "location": "eq. 1",
        "extracted": "[γ‘'=arctanY0X0]",
        "printed": "γ' = arctan(Y0/X0)",
        "parts": [{"lhs": "gammap", "rhs": "atan(Y0/X0)"}],
        "garbled": "the fraction bar is lost (Y0 over X0 read as Y0/X0); ‘' are the prime.",
    },
    "eq2": {
        "location": "eq. 2",
        "extracted": "[L'4‘=X02+Y02-L3'2+Z0+h2]",
        "printed": "L4' = sqrt((sqrt(X0² + Y0²) - L3')² + (Z0 + h)²)",
        "parts": [{"lhs": "L4p", "rhs": "sqrt((sqrt(X0**2 + Y0**2) - L3p)**2 + (Z0 + h)**2)"}],
        "alternatives": {
            "literal": {"lhs": "L4p", "rhs": "X0**2 + Y0**2 - L3p**2 + Z0 + h**2"},
        },
        "garbled": "both radicals, the parentheses and the superscripts are lost: '2' after "
        "X0, Y0, L3' and h are exponents. The grouping is inferred from the figure's "
        "triangle (horizontal leg sqrt(X0²+Y0²) - L3', vertical leg Z0 + h); the literal "
        "run adds mm² to mm.",
    },
    "eq3": {
        "location": "eq. 3",
        "extracted": "[α1=arccosL1'2+L4'2-L2'22·L1'·L4'α2=arcsinHL4'β1=L1'2+L2'2-L4'22L1'·L2']",
        "printed": "α1 = arccos((L1'² + L4'² - L2'²)/(2·L1'·L4')); α2 = arcsin(H/L4'); "
        "β1 = (L1'² + L2'² - L4'²)/(2L1'·L2')",
        "parts": [
            {"lhs": "alpha1", "rhs": "acos((L1p**2 + L4p**2 - L2p**2)/(2*L1p*L4p))"},
            {"lhs": "alpha2", "rhs": "asin(H/L4p)"},
            {"lhs": "beta1", "rhs": "(L1p**2 + L2p**2 - L4p**2)/(2*L1p*L2p)"},
        ],
        "garbled": "fraction bars and exponents lost. H is used and never defined. β1 has no "
        "arccos: the run keeps 'arccos' for α1 and 'arcsin' for α2, so the omission is "
        "probably the print's (UNCERTAIN).",
    },
    "eq4": {
        "location": "eq. 4",
        "extracted": "[α=π2-α1+α2? β=π2-β1]",
        "printed": "α = π/2 - α1 + α2; β = π/2 - β1",
        "parts": [
            {"lhs": "alpha", "rhs": "pi/2 - alpha1 + alpha2"},
            {"lhs": "beta", "rhs": "pi/2 - beta1"},
        ],
        "garbled": "'π2' is π/2 (fraction bar lost); '?' is a lost space.",
    },
    "eq5": {
        "location": "eq. 5",
        "extracted": "[θ=-α+β]",
        "printed": "θ = -α + β",
        "parts": [{"lhs": "theta", "rhs": "-alpha + beta"}],
        "garbled": "",
    },
    "eq6": {
        "location": "eq. 6",
        "extracted": "[][γ=γ'X0>0π-γ'X0≤0,Y0>0-π2+γ'X0≤0,Y0<0]",
        "printed": "γ = γ' (X0 > 0); π - γ' (X0 ≤ 0, Y0 > 0); -π/2 + γ' (X0 ≤ 0, Y0 < 0)",
        "parts": [
            {
                "lhs": "gamma",
                "rhs": "Piecewise((gammap, X0 > 0), (pi - gammap, (X0 <= 0) & (Y0 > 0)), "
                "(-pi/2 + gammap, (X0 <= 0) & (Y0 < 0)))",
            }
        ],
        "garbled": "the brace and line breaks of the case list are lost; '-π2' read as -π/2 "
        "as elsewhere in the run (eqs. 4, 12). No case is printed for X0 ≤ 0, Y0 = 0.",
    },
    "eq7": {
        "location": "eq. 7",
        "extracted": "[θ0T=0-π2π2π20T]",
        "printed": "θ⁰ = [0, -π/2, π/2, π/2, 0]^T (the pose of Figure 5)",
        "parts": [
            {"lhs": "theta1", "rhs": "0"},
            {"lhs": "theta2", "rhs": "-pi/2"},
            {"lhs": "theta3", "rhs": "pi/2"},
            {"lhs": "theta4", "rhs": "pi/2"},
            {"lhs": "theta5", "rhs": "0"},
        ],
        "garbled": "the column vector is flattened; the split into five entries "
        "0, -π/2, π/2, π/2, 0 is inferred (five frames 1..5 in section 4.2).",
    },
    "eq8": {
        "location": "eq. 8",
        "extracted": MATRICES["eq8"]["extracted"],
        "printed": "i-1_iT = [[cθi, -sθi, 0, a_{i-1}], [sθi cα_{i-1}, cθi cα_{i-1}, "
        "-s a_{i-1}, -d_i s a_{i-1}], [sθi s a_{i-1}, cθi s a_{i-1}, c a_{i-1}, "
        "d_i c a_{i-1}], [0, 0, 0, 1]]",
        "parts": [{"lhs": "matrix:eq8", "rhs": "matrix:eq8"}],
        "garbled": MATRICES["eq8"]["garbled"],
    },
    "eq9": {
        "location": "eq. 9",
        "extracted": "[05T=01T12T23T34T45T]",
        "printed": "0_5T = 0_1T 1_2T 2_3T 3_4T 4_5T",
        "parts": [{"lhs": "T05", "rhs": "T01*T12*T23*T34*T45"}],
        "garbled": "",
    },
    "eq10": {
        "location": "eq. 10",
        "extracted": "[05T=t11t12t13t14t21t22t23t24t31t32t33t34t41t42t43t44](10)",
        "printed": "0_5T = [t_ij], i, j = 1..4; t14, t24, t34 the gripper tip (x5, y5, z5)",
        "parts": [],
        "garbled": "",
    },
    "eq11": {
        "location": "eq. 11",
        "extracted": "[t14=c1c2c3-c1s2s3(c4h+s4L3+L2)-c1c2s3+c1s2c3s4h-s4L3+c1c2L1"
        "t34=s1c2c3-s1s2s3(c4h+s4L3+L2)-(s1c2s3+s1s2c3)s4h-s4L3+s1c2L1"
        "t34=-(s2c3+c2s3)(c4h+s4L3+L2)+(s2s3-c2c3)s4h-s4L3-s2L1]",
        "printed": f"t14 = (c1c2c3 - c1s2s3){_A} - (c1c2s3 + c1s2c3){_B} + c1c2L1; "
        f"t34 = (s1c2c3 - s1s2s3){_A} - (s1c2s3 + s1s2c3){_B} + s1c2L1; "
        f"t34 = -(s2c3 + c2s3){_A} + (s2s3 - c2c3){_B} - s2L1",
        "parts": [
            {
                "label": "t14",
                "lhs": "t14",
                "rhs": f"({_c(1)}*{_c(2)}*{_c(3)} - {_c(1)}*{_s(2)}*{_s(3)})*{_F1}"
                f" - ({_c(1)}*{_c(2)}*{_s(3)} + {_c(1)}*{_s(2)}*{_c(3)})*{_F2}"
                f" + {_c(1)}*{_c(2)}*L1",
            },
            {
                "label": "t34",
                "lhs": "t34",
                "rhs": f"({_s(1)}*{_c(2)}*{_c(3)} - {_s(1)}*{_s(2)}*{_s(3)})*{_F1}"
                f" - ({_s(1)}*{_c(2)}*{_s(3)} + {_s(1)}*{_s(2)}*{_c(3)})*{_F2}"
                f" + {_s(1)}*{_c(2)}*L1",
            },
            {
                "label": "t34",
                "lhs": "t34",
                "rhs": f"-({_s(2)}*{_c(3)} + {_c(2)}*{_s(3)})*{_F1}"
                f" + ({_s(2)}*{_s(3)} - {_c(2)}*{_c(3)})*{_F2}"
                f" - {_s(2)}*L1",
            },
        ],
        "garbled": "parentheses partly lost: row 1 lost those of (c1c2c3 - c1s2s3) and "
        "(c1c2s3 + c1s2c3), rows 1-2 lost those of (c1c2c3 - ...) and (s1c2c3 - ...), every "
        "row lost those of (s4h - s4L3); they are restored by analogy with the rows that "
        "kept them (row 2: -(s1c2s3+s1s2c3), row 3: -(s2c3+c2s3), (s2s3-c2c3)). The run "
        "prints 's4h-s4L3' in all three rows and labels rows 2 and 3 both 't34'.",
    },
    "eq12": {
        "location": "eq. 12",
        "extracted": "[θ1=γθ2=-π2-αθ3=π2+βθ4=π2-θ2+θ3]",
        "printed": "θ1 = γ; θ2 = -π/2 - α; θ3 = π/2 + β; θ4 = π/2 - θ2 + θ3",
        "parts": [
            {"lhs": "theta1", "rhs": "gamma"},
            {"lhs": "theta2", "rhs": "-pi/2 - alpha"},
            {"lhs": "theta3", "rhs": "pi/2 + beta"},
            {"lhs": "theta4", "rhs": "pi/2 - theta2 + theta3"},
        ],
        "garbled": "'π2' is π/2. θ4 = π/2 - θ2 + θ3 as extracted; the run lost parentheses "
        "elsewhere (eq. 11), so π/2 - (θ2 + θ3) may have been printed (UNCERTAIN).",
    },
}
"""Eqs. 1-12: ``{"eq1": {"location", "extracted", "printed", "parts", "garbled"}}``; each part
is ``{"lhs", "rhs"}`` (SymPy text; eq. 11 parts also carry the printed ``label``)."""


def equation(key: str) -> list[tuple[sp.Expr, sp.Expr]]:
    """The parts of a printed equation as ``(lhs, rhs)`` SymPy pairs (not for eqs. 8-10,
    which are matrices: use :func:`matrix`)."""
    if key not in EQUATIONS:
        raise ValueError(f"unknown equation {key!r}; expected one of {sorted(EQUATIONS)}")
    if key in ("eq8", "eq9", "eq10"):
        raise ValueError(f"{key} is a matrix equation; use matrix() and MATRICES")
    t = {f"t{i}{j}": sp.Symbol(f"t{i}{j}", real=True) for i in range(1, 5) for j in range(1, 5)}
    out = []
    for part in EQUATIONS[key]["parts"]:
        lhs = t[part["lhs"]] if part["lhs"] in t else parse(part["lhs"])
        out.append((lhs, parse(part["rhs"])))
    return out


# --- statements in running text ---------------------------------------------------------------
CLAIMS: dict[str, dict] = {
    "isosceles": {
        "extracted": [
            "已知目標(biāo)點(diǎn)、大臂、小臂參數(shù),那么一定可以構(gòu)成如圖3中紅色虛線部分所示的等腰三角形",
            "至此,圖3中的等腰三角形三邊長(zhǎng)均已知",
        ],
        "location": "sec. 3, before eq. 1 and after eq. 2",
        "printed": "已知目標點、大臂、小臂參數,那麼一定可以構成如圖3中紅色虛線部分所示的等腰三角形"
        " ... 至此,圖3中的等腰三角形三邊長均已知",
        "meaning": "given the target and the arm lengths, the red dashed triangle of Figure 3 "
        "(sides L1', L2', L4') can always be formed and is isosceles",
    },
    "unique_pose": {
        "extracted": [
            "械結(jié)構(gòu)的限制,小臂和大臂之間的夾角小于900,所以其抓取時(shí)的位置狀態(tài)是唯一的"
        ],
        "location": "sec. 2, third paragraph",
        "printed": "因為機械結構的限制,小臂和大臂之間的夾角小於900,所以其抓取時的位置狀態是唯一的",
        "meaning": "the angle between forearm and upper arm is below 90° (printed '900', the "
        "degree sign extracted as 0), therefore the grasping pose is unique",
        "limit_deg": 90.0,
    },
    "fk_equals_target": {
        "extracted": [
            "編碼測(cè)試[9],基于幾何法的碼垛機(jī)械臂逆向求解方法得出的角度帶入D-H正向解算公式的結(jié)果完全等于待抓取點(diǎn)Gi"
        ],
        "location": "sec. 5, last paragraph",
        "printed": "基於幾何法的碼垛機械臂逆向求解方法得出的角度帶入D-H正向解算公式的"
        "結果完全等於待抓取點Gi",
        "meaning": "eq. 11 evaluated at the eq. 12 angles of the IK (eqs. 1-6) equals the "
        "target G_i exactly, for all four targets",
    },
    "targets_in_metres": {
        "extracted": ["表中Gi和Ti的單位為米(m),角度單位為度"],
        "location": "sec. 5, second paragraph",
        "printed": "表中Gi和Ti的單位為米(m),角度單位為度",
        "meaning": "Tables 2-3 give G_i and T_i in metres, angles in degrees",
        "unit": "m",
    },
    "four_quadrants": {
        "extracted": [
            "在Z軸正方向所在的空間分別選擇了四個(gè)待抓取目標(biāo)點(diǎn),分別所處四個(gè)不同象限"
        ],
        "location": "sec. 5, second paragraph",
        "printed": "在Z軸正方向所在的空間分別選擇了四個待抓取目標點,分別所處四個不同象限",
        "meaning": "four targets with Z > 0, one in each quadrant of the XOY plane",
        "n_targets": 4,
    },
    "quadrant_rule": {
        "extracted": [
            "G投影位于一、二象限時(shí),電機(jī)M1為向左正轉(zhuǎn),反之三、四象限為反轉(zhuǎn)"
        ],
        "location": "sec. 3, before eq. 6",
        "printed": "當G投影位於一、二象限時,電機M1為向左正轉,反之三、四象限為反轉",
        "meaning": "gamma > 0 (M1 turns left) in quadrants 1-2, gamma < 0 in quadrants 3-4",
    },
    "sign_conventions": {
        "extracted": [
            "γ>0表示M1左轉(zhuǎn);α>0表示M2繞坐標(biāo)軸+Y2順時(shí)針旋轉(zhuǎn)、β>0表示M3繞坐標(biāo)軸+Y3旋轉(zhuǎn)順時(shí)針旋轉(zhuǎn);θ>0表示M4繞坐標(biāo)+Y4軸旋轉(zhuǎn)"
        ],
        "location": "sec. 3, second paragraph",
        "printed": "γ>0表示M1左轉;α>0表示M2繞坐標軸+Y2順時針旋轉、"
        "β>0表示M3繞坐標軸+Y3旋轉順時針旋轉;θ>0表示M4繞坐標+Y4軸旋轉。",
        "meaning": "alpha and beta are both clockwise about +Y2, +Y3 (axes drawn in the lost "
        "Figure 2); theta's sense about +Y4 is not stated",
    },
    "initial_pose": {
        "extracted": ["位于初始位置時(shí),大臂與基座保持垂直,小臂與大臂保持垂直"],
        "location": "sec. 3, second paragraph",
        "printed": "機械臂位於初始位置時,大臂與基座保持垂直,小臂與大臂保持垂直",
        "meaning": "at the initial pose (all motor angles 0) the upper arm is vertical and the "
        "forearm perpendicular to it",
    },
    "gripper_level": {
        "extracted": [
            "末端抓手始終與基座所處的平面保持平行",
            "X5和X4軸之間的方向永遠(yuǎn)保持不變,即:θ5=0",
        ],
        "location": "sec. 3 (assumptions) and sec. 4.2 (before 4_5T)",
        "printed": "末端抓手始終與基座所處的平面保持平行 ... "
        "X5和X4軸之間的方向永遠保持不變,即:θ5=0",
        "meaning": "the gripper stays parallel to the base plane; theta5 = 0",
    },
    "gripper_geometry": {
        "extracted": [
            "大臂、小臂、末端夾具的長(zhǎng)度分別為:L1、L2、L3",
            "末端夾具的垂直高度是h",
        ],
        "location": "sec. 2 and sec. 3",
        "printed": "大臂、小臂、末端夾具的長度分別為:L1、L2、L3 ... 末端夾具的垂直高度是h",
        "meaning": "L1, L2, L3 are the lengths of upper arm, forearm and gripper; h is the "
        "vertical height of the L-shaped gripper",
    },
    "shoulder_at_origin": {
        "extracted": ["上述坐標(biāo)系0、1、2的坐標(biāo)原點(diǎn)重合,故L0=0"],
        "location": "sec. 4.1",
        "printed": "上述坐標系0、1、2的坐標原點重合,故L0=0",
        "meaning": "frames 0, 1, 2 share their origin: the shoulder is at the base origin",
    },
    "xref_section": {
        "extracted": ["第2節(jié)中的逆向解算方法求出的角度(γ、α、β、θ)"],
        "location": "sec. 5, third paragraph",
        "printed": "第2節中的逆向解算方法求出的角度(γ、α、β、θ)",
        "refers_to_section": 2,
        "meaning": "the angles come from the IK method of section 2",
    },
    "xref_reference": {
        "extracted": ["參照第5篇文獻(xiàn)簡(jiǎn)述的方法[6]"],
        "location": "sec. 4.1",
        "printed": "參照第5篇文獻簡述的方法[6]",
        "refers_to_reference": (5, 6),
        "meaning": "the method of 'the 5th reference', cited as [6]",
    },
    "eq12_purpose": {
        "extracted": [
            "在帶入式(11)時(shí),需要結(jié)合D-H參數(shù)法中θi的幾何意義對(duì)其轉(zhuǎn)換"
        ],
        "location": "sec. 5, before eq. 12",
        "printed": "在帶入式(11)時,需要結合D-H參數法中θi的幾何意義對其轉換",
        "meaning": "eq. 12 converts the motor angles (gamma, alpha, beta, theta) to D-H theta_i",
    },
}
"""Checkable claims of the running text: ``extracted`` holds the verbatim runs of the seed
(which carries pinyin readings in parentheses after some characters, e.g. 目標(biāo), and
mis-decoded characters such as 因?yàn)闄C for 因為機); ``printed`` is the same text read
without those artefacts; ``meaning`` is ours."""

SECTIONS: dict[int, str] = {
    1: "引言 (Introduction)",
    2: "機械臂模型的簡化 (Simplified Robotic Arm Model)",
    3: "逆向運動學解算 (Inverse kinematics Solution)",
    4: "正向運動學解算 (Forward kinematics Solution)",
    5: "數值算例 (Numerical Verification)",
    6: "結論 (Conclusion)",
}
"""Section headings as printed (numbers and titles; the extraction keeps them)."""

REFERENCES: dict[int, dict[str, str]] = {
    1: {
        "printed": "《中國機器人產業發展報告2019》發布. 傳感器世界, 2019",
        "topic": "industry report",
    },
    2: {
        "printed": "Hartenburg R.S., Denavit J., Freudenstein F. Kinematic Synthesis of Linkages. "
        "Journal of Applied Mechanics, 1965",
        "topic": "D-H method",
    },
    3: {
        "printed": "冷舒, 吳克, 居鶴華. 機械臂運動學建模及解算方法綜述. 宇航學報, 2019",
        "topic": "survey",
    },
    4: {
        "printed": "趙毓, 管公順, 郭繼峰, 等. 基於多智能體強化學習的空間機械臂軌跡規劃. 航空學報",
        "topic": "reinforcement learning",
    },
    5: {
        "printed": "馮晨旭, 胡三寶. 基於改進天牛須搜索的機械臂運動學逆解. 武漢大學學報(工學版)",
        "topic": "search method (beetle antennae)",
    },
    6: {
        "printed": "Tony Owen. Introduction to Robotics. Robotica, 1991, 9(4)",
        "topic": "D-H method",
    },
    7: {
        "printed": "朱訓棟, 徐海港, 趙棟杰. 碼垛機械臂運動學位置正逆解分析. 農業工程, 2017",
        "topic": "palletizer kinematics",
    },
    8: {
        "printed": "彭光宇, 董洪波, 馬斌. 兩種DH模型的機器人運動學建模對比研究. "
        "機械研究與應用, 2019",
        "topic": "modified D-H",
    },
    9: {
        "printed": "潘磊, 錢煒, 張志艷, 等. 四自由度機械臂運動學分析及Matlab仿真. "
        "機械科學與技術, 2013",
        "topic": "4-DOF arm kinematics",
    },
}
"""The reference list as printed (without the extraction's pinyin artefacts), with a topic
tag of ours: what each cited work is about (for the cross-reference checks)."""

LOST: dict[str, str] = {
    "Table 1": "the D-H parameter table (sec. 4.1, '如下表1'): body lost. The five printed "
    "matrices of sec. 4.2 imply alpha_{i-1} = 0, -90, 0, 0, 90 deg, a_{i-1} = 0, 0, L1, L2, h, "
    "d_i = 0, 0, 0, 0, L3 (theta5 = 0); the table's own values are not in the extraction.",
    "Table 2": "(gamma, alpha, beta, theta) for the four targets G1..G4 [deg]: body lost.",
    "Table 3": "theta1..theta4 by eq. 12 and the FK results T1..T4 [m]: body lost.",
    "targets": "the four targets G_i [m] (one per quadrant, Z > 0) appear only in the lost "
    "Tables 2-3.",
    "lengths": "L1, L2, L3 and h are never printed as numbers anywhere in the text.",
    "Figure 1": "photograph/drawing of the palletizer with motors M1..M4: image lost.",
    "Figure 2": "the simplified 3D model with the axes Y2, Y3, Y4 of the sign conventions and "
    "the point G: image lost.",
    "Figure 3": "the coplanar red triangle (L1', L2', L4') and H: image lost.",
    "Figure 4": "the quadrants and gamma: image lost.",
    "Figure 5": "the D-H frames at the pose of eq. 7: image lost.",
    "Figure 6": "not referred to in the text; image lost.",
    "Figure 7": "the aluminium arm with stepper motors near a target (sec. 5): image lost.",
    "sec. 4.1 steps": "'其步驟如下:' (the steps follow) is followed by nothing.",
}
"""What the extraction lost, by item."""

UNCERTAIN: dict[str, str] = {
    "eq. 2 grouping": "radicals and parentheses are inferred; the literal run "
    "X0²+Y0²-L3'²+Z0+h² mixes mm² and mm.",
    "eq. 3 H": "H is never defined. Read as the vertical leg Z0 + h of the red triangle "
    "(eq. 2) it makes alpha2 the elevation of the shoulder-wrist line; read as a depth below "
    "the shoulder (if Figure 3 drew the target low) it is -(Z0 + h). The two readings change "
    "the sign of alpha2 in eq. 4.",
    "eq. 3 beta1": "printed without arccos (the same run keeps arccos for alpha1), so the print "
    "probably omitted it; it could also be the extraction's loss.",
    "eq. 1 arctan": "arctan(Y0/X0) may mean the signed arctangent or the acute angle "
    "arctan|Y0/X0| of Figure 4; eq. 6 is checked under both.",
    "eq. 6 -π/2": "'-π2+γ'' is read as -π/2 + γ' as 'π2' is π/2 in eqs. 4 and 12; -π + γ' "
    "would be a different (also partial) rule.",
    "eq. 7 split": "the flattened vector '0-π2π2π20' is split as 0, -π/2, π/2, π/2, 0.",
    "eq. 8 glyph": "'sinai-1', 'cosai-1' print the length a_{i-1} where the twist "
    "alpha_{i-1} belongs, while 'cosαi-1' in the same run shows that α can be extracted; a "
    "misprint is likely but a font-mapping loss cannot be excluded.",
    "eq. 11 parentheses": "restored by analogy across rows; the run is consistent in "
    "'s4h-s4L3' (all three rows) and in the row labels 't14, t34, t34'.",
    "eq. 12 parentheses": "θ4 = π/2 - θ2 + θ3 as extracted; π/2 - (θ2 + θ3) would differ only "
    "by lost parentheses.",
    "sec. 2 '900'": "read as 90° (degree sign extracted as 0).",
    "sec. 2 'r弧度'": "'當基座電機(M1)旋轉r弧度後': r is presumably γ (a lost glyph).",
    "sec. 2 point G": "'目標點G在基座平面的投影為點G': the projection carries the same name as "
    "G (a prime G' was probably lost).",
    "axes Y2, Y3, Y4": "drawn in the lost Figure 2: whether +Y2 and +Y3 point the same way (so "
    "that 'clockwise' means the same sense for alpha and beta) cannot be read from the text.",
}
"""What the text extraction leaves undecidable, by item."""
