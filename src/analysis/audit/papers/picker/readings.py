"""Seed 002's findings that rest on a reading of printed text, each reading recorded as data
beside the words it reads (``data/papers/picker.toml``) and compared here, never decided by the
words a description happens to hold: the works the introduction reviews against the claim of
novelty (``prior_work.cited``, ``novelty.reads_as``: pick-claim-novelty), and the test hardware
of sec. 4 against the claims made for the arm's structure (``test_platform.devices``,
``structure_claim.claimed``: pick-claim-structure). Each reading says plainly what it adds to
the printed text (``beyond_print``); a reading not anchored in the print is refused, naming it.
"""

from __future__ import annotations

import numpy as np

__all__ = ["MEASURES", "PRIOR_READING", "prior_methods", "structure_claims", "test_devices"]

PRIOR_READING = {
    "theory": ("screw theory",),
    "builds": ("kinematic equations", "mechanism analysis"),
    "robot": ("serial", "parallel", "hybrid"),
    "proposes_method": (True, False),
}
"""The vocabulary a reading of a cited work (``prior_work.cited`` in ``data/papers/picker.toml``)
and the novelty claim's own reading (``novelty.reads_as``) are written in: the fields compared."""
_CITED_KEYS = {"ref", "location", "quote", "said", "method", "beyond_print", *PRIOR_READING}


def prior_methods(paper) -> dict:
    """Each work the introduction reviews, as recorded: is our reading of it (theory, what it
    builds, the robot's class, whether it proposes a method) the novelty claim's reading of the
    paper's own contribution? ValueError, naming the work, for a reading that is not anchored
    in the printed text (its quote right after its citation mark, its entry in the list) or
    that leaves the vocabulary (:data:`PRIOR_READING`)."""
    prior, claim = paper.record("prior_work"), paper.record("novelty")["reads_as"]
    if set(claim) != set(PRIOR_READING):
        raise ValueError(f"picker:novelty reads_as has {sorted(claim)}; expected {sorted(PRIOR_READING)}")  # noqa: E501
    same, keys = [], []
    for c in prior["cited"]:
        where = f"picker:prior_work cited [{c.get('ref')}]"
        if set(c) != _CITED_KEYS:
            raise ValueError(f"{where}: keys {sorted(set(c) ^ _CITED_KEYS)} unknown or missing")
        if f"[{c['ref']}]" + c["quote"] not in prior.text.replace("等[", "["):
            raise ValueError(f"{where}: the quote is not the text right after [{c['ref']}]")
        paper.record(f"references.{c['ref']}")  # the entry, as printed
        for k, allowed in PRIOR_READING.items():
            if c[k] not in allowed or type(c[k]) is not type(allowed[0]):
                raise ValueError(f"{where}: {k} = {c[k]!r} not in {allowed}")
        if not c["beyond_print"].strip():
            raise ValueError(f"{where}: say what the reading adds to the printed text")
        same.append(all(c[k] == claim[k] for k in PRIOR_READING))
        keys.append(c["ref"])
    return {"same_method": np.array(same), "key": np.array(keys)}


MEASURES = ("marker position", "joint value", "force", "acceleration")
"""What a device of the test platform (``test_platform.devices``) can measure, and what a claimed
property of the structure needs measured (``structure_claim.claimed[].needs``)."""
_DEVICE_KEYS = {"device", "quote", "measures", "beyond_print"}
_CLAIMED_KEYS = {"property", "quote", "needs", "reported_in", "beyond_print"}


def _anchored(where: str, d: dict, keys: set, text: str) -> None:
    if set(d) != keys:
        raise ValueError(f"{where}: keys {sorted(set(d) ^ keys)} unknown or missing")
    if d["quote"] not in text:
        raise ValueError(f"{where}: the quote {d['quote']!r} is not printed there")
    if not d["beyond_print"].strip():
        raise ValueError(f"{where}: say what the reading adds to the printed text")


def test_devices(paper) -> list[dict]:
    """The devices sec. 4's test platform consists of, as our reading records each
    (``test_platform.devices``: the device, its words in the text, what it measures)."""
    rec = paper.record("test_platform")
    out = []
    for d in rec["devices"]:
        where = f"picker:test_platform device {d.get('device')!r}"
        _anchored(where, d, _DEVICE_KEYS, rec.text)
        if not set(d["measures"]) <= set(MEASURES):
            raise ValueError(f"{where}: measures {d['measures']} not in {MEASURES}")
        out.append(d)
    return out


def structure_claims(paper) -> dict:
    """Each property claimed for the arm's structure (``structure_claim.claimed``): is it
    reported anywhere (``reported_in``: the places the paper gives its value; a place must be a
    record of the paper), and could the test hardware have measured it (what it ``needs`` is
    among what the devices measure)?"""
    rec = paper.record("structure_claim")
    measured = {m for d in test_devices(paper) for m in d["measures"]}
    shown, measurable = [], []
    for c in rec["claimed"]:
        where = f"picker:structure_claim {c.get('property')!r}"
        _anchored(where, c, _CLAIMED_KEYS, rec.text + rec["section_two"])
        if not c["needs"] or not set(c["needs"]) <= set(MEASURES):
            raise ValueError(f"{where}: needs {c['needs']} not in {MEASURES}")
        for ref in c["reported_in"]:
            paper.record(ref)  # a place the paper reports the property: one of its records
        shown.append(bool(c["reported_in"]))
        measurable.append(set(c["needs"]) <= measured)
    return {"shown": np.array(shown), "measurable": np.array(measurable)}
