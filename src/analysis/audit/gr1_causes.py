"""Seed 004's register: the GR-1 thesis's findings as root causes, each shown where it
appears, each with a check that rejects the printed text and accepts the correction.

The checks run what they check: equations of chapter 3 and section 4.2 on 200 seeded
configurations of the GR-1's chain (:func:`analysis.audit.gr1_checks.equation_holds`),
statements of the VB6 listing in the VB6 interpreter with the listing's variables preset for
a known configuration (:func:`analysis.audit.gr1_checks.run_statement`; ``trig_degrees``
isolates the unit defect from the others), poses through the arm's closed form, the cubic
in SymPy, the PLC's move through :mod:`analysis.studies.gr1`. Evidence numbers are computed
here, not typed.

This module holds the causes found in the VB6 listing (Command1_Click) and builds the
register; :mod:`analysis.audit.gr1_causes_model` has the kinematics, Table 5-4, what the
extraction lost and what holds, :mod:`analysis.audit.gr1_causes_plc` the PLC, the trajectory
and the work area.
"""

from __future__ import annotations

import math
import re
from functools import cache

from analysis.audit import gr1_checks as chk
from analysis.audit import vb6
from analysis.audit.gr1_checks import printed_run as _printed_run
from analysis.audit.schema import Cause, Manifestation, Register
from analysis.audit.schema import all_fail as _all_fail
from analysis.audit.schema import make_cause as _cause
from analysis.kinematics.status import Status
from analysis.papers import gr1_thesis as paper
from analysis.studies import gr1 as study

_arm = study.gr1_arm

__all__ = ["register"]

LISTING_LOC = "appendix listing, Command1_Click, pp. 36-37"
W_T1 = (150.0, 30.0, 60.0, -50.0, 20.0)  # waist in the second quadrant: px < 0
W_T5 = (40.0, 30.0, 60.0, -50.0, 130.0)  # |theta5| > 90 deg
W_T234 = (40.0, 30.0, 60.0, 20.0, 20.0)  # theta234 = 110 deg, sin(theta5) > 0
W_T3 = (40.0, -30.0, 120.0, -50.0, 20.0)  # elbow beyond 90 deg on the listing's branch
W_T2 = (40.0, 95.0, 60.0, 0.0, 20.0)  # upper arm beyond vertical: the s2/c2 denominator < 0
W_END = (30.0, 20.0, 50.0, -40.0, 10.0)  # a principal end configuration


# ---------------------------------------------------------------------------------------------
# the listing's statements (Command1_Click)
# ---------------------------------------------------------------------------------------------
def _meant(printed: str, q=chk.PRINCIPAL, atol=1e-3):
    """verify: ``text`` run as VB6 (Sin/Cos in radians) gives what the printed statement
    means when its Sin/Cos read degrees (the unit defect alone)."""
    want = chk.run_statement(printed, chk.listing_env(q), trig_degrees=True)
    return lambda text: chk.statement_gives(text, q, want, trig_degrees=False, atol=atol)


def _trig_degrees() -> Cause:
    ms = []
    for prefix, slug, tol in (
        ("θ5 = ", "theta5", 1e-3),
        ("θ234 = ", "theta234", 1e-3),
        ("c3 = ", "c3", 1e-5),
        ("θ2 = ", "theta2", 1e-3),
        ("θf5 = ", "thetaf5", 1e-3),
        ("θf234 = ", "thetaf234", 1e-3),
        ("cf3 = ", "cf3", 1e-5),
        ("θf2 = ", "thetaf2", 1e-3),
    ):
        printed = chk.listing_statement(prefix, repaired=True)
        args = ", ".join(sorted(set(re.findall(r"(?:Sin|Cos)[(](\w+)[)]", printed))))
        got = chk.run_statement(printed, chk.listing_env(chk.PRINCIPAL))
        meant = chk.run_statement(printed, chk.listing_env(chk.PRINCIPAL), trig_degrees=True)
        ms.append(
            Manifestation(
                f"gr1-trig-degrees/{slug}",
                LISTING_LOC + f", {prefix.strip(' =')} statement",
                printed,
                chk.radians_in_trig(printed),
                f"At the configuration (40, 30, 60, -50, 20) deg the statement gives "
                f"{got:.6g} where its formula, read in degrees, gives {meant:.6g}: its "
                f"Sin/Cos arguments ({args}) hold degrees (θ = (180 / PI) * Atn(...); α, β, "
                f"γ typed in degrees).",
                _meant(printed, atol=tol),
            )
        )
    cells_as_printed = chk.cells_matching(vb6.listing())
    cells_in_degrees = chk.cells_matching(vb6.listing(), trig_degrees=True)
    return _cause(
        "gr1-trig-degrees",
        "The listing converts angles to degrees (θ = (180 / PI) * Atn(...)), and takes the RPY "
        "angles in degrees, then feeds them to Sin and Cos, which take radians.",
        "error",
        "unit",
        f"VB6's Sin/Cos read radians. Table 5-4 is a fingerprint of the mistake: run as "
        f"printed the listing reproduces {cells_as_printed} of its 10 cells, with Sin/Cos "
        f"reading degrees only {cells_in_degrees} (the two theta1 cells, which use no Sin/Cos).",
        ms,
        lambda: _all_fail(ms) and cells_as_printed == 10 and cells_in_degrees == 2,
    )


