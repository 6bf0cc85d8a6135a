"""Every arm as URDF: the exchange format of ROS/RViz, MoveIt, MuJoCo's importer and Pinocchio.

:func:`arm_urdf` writes the kinematic tree of an arm, by name or by the path of a
description file (a user's own arm included):

- **D-H arms** (standard or modified, ``data/arms/*.toml``): one link per D-H frame, one
  joint per revolute or prismatic row, its origin the row's constant part (standard: the
  previous row's ``Tz(d) Tx(a) Rx(alpha)`` then ``Rz(theta_offset)``; modified:
  ``Rx(alpha) Tx(a) Tz(d) Rz(theta_offset)``), its axis z; fixed rows and the tool become a
  fixed joint to a ``tool`` link whose frame is the chain's last frame. A prismatic row is a
  ``prismatic`` joint along the same z axis (its value adds to ``d``), its stroke the limits.
  Each link frame is the D-H frame of the description, so a user sees the table's frames in
  RViz, and a joint value is the description's joint variable (``theta_i = q_i +
  theta_offset_i``).
- **the picker** (seed 002, a closed chain: :mod:`analysis.kinematics.picker`): its open-chain
  equivalent from the screws at the reference pose. URDF describes trees, so the loop is cut
  at the wrist base: the main chain (waist, vertical slider, the passive joints theta3-5, the
  3R wrist, the tool marker) and the secondary chain (the horizontal slider and theta10-13)
  are two branches of the waist link, each ending in a frame at F'. The closure (both F'
  frames coincide; the passive joints are those of
  :meth:`analysis.kinematics.picker.Picker.joints`) is stated in the file's comments.

Units are URDF's: metres and radians (the description's millimetres / 1000). Joint types:
``continuous`` where the description allows a full turn, ``revolute`` with its limits
otherwise, ``prismatic`` with the slider stroke. ``effort`` and ``velocity`` are required by
URDF's ``<limit>``; no paper prints them, so they are 0 with a comment saying so. Every
parameter, its value and its provenance (printed, derived, assumed) and every joint's
limits and pulses per revolution with theirs are carried as XML comments, so what the
extraction lost stays marked in the exchanged file. Links carry no inertia or geometry:
this is the kinematics the papers give, nothing more.

Why a plain XML writer (the standard library's :mod:`xml.etree.ElementTree`): the only URDF
library pinned here (``urchin``, in the ``bench`` extra for EAIK) pulls trimesh, pyglet and
lxml into the runtime for what is ten element types; ElementTree escapes text and writes
comments, and Pinocchio (``buildModelFromUrdf``/``buildModelFromXML``) reading the file back
is the check (``tests/kinematics/test_urdf.py``).
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from analysis.escape import xml_chars, xml_comment
from analysis.kinematics.dh import exact_cos_sin
from analysis.kinematics.loader import load_arm
from analysis.kinematics.model import Arm
from analysis.kinematics.picker import load_picker
from analysis.kinematics.rpy import rpy_from_matrix

__all__ = [
    "UrdfJoint",
    "arm_urdf",
    "dh_joints",
    "pinocchio_configuration",
    "screw_joints",
    "to_xml",
]

MM = 1e-3
"""Metres per millimetre (URDF lengths are in metres)."""


@dataclass(frozen=True)
class UrdfJoint:
    """One joint of the tree. ``origin`` (4, 4) [mm] places the child link's frame in the
    parent's at zero joint value; ``axis`` in that frame; ``limits`` [rad | mm] or None."""

    name: str
    kind: str
    parent: str
    child: str
    origin: np.ndarray
    axis: tuple = (0.0, 0.0, 1.0)
    limits: tuple | None = None
    comments: tuple = field(default=())


def _clean(text: str) -> str:
    """Text a comment can hold (:func:`analysis.escape.xml_comment`: one line, XML
    characters only, no ``--``)."""
    return xml_comment(text)


def _unique(kind: str, names) -> None:
    """Refuse two links or two joints of one name (a URDF names each once)."""
    seen: set[str] = set()
    for n in names:
        if n in seen:
            raise ValueError(f"URDF: two {kind}s are named {n!r}; each needs its own name")
        seen.add(n)


