"""The machine program of an arm in IEC 61131-3 ST (CODESYS, TwinCAT, the ST engine) and
Siemens SCL (TIA Portal, S7-1500 technology objects): PLCopen Part 1 motion blocks around the
IK block (issue 29 item 1).

One ``PROGRAM MACHINE_<ARM>`` (ST) or ``FUNCTION_BLOCK "MACHINE_<ARM>"`` (SCL). A scan:

1. edges of Home, Start, Reset; every axis powered (MC_Power, level: Enable), its position
   (MC_ReadActualPosition) and error (MC_ReadAxisError) read;
2. the stop circuit (StopOK, normally closed: FALSE or a broken wire stops) and any axis error
   latch; nothing moves again until Reset (with the circuit closed), then Start;
3. Start's rising edge latches the target (the inputs are never written by the program), runs
   the IK block on it and, if it is refused (unreachable, NaN, a joint limit), reports its
   status and moves nothing; else the move is planned from where the axes are: each joint's
   goal is its IK pulse count times its step (an unlimited revolute joint the short way,
   within +-180 deg of where it is), and every axis gets the same normalised profile: the
   velocity, acceleration and jerk limits of the path parameter s in [0, 1] are the smallest
   ``limit_i / distance_i`` over the moving joints, and joint i moves with those times its
   distance, so every joint is within its own limits and all arrive together; the unit
   move's phases are lengthened to whole task cycles (:meth:`MachinePrinter.align`), so a
   planner that works in cycles ends every joint on the same one (a new Start during a move
   halts every axis with MC_Halt first, then plans from where they stopped);
4. Home, per axis as the description says (:meth:`MachinePrinter.home_call`): ``set``: the
   present position is declared the home position (PLCopen Part 5 MC_HomeDirect, no
   motion: the operator has put the axis on its mark); ``switch``: the reference switch is
   searched (Part 5 MC_StepAbsoluteSwitch, direction from the switch's level, the edge
   latched) at a quarter of the joint's velocity limit, then searched again from the far
   side of the edge at a creep speed (a sixteenth of the limit, and at most half a pulse
   per task cycle: the edge is seen to half a pulse), the position set to the home position
   there, and
   MC_FinishHoming ends it (soft limits watched again); each search gives up after the
   joint's range. On TIA, MC_Home Mode 0 (set) or 3 (active homing: the technology
   object's approach and referencing velocities). Start before Homed is refused (status
   101);
5. the gripper output (Gripper) follows Grip at standstill only, then a dwell (TON) before
   Done; it holds through a stop.

Units (the ST engine's axes take a motion block's Velocity, Acceleration and Jerk per cycle,
the vendors' per second): every such input is written as ``value * MotionTimeUnit**k``, with
``MotionTimeUnit`` 1.0 (per second) on a PLC; ``stl-run`` writes the cycle time there before
the first scan (:mod:`analysis.plc.st_engine`). That is the one place the unit is converted.
``TaskCycle`` is the task's cycle time [s] (4 ms unless set; ``stl-run`` writes its cycle).

Why by hand: no library prints PLCopen motion programs; the text is held by the ST engine
(scenarios in :mod:`analysis.plc.machine.scenarios`).
"""

from __future__ import annotations

from analysis.escape import iec_identifier, plc_comment
from analysis.plc.emit import fmt_real
from analysis.plc.machine.homing import HOMING_STEP, HomingMixin, lreal
from analysis.plc.machine.spec import MACHINE_STATUS, MachineSpec

__all__ = ["STEPS", "MachinePrinter", "lreal", "machine_name"]

STEPS = {
    "IDLE": 0,
    "HOMING": HOMING_STEP,
    "PLAN": 20,
    "MOVING": 21,
    "HALTING": 30,
    "STOPPED": 40,
    "GRIPPING": 50,
}
"""The sequence's steps (``Phase`` in the program)."""

_CODE = {word: code for code, (word, _, _) in MACHINE_STATUS.items()}


def machine_name(spec: MachineSpec) -> str:
    return iec_identifier(f"MACHINE_{spec.arm}").upper()  # IEC 61131-3 (analysis.escape)