def _atan_equations() -> list[Manifestation]:
    """Section 4.2's theta1, theta5, theta234, theta3 and theta2 by a single-argument arctan."""
    eqs = []
    for key, slug, corrected in (
        ("4.2-theta1", "eq-theta1", "theta1 = atan2(py, px)"),
        (
            "4.2-theta5",
            "eq-theta5",
            "theta5 = atan2(sin(theta1)*n_x - cos(theta1)*n_y, sin(theta1)*o_x - cos(theta1)*o_y)",
        ),
        (
            "4.2-theta234",
            "eq-theta234",
            "theta234 = atan2(cos(theta1)*a_x + sin(theta1)*a_y, -a_z)",
        ),
        ("4.2-theta3", "eq-theta3", "theta3 = atan2(sin(theta3), cos(theta3))"),
    ):
        e = paper.EQUATIONS[key]
        eqs.append(
            Manifestation(
                f"gr1-atan/{slug}",
                e["location"],
                f"{e['lhs']} = {e['rhs']}",
                corrected,
                "Evaluated on 200 seeded configurations of the chain (front solutions, every "
                "angle over a full turn), the single-argument arctangent misses the angle by "
                "180 deg wherever its denominator is negative; atan2 returns it everywhere.",
                lambda t: chk.equation_holds(t, angle=True),
            )
        )
    e = paper.EQUATIONS["4.2-theta2"]
    num, den = _split_ratio(e["rhs"][len("atan(") : -1])
    eqs.append(
        Manifestation(
            "gr1-atan/eq-theta2",
            e["location"],
            f"theta2 = {e['rhs']}",
            f"theta2 = atan2({num}, {den})",
            "theta2 = arctan(s2 / c2) with the printed s2 and c2 (a common positive "
            "denominator): 180 deg off where c2 < 0 (upper arm beyond vertical).",
            lambda t: chk.equation_holds(t, angle=True),
        )
    )
    return eqs


def _atan_listing() -> list[Manifestation]:
    """The listing's Atn statements for theta1, theta5, theta3, theta2 and theta234."""
    listing = []
    for prefix, slug, q in (
        ("θ1 = ", "listing-theta1", W_T1),
        ("θ5 = ", "listing-theta5", W_T5),
        ("θ3 = ", "listing-theta3", W_T3),
        ("θ2 = ", "listing-theta2", W_T2),
    ):
        printed = chk.listing_statement(prefix)
        y, x = chk.atn_parts(printed)
        env = chk.listing_env(q)
        yv = chk.run_statement(f"Yv = {y}", env, trig_degrees=True)
        xv = chk.run_statement(f"Xv = {x}", env, trig_degrees=True)
        want = math.degrees(math.atan2(yv, xv)) * (180 / chk.PI_LISTING) / (180 / math.pi)
        got = chk.run_statement(printed, env, trig_degrees=True)
        listing.append(
            Manifestation(
                f"gr1-atan/{slug}",
                LISTING_LOC + f", {prefix.strip(' =')} statement",
                printed,
                chk.atan2_statement(prefix.strip(" ="), y, x),
                f"At the configuration {q} deg (Sin/Cos read in degrees to isolate this "
                f"defect) Atn(y / x) gives {got:.3f} deg; y = {yv:.6g}, x = {xv:.6g} put the "
                f"angle at {want:.3f} deg. VB6 has no Atan2; 2 Atn(y / (Sqr(x^2 + y^2) + x)) "
                f"is one with the listing's functions.",
                _gives(q, want),
            )
        )
    printed = chk.listing_statement("θ234 = ")
    t234 = chk.truth(W_T234)["theta234"]
    got = chk.run_statement(printed, chk.listing_env(W_T234), trig_degrees=True)
    listing.append(
        Manifestation(
            "gr1-atan/listing-theta234",
            LISTING_LOC + ", θ234 statement",
            printed,
            chk.approach_theta234(),
            f"At (40, 30, 60, 20, 20) deg, theta234 = {t234:g} deg; Atn(o_z / (c1 o_x + s1 o_y)) "
            f"gives {got:.3f}. A two-argument arctangent of o would not help: o_z and "
            f"c1 o_x + s1 o_y are -sin(theta5) times sin and cos of theta234, so it is 180 deg "
            f"off whenever sin(theta5) > 0 and undefined at theta5 = 0; the approach vector "
            f"gives theta234 = atan2(c1 a_x + s1 a_y, -a_z) for every theta5.",
            _gives(W_T234, t234),
        )
    )
    return listing


