"""MAP.json for every dialect (issue 22 item 6; analysis.plc.memmap): units per input, every
status code with its meaning, every memory range the program uses, the start-up, the target
CPU and its limits checked at generation time."""

from __future__ import annotations

import itertools
import json

import pytest

from analysis.audit.papers.gr1.thesis import gr1_arm
from analysis.kinematics.arm import load_arm, paper_arm
from analysis.kinematics.status import Status
from analysis.plc.generate import generate
from analysis.plc.memmap import CPUS, SCHEMA, MemoryMap, default_map, map_document

PAPER = paper_arm()


def _doc(dialect="s7-200", **kw) -> dict:
    return json.loads(generate(kw.pop("arm", PAPER), dialect, **kw).map)


@pytest.mark.parametrize("dialect", ["s7-200", "s7-300"])
def test_the_gr1_map_gives_its_angles_in_radians_and_every_status(dialect):
    """The GR-1's alpha/beta/gamma are radians (the map said "inputs: mm"); its program
    writes statuses 5 and 7 too (the list omitted them; 7 in 385 of 4,079 scans)."""
    d = _doc(dialect, arm=gr1_arm())
    units = {k: v["unit"] for k, v in d["signals"].items() if v["direction"] == "input"}
    assert units == {
        "px": "mm",
        "py": "mm",
        "pz": "mm",
        "alpha": "rad",
        "beta": "rad",
        "gamma": "rad",
    }
    assert "alpha, beta, gamma: rad" in d["units"]["inputs"]
    assert set(d["status_codes"]) == {str(int(s)) for s in Status}
    assert d["status_codes"]["7"]["name"] == "orientation" and d["status_codes"]["5"]["meaning"]
    assert d["schema"] == SCHEMA and d["target_cpu"]["name"] in CPUS


def test_the_grabber_map_lists_its_motion_memory():
    """VB120-VB180, the profile tables, I0.0/I0.1, Q0.x, SMB67/SMB77 (an HMI tag there breaks
    the motion logic: the map must say they are taken); nothing is left unnamed."""
    d = _doc("s7-200")
    ranges = {m["range"]: m["use"] for m in d["memory"]}
    for need in (
        "VB120",
        "V121.0",
        "VW124",
        "VD128",
        "VD172",
        "VW180",
        "I0.0",
        "I0.1",
        "Q0.0",
        "Q0.7",
        "SMB67",
        "SMB77",
        "SMW168",
        "SM76.7",
        "AC0",
    ):
        assert need in ranges, need
    assert not [r for r, use in ranges.items() if use == "program-internal"]
    assert ranges["VB0-VB11"] == "inputs: px, py, pz" and ranges["VB200-VB291"].startswith("work:")
    assert ranges["LB0-LB43"].startswith("subroutine parameters")  # ATAN2: 11 REALs
    # no two ranges share a byte (every byte the program uses has one owner)
    spans = sorted(
        (m["area"], m["first"], m["last"])
        for m in d["memory"]
        if m["area"] != "AC" and "." not in m["range"]  # bits of one byte are listed apart
    )
    for (a1, _, l1), (a2, f2, _) in itertools.pairwise(spans):
        assert a1 != a2 or f2 > l1, (a1, l1, f2)


def test_the_startup_is_stated():
    d = _doc("s7-200")
    assert "not written" in d["startup"]["inputs"] and "not homed" in d["startup"]["motion"]
    d = _doc("s7-300", startup_target="paper")
    assert "OB100" in d["startup"]["inputs"] and "overwritten" in d["startup"]["inputs"]


def test_the_target_cpu_limits_are_checked_at_generation():
    """The GR-1 program uses M bytes up to MB351: an S7-300 CPU 314 has 256 (refused,
    naming the CPU and the limit); the CPU 315-2 DP (2048, awlsim's) takes it."""
    gr1 = gr1_arm()
    assert _doc("s7-300", arm=gr1)["memory"][-1]["last"] == 351
    with pytest.raises(ValueError, match=r"MB351, beyond the CPU 314's M memory \(MB0-MB255\)"):
        generate(gr1, "s7-300", cpu="CPU 314")
    with pytest.raises(ValueError, match="CPU 221"):
        MemoryMap(
            "s7-200", {"px": 2048, "py": 4, "pz": 8}, default_map("s7-200").outputs, 3000, "CPU 221"
        )
    with pytest.raises(ValueError, match=r"work_base 3000 .*CPU 221"):
        MemoryMap(
            "s7-200", {"px": 0, "py": 4, "pz": 8}, default_map("s7-200").outputs, 3000, "CPU 221"
        )
    big = MemoryMap(
        "s7-200",
        {"px": 6000, "py": 6004, "pz": 6008},
        {"c1": 6100, "c2": 6104, "c3": 6108, "reachable": (6112, 0), "status": 6116},
        6200,
    )
    text, mjson = generate(PAPER, "s7-200", mmap=big, motion=False)  # a CPU 224 has VB0-VB8191
    assert "VD6000" in text and json.loads(mjson)["inputs"]["px"] == "VD6000"
    assert MemoryMap.from_dict(json.loads(mjson)) == big


def test_maps_round_trip_and_old_maps_still_read():
    for arm in ("grabber", "palletizer"):
        for dialect in ("s7-200", "s7-300"):
            d = _doc(dialect, arm=load_arm(arm))
            assert MemoryMap.from_dict(d) == default_map(
                dialect, d["inputs"], 3 + (arm != "grabber")
            )
    old = {
        "dialect": "s7-300",
        "inputs": {"px": "MD0", "py": "MD4", "pz": "MD8"},
        "outputs": {"c1": "MD100", "c2": "MD104", "c3": "MD108", "reachable": "M112.0"},
    }
    assert MemoryMap.from_dict(old).cpu == "CPU 315-2 DP"


def test_an_interface_map_for_st_and_scl():
    """The ST/SCL/PLCopen emitters describe the block interface through map_document."""
    d = map_document(
        "st",
        inputs={"px": "IK.px", "py": "IK.py", "pz": "IK.pz"},
        outputs={"c1": "IK.c1", "reachable": "IK.reachable", "status": "IK.status"},
        units={"px": "mm", "py": "mm", "pz": "mm"},
        status_codes=[0, 1, 6],
        target_cpu={"name": "IEC 61131-3 runtime (CODESYS, TwinCAT, OpenPLC)"},
    )
    assert d["inputs"]["px"] == "IK.px" and d["signals"]["c1"]["type"] == "DINT"
    assert list(d["status_codes"]) == ["0", "1", "6"]
    with pytest.raises(ValueError, match="unit 'inch'"):
        map_document("st", inputs={"px": "IK.px"}, outputs={}, units={"px": "inch"})
    with pytest.raises(ValueError, match="status code 9"):
        map_document("st", inputs={}, outputs={}, units={}, status_codes=[9])
