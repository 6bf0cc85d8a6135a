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
"""

from __future__ import annotations

import sympy as sp

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

# --- symbols -------------------------------------------------------------------------------
_KIN_NAMES = (
    "theta1 theta2 theta3 theta4 theta5 theta234 px py pz "
    "n_x n_y n_z o_x o_y o_z a_x a_y a_z phi theta psi "
    "theta_i d_i a_i alpha_i theta1_alt theta5_alt theta234_alt"
)
SYMBOLS: dict[str, sp.Symbol] = {
    **{name: sp.Symbol(name, real=True) for name in _KIN_NAMES.split()},
    **{name: sp.Symbol(name, positive=True) for name in ("a2", "a3", "a4")},
}
"""Symbols of chapters 3-4 by name: joint angles, link lengths ``a2 a3 a4``, target, the
orientation columns ``n o a``, the RPY angles ``phi theta psi``, the generic D-H
parameters ``theta_i d_i a_i alpha_i`` of eq. 3.19 and ``theta1_alt theta5_alt
theta234_alt`` for the second solutions printed as θ1', θ5', θ234' (section 4.2)."""

CUBIC_SYMBOLS: dict[str, sp.Symbol] = {
    name: sp.Symbol(name, real=True)
    for name in ("t", "t_f", "theta_0", "theta_f", "a0", "a1", "a2", "a3")
}
"""Symbols of section 5.4.1 (eqs. 5.1-5.4): time, duration, end angles, coefficients."""

_FUNCTIONS = {
    "sin": sp.sin,
    "cos": sp.cos,
    "atan": sp.atan,
    "atan2": sp.atan2,
    "sqrt": sp.sqrt,
    "Function": sp.Function,
    "Derivative": sp.Derivative,
}


def parse(text: str, symbols: str = "kinematics") -> sp.Expr:
    """Parse one transcribed expression over :data:`SYMBOLS` (``symbols="kinematics"``) or
    :data:`CUBIC_SYMBOLS` (``symbols="cubic"``; ``theta(t)`` is a function there).

    Raises ``ValueError`` naming the text if it does not parse or uses an unknown name.
    """
    if symbols == "kinematics":
        local: dict = dict(SYMBOLS)
    elif symbols == "cubic":
        local = dict(CUBIC_SYMBOLS)
        local["theta"] = sp.Function("theta")
    else:
        raise ValueError(f"symbols must be 'kinematics' or 'cubic', not {symbols!r}")
    local.update(_FUNCTIONS)
    try:
        expr = sp.parse_expr(text, local_dict=local, evaluate=True)
    except Exception as exc:  # sympy raises many types for bad syntax
        raise ValueError(f"cannot parse transcribed expression {text!r}: {exc}") from None
    known = set(SYMBOLS) if symbols == "kinematics" else set(CUBIC_SYMBOLS)
    unknown = {s.name for s in expr.free_symbols} - known
    if unknown:
        raise ValueError(f"expression {text!r} uses unknown name(s) {sorted(unknown)}")
    return expr


def matrix(name: str) -> sp.Matrix:
    """A printed matrix of :data:`MATRICES` as a SymPy matrix."""
    if name not in MATRICES:
        raise ValueError(f"unknown printed matrix {name!r}; expected one of {sorted(MATRICES)}")
    return sp.Matrix([[parse(e) for e in row] for row in MATRICES[name]["rows"]])


# --- section 2.1: the arm, the motors, Table 2-1 ---------------------------------------------
ARM: dict[str, dict] = {
    "dof": {
        "location": "sec. 2.1 item a, p. 5",
        "printed": "a、自由度:5(不包括手指开闭控制)",
        "value": 5,
        "note": "five joints, the gripper's open/close not counted",
    },
    "joint_ranges": {
        "location": "sec. 2.1 item b, p. 5",
        "printed": "b、各关节活动范围: 腰: ≥ ? 180 肩: 肘: 手俯仰: ≥ 200 ≥270。 ≥ 270 "
        "手指旋转:≥ 360",
        "reading_deg": {
            "腰 (waist)": "≥ ±180 (symbol lost)",
            "肩 (shoulder)": 200,
            "肘 (elbow)": 270,
            "手俯仰 (wrist pitch)": 270,
            "手指旋转 (finger roll)": 360,
        },
        "note": "ranges (spans), not limits: no zero positions are printed; the order of "
        "the three values after 肩: 肘: 手俯仰: is the extraction's (see UNCERTAIN)",
    },
    "work_area": {
        "location": "sec. 2.1 item c, p. 5",
        "printed": "c、最大活动区域: 垂直方向:850mm 水平方向:600mm",
        "vertical_mm": 850,
        "horizontal_mm": 600,
        "note": "whether these are spans or radii is not said",
    },
    "dimensions": {
        "location": "sec. 2.1 item d, p. 5",
        "printed": "d、基本尺寸: 上、下臂长:228mm 手后部:73mm",
        "upper_arm_mm": 228,
        "lower_arm_mm": 228,
        "hand_mm": 73,
        "note": "the listing uses a2 = 228, a3 = 228, a4 = 73; no base height is printed",
    },
    "joints": {
        "location": "sec. 2.2, p. 6",
        "printed": "整个机械手分 5 个自由度:腰、肩关节、肘关节、腕关节和手指,全部有直流电机驱动",
        "order": ["腰 waist", "肩 shoulder", "肘 elbow", "腕 wrist", "手指 finger"],
    },
}
"""Section 2.1 item by item (dimensions, ranges, work area) and section 2.2's joint list."""

MOTOR: dict = {
    "location": "sec. 2.1 item 2 (printed inside the Table 2-1 text), p. 5",
    "printed": "2 电机 工作电压:U = ? 12 V 空载转速:n = 3000 r/min 空载电流:I = 0.15 A",
    "voltage_V": 12,
    "voltage_sign": "lost ('?': ± or =)",
    "no_load_speed_rpm": 3000,
    "no_load_current_A": 0.15,
    "kind": "DC motor (sec. 2.2: 全部有直流电机驱动)",
}
"""Motor data of section 2.1."""

TABLE2_1: dict = {
    "location": "Table 2-1 各轴分辨率参数, sec. 2.1 item e, p. 5",
    "printed": "表 2-1 各轴分辨率参数 轴 躯干 上臂 下臂 手俯仰 手指旋转 ... 电机代号 M1 M2 M3 "
    "M4 M5 分辨率(度/脉冲) 0.14 0.11 0.11 0.11 0.24",
    "columns": ["axis", "motor", "resolution_deg_per_pulse"],
    "rows": [
        ("躯干 torso (waist)", "M1", 0.14),
        ("上臂 upper arm", "M2", 0.11),
        ("下臂 lower arm", "M3", 0.11),
        ("手俯仰 wrist pitch", "M4", 0.11),
        ("手指旋转 finger roll", "M5", 0.24),
    ],
    "note": "rows matched by order (the table grid is lost); joint k is driven by motor Mk",
}
"""Table 2-1: per-axis resolution in degrees per encoder pulse."""

ENCODER: dict = {
    "location": "sec. 2.3.2, p. 6-7",
    "printed": "光电编码器输出包括 A、B 两个频道的信号,码盘为 6 孔均匀分布的金属盘 ... "
    "码盘每旋转一周发送 12 次信号",
    "holes": 6,
    "channels": ["A", "B"],
    "signals_per_rev": 12,
    "mounting": "每个直流电机输出轴上都装有光电编码器 (on every motor's output shaft)",
}
"""The incremental encoder of section 2.3.2."""

PLC: dict = {
    "model": {
        "location": "sec. 2.3.1, p. 6",
        "printed": "最后选定用三菱公司生产的 FX2N—64MR 型 PLC",
        "value": "Mitsubishi FX2N-64MR",
    },
    "sizing_rule": {
        "location": "sec. 2.3.1, p. 6",
        "printed": "指令条数=(输入点数+输出点数) ? (10--12) 再留有 15%左右的备用量",
        "reading": "instructions = (inputs + outputs) x (10..12), plus about 15 % spare",
    },
    "high_speed_counters": {
        "location": "sec. 2.3.3, p. 7",
        "printed": "FX2N—64MR 提供 21 个高速计数器,即 C235 至 C255,但它们共享同一个 PLC 上的 "
        "6 个高速计数器输入端(X0~X5) ... 最多同时用 6 个高速计数器。在本文中将用到的是没有"
        "启动/复位的单相高速计数器 C235~C239。",
        "counters": 21,
        "first": "C235",
        "last": "C255",
        "inputs": ["X0", "X1", "X2", "X3", "X4", "X5"],
        "used": ["C235", "C236", "C237", "C238", "C239"],
    },
    "outputs_per_motor": {
        "location": "sec. 2.3.3 item 2, p. 7",
        "printed": "由于五个电机都要实现正反转,即能实现正反向供电,每个电机分配 4 个输出端口",
        "value": 4,
    },
}
"""PLC facts of sections 2.3.1-2.3.3."""

TABLE2_2: dict = {
    "location": "Table 2-2 高计数器表, sec. 2.3.3, p. 7",
    "printed": "表 2-2 高计数器表 输入 C235 C236 C237 C238 C239 X0 U/D X1 U/D X2 U/D X3 U/D "
    "X4 U/D 注:U—增计数输入;D—减计数输入。",
    "inputs": {"C235": "X0", "C236": "X1", "C237": "X2", "C238": "X3", "C239": "X4"},
    "mode": "U/D (up/down) for each",
}
"""Table 2-2: high-speed counter to input assignment."""

TABLE2_3: dict = {
    "location": "Table 2-3 各计数器数值, sec. 2.3.4, p. 8",
    "printed": "表 2-3 各计数器数值 计数器 数值 ... C235 4 C236 147 C237 118 C238 31 C239 16",
    "presets": {"C235": 4, "C236": 147, "C237": 118, "C238": 31, "C239": 16},
    "derivation_printed": "各计数器的值由表 2-1 和轨迹规划的结果表 5-4 确定如表 2-3",
    "counter_of_joint": {1: "C235", 2: "C236", 3: "C237", 4: "C238", 5: "C239"},
    "note": "counter k counts motor Mk's encoder (Figure 2-1: C235 腰部, C236 上臂, "
    "C238 手腕, C239 手指; the C237 box is lost)",
}
"""Table 2-3: counter presets, said to follow from Table 2-1 and Table 5-4."""

# --- chapter 3: orientation, transforms ------------------------------------------------------
RPY: dict = {
    "location": "sec. 3.3 (second of that number) item 1-2, eq. 3.14, p. 13",
    "printed": "RPY 角是描述船舶在海中航行时的姿态的一种方法。将船的行驶方向取为 Z 轴,则绕 Z 轴"
    "的旋转( ? 角)称为滚动(Roll);把绕 Y 轴的旋转( ? 角)称为俯仰(Pitch);而把垂直方向取为 X "
    "轴,将绕 X 轴的旋转( ? 角)称为偏转(Yaw) ... 首先将活动系绕参考系的 X 轴旋转 ? 角,再绕"
    "参考系的 Y 轴转 ? 角,最后绕参考系的 Z 轴转 ? 角",
    "definition": "RPY(phi, theta, psi) = Rot(z, phi) Rot(y, theta) Rot(x, psi), all three "
    "rotations about the fixed reference axes, x first",
    "angles": {"phi": "about z (roll)", "theta": "about y (pitch)", "psi": "about x (yaw)"},
    "listing_names": {
        "phi": "α (Text4 / Text10)",
        "theta": "β (Text5 / Text11)",
        "psi": "γ (Text6 / Text12)",
    },
    "units": "degrees in Tables 5-3 (not stated; assumed from the values)",
}
"""The RPY orientation convention of section 3.3 (the Greek letters are lost: assumed)."""

