"""``make bench``: the derived kinematics against peers, measured in one process.

Every case runs on the same seeded data, in interleaved rounds (case A, B, C, ..., then
again), and the median of the rounds is kept, so a burst of load hits every case alike.
Rates are targets (or configurations) per second of wall time. Nothing here asserts: the
targets of issue 14 are checked by reading ``build/bench.json`` (``"targets"``), quoted with
the machine's load average.

Cases
-----
IK, all four branches, targets uniform in the reachable shell (every target solved):
``compiled`` (``Arm.solve(backend="compiled")``, generated from the closed form),
``compiled_out`` (the same with preallocated ``out=`` buffers), ``kernel`` (the generated
kernel alone on preallocated arrays), ``numpy`` (``Arm.solve``), and the peers
``handfused`` (this project's hand-written Numba kernel before the one-source design),
``numexpr15`` and ``numpy15`` (the 15-line closed form a user would write), ``eaik``
(EAIK's batched analytical IK, on fewer targets), and ``ceiling`` (a generated kernel doing
only the IK's 4 atan2 and 3 sqrt per target: the fastest any kernel with these calls can be).
FK: ``fk_compiled``, ``fk_numpy``, ``fk_pinocchio`` (per-configuration loop, fewer
configurations) and ``fk_ceiling`` (only the 6 sin/cos per configuration).
Cold calls: the first compiled call after a second of idling, with fresh outputs and with
``out=``, against the warm median. CLI: ``python -m analysis ik 100 100 600 --json`` as a
whole process, median of 5. Vectorization: packed (ymm/zmm) divide and square-root
instructions counted in the IK kernel's assembly.

The machine program (benchmarks/machine_scan.py): each arm's 10 s scenario at 4 ms on the ST
engine (wall and in-scan scans per second) beside awlsim's scans of the same arm's program.

Derived closed forms (benchmarks/derived.py): EAIK's solution sets against the derived
ones on the seed arms and 120 random arms (20 per family and D-H convention, 50
configurations each), and the derived seed arms' compiled kernels against numpy and against
the hand-written kernels. The families engineers own (benchmarks/families.py): the PUMA 560's
and the UR5's eight-branch kernels against EAIK and IK-Geo on the same poses, every family's
solution sets against EAIK, IK-Geo and pyplcopen's kinematics.

Usage: ``python benchmarks/run.py --out build/bench.json [--n 2000000] [--rounds 4]``
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import handfused  # noqa: E402 - the peer kernel lives beside this script
import peers  # noqa: E402

from analysis.kinematics import compiled  # noqa: E402
from analysis.kinematics.arm import paper_arm  # noqa: E402
from analysis.kinematics.pinocchio_model import PinocchioArm  # noqa: E402
from analysis.studies import workspace as W  # noqa: E402


def _optional(name: str):
    try:
        return __import__(name)
    except ImportError:
        return None


def interleaved(cases: dict, rounds: int) -> dict[str, float]:
    """Median seconds per case over ``rounds`` interleaved rounds (after one warm-up each)."""
    for fn, _ in cases.values():
        fn()
    times: dict[str, list[float]] = {k: [] for k in cases}
    for _ in range(rounds):
        for k, (fn, _) in cases.items():
            t0 = time.perf_counter()
            fn()
            times[k].append(time.perf_counter() - t0)
    return {k: statistics.median(v) for k, v in times.items()}


def packed_instructions(kern) -> dict:
    """Count packed divide/sqrt instructions on ymm/zmm registers in a kernel's assembly.

    The cached dispatcher cannot show its assembly, so the same generated source is
    compiled once more, uncached, and inspected after a call."""
    import importlib.util
    import tempfile

    text = compiled.module_text(kern.source).replace("cache=True", "cache=False")
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "kernel_inspect.py"
        path.write_text(text)
        spec = importlib.util.spec_from_file_location("kernel_inspect", path)
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        k = len(kern.arrays)
        args = [np.ones(8) for _ in range(k)] + [1.0] * len(kern.scalars)
        outs = [np.empty(8, {"f8": float, "i1": np.int8, "b1": bool, "i8": np.int64}[d])
                for d in kern.outputs.values()]  # fmt: skip
        mod.kernel(8, *args, *outs)
        asm = "\n".join(mod.kernel.inspect_asm().values())
    count = {
        op: len(re.findall(rf"\b{op}\s+%[yz]mm", asm)) for op in ("vdivpd", "vsqrtpd", "vmulpd")
    }
    count["scalar_divsd"] = len(re.findall(r"\bv?divsd\b", asm))
    count["zmm"] = "zmm" in asm
    return count


def cli_seconds(runs: int = 5) -> float:
    cmd = [sys.executable, "-m", "analysis", "ik", "100", "100", "600", "--json"]
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        subprocess.run(cmd, check=True, capture_output=True)
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="build/bench.json", help="JSON output file")
    ap.add_argument("--n", type=int, default=2_000_000, help="targets per batch call")
    ap.add_argument("--n-peer", type=int, default=20_000, help="targets for per-point peers")
    ap.add_argument("--rounds", type=int, default=4, help="interleaved rounds (median kept)")
    args = ap.parse_args(argv)
    if min(args.n, args.n_peer, args.rounds) <= 0:
        print("--n, --n-peer and --rounds must be positive", file=sys.stderr)
        return 2
    load_before = os.getloadavg()
    arm = paper_arm()
    L1, L2, L3 = (arm.params[k] for k in ("L1", "L2", "L3"))
    rng = np.random.default_rng(20161)
    p = W.sample_shell(arm, args.n, rng)
    q = rng.uniform(-np.pi, np.pi, (args.n, 3))
    n_peer = min(args.n_peer, args.n)
    names = arm.branches
    out = compiled.allocate(arm.n_joints, (args.n,), names)
    kern = compiled.ik_kernel(arm.closed_form, tuple(arm.params), names, ())
    raw_out = [np.empty(args.n, np.int8), np.empty(args.n)]
    raw_out += [np.empty(args.n, bool) for _ in names] + [np.empty(args.n, np.int8) for _ in names]
    raw_out += [np.empty(args.n) for _ in range(12)]  # the kernel's outputs, in its order
    scal = [*arm.params.values(), 1e-6]
    ceil_ik = compiled.build(
        lambda m, v: {
            "r": m.atan2(v["y"], v["x"])
            + m.atan2(v["z"], v["x"])
            + m.atan2(v["y"], v["z"])
            + m.atan2(v["z"], v["y"])
            + m.sqrt(v["x"])
            + m.sqrt(v["y"])
            + m.sqrt(v["z"])
        },
        ("x", "y", "z"),
        (),
        {"r": "f8"},
    )
    ceil_fk = compiled.build(
        lambda m, v: {"r": sum(m.sin(v[k]) + m.cos(v[k]) for k in "abc")},
        ("a", "b", "c"),
        (),
        {"r": "f8"},
    )
    p_abs = np.abs(p)
    r_ik, r_fk = np.empty(args.n), np.empty(args.n)
    fk_out = compiled.allocate_points((args.n,))
    pin_arm = PinocchioArm(arm.table)
    ne = _optional("numexpr")
    eaik = _optional("eaik")

    ik_cases = {
        "compiled": (lambda: arm.solve(p, backend="compiled"), args.n),
        "compiled_out": (lambda: arm.solve(p, backend="compiled", out=out), args.n),
        "kernel": (lambda: kern.run(p, scal, raw_out), args.n),
        "numpy": (lambda: arm.solve(p), args.n),
        "handfused": (lambda: handfused.solve_all(arm, p), args.n),
        "numpy15": (lambda: peers.numpy15(p, L1, L2, L3), args.n),
        "ceiling": (lambda: ceil_ik.run(p_abs, [], [r_ik]), args.n),
    }
    if ne is not None:
        ik_cases["numexpr15"] = (lambda: peers.numexpr15(p, L1, L2, L3), args.n)
    if eaik is not None:
        robot = peers.eaik_robot(L1, L2, L3)
        poses = [robot.fwdKin(x) for x in q[:n_peer]]
        ik_cases["eaik"] = (lambda: robot.IK_batched(poses), n_peer)
    fk_cases = {
        "fk_compiled": (lambda: compiled.fk(arm, q, out=fk_out), args.n),
        "fk_numpy": (lambda: arm.fk(q), args.n),
        "fk_pinocchio": (lambda: pin_arm.fk(q[:n_peer]), n_peer),
        "fk_ceiling": (lambda: ceil_fk.run(q, [], [r_fk]), args.n),
    }
    med = interleaved({**ik_cases, **fk_cases}, args.rounds)
    rate = {k: n / med[k] for k, (_, n) in {**ik_cases, **fk_cases}.items()}

    # cold calls: after a second of idling, fresh outputs and out= buffers
    cold = {}
    for key, fn in (
        ("compiled", lambda: arm.solve(p, backend="compiled")),
        ("compiled_out", lambda: arm.solve(p, backend="compiled", out=out)),
    ):
        times = []
        for _ in range(3):
            time.sleep(1.0)
            t0 = time.perf_counter()
            fn()
            times.append(time.perf_counter() - t0)
        cold[key] = args.n / statistics.median(times)
    cli = cli_seconds()
    vec = packed_instructions(kern)
    from plc_scan import plc_scan_times  # benchmarks/ is the script's folder

    plc_scan = plc_scan_times()
    from machine_scan import machine_scan_times  # the machine program (issue 29 item 7)

    machine_scan = machine_scan_times()
    # the derived closed forms: EAIK's solution sets, and their kernels (benchmarks/derived.py)
    from derived import derived_kernels, eaik_agreement

    derived = {"eaik_agreement": eaik_agreement(), "kernels": derived_kernels()}
    # the families engineers own: the six-axis kernels against EAIK and IK-Geo, every
    # family against its oracles (benchmarks/families.py)
    from families import agreement, sixaxis

    families = {"sixaxis": sixaxis(), "agreement": agreement()}
    load_after = os.getloadavg()

    def ratio(a, b):
        return rate[a] / rate[b] if a in rate and b in rate else None

    targets = {
        "IK 4 branches >= 60 M/s (compiled_out)": (rate["compiled_out"] / 1e6, 60.0),
        "IK >= 12 x numexpr": (ratio("compiled_out", "numexpr15"), 12.0),
        "IK >= 0.9 x the hand-fused kernel": (ratio("compiled", "handfused"), 0.9),
        "FK >= 0.9 x its ceiling": (ratio("fk_compiled", "fk_ceiling"), 0.9),
        "FK >= 10 x a per-point Pinocchio loop": (ratio("fk_compiled", "fk_pinocchio"), 10.0),
        "cold call within 1.5 x warm (out=)": (rate["compiled_out"] / cold["compiled_out"], 1.5),
        "cold call within 1.5 x warm (fresh outputs)": (rate["compiled"] / cold["compiled"], 1.5),
        "public API within 1.25 x its kernel": (ratio("kernel", "compiled_out"), 1.25),
        "CLI answers in < 0.3 s": (cli, 0.3),
        "GR-1 machine, 10 s at 4 ms on the ST engine < 2 s": (machine_scan["gr1"]["wall_s"], 2.0),
        **{f"{k} IK, 8 branches, >= 10 x EAIK's batch": (v["compiled / eaik"], 10.0)
           for k, v in families["sixaxis"].items()},
    }
    doc = {
        "rates_per_s": rate,
        "cold_rates_per_s": cold,
        "ratios": {
            "compiled / handfused": ratio("compiled", "handfused"),
            "compiled_out / numexpr15": ratio("compiled_out", "numexpr15"),
            "compiled_out / numpy15": ratio("compiled_out", "numpy15"),
            "compiled_out / eaik": ratio("compiled_out", "eaik"),
            "compiled_out / ceiling": ratio("compiled_out", "ceiling"),
            "kernel / compiled_out": ratio("kernel", "compiled_out"),
            "numpy / numpy15": ratio("numpy", "numpy15"),
            "fk_compiled / fk_ceiling": ratio("fk_compiled", "fk_ceiling"),
            "fk_compiled / fk_pinocchio": ratio("fk_compiled", "fk_pinocchio"),
            "warm / cold (out=)": rate["compiled_out"] / cold["compiled_out"],
            "warm / cold (fresh)": rate["compiled"] / cold["compiled"],
        },
        "targets": {k: _verdict(k, v, lim) for k, (v, lim) in targets.items()},
        "cli_seconds_median_of_5": cli,
        "plc_scan_us": plc_scan,
        "machine_scan": machine_scan,
        "derived_closed_forms": derived,
        "families": families,
        "vectorization": vec,
        "machine": {
            "cpu_count": os.cpu_count(),
            "threads": compiled.threads(),
            "python": platform.python_version(),
            "numpy": np.__version__,
            "load_average_before": load_before,
            "load_average_after": load_after,
        },
        "n": args.n,
        "n_peer": n_peer,
        "rounds": args.rounds,
    }
    path = Path(args.out)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(doc, indent=2) + "\n")
    for k in sorted(rate, key=lambda k: -rate[k]):
        print(f"{k:<14} {rate[k] / 1e6:10.2f} M/s")
    for k, t in doc["targets"].items():
        v = t["value"]
        print(f"{'met ' if t['met'] else 'MISS'} {k}: {v if v is None else round(v, 3)}")
    for k, v in plc_scan.items():
        print(f"PLC scan {k:<10} awlsim {v['awlsim_us_per_scan']:9.1f} us, ST engine "
              f"{v['st_engine_us_per_scan']:7.2f} us ({v['awlsim / st_engine (scan)']:.0f}x)")
        print(f"S7-200   {k:<10} awlsim {v['awlsim_s7200_translated_us_per_scan']:9.1f} us "
              f"(translated), evaluator {v['s7200_evaluator_us_per_scan']:7.1f} us "
              f"({v['awlsim_s7200 / evaluator']:.1f}x)")
    for k, v in machine_scan.items():
        print(f"machine  {k:<10} 10 s at 4 ms in {v['wall_s']:.3f} s: "
              f"{v['machine_scans_per_s_wall']:,.0f} scans/s (wall), "
              f"{v['machine_scans_per_s_in_scan']:,.0f} in scan; awlsim IK "
              f"{v['awlsim_ik_scans_per_s']:,.0f} scans/s")
    for k, v in derived["eaik_agreement"].items():
        if isinstance(v, dict):
            print(
                f"EAIK {k:<17} {v['equal']}/{v['configurations']} equal sets, "
                f"{v['eaik_empty']} EAIK empty, {v['disagree']} disagree "
                f"({v['arms_all_equal']}/{v['arms']} arms all equal)"
            )
        else:
            print(f"EAIK: {v}")
    for k, v in derived["kernels"].items():
        print(
            f"derived kernel {k:<10} = numpy to {v['max_angle_diff_rad']:.1e} rad, "
            f"{v['derived / hand-written (rate)']:.2f} x the hand-written kernel's rate"
        )
    for k, v in families["sixaxis"].items():
        r = v["rates_poses_per_s"]
        print(f"six-axis {k:<8} compiled {r['compiled']:,.0f}/s, numpy {r['numpy']:,.0f}/s, "
              f"EAIK {r.get('eaik', 0):,.0f}/s, IK-Geo {r.get('ikgeo', 0):,.0f}/s "
              f"(8 branches; first call {v['first_compiled_call_s']:.0f} s)")
    for k, v in families["agreement"].items():
        if "equal" in v:
            print(f"{k:<30} {v['equal']}/{v['configurations']} equal sets, {v['oracle_empty']} "
                  f"oracle empty, {v['oracle_subset']} subset, {v['disagree']} disagree")
        else:
            print(f"{k:<30} {v}")
    print(f"load {load_before[0]:.2f} -> {load_after[0]:.2f}; wrote {path}")
    _plot(doc, path.with_suffix(".svg"))
    return 0


def _verdict(name: str, value, limit) -> dict:
    """A target is an upper bound if its name says "<" or "within", else a lower bound."""
    upper = "<" in name or "within" in name
    met = value is not None and (value <= limit if upper else value >= limit)
    return {"value": value, "limit": limit, "met": met}


def _plot(doc: dict, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rates = doc["rates_per_s"]
    ik = [k for k in rates if not k.startswith("fk")]
    fk = [k for k in rates if k.startswith("fk")]
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, keys, title in ((axes[0], ik, "IK, 4 branches"), (axes[1], fk, "FK")):
        keys = sorted(keys, key=lambda k: rates[k])
        ax.barh(keys, [rates[k] / 1e6 for k in keys], color="C0")
        ax.set_xscale("log")
        ax.set_xlabel("million per second (log)")
        ax.set_title(title)
    load = doc["machine"]["load_average_before"][0]
    fig.suptitle(f"make bench: {doc['machine']['cpu_count']} cores, load {load:.2f}")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


if __name__ == "__main__":
    raise SystemExit(main())
