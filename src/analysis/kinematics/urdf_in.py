"""Arms from a URDF: a robot description's serial chain converted to the project's chain
description (modified D-H rows), so the loader derives its closed form where a family applies.

:func:`description_text` reads a URDF (``--arm robot.urdf``) and writes the TOML of the
equivalent description (``data/arms``'s format): the chain from the root link to the tool
frame, one modified D-H row per revolute, continuous or prismatic joint, a fixed row for the
base and one for the tool where they are needed, the joints' limits (and, where the URDF
gives one, ``velocity`` as ``max_velocity``) with their provenance, and no drive: a URDF
has no drive data and none is invented (no ``pulses_per_rev``, no ``lead_mm``; ``ik`` says "no
drive given", and ``stl`` refuses naming the joint; ``arms --arm robot.urdf --toml`` prints
this description, to which a user adds the drive). The conversion:

1. the chain's frames at q = 0 (URDF: ``T_parent_child = Trans(xyz) Rz(yaw) Ry(pitch)
   Rx(roll)`` per joint origin, the joint turning or sliding the child frame along its
   ``axis``); each joint axis is a line in space, and so are the base's z axis (line 0) and
   the tool frame's z axis (the last line);
2. on each line a D-H frame (Craig): z along the line, x along the common normal to the next
   line, the origin at the normal's foot (parallel lines: at the previous normal's foot;
   meeting lines: at the meeting point, x along ``z_i x z_i+1``);
3. each row from two frames: ``alpha`` (z_i-1 to z_i about x_i-1), ``a`` (along x_i-1),
   ``d`` (along z_i), ``theta_offset`` (x_i-1 to x_i about z_i); a joint's variable is the
   URDF's (its axis the row's +z), so joint values mean the same in both.

The FK of the description equals the URDF's (Pinocchio on the same file: tests/kinematics/
test_urdf_in.py, 10,000 configurations).

A URDF is untrusted input (issue 27): read bounded (:data:`MAX_BYTES`, regular files only),
parsed by ``defusedxml`` with DTDs refused (no entity can expand), every element and
attribute the chain needs checked (unknown ones refused, naming them; the ones URDF allows
for other purposes, geometry, inertia, transmissions, Gazebo tags, ignored), every number
through :func:`analysis.validate.parse_real`; one line per error naming the file and what
is wrong. Refused: a branch of moving joints in the tree, a joint type other than revolute,
continuous, prismatic or fixed (floating, planar; ``mimic``), several roots or a cycle, no
moving joint, no tool frame (fixed frames branching after the last joint, none of them
``tool0``, REP 199's flange frame).

Why hand-written: the URDF libraries (urchin, urdfpy, Pinocchio's parser) read files whole
and trust them, and none converts a chain to D-H rows; the subset read here is twelve
elements and attributes.
"""

from __future__ import annotations

import itertools
import math
import os
import stat
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from analysis import validate
from analysis.escape import toml_string

__all__ = ["MAX_BYTES", "MAX_JOINTS", "UrdfChain", "description_text", "read_urdf"]

MAX_BYTES = 4 * 2**20
"""Largest URDF read [bytes]: a kinematic description is kilobytes (meshes are separate
files); a larger file is refused before it is parsed."""
MAX_JOINTS = 256
"""Most joints a URDF may have (the chain itself: at most 6 derivable, any number for FK)."""
MM = 1000.0
"""Millimetres per metre (URDF lengths are metres)."""
MOVING = ("revolute", "continuous", "prismatic")
_IGNORED = {"material", "transmission", "gazebo"}
_JOINT_CHILDREN = {"origin", "parent", "child", "axis", "limit", "dynamics", "calibration",
                   "safety_controller"}  # fmt: skip
_LINK_CHILDREN = {"visual", "collision", "inertial"}


@dataclass(frozen=True)
class Joint:
    """One joint of the chain: URDF name and type, origin (4, 4) [mm] of the child in the
    parent frame, unit axis in the child frame, limits [rad | mm] and velocity [rad/s | mm/s]
    (None where not given)."""

    name: str
    kind: str
    parent: str
    child: str
    origin: np.ndarray
    axis: np.ndarray
    limits: tuple | None
    velocity: float | None