_ROT = {
    "3.5": [["1", "0", "0"], ["0", "cos(theta)", "-sin(theta)"], ["0", "sin(theta)", "cos(theta)"]],
    "3.6": [["cos(theta)", "0", "sin(theta)"], ["0", "1", "0"], ["-sin(theta)", "0", "cos(theta)"]],
    "3.7": [["cos(theta)", "-sin(theta)", "0"], ["sin(theta)", "cos(theta)", "0"], ["0", "0", "1"]],
}
_CPHI, _SPHI, _CTH, _STH, _CPS, _SPS = (
    "cos(phi)",
    "sin(phi)",
    "cos(theta)",
    "sin(theta)",
    "cos(psi)",
    "sin(psi)",
)
MATRICES: dict[str, dict] = {
    "3.5": {"location": "eq. 3.5 Rot(x, θ), p. 10", "rows": _ROT["3.5"]},
    "3.6": {"location": "eq. 3.6 Rot(y, θ), p. 11", "rows": _ROT["3.6"]},
    "3.7": {"location": "eq. 3.7 Rot(z, θ), p. 11", "rows": _ROT["3.7"]},
    "3.15": {
        "location": "eq. 3.15 RPY(φ, θ, ψ), p. 14",
        "printed": "?c? c ? ? s? c ? RPY (? , ? , ? ) ?? ? ? ?s? ? ? 0 c? s ? s? ? s? c? s? s ? s? "
        "? c? c? c ? s? 0 c ? s ? c ? ? s? s? s? s ? c? ? c? s? c ? c? 0 0? 0? ? 0? ? 1?",
        "rows": [
            [
                f"{_CPHI}*{_CTH}",
                f"{_CPHI}*{_STH}*{_SPS} - {_SPHI}*{_CPS}",
                f"{_CPHI}*{_STH}*{_CPS} + {_SPHI}*{_SPS}",
                "0",
            ],
            [
                f"{_SPHI}*{_CTH}",
                f"{_SPHI}*{_STH}*{_SPS} + {_CPHI}*{_CPS}",
                f"{_SPHI}*{_STH}*{_CPS} - {_CPHI}*{_SPS}",
                "0",
            ],
            [f"-{_STH}", f"{_CTH}*{_SPS}", f"{_CTH}*{_CPS}", "0"],
            ["0", "0", "0", "1"],
        ],
        "note": "operators read from the extraction's column order; every sign is a '?'",
    },
    "3.16": {
        "location": "eq. 3.16 RPY = [n o a 0; 0 0 0 1], p. 14",
        "rows": [
            ["n_x", "o_x", "a_x", "0"],
            ["n_y", "o_y", "a_y", "0"],
            ["n_z", "o_z", "a_z", "0"],
            ["0", "0", "0", "1"],
        ],
    },
    "3.19": {
        "location": "eq. 3.19 i-1A_i = R(z,θ_i) T(z,d_i) T(x,a_i) R(x,α_i), p. 17",
        "printed": "?c?i ? s? ?? i ?0 ? ?0 ... ?c? i s?i c? i c?i s? i 0 ... s? i s?i ? s? i c?i "
        "c? i 0 ... ai c?i ? ai s?i ? ? di ? ? 1 ?",
        "rows": [
            [
                "cos(theta_i)",
                "-sin(theta_i)*cos(alpha_i)",
                "sin(theta_i)*sin(alpha_i)",
                "a_i*cos(theta_i)",
            ],
            [
                "sin(theta_i)",
                "cos(theta_i)*cos(alpha_i)",
                "-cos(theta_i)*sin(alpha_i)",
                "a_i*sin(theta_i)",
            ],
            ["0", "sin(alpha_i)", "cos(alpha_i)", "d_i"],
            ["0", "0", "0", "1"],
        ],
        "note": "the general standard (distal) D-H link transform; the four factor matrices "
        "are printed too",
    },
}
"""Printed matrices: ``{"3.15": {"location", "rows", ...}}``; rows of SymPy strings."""

DH_TABLE: dict = {
    "location": "sec. 4.1 机器人正向运动学, p. 18",
    "printed": None,
    "note": "section 4.1 has a heading and no body in the extraction; no D-H table, frame "
    "figure or forward-kinematics result of the GR-1 is printed anywhere in the thesis. "
    "Section 3.4 gives only the general method (eq. 3.19); section 4.2 takes its results "
    "from a group-mate's thesis ('参考同组同学论文逆向运动学部分可得如下结果').",
}
"""The GR-1 D-H table: not printed (see :data:`LOST`)."""

# --- equations -------------------------------------------------------------------------------
_R = "(px*cos(theta1) + py*sin(theta1) - cos(theta234)*a4)"
_Z = "(pz - sin(theta234)*a4)"
_K = "(cos(theta3)*a3 + a2)"
_DEN = f"({_K}**2 + sin(theta3)**2*a3**2)"
EQUATIONS: dict[str, dict] = {
    "3.17": {
        "location": "eq. 3.17, p. 14",
        "printed": "2 2 cos ? ? nx ? ny",
        "lhs": "cos(theta)",
        "rhs": "sqrt(n_x**2 + n_y**2)",
    },
    "3.18a": {
        "location": "eq. 3.18 first line, p. 14",
        "printed": "? ? ? A tan 2(?n , n 2 ? n 2 ) z x y",
        "lhs": "theta",
        "rhs": "atan2(-n_z, sqrt(n_x**2 + n_y**2))",
    },
    "3.18b": {
        "location": "eq. 3.18 second line, p. 14",
        "printed": "? ? A tan 2(ox , nx )",
        "lhs": "phi",
        "rhs": "atan2(o_x, n_x)",
        "note": "the left-hand letter is lost; phi assumed (second line)",
    },
    "3.18c": {
        "location": "eq. 3.18 third line, p. 14",
        "printed": "? ? A tan 2(a y , az )",
        "lhs": "psi",
        "rhs": "atan2(a_y, a_z)",
        "note": "the left-hand letter is lost; psi assumed (third line)",
    },
    "4.2-theta1": {
        "location": "sec. 4.2, p. 19, first result",
        "printed": "?1 ? arctan ? ? py ? ? , ?1? ? ?1 ?180 p ? x?",
        "lhs": "theta1",
        "rhs": "atan(py/px)",
    },
    "4.2-theta1'": {
        "location": "sec. 4.2, p. 19, first result (second solution)",
        "printed": "?1? ? ?1 ?180",
        "lhs": "theta1_alt",
        "rhs": "theta1 + 180",
        "note": "degrees; the operator is a '?' (+ read)",
    },
    "4.2-theta5": {
        "location": "sec. 4.2, p. 19, second result",
        "printed": "?5 ? arctan ? ? s1nx ? c1n y ? s o ?c o ? 1 x 1 y",
        "lhs": "theta5",
        "rhs": "atan((sin(theta1)*n_x - cos(theta1)*n_y)/(sin(theta1)*o_x - cos(theta1)*o_y))",
    },
    "4.2-theta5'": {
        "location": "sec. 4.2, p. 19, second result (second solution)",
        "printed": "?5 ? 180 , ?5 ? ? ?",
        "lhs": "theta5_alt",
        "rhs": "theta5 + 180",
    },
    "4.2-theta234": {
        "location": "sec. 4.2, p. 19, third result",
        "printed": "? 234 ? arctan oz ? ? ?234 ?180 , ?234 c1ox ? s1oy",
        "lhs": "theta234",
        "rhs": "atan(o_z/(cos(theta1)*o_x + sin(theta1)*o_y))",
    },
    "4.2-theta234'": {
        "location": "sec. 4.2, p. 19, third result (second solution)",
        "printed": "? ?234 ?180 , ?234",
        "lhs": "theta234_alt",
        "rhs": "theta234 + 180",
    },
    "4.2-c3": {
        "location": "sec. 4.2, p. 19",
        "printed": "c3 ? ( px c1 ? py s1 ? c234a4 )2 ? ( pz ? s234a4 )2 ? a22 ? a32 2a2 a3",
        "lhs": "cos(theta3)",
        "rhs": f"({_R}**2 + {_Z}**2 - a2**2 - a3**2)/(2*a2*a3)",
    },
    "4.2-s3": {
        "location": "sec. 4.2, p. 19",
        "printed": "s3 ? ? 1 ? c32",
        "lhs": "sin(theta3)",
        "rhs": "sqrt(1 - cos(theta3)**2)",
        "note": "printed with a sign '?' in front: ± (both roots) read; rhs is the + root",
    },
    "4.2-theta3": {
        "location": "sec. 4.2, p. 19",
        "printed": "?3 ? arctan s3 c3",
        "lhs": "theta3",
        "rhs": "atan(sin(theta3)/cos(theta3))",
    },
    "4.2-s2": {
        "location": "sec. 4.2, p. 19",
        "printed": "s2 ? (c3a3 ? a2 )( pz ? s234a4 ) ? s3a3 ( pxc1 ? p y s1 ? c234a4 ) "
        "(c3a3 ? a2 )2 ? s32 a32",
        "lhs": "sin(theta2)",
        "rhs": f"({_K}*{_Z} - sin(theta3)*a3*{_R})/{_DEN}",
    },
    "4.2-c2": {
        "location": "sec. 4.2, p. 19",
        "printed": "c2 ? (c3a3 ? a2 )( pxc1 ? p y s1 ? c234a4 ) ? s3a3 ( pz ? s234a4 ) "
        "(c3a3 ? a2 )2 ? s32 a32",
        "lhs": "cos(theta2)",
        "rhs": f"({_K}*{_R} + sin(theta3)*a3*{_Z})/{_DEN}",
    },
    "4.2-theta2": {
        "location": "sec. 4.2, p. 19",
        "printed": "?2 ? arctan (c3a3 ? a2 )( pz ? s234 a4 ) ? s3a3 ( px c1 ? py s1 ? c234a4 ) s2 "
        "? arctan c2 (c3a3 ? a2 )( px c1 ? py s1 ? c234a4 ) ? s3a3 ( pz ? s234a4 )",
        "lhs": "theta2",
        "rhs": f"atan(({_K}*{_Z} - sin(theta3)*a3*{_R})/({_K}*{_R} + sin(theta3)*a3*{_Z}))",
    },
    "4.2-theta4": {
        "location": "sec. 4.2, p. 19",
        "printed": "因 ?234、?2、?3 均已知,所以可进而求得 ?4 。 ?4 ? ?234 ? ?2 ? ?3",
        "lhs": "theta4",
        "rhs": "theta234 - theta2 - theta3",
    },
    "5.1a": {
        "location": "eq. 5.1 first line, p. 22",
        "printed": "? (0) ? ? 0",
        "lhs": "theta(0)",
        "rhs": "theta_0",
        "symbols": "cubic",
    },
    "5.1b": {
        "location": "eq. 5.1 second line, p. 22",
        "printed": "? (t f ) ? 0 ?",
        "lhs": "theta(t_f)",
        "rhs": "theta_f",
        "symbols": "cubic",
        "note": "the extraction shows '0' where the text says 终止关节角度 θf",
    },
    "5.2a": {
        "location": "eq. 5.2 first line, p. 22",
        "printed": "? (0) ? 0",
        "lhs": "Derivative(theta(t), t).subs(t, 0)",
        "rhs": "0",
        "symbols": "cubic",
    },
    "5.2b": {
        "location": "eq. 5.2 second line, p. 22",
        "printed": "? (t f ) ? 0",
        "lhs": "Derivative(theta(t), t).subs(t, t_f)",
        "rhs": "0",
        "symbols": "cubic",
    },
    "5.3": {
        "location": "eq. 5.3, p. 22",
        "printed": "? ?t ? ? a0 ? a1t ? a2t 2 ? a3t 3",
        "lhs": "theta(t)",
        "rhs": "a0 + a1*t + a2*t**2 + a3*t**3",
        "symbols": "cubic",
    },
    "5.4a": {
        "location": "eq. 5.4 first line, p. 22",
        "printed": "? ? (t ) ? a1 ? 2a2t ? 3a3t 2",
        "lhs": "Derivative(theta(t), t)",
        "rhs": "a1 + 2*a2*t + 3*a3*t**2",
        "symbols": "cubic",
    },
    "5.4b": {
        "location": "eq. 5.4 second line, p. 22",
        "printed": ".. ? ? (t ) ? 2a2 ? 6a3t",
        "lhs": "Derivative(theta(t), t, 2)",
        "rhs": "2*a2 + 6*a3*t",
        "symbols": "cubic",
    },
}
"""Printed equations as ``{"lhs", "rhs"}`` SymPy strings with ``location`` and the extracted
``printed`` text. Every operator printed as ``?`` is read as noted in :data:`UNCERTAIN`
(section 4.2: the signs that the listing's statements for the same quantities have)."""

