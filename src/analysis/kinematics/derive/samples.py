"""Random arm descriptions of the derivable families, for the property tests and the EAIK
agreement of ``make bench``.

:func:`random_arm` writes the TOML text of a random arm (``data/arms``'s format, no
``closed_form``: loading it derives one) of a family, in standard or modified D-H: the twists
that make the family (a waist across the parallel axes, 0 or 180 deg between parallel ones,
a roll across them) are drawn where the family allows any, every other twist, every length
and every joint offset is random (some exactly zero, as real tables have them), with an
optional fixed tool row, parameter names or literal numbers in the rows, and joint limits
on some joints. A 4-axis arm gets a ``keep`` that its chain can hold (a tool axis and the
direction it has at a random pitch).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["chain_toml", "random_arm"]

_PARALLEL = (0.0, 180.0)


def random_twist(rng, kind: str) -> float:
    """A twist [deg]: "parallel" (0 or 180), "across" (|sin| >= 0.2) or "any"."""
    if kind == "parallel":
        return float(rng.choice(_PARALLEL))
    if kind == "across":
        if rng.random() < 0.5:
            return float(rng.choice((90.0, -90.0)))
        return float(rng.choice((-1, 1)) * rng.uniform(12.0, 168.0))
    if rng.random() < 0.4:
        return float(rng.choice((0.0, 90.0, -90.0, 180.0)))
    return float(rng.uniform(-180.0, 180.0))


def random_length(rng, scale: float, p_zero: float = 0.4) -> float:
    return 0.0 if rng.random() < p_zero else float(round(rng.uniform(-scale, scale), 3))


def random_arm(rng: np.random.Generator, family: str, convention: str, name: str = "random") -> str:
    """TOML text of a random arm of ``family`` ("3R", "4R-kept", "5R") in ``convention``
    ("standard" or "modified"); lengths in mm, of the order of 100-400 mm."""
    n = {"3R": 3, "4R-kept": 4, "5R": 5}[family]
    # the twist of each joint axis against the previous one: waist -> axis 2 across,
    # then parallel ones, then (5R) the roll across
    rel = ["across"] + ["parallel"] * (n - 2 if family != "5R" else 2)
    if family == "5R":
        rel.append("across")
    if convention == "standard":
        # row i's alpha turns axis i (z_{i-1}) into axis i+1 (z_i); the last row's is free
        alphas = [random_twist(rng, k) for k in rel] + [random_twist(rng, "any")]
    else:
        # row i's alpha_{i-1} turns axis i-1 into axis i; row 1's tilts the waist
        alphas = [random_twist(rng, "any") if rng.random() < 0.3 else 0.0]
        alphas += [random_twist(rng, k) for k in rel]
    params: dict[str, float] = {}
    rows = []
    for i in range(n):
        row = {"joint": f"theta{i + 1}", "alpha_deg": alphas[i]}
        # links of the parallel part carry the reach; the others small offsets
        for key in ("a", "d"):
            big = key == "a" and (
                (convention == "standard" and i in (1, 2))
                or (convention == "modified" and i in (2, 3))
            )
            v = (
                float(round(rng.uniform(150.0, 400.0) * rng.choice((-1, 1)), 3))
                if big
                else random_length(rng, 120.0)
            )
            if v != 0.0 and rng.random() < 0.6:
                pname = f"{key}{i + 1}"
                params[pname] = v
                row[key] = pname
            else:
                row[key] = v
        if rng.random() < 0.5:
            row["theta_offset_deg"] = float(
                rng.choice((90.0, -90.0, 180.0))
                if rng.random() < 0.5
                else round(rng.uniform(-180, 180), 2)
            )
        rows.append(row)
    if rng.random() < 0.5 or convention == "modified":
        # modified D-H: a 3R arm's forearm is the tool row's a_{n}
        forearm = convention == "modified" and n == 3
        rows.append(
            {
                "joint": "tool",
                "kind": "fixed",
                "alpha_deg": random_twist(rng, "any"),
                "a": (
                    float(round(rng.uniform(150.0, 400.0), 3))
                    if forearm
                    else random_length(rng, 100.0)
                ),
                "d": random_length(rng, 100.0),
                "theta_offset_deg": float(
                    rng.choice((0.0, 90.0, round(rng.uniform(-180, 180), 2)))
                ),
            }
        )
    joints = []
    for i in range(n):
        lim = [-180.0, 180.0]
        if rng.random() < 0.2:
            lo = float(round(rng.uniform(-170.0, 0.0), 1))
            lim = [lo, float(round(rng.uniform(lo + 90.0, 180.0), 1))]
        joints.append(
            {"name": f"theta{i + 1}", "ppr": int(rng.choice((2000, 3200, 4000))), "limits": lim}
        )
    derive = ""
    if family == "4R-kept":
        derive = _keep(rng, convention, rows, params)
    return _toml(name, family, convention, params, rows, joints, derive)


def _keep(rng, convention, rows, params) -> str:
    """A ``keep`` the chain can hold: a tool axis and the direction it has when the
    parallel joints' pitch is a random angle (read off the chain at that pitch)."""
    from analysis.kinematics.derive.chain import home
    from analysis.kinematics.dh import DHRow, DHTable
    from analysis.kinematics.ops import numpy_ops

    def val(v):
        return params[v] if isinstance(v, str) else float(v)

    table = DHTable(
        tuple(
            DHRow(
                math.radians(r["alpha_deg"]), val(r["a"]), val(r["d"]),
                math.radians(r.get("theta_offset_deg", 0.0)), r.get("kind", "revolute"),
            )
            for r in rows
        ),
        convention,
    )  # fmt: skip
    h = home(numpy_ops, table)
    u = h.axes[1]
    psi = rng.uniform(-math.pi, math.pi)
    axis = str(rng.choice(("x", "y", "z")))
    t = h.rotation[:, "xyz".index(axis)]
    if np.linalg.norm(np.cross(u, t)) < 0.1:  # along the parallel axes: take another
        axis = "x" if axis != "x" else "y"
        t = h.rotation[:, "xyz".index(axis)]
    c, s = math.cos(psi), math.sin(psi)
    d = t * c + np.cross(u, t) * s + u * np.dot(u, t) * (1 - c)
    vec = ", ".join(repr(float(v)) for v in d)
    return f'\n[derive]\nkeep = {{ tool_axis = "{axis}", direction = [{vec}] }}\n'


