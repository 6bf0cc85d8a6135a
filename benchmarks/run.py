"""Throughput of this project's batch kinematics against per-point peers (``make bench``).

All measurements run in one process, one after the other, on the same seeded data:

- ours: ``analysis.kinematics.arm.Arm`` (numpy) and ``analysis.kinematics.fastik`` (Numba, both
cores), batch
  calls over ``--n`` points;
- peers: a per-point loop over Pinocchio's ``framesForwardKinematics``
  (``analysis.kinematics.pinocchio_model.PinocchioArm``) and a per-point loop of the same closed
  form (eqs. 2, 6-19) in plain Python ``math``, over ``--n-peer`` points.

Each rate is the best of ``--repeat`` timed runs (after one warm-up call that also
JIT-compiles), in points per second. Writes a JSON list of
``{"name", "ours_per_s", "peer", "peer_per_s", "ratio"}`` (ratio = ours / peer) plus
``"extra"`` details, and prints a table. Benchmarks are not tests: nothing here asserts.

Usage: ``python benchmarks/run.py --out build/bench.json [--n 2000000] [--n-peer 20000]``
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "src"))

from analysis.kinematics import fastik
from analysis.kinematics.arm import paper_arm
from analysis.kinematics.pinocchio_model import PinocchioArm
from analysis.kinematics.pulses import angles_to_pulses, pulses_to_angles
from analysis.studies import workspace as W

CPU_RATES: dict[int, float] = {}  # id(fn) -> points per CPU-second (all threads summed)


def best_rate(fn, n: int, repeat: int) -> float:
    """Points per wall-clock second of ``fn()`` over ``n`` points: best of ``repeat`` runs
    after a warm-up. Also records points per CPU-second (``time.process_time``, summed over
    threads) in ``CPU_RATES``: on a loaded machine wall time inflates, CPU time much less."""
    fn()
    best, best_cpu = math.inf, math.inf
    for _ in range(repeat):
        c0, t0 = time.process_time(), time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
        best_cpu = min(best_cpu, time.process_time() - c0)
    CPU_RATES[id(fn)] = n / best_cpu if best_cpu > 0 else math.inf
    return n / best


def python_fk(L1, L2, L3, qs):
    """Per-point FK (eq. 2's P column) in plain Python ``math``: the loop peer."""
    out = []
    cos, sin = math.cos, math.sin
    for t1, t2, t3 in qs:
        r = L2 * cos(t2) + L3 * cos(t2 + t3)
        out.append((cos(t1) * r, sin(t1) * r, L1 + L2 * sin(t2) + L3 * sin(t2 + t3)))
    return out


def python_ik_all(L1, L2, L3, pts, tol=1e-6):
    """Per-point corrected IK, all four branches, in plain Python ``math`` (same closed form)."""
    out = []
    pi = math.pi
    for x, y, pz in pts:
        z = pz - L1
        rho = math.hypot(x, y)
        D = math.hypot(rho, z)
        if rho <= tol or D - (L2 + L3) > tol or abs(L2 - L3) - D > tol:
            out.append(None)
            continue
        phi = math.atan2(y, x)
        c3 = max(-1.0, min(1.0, (D * D - L2 * L2 - L3 * L3) / (2 * L2 * L3)))
        t3m = math.acos(c3)
        sols = []
        for rs, us in ((1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)):
            r = rs * rho
            t3 = -us * rs * t3m
            k = L2 * math.cos(t3) + L3
            s = L2 * math.sin(t3)
            t23 = math.atan2(z * k + r * s, r * k - z * s)
            t1 = phi if rs > 0 else phi + pi
            sols.append(((t1 + pi) % (2 * pi) - pi, (t23 - t3 + pi) % (2 * pi) - pi, t3))
        out.append(sols)
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="build/bench.json", help="JSON output file")
    ap.add_argument("--n", type=int, default=2_000_000, help="points per batch call")
    ap.add_argument("--n-peer", type=int, default=20_000, help="points per per-point peer loop")
    ap.add_argument(
        "--repeat", type=int, default=5, help="timed runs per measurement (best is kept)"
    )
    args = ap.parse_args(argv)
    if args.n <= 0 or args.n_peer <= 0 or args.repeat <= 0:
        print("--n, --n-peer and --repeat must be positive", file=sys.stderr)
        return 2

    arm = paper_arm()
    P = arm.params
    L1, L2, L3 = P.L1, P.L2, P.L3
    rng = np.random.default_rng(20161)
    q = rng.uniform(-np.pi, np.pi, (args.n, 3))
    # IK targets: uniform in the reachable shell (every target solved: the hard case) and
    # uniform in the shell's bounding cube (about 52 % reachable; the rest exit early)
    p = W.sample_shell(arm, args.n, rng)
    p_box = W.sample_box(arm, args.n, rng)
    q_peer, p_peer, pb_peer = q[: args.n_peer], p[: args.n_peer], p_box[: args.n_peer]
    q_list, p_list, pb_list = q_peer.tolist(), p_peer.tolist(), pb_peer.tolist()
    pin_arm = PinocchioArm(P.dh_table())
    n_map = min(1_000_000, args.n)  # the map size (fewer only with a small --n)
    p_map = p[:n_map]  # all in the reachable shell

    def numpy_quant_map():
        sol = arm.solve(p_map, ("front-up",))
        ok = sol.ok[..., 0]
        qq = sol.theta[ok, 0, :]
        c = angles_to_pulses(qq)
        return np.linalg.norm(arm.fk(pulses_to_angles(c)) - p_map[ok], axis=-1)

    cpu: dict[str, float] = {}

    def rate(key, fn, n):
        r = best_rate(fn, n, args.repeat)
        cpu[key] = CPU_RATES[id(fn)]
        return r

    rates = {
        "pinocchio_fk_loop": rate("pinocchio_fk_loop", lambda: pin_arm.fk(q_peer), args.n_peer),
        "python_fk_loop": rate(
            "python_fk_loop", lambda: python_fk(L1, L2, L3, q_list), args.n_peer
        ),
        "python_ik_loop": rate(
            "python_ik_loop", lambda: python_ik_all(L1, L2, L3, p_list), args.n_peer
        ),
        "numpy_fk": rate("numpy_fk", lambda: arm.fk(q), args.n),
        "numba_fk": rate("numba_fk", lambda: fastik.fk(arm, q), args.n),
        "numpy_ik": rate("numpy_ik", lambda: arm.solve(p), args.n),
        "numba_ik": rate("numba_ik", lambda: fastik.solve_all(arm, p), args.n),
        "python_ik_loop_box": rate(
            "python_ik_loop_box", lambda: python_ik_all(L1, L2, L3, pb_list), args.n_peer
        ),
        "numpy_ik_box": rate("numpy_ik_box", lambda: arm.solve(p_box), args.n),
        "numba_ik_box": rate("numba_ik_box", lambda: fastik.solve_all(arm, p_box), args.n),
        "numpy_quant": rate("numpy_quant", numpy_quant_map, n_map),
        "numba_quant": rate("numba_quant", lambda: fastik.ik_front_up_pulses(arm, p_map), n_map),
    }
    shell, box = "targets in the reachable shell", "targets in the bounding cube"
    rows = [
        (
            "batch FK, numba (analysis.kinematics.fastik.fk)",
            "numba_fk",
            "Pinocchio FK per-point loop",
            "pinocchio_fk_loop",
        ),
        (
            "batch FK, numpy (analysis.kinematics.arm.Arm.fk)",
            "numpy_fk",
            "Pinocchio FK per-point loop",
            "pinocchio_fk_loop",
        ),
        (
            "batch FK, numba (analysis.kinematics.fastik.fk)",
            "numba_fk",
            "plain-Python math FK loop",
            "python_fk_loop",
        ),
        (
            f"batch IK 4 branches, numba (fastik.solve_all), {shell}",
            "numba_ik",
            "plain-Python math IK loop",
            "python_ik_loop",
        ),
        (
            f"batch IK 4 branches, numpy (Arm.solve), {shell}",
            "numpy_ik",
            "plain-Python math IK loop",
            "python_ik_loop",
        ),
        (
            f"batch IK 4 branches, numba (fastik.solve_all), {shell}",
            "numba_ik",
            "numpy Arm.solve (same run)",
            "numpy_ik",
        ),
        (
            f"batch IK 4 branches, numba (fastik.solve_all), {box}",
            "numba_ik_box",
            "plain-Python math IK loop",
            "python_ik_loop_box",
        ),
        (
            f"batch IK 4 branches, numpy (Arm.solve), {box}",
            "numpy_ik_box",
            "plain-Python math IK loop",
            "python_ik_loop_box",
        ),
        (
            f"quantization map {n_map:.0e} targets, numba (fastik.ik_front_up_pulses)",
            "numba_quant",
            "numpy pipeline (Arm.solve, angles_to_pulses, Arm.fk)",
            "numpy_quant",
        ),
    ]
    out = [
        {
            "name": name,
            "ours_per_s": rates[ours],
            "peer": peer,
            "peer_per_s": rates[pk],
            "ratio": rates[ours] / rates[pk],
            "ours_per_cpu_s": cpu[ours],
            "peer_per_cpu_s": cpu[pk],
            "cpu_ratio": cpu[ours] / cpu[pk],
        }
        for name, ours, peer, pk in rows
    ]
    extra = {
        "name": "environment and absolute times",
        "ours_per_s": rates["numba_quant"],
        "peer": "-",
        "peer_per_s": None,
        "ratio": None,
        "quant_map_targets": n_map,
        "quant_map_seconds_numba": n_map / rates["numba_quant"],
        "quant_map_seconds_numpy": n_map / rates["numpy_quant"],
        "n": args.n,
        "n_peer": args.n_peer,
        "repeat": args.repeat,
        "cpu_count": os.cpu_count(),
        "numba_threads": fastik.numba.get_num_threads() if fastik.HAVE_NUMBA else 0,
        "python": platform.python_version(),
        "numpy": np.__version__,
        "load_average_1min": os.getloadavg()[0],
    }
    out.append(extra)
    path = Path(args.out)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(out, indent=2) + "\n")
    width = max(len(r["name"]) for r in out[:-1])
    for r in out[:-1]:
        ours, peer = f"{r['ours_per_s']:>12.4g}/s", f"{r['peer_per_s']:>11.4g}/s"
        print(
            f"{r['name']:<{width}}  {ours}  vs {r['peer']:<30} {peer}  x{r['ratio']:.1f}"
            f"  (CPU-time ratio x{r['cpu_ratio']:.1f})"
        )
    print(
        f"quantization map over {n_map:.0e} targets: "
        f"{extra['quant_map_seconds_numba']:.3f} s (numba), "
        f"{extra['quant_map_seconds_numpy']:.3f} s (numpy); "
        f"load average {extra['load_average_1min']:.2f}"
    )
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