# --- chapter 5 -----------------------------------------------------------------------------
TABLE5_3: dict = {
    "location": "Table 5-3 机械手起点、终点给定值, sec. 5.4.2, p. 23",
    "printed": "表 5-3 机械手起点、终点给定值 ? ? pz px py 控制点 ? 起点 151 231 250 32 45 60 "
    "终点 200 300 178 20 50 80",
    "columns": ["px", "py", "pz", "alpha", "beta", "gamma"],
    "rows": {"start": (151, 231, 250, 32, 45, 60), "end": (200, 300, 178, 20, 50, 80)},
    "units": "mm and degrees (not printed)",
    "listing_inputs": {
        "start": ("Text1", "Text2", "Text3", "Text4", "Text5", "Text6"),
        "end": ("Text7", "Text8", "Text9", "Text10", "Text11", "Text12"),
    },
    "note": "the three angle headers are lost ('?'); their order is taken as the "
    "listing's input order α, β, γ (RPY phi, theta, psi about z, y, x)",
}
"""Table 5-3: start and end poses (position mm, RPY angles deg)."""

TABLE5_4_EXTRACTED: dict = {
    "location": "Table 5-4 机械手起点、终点关节变量值, sec. 5.4.2, p. 23",
    "printed_header": "表 5-4 机械手起点、终点关节变量值 ?1 ?2 ?4 ?3 ?5 控制点 起点 终点",
    "numbers": (56.31, 56.828, 80.922, -66.006, -45.244, 73.282, -52.738, -83.861, -24.683, -9.074),
    "printed_numbers": "56.31 56.828 80.922 -66.006 -45.244 73.282 -52.738 -83.861 -24.683 -9.074",
    "where": "the ten numbers come out at the end of section 5.4.2, after the paragraph that "
    "follows the table, not inside the table",
}
"""Table 5-4 as extracted: a header with the joint names scrambled and ten loose numbers."""

TABLE5_4: dict = {
    "location": "Table 5-4, sec. 5.4.2, p. 23",
    "columns": ["theta1", "theta2", "theta3", "theta4", "theta5"],
    "rows": {
        "start": (56.828, -66.006, 73.282, -83.861, -9.074),
        "end": (56.31, 80.922, -45.244, -52.738, -24.683),
    },
    "units": "degrees",
    "assignment": "the extracted numbers read column by column, θ1 to θ5, the end value "
    "first in each pair: (end, start) = (56.31, 56.828), (80.922, -66.006), "
    "(-45.244, 73.282), (-52.738, -83.861), (-24.683, -9.074)",
    "basis": [
        "theta1 = atan(py/px) of Table 5-3 is 56.828 deg for the start (231/151) and 56.310 "
        "for the end (300/200): this fixes the pair order (end first) without the listing",
        "the listing's Command1_Click (Text13-17 start, Text18-22 end) reproduces all ten "
        "numbers in this assignment to the printed three decimals (tests/audit/test_vb6.py)",
        'Format(x, "####.###") drops trailing zeros: 56.310 prints as 56.31, as extracted',
    ],
    "uncertainty": "the printed table's own column order cannot be read (the extraction "
    "gives θ1 θ2 θ4 θ3 θ5); row-major readings fail the theta1 check (56.828 would be a "
    "theta2). The assignment rests on theta1 for the pair order and on the listing for "
    "the joint order.",
}
"""Table 5-4 with each extracted number assigned to a cell (see ``basis``/``uncertainty``)."""

CUBIC: dict = {
    "location": "sec. 5.4.1-5.4.2, eqs. 5.1-5.9, pp. 22-23",
    "equations": ["5.1a", "5.1b", "5.2a", "5.2b", "5.3", "5.4a", "5.4b"],
    "lost": {
        "5.5": "the system for a0..a3 (only its number survives)",
        "5.6": "its solution (only the number)",
        "5.7": "the interpolation function (text: 满足连续平稳运动要求的三次多项式插值函数为 ...)",
        "5.8": "velocity (named in the text, body lost)",
        "5.9": "acceleration (named in the text, body lost)",
    },
    "listing_form": {
        "location": "appendix listing, Command3_Click, each joint block",
        "printed": "Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * "
        "(X * X * X)",
        "reading": "theta(t) = theta_0 + 3/t_f**2*(theta_f - theta_0)*t**2 "
        "- 2/t_f**3*(theta_f - theta_0)*t**3",
    },
    "duration_s": 10,
    "duration_location": "listing only: 'c = 10' and 'For X = 0 To 10 Step 0.001' "
    "(the text gives no duration)",
    "claim": "c5.4.2-acc",
}
"""The cubic trajectory of section 5.4: printed equations, lost ones, the listing's form."""