def _atan() -> Cause:
    ms = [*_atan_equations(), *_atan_listing()]

    def demo() -> bool:
        # Table 5-4's theta3 and theta5 cells are atan's branch of the listing's values
        return _all_fail(ms)

    return _cause(
        "gr1-atan",
        "A single-argument arctangent stands where the quadrant matters: theta1, theta5, "
        "theta234, theta3 and theta2 in section 4.2 and in the listing (Atn).",
        "error",
        "branch/quadrant",
        "arctan and VB's Atn return (-90, 90) deg. Section 4.2 prints second solutions "
        "theta1' = theta1 + 180, theta5' = theta5 + 180, theta234' = theta234 + 180 but no rule "
        "to choose between them, and none for theta2 and theta3; the listing takes the first "
        "always. The end-pose copies (θf1, θf5, θf234, θf3, θf2) repeat each statement.",
        ms,
        demo,
    )


def _gives(q, want: float, **options):
    """verify: the VB6 text computes ``want`` at configuration ``q`` (Sin/Cos in degrees)."""

    def verify(text: str) -> bool:
        return chk.statement_gives(text, q, want, trig_degrees=True, **options)

    return verify


def _split_ratio(text: str) -> tuple[str, str]:
    """``(A)/(B)`` -> (A, B) at the top-level '/' (outer parentheses removed)."""
    depth = 0
    for i, ch in enumerate(text):
        depth += {"(": 1, ")": -1}.get(ch, 0)
        if ch == "/" and depth == 0:
            a, b = text[:i].strip(), text[i + 1 :].strip()
            return a[1:-1] if a.startswith("(") else a, b[1:-1] if b.startswith("(") else b
    raise ValueError(f"no top-level '/' in {text!r}")


def _r_sign() -> Cause:
    ms = []
    truth = chk.truth(chk.PRINCIPAL)["theta2"]
    for prefix, slug in (("θ2 = ", "theta2"), ("θf2 = ", "thetaf2")):
        printed = chk.listing_statement(prefix)
        got = chk.run_statement(printed, chk.listing_env(chk.PRINCIPAL), trig_degrees=True)
        corrected = re.sub(r"\+ Cos\((θf?234)\) \* a4", r"- Cos(\1) * a4", printed)
        ms.append(
            Manifestation(
                f"gr1-r-sign/{slug}",
                LISTING_LOC + f", {prefix.strip(' =')} statement (twice)",
                printed,
                corrected,
                f"r = px c1 + py s1 - a4 c234 (the c3 statement and section 4.2 have '-'); "
                f"with '+' the statement gives {got:.3f} deg for theta2 = {truth:g} deg at "
                f"(40, 30, 60, -50, 20) (Sin/Cos read in degrees to isolate this defect).",
                _gives(chk.PRINCIPAL, truth),
            )
        )
    return _cause(
        "gr1-r-sign",
        "The θ2 statements add a4 cos(θ234) to the wrist's radius where the c3 statements "
        "(and section 4.2) subtract it.",
        "error",
        "sign",
        "The same quantity r is written two ways in one procedure: the listing's c3 and θ2 "
        "describe wrists 2 a4 cos(theta234) apart.",
        ms,
    )