def _num(v: float) -> str:
    v = float(v)
    if abs(v) < 1e-15:
        return "0"
    if v == int(v) and abs(v) < 1e15:
        return str(int(v))
    return repr(v)


def _origin(T: np.ndarray) -> dict:
    """URDF ``<origin>`` attributes (metres; roll-pitch-yaw about fixed x, y, z)."""
    alpha, beta, gamma = rpy_from_matrix(T[:3, :3])  # R = Rz(alpha) Ry(beta) Rx(gamma)
    return {
        "xyz": " ".join(_num(v * MM) for v in T[:3, 3]),
        "rpy": " ".join(_num(v) for v in (gamma, beta, alpha)),
    }


def to_xml(robot: str, header: list[str], links: list[str], joints: list[UrdfJoint]) -> str:
    """The URDF text of a tree (``<robot>`` with ``header`` comments first)."""
    links = [xml_chars(n) for n in links]  # ElementTree escapes markup, not these
    _unique("link", links)
    _unique("joint", [xml_chars(j.name) for j in joints])
    root = ET.Element("robot", name=xml_chars(robot))
    for line in header:
        root.append(ET.Comment(f" {_clean(line)} "))
    for name in links:
        ET.SubElement(root, "link", name=name)
    for j in joints:
        for line in j.comments:
            root.append(ET.Comment(f" {_clean(line)} "))
        el = ET.SubElement(root, "joint", name=xml_chars(j.name), type=j.kind)
        ET.SubElement(el, "parent", link=xml_chars(j.parent))
        ET.SubElement(el, "child", link=xml_chars(j.child))
        ET.SubElement(el, "origin", **_origin(j.origin))
        if j.kind != "fixed":
            ET.SubElement(el, "axis", xyz=" ".join(_num(v) for v in j.axis))
        if j.kind in ("revolute", "prismatic"):
            scale = 1.0 if j.kind == "revolute" else MM
            lo, hi = j.limits
            ET.SubElement(
                el, "limit", lower=_num(lo * scale), upper=_num(hi * scale), effort="0",
                velocity="0",
            )  # fmt: skip
    ET.indent(root, space="  ")
    return '<?xml version="1.0" encoding="utf-8"?>\n' + ET.tostring(root, "unicode") + "\n"


# --------------------------------------------------------------------------- D-H arms
def _rz(angle: float) -> np.ndarray:
    c, s = exact_cos_sin(angle)
    T = np.eye(4)
    T[:2, :2] = [[c, -s], [s, c]]
    return T


def _rx(angle: float) -> np.ndarray:
    c, s = exact_cos_sin(angle)
    T = np.eye(4)
    T[1:3, 1:3] = [[c, -s], [s, c]]
    return T


def _trans(x: float, z: float) -> np.ndarray:
    T = np.eye(4)
    T[0, 3], T[2, 3] = x, z
    return T


def _slug(text: str, fallback: str) -> str:
    out = "".join(c if c.isalnum() or c in "_-" else "_" for c in str(text)).strip("_")
    return out or fallback


def _drive(spec) -> str:
    """A joint's drive as a comment: pulses per revolution (a prismatic joint's lead), or
    that the description gives none."""
    if not spec.has_drive:
        return f"{spec.name}: no drive given ({spec.missing_drive})"
    lead = f", lead {spec.lead_mm:g} mm per revolution" if spec.kind == "prismatic" else ""
    return f"{spec.name}: {spec.pulses_per_rev} pulses per revolution [{spec.pulses_status}]{lead}"