# --- the appendix VB6 listing (pp. 36-46) ----------------------------------------------------
_LISTING_EXTRACTED_LINES: tuple[str, ...] = (
    ("轨迹规划界面 VB 程序如下: Dim a2, a3, a4, PI, a, b, c, d, h, m, n, max, min As Double"),
    "",
    (
        "Private Sub Command1_Click() Dim Px0, Py0, Pz0, α0, β0, γ0 As Single Dim θ1,"
        " θ2, θ3, θ4, θ5, θ234 As Single, c3 As Double Dim Px1, Py1, Pz1, α1, β1, γ1 As"
        " Single Dim θf1, θf2, θf3, θf4, θf5, θf234 As Single, cf3 As Double a2 = 228 a3"
        " = 228 a4 = 73 PI = 3.141593"
    ),
    "",
    (
        "Px0 = Val(Text1.Text) Py0 = Val(Text2.Text) Pz0 = Val(Text3.Text) α 0 ="
        " Val(Text4.Text) β 0 = Val(Text5.Text) γ 0 = Val(Text6.Text) Px1 ="
        " Val(Text7.Text) Py1 = Val(Text8.Text) Pz1 = Val(Text9.Text) α 1 ="
        " Val(Text10.Text) β 1 = Val(Text11.Text) γ 1 = Val(Text12.Text)"
        " Command3.Enabled = True If Sqr((Px0 - Px1) * (Px0 - Px1) + (Py0 - Py1) * (Py0"
        " - Py1)) > 850 Then Command3 = False ElseIf Abs(Pz0 - Pz1) > 600 Then"
        " Command3.Enabled = False End If θ 1 = (180 / PI) * (Atn(Py0 / Px0))"
        ' Text13.Text = Format(θ1, "####.###") θ 5 = (180 / PI) * (Atn((Sin(θ1) *'
        " Cos(α0) * Cos(β0) - Cos(θ1) * Sin(α0) * Cos(β0)) / (Sin(θ1) * (Cos(α0) 36"
    ),
    "",
    (
        "* Sin(β0) * Sin(γ0) - Sin(α0) * Cos(γ0)) - Cos(θ1) * (Sin(α0) * Sin(β0) *"
        ' Sin(γ0) + Cos(α0) * Cos(γ0))))) Text17.Text = Format(θ5, "####.###") θ 234 ='
        " (180 / PI) * (Atn((Cos(β0) * Sin(γ0)) / (Cos(θ1) * (Cos(α0) * Sin(β0) *"
        " Sin(γ0) - Sin(α0) * Cos(γ0)) + Sin(θ1) * (Sin(α0) * Sin(β0) * Sin(γ0) +"
        " Cos(α0) * Cos(γ0))))) c3 = ((Px0 * Cos(θ1) + Py0 * Sin(θ1) - Cos(θ234) * a4) *"
        " (Px0 * Cos(θ1) + Py0 * Sin(θ1) - Cos(θ234) * a4) + (Pz0 - Sin(θ234) * a4) *"
        " (Pz0 - Sin(θ234) * a4) - a2 * a2 - a3 * a3) / (2 * a2 * a3) θ 3 = (180 / PI) *"
        ' (Atn(Sqr(Abs(1 - c3 * c3)) / c3)) Text15.Text = Format(θ3, "####.###") θ 2 ='
        " (180 / PI) * (Atn(((Cos(θ3) * a3 + a2) * (Pz0 - Sin(θ234) * a4) - Sin(θ3) * a3"
        " * (Px0 * Cos(θ1) + Py0 * Sin(θ1) + Cos(θ234) * a4)) / ((Cos(θ3) * a3 + a2) *"
        " (Px0 * Cos(θ1) + Py0 * Sin(θ1) + Cos(θ234) * a4) + Sin(θ3) * a3 * (Pz0 -"
        ' Sin(θ234) * a4)))) Text14.Text = Format(θ2, "####.###") θ 4 = θ234 - θ2 - θ3'
        ' Text16.Text = Format(θ4, "####.###") θ f1 = (180 / PI) * (Atn(Py1 / Px1))'
        ' Text18.Text = Format(θf1, "####.###") θ f5 = (180 / PI) * (Atn((Sin(θf1) *'
        " Cos(α0) * Cos(β0) - Cos(θf1) * Sin(α0) * Cos(β0)) / (Sin(θf1) * (Cos(α0) *"
        " Sin(β0) * Sin(γ0) - Sin(α0) * Cos(γ0)) - Cos(θf1) * (Sin(α0) * Sin(β0) *"
        ' Sin(γ0) + Cos(α0) * Cos(γ0))))) Text22.Text = Format(θf5, "####.###") θ f234 ='
        " (180 / PI) * (Atn((Cos(β0) * Sin(γ0)) / (Cos(θf1) * (Cos(α0) * Sin(β0) *"
        " Sin(γ0) - Sin(α0) * Cos(γ0)) + Sin(θf1) * (Sin(α0) * Sin(β0) * Sin(γ0) +"
        " Cos(α0) * Cos(γ0))))) cf3 = ((Px1 * Cos(θf1) + Py1 * Sin(θf1) - Cos(θf234) *"
        " a4) * (Px1 * Cos(θf1) + Py1 * Sin(θf1) Cos(θf234) * a4) + (Pz1 - Sin(θf234) *"
        " a4) * (Pz1 - Sin(θf234) * a4) - a2 * a2 - a3 * a3) / (2 * a2 * a3) θ f3 = (180"
        " / PI) * (Atn(Sqr(Abs(1 - cf3 * cf3)) / cf3)) Text20.Text = Format(θf3,"
        ' "####.###") θ f2 = (180 / PI) * (Atn(((Cos(θf3) * a3 + a2) * (Pz1 - Sin(θf234)'
        " * a4) - Sin(θf3) * a3 * (Px1 * Cos(θf1) + Py1 * Sin(θf1) + Cos(θf234) * a4)) /"
        " ((Cos(θf3) * a3 + a2) * (Px1 * Cos(θf1) + Py1 * Sin(θf1) + Cos(θf234) * a4) +"
        " Sin(θf3) * a3 * (Pz1 - Sin(θf234) * a4)))) Text19.Text = Format(θf2,"
        ' "####.###") θ f4 = θf234 - θf2 - θf3 Text21.Text = Format(θf4, "####.###") End'
        " Sub Private Sub Command3_Click() 37"
    ),
    "",
    (
        "Dim m1, m2, m3, m4, m5, n1, n2, n3, n4, n5 As Double Frame6.Visible = True"
        " '关节 1 轨迹 '取值 a = Text13.Text b = Text18.Text c = 10 d = a + (3 / (c *"
        " c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b - a) * (10 * 10 * 10) If"
        " Val(a) > Val(d) Then m1 = a n1 = d Else m1 = d n1 = a End If Picture1.Cls"
        " '清空画图区域 Picture1.Scale (0, m1 + (m1 - n1) / 5)-(12, n1) '设置画图区域"
        " 根据需要进行设置大小 Picture1.ForeColor = &H0 Picture1.DrawWidth = 1 '画 X 轴"
        " 'Picture1.Line (0, n1)-(5, n1) '标记 t 轴 Picture1.CurrentX = 11.5"
        ' Picture1.CurrentY = n1 + (m1 - n1) / 10 Picture1.Print "t" \'画 Y 轴'
        " Picture1.Line (0, n1 - 5)-(0, m1 + (m1 - n1) / 5) '标记 Y 轴 Picture1.CurrentX"
        ' = 0.2 Picture1.CurrentY = m1 + (m1 - n1) / 5 Picture1.Print "Y" \'画坐标 Dim i'
        " As Single For i = 1 To 10 38"
    ),
    "",
    (
        "Picture1.CurrentX = i: Picture1.CurrentY = n1 + (m1 - n1) / 10: Picture1.Print"
        " i Picture1.Line (i, n1)-(i, n1 + (m1 - n1) / 15) Next i Dim j As Integer For j"
        " = 1 To 5 Picture1.Line (0, n1 + (m1 - n1) / 5 * j)-(0.1, n1 + (m1 - n1) / 5 *"
        " j) Picture1.CurrentX = 0.1: Picture1.CurrentY = n1 + (m1 - n1) / 5 * j:"
        " Picture1.Print Fix(n1 + ((m1 - n1) / 5) * j) Next j Picture1.DrawWidth = 2"
        " Picture1.Line (0, 0)-(0, 0) '归零收笔 '开始画图 For X = 0 To 10 Step 0.001"
        " '0.001 改小可以获得更高的精度 Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 /"
        " (c * c * c)) * (b - a) * (X * X * X) '输入函数 可以写入自己的函数"
        " Picture1.CurrentY = (m1 + n1) / 2 Picture1.CurrentX = 0.5 Picture1.PSet (X,"
        " Y), vbRed '标记 X,Y 轴 Next Picture1.CurrentX = 4 Picture1.CurrentY = m1"
        " Picture1.Print \"Y = θ 1(t)\" '将函数显示在图形上 '关节 2 轨迹 '取值 a ="
        " Text14.Text b = Text19.Text c = 10 d = a + (3 / (c * c)) * (b - a) * (10 * 10)"
        " - (2 / (c * c * c)) * (b - a) * (10 * 10 * 10) If Val(a) > Val(d) Then m2 = a"
        " n2 = d Else m2 = d 39"
    ),
    "",
    (
        "n2 = a End If Picture2.Cls '清空画图区域 Picture2.Scale (0, m2 + (m2 - n2) /"
        " 5)-(12, n2) '设置画图区域 根据需要进行设置大小 Picture2.ForeColor = &H0"
        " Picture2.DrawWidth = 1 '画 X 轴 Picture2.Line (0, n2)-(12, n2) '标记 t 轴"
        " Picture2.CurrentX = 11.5 Picture2.CurrentY = n2 + (m2 - n2) / 10"
        ' Picture2.Print "t" \'画 Y 轴 Picture2.Line (0, n2 - 5)-(0, m2 + (m2 - n2) / 5)'
        " '标记 Y 轴 Picture2.CurrentX = 0.2 Picture2.CurrentY = m2 + (m2 - n2) / 5"
        ' Picture2.Print "Y" \'画坐标 For i = 1 To 10 Picture2.CurrentX = i:'
        " Picture2.CurrentY = n2 + (m2 - n2) / 10: Picture2.Print i Picture2.Line (i,"
        " n2)-(i, n2 + (m2 - n2) / 15) Next i For j = 1 To 5 Picture2.Line (0, n2 + (m2"
        " - n2) / 5 * j)-(0.1, n2 + (m2 - n2) / 5 * j) Picture2.CurrentX = 0.1:"
        " Picture2.CurrentY = n2 + (m2 - n2) / 5 * j: Picture2.Print Fix(n2 + ((m2 - n2)"
        " / 5) * j) Next j Picture2.DrawWidth = 2 Picture2.Line (0, 0)-(0, 0) '归零收笔"
        " '开始画图 For X = 0 To 10 Step 0.001 '0.005 改小可以获得更高的精度 Y = a + (3"
        " / (c * c)) * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * (X * X * X)"
        " '输入函数 可以写入自己的函数 40"
    ),
    "",
    (
        "Picture2.CurrentY = (m2 + n2) / 2 Picture2.CurrentX = 0.5 Picture2.PSet (X, Y),"
        " vbRed '标记 X,Y 轴 Next Picture2.CurrentX = 4 Picture2.CurrentY = m2"
        " Picture2.Print \"Y = θ 2(t)\" '关节 3 轨迹 '取值 a = Text15.Text b = Text20.Text"
        " c = 10 d = a + (3 / (c * c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b -"
        " a) * (10 * 10 * 10) If Val(a) > Val(d) Then m3 = a n3 = d Else m3 = d n3 = a"
        " End If Picture3.Cls '清空画图区域 Picture3.Scale (0, m3 + (m3 - n3) / 5)-(12,"
        " n3) '设置画图区域 根据需要进行设置大小 Picture3.ForeColor = &H0"
        " Picture3.DrawWidth = 1 '画 X 轴 Picture3.Line (0, n3)-(12, n3) '标记 t 轴"
        " Picture3.CurrentX = 11.5 Picture3.CurrentY = n3 + (m3 - n3) / 10"
        ' Picture3.Print "t" \'画 Y 轴 Picture3.Line (0, n3 - 5)-(0, m3 + (m3 - n3) / 5)'
        " 41 '将函数显示在图形上"
    ),
    "",
    (
        "'标记 Y 轴 Picture3.CurrentX = 0.2 Picture3.CurrentY = m3 + (m3 - n3) / 5"
        ' Picture3.Print "Y" \'画坐标 For i = 1 To 10 Picture3.CurrentX = i:'
        " Picture3.CurrentY = n3 + (m3 - n3) / 10: Picture3.Print i Picture3.Line (i,"
        " n3)-(i, n3 + (m3 - n3) / 15) Next i For j = 1 To 5 Picture3.Line (0, n3 + (m3"
        " - n3) / 5 * j)-(0.1, n3 + (m3 - n3) / 5 * j) Picture3.CurrentX = 0.1:"
        " Picture3.CurrentY = n3 + (m3 - n3) / 5 * j: Picture3.Print Fix(n3 + ((m3 - n3)"
        " / 5) * j) Next j Picture3.DrawWidth = 2"
    ),
    "",
    (
        "Picture3.Line (0, 0)-(0, 0) '归零收笔 '开始画图 For X = 0 To 10 Step 0.001"
        " '0.001 改小可以获得更高的精度 Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 /"
        " (c * c * c)) * (b - a) * (X * X * X) '输入函数 可以写入自己的函数"
        " Picture3.CurrentY = (m3 + n3) / 2 Picture3.CurrentX = 0.5 Picture3.PSet (X,"
        " Y), vbRed '标记 X,Y 轴 Next Picture3.CurrentX = 4 Picture3.CurrentY = m3"
        ' Picture3.Print "Y = θ 3(t)" \'将函数显示在图形'
    ),
    "",
    "'关节 4 轨迹 '取值 a = Text16.Text b = Text21.Text 42",
    "",
    (
        "c = 10 d = a + (3 / (c * c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b -"
        " a) * (10 * 10 * 10) If Val(a) > Val(d) Then m4 = a n4 = d Else m4 = d n4 = a"
        " End If Picture4.Cls '清空画图区域 Picture4.Scale (0, m4 + (m4 - n4) / 5)-(12,"
        " n4) '设置画图区域 根据需要进行设置大小 Picture4.ForeColor = &H0"
        " Picture4.DrawWidth = 1 '画 X 轴 Picture4.Line (0, n4)-(12, n4) '标记 t 轴"
        " Picture4.CurrentX = 11.5 Picture4.CurrentY = n4 + (m4 - n4) / 10"
        ' Picture4.Print "t" \'画 Y 轴 Picture4.Line (0, n4 - 5)-(0, m4 + (m4 - n4) / 5)'
        " '标记 Y 轴 Picture4.CurrentX = 0.2 Picture4.CurrentY = m4 + (m4 - n4) / 5"
        ' Picture4.Print "Y" \'画坐标 For i = 1 To 10 Picture4.CurrentX = i:'
        " Picture4.CurrentY = n4 + (m4 - n4) / 10: Picture4.Print i Picture4.Line (i,"
        " n4)-(i, n4 + (m4 - n4) / 15) Next i For j = 1 To 5 Picture4.Line (0, n4 + (m4"
        " - n4) / 5 * j)-(0.1, n4 + (m4 - n4) / 5 * j) Picture4.CurrentX = 0.1:"
        " Picture4.CurrentY = n4 + (m4 - n4) / 5 * j: Picture4.Print Fix(n4 + ((m4 - n4)"
        " / 5) * j) 43"
    ),
    "",
    (
        "Next j Picture4.DrawWidth = 2 Picture4.Line (0, 0)-(0, 0) '归零收笔 '开始画图"
        " For X = 0 To 10 Step 0.001 '0.005 改小可以获得更高的精度 Y = a + (3 / (c * c))"
        " * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * (X * X * X) '输入函数"
        " 可以写入自己的函数 Picture4.CurrentY = (m4 + n4) / 2 Picture4.CurrentX = 0.5"
        " Picture4.PSet (X, Y), vbRed '标记 X,Y 轴 Next Picture4.CurrentX = 4"
        " Picture4.CurrentY = m4 Picture4.Print \"Y = θ 4(t)\" '关节 5 轨迹 '取值 a ="
        " Text17.Text b = Text22.Text c = 10 d = a + (3 / (c * c)) * (b - a) * (10 * 10)"
        " - (2 / (c * c * c)) * (b - a) * (10 * 10 * 10) If Val(a) > Val(d) Then m5 = a"
        " n5 = d Else m5 = d n5 = a End If '将函数显示在图形上"
    ),
    "",
    (
        "Picture5.Cls '清空画图区域 Picture5.Scale (0, m5 + (m5 - n5) / 5)-(12, n5)"
        " '设置画图区域 根据需要进行设置大小 Picture5.ForeColor = &H0 Picture5.DrawWidth"
        " = 1 '画 X 轴 44"
    ),
    "",
    (
        "Picture5.Line (0, n5)-(12, n5) '标记 t 轴 Picture5.CurrentX = 11.5"
        ' Picture5.CurrentY = n5 + (m5 - n5) / 10 Picture5.Print "t" \'画 Y 轴'
        " Picture5.Line (0, n5 - 5)-(0, m5 + (m5 - n5) / 5) '标记 Y 轴 Picture5.CurrentX"
        ' = 0.2 Picture5.CurrentY = m5 + (m5 - n5) / 5 Picture5.Print "Y" \'画坐标 For i'
        " = 1 To 10 Picture5.CurrentX = i: Picture5.CurrentY = n5 + (m5 - n5) / 10:"
        " Picture5.Print i Picture5.Line (i, n5)-(i, n5 + (m5 - n5) / 15) Next i"
    ),
    "",
    (
        "For j = 1 To 5 Picture5.Line (0, n5 + (m5 - n5) / 5 * j)-(0.1, n5 + (m5 - n5) /"
        " 5 * j) Picture5.CurrentX = 0.1: Picture5.CurrentY = n5 + (m5 - n5) / 5 * j:"
        " Picture5.Print Fix(n5 + ((m5 - n5) / 5) * j) Next j Picture5.DrawWidth = 2"
        " Picture5.Line (0, 0)-(0, 0) '归零收笔 '开始画图 For X = 0 To 10 Step 0.001"
        " '0.005 改小可以获得更高的精度 Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 /"
        " (c * c * c)) * (b - a) * (X * X * X) '输入函数 可以写入自己的函数"
        " Picture5.CurrentY = (m5 + n5) / 2 Picture5.CurrentX = 0.5 Picture5.PSet (X,"
        " Y), vbRed '标记 X,Y 轴 Next Picture5.CurrentX = 4 45"
    ),
    "",
    'Picture5.CurrentY = m5 Picture5.Print "Y = θ 5(t)" \'将函数显示在图形上',
    "",
    "End Sub",
    "",
    (
        'Private Sub Command4_Click() Text1.Text = "" Text2.Text = "" Text3.Text = ""'
        ' Text4.Text = "" Text5.Text = "" Text6.Text = "" Text7.Text = "" Text8.Text ='
        ' "" Text9.Text = "" Text10.Text = "" Text11.Text = "" Text12.Text = ""'
        ' Text13.Text = "" Text14.Text = "" Text15.Text = "" Text16.Text = ""'
        ' Text17.Text = "" Text18.Text = "" Text19.Text = "" Text20.Text = ""'
        ' Text21.Text = "" Text22.Text = ""'
    ),
    "",
    "End Sub",
    "",
)
"""Seed lines of the appendix listing, verbatim (one string per extracted line)."""

