"""Shared machine programs and traces: each arm's program generated once, each scenario run
once per dialect on the ST engine, the traces shared by every test that reads them."""

from __future__ import annotations

import functools

from analysis.kinematics.arm import load_arm

ARMS = ("grabber", "palletizer", "picker", "gr1")


@functools.cache
def machine(arm_name: str, dialect: str = "st"):
    """(arm, spec, ST source, PROGRAM name, MAP.json) of ``arm_name``'s machine program as
    ``dialect`` prints it (the XML read back into ST by analysis.plc.machine.xml_st)."""
    import json

    from analysis.plc.generate import generate
    from analysis.plc.machine.program import machine_name
    from analysis.plc.machine.spec import machine_spec
    from analysis.plc.machine.xml_st import st_from_plcopen

    arm = load_arm(arm_name)
    spec = machine_spec(arm)
    text, mjson = generate(arm, dialect)
    source = st_from_plcopen(text) if dialect == "plcopen-xml" else text
    return arm, spec, source, machine_name(spec), json.loads(mjson)


@functools.cache
def scenario_set(arm_name: str):
    from analysis.plc.machine.scenarios import scenarios

    return scenarios(load_arm(arm_name))


@functools.cache
def trace(arm_name: str, dialect: str, scenario: str):
    """The trace of one scenario (run once per session)."""
    from analysis.plc.machine.run import run_scenario

    _, spec, source, program, _ = machine(arm_name, dialect)
    return run_scenario(source, program, spec, scenario_set(arm_name)[scenario].rows)
