"""Audit items for the STL of Figures 3-6 (PLC semantics, units, branches, data flow).

Each item's ``verify(text)`` runs an STL fragment (instructions separated by ``;`` or
newlines) through :func:`analysis.plc.stl_eval.evaluate` with the inputs a correct program
would see, and compares with the corrected kinematics of :mod:`analysis.kinematics.arm` and the
pulse rule of :mod:`analysis.kinematics.pulses`. Facts about the S7-200 come from the S7-200
System Manual's instruction descriptions (in-place arithmetic, MOVD/MOVR, ROUND, REAL
format). Used by :func:`analysis.audit.grabber_audit.audit`.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

import numpy as np

from analysis.audit.grabber_items import verify_angle
from analysis.audit.table4 import load_printed
from analysis.kinematics.arm import Arm, paper_arm
from analysis.kinematics.pulses import angles_to_pulses
from analysis.papers import grabber as paper
from analysis.plc import stl_eval as stl

__all__ = ["CORRECTED_FIG4", "figure5_repaired", "stl_items"]

CORRECTED_FIG4 = (
    "LD 上电置1; MOVR VD4, VD12; /R VD0, VD12; CALL ARCTAN, VD12, VD12; MOVR VD12, VD16; "
    "AENO; *R 57.29578, VD16; AENO; /R 360.0, VD16; AENO; *R 4000.0, VD16; AENO; ROUND VD16, VD16"
)
"""Figure 4 with the radian-to-degree factor and VD12 left holding theta1 (quadrant aside)."""

_REL32 = 1e-6  # float32 REAL arithmetic: a few ulps (6e-8 each) over a handful of operations


def _prog(text: str) -> list[stl.Instr]:
    return stl.parse_stl(text.replace(";", "\n"))


def _one_line(listing: str) -> str:
    def one(i):
        op = i.op.replace("CALL ", "CALL ") + ("," if i.op.startswith("CALL ") and i.args else "")
        return f"{op} {', '.join(i.args)}".strip()

    return "; ".join(one(i) for i in stl.parse_stl(listing))


def _reachable_rows() -> tuple[np.ndarray, np.ndarray]:
    """Table 4 targets with a solution and their front-up angles [rad]."""
    p = load_printed()[["x_mm", "y_mm", "z_mm"]].astype(float).to_numpy()
    sol = paper_arm().solve(p, ("front-up",))
    ok = sol.ok[:, 0]
    return p[ok], sol.theta[ok, 0, :]


def figure5_repaired() -> str:
    """Figure 5 (reconstruction) with only the two local repairs of the register applied:
    ``VD92 := 310 * VD68`` moved before VD68 is overwritten (paper-fig5-vd68) and the
    radian-to-degree factor before ``/R 360.0, VD118`` (paper-fig5-unit). The
    single-argument ARCTAN is kept, so the 180 deg error of eq. 18 remains visible."""
    lines = paper.FIGURE_STL[5].splitlines()
    i92 = next(i for i, ln in enumerate(lines) if ln.startswith("MOVR   VD68, VD92"))
    block, rest = lines[i92 : i92 + 3], lines[:i92] + lines[i92 + 3 :]
    isin = next(i for i, ln in enumerate(rest) if ln.startswith("SIN    VD48, VD68"))
    text = "\n".join(rest[: isin + 1] + block + rest[isin + 1 :]) + "\n"
    return text.replace("/R     360.0, VD118", "*R     57.29578, VD118\n/R     360.0, VD118")


def figure5_c2(listing: str, p, q) -> int:
    """c2 (VD122) of a Figure 5 listing for target ``p`` [mm], given the correct theta1 in
    VD12 and theta3 in VD48 [rad] (what Figures 4 and 6 should deliver)."""
    regs = dict(VD0=p[0], VD4=p[1], VD8=p[2], VD12=q[0], VD48=q[2])
    return stl.dint(stl.evaluate(stl.parse_stl(listing), stl.real_memory(**regs)), "VD122")


def _fmt(p) -> str:
    return "(" + ", ".join(f"{v:g}" for v in p) + ")"


def _run(text: str, **regs: float) -> dict[str, int]:
    return stl.evaluate(_prog(text), stl.real_memory(**regs))


@dataclass
class _Audit:
    """What every figure's checks share: the arm, Table 4's reachable rows, the listings."""

    Item: type
    arm: Arm
    P: np.ndarray  # reachable Table 4 targets [mm]
    Q: np.ndarray  # their corrected front-up angles [rad]
    fig: dict[int, str]  # the printed listings, one line each
    items: list = field(default_factory=list)

    @property
    def c_ok(self) -> np.ndarray:
        """Pulses of the corrected angles, (n, 3)."""
        return angles_to_pulses(self.Q)

    def add(self, key, location, printed, corrected, kind, verify, evidence, derived=""):
        ok = verify(printed)
        self.items.append(
            self.Item(
                f"paper-{key}",
                location,
                printed,
                derived or corrected,
                "holds" if ok else "wrong",
                evidence,
                "" if ok else kind,
                "" if ok else corrected,
                verify,
            )
        )


def stl_items(Item) -> list:
    """The STL audit items (built with the :class:`analysis.audit.register.Item` class given)."""
    P, Q = _reachable_rows()
    fig = {k: _one_line(v) for k, v in paper.FIGURE_STL.items()}
    a = _Audit(Item, paper_arm(), P, Q, fig)
    for family in (_figure3, _figure4, _figure5, _figure5_atan, _figure6, _reach):
        family(a)
    return a.items


def _figure3(a: _Audit) -> None:
    """Figure 3: MOVD stores integers; the REAL reads of Figures 4-6 see denormals."""
    add = a.add
    # Figure 3: MOVD stores integers; the REAL reads of Figures 4-6 see denormals
    target = (100.0, 100.0, 600.0)

    def v_fig3(text):
        m = stl.evaluate(_prog(text))
        return all(
            abs(stl.real(m, a) - t) <= 1e-6 * t
            for a, t in zip(("VD0", "VD4", "VD8"), target, strict=True)
        )

    m3 = stl.evaluate(stl.parse_stl(paper.FIGURE_STL[3]))
    add(
        "fig3-movd",
        "Figure 3",
        "MOVD 100, VD0; MOVD 100, VD4; MOVD 600, VD8",
        "MOVR 100.0, VD0; MOVR 100.0, VD4; MOVR 600.0, VD8",
        "PLC semantics",
        v_fig3,
        f"MOVD copies the DINT bit pattern 16#{m3['VD0']:08X}; read as REAL (Figure 4's MOVR, /R) "
        f"VD0 = {stl.real(m3, 'VD0'):.4g}, not 100.0",
    )


def _figure4(a: _Audit) -> None:
    """Figure 4: the unit of ARCTAN's result, the in-place /R, the quadrant, the CALL alias."""
    arm, P, Q, c_ok, fig, add = a.arm, a.P, a.Q, a.c_ok, a.fig, a.add

    # Figure 4: units of ARCTAN's result
    def c1_of(text, p):
        m = _run(text, VD0=p[0], VD4=p[1], VD8=p[2])
        return stl.dint(m, "VD16"), stl.real(m, "VD12")

    def v_fig4_unit(text):
        return all(c1_of(text, p)[0] == c[0] for p, c in zip(P, c_ok, strict=True))

    c_printed = c1_of(fig[4], P[0])[0]
    add(
        "fig4-unit",
        "Figure 4",
        fig[4],
        CORRECTED_FIG4,
        "unit",
        v_fig4_unit,
        f"ARCTAN returns radians (Siemens 'Arcusfunctions'; Figure 5 feeds the same VD12 to COS, which "  # noqa: E501
        f"takes radians): target {_fmt(P[0])} mm gives c1 = {c_printed}, eq. 20 needs {c_ok[0, 0]}",
    )

    def v_fig4_vd12(text):
        return all(
            abs(c1_of(text, p)[1] - q[0]) <= _REL32 * abs(q[0]) for p, q in zip(P, Q, strict=True)
        )

    add(
        "fig4-vd12",
        "Figure 4 -> Figure 5",
        fig[4],
        CORRECTED_FIG4,
        "PLC semantics",
        v_fig4_vd12,
        f"'/R 360.0, VD12' divides in place (OUT := OUT / IN1): after Figure 4 VD12 = theta1/360 = "
        f"{c1_of(fig[4], P[0])[1]:.6f}, but Figure 5 reads VD12 as theta1 ({Q[0, 0]:.6f} rad) in COS/SIN",  # noqa: E501
    )

    # Figure 4: single-argument ARCTAN loses the quadrant (and Px = 0 divides by zero)
    probes = np.array([[-100.0, 100.0, 600.0], [-200.0, -100.0, 700.0]])
    q_probe = arm.solve(probes, ("front-up",)).branch("front-up")

    def v_fig4_quadrant(text):
        if text.startswith("theta1"):
            rhs = paper.parse(text.split("=", 1)[1])
            vals = [
                float(rhs.subs({paper.SYMBOLS["Px"]: p[0], paper.SYMBOLS["Py"]: p[1]}).evalf())
                for p in probes
            ]
        else:
            vals = [c1_of(text, p)[1] for p in probes]
        return bool(np.allclose(vals, q_probe[:, 0], atol=1e-6))

    add(
        "fig4-quadrant",
        "Figure 4",
        "MOVR VD4, VD12; /R VD0, VD12; CALL ARCTAN, VD12, VD12",
        "theta1 = atan2(Py, Px)",
        "branch/quadrant",
        v_fig4_quadrant,
        f"target {_fmt(probes[0])} mm: ARCTAN(Py/Px) = {np.degrees(np.arctan(probes[0, 1] / probes[0, 0])):.2f} deg, "  # noqa: E501
        f"theta1 = {np.degrees(q_probe[0, 0]):.2f} deg; Px = 0 divides by zero (SM1.3)",
    )

    # CALL ARCTAN, VD12, VD12: IN and OUT on the same address is harmless (IN copied at call)
    def v_alias(text):
        a = stl.real(_run(text, VD12=0.5), "VD12")
        b = stl.real(_run("CALL ARCTAN, VD12, VD20", VD12=0.5), "VD20")
        return a == b

    add(
        "fig4-call-alias",
        "Figure 4",
        "CALL ARCTAN, VD12, VD12",
        "",
        "PLC semantics",
        v_alias,
        "IN parameters are copied to L memory at the call, OUT written back at return "
        "(S7-200 System Manual, in-place math): same result as with a separate OUT address",
        derived="same as CALL ARCTAN, VD12, VD20",
    )