_LISTING_LINES: tuple[str, ...] = (
    "Dim a2, a3, a4, PI, a, b, c, d, h, m, n, max, min As Double",
    "Private Sub Command1_Click()",
    "Dim Px0, Py0, Pz0, α0, β0, γ0 As Single",
    "Dim θ1, θ2, θ3, θ4, θ5, θ234 As Single, c3 As Double",
    "Dim Px1, Py1, Pz1, α1, β1, γ1 As Single",
    "Dim θf1, θf2, θf3, θf4, θf5, θf234 As Single, cf3 As Double",
    "a2 = 228",
    "a3 = 228",
    "a4 = 73",
    "PI = 3.141593",
    "Px0 = Val(Text1.Text)",
    "Py0 = Val(Text2.Text)",
    "Pz0 = Val(Text3.Text)",
    "α0 = Val(Text4.Text)",
    "β0 = Val(Text5.Text)",
    "γ0 = Val(Text6.Text)",
    "Px1 = Val(Text7.Text)",
    "Py1 = Val(Text8.Text)",
    "Pz1 = Val(Text9.Text)",
    "α1 = Val(Text10.Text)",
    "β1 = Val(Text11.Text)",
    "γ1 = Val(Text12.Text)",
    "Command3.Enabled = True",
    "If Sqr((Px0 - Px1) * (Px0 - Px1) + (Py0 - Py1) * (Py0 - Py1)) > 850 Then",
    "Command3 = False",
    "ElseIf Abs(Pz0 - Pz1) > 600 Then",
    "Command3.Enabled = False",
    "End If",
    "θ1 = (180 / PI) * (Atn(Py0 / Px0))",
    'Text13.Text = Format(θ1, "####.###")',
    (
        "θ5 = (180 / PI) * (Atn((Sin(θ1) * Cos(α0) * Cos(β0) - Cos(θ1) * Sin(α0) *"
        " Cos(β0)) / (Sin(θ1) * (Cos(α0) * Sin(β0) * Sin(γ0) - Sin(α0) * Cos(γ0)) -"
        " Cos(θ1) * (Sin(α0) * Sin(β0) * Sin(γ0) + Cos(α0) * Cos(γ0)))))"
    ),
    'Text17.Text = Format(θ5, "####.###")',
    (
        "θ234 = (180 / PI) * (Atn((Cos(β0) * Sin(γ0)) / (Cos(θ1) * (Cos(α0) * Sin(β0) *"
        " Sin(γ0) - Sin(α0) * Cos(γ0)) + Sin(θ1) * (Sin(α0) * Sin(β0) * Sin(γ0) +"
        " Cos(α0) * Cos(γ0)))))"
    ),
    (
        "c3 = ((Px0 * Cos(θ1) + Py0 * Sin(θ1) - Cos(θ234) * a4) * (Px0 * Cos(θ1) + Py0 *"
        " Sin(θ1) - Cos(θ234) * a4) + (Pz0 - Sin(θ234) * a4) * (Pz0 - Sin(θ234) * a4) -"
        " a2 * a2 - a3 * a3) / (2 * a2 * a3)"
    ),
    "θ3 = (180 / PI) * (Atn(Sqr(Abs(1 - c3 * c3)) / c3))",
    'Text15.Text = Format(θ3, "####.###")',
    (
        "θ2 = (180 / PI) * (Atn(((Cos(θ3) * a3 + a2) * (Pz0 - Sin(θ234) * a4) - Sin(θ3)"
        " * a3 * (Px0 * Cos(θ1) + Py0 * Sin(θ1) + Cos(θ234) * a4)) / ((Cos(θ3) * a3 +"
        " a2) * (Px0 * Cos(θ1) + Py0 * Sin(θ1) + Cos(θ234) * a4) + Sin(θ3) * a3 * (Pz0 -"
        " Sin(θ234) * a4))))"
    ),
    'Text14.Text = Format(θ2, "####.###")',
    "θ4 = θ234 - θ2 - θ3",
    'Text16.Text = Format(θ4, "####.###")',
    "θf1 = (180 / PI) * (Atn(Py1 / Px1))",
    'Text18.Text = Format(θf1, "####.###")',
    (
        "θf5 = (180 / PI) * (Atn((Sin(θf1) * Cos(α0) * Cos(β0) - Cos(θf1) * Sin(α0) *"
        " Cos(β0)) / (Sin(θf1) * (Cos(α0) * Sin(β0) * Sin(γ0) - Sin(α0) * Cos(γ0)) -"
        " Cos(θf1) * (Sin(α0) * Sin(β0) * Sin(γ0) + Cos(α0) * Cos(γ0)))))"
    ),
    'Text22.Text = Format(θf5, "####.###")',
    (
        "θf234 = (180 / PI) * (Atn((Cos(β0) * Sin(γ0)) / (Cos(θf1) * (Cos(α0) * Sin(β0)"
        " * Sin(γ0) - Sin(α0) * Cos(γ0)) + Sin(θf1) * (Sin(α0) * Sin(β0) * Sin(γ0) +"
        " Cos(α0) * Cos(γ0)))))"
    ),
    (
        "cf3 = ((Px1 * Cos(θf1) + Py1 * Sin(θf1) - Cos(θf234) * a4) * (Px1 * Cos(θf1) +"
        " Py1 * Sin(θf1) Cos(θf234) * a4) + (Pz1 - Sin(θf234) * a4) * (Pz1 - Sin(θf234)"
        " * a4) - a2 * a2 - a3 * a3) / (2 * a2 * a3)"
    ),
    "θf3 = (180 / PI) * (Atn(Sqr(Abs(1 - cf3 * cf3)) / cf3))",
    'Text20.Text = Format(θf3, "####.###")',
    (
        "θf2 = (180 / PI) * (Atn(((Cos(θf3) * a3 + a2) * (Pz1 - Sin(θf234) * a4) -"
        " Sin(θf3) * a3 * (Px1 * Cos(θf1) + Py1 * Sin(θf1) + Cos(θf234) * a4)) /"
        " ((Cos(θf3) * a3 + a2) * (Px1 * Cos(θf1) + Py1 * Sin(θf1) + Cos(θf234) * a4) +"
        " Sin(θf3) * a3 * (Pz1 - Sin(θf234) * a4))))"
    ),
    'Text19.Text = Format(θf2, "####.###")',
    "θf4 = θf234 - θf2 - θf3",
    'Text21.Text = Format(θf4, "####.###")',
    "End Sub",
    "Private Sub Command3_Click()",
    "Dim m1, m2, m3, m4, m5, n1, n2, n3, n4, n5 As Double",
    "Frame6.Visible = True",
    "'关节 1 轨迹",
    "'取值",
    "a = Text13.Text",
    "b = Text18.Text",
    "c = 10",
    ("d = a + (3 / (c * c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b - a) * (10 * 10 * 10)"),
    "If Val(a) > Val(d) Then",
    "m1 = a",
    "n1 = d",
    "Else",
    "m1 = d",
    "n1 = a",
    "End If",
    "Picture1.Cls '清空画图区域",
    ("Picture1.Scale (0, m1 + (m1 - n1) / 5)-(12, n1) '设置画图区域 根据需要进行设置大小"),
    "Picture1.ForeColor = &H0",
    "Picture1.DrawWidth = 1",
    "'画 X 轴",
    "'Picture1.Line (0, n1)-(5, n1)",
    "'标记 t 轴",
    "Picture1.CurrentX = 11.5",
    "Picture1.CurrentY = n1 + (m1 - n1) / 10",
    'Picture1.Print "t"',
    "'画 Y 轴",
    "Picture1.Line (0, n1 - 5)-(0, m1 + (m1 - n1) / 5)",
    "'标记 Y 轴",
    "Picture1.CurrentX = 0.2",
    "Picture1.CurrentY = m1 + (m1 - n1) / 5",
    'Picture1.Print "Y"',
    "'画坐标",
    "Dim i As Single",
    "For i = 1 To 10",
    "Picture1.CurrentX = i: Picture1.CurrentY = n1 + (m1 - n1) / 10: Picture1.Print i",
    "Picture1.Line (i, n1)-(i, n1 + (m1 - n1) / 15)",
    "Next i",
    "Dim j As Integer",
    "For j = 1 To 5",
    "Picture1.Line (0, n1 + (m1 - n1) / 5 * j)-(0.1, n1 + (m1 - n1) / 5 * j)",
    (
        "Picture1.CurrentX = 0.1: Picture1.CurrentY = n1 + (m1 - n1) / 5 * j:"
        " Picture1.Print Fix(n1 + ((m1 - n1) / 5) * j)"
    ),
    "Next j",
    "Picture1.DrawWidth = 2",
    "Picture1.Line (0, 0)-(0, 0) '归零收笔",
    "'开始画图",
    "For X = 0 To 10 Step 0.001 '0.001 改小可以获得更高的精度",
    (
        "Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * (X *"
        " X * X) '输入函数 可以写入自己的函数"
    ),
    "Picture1.CurrentY = (m1 + n1) / 2",
    "Picture1.CurrentX = 0.5",
    "Picture1.PSet (X, Y), vbRed '标记 X,Y 轴",
    "Next",
    "Picture1.CurrentX = 4",
    "Picture1.CurrentY = m1",
    'Picture1.Print "Y = θ 1(t)" \'将函数显示在图形上',
    "'关节 2 轨迹",
    "'取值",
    "a = Text14.Text",
    "b = Text19.Text",
    "c = 10",
    ("d = a + (3 / (c * c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b - a) * (10 * 10 * 10)"),
    "If Val(a) > Val(d) Then",
    "m2 = a",
    "n2 = d",
    "Else",
    "m2 = d",
    "n2 = a",
    "End If",
    "Picture2.Cls '清空画图区域",
    ("Picture2.Scale (0, m2 + (m2 - n2) / 5)-(12, n2) '设置画图区域 根据需要进行设置大小"),
    "Picture2.ForeColor = &H0",
    "Picture2.DrawWidth = 1",
    "'画 X 轴",
    "Picture2.Line (0, n2)-(12, n2)",
    "'标记 t 轴",
    "Picture2.CurrentX = 11.5",
    "Picture2.CurrentY = n2 + (m2 - n2) / 10",
    'Picture2.Print "t"',
    "'画 Y 轴",
    "Picture2.Line (0, n2 - 5)-(0, m2 + (m2 - n2) / 5)",
    "'标记 Y 轴",
    "Picture2.CurrentX = 0.2",
    "Picture2.CurrentY = m2 + (m2 - n2) / 5",
    'Picture2.Print "Y"',
    "'画坐标",
    "For i = 1 To 10",
    "Picture2.CurrentX = i: Picture2.CurrentY = n2 + (m2 - n2) / 10: Picture2.Print i",
    "Picture2.Line (i, n2)-(i, n2 + (m2 - n2) / 15)",
    "Next i",
    "For j = 1 To 5",
    "Picture2.Line (0, n2 + (m2 - n2) / 5 * j)-(0.1, n2 + (m2 - n2) / 5 * j)",
    (
        "Picture2.CurrentX = 0.1: Picture2.CurrentY = n2 + (m2 - n2) / 5 * j:"
        " Picture2.Print Fix(n2 + ((m2 - n2) / 5) * j)"
    ),
    "Next j",
    "Picture2.DrawWidth = 2",
    "Picture2.Line (0, 0)-(0, 0) '归零收笔",
    "'开始画图",
    "For X = 0 To 10 Step 0.001 '0.005 改小可以获得更高的精度",
    (
        "Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * (X *"
        " X * X) '输入函数 可以写入自己的函数"
    ),
    "Picture2.CurrentY = (m2 + n2) / 2",
    "Picture2.CurrentX = 0.5",
    "Picture2.PSet (X, Y), vbRed '标记 X,Y 轴",
    "Next",
    "Picture2.CurrentX = 4",
    "Picture2.CurrentY = m2",
    'Picture2.Print "Y = θ 2(t)"',
    "'关节 3 轨迹",
    "'取值",
    "a = Text15.Text",
    "b = Text20.Text",
    "c = 10",
    ("d = a + (3 / (c * c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b - a) * (10 * 10 * 10)"),
    "If Val(a) > Val(d) Then",
    "m3 = a",
    "n3 = d",
    "Else",
    "m3 = d",
    "n3 = a",
    "End If",
    "Picture3.Cls '清空画图区域",
    ("Picture3.Scale (0, m3 + (m3 - n3) / 5)-(12, n3) '设置画图区域 根据需要进行设置大小"),
    "Picture3.ForeColor = &H0",
    "Picture3.DrawWidth = 1",
    "'画 X 轴",
    "Picture3.Line (0, n3)-(12, n3)",
    "'标记 t 轴",
    "Picture3.CurrentX = 11.5",
    "Picture3.CurrentY = n3 + (m3 - n3) / 10",
    'Picture3.Print "t"',
    "'画 Y 轴",
    "Picture3.Line (0, n3 - 5)-(0, m3 + (m3 - n3) / 5) '将函数显示在图形上",
    "'标记 Y 轴",
    "Picture3.CurrentX = 0.2",
    "Picture3.CurrentY = m3 + (m3 - n3) / 5",
    'Picture3.Print "Y"',
    "'画坐标",
    "For i = 1 To 10",
    "Picture3.CurrentX = i: Picture3.CurrentY = n3 + (m3 - n3) / 10: Picture3.Print i",
    "Picture3.Line (i, n3)-(i, n3 + (m3 - n3) / 15)",
    "Next i",
    "For j = 1 To 5",
    "Picture3.Line (0, n3 + (m3 - n3) / 5 * j)-(0.1, n3 + (m3 - n3) / 5 * j)",
    (
        "Picture3.CurrentX = 0.1: Picture3.CurrentY = n3 + (m3 - n3) / 5 * j:"
        " Picture3.Print Fix(n3 + ((m3 - n3) / 5) * j)"
    ),
    "Next j",
    "Picture3.DrawWidth = 2",
    "Picture3.Line (0, 0)-(0, 0) '归零收笔",
    "'开始画图",
    "For X = 0 To 10 Step 0.001 '0.001 改小可以获得更高的精度",
    (
        "Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * (X *"
        " X * X) '输入函数 可以写入自己的函数"
    ),
    "Picture3.CurrentY = (m3 + n3) / 2",
    "Picture3.CurrentX = 0.5",
    "Picture3.PSet (X, Y), vbRed '标记 X,Y 轴",
    "Next",
    "Picture3.CurrentX = 4",
    "Picture3.CurrentY = m3",
    'Picture3.Print "Y = θ 3(t)" \'将函数显示在图形',
    "'关节 4 轨迹",
    "'取值",
    "a = Text16.Text",
    "b = Text21.Text",
    "c = 10",
    ("d = a + (3 / (c * c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b - a) * (10 * 10 * 10)"),
    "If Val(a) > Val(d) Then",
    "m4 = a",
    "n4 = d",
    "Else",
    "m4 = d",
    "n4 = a",
    "End If",
    "Picture4.Cls '清空画图区域",
    ("Picture4.Scale (0, m4 + (m4 - n4) / 5)-(12, n4) '设置画图区域 根据需要进行设置大小"),
    "Picture4.ForeColor = &H0",
    "Picture4.DrawWidth = 1",
    "'画 X 轴",
    "Picture4.Line (0, n4)-(12, n4)",
    "'标记 t 轴",
    "Picture4.CurrentX = 11.5",
    "Picture4.CurrentY = n4 + (m4 - n4) / 10",
    'Picture4.Print "t"',
    "'画 Y 轴",
    "Picture4.Line (0, n4 - 5)-(0, m4 + (m4 - n4) / 5)",
    "'标记 Y 轴",
    "Picture4.CurrentX = 0.2",
    "Picture4.CurrentY = m4 + (m4 - n4) / 5",
    'Picture4.Print "Y"',
    "'画坐标",
    "For i = 1 To 10",
    "Picture4.CurrentX = i: Picture4.CurrentY = n4 + (m4 - n4) / 10: Picture4.Print i",
    "Picture4.Line (i, n4)-(i, n4 + (m4 - n4) / 15)",
    "Next i",
    "For j = 1 To 5",
    "Picture4.Line (0, n4 + (m4 - n4) / 5 * j)-(0.1, n4 + (m4 - n4) / 5 * j)",
    (
        "Picture4.CurrentX = 0.1: Picture4.CurrentY = n4 + (m4 - n4) / 5 * j:"
        " Picture4.Print Fix(n4 + ((m4 - n4) / 5) * j)"
    ),
    "Next j",
    "Picture4.DrawWidth = 2",
    "Picture4.Line (0, 0)-(0, 0) '归零收笔",
    "'开始画图",
    "For X = 0 To 10 Step 0.001 '0.005 改小可以获得更高的精度",
    (
        "Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * (X *"
        " X * X) '输入函数 可以写入自己的函数"
    ),
    "Picture4.CurrentY = (m4 + n4) / 2",
    "Picture4.CurrentX = 0.5",
    "Picture4.PSet (X, Y), vbRed '标记 X,Y 轴",
    "Next",
    "Picture4.CurrentX = 4",
    "Picture4.CurrentY = m4",
    'Picture4.Print "Y = θ 4(t)"',
    "'关节 5 轨迹",
    "'取值",
    "a = Text17.Text",
    "b = Text22.Text",
    "c = 10",
    ("d = a + (3 / (c * c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b - a) * (10 * 10 * 10)"),
    "If Val(a) > Val(d) Then",
    "m5 = a",
    "n5 = d",
    "Else",
    "m5 = d",
    "n5 = a",
    "End If '将函数显示在图形上",
    "Picture5.Cls '清空画图区域",
    ("Picture5.Scale (0, m5 + (m5 - n5) / 5)-(12, n5) '设置画图区域 根据需要进行设置大小"),
    "Picture5.ForeColor = &H0",
    "Picture5.DrawWidth = 1",
    "'画 X 轴",
    "Picture5.Line (0, n5)-(12, n5)",
    "'标记 t 轴",
    "Picture5.CurrentX = 11.5",
    "Picture5.CurrentY = n5 + (m5 - n5) / 10",
    'Picture5.Print "t"',
    "'画 Y 轴",
    "Picture5.Line (0, n5 - 5)-(0, m5 + (m5 - n5) / 5)",
    "'标记 Y 轴",
    "Picture5.CurrentX = 0.2",
    "Picture5.CurrentY = m5 + (m5 - n5) / 5",
    'Picture5.Print "Y"',
    "'画坐标",
    "For i = 1 To 10",
    "Picture5.CurrentX = i: Picture5.CurrentY = n5 + (m5 - n5) / 10: Picture5.Print i",
    "Picture5.Line (i, n5)-(i, n5 + (m5 - n5) / 15)",
    "Next i",
    "For j = 1 To 5",
    "Picture5.Line (0, n5 + (m5 - n5) / 5 * j)-(0.1, n5 + (m5 - n5) / 5 * j)",
    (
        "Picture5.CurrentX = 0.1: Picture5.CurrentY = n5 + (m5 - n5) / 5 * j:"
        " Picture5.Print Fix(n5 + ((m5 - n5) / 5) * j)"
    ),
    "Next j",
    "Picture5.DrawWidth = 2",
    "Picture5.Line (0, 0)-(0, 0) '归零收笔",
    "'开始画图",
    "For X = 0 To 10 Step 0.001 '0.005 改小可以获得更高的精度",
    (
        "Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * (X *"
        " X * X) '输入函数 可以写入自己的函数"
    ),
    "Picture5.CurrentY = (m5 + n5) / 2",
    "Picture5.CurrentX = 0.5",
    "Picture5.PSet (X, Y), vbRed '标记 X,Y 轴",
    "Next",
    "Picture5.CurrentX = 4",
    "Picture5.CurrentY = m5",
    'Picture5.Print "Y = θ 5(t)" \'将函数显示在图形上',
    "End Sub",
    "Private Sub Command4_Click()",
    'Text1.Text = ""',
    'Text2.Text = ""',
    'Text3.Text = ""',
    'Text4.Text = ""',
    'Text5.Text = ""',
    'Text6.Text = ""',
    'Text7.Text = ""',
    'Text8.Text = ""',
    'Text9.Text = ""',
    'Text10.Text = ""',
    'Text11.Text = ""',
    'Text12.Text = ""',
    'Text13.Text = ""',
    'Text14.Text = ""',
    'Text15.Text = ""',
    'Text16.Text = ""',
    'Text17.Text = ""',
    'Text18.Text = ""',
    'Text19.Text = ""',
    'Text20.Text = ""',
    'Text21.Text = ""',
    'Text22.Text = ""',
    "End Sub",
)
"""The listing with line breaks restored, one string per VB line."""