def _end_orientation() -> Cause:
    ms = []
    t = chk.truth(W_END)
    for prefix, slug, key in (
        ("θf5 = ", "thetaf5", "theta5"),
        ("θf234 = ", "thetaf234", "theta234"),
    ):
        printed = chk.listing_statement(prefix)
        corrected = printed.replace("α0", "α1").replace("β0", "β1").replace("γ0", "γ1")
        env = chk.listing_env(chk.PRINCIPAL, W_END)
        got = chk.run_statement(printed, env, trig_degrees=True)
        ms.append(
            Manifestation(
                f"gr1-end-orientation/{slug}",
                LISTING_LOC + f", {prefix.strip(' =')} statement",
                printed,
                corrected,
                f"The end pose's statement reads the start orientation α0, β0, γ0: for a start "
                f"at (40, 30, 60, -50, 20) and an end at {W_END} deg it gives {got:.3f} deg "
                f"for {key} = {t[key]:g} deg (Sin/Cos read in degrees to isolate this).",
                _gives(chk.PRINCIPAL, t[key], q_end_deg=W_END),
            )
        )
    other = dict(chk.table5_3_inputs(), Text10="-70", Text11="10", Text12="5")
    ends = [f"Text{i}" for i in range(18, 23)]
    same = [vb6.run_command1(other)["text"][b] for b in ends] == [
        _printed_run()["text"][b] for b in ends
    ]
    return _cause(
        "gr1-end-orientation",
        "The end pose's θf5 and θf234 are computed from the start orientation (α0, β0, γ0): "
        "the end orientation typed into Text10-12 is read and never used.",
        "error",
        "transcription",
        f"Copies of the start statements with θ1 -> θf1 only. Typing another end orientation "
        f"(-70, 10, 5) leaves all five end cells unchanged: {same}.",
        ms,
        lambda: same and _all_fail(ms),
    )


def _cf3() -> Cause:
    printed = chk.listing_statement("cf3 = ")
    corrected = chk.listing_statement("cf3 = ", repaired=True)
    want = chk.truth(chk.PRINCIPAL)["c3"]
    m = Manifestation(
        "gr1-cf3-operator/cf3",
        "appendix listing, Command1_Click, the cf3 statement, p. 37",
        printed,
        corrected,
        "As printed 'Py1 * Sin(θf1) Cos(θf234) * a4' has no operator: VB6 rejects the line "
        "(the form would not compile). With '-' (as the c3 statement has) the listing "
        "reproduces the printed end-pose theta3 = -45.244. Lost in the print or in the "
        "extraction: the extraction keeps every other '-' of the listing.",
        lambda t: chk.statement_gives(t, chk.PRINCIPAL, want, trig_degrees=True, atol=1e-9),
    )

    def demo() -> bool:
        try:
            vb6.VB6Form(vb6.listing(repaired=False))
        except vb6.VB6SyntaxError:
            return _all_fail([m]) and _printed_run()["text"]["Text20"] == "-45.244"
        return False

    return _cause(
        "gr1-cf3-operator",
        "The end pose's cf3 statement lacks the '-' before Cos(θf234) * a4.",
        "uncertain",
        "transcription",
        "The one edit needed to run the listing (analysis.audit.vb6.LISTING_REPAIRS).",
        [m],
        demo,
    )


def _no_reach_check() -> Cause:
    ms = []
    for prefix, slug, c in (("θ3 = ", "theta3", "c3"), ("θf3 = ", "thetaf3", "cf3")):
        printed = chk.listing_statement(prefix)
        corrected = printed.replace("Sqr(Abs(1 - ", "Sqr((1 - ")

        def verify(text, c=c):
            env = chk.listing_env(chk.PRINCIPAL)
            try:  # an unreachable pose (|c3| > 1) must stop the computation
                chk.run_statement(text, {**env, c: 1.5})
                return False
            except vb6.VB6Error:
                pass
            except vb6.VB6SyntaxError:
                return False
            return chk.statement_gives(text, chk.PRINCIPAL, 60.0, trig_degrees=False)

        ms.append(
            Manifestation(
                f"gr1-no-reach-check/{slug}",
                LISTING_LOC + f", {prefix.strip(' =')} statement",
                printed,
                corrected,
                f"|{c}| > 1 means the wrist is beyond a2 + a3; Sqr(Abs(1 - {c}^2)) turns it into "
                f"an angle. Without Abs, VB raises run-time error 5 there and nothing is shown.",
                verify,
            )
        )
    far = dict(chk.table5_3_inputs(), Text1="600", Text2="10", Text3="0", Text7="600",
               Text8="10", Text9="0")  # fmt: skip
    out = vb6.run_command1(far)
    shown = [out["text"][f"Text{i}"] for i in range(13, 18)]
    arm = _arm()
    status = int(arm.solve([600.0, 10.0, 0.0, 0.0, 0.0, 0.0]).status)
    return _cause(
        "gr1-no-reach-check",
        "No reach check: the listing turns an unreachable pose into joint angles "
        "(Sqr(Abs(1 - c3 * c3))), and nothing else tests the reach.",
        "omission",
        "VB semantics",
        f"(600, 10, 0) mm is {math.hypot(600, 10):.1f} mm from the shoulder, beyond a2 + a3 + "
        f"a4 = 529 mm; the listing shows {shown} for it, the corrected arm refuses it "
        f"(status {Status(status).text}).",
        ms,
        lambda: status == Status.OUT_OF_REACH and all(shown) and _all_fail(ms),
    )


