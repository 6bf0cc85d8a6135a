"""Random arm descriptions of the planar, SCARA, six-axis and gantry families (:mod:`.samples`
writes the seed families'), for the property tests, the oracles and ``make bench``.

:func:`random_family_arm` writes the TOML text of a random arm of a family in standard or
modified D-H: per row the twist's kind (``across``: any angle at least 12 deg from parallel,
``parallel``: 0 or 180 deg, ``perp``: +-90 deg, ``any``), the kind of each length (``big``:
150-400 mm either sign, ``small``: 0 or up to 120 mm, ``zero``) and a random joint offset;
the rows a family needs (the wrist's meeting point: ``a`` and ``d`` zero where Pieper's
condition needs them) are fixed. A gantry's directions and a vertical roll or wrist are
drawn until the chain is of the family (:func:`analysis.kinematics.derive.families.classify`,
at most :data:`TRIES` draws).
"""

from __future__ import annotations

import numpy as np

from analysis.kinematics.derive.samples import chain_toml, random_length, random_twist

__all__ = ["NEW_FAMILIES", "TRIES", "random_family_arm"]

NEW_FAMILIES = ("2R-planar", "3R-planar", "SCARA", "6R-wrist", "6R-parallel", "gantry",
                "gantry-roll", "gantry-wrist")  # fmt: skip
TRIES = 200

# (joint kind, twist kind, a kind, d kind) per row, in chain order; standard D-H: row i's
# twist turns axis i into axis i+1, its a joins them, its d lies along axis i.
_STANDARD = {
    "2R-planar": "R parallel big small | R any big small",
    "3R-planar": "R parallel big small | R parallel big small | R any small small",
    "6R-wrist": ("R across small small | R parallel big small | R across small small | "
                 "R perp zero big | R perp zero zero | R any small small"),
    "6R-parallel": ("R across small small | R parallel big small | R parallel big small | "
                    "R perp small small | R perp zero small | R any small small"),
}
# modified D-H: row i's twist and a (alpha_{i-1}, a_{i-1}) join axis i-1 to axis i, its d lies
# along axis i; the last row is the tool's (fixed)
_MODIFIED = {
    "2R-planar": "R base4 small small | R parallel big small | F any big small",
    "3R-planar": "R base2 small small | R parallel big small | R parallel big small | "
                 "F any small small",
    "6R-wrist": ("R base small small | R across small small | R parallel big small | "
                 "R across small big | R perp zero zero | R perp zero small | F any small small"),
    "6R-parallel": ("R base small small | R across small small | R parallel big small | "
                    "R parallel big small | R perp small small | R perp zero small | "
                    "F any small small"),
}


def _scara(rng, convention: str) -> str:
    """A SCARA's rows: two or three parallel revolute joints and a prismatic one along them,
    the prismatic one anywhere after the first."""
    rev = int(rng.choice((2, 3)))
    kinds = ["R"] * rev
    kinds.insert(int(rng.integers(1, rev + 1)), "P")
    rows = []
    for i, k in enumerate(kinds):
        twist = "base2" if (i == 0 and convention == "modified") else "parallel"
        rows.append(f"{k} {twist} {'big' if i < 3 else 'small'} small")
    if convention == "modified":
        rows.append("F any big small")
    elif rng.random() < 0.5:
        rows[-1] = rows[-1].replace("parallel", "any", 1)
    return " | ".join(rows)


def _gantry(rng, family: str) -> str:
    rows = ["P axis zero small"] * 3
    if family == "gantry-roll":
        rows.append("R axis small small")
    elif family == "gantry-wrist":
        rows += ["R axis zero big", "R perp zero zero", "R perp zero small"]
    rows.append("F any small small")
    return " | ".join(rows)


def _angle(rng, kind: str) -> float:
    if kind == "perp":
        return float(rng.choice((90.0, -90.0)))
    if kind == "base":
        return random_twist(rng, "any") if rng.random() < 0.3 else 0.0
    if kind == "base2":
        return float(rng.choice((0.0, 180.0)))
    if kind in ("base4", "axis"):
        return float(rng.choice((0.0, 90.0, -90.0, 180.0)))
    return random_twist(rng, kind)


def _rows(rng, spec: str) -> tuple[list[dict], dict]:
    params: dict[str, float] = {}
    rows = []
    for i, part in enumerate(spec.split("|")):
        kind, twist, a_kind, d_kind = part.split()
        row = {"joint": f"q{i + 1}" if kind != "F" else "tool", "alpha_deg": _angle(rng, twist)}
        if kind != "R":
            row["kind"] = {"P": "prismatic", "F": "fixed"}[kind]
        for key, k in (("a", a_kind), ("d", d_kind)):
            v = 0.0 if k == "zero" else (
                float(round(rng.uniform(150.0, 400.0) * rng.choice((-1, 1)), 3)) if k == "big"
                else random_length(rng, 120.0))  # fmt: skip
            if v != 0.0 and rng.random() < 0.5:
                params[f"{key}{i + 1}"] = v
                v = f"{key}{i + 1}"
            row[key] = v
        if twist == "axis" or rng.random() < 0.5:
            square = float(rng.choice((0.0, 90.0, -90.0, 180.0)))
            row["theta_offset_deg"] = square if rng.random() < 0.7 else float(
                round(rng.uniform(-180, 180), 2))  # fmt: skip
        rows.append(row)
    return rows, params


def _toml(name, family, convention, params, rows) -> str:
    out = chain_toml(name, family, convention, params, rows, "samples_more")
    for r in rows:
        if r.get("kind") == "fixed":
            continue
        out += ["\n[[joints]]", f'name = "{r["joint"]}"', "pulses_per_rev = 4000"]
        if r.get("kind") == "prismatic":
            out += ['kind = "prismatic"', "lead_mm = 10.0", "limits_mm = [-300.0, 300.0]"]
    return "\n".join(out) + "\n"


def _family_of(text: str) -> str | None:
    """The family the derivation finds for description ``text`` (None: none)."""
    import tempfile
    from pathlib import Path

    from analysis.kinematics.derive import derive
    from analysis.kinematics.derive.families import NotDerivable
    from analysis.kinematics.description import load_description

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "arm.toml"
        path.write_text(text, encoding="utf-8")
        try:
            return derive(load_description(str(path))).family
        except (NotDerivable, ValueError):
            return None


def random_family_arm(rng: np.random.Generator, family: str, convention: str,
                      name: str = "random") -> str:  # fmt: skip
    """TOML text of a random arm of ``family`` (one of :data:`NEW_FAMILIES`) in
    ``convention`` ("standard" or "modified"); lengths in mm, of the order of 100-400 mm.
    Raises RuntimeError if :data:`TRIES` draws give no arm of the family."""
    name = "".join(c if c.isalnum() else "_" for c in name)  # an identifier (the schema's)
    name = name if name[:1].isalpha() else f"arm_{name}"
    for _ in range(TRIES):
        if family.startswith("gantry"):
            spec = _gantry(rng, family)
        elif family == "SCARA":
            spec = _scara(rng, convention)
        else:
            spec = (_STANDARD if convention == "standard" else _MODIFIED)[family]
        rows, params = _rows(rng, spec)
        text = _toml(name, family, convention, params, rows)
        if _family_of(text) == family:
            return text
    raise RuntimeError(f"no random {family} arm ({convention}) in {TRIES} draws")
