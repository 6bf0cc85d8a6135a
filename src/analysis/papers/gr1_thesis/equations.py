"""The printed equations of the GR-1 thesis (eqs. 3.17, 3.18, the inverse-kinematics results
of section 4.2, eqs. 5.1-5.4) as SymPy strings over
:data:`analysis.papers.gr1_thesis.SYMBOLS`."""

from __future__ import annotations

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