def _figure5(a: _Audit) -> None:
    """Figure 5: the VD68 overwrite and the unit of theta2."""
    arm, P, Q, c_ok, add = a.arm, a.P, a.Q, a.c_ok, a.add
    L2, L3 = arm.params.L2, arm.params.L3
    # Figure 5: VD68 holds sin(theta3) and is overwritten before VD92 := 310 * VD68
    frag5 = "SIN VD48, VD68; MOVR 310.0, VD68; *R VD64, VD68; +R 200.0, VD68; MOVR VD68, VD92; *R 310.0, VD92"  # noqa: E501
    fix5 = "SIN VD48, VD68; MOVR VD68, VD92; *R 310.0, VD92; MOVR 310.0, VD68; *R VD64, VD68; +R 200.0, VD68"  # noqa: E501

    def v_fig5_vd68(text):
        for q in Q:
            m = _run(text, VD48=q[2], VD64=np.cos(q[2]))
            want92, want68 = L2 * np.sin(q[2]), L2 * np.cos(q[2]) + L3
            if (
                abs(stl.real(m, "VD92") - want92) > 1e-4 * L2
                or abs(stl.real(m, "VD68") - want68) > 1e-4 * L2
            ):
                return False
        return True

    i3 = 2  # Table 4 row 3: eq. 18's denominator is positive there, so only the overwrite matters
    c2_printed = figure5_c2(paper.FIGURE_STL[5], P[i3], Q[i3])
    c2_fixed = figure5_c2(figure5_repaired(), P[i3], Q[i3])
    c2_row1 = figure5_c2(figure5_repaired(), P[0], Q[0])
    add(
        "fig5-vd68",
        "Figure 5 (reconstructed order)",
        frag5,
        fix5,
        "PLC semantics",
        v_fig5_vd68,
        "VD68 must hold L2 sin(theta3) for VD92 and L2 cos(theta3) + L3 for VD76/VD104; in the printed "  # noqa: E501
        f"column order it is overwritten first. Whole listing, Table 4 row 3 with correct inputs: "
        f"c2 = {c2_printed} (correct {c_ok[i3, 1]}); with this repair and the degree factor "
        f"(paper-fig5-unit) c2 = {c2_fixed}, and row 1 gives {c2_row1} = {c_ok[0, 1]} + 2000 "
        "(+180 deg: Table 4's 190.20). Depends on the reconstructed reading order.",
    )

    # Figure 5: theta2 in radians scaled as degrees
    frag5u = "MOVR VD114, VD118; -R VD48, VD118; /R 360.0, VD118; MOVR VD118, VD122; *R 4000.0, VD122; ROUND VD122, VD122"  # noqa: E501
    fix5u = frag5u.replace("/R 360.0, VD118", "*R 57.29578, VD118; /R 360.0, VD118")

    def v_fig5_unit(text):
        return all(
            stl.dint(_run(text, VD114=q[1] + q[2], VD48=q[2]), "VD122") == c[1]
            for q, c in zip(Q, c_ok, strict=True)
        )

    add(
        "fig5-unit",
        "Figure 5",
        frag5u,
        fix5u,
        "unit",
        v_fig5_unit,
        f"theta2 = ARCTAN(...) - theta3 is in radians; Table 4 row 1 gives c2 = "
        f"{stl.dint(_run(frag5u, VD114=Q[0, 1] + Q[0, 2], VD48=Q[0, 2]), 'VD122')}, eq. 21 needs {c_ok[0, 1]}",  # noqa: E501
    )