def chain_toml(name, family, convention, params, rows, module: str = "samples") -> list[str]:
    """The lines of a random arm's description up to its joints: the header, the parameters
    (mm, assumed) and the D-H rows (``module``: the generator named in its first comment)."""
    out = [
        f"# A random {family} arm ({convention} D-H): analysis.kinematics.derive.{module}",
        f'name = "{name}"',
        f'title = "random {family} arm"',
        'paper = "none: generated"',
        f'convention = "{convention}"',
        "",
        "[parameters]",
    ]
    for k, v in params.items():
        out.append(f'{k} = {{ value = {v!r}, unit = "mm", status = "assumed", note = "random" }}')
    for r in rows:
        out.append("\n[[rows]]")
        for k, v in r.items():
            out.append(f'{k} = "{v}"' if isinstance(v, str) else f"{k} = {v!r}")
    return out


def _toml(name, family, convention, params, rows, joints, derive) -> str:
    out = chain_toml(name, family, convention, params, rows)
    for j in joints:
        out.append("\n[[joints]]")
        out.append(f'name = "{j["name"]}"')
        out.append(f"pulses_per_rev = {j['ppr']}")
        out.append(f"limits_deg = [{j['limits'][0]!r}, {j['limits'][1]!r}]")
    return "\n".join(out) + "\n" + derive
