"""The grabber's three stepper drives as Table 2 wires them, fed by an engine's pulses.

A pulse from PTO0 (Q0.0) steps the waist; a pulse from PTO1 (Q0.1) steps the shoulder if
relay KM1 (Q0.3) is closed and the elbow if KM2 (Q0.4) is (:data:`WIRING`). A driver steps
one count up if its direction input (Q0.2, Q0.5, Q0.7) is on, down if off. Every input is
read at the terminals, i.e. as the process image the previous scan wrote
(:class:`~.engines.Interval`): a direction written in the scan of its PLS reaches the driver
only after that scan's first pulses.

What a real machine would do wrong is counted, not hidden: pulses that reach no driver (both
relays open), pulses that reach two (both closed), and pulses of one train whose direction
differs from that train's last pulse (the direction changed under a running train). The
operator can move the arm by hand (:meth:`Drives.jog`: bringing it to its home marks before
Home, as home mode "set" needs).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from analysis.plc.motion.engines import Interval

__all__ = ["WIRING", "Drives"]

WIRING = (  # joint: PTO channel, relay terminal (None: the channel's own), direction terminal
    (0, None, "Q0.2"),
    (1, "Q0.3", "Q0.5"),
    (1, "Q0.4", "Q0.7"),
)
"""Table 2: PTO0 -> waist (direction Q0.2); PTO1 -> shoulder through KM1 (Q0.3, direction
Q0.5) or elbow through KM2 (Q0.4, direction Q0.7)."""


@dataclass
class Drives:
    """Joint positions [pulses] and every step, from the intervals an engine ran."""

    counts: np.ndarray = field(default_factory=lambda: np.zeros(3, dtype=np.int64))
    steps: list[tuple[float, int, int, int, int]] = field(default_factory=list)
    """(time [s], joint, +1 | -1, channel, train) per step."""
    lost: int = 0
    """PTO1 pulses with both relays open (no driver got them)."""
    doubled: int = 0
    """PTO1 pulses with both relays closed (two drivers stepped)."""

    def apply(self, iv: Interval) -> None:
        for ch in (0, 1):
            joints = [j for j, (c, relay, _) in enumerate(WIRING)
                      if c == ch and (relay is None or iv.q(relay))]  # fmt: skip
            pulses, trains = iv.pulses[ch], iv.trains[ch]
            if not pulses:
                continue
            if not joints:
                self.lost += len(pulses)
                continue
            if len(joints) > 1:
                self.doubled += len(pulses)
            for j in joints:
                sign = 1 if iv.q(WIRING[j][2]) else -1
                self.counts[j] += sign * len(pulses)
                self.steps += [(t, j, sign, ch, k) for t, k in zip(pulses, trains, strict=True)]

    def jog(self, counts) -> None:
        """The operator moves the joints by hand to ``counts`` (no pulse)."""
        self.counts = np.asarray(counts, dtype=np.int64).copy()

    def wrong_direction(self) -> int:
        """Steps whose direction differs from their train's last step on the same joint."""
        last: dict[tuple[int, int, int], int] = {}
        for _t, j, sign, ch, k in self.steps:
            last[(j, ch, k)] = sign
        return sum(sign != last[(j, ch, k)] for _t, j, sign, ch, k in self.steps)

    def step_times(self, joint: int) -> np.ndarray:
        """The times [s] of ``joint``'s steps."""
        return np.array([t for t, j, *_ in self.steps if j == joint])