def _figure5_atan(a: _Audit) -> None:
    """Figure 5: eq. 18's single-argument ARCTAN; the network order of Figures 5 and 6."""
    arm, P, Q, add = a.arm, a.P, a.Q, a.add
    L2, L3 = arm.params.L2, arm.params.L3

    # Figure 5: eq. 18's single-argument ARCTAN
    def num(p, q):  # numerator of eq. 18 with r = rho (front branch)
        z = p[2] - arm.params.L1
        return z * (L2 * np.cos(q[2]) + L3) + np.hypot(p[0], p[1]) * L2 * np.sin(q[2])

    def den(p, q):  # denominator of eq. 18
        z = p[2] - arm.params.L1
        return np.hypot(p[0], p[1]) * (L2 * np.cos(q[2]) + L3) - z * L2 * np.sin(q[2])

    def v_fig5_atan(text):
        if text.startswith("theta"):
            return verify_angle(text)
        return all(
            abs(stl.real(_run(text, VD100=num(p, q), VD110=den(p, q)), "VD114") - (q[1] + q[2]))
            < 1e-5
            for p, q in zip(P, Q, strict=True)
        )

    add(
        "fig5-atan",
        "Figure 5",
        "MOVR VD100, VD114; /R VD110, VD114; CALL ARCTAN, VD114, VD114",
        f"theta2 + theta3 = atan2({paper.EQ18_NUM}, {paper.EQ18_DEN})",
        "branch/quadrant",
        v_fig5_atan,
        f"Table 4 row 1: ARCTAN(num/den) = {np.degrees(np.arctan(num(P[0], Q[0]) / den(P[0], Q[0]))):.2f} deg, "  # noqa: E501
        f"theta2 + theta3 = {np.degrees(Q[0, 1] + Q[0, 2]):.2f} deg (den < 0): the 190.20 of Table 4",  # noqa: E501
    )

    # network order: Figure 5 reads theta3 (VD48) before Figure 6 writes it
    def v_order(text):
        order = [int(d) for d in re.findall(r"\d", text)]
        written = set()
        for f in order:
            for ins in stl.parse_stl(paper.FIGURE_STL[f]):
                w, r = stl.defs_uses(ins)
                if "VD48" in r and "VD48" not in written and f == 5:
                    return False
                written |= w
        return True

    add(
        "fig5-order",
        "Figures 5-6",
        "network order 3, 4, 5, 6",
        "network order 3, 4, 6, 5",
        "PLC semantics",
        v_order,
        "Figure 5 reads VD48 (theta3: COS VD48, -R VD48) before Figure 6 writes it "
        "(CALL ARCCOS ..., VD48): in the first scan theta2 uses VD48 = 0, later the previous scan's value",  # noqa: E501
    )