@dataclass(frozen=True)
class UrdfChain:
    """The serial chain of a URDF: its robot name, the joints from the root link to the tool
    link (fixed ones included) and the tool link's name."""

    name: str
    joints: tuple[Joint, ...]
    tool: str
    path: Path


def _err(path: Path, text: str) -> ValueError:
    return ValueError(f"{path.name}: {text}")


def _read_bounded(path: Path) -> bytes:
    try:
        st = os.stat(path)
    except OSError as exc:
        raise _err(path, f"cannot read ({exc.strerror})") from None
    if not stat.S_ISREG(st.st_mode):
        raise _err(path, "not a regular file (a URDF is read from a file)")
    with open(path, "rb") as fh:
        data = fh.read(MAX_BYTES + 1)
    if len(data) > MAX_BYTES:
        raise _err(path, f"larger than {MAX_BYTES} bytes: not read (a URDF is kilobytes)")
    return data


def _numbers(path, el, attr: str, n: int, default=None) -> np.ndarray:
    text = el.get(attr)
    if text is None:
        if default is None:
            raise _err(path, f"<{el.tag}> needs {attr}=\"...\" ({n} numbers)")
        return np.array(default, dtype=float)
    parts = text.split()
    if len(parts) != n:
        raise _err(path, f"<{el.tag} {attr}={text[:40]!r}>: expected {n} numbers")
    return np.array([_real(path, p, f"<{el.tag} {attr}>") for p in parts])


def _real(path, text: str, what: str) -> float:
    """A number of the file (:func:`analysis.validate.parse_real`), its errors naming it."""
    try:
        return validate.parse_real(text, what)
    except ValueError as exc:
        raise _err(path, str(exc)) from None


def _rotation(rpy) -> np.ndarray:
    r, p, y = rpy
    cr, sr, cp, sp_, cy, sy = (math.cos(r), math.sin(r), math.cos(p), math.sin(p),
                               math.cos(y), math.sin(y))  # fmt: skip
    return np.array([[cy * cp, cy * sp_ * sr - sy * cr, cy * sp_ * cr + sy * sr],
                     [sy * cp, sy * sp_ * sr + cy * cr, sy * sp_ * cr - cy * sr],
                     [-sp_, cp * sr, cp * cr]])  # fmt: skip


def _parse_joint(path, el) -> Joint:
    name, kind = el.get("name"), el.get("type")
    if not name or not kind:
        raise _err(path, "a <joint> needs name=\"...\" and type=\"...\"")
    if kind not in (*MOVING, "fixed"):
        raise _err(path, f"joint {name!r} is {kind!r}: only revolute, continuous, prismatic "
                         "and fixed joints make a serial arm")  # fmt: skip
    tags = {c.tag for c in el}
    if "mimic" in tags:
        raise _err(path, f"joint {name!r} mimics another: coupled joints are not a serial arm")
    unknown = sorted(tags - _JOINT_CHILDREN)
    if unknown:
        raise _err(path, f"joint {name!r} has unknown element(s) {unknown}")
    parent, child = el.find("parent"), el.find("child")
    if parent is None or child is None or not parent.get("link") or not child.get("link"):
        raise _err(path, f"joint {name!r} needs <parent link=...> and <child link=...>")
    T = np.eye(4)
    origin = el.find("origin")
    if origin is not None:
        T[:3, :3] = _rotation(_numbers(path, origin, "rpy", 3, (0.0, 0.0, 0.0)))
        T[:3, 3] = _numbers(path, origin, "xyz", 3, (0.0, 0.0, 0.0)) * MM
    axis = np.array([1.0, 0.0, 0.0])
    if el.find("axis") is not None:
        axis = _numbers(path, el.find("axis"), "xyz", 3)
    norm = float(np.linalg.norm(axis))
    if kind in MOVING and not norm > 1e-9:
        raise _err(path, f"joint {name!r}: axis {axis.tolist()} has no direction")
    limits, velocity = _limits(path, el, name, kind)
    return Joint(name, kind, parent.get("link"), child.get("link"), T,
                 axis / norm if norm > 0 else axis, limits, velocity)  # fmt: skip


