"""PLC scan time per target: the generated program on awlsim (S7-300 AWL, native ATAN/ACOS)
beside the same program as IEC 61131-3 ST on the ST engine (analysis.plc.st_engine), for
every arm, in the same process and on the same targets (issue 22 item 7).

awlsim: wall time of ``AwlRunner.solve`` (one OB1 cycle per target, Python) per target. ST
engine: the driver's own time inside ``Instance::scan`` per target (``scan_ns``), and the
wall time of the whole call (process start, compile, I/O) per target. S7-200: the
generator's S7-200 text on the project's S7-200 evaluator (``S7200Runner.solve``) beside the
same text translated to AWL on awlsim (``AwlRunner.solve``), wall time per target.
"""

from __future__ import annotations

import json
import time


def plc_scan_times(n: int = 300) -> dict:
    from analysis.kinematics.arm import load_arm
    from analysis.plc import st_engine
    from analysis.plc.generate import generate
    from analysis.plc.ir import build_program
    from analysis.plc.memmap import MemoryMap
    from analysis.plc.runner import AwlRunner, S7200Runner
    from analysis.plc.st import block_name, emit_st
    from analysis.plc.sweep import sweep_targets
    from analysis.plc.translate import translate_s7200
    from analysis.plc.verify import input_columns

    out = {}
    for name in ("grabber", "palletizer", "gr1", "picker"):
        arm = load_arm(name)
        xyz = sweep_targets(arm)[input_columns(arm)].to_numpy(dtype=float)[:n]
        text, map_text = generate(arm, "s7-300")
        runner = AwlRunner(text, MemoryMap.from_dict(json.loads(map_text)))
        t0 = time.perf_counter()
        runner.solve(xyz)
        awl = (time.perf_counter() - t0) / len(xyz)
        prog = build_program(arm, None, "function")
        st = emit_st(prog, units=arm.input_units, default_branch=arm.branches[0])
        t0 = time.perf_counter()
        _, run = st_engine.sweep(st, block_name(prog, arm.branches[0]), prog.inputs,
                                 len(prog.outputs), xyz)  # fmt: skip
        wall = (time.perf_counter() - t0) / len(xyz)
        scan = run.scan_ns * 1e-9 / len(xyz)
        s7200, map200 = generate(arm, "s7-200", motion=False)
        mmap200 = MemoryMap.from_dict(json.loads(map200))
        ev = S7200Runner(s7200, mmap200)
        t0 = time.perf_counter()
        ev.solve(xyz)
        evaluator = (time.perf_counter() - t0) / len(xyz)
        tr = AwlRunner(translate_s7200(s7200).awl, mmap200)
        t0 = time.perf_counter()
        tr.solve(xyz)
        translated = (time.perf_counter() - t0) / len(xyz)
        out[name] = {
            "targets": len(xyz),
            "s7200_evaluator_us_per_scan": evaluator * 1e6,
            "awlsim_s7200_translated_us_per_scan": translated * 1e6,
            "awlsim_s7200 / evaluator": translated / evaluator,
            "awlsim_us_per_scan": awl * 1e6,
            "st_engine_us_per_scan": scan * 1e6,
            "st_engine_wall_us_per_target": wall * 1e6,
            "awlsim / st_engine (scan)": awl / scan if scan else None,
        }
    return out


if __name__ == "__main__":
    print(json.dumps(plc_scan_times(), indent=2))
