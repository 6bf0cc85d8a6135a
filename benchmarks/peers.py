"""The peers ``make bench`` measures against: what a user would write, and other libraries.

- :func:`numpy15`: the corrected closed form in 15 lines of numpy, all four branches;
- :func:`numexpr15`: the same expressions evaluated by numexpr (multi-threaded, fused);
- :func:`eaik_robot`: EAIK (analytical IK by subproblem decomposition) set up as the paper's
  arm from its joint axes and offsets (the ``bench`` extra);
- the hand-fused Numba kernel this project used before the one-source design
  (``benchmarks/handfused.py``), and Pinocchio's per-point FK (``analysis.kinematics.
  pinocchio_model.PinocchioArm``).

None of these is a runtime dependency of ``analysis``.
"""

from __future__ import annotations

import numpy as np


def numpy15(p, L1, L2, L3):
    """All four branches (front-up, front-down, back-up, back-down) -> (n, 4, 3) [rad]."""
    x, y, z = p[:, 0], p[:, 1], p[:, 2] - L1
    rho = np.hypot(x, y)
    c3 = np.clip((rho * rho + z * z - L2 * L2 - L3 * L3) / (2 * L2 * L3), -1, 1)
    t3 = np.arccos(c3)
    s = L2 * np.sqrt(1 - c3 * c3)
    k = L2 * c3 + L3
    t1 = np.arctan2(y, x)
    up = np.arctan2(z * k - rho * s, rho * k + z * s)
    down = np.arctan2(z * k + rho * s, rho * k - z * s)
    t1b = np.where(t1 > 0, t1 - np.pi, t1 + np.pi)
    return np.stack(
        [
            np.stack([t1, up + t3, -t3], -1),
            np.stack([t1, down - t3, t3], -1),
            np.stack([t1b, np.pi - up - t3, t3], -1),
            np.stack([t1b, np.pi - down + t3, -t3], -1),
        ],
        axis=1,
    )


def numexpr15(p, L1, L2, L3):
    """:func:`numpy15` with every expression evaluated by numexpr (requires numexpr)."""
    import numexpr as ne

    x, y = p[:, 0], p[:, 1]
    z = ne.evaluate("pz - L1", {"pz": p[:, 2], "L1": L1})
    env = {"x": x, "y": y, "z": z, "L2": L2, "L3": L3}
    rho = ne.evaluate("sqrt(x*x + y*y)", env)
    c3 = ne.evaluate("(rho*rho + z*z - L2*L2 - L3*L3) / (2*L2*L3)", {**env, "rho": rho})
    c3 = ne.evaluate("where(c3 < -1, -1, where(c3 > 1, 1, c3))", {"c3": c3})
    env.update(rho=rho, c3=c3)
    t3 = ne.evaluate("arccos(c3)", env)
    s = ne.evaluate("L2 * sqrt(1 - c3*c3)", env)
    k = ne.evaluate("L2 * c3 + L3", env)
    env.update(s=s, k=k, t3=t3)
    t1 = ne.evaluate("arctan2(y, x)", env)
    up = ne.evaluate("arctan2(z*k - rho*s, rho*k + z*s)", env)
    down = ne.evaluate("arctan2(z*k + rho*s, rho*k - z*s)", env)
    env.update(t1=t1, up=up, down=down, pi=np.pi)
    out = np.empty((len(x), 4, 3))
    out[:, 0, 0] = out[:, 1, 0] = t1
    out[:, 2, 0] = out[:, 3, 0] = ne.evaluate("where(t1 > 0, t1 - pi, t1 + pi)", env)
    out[:, 0, 1] = ne.evaluate("up + t3", env)
    out[:, 1, 1] = ne.evaluate("down - t3", env)
    out[:, 2, 1] = ne.evaluate("pi - up - t3", env)
    out[:, 3, 1] = ne.evaluate("pi - down + t3", env)
    out[:, 0, 2] = out[:, 3, 2] = -t3
    out[:, 1, 2] = out[:, 2, 2] = t3
    return out


def eaik_robot(L1, L2, L3):
    """EAIK's model of the paper's arm: joint axes H and offsets P at the zero pose
    (waist +z through the origin; shoulder and elbow -y through (0, 0, L1), (L2, 0, L1))."""
    from eaik.IK_HP import HPRobot

    H = np.array([[0, 0, 1], [0, -1, 0], [0, -1, 0]], dtype=float)
    P = np.array([[0, 0, 0], [0, 0, L1], [L2, 0, 0], [L3, 0, 0]], dtype=float)
    return HPRobot(H, P)
