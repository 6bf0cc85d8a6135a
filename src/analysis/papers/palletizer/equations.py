"""Seed 001's displayed mathematics as printed: eq. 8 and the five link transforms of section
4.2 (:data:`MATRICES`) and eqs. 1-12 (:data:`EQUATIONS`), each with its extracted run."""

from __future__ import annotations

import sympy as sp

from analysis.papers.palletizer.symbols import parse

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