def _figure6(a: _Audit) -> None:
    """Figure 6: the VDD0 operand, 2 L2 L3, the ARCCOS branch, the unit of theta3."""
    arm, Q, c_ok, add = a.arm, a.Q, a.c_ok, a.add
    L2, L3 = arm.params.L2, arm.params.L3
    # Figure 6: VDD0 is not an operand; SIN/COS need theta1 (VD12), the products need Px (VD0)
    theta1_addr = next(
        i.args[-1] for i in stl.parse_stl(paper.FIGURE_STL[4]) if i.op == "CALL ARCTAN"
    )
    px_addr = next(i.args[-1] for i in stl.parse_stl(paper.FIGURE_STL[3]) if i.op == "MOVD")

    def v_vdd0(text):
        prog = _prog(text)
        if stl.invalid_operands(prog):
            return False
        trig_ok = all(i.args[0] == theta1_addr for i in prog if i.op in ("SIN", "COS"))
        mul_ok = all(i.args[0] == px_addr for i in prog if i.op == "*R")
        return trig_ok and mul_ok

    add(
        "fig6-vdd0",
        "Figure 6",
        "COS VDD0, VD180; SIN VDD0, VD192; *R VDD0, VD188; *R VDD0, VD208",
        f"COS {theta1_addr}, VD180; SIN {theta1_addr}, VD192; *R {px_addr}, VD188; *R {px_addr}, VD208",  # noqa: E501
        "PLC semantics",
        v_vdd0,
        f"VDD0 is no S7-200 address; cos/sin theta1 need {theta1_addr} (Figure 4's ARCTAN output), "
        f"Px is in {px_addr} (Figure 3): one operand cannot be both",
    )

    # Figure 6: 2 L2 L3
    def v_2l2l3(text):
        return abs(stl.real(_run(text), "VD40") - 2 * L2 * L3) < 1e-3

    add(
        "fig6-2l2l3",
        "Figure 6 (reconstructed)",
        "MOVR 310.0, VD40; *R 310.0, VD40; +R VD40, VD40",
        "MOVR 310.0, VD40; *R 200.0, VD40; +R VD40, VD40",
        "transcription",
        v_2l2l3,
        f"eq. 10 divides by 2 L3 L2 = {2 * L2 * L3:g}; the printed constants give {2 * L2 * L2:g} "
        "(reading of the scrambled columns uncertain)",
    )

    # Figure 6: ARCCOS gives theta3 >= 0 only
    def v_acos(text):
        return all(abs(stl.real(_run(text, VD48=np.cos(q[2])), "VD48") - q[2]) < 1e-5 for q in Q)

    add(
        "fig6-branch",
        "Figure 6",
        "CALL ARCCOS, VD48, VD48",
        "CALL ARCCOS, VD48, VD48; *R -1.0, VD48",
        "branch/quadrant",
        v_acos,
        f"ARCCOS returns [0, pi]; Table 4 row 1 needs theta3 = {np.degrees(Q[0, 2]):.2f} deg (front-up, elbow up)",  # noqa: E501
    )

    # Figure 6: theta3 in radians times 4000
    frag6u = "MOVR VD48, VD52; *R 4000.0, VD52; ROUND VD52, VD52"
    fix6u = "MOVR VD48, VD52; *R 57.29578, VD52; /R 360.0, VD52; *R 4000.0, VD52; ROUND VD52, VD52"

    def v_fig6_unit(text):
        return all(
            stl.dint(_run(text, VD48=q[2]), "VD52") == c[2] for q, c in zip(Q, c_ok, strict=True)
        )

    add(
        "fig6-unit",
        "Figure 6",
        frag6u,
        fix6u,
        "unit",
        v_fig6_unit,
        f"no degree conversion (and no /R 360.0 is legible): Table 4 row 1 gives c3 = "
        f"{stl.dint(_run(frag6u, VD48=Q[0, 2]), 'VD52')}, eq. 22 needs {c_ok[0, 2]}; with '/R 360.0' added "  # noqa: E501
        f"it would be {stl.dint(_run(frag6u.replace('*R 4000.0', '/R 360.0, VD52; *R 4000.0'), VD48=Q[0, 2]), 'VD52')}",  # noqa: E501
    )