# ---------------------------------------------------------------------------------------------
# the input check, Format
# ---------------------------------------------------------------------------------------------
_CHECK_LINES = (
    "If Sqr((Px0 - Px1) * (Px0 - Px1) + (Py0 - Py1) * (Py0 - Py1)) > 850 Then",
    "Command3 = False",
    "ElseIf Abs(Pz0 - Pz1) > 600 Then",
    "Command3.Enabled = False",
    "End If",
)


def _check_result(block: str, start, end) -> tuple[bool, bool]:
    """Run the check ``block`` for a start and an end position [mm]: (Enabled, Value) of
    Command3 afterwards."""
    env = dict(zip(("Px0", "Py0", "Pz0", "Px1", "Py1", "Pz1"), (*start, *end), strict=True))
    lines = ["Private Sub T_Click()", *(f"{k} = {float(v)!r}" for k, v in env.items())]
    lines += ["Command3.Enabled = True", "Command3.Value = True", block, "End Sub", ""]
    form = vb6.VB6Form("\n".join(lines))
    form.subs.pop("command3_click", None)
    form.call("T_Click")
    props = form.control("Command3").props
    return bool(props["Enabled"].value), bool(props["Value"].value)


def _default_property_ok(text: str) -> bool:
    """verify: the statement in place of 'Command3 = False' greys the button for poses
    1006 mm apart (sec. 6.3)."""
    src = vb6.listing().replace("\nCommand3 = False\n", f"\n{text}\n")
    far = dict(chk.table5_3_inputs(), Text7="1100", Text8="0")  # 1006 mm horizontally
    try:
        out = vb6.run(src, "Command1_Click", far)
    except (vb6.VB6Error, vb6.VB6SyntaxError):
        return False
    return out["controls"]["Command3"]["props"]["Enabled"].value is False


def _reach_check_ok(text: str) -> bool:
    """verify: the check block accepts and rejects pose pairs by reach, not by their distance
    (sec. 6.4)."""
    # (expected Enabled) for pairs: reachable 900 mm apart; unreachable at one spot;
    # reachable 700 mm apart vertically
    cases = [
        (((450.0, 0.0, 100.0), (-450.0, 0.0, 100.0)), True),
        (((600.0, 10.0, 0.0), (600.0, 10.0, 0.0)), False),
        (((100.0, 0.0, 350.0), (100.0, 0.0, -350.0)), True),
    ]
    try:
        return all(_check_result(text, *pair)[0] == ok for pair, ok in cases)
    except (vb6.VB6Error, vb6.VB6SyntaxError):
        return False


def _work_area_ok(text: str) -> bool:
    """verify: the check block holds sec. 2.1's 600 mm horizontally and 850 mm vertically."""
    # sec. 2.1: 600 mm horizontally, 850 mm vertically: a 700 mm horizontal move is
    # beyond it, a 700 mm vertical one within (the check 'fires': Enabled or Value off)
    try:
        wide = _check_result(text, (350.0, 0.0, 0.0), (-350.0, 0.0, 0.0))
        tall = _check_result(text, (100.0, 0.0, 350.0), (100.0, 0.0, -350.0))
    except (vb6.VB6Error, vb6.VB6SyntaxError):
        return False
    return not all(wide) and all(tall)


