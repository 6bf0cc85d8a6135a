"""The paper's own program (Figures 3-6) through the machine's scenarios: what it does with
its stop button, a typed target, and a move, executed on the S7-200 evaluator.

Sec. 2.1 says: press SB1, the program computes each joint's angle and "gives it to the
joint"; press SB2 during the run and the program stops at once. The listings (Figures 3-6,
:mod:`analysis.plc.paper_listings`) read neither button, write no PLS and no direction, and
Figure 3 writes its own target into the inputs. :func:`run_paper` runs them scan by scan
through a :class:`~.scenarios.Scenario` (the same rows as the corrected machine: targets
typed into VD0-VD8, SB1 on I0.0, SB2 on I0.1) and records what they compute: the counts
c1 (VD16; with Figures 5-6 also c2 VD122 and c3 VD52, under the transcriber's VDD0 reading)
and every PLS they issue (none). Two readings of the contact "上电置1": SM0.0 (always on) and
SM0.1 (the first scan); Figure 3's MOVD inputs and Figure 4's unit can be repaired
(``real_inputs``, ``degrees``) so that these behaviours stand apart from the arithmetic
defects, as the register does.

Since the listings move nothing, :func:`follow` adds the reading the paper implies and marks
it as such: a drive that takes the computed count as the joint's absolute position and runs
to it at the joint's top speed (an assumption: no such drive is printed). The register's
behaviour findings can then be executed (:func:`paper_findings`): SB2 changes nothing of
what the program computes; a target typed on the HMI never reaches the counts; the counts are
absolute angles commanded from power-up, with no reference and no Home.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from analysis.plc.machine.scenarios import Scenario
from analysis.plc.machine.spec import machine_spec
from analysis.plc.motion.engines import EvaluatorEngine
from analysis.plc.motion.scenarios import S7Case
from analysis.plc.paper_listings import paper_program
from analysis.plc.stl_eval.legacy import PAPER_SYMBOLS

__all__ = ["PaperTrace", "follow", "paper_findings", "run_paper"]

_COUNTS = {"c1": "VD16", "c2": "VD122", "c3": "VD52"}
_VDD0 = {"COS": "VD12", "SIN": "VD12", "*R": "VD0", "MOVR": "VD0"}
_IO = {"TargetX": ("VD0", "REAL"), "TargetY": ("VD4", "REAL"), "TargetZ": ("VD8", "REAL"),
       "Start": ("I0.0", "BOOL"), "StopOK": ("I0.1", "BOOL")}  # fmt: skip


@dataclass
class PaperTrace:
    """After every scan: its end time [s] and the counts the listings computed; the PLS
    they issued; the reading and repairs the run used."""

    t: np.ndarray
    counts: dict[str, np.ndarray]
    pls: int
    reading: str
    notes: tuple[str, ...]


def run_paper(
    case: S7Case,
    *,
    reading: str = "SM0.0",
    figures=(3, 4),
    real_inputs: bool = True,
    degrees: bool = True,
    scan_ms: float = 40.0,
) -> PaperTrace:
    """Run the paper's ``figures`` through ``case`` (module docstring). Rows the listings
    have no input for (Home, Reset, Enable, jog) are ignored; SB2 is written to I0.1 as a
    push button (TRUE while pressed: StopOK FALSE), and read by nothing."""
    if reading not in ("SM0.0", "SM0.1"):
        raise ValueError(f"reading {reading!r}: 上电置1 is read as SM0.0 or SM0.1")
    text = paper_program((100, 100, 600), figures, real_inputs, _VDD0, degrees)
    eng = EvaluatorEngine(text, scan_ms=scan_ms, symbols={**PAPER_SYMBOLS, "上电置1": reading})
    rows = sorted(case.scenario.rows, key=lambda r: r[0])
    wanted = [k for k, f in (("c1", 4), ("c2", 5), ("c3", 6)) if f in figures]
    ts, out, i = [], {k: [] for k in wanted}, 0
    while eng.time < case.end - 1e-9:
        while i < len(rows) and rows[i][0] <= eng.time + 1e-9:
            _t, name, value = rows[i]
            if name in _IO:
                addr, typ = _IO[name]
                if typ == "BOOL":  # SB2 is a push button: TRUE while pressed (StopOK FALSE)
                    value = not value if name == "StopOK" else bool(value)
                eng.write(typ, addr, value)
            i += 1
        eng.scan()
        ts.append(eng.time)
        for k in wanted:
            out[k].append(eng.read("DINT", _COUNTS[k]))
    notes = (f"上电置1 read as {reading}",
             "Figure 3's inputs written with MOVR" if real_inputs else "Figure 3 as printed (MOVD)",
             "Figure 4's unit repaired (degrees)" if degrees else "Figure 4 as printed (radians)",
             "SB2 (I0.1) TRUE while pressed: Figure 2, the wiring, is lost")  # fmt: skip
    pls = sum(len(p.trains) for p in eng.pto)
    return PaperTrace(np.array(ts), {k: np.array(v) for k, v in out.items()}, pls, reading, notes)


def follow(t: np.ndarray, counts: np.ndarray, rate: float, start: int = 0) -> np.ndarray:
    """The position [counts] of a drive that runs to each scan's ``counts`` at ``rate``
    [counts/s] from ``start``: the reading sec. 2.1 implies (the angle "given to the joint"),
    an assumption the listings do not implement."""
    pos, out, prev = float(start), [], 0.0
    for ti, c in zip(t, counts, strict=True):
        step = rate * (ti - prev)
        pos += float(np.clip(c - pos, -step, step))
        out.append(pos)
        prev = ti
    return np.array(out)


def paper_findings(case: S7Case, stop_at: float, typed_target, reading: str = "SM0.0") -> dict:
    """The register's behaviour findings (data/registers/grabber.toml: grabber-impl-start's
    sb2, grabber-op-target-entry, grabber-impl-absolute), executed on ``case``:

    * ``stop_changes_nothing``: the counts with SB2 pressed at ``stop_at`` and never pressed
      are the same, scan for scan;
    * ``target_followed``: whether c1 ever equals the waist's count the float64 IK gives for
      ``typed_target`` (:func:`~analysis.plc.machine.scenarios.expected_joints`);
    * ``moves_before_home``: the first scan already commands a non-zero count (an absolute
      angle, with no reference input and no Home);
    * ``pls``: pulse trains issued (none: nothing reaches a driver).
    """
    from analysis.kinematics.arm import paper_arm
    from analysis.plc.machine.scenarios import expected_joints

    sc, end = case.scenario, case.end
    rows = [r for r in sc.rows if r[1] != "StopOK"]

    def until_end(rows_) -> S7Case:  # both runs as long as ``case``
        return S7Case(Scenario(sc.name, sc.title, tuple(rows_), sc.expect),
                      end - max(r[0] for r in rows_))  # fmt: skip

    pressed = until_end([*rows, (0.0, "StopOK", 1.0), (stop_at, "StopOK", 0.0)])
    free = until_end([*rows, (0.0, "StopOK", 1.0)])
    a, b = run_paper(pressed, reading=reading), run_paper(free, reading=reading)
    arm = paper_arm()
    spec = machine_spec(arm)
    want = expected_joints(arm, spec, tuple(typed_target))
    c1 = a.counts["c1"]
    return {
        "stop_changes_nothing": bool((a.counts["c1"] == b.counts["c1"]).all()),
        "target_followed": bool(want is not None
                                and (c1 == round(want[0] / spec.axes[0].per_pulse)).any()),
        "moves_before_home": bool(c1[0] != 0),
        "pls": a.pls,
        "c1": c1,
        "t": a.t,
        "notes": a.notes,
    }  # fmt: skip