def dh_joints(desc) -> tuple[list[str], list[UrdfJoint]]:
    """Links and joints of a D-H description (the module docstring's mapping)."""
    table = desc.dh_table()
    joints, links = [], ["base_link"]
    pending = np.eye(4)
    parent = "base_link"
    specs = iter(desc.joints)
    for i, (row, raw) in enumerate(zip(table.rows, desc.rows, strict=True)):
        if table.convention == "standard":
            place = pending @ _rz(row.theta_offset)
            after = _trans(row.a, row.d) @ _rx(row.alpha)
        else:
            place = pending @ _rx(row.alpha) @ _trans(row.a, row.d) @ _rz(row.theta_offset)
            after = np.eye(4)
        if row.kind == "fixed":
            pending = place @ after if table.convention == "standard" else place
            continue
        # a prismatic row slides along the same z axis a revolute row turns about: standard
        # Rz(off) Tz(d + q) Tx(a) Rx(alpha) = [Rz(off)] Tz(q) [Tz(d) Tx(a) Rx(alpha)], modified
        # Rx(alpha) Tx(a) Rz(off) Tz(d + q) = [Rx Tx Tz(d) Rz(off)] Tz(q): the same place
        spec = next(specs)
        child = f"link{len(joints) + 1}_{_slug(raw.get('link', ''), spec.name)}"
        links.append(child)
        link = f", {raw['link']}" if raw.get("link") else ""
        where = f"joint {spec.name} (D-H row {i + 1}{link})"
        status = f" [{spec.limits_status}]" if spec.limits_status else ""
        if row.kind == "prismatic":
            limited = True
            kind = "prismatic"
            notes = [
                f"{where}: prismatic along z, d = {row.d:g} mm + {spec.name}, stroke "
                f"{spec.lower:g} .. {spec.upper:g} mm{status}",
                _drive(spec)
                + (
                    f"; theta = {math.degrees(row.theta_offset):g} deg (fixed)"
                    if row.theta_offset
                    else ""
                ),
            ]
        else:
            limited = not spec.unlimited
            kind = "revolute" if limited else "continuous"
            notes = [
                f"{where}: "
                f"{'revolute, limits' if limited else 'continuous (a full turn allowed)'} "
                f"{math.degrees(spec.lower):g} .. {math.degrees(spec.upper):g} deg{status}",
                _drive(spec)
                + (
                    f"; theta = {spec.name} + {math.degrees(row.theta_offset):g} deg (offset)"
                    if row.theta_offset
                    else ""
                ),
            ]
        if limited:
            notes.append("effort and velocity: not printed in the paper (0 = not given)")
        joints.append(
            UrdfJoint(
                spec.name,
                kind,
                parent,
                child,
                place,
                limits=(spec.lower, spec.upper) if limited else None,
                comments=tuple(notes),
            )
        )
        parent, pending = child, after
    links.append("tool")
    joints.append(
        UrdfJoint(
            "tool_joint", "fixed", parent, "tool", pending,
            comments=("the tool frame: the chain's last frame (fixed rows included), the point "
                      "fk/ik use",),
        )
    )  # fmt: skip
    return links, joints


def _header(desc_like, path: Path | None, extra: list[str]) -> list[str]:
    from analysis import __version__

    lines = [
        f"{desc_like['title']} ({desc_like['name']}): {desc_like['paper']}",
        f"generated by python -m analysis urdf (analysis {__version__})"
        + (f" from {path.name}" if path else ""),
        "units: metres and radians (the description's mm / 1000); links carry no inertia or "
        "geometry (kinematics only)",
        *extra,
        "parameters (value, provenance: printed in the paper, derived, or ASSUMED where the "
        "extraction lost it or the paper never gave it):",
    ]
    for p in desc_like["parameters"]:
        lines.append(p)
    return lines


def _param_lines(desc) -> list[str]:
    out = []
    for p in desc.parameters.values():
        mark = "ASSUMED" if p.status == "assumed" else p.status
        out.append(
            f"  {p.name} = {p.value:g} {p.unit} [{mark}]" + (f": {p.source}" if p.source else "")
        )
    return out


# --------------------------------------------------------------------------- screws
def screw_joints(
    S: np.ndarray,
    names: list[str],
    parent: str,
    origin: np.ndarray,
    limits: list,
    comments: list,
    prefix: str,
) -> tuple[list[str], list[UrdfJoint], str, np.ndarray]:
    """Links and joints of a serial chain of space-frame screws ``S`` (n, 6) at the home
    pose, hung below ``parent`` whose frame is ``origin`` (4, 4) [mm] in the base frame.

    Every joint frame is parallel to the base frame, at the point of its axis nearest the
    base origin (a revolute joint: ``omega x v``) or at the previous joint's (a prismatic
    one), with the axis ``omega`` (or ``v``) in it: then ``oMi`` at q = 0 is a translation
    and Pinocchio's product of the joint motions is the POE ``exp([S1] q1) ... M``. Returns
    the links, the joints, the last link and its frame."""
    links, joints = [], []
    frame = origin
    for k, row in enumerate(S):
        w, v = row[:3], row[3:]
        revolute = np.linalg.norm(w) > 0.5
        here = np.eye(4)
        here[:3, 3] = np.cross(w, v) if revolute else frame[:3, 3]
        child = f"{prefix}{names[k]}"
        lim = limits[k]
        kind = "prismatic" if not revolute else ("continuous" if lim is None else "revolute")
        joints.append(
            UrdfJoint(
                names[k], kind, parent, child, np.linalg.inv(frame) @ here,
                axis=tuple(float(x) for x in (w if revolute else v)),
                limits=lim, comments=tuple(comments[k]),
            )
        )  # fmt: skip
        links.append(child)
        parent, frame = child, here
    return links, joints, parent, frame


