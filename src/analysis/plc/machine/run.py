"""Run a machine program on the ST engine (:func:`analysis.plc.st_engine.run_machine`): a
scenario's rows as writes between scans, one simulated axis per joint from the arm's
:class:`~.spec.MachineSpec` (its limits, its software limits; off home at power-up, its
reference switch: :mod:`.plant`), the trace as a :class:`~.scenarios.Trace`.
"""

from __future__ import annotations

import math

from analysis.plc.machine.plant import power_up
from analysis.plc.machine.scenarios import Trace
from analysis.plc.machine.spec import MACHINE_OUTPUTS, MachineSpec

__all__ = ["TRACED", "run_scenario", "schedule", "sim_axes"]

TRACED = (*MACHINE_OUTPUTS, "AxisErrorID")
"""The outputs a machine trace carries."""


def sim_axes(spec: MachineSpec):
    """One :class:`~analysis.plc.st_engine.SimAxis` per joint: its limits, its software
    limits (none for an unlimited joint), where it stands at power-up, what its encoder reads
    then and its reference switch (:func:`.plant.power_up`)."""
    from analysis.plc.st_engine import SimAxis

    return [
        SimAxis(
            a.name,
            a.max_velocity,
            a.max_acceleration,
            a.max_jerk,
            a.lower,
            a.upper,
            start,
            coord,
            switch,
        )
        for a, (start, coord, switch) in zip(spec.axes, power_up(spec), strict=True)
    ]


def schedule(rows, cycle_s: float, settle_s: float):
    """Rows (t_s, name, value) as (cycle, name, value) writes, and the number of cycles: up to
    the last row's time plus ``settle_s``. A row at t is written before the first scan at or
    after t."""
    writes = [(math.ceil(t / cycle_s - 1e-9), n, v) for t, n, v in rows]
    end = max((t for t, _, _ in rows), default=0.0) + settle_s
    return writes, math.floor(end / cycle_s + 1e-9) + 1


def run_scenario(
    source: str,
    program: str,
    spec: MachineSpec,
    rows,
    *,
    cycle_s=0.004,
    settle_s=2.0,
    outputs=TRACED,
) -> Trace:
    """The trace of ``rows`` on PROGRAM ``program`` of ``source``."""
    from analysis.plc.st_engine import run_machine

    writes, n = schedule(rows, cycle_s, settle_s)
    run = run_machine(
        source, program, sim_axes(spec), writes, list(outputs), cycle_s=cycle_s, n_cycles=n
    )
    return Trace.from_run(run)
