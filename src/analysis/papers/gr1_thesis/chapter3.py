"""Chapter 3 and section 4.1 of the GR-1 thesis as printed: the RPY convention (section 3.3,
eq. 3.14), the printed matrices (eqs. 3.5-3.7, 3.15, 3.16, 3.19) and the D-H table that
section 4.1 does not print."""

from __future__ import annotations

import sympy as sp

from analysis.papers.gr1_thesis.symbols import parse

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


def matrix(name: str) -> sp.Matrix:
    """A printed matrix of :data:`MATRICES` as a SymPy matrix."""
    if name not in MATRICES:
        raise ValueError(f"unknown printed matrix {name!r}; expected one of {sorted(MATRICES)}")
    return sp.Matrix([[parse(e) for e in row] for row in MATRICES[name]["rows"]])
