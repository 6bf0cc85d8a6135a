"""The machine program in Siemens SCL for TIA Portal (S7-1500 technology objects): the
sequence of :mod:`.program` as a function block (module docstring there)."""

from __future__ import annotations

import re

from analysis.escape import plc_comment
from analysis.plc.machine.program import STEPS, MachinePrinter, lreal
from analysis.plc.machine.spec import MACHINE_INPUTS, MACHINE_OUTPUTS

__all__ = ["SclMachinePrinter"]


class SclMachinePrinter(MachinePrinter):
    """Siemens SCL for TIA Portal (S7-1500 technology objects): the same sequence as a
    function block with the axes as in/out parameters (TO_PositioningAxis), MC_Halt for the
    stop (TIA has no MC_Stop), MC_Home's Mode (0 set position, 3 reference switch), the
    position and error read from the technology object."""

    dialect = "scl"

    def v(self, name: str) -> str:
        return f"#{name}"

    def axis_type(self) -> str:
        return "TO_PositioningAxis"

    def fb_type(self, kind: str) -> str:
        return {"TON": "TON_TIME"}.get(kind, kind.upper())

    def stop_block(self) -> str:
        return "MC_Halt"

    def read_declarations(self, k: str) -> list[str]:
        return []

    def read_axis(self, k: str, axis: str) -> list[str]:
        return [f"#Pos{k} := {self.v(axis)}.ActualPosition;"]

    def home_blocks(self, a) -> list[tuple[str, str]]:
        return [("Homing", "MC_Home")]

    def homed(self, a) -> str:
        return f"#Homing{a.name[4:]}.Done"

    def axis_fault(self, k: str, a) -> str:
        errs = " OR ".join(f"#{fb}{k}.Error" for fb in self.fault_blocks(a))
        return f"{self.v('Axis' + k)}.StatusWord.%X1 OR {errs}"

    def latches(self) -> list[str]:
        out = super().latches()
        return [
            ln.replace(f"#ReadErr{k}.AxisErrorID", f"#Axis{k}.ErrorDetail.Number")
            for ln in out
            for k in [self._k(ln)]
        ]

    @staticmethod
    def _k(line: str) -> str:
        m = re.search(r"#ReadErr(\d+)", line)
        return m.group(1) if m else ""

    def home_call(self, k: str, ax: str, a) -> list[str]:
        mode = 3 if a.home_mode == "switch" else 0
        return [
            f"#Homing{k}(Axis := {ax}, Execute := #Phase = {STEPS['HOMING']}, Position := "
            f"{lreal(a.home_position)}, Mode := {mode});"
        ]

    def stop_call(self, k: str, ax: str, a) -> list[str]:
        return [
            f"#Stop{k}(Axis := {ax}, Execute := #Phase = {STEPS['STOPPED']}, Deceleration := "
            f"{lreal(a.max_acceleration)} * #Tu * #Tu, Jerk := {lreal(a.max_jerk)} * #Tu * "
            "#Tu * #Tu);"
        ]

    def drive_axes(self) -> list[str]:
        out = super().drive_axes()
        return [
            re.sub(r"\(#ReadErr(\d+)\.AxisErrorID <> 0\)", r"#Axis\1.StatusWord.%X1", ln)
            for ln in out
        ]

    def text(self) -> str:
        t = self.indent
        out = [
            f'FUNCTION_BLOCK "{self.name}"',
            f"TITLE = {plc_comment(f'machine of the {self.spec.title} ({self.spec.arm})')}",
            "{ S7_Optimized_Access := 'TRUE' }",
            "VERSION : 0.1",
        ]
        decl = self.declarations()
        ins = {*MACHINE_INPUTS, *self.spec.targets}
        outs = {*MACHINE_OUTPUTS, "AxisErrorID"}

        def named(line: str, names) -> bool:
            m = re.match(r"\s+(\w+) :", line)
            return m is not None and m.group(1) in names

        axes = [ln for ln in decl if ": TO_PositioningAxis;" in ln]
        rest = [ln for ln in decl if ln not in axes and not named(ln, ins | outs)]
        out += ["VAR_INPUT", *(ln for ln in decl if named(ln, ins)), "END_VAR"]
        out += ["VAR_OUTPUT", *(ln for ln in decl if named(ln, outs)), "END_VAR"]
        out += ["VAR_IN_OUT", *axes, "END_VAR", "VAR", *rest]
        out += ["END_VAR", "", "BEGIN"]
        out += [t + line if line else "" for line in self.body()]
        out += [
            "END_FUNCTION_BLOCK",
            "",
            f'DATA_BLOCK "{self.name}_DB"',
            "{ S7_Optimized_Access := 'TRUE' }",
            "VERSION : 0.1",
            "NON_RETAIN",
            f'"{self.name}"',
            "BEGIN",
            "END_DATA_BLOCK",
            "",
        ]
        return "\n".join(out)