def _limits(path, el, name: str, kind: str):
    lim = el.find("limit")
    if kind in ("revolute", "prismatic") and lim is None:
        raise _err(path, f"{kind} joint {name!r} needs <limit lower upper effort velocity>")
    if lim is None or kind == "fixed":
        return None, None
    scale = MM if kind == "prismatic" else 1.0
    velocity = _real(path, lim.get("velocity", "0"), f"joint {name} velocity") * scale
    if kind == "continuous":
        return None, velocity if velocity > 0 else None
    lo = _real(path, lim.get("lower", "0"), f"joint {name} lower") * scale
    hi = _real(path, lim.get("upper", "0"), f"joint {name} upper") * scale
    if not lo < hi:
        raise _err(path, f"joint {name!r}: limit lower {lo:g} is not below upper {hi:g}")
    return (lo, hi), velocity if velocity > 0 else None


def _parse(path: Path):
    from xml.etree.ElementTree import ParseError

    import defusedxml.ElementTree as DET
    from defusedxml import DefusedXmlException

    data = _read_bounded(path)
    try:
        root = DET.fromstring(data, forbid_dtd=True)
    except DefusedXmlException as exc:
        raise _err(path, f"refused ({type(exc).__name__}: a URDF needs no DTD or entity)") from None
    except ParseError as exc:
        raise _err(path, f"not well-formed XML ({exc})") from None
    if root.tag != "robot":
        raise _err(path, f"the root element is <{root.tag}>, not <robot>")
    links, joints = [], []
    for el in root:
        if not isinstance(el.tag, str) or el.tag in _IGNORED:
            continue
        if el.tag == "link":
            unknown = sorted({c.tag for c in el} - _LINK_CHILDREN)
            if not el.get("name") or unknown:
                raise _err(path, f"a <link> needs a name and holds only {sorted(_LINK_CHILDREN)}"
                                 + (f" (found {unknown})" if unknown else ""))  # fmt: skip
            links.append(el.get("name"))
        elif el.tag == "joint":
            joints.append(_parse_joint(path, el))
            if len(joints) > MAX_JOINTS:
                raise _err(path, f"more than {MAX_JOINTS} joints")
        else:
            raise _err(path, f"unknown element <{el.tag}> in <robot>")
    return root.get("name") or path.stem, links, joints


def read_urdf(path) -> UrdfChain:
    """The serial chain of the URDF at ``path`` (module docstring); ValueError naming the
    file and the reason otherwise."""
    path = Path(path)
    name, links, joints = _parse(path)
    for kind, seen in (("link", links), ("joint", [j.name for j in joints])):
        dup = sorted({x for x in seen if seen.count(x) > 1})
        if dup:
            raise _err(path, f"{kind} name(s) {dup} appear more than once")
    known = set(links)
    children: dict[str, list[Joint]] = {}
    for j in joints:
        for link in (j.parent, j.child):
            if link not in known:
                raise _err(path, f"joint {j.name!r} names link {link!r}, which is not defined")
        children.setdefault(j.parent, []).append(j)
    roots = sorted(known - {j.child for j in joints})
    if len(roots) != 1:
        raise _err(path, f"{len(roots)} root links {roots[:5]}: a chain has one (or a cycle)")
    return _walk(path, name, roots[0], children)


def _moving_below(link, children, depth=0) -> bool:
    if depth > MAX_JOINTS:
        return False
    return any(j.kind in MOVING or _moving_below(j.child, children, depth + 1)
               for j in children.get(link, ()))  # fmt: skip


def _walk(path, name, root, children) -> UrdfChain:
    chain, link = [], root
    for _ in range(MAX_JOINTS + 1):
        moving = [j for j in children.get(link, ()) if j.kind in MOVING
                  or _moving_below(j.child, children)]  # fmt: skip
        if len(moving) > 1:
            raise _err(path, f"link {link!r} has {len(moving)} branches with moving joints "
                             f"({', '.join(j.name for j in moving)}): a tree, not a serial arm")
        if not moving:
            break
        chain.append(moving[0])
        link = moving[0].child
    if not any(j.kind in MOVING for j in chain):
        raise _err(path, "no revolute, continuous or prismatic joint: nothing moves")
    tail = _tool(path, link, children)
    return UrdfChain(name, tuple(chain + tail), tail[-1].child if tail else link, path)


