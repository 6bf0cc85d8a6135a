"""The machine program on the ST engine against awlsim's scan of the same arm, in one run
(issue 29 item 7).

For each arm: a 10 s scenario at 4 ms cycles (2,501 cycles: power up, home from off home, a
move, a new target mid-move, the stop circuit opened and closed, Reset, the move resumed) on
the ST
engine (``analysis.plc.st_engine.run_machine``: a process, compile, bind the axes, every
cycle's scan and trace row), timed as a whole (wall) and inside ``Instance::scan`` alone
(the driver's ``scan_ns``): machine scans per second. Beside it, awlsim's scans per second
of the same arm's S7-300 program (the IK; ``AwlRunner.solve``, one OB1 cycle per target), in
the same process.
The issue's target: the GR-1's 10 s scenario in under 2 s of wall time.
"""

from __future__ import annotations

import json
import time


def _ten_seconds(arm) -> list[tuple[float, str, float]]:
    """A 10 s scenario, the last row at 8 s (+ 2 s settle): power up and home (the retarget
    scenario's rows up to its first Start, which comes once every axis is homed: about 5.6 s
    for the arms with reference switches, the axes powering up 2 s of their homing approach
    off home), then within the next 1.6 s: the move, its second target 0.4 s in, the stop
    circuit opened at 0.8 s and closed at 1.1 s, Reset, a Start back to the first target."""
    from analysis.plc.machine.scenarios import scenarios

    sc = scenarios(arm)
    rows = sc["retarget"].rows
    starts = [t for t, n, v in rows if n == "Start" and v == 1.0]
    t0, t1 = starts[0], starts[1]
    boot = [r for r in rows if r[0] <= t0 + 0.1]
    second = [(t0 + 0.4 + (t - t1), n, v) for t, n, v in rows if t1 - 0.06 <= t <= t1 + 0.1]
    first = [r for r in sc["move"].rows if r[1].startswith("Target")]
    k = t0 + 0.8
    rows = [*boot, *second, (k, "StopOK", 0.0), (k + 0.3, "StopOK", 1.0), (k + 0.5, "Reset", 1.0),
            (k + 0.6, "Reset", 0.0), *((k + 0.7, n, v) for _, n, v in first),
            (k + 0.8, "Start", 1.0), (k + 0.9, "Start", 0.0), (8.0, "Start", 0.0)]  # fmt: skip
    assert max(t for t, _, _ in rows) == 8.0, "the scenario outgrew its 10 s"
    return sorted(rows, key=lambda r: r[0])


def machine_scan_times(rounds: int = 3) -> dict:
    from analysis.kinematics.arm import load_arm
    from analysis.plc.generate import generate
    from analysis.plc.machine.program import machine_name
    from analysis.plc.machine.run import TRACED, schedule, sim_axes
    from analysis.plc.machine.spec import machine_spec
    from analysis.plc.memmap import MemoryMap
    from analysis.plc.runner import AwlRunner
    from analysis.plc.st_engine import run_machine
    from analysis.plc.sweep import sweep_targets
    from analysis.plc.verify import input_columns

    out = {}
    for name in ("grabber", "palletizer", "picker", "gr1"):
        arm = load_arm(name)
        st, _ = generate(arm, "st")
        spec = machine_spec(arm)
        writes, n = schedule(_ten_seconds(arm), 0.004, 2.0)
        walls, scans, cycles = [], [], 0
        for _ in range(rounds):
            t0 = time.perf_counter()
            run = run_machine(st, machine_name(spec), sim_axes(spec), writes, list(TRACED),
                              cycle_s=0.004, n_cycles=n)
            walls.append(time.perf_counter() - t0)
            scans.append(run.scan_ns * 1e-9)
            cycles = len(run.t)
        text, map_text = generate(arm, "s7-300")
        runner = AwlRunner(text, MemoryMap.from_dict(json.loads(map_text)))
        xyz = sweep_targets(arm)[input_columns(arm)].to_numpy(dtype=float)[:200]
        t0 = time.perf_counter()
        runner.solve(xyz)
        awl = (time.perf_counter() - t0) / len(xyz)
        wall, scan = min(walls), min(scans)
        out[name] = {
            "scenario_s": 10.0,
            "cycles": cycles,
            "wall_s": wall,
            "machine_scans_per_s_wall": cycles / wall,
            "machine_scans_per_s_in_scan": cycles / scan if scan else None,
            "awlsim_ik_scans_per_s": 1.0 / awl,
            "st_machine / awlsim_ik (scans per s, wall)": (cycles / wall) * awl,
        }
    return out


if __name__ == "__main__":
    print(json.dumps(machine_scan_times(), indent=2))