LISTING_EXTRACTED: str = "\n".join(_LISTING_EXTRACTED_LINES)
"""The VB6 listing exactly as extracted (seed lines 1001-1039: the heading
'轨迹规划界面 VB 程序如下:', page footers 36-45 inside the code, each page's lines joined)."""

LISTING: str = "\n".join(_LISTING_LINES) + "\n"
"""The VB6 listing (appendix 程序清单, pp. 36-46: module Dim, ``Command1_Click`` "计算",
``Command3_Click`` "轨迹规划", ``Command4_Click`` "清除") with line breaks restored as
described in :data:`LISTING_RESTORATIONS`; otherwise verbatim, including the statement
that does not compile (``cf3 = ... Py1 * Sin(θf1) Cos(θf234) * a4 ...``)."""

LISTING_RESTORATIONS: list[dict] = [
    {
        "what": "line breaks",
        "detail": "the extraction joined each page's lines into one paragraph; a line break "
        "is put before every statement (Dim, If/ElseIf/Else/End If, For/Next, Sub/End Sub, "
        "assignments, PictureN.Cls/Scale/Line/PSet/Print) and before every comment that "
        "does not directly follow a statement; statements the print separated by ':' stay "
        "on one line",
    },
    {
        "what": "trailing comments",
        "detail": "a comment that follows a statement in the extraction stays on that "
        "statement's line ('清空画图区域, '设置画图区域..., '归零收笔, '0.001/'0.005 改小..., "
        "'输入函数..., '标记 X,Y 轴, '将函数显示在图形上); whether the print had them on "
        "the same line is not recoverable and does not change the program",
    },
    {
        "what": "page footers",
        "detail": "the page numbers 36, 37, 38, 39, 40, 41, 42, 43, 44, 45 that the extraction "
        "put inside the code are removed (46 follows the last End Sub)",
        "contexts": [
            "(Cos(α0) 36",
            "Command3_Click() 37",
            "To 10 38",
            "m2 = d 39",
            "可以写入自己的函数 40",
            "/ 5) 41 ",
            "Text21.Text 42",
            "* j) 43",
            "画 X 轴 44",
            "CurrentX = 4 45",
        ],
    },
    {
        "what": "heading",
        "detail": "the text '轨迹规划界面 VB 程序如下:' before the first Dim is not code",
    },
    {
        "what": "identifier spaces",
        "detail": "a space between a Greek letter and its index at the start of 18 "
        "assignments ('α 0 =', 'θ 234 =', 'θ f5 =' ...) is removed: the same names are "
        "written without the space in the Dim statements and in every expression; the "
        'spaces inside the five strings "Y = θ 1(t)" ... are kept',
    },
    {
        "what": "indentation",
        "detail": "none restored (not recoverable); VB ignores it",
    },
]
"""What was done to :data:`LISTING_EXTRACTED` to get :data:`LISTING` (nothing else)."""