def _reach(a: _Audit) -> None:
    """Figures 5-6: no reach check before ARCCOS."""
    arm, add = a.arm, a.add
    L2, L3 = arm.params.L2, arm.params.L3
    # no reach check anywhere before ARCCOS
    t4 = load_printed()[["x_mm", "y_mm", "z_mm"]].astype(float).to_numpy()
    allp = np.vstack([t4, [[0.0, 600.0, 660.0], [50.0, 0.0, 660.0]]])
    rho, z = np.hypot(allp[:, 0], allp[:, 1]), allp[:, 2] - arm.params.L1
    arg = (rho**2 + z**2 - L2**2 - L3**2) / (2 * L2 * L3)

    def v_reach(text):
        if "no range check" in text:
            accept = np.ones(len(allp), bool)
        else:
            lo, hi = (float(v) for v in re.findall(r"(-?\d+\.\d+)", text)[:2])
            accept = (arg >= lo) & (arg <= hi)
        return bool(np.array_equal(accept, arm.is_reachable(allp)))

    add(
        "stl-reach",
        "Figures 5-6",
        "CALL ARCCOS, VD48, VD48 (no range check of its argument)",
        "reachable iff -1.0 <= VD44 <= 1.0 (LDR>= VD44, -1.0; AR<= VD44, 1.0) before ARCCOS; else no pulses",  # noqa: E501
        "PLC semantics",
        v_reach,
        f"Table 4 row 8 ({t4[7, 0]:g}, {t4[7, 1]:g}, {t4[7, 2]:g}): ARCCOS argument {arg[7]:.4f} > 1, "  # noqa: E501
        "the listing has no branch for it (NaN; a NaN in a REAL compare stops an S7-200 (System Manual))",  # noqa: E501
    )