def _picker_urdf(desc) -> str:
    path = desc.path
    pk = load_picker(path)
    p = pk.params
    S, M = pk.open_chain()
    S2, M2 = pk.secondary_chain()
    pas = "passive: set by the loop closure (link 5 |B - G| = b, the parallelograms), not a drive"
    main_names = ["theta1", "theta2", "theta3", "theta4", "theta5", "theta6", "theta7", "theta8"]
    main_lim = [None, (p["z_min"], p["z_max"]), None, None, None, None, None, None]
    main_notes = [
        ["theta1: waist (revolute about Z), active; no range printed: continuous"],
        [f"theta2 = z: vertical slider (prismatic), active; stroke {p['z_min']:g} .. "
         f"{p['z_max']:g} mm [ASSUMED: no stroke is printed]",
         "effort and velocity: not printed in the paper (0 = not given)"],
        [f"theta3: back-arm hinge A, {pas}"],
        [f"theta4: lower small-arm hinge D, {pas}"],
        [f"theta5: wrist-base hinge F, {pas}"],
        ["theta6: wrist xi6 (axis ASSUMED), active"],
        ["theta7: wrist xi7 (axis ASSUMED), active"],
        ["theta8: wrist xi8 (axis ASSUMED), active"],
    ]  # fmt: skip
    links = ["base_link"]
    w_links, w_joints, _, waist = screw_joints(
        S[:1], main_names[:1], "base_link", np.eye(4), main_lim[:1], main_notes[:1], "link_"
    )
    m_links, m_joints, last, frame = screw_joints(
        S[1:], main_names[1:], w_links[-1], waist, main_lim[1:], main_notes[1:], "link_"
    )
    sec_names = ["theta9", "theta10", "theta11", "theta12", "theta13"]
    sec_lim = [(p["x_min"], p["x_max"]), None, None, None, None]
    sec_notes = [
        [f"theta9 = x: horizontal slider (prismatic), active; stroke {p['x_min']:g} .. "
         f"{p['x_max']:g} mm [ASSUMED]", "effort and velocity: not printed (0 = not given)"],
        [f"theta10 = theta3 (back small-arm C'), {pas}"],
        [f"theta11 = -theta3 (E''), {pas}"],
        [f"theta12 (E'), {pas}"],
        [f"theta13 (F'), {pas}"],
    ]  # fmt: skip
    s_links, s_joints, s_last, s_frame = screw_joints(
        S2[1:], sec_names, w_links[-1], waist, sec_lim, sec_notes, "secondary_"
    )
    # the frames at F' on the wrist base, through either chain, and the tool marker
    fp = np.eye(4)
    fp[:3, 3] = M2[:3, 3]
    link5 = m_links[3]  # the child of theta5: the wrist base
    tree = [*w_links, *m_links, *s_links, "tool", "closure_main", "closure_secondary"]
    joints = [
        *w_joints,
        *m_joints,
        UrdfJoint("tool_joint", "fixed", last, "tool", np.linalg.inv(frame) @ M,
                  comments=("the tool marker P (sec. 4), the point fk uses",)),
        *s_joints,
        UrdfJoint("closure_main_joint", "fixed", link5, "closure_main",
                  np.linalg.inv(_home(S[:5])) @ fp,
                  comments=("F' on the wrist base through the main chain",)),
        UrdfJoint("closure_secondary_joint", "fixed", s_last, "closure_secondary",
                  np.linalg.inv(s_frame) @ M2,
                  comments=("F' on the wrist base through the secondary chain",)),
    ]  # fmt: skip
    statuses = [
        f"  {q.name} = {q.value:g} {q.unit} [{'ASSUMED' if q.status == 'assumed' else q.status}]"
        f": {q.note}"
        if not isinstance(q.value, tuple)
        else f"  {q.name} = {q.value} [{'ASSUMED' if q.status == 'assumed' else q.status}]: "
        f"{q.note}"
        for q in p.parameters.values()
    ]
    extra = [
        "CLOSED CHAIN exported as its open-chain equivalent: URDF holds trees only. The loop "
        "is cut at the wrist base F': closure_main (main chain) and closure_secondary (the "
        "secondary chain) are the same frame when the passive joints theta3, theta4, theta5, "
        "theta10..theta13 take the values of the loop closure for the sliders theta2 = z and "
        "theta9 = x (analysis.kinematics.picker.Picker.joints; residuals: loop_residuals).",
        "a simulator must enforce that closure (MuJoCo: an equality constraint; Pinocchio: "
        "a rigid constraint between the two frames); RViz shows any joint values.",
    ]
    desc_like = {
        "name": "picker",
        "title": desc.title,
        "paper": desc.paper,
        "parameters": statuses,
    }
    return to_xml("picker", _header(desc_like, path, extra), [*links, *tree], joints)