LISTING_BLOCK_DIFFERENCES: list[dict] = [
    {
        "where": "Command3_Click, joint 1 block",
        "difference": "the x axis line is commented out and shorter: "
        '"\'Picture1.Line (0, n1)-(5, n1)"; joints 2-5 draw "PictureK.Line (0, nK)-(12, nK)"',
    },
    {
        "where": "Command3_Click, joints 1-5",
        "difference": "'Dim i As Single' and 'Dim j As Integer' appear in block 1 only "
        "(procedure scope, so blocks 2-5 reuse them)",
    },
    {
        "where": "Command3_Click, 'For X = 0 To 10 Step 0.001' comments",
        "difference": "blocks 1 and 3 say '0.001 改小可以获得更高的精度, blocks 2, 4, 5 say "
        "'0.005 改小...' although every block steps 0.001",
    },
    {
        "where": 'Command3_Click, comment after PictureK.Print "Y = θ K(t)"',
        "difference": "block 1 and 5: '将函数显示在图形上; block 3: '将函数显示在图形 (cut); "
        "blocks 2 and 4 have none there, and two displaced copies of '将函数显示在图形上 "
        "appear after Picture3's y-axis Line and after block 5's End If",
    },
    {
        "where": "Command3_Click, 'Dim m1, m2, m3, m4, m5, n1, n2, n3, n4, n5 As Double'",
        "difference": "only n5 is a Double; m1-m5 and n1-n4 are Variants, so mK/nK hold the "
        "TextBox String or the Double d, while n5 = a converts the String to Double",
    },
    {
        "where": "Command1_Click, end pose",
        "difference": "the θf5 and θf234 statements are copies of the start-pose statements "
        "with θ1 -> θf1 but α0, β0, γ0 unchanged: the end orientation (α1, β1, γ1, Text10-12) "
        "is read and never used",
    },
    {
        "where": "Command1_Click, c3 vs θ2 statements",
        "difference": "c3 uses 'Px0 * Cos(θ1) + Py0 * Sin(θ1) - Cos(θ234) * a4', θ2 uses "
        "'... + Cos(θ234) * a4' for the same quantity (also in cf3 vs θf2)",
    },
    {
        "where": "copies",
        "difference": "the listing is printed once (appendix pp. 36-46); chapter 6 shows no "
        "code; the table of contents lists two 程序清单 appendices (pp. 34 and 50) but the "
        "body has one appendix holding the ladder (pp. 31-35) and this listing",
    },
]
"""How the near-identical parts of the listing differ from each other (as printed)."""

GUI_CHECK: dict = {
    "location": "appendix listing, Command1_Click, p. 36",
    "printed": (
        "Command3.Enabled = True\n"
        "If Sqr((Px0 - Px1) * (Px0 - Px1) + (Py0 - Py1) * (Py0 - Py1)) > 850 Then\n"
        "Command3 = False\n"
        "ElseIf Abs(Pz0 - Pz1) > 600 Then\n"
        "Command3.Enabled = False\n"
        "End If"
    ),
    "text_claims": ["c6.3-grey", "c6.4-check"],
    "work_area_claim": "ARM['work_area']: 垂直方向 850 mm, 水平方向 600 mm",
    "note": "Command3 is the 轨迹规划 (trajectory) button; the check compares the start and "
    "end poses with each other, after which Command1_Click goes on to compute and display "
    "the joint values whatever the outcome",
}
"""The input check of the 计算 button, as printed, with the claims it is meant to meet."""

# --- the ladder diagram (appendix, pp. 31-35) ------------------------------------------------
LADDER_EXTRACTED: dict[int, str] = {
    31: "M8002 RST RST RST RST RST X20 Y40 Y40 Y40 M1 Y1 Y4 C235 Y0 C235 C236 C235 C235 C235 "
    "Y40 Y5 M11 M8235 Y0 Y5 C235 K1 Y3 C235 Y40 M2 C236 Y6 Y2 Y7",
    32: "M12 M8236 Y2 Y7 C236 K2 C236 M3 Y40 Y11 Y14 C237 Y10 Y15 M13 M8237 C237 K3 Y10 Y15 "
    "C237 Y40 Y13 Y16 C238 Y12 Y17 M14 M8238 Y12 Y17 C238 K4 C239 Y40 Y21 Y30 Y20 Y31 M15 "
    "M8239 Y20 Y31 C239 K5",
    33: "X20 Y40 Y40 Y40 M1 Y0 Y5 C235 Y40 Y1 Y4 M11 M8235 Y1 Y4 C235 K1 Y2 C235 Y40 M2 C236 "
    "Y7 Y3 Y6 M12 M8236 Y3 Y6 C236 K2 C236 M3 Y40 Y10 Y15 C237 Y11 Y14 M13 M8237",
    34: "Y11 Y114 C237 K3 C237 Y40 Y12 Y17 C238 Y13 Y16 M14 M8238 Y13 Y16 C238 K4 C239 Y40 "
    "Y20 Y31 Y21 Y30 M15 M8239 Y21 Y30 C239 K5 X21 Y41 Y41 X6 Y41 Y1 Y4",
    35: "X7 Y3 Y6 X10 Y11 Y14 X11 Y13 Y16 X12 Y20 Y31 END",
}
"""The ladder diagram ("1、机械手控制程序梯形图") as extracted, page by page: operand labels
in extraction order; every contact and coil symbol and every rung line is lost."""

LADDER: dict = {
    "location": "appendix 程序清单 item 1, pp. 31-35",
    "recoverable": {
        "first_scan_reset": "M8002 followed by five RST (the counters, presumably C235-C239)",
        "counters": {"C235": "K1", "C236": "K2", "C237": "K3", "C238": "K4", "C239": "K5"},
        "direction_relays": ["M8235", "M8236", "M8237", "M8238", "M8239"],
        "step_relays": {"M1": "C235", "M2": "C236", "M3": "C237"},
        "direction_bits": ["M11", "M12", "M13", "M14", "M15"],
        "motor_output_pairs": {
            "M1": [("Y0", "Y5"), ("Y1", "Y4")],
            "M2": [("Y2", "Y7"), ("Y3", "Y6")],
            "M3": [("Y10", "Y15"), ("Y11", "Y14")],
            "M4": [("Y12", "Y17"), ("Y13", "Y16")],
            "M5": [("Y20", "Y31"), ("Y21", "Y30")],
        },
        "two_programs": "pp. 31-32 and pp. 33-34 are the same sequence with each motor's "
        "output pair swapped (one direction each, presumably)",
        "manual_section": "X21 -> Y41; X6 -> Y1 Y4, X7 -> Y3 Y6, X10 -> Y11 Y14, "
        "X11 -> Y13 Y16, X12 -> Y20 Y31 (one input per motor, one direction only)",
        "other": ["X20", "Y40", "Y41", "END"],
    },
    "not_recoverable": [
        "contact types (normally open / closed), coils vs contacts, SET/RST targets",
        "rung boundaries, series/parallel structure, rung order",
        "which output pair turns a motor forward; what Y40 and Y41 drive",
        "how the step relays M4, M5 (never seen) or the sequence M1 -> M2 -> ... are set",
        "'Y114' on p. 34 (not a valid FX2N output in the series; Y14 with a stray digit?)",
    ],
    "presets_vs_table2_3": "the ladder's counter constants are K1..K5, not Table 2-3's "
    "4, 147, 118, 31, 16 (sec. 6.4 says the 写入 PLC button writes the data to the counters; "
    "that code is not in the listing)",
    "sequence_claim": "c2.3.4-sequential",
}
"""What the ladder diagram says as far as the extraction lets one read it."""