def cycles_up(x: str, cycle: str) -> str:
    """ST: the whole number of ``cycle`` s that ``x`` s rounds up to (a tolerance of 1e-9
    cycle), as an LREAL."""
    n = f"LREAL_TO_DINT({x} / {cycle} + LREAL#0.5 - LREAL#1.0E-9)"
    return f"DINT_TO_LREAL({n})"


class MachinePrinter(HomingMixin):
    """IEC 61131-3 ST (module docstring). Subclassed for SCL."""

    dialect = "st"
    indent = "    "

    def __init__(self, spec: MachineSpec, ik_block: str) -> None:
        self.spec, self.ik_block = spec, ik_block
        self.name = machine_name(spec)

    # --- dialect words (SCL overrides) ---------------------------------------------------
    def v(self, name: str) -> str:
        """A use of variable ``name``."""
        return name

    def axis_type(self) -> str:
        return "AXIS_REF"

    def fb_type(self, kind: str) -> str:
        return kind

    def comment(self, text: str) -> str:
        return f"(* {plc_comment(text)} *)"  # one line, no (* *) (analysis.escape)

    # --- declarations ---------------------------------------------------------------------
    def declarations(self) -> list[str]:
        s, t = self.spec, self.indent
        targets = ", ".join(f"{n} [{u}]" for n, u in zip(s.targets, s.target_units, strict=True))
        out = [
            self.comment(
                "inputs (written by an HMI or the I/O, never by the program): Enable "
                "powers the axes; Home, Start, Reset act on their rising edge; StopOK "
                f"is the normally closed stop circuit; {targets}; Grip closes the "
                "gripper"
            ),
            *[f"{t}{n} : BOOL;" for n in ("Enable", "Home", "Start", "StopOK", "Reset", "Grip")],
            *[f"{t}{n} : REAL;" for n in s.targets],
            self.comment(
                "outputs: Status is the IK block's code (0-7) or the machine's "
                "(100-104), see MAP.json; Gripper drives the gripper valve, "
                "GripperClosed follows it after the dwell"
            ),
            *[f"{t}{n} : BOOL;" for n in ("Homed", "Busy", "Done", "Error")],
            f"{t}Status : INT;",
            f"{t}AxisErrorID : DINT;",
            f"{t}Gripper : BOOL;",
            f"{t}GripperClosed : BOOL;",
            self.comment(
                "seconds per time unit of the motion blocks' Velocity, Acceleration "
                "and Jerk: 1.0 (per second) on a PLC"
            ),
            f"{t}MotionTimeUnit : LREAL := LREAL#1.0;",
            self.comment("the task's cycle time [s]: motion profiles are planned in whole cycles"),
            f"{t}TaskCycle : LREAL := LREAL#0.004;",
            f"{t}GripDwell : TIME := T#{round(s.grip_dwell_s * 1000)}ms;",
        ]
        out += self.axis_declarations()
        out += [
            self.comment("the sequence"),
            f"{t}Phase : INT;",
            f"{t}StopLatched : BOOL;",
            f"{t}FaultLatched : BOOL;",
            f"{t}ResetPending : BOOL;",
            f"{t}Fault : BOOL;",
            f"{t}Powered : BOOL;",
            f"{t}AllDone : BOOL;",
        ]
        out += [f"{t}Latched{n[6:]} : REAL;" for n in s.targets]
        out += [
            f"{t}{n} : LREAL;"
            for n in (
                "Tu",
                "Scale",
                "NormV",
                "NormA",
                "NormJ",
                "PhaseJ",
                "PhaseA",
                "PhaseC",
                "Peak",
            )
        ]
        out += [
            f"{t}StartEdge : R_TRIG;",
            f"{t}HomeEdge : R_TRIG;",
            f"{t}ResetEdge : R_TRIG;",
            f"{t}GripTimer : {self.fb_type('TON')};",
            f"{t}Ik : {self.ik_block};",
        ]
        return out

    def axis_declarations(self) -> list[str]:
        t, out = self.indent, []
        for a in self.spec.axes:
            k = a.name[4:]
            limits = (
                "unlimited: moved the short way"
                if a.unlimited
                else f"{a.lower:g} .. {a.upper:g} {a.unit}"
            )
            out.append(
                self.comment(
                    f"{a.name}: joint {a.joint} [{a.unit}], {a.per_pulse:.9g} {a.unit}/pulse, "
                    f"{limits}; max {a.max_velocity:g} {a.unit}/s, {a.max_acceleration:g} "
                    f"{a.unit}/s2, {a.max_jerk:g} {a.unit}/s3; home: {a.home_mode} at "
                    f"{a.home_position:g} {a.unit}"
                )
            )
            out.append(f"{t}{a.name} : {self.axis_type()};")
            out += [f"{t}{fb}{k} : {self.fb_type(kind)};" for fb, kind in self.home_blocks(a)]
            for fb, kind in (
                ("Power", "MC_Power"),
                ("Move", "MC_MoveAbsolute"),
                ("Halt", "MC_Halt"),
                ("Stop", self.stop_block()),
                ("Reset", "MC_Reset"),
            ):
                out.append(f"{t}{fb}{k} : {self.fb_type(kind)};")
            out += self.read_declarations(k)
            out += [f"{t}{n}{k} : LREAL;" for n in ("Pos", "Goal", "Dist")]
        return out

    def read_declarations(self, k: str) -> list[str]:
        t = self.indent
        return [f"{t}ReadPos{k} : MC_ReadActualPosition;", f"{t}ReadErr{k} : MC_ReadAxisError;"]

    def stop_block(self) -> str:
        return "MC_Stop"

    # --- statements -----------------------------------------------------------------------
    def body(self) -> list[str]:
        out = self.read_axes() + self.latches() + self.commands() + self.sequence()
        return out + self.drive_axes()

    def read_axes(self) -> list[str]:
        v, out = self.v, [self.comment("1. edges; each axis powered, its position and error")]
        out += [
            f"{v('StartEdge')}(CLK := {v('Start')});",
            f"{v('HomeEdge')}(CLK := {v('Home')});",
            f"{v('ResetEdge')}(CLK := {v('Reset')});",
            f"{v('Tu')} := {v('MotionTimeUnit')};",
        ]
        powered, faults = [], []
        for a in self.spec.axes:
            k = a.name[4:]
            out += [f"{v('Power' + k)}(Axis := {v(a.name)}, Enable := {v('Enable')});"]
            out += self.read_axis(k, a.name)
            powered.append(f"{v('Power' + k)}.Status")
            faults.append(self.axis_fault(k, a))
        out.append(f"{v('Powered')} := {' AND '.join(powered)};")
        out.append(f"{v('Fault')} := {' OR '.join(faults)};")
        return out

    def read_axis(self, k: str, axis: str) -> list[str]:
        v = self.v
        return [
            f"{v('ReadPos' + k)}(Axis := {v(axis)}, Enable := TRUE);",
            f"{v('ReadErr' + k)}(Axis := {v(axis)}, Enable := TRUE);",
            f"{v('Pos' + k)} := {v('ReadPos' + k)}.Position;",
        ]

    def fault_blocks(self, a) -> list[str]:
        """The blocks whose Error is the axis' fault (not the stop's own: stopping an axis
        already in error fails by design)."""
        homing = [fb for fb, kind in self.home_blocks(a) if not kind.endswith("_REF")]
        return ["Power", *homing, "Move", "Halt"]

    def axis_fault(self, k: str, a) -> str:
        v = self.v
        errs = " OR ".join(f"{v(fb + k)}.Error" for fb in self.fault_blocks(a))
        return f"({v('ReadErr' + k)}.AxisErrorID <> 0) OR {errs}"

    def latches(self) -> list[str]:
        v, t = self.v, self.indent
        first = [
            f"{'IF' if i == 0 else 'ELSIF'} {v('ReadErr' + a.name[4:])}.AxisErrorID <> 0 "
            f"THEN\n{t}{t}{v('AxisErrorID')} := {v('ReadErr' + a.name[4:])}.AxisErrorID;"
            for i, a in enumerate(self.spec.axes)
        ]
        return [
            "",
            self.comment(
                "2. the stop circuit (normally closed) and axis errors latch; Reset "
                "clears them once the circuit is closed and no axis reports an error"
            ),
            f"IF NOT {v('StopOK')} THEN",
            f"{t}{v('StopLatched')} := TRUE;",
            "END_IF;",
            f"IF {v('Fault')} AND NOT {v('FaultLatched')} THEN",
            f"{t}{v('FaultLatched')} := TRUE;",
            *[f"{t}{line}" for line in "\n".join(first).split("\n")],
            f"{t}END_IF;",
            "END_IF;",
            f"IF {v('ResetEdge')}.Q THEN",
            f"{t}{v('ResetPending')} := TRUE;",
            "END_IF;",
            f"IF {v('ResetPending')} AND NOT {v('Reset')} THEN",
            f"{t}{v('ResetPending')} := FALSE;",
            f"{t}IF {v('StopOK')} THEN",
            f"{t}{t}{v('StopLatched')} := FALSE;",
            f"{t}END_IF;",
            f"{t}IF NOT {v('Fault')} THEN",
            f"{t}{t}{v('FaultLatched')} := FALSE;",
            f"{t}{t}{v('AxisErrorID')} := 0;",
            f"{t}END_IF;",
            "END_IF;",
            f"IF NOT {v('Enable')} OR NOT {v('Powered')} THEN",
            f"{t}{v('Homed')} := FALSE;",
            "END_IF;",
        ]

    def refuse(self, code: str, depth: int = 2) -> list[str]:
        t, v = self.indent * depth, self.v
        return [
            f"{t}{v('Status')} := {code};",
            f"{t}{v('Error')} := TRUE;",
            f"{t}{v('Done')} := FALSE;",
        ]

    def commands(self) -> list[str]:
        v, t = self.v, self.indent
        st = STEPS
        gate = [
            f"{t}IF {v('StopLatched')} THEN",
            *self.refuse(_CODE["stopped"]),
            f"{t}ELSIF {v('FaultLatched')} THEN",
            *self.refuse(_CODE["axis-error"]),
            f"{t}ELSIF NOT {v('Enable')} OR NOT {v('Powered')} THEN",
            *self.refuse(_CODE["not-powered"]),
        ]
        ik_call = ", ".join(
            f"{n} := {self.ik_arg(n, tgt)}"
            for n, tgt in zip(self.spec.ik_inputs, self.spec.targets, strict=True)
        )
        latch = [f"{t}{t}{v('Latched' + n[6:])} := {v(n)};" for n in self.spec.targets]
        return [
            "",
            self.comment(
                "3. commands: Home and Start on their rising edge, refused with a "
                "status where they cannot run (nothing moves then)"
            ),
            f"IF {v('HomeEdge')}.Q THEN",
            *gate,
            f"{t}ELSIF {v('Phase')} <> {st['IDLE']} THEN",
            *self.refuse(_CODE["busy"]),
            f"{t}ELSE",
            f"{t}{t}{v('Phase')} := {st['HOMING']};",
            f"{t}{t}{v('Homed')} := FALSE;",
            *self.accepted(2),
            f"{t}END_IF;",
            "END_IF;",
            f"IF {v('StartEdge')}.Q THEN",
            *gate,
            f"{t}ELSIF NOT {v('Homed')} THEN",
            *self.refuse(_CODE["not-homed"]),
            f"{t}ELSIF ({v('Phase')} = {st['HOMING']}) OR ({v('Phase')} = {st['GRIPPING']}) THEN",
            *self.refuse(_CODE["busy"]),
            f"{t}ELSE",
            self.comment("the target latched: the inputs stay as the operator wrote them"),
            *latch,
            f"{t}{t}{v('Ik')}(Execute := FALSE, {ik_call});",
            f"{t}{t}{v('Ik')}(Execute := TRUE, {ik_call});",
            f"{t}{t}IF {v('Ik')}.Error THEN",
            *self.refuse(f"DINT_TO_INT({v('Ik')}.ErrorID)", 3),
            f"{t}{t}ELSIF ({v('Phase')} = {st['MOVING']}) OR ({v('Phase')} = {st['PLAN']}) OR "
            f"({v('Phase')} = {st['HALTING']}) THEN",
            f"{t}{t}{t}{v('Phase')} := {st['HALTING']};",
            *self.accepted(3),
            f"{t}{t}ELSE",
            f"{t}{t}{t}{v('Phase')} := {st['PLAN']};",
            *self.accepted(3),
            f"{t}{t}END_IF;",
            f"{t}END_IF;",
            "END_IF;",
        ]

    def ik_arg(self, ik_input: str, target: str) -> str:
        latched = self.v("Latched" + target[6:])
        if ik_input in ("alpha", "beta", "gamma"):
            return f"{latched} * REAL#{fmt_real(3.141592653589793 / 180.0, 'E')}"
        return latched

    def accepted(self, depth: int) -> list[str]:
        t, v = self.indent * depth, self.v
        return [
            f"{t}{v('Status')} := 0;",
            f"{t}{v('Error')} := FALSE;",
            f"{t}{v('Done')} := FALSE;",
        ]

    def sequence(self) -> list[str]:
        v, t, st = self.v, self.indent, STEPS
        homed = " AND ".join(self.homed(a) for a in self.spec.axes)
        moved = " AND ".join(f"{v('Move' + a.name[4:])}.Done" for a in self.spec.axes)
        halted = " AND ".join(f"{v('Halt' + a.name[4:])}.Done" for a in self.spec.axes)
        return [
            "",
            self.comment("4. the sequence"),
            f"IF {v('StopLatched')} OR {v('FaultLatched')} THEN",
            f"{t}{v('Phase')} := {st['STOPPED']};",
            f"{t}{v('Status')} := {_CODE['stopped']};",
            f"{t}IF {v('FaultLatched')} THEN",
            f"{t}{t}{v('Status')} := {_CODE['axis-error']};",
            f"{t}END_IF;",
            f"{t}{v('Error')} := TRUE;",
            f"ELSIF {v('Phase')} = {st['STOPPED']} THEN",
            f"{t}{v('Phase')} := {st['IDLE']};",
            f"{t}{v('Status')} := 0;",
            f"{t}{v('Error')} := FALSE;",
            f"ELSIF NOT {v('Enable')} OR NOT {v('Powered')} THEN",
            f"{t}{v('Phase')} := {st['IDLE']};",
            f"ELSIF ({v('Phase')} = {st['HOMING']}) AND ({homed}) THEN",
            f"{t}{v('Homed')} := TRUE;",
            f"{t}{v('Phase')} := {st['IDLE']};",
            f"{t}{v('Done')} := TRUE;",
            f"ELSIF {v('Phase')} = {st['PLAN']} THEN",
            *[f"{t}{line}" for line in self.plan()],
            f"{t}{v('Phase')} := {st['MOVING']};",
            f"ELSIF ({v('Phase')} = {st['MOVING']}) AND ({moved}) THEN",
            f"{t}{v('Phase')} := {st['IDLE']};",
            f"{t}{v('Done')} := TRUE;",
            f"ELSIF ({v('Phase')} = {st['HALTING']}) AND ({halted}) THEN",
            f"{t}{v('Phase')} := {st['PLAN']};",
            f"ELSIF ({v('Phase')} = {st['IDLE']}) AND ({v('Grip')} <> {v('Gripper')}) THEN",
            f"{t}{v('Gripper')} := {v('Grip')};",
            f"{t}{v('Phase')} := {st['GRIPPING']};",
            f"{t}{v('Done')} := FALSE;",
            f"ELSIF ({v('Phase')} = {st['GRIPPING']}) AND {v('GripTimer')}.Q THEN",
            f"{t}{v('GripperClosed')} := {v('Gripper')};",
            f"{t}{v('Phase')} := {st['IDLE']};",
            f"{t}{v('Done')} := TRUE;",
            "END_IF;",
            f"{v('Busy')} := ({v('Phase')} = {st['HOMING']}) OR ({v('Phase')} = {st['PLAN']}) OR "
            f"({v('Phase')} = {st['MOVING']}) OR ({v('Phase')} = {st['HALTING']}) OR "
            f"({v('Phase')} = {st['GRIPPING']});",
        ]

    def plan(self) -> list[str]:
        """Goals from the IK counts (an unlimited revolute joint the short way) and the one
        normalised profile (module docstring)."""
        v, t = self.v, self.indent
        big = "LREAL#1.0E30"
        out = [
            self.comment("goals from the IK pulses; the normalised profile of all joints"),
            f"{v('NormV')} := {big};",
            f"{v('NormA')} := {big};",
            f"{v('NormJ')} := {big};",
        ]
        for a in self.spec.axes:
            k = a.name[4:]
            goal, pos, dist = v("Goal" + k), v("Pos" + k), v("Dist" + k)
            out.append(f"{goal} := DINT_TO_LREAL({v('Ik')}.c{k}) * {lreal(a.per_pulse)};")
            if a.unlimited:
                out += [
                    f"{dist} := {goal} - {pos};",
                    self.comment("the short way: within +-180 deg of where the axis is"),
                    f"{goal} := {pos} + ({dist} - LREAL#360.0 * DINT_TO_LREAL("
                    f"LREAL_TO_DINT({dist} / LREAL#360.0)));",
                ]
            out += [f"{dist} := ABS({goal} - {pos});", f"IF {dist} > LREAL#0.0 THEN"]
            for norm, lim in (
                ("NormV", a.max_velocity),
                ("NormA", a.max_acceleration),
                ("NormJ", a.max_jerk),
            ):
                out.append(f"{t}{v(norm)} := MIN({v(norm)}, {lreal(lim)} / {dist});")
            out.append("END_IF;")
        return out + self.align()

    def align(self) -> list[str]:
        """The unit move's S-curve (jerk, constant acceleration, cruise phases of the path
        parameter s in [0, 1] within NormV, NormA, NormJ) with each phase lengthened to whole
        task cycles and three quarters, and the limits that give exactly those phases: a
        planner that works in whole cycles (the ST engine's; a PLC's motion kernel) then ends
        every joint's scaled copy of it on the same cycle, whatever its rounding of the
        scaled numbers (each phase ``x.75`` cycles: floored or ceiled, never on a knife's
        edge). Costs at most a cycle per phase; never exceeds a limit (phases only grow)."""
        v, t = self.v, self.indent
        nv, na, nj = v("NormV"), v("NormA"), v("NormJ")
        tj, ta, tc, vp, tk = v("PhaseJ"), v("PhaseA"), v("PhaseC"), v("Peak"), v("TaskCycle")
        one = "LREAL#1.0"
        lines = [
            self.comment("the unit move's phases, each lengthened to whole task cycles + 3/4"),
            f"IF {nv} < LREAL#1.0E29 THEN",
            f"{t}{tj} := {na} / {nj};",
            f"{t}IF {nv} < {na} * {tj} THEN",
            f"{t}{t}{tj} := SQRT({nv} / {nj});",
            f"{t}END_IF;",
            f"{t}{ta} := MAX({nv} / {na} - {tj}, LREAL#0.0);",
            f"{t}{tc} := {one} / {nv} - (LREAL#2.0 * {tj} + {ta});",
            f"{t}IF {tc} < LREAL#0.0 THEN",
            self.comment("the peak velocity is below NormV: its phases"),
            f"{t}{t}{tj} := {na} / {nj};",
            f"{t}{t}{vp} := {na} * (SQRT({tj} * {tj} + LREAL#4.0 / {na}) - {tj}) / LREAL#2.0;",
            f"{t}{t}IF {vp} < {na} * {tj} THEN",
            f"{t}{t}{t}{vp} := EXP(LN(SQRT({nj}) / LREAL#2.0) * LREAL#2.0 / LREAL#3.0);",
            f"{t}{t}{t}{tj} := SQRT({vp} / {nj});",
            f"{t}{t}END_IF;",
            f"{t}{t}{ta} := MAX({vp} / {na} - {tj}, LREAL#0.0);",
            f"{t}{t}{tc} := LREAL#0.0;",
            f"{t}END_IF;",
        ]
        for ph in (tj, ta, tc):
            lines += [
                f"{t}IF {ph} > LREAL#0.0 THEN",
                f"{t}{t}{ph} := ({cycles_up(ph, tk)} + LREAL#0.75) * {tk};",
                f"{t}END_IF;",
            ]
        return [
            *lines,
            f"{t}{nv} := {one} / (LREAL#2.0 * {tj} + {ta} + {tc});",
            f"{t}{na} := {nv} / ({tj} + {ta});",
            f"{t}{nj} := {na} / {tj};",
            "END_IF;",
        ]

    def drive_axes(self) -> list[str]:
        v, st, out = self.v, STEPS, [""]
        out.append(
            self.comment(
                "5. the motion blocks, from the step (Velocity, Acceleration and "
                "Jerk per MotionTimeUnit)"
            )
        )
        tu = v("Tu")
        for a in self.spec.axes:
            k = a.name[4:]
            ax, dist = v(a.name), v("Dist" + k)
            out += [
                f"{v('Scale')} := {dist};",
                f"IF {dist} <= LREAL#0.0 THEN",
                f"{self.indent}{v('Scale')} := {lreal(a.max_velocity)} / {v('NormV')};",
                "END_IF;",
                *self.home_call(k, ax, a),
                f"{v('Move' + k)}(Axis := {ax}, Execute := {v('Phase')} = {st['MOVING']}, "
                f"Position := {v('Goal' + k)}, Velocity := {v('NormV')} * {v('Scale')} * {tu}, "
                f"Acceleration := {v('NormA')} * {v('Scale')} * {tu} * {tu}, Deceleration := "
                f"{v('NormA')} * {v('Scale')} * {tu} * {tu}, Jerk := {v('NormJ')} * "
                f"{v('Scale')} * {tu} * {tu} * {tu});",
                f"{v('Halt' + k)}(Axis := {ax}, Execute := {v('Phase')} = {st['HALTING']}, "
                f"Deceleration := {lreal(a.max_acceleration)} * {tu} * {tu}, Jerk := "
                f"{lreal(a.max_jerk)} * {tu} * {tu} * {tu});",
                *self.stop_call(k, ax, a),
                f"{v('Reset' + k)}(Axis := {ax}, Execute := {v('ResetPending')} AND "
                f"({v('ReadErr' + k)}.AxisErrorID <> 0));",
            ]
        out.append(
            f"{v('GripTimer')}(IN := {v('Phase')} = {st['GRIPPING']}, PT := {v('GripDwell')});"
        )
        return out

    def stop_call(self, k: str, ax: str, a) -> list[str]:
        v, tu = self.v, self.v("Tu")
        return [
            f"{v('Stop' + k)}(Axis := {ax}, Execute := {v('Phase')} = {STEPS['STOPPED']}, "
            f"Deceleration := {lreal(a.max_acceleration)} * {tu} * {tu}, Jerk := "
            f"{lreal(a.max_jerk)} * {tu} * {tu} * {tu});"
        ]

    # --- the POU --------------------------------------------------------------------------
    def header(self) -> list[str]:
        s = self.spec
        return [
            "",
            self.comment(
                f"The machine of the {s.title} ({s.arm}): power, home, move to a "
                "target on Start, grip, stop; PLCopen Part 1 motion blocks"
            ),
            self.comment(
                "CODESYS SoftMotion: the AXIS_REF declarations below name the "
                "device tree's axes (delete them there, keep the names); TwinCAT: "
                "link Axis1..AxisN to the NC axes"
            ),
        ]

    def text(self) -> str:
        t = self.indent
        out = [*self.header(), f"PROGRAM {self.name}", "VAR"]
        out += self.declarations()
        out += ["END_VAR", ""]
        out += [t + line if line else "" for line in self.body()]
        out += ["END_PROGRAM", ""]
        return "\n".join(out)