def _home(S: np.ndarray) -> np.ndarray:
    """The frame of the last joint of ``S`` as :func:`screw_joints` places it."""
    frame = np.eye(4)
    for row in S:
        w, v = row[:3], row[3:]
        here = np.eye(4)
        here[:3, 3] = np.cross(w, v) if np.linalg.norm(w) > 0.5 else frame[:3, 3]
        frame = here
    return frame


# --------------------------------------------------------------------------- dispatch
def arm_urdf(arm: Arm | str | Path) -> str:
    """The URDF text of an arm (an :class:`~analysis.kinematics.model.Arm`, or a name in
    ``data/arms`` or a description's path, loaded by :func:`~analysis.kinematics.loader.
    load_arm`)."""
    if not isinstance(arm, Arm):
        arm = load_arm(arm)
    desc = arm.description
    if not desc.has_rows and "vertical_guide" in {**desc.parameters, **desc.axes}:
        return _picker_urdf(desc)  # the closed chain (its guides: parameters, or [axes])
    links, joints = dh_joints(desc)
    cf = arm.closed_form
    if cf is None:
        route = f"no closed form ({' '.join(arm.no_ik.split())})"
    elif getattr(cf, "family", None):
        route = f"closed form derived from these rows ({cf.family} family)"
    else:
        route = f"hand-written closed form analysis.kinematics.arms.{desc.closed_form}"
    extra = [f"{desc.convention} D-H ({len(desc.joints)} joints); IK in this project: {route}"]
    desc_like = {
        "name": desc.name,
        "title": desc.title,
        "paper": desc.paper,
        "parameters": _param_lines(desc),
    }
    return to_xml(_slug(desc.name, "arm"), _header(desc_like, desc.path, extra), links, joints)


def pinocchio_configuration(model, names, q) -> np.ndarray:
    """Pinocchio configurations (N, model.nq) of joint values ``q`` (N, len(names)) [rad |
    mm] of the joints ``names`` of a model read from this module's URDF (others at 0).

    A ``continuous`` joint is Pinocchio's ``JointModelRUB*`` (nq = 2: cos and sin); a
    prismatic one is in metres there."""
    q = np.atleast_2d(np.asarray(q, dtype=float))
    out = np.zeros((len(q), model.nq))
    out[:, :] = np.asarray(_neutral(model))
    for k, name in enumerate(names):
        j = model.getJointId(name)
        if j >= model.njoints:
            raise ValueError(f"no joint {name!r} in the model")
        iq, nq = model.idx_qs[j], model.nqs[j]
        shortname = model.joints[j].shortname()
        if nq == 2:
            out[:, iq], out[:, iq + 1] = np.cos(q[:, k]), np.sin(q[:, k])
        elif shortname.startswith("JointModelP"):
            out[:, iq] = q[:, k] * MM
        else:
            out[:, iq] = q[:, k]
    return out


def _neutral(model):
    import pinocchio as pin

    return pin.neutral(model)