def _tool(path, link, children) -> list[Joint]:
    """The fixed joints from the last moving joint's link to the tool frame: the one leaf of
    the fixed frames after it, or, where they branch, the path to ``tool0``."""
    paths, stack = [], [(link, [])]
    while stack:
        if len(paths) > MAX_JOINTS:
            raise _err(path, "the fixed frames after the last joint form a cycle")
        here, way = stack.pop()
        kids = children.get(here, [])
        if not kids:
            paths.append(way)
        stack.extend((j.child, [*way, j]) for j in reversed(kids))
    if len(paths) == 1:
        return paths[0]
    named = [w for w in paths if any(j.child == "tool0" for j in w)]
    if not named:
        leaves = sorted(w[-1].child for w in paths)
        raise _err(path, f"no tool frame: after the last joint the fixed frames end in "
                         f"{len(paths)} links ({', '.join(leaves)}) and none is tool0")
    way = named[0]
    return way[: next(i for i, j in enumerate(way) if j.child == "tool0") + 1]


# --- the D-H rows -------------------------------------------------------------------------
def _lines(chain: UrdfChain):
    """The base's z axis, every moving joint's axis and the tool frame's z axis at q = 0:
    ``(point [mm], unit direction)`` per line, the moving joints, and the tool frame (4, 4)."""
    T = np.eye(4)
    lines = [(np.zeros(3), np.array([0.0, 0.0, 1.0]))]
    moving = []
    for j in chain.joints:
        T = T @ j.origin
        if j.kind in MOVING:
            lines.append((T[:3, 3].copy(), T[:3, :3] @ j.axis))
            moving.append(j)
    lines.append((T[:3, 3].copy(), T[:3, 2].copy()))
    return lines, moving, T


def _frames(lines, tool: np.ndarray) -> list[np.ndarray]:
    """A D-H frame (4, 4) on every line (module docstring, step 2); the last is the tool's."""
    frames = []
    prev = np.zeros(3)  # where the previous common normal meets this line
    x_prev = np.array([1.0, 0.0, 0.0])
    for (p, z), (q, w) in itertools.pairwise(lines):
        n = np.cross(z, w)
        if np.linalg.norm(n) > 1e-12:
            n /= np.linalg.norm(n)
            # feet of the common normal: p + s z and q + t w
            A = np.array([[z @ z, -z @ w], [z @ w, -w @ w]])
            s, t = np.linalg.solve(A, [(q - p) @ z, (q - p) @ w])
            origin, other = p + s * z, q + t * w
            gap = other - origin
            x = gap / np.linalg.norm(gap) if np.linalg.norm(gap) > 1e-9 else n
        else:  # parallel lines: at the previous normal's foot
            origin = p + ((prev - p) @ z) * z
            gap = (q - origin) - ((q - origin) @ z) * z
            if np.linalg.norm(gap) > 1e-9:
                x = gap / np.linalg.norm(gap)
            else:  # the same line: keep the previous x, across z
                x = x_prev - (x_prev @ z) * z
                x = x / np.linalg.norm(x) if np.linalg.norm(x) > 1e-9 else _across(z)
        F = np.eye(4)
        F[:3, 0], F[:3, 1], F[:3, 2], F[:3, 3] = x, np.cross(z, x), z, origin
        frames.append(F)
        prev = origin + (x @ (q - origin)) * x  # the normal's foot on the next line
        x_prev = x
    frames.append(tool)
    return frames


def _across(z) -> np.ndarray:
    e = np.eye(3)[int(np.argmin(np.abs(z)))]
    v = e - (e @ z) * z
    return v / np.linalg.norm(v)


def _snap(v: float, unit: float) -> float:
    """``v`` with float noise removed: within 1e-9 of a multiple of ``unit`` (90 deg; 0 mm
    with unit 0) it is that multiple."""
    if unit == 0.0:
        return 0.0 if abs(v) < 1e-9 else float(v)
    k = round(v / unit)
    return float(k * unit) if abs(v - k * unit) < 1e-9 else float(v)