# --- claims in the text ----------------------------------------------------------------------
TEXT_CLAIMS: dict[str, dict] = {
    "c1.3-dh": {
        "location": "sec. 1.3 item 1, p. 4",
        "printed": "对机械手进行位姿描述,应用 D-H 参数法建立串联关节机器人杆件坐标系,求解位姿正解",
        "statement": "the thesis sets up the D-H link frames of the arm and solves its "
        "forward kinematics",
    },
    "c2.3.2-encoder": {
        "location": "sec. 2.3.2, p. 7",
        "printed": "码盘为 6 孔均匀分布的金属盘 ... 从 A、B 输出信号, 码盘每旋转一周发送 12 次信号",
        "statement": "6 holes, channels A and B: 12 signals per revolution of the motor",
    },
    "c2.3.4-sequential": {
        "location": "sec. 2.3.4 item 1 and Figure 2-1, p. 7-8",
        "printed": "程序启动后,各个电机按照程序要求逐个开始运动 ... 计数器计满数据后,PLC 输出控制"
        "指令,使 M1 停止转动,同时依次逐个启动控制电机 M2、M3、M4、M5 开始转动",
        "statement": "the motors run one after another, M1 to M5, each until its counter is full",
    },
    "c2.3.4-presets": {
        "location": "sec. 2.3.4 item 2, p. 8",
        "printed": "转动角度由计数器计数控制,计数器值满后断电使电机停止运转。各计数器的值由"
        "表 2-1 和轨迹规划的结果表 5-4 确定如表 2-3。",
        "statement": "each counter preset follows from the joint angle change (Table 5-4) "
        "and the resolution (Table 2-1)",
    },
    "c4.2-source": {
        "location": "sec. 4.2, p. 18",
        "printed": "参考同组同学论文逆向运动学部分可得如下结果",
        "statement": "the inverse kinematics is taken from a group-mate's thesis",
    },
    "c4.2-any-pose": {
        "location": "sec. 4.2, p. 19",
        "printed": "以上结果,给出了机械手置于任何期望位姿时所需的关节值,为下一章轨迹规划所用。",
        "statement": "the results give the joint values for any desired pose",
    },
    "c5.4.1-unique": {
        "location": "sec. 5.4.1, p. 22",
        "printed": "上面给出的四个约束条件可以惟一地确定一个三次多项式",
        "statement": "the four conditions 5.1-5.2 determine one cubic",
    },
    "c5.4.2-acc": {
        "location": "sec. 5.4.2, p. 23",
        "printed": "为了使实际生成的轨迹平滑,在机械手的整个工作期间,除了保证其运动和速度的连续之外,"
        "还应该保证加速度不发生突变,使运动平稳。根据已知条件和前文的讨论,选用三次多项式轨迹规划"
        "方法进行规划。",
        "statement": "besides continuous motion and velocity the acceleration must not jump; "
        "the cubic is chosen on that basis",
    },
    "c5.4.2-forward": {
        "location": "sec. 5.4.2, p. 23",
        "printed": "本文所研究的是五自由度机械手的正运动问题",
        "statement": "the problem studied is the forward motion problem of a 5-DOF arm",
    },
    "c6.2-buttons": {
        "location": "sec. 6.2, p. 25",
        "printed": "其中命令控制区有 5 个控件:计算、轨迹规划、输出、写入 PLC 和清除。",
        "statement": "five buttons: compute, trajectory, output, write to PLC, clear",
    },
    "c6.3-grey": {
        "location": "sec. 6.3 item 3, p. 26",
        "printed": "该控件在计算前,或在数据超出范围时呈现灰色,不能对其进行操作",
        "statement": "the trajectory button is grey before computing or when the data are "
        "out of range",
    },
    "c6.4-check": {
        "location": "sec. 6.4 item 1, p. 26",
        "printed": "按计算控件,对输入机械手起点和终点的位姿参数进行判断,当数据符合要求就会得出"
        "计算出并显示关节变量角数值,同时,轨迹控制控件回到可控状态",
        "statement": "the compute button checks the input poses and shows joint values only "
        "when they meet the requirements",
    },
    "c6.4-plc": {
        "location": "sec. 6.4 item 4, p. 27",
        "printed": "写入 PLC 控件的运行是将前一步输出的控制数据写入 PLC 计数器中",
        "statement": "the write-to-PLC button writes the control data into the PLC counters",
    },
}
"""Statements in the text that the audit checks, by id."""

STRUCTURE: list[dict] = [
    {
        "location": "heading before 3.4, p. 13",
        "printed": "3.3 点在空间直角坐标系中绕过原点任意轴的一般旋转变换",
        "note": "second section numbered 3.3 (after 3.3 空间齐次坐标变换)",
    },
    {
        "location": "sec. 3.4 heading, p. 15",
        "printed": "3.4 Denavt-Hartenberg(D-H)表示法",
        "note": "Denavit misspelt",
    },
    {
        "location": "sec. 3.4, p. 15",
        "printed": "如图 2.5 所示",
        "note": "no Figure 2.5 exists; the link-parameter figure is 图3-5",
    },
    {
        "location": "Figures 3-4, pp. 12 and 15",
        "printed": "图 3-4 平移变换与旋转变换 / 图 3-4 关节参数规定",
        "note": "two figures numbered 3-4",
    },
    {
        "location": "eqs. 3.3-3.4, p. 10",
        "printed": "(3.3) ... (3.3) (3.4)",
        "note": "eq. 3.3 is used twice, eq. 3.2 never",
    },
    {
        "location": "table of contents and appendices, pp. 31, 47",
        "printed": "附录错误!未找到引用源。程序清单",
        "note": "Word's 'Error! Reference source not found.' printed in the appendix headings",
    },
    {
        "location": "sec. 3.4.3, p. 17",
        "printed": "特别当 i=6 时,求得 T 矩阵,T ? A6",
        "note": "six links written for a five-joint arm (generic text)",
    },
    {
        "location": "table of contents vs chapter 6 heading",
        "printed": "第 6 章 系统交流界面设计 / 第 6 章 系统交互界面设计",
        "note": "different chapter titles",
    },
]
"""Numbering and cross-reference slips of the print (not used by the checks)."""

# --- what the extraction lost, and readings it leaves open -----------------------------------
LOST: dict[str, str] = {
    "sec. 4.1": "the forward-kinematics section has no body: no D-H table, frame figure or "
    "T matrix of the GR-1",
    "Table 2-1": "the grid: axis, motor code and resolution are matched by order only; the "
    "motor data (item 2) came out inside the table text",
    "sec. 2.1 item b": "the symbol after the waist's '≥' ('? 180': ± presumably) and the "
    "order of the three values printed after '肩: 肘: 手俯仰:'",
    "chapter 3 Greek letters": "every Greek letter of eqs. 3.5-3.19 and of the RPY "
    "definition is a '?' (names phi/theta/psi assumed)",
    "chapter 3 and 4 operators": "every +, -, = and bracket of eqs. 3.1-3.19 and of the "
    "section 4.2 results is a '?'",
    "eqs. 5.5-5.9": "bodies lost (numbers only): the coefficient system, its solution, the "
    "interpolation function, velocity and acceleration",
    "Table 5-3": "the three angle headers",
    "Table 5-4": "the body: ten numbers come out after the next paragraph; the header's "
    "joint order is scrambled",
    "Tables 5-1, 5-2": "grids (text only, scrambled)",
    "figures": "all drawings: Figs. 1-1, 3-1 to 3-5, 6-1 to 6-3 (GUI screenshots); "
    "Figure 2-1 (flow chart) survives as scattered labels without the C237 box",
    "ladder diagram": "contacts, coils and rung lines; only operand labels survive "
    "(LADDER_EXTRACTED)",
    "listing layout": "line breaks (restored, LISTING_RESTORATIONS) and indentation",
    "listing: buttons": "the 输出 (output) and 写入 PLC (write to PLC) handlers named in "
    "sec. 6.2 are not in the listing: no code path writes Table 2-3 to the PLC",
}
"""What the text extraction (or the print) does not contain, by location."""

UNCERTAIN: dict[str, str] = {
    "Table 5-4 cells": "see TABLE5_4['basis'] and ['uncertainty']: pair order from "
    "theta1 = atan(py/px), joint order from the listing",
    "Table 5-3 angle order": "the angle headers are lost; α, β, γ (RPY about z, y, x) in "
    "the listing's input order is assumed; the listing reproduces Table 5-4 with it",
    "listing cf3 operator": "'Py1 * Sin(θf1) Cos(θf234) * a4' has no operator between "
    "the terms: a syntax error as printed; whether the '-' was lost in the print or the "
    "extraction cannot be told (the extraction keeps every other '-' of the listing)",
    "sec. 4.2 signs": "every operator of the section 4.2 results is a '?'; EQUATIONS reads "
    "them as the listing's statements for the same quantities where the listing is "
    "self-consistent (c3), and as '-' before c234*a4 in s2, c2, theta2 where the listing "
    "has '+' (its theta2 and c3 disagree)",
    "sec. 4.2 second solutions": "theta' = theta ? 180: '+' read",
    "eq. 3.18 subscripts": "printed atan2(ox, nx) and atan2(ay, az) (for phi and psi) may "
    "carry subscripts displaced by the extraction; as extracted neither inverts eq. 3.15",
    "eq. 3.15 signs": "read from the column order of the extraction and the product 3.14",
    "joint ranges": "waist '≥ ? 180' (±180 read); the order 200, 270, 270 for shoulder, "
    "elbow, wrist pitch",
    "motor voltage": "'U = ? 12 V' (±12 V or 12 V)",
    "hand length": "'手后部:73mm' (rear part of the hand?) is used as a4 = 73 by the listing",
    "work area": "850 mm vertical and 600 mm horizontal: spans or radii is not said",
    "encoder counting": "12 signals per revolution come from two channels; a single-phase "
    "counter on one input (Table 2-2) sees one channel unless the interface circuit "
    "combines them (the circuit is in the group-mate's thesis)",
    "ladder Y114": "an operand 'Y114' on p. 34 where the pattern expects Y14",
    "displaced comments": "two copies of '将函数显示在图形上 sit after Picture3's y-axis Line "
    "and after block 5's End If (blocks 2 and 4 lack it after Print)",
}
"""Readings the text cannot decide, by item."""