def _gui_check() -> Cause:
    printed_block = "\n".join(_CHECK_LINES)
    reach = study.gr1_arm().geometry["reach_tool"]
    corrected_reach = "\n".join(
        [
            f"If Sqr(Px0 * Px0 + Py0 * Py0 + Pz0 * Pz0) > {reach:g} Or "
            f"Sqr(Px1 * Px1 + Py1 * Py1 + Pz1 * Pz1) > {reach:g} Then",
            "Command3.Enabled = False",
            "End If",
        ]
    )
    swapped = printed_block.replace("> 850", "> @").replace("> 600", "> 850").replace("@", "600")
    ms = [
        Manifestation(
            "gr1-gui-check/default-property",
            "appendix listing, Command1_Click, p. 36 (sec. 6.3 item 3)",
            "Command3 = False",
            "Command3.Enabled = False",
            "A CommandButton's default property is Value, not Enabled: 'Command3 = False' "
            "leaves the 轨迹规划 button enabled; for poses 1006 mm apart horizontally it stays "
            "enabled, against sec. 6.3 ('呈现灰色').",
            _default_property_ok,
        ),
        Manifestation(
            "gr1-gui-check/start-vs-end",
            "appendix listing, Command1_Click, p. 36 (sec. 6.4 item 1)",
            printed_block,
            corrected_reach,
            f"The check compares the start with the end, not either pose with the arm: two "
            f"reachable poses 900 mm apart are rejected, two unreachable ones at the same spot "
            f"(600, 10, 0) mm pass, and it never tests the reach ({reach:g} mm = a2 + a3 + a4 "
            f"from the shoulder; the full test is the closed form's: reach per branch and the "
            f"orientation). Nor does the check stop anything: the joint values are computed "
            f"and shown whatever it says (sec. 6.4: only when the data meet the requirements).",
            _reach_check_ok,
        ),
        Manifestation(
            "gr1-gui-check/swapped",
            "appendix listing, Command1_Click, p. 36; sec. 2.1 c",
            printed_block,
            swapped,
            "Section 2.1 prints 850 mm vertically and 600 mm horizontally; the check compares "
            "the horizontal distance with 850 and the vertical one with 600: a 700 mm "
            "horizontal move passes, a 700 mm vertical one is rejected.",
            _work_area_ok,
        ),
    ]
    return _cause(
        "gr1-gui-check",
        "The 计算 button's input check does not do what sections 6.3-6.4 say: it sets the "
        "wrong property, compares the two poses with each other, and swaps section 2.1's "
        "numbers.",
        "error",
        "VB semantics",
        "Sections 6.3-6.4 promise a greyed trajectory button and no joint values for data "
        "out of range.",
        ms,
    )


def _format_zero() -> Cause:
    line = 'Text18.Text = Format(θf1, "####.###")'

    # Command3_Click's first use of the box, without its 50,000 drawing steps
    probe = "Private Sub Probe_Click()\na = Text13.Text\nb = Text18.Text\nc = 10\n"
    probe += "d = a + (3 / (c * c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b - a) * "
    probe += "(10 * 10 * 10)\nEnd Sub\n"

    def verify(text: str) -> bool:
        src = vb6.listing().replace(line, text) + probe
        inputs = dict(chk.table5_3_inputs(), Text7="300", Text8="0", Text9="200")
        try:
            out = vb6.run(src, "Command1_Click", inputs)
            d = vb6.run(src, "Probe_Click", form=out["form"])["module"]["d"]
        except (vb6.VB6Error, vb6.VB6SyntaxError):
            return False
        return abs(float(d.value)) < 1e-3 and out["text"]["Text18"] != "."

    m = Manifestation(
        "gr1-format-zero/text18",
        LISTING_LOC + ", the ten Format statements (θf1 shown)",
        line,
        'Text18.Text = Format(θf1, "0.000")',
        'Format(0, "####.###") is "." (a # shows no zero); Command3_Click then computes '
        'b - a with b = ".": run-time error 13 (Type mismatch) for any pose with py = 0 '
        "(theta1 = 0), and likewise for any other joint value that is 0.",
        verify,
    )
    return _cause(
        "gr1-format-zero",
        "A joint value of 0 is displayed as '.', which the trajectory button cannot read.",
        "error",
        "VB semantics",
        "The displayed text is what Command3_Click reads back (a = Text13.Text ...).",
        [m],
    )


@cache
def register() -> Register:
    """Seed 004's register (a few seconds: the VB6 listing runs, the chain checks)."""
    from analysis.audit import gr1_causes_model as model
    from analysis.audit import gr1_causes_plc as plc

    causes = [
        _trig_degrees(),
        _atan(),
        _r_sign(),
        _end_orientation(),
        _gui_check(),
        _format_zero(),
        *model.causes_results(),
        *plc.causes(),
        _no_reach_check(),
        _cf3(),
        *model.causes_open(),
    ]
    return Register(
        "gr1",
        "Chen Huihuang, Xiangtan University thesis 2007 (seed 004): GR-1 5-DOF handling arm",
        tuple(causes),
    )