def dh_rows(chain: UrdfChain) -> list[dict]:
    """The modified D-H rows of ``chain`` (module docstring): ``{joint, kind, alpha_deg, a, d,
    theta_offset_deg}`` [deg, mm], a fixed base row first where the first joint's frame is
    not on the base's z axis, a fixed tool row last."""
    lines, moving, tool = _lines(chain)
    frames = _frames(lines, tool)
    rows = []
    prev = np.eye(4)
    names = ["base", *(j.name for j in moving), "tool"]
    for k, F in enumerate(frames):
        x0, z0, o0 = prev[:3, 0], prev[:3, 2], prev[:3, 3]
        x1, z1, o1 = F[:3, 0], F[:3, 2], F[:3, 3]
        alpha = math.degrees(math.atan2(np.cross(z0, z1) @ x0, z0 @ z1))
        theta = math.degrees(math.atan2(np.cross(x0, x1) @ z1, x0 @ x1))
        a = float((o1 - o0) @ x0)
        d = float((o1 - o0 - a * x0) @ z1)
        row = {"joint": names[k], "alpha_deg": _snap(alpha, 90.0), "a": _snap(a, 0.0),
               "d": _snap(d, 0.0), "theta_offset_deg": _snap(theta, 90.0)}  # fmt: skip
        if 0 < k <= len(moving):
            row["kind"] = "prismatic" if moving[k - 1].kind == "prismatic" else "revolute"
        else:
            row["kind"] = "fixed"
        trivial = row["kind"] == "fixed" and not any(row[key] for key in ("alpha_deg", "a", "d",
                                                                          "theta_offset_deg"))
        if not (k == 0 and trivial):
            rows.append(row)
        prev = F
    return rows


# --- the description ------------------------------------------------------------------------
def _joint_entry(j: Joint) -> list[str]:
    src = f"{j.name} in the URDF"
    out = ["", "[[joints]]", f"name = {toml_string(j.name)}"]
    # no pulses_per_rev, no lead_mm: a URDF has no drive, and none is invented (what needs
    # one, a PLC program, refuses naming the joint: analysis.kinematics.schema.NoDrive)
    if j.kind == "prismatic":
        lo, hi = j.limits
        out += ['kind = "prismatic"', f"limits_mm = [{lo!r}, {hi!r}]"]
        unit = "mm/s"
    else:
        if j.limits is not None:
            out.append(f"limits_deg = [{math.degrees(j.limits[0])!r}, "
                       f"{math.degrees(j.limits[1])!r}]")  # fmt: skip
        unit = "rad/s"
        status = f"printed: <limit> of joint {src}" if j.limits else "continuous: a full turn"
        out.append(f"limits_status = {toml_string(status)}")
    if j.velocity is not None:
        out.append(f'max_velocity = {{ value = {j.velocity!r}, unit = "{unit}", status = '
                   f'"printed", source = {toml_string("<limit velocity> of joint " + src)} }}')
    return out


def description_text(path) -> str:
    """The TOML description of the URDF at ``path`` (module docstring): the project's chain
    description, its closed form left to the derivation (no ``closed_form``)."""
    chain = read_urdf(path)
    rows = dh_rows(chain)
    fname = Path(path).name
    out = [f"# Converted from the URDF {fname} by analysis.kinematics.urdf_in: modified D-H rows",
           "# from the chain's joint axes at q = 0 (a fixed base row and a tool row where needed).",
           f"name = {toml_string(_identifier(chain.name))}",
           f"title = {toml_string(f'{chain.name} (from {fname})')}",
           f"paper = {toml_string(f'URDF {fname}, tool frame {chain.tool}')}",
           'convention = "modified"']  # fmt: skip
    for r in rows:
        out += ["", "[[rows]]", f"joint = {toml_string(r['joint'])}", f"kind = \"{r['kind']}\""]
        out += [f"{k} = {r[k]!r}" for k in ("alpha_deg", "a", "d", "theta_offset_deg")]
    for j in chain.joints:
        if j.kind in MOVING:
            out += _joint_entry(j)
    return "\n".join(out) + "\n"


def _identifier(name: str) -> str:
    """A robot name as a description name: letters, digits and underscores."""
    out = "".join(c if (c.isascii() and c.isalnum()) else "_" for c in name).strip("_")
    return out or "urdf_arm"
