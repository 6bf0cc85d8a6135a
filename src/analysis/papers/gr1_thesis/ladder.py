"""The FX2N ladder diagram of the GR-1 thesis (appendix 程序清单 item 1, pp. 31-35) as far as
the extraction lets one read it."""

from __future__ import annotations

# --- the ladder diagram (appendix, pp. 31-35) ------------------------------------------------
LADDER_EXTRACTED: dict[int, str] = {
    31: "M8002 RST RST RST RST RST X20 Y40 Y40 Y40 M1 Y1 Y4 C235 Y0 C235 C236 C235 C235 C235 "
    "Y40 Y5 M11 M8235 Y0 Y5 C235 K1 Y3 C235 Y40 M2 C236 Y6 Y2 Y7",
    32: "M12 M8236 Y2 Y7 C236 K2 C236 M3 Y40 Y11 Y14 C237 Y10 Y15 M13 M8237 C237 K3 Y10 Y15 "
    "C237 Y40 Y13 Y16 C238 Y12 Y17 M14 M8238 Y12 Y17 C238 K4 C239 Y40 Y21 Y30 Y20 Y31 M15 "
    "M8239 Y20 Y31 C239 K5",
    33: "X20 Y40 Y40 Y40 M1 Y0 Y5 C235 Y40 Y1 Y4 M11 M8235 Y1 Y4 C235 K1 Y2 C235 Y40 M2 C236 "
    "Y7 Y3 Y6 M12 M8236 Y3 Y6 C236 K2 C236 M3 Y40 Y10 Y15 C237 Y11 Y14 M13 M8237",
    34: "Y11 Y114 C237 K3 C237 Y40 Y12 Y17 C238 Y13 Y16 M14 M8238 Y13 Y16 C238 K4 C239 Y40 "
    "Y20 Y31 Y21 Y30 M15 M8239 Y21 Y30 C239 K5 X21 Y41 Y41 X6 Y41 Y1 Y4",
    35: "X7 Y3 Y6 X10 Y11 Y14 X11 Y13 Y16 X12 Y20 Y31 END",
}
"""The ladder diagram ("1、机械手控制程序梯形图") as extracted, page by page: operand labels
in extraction order; every contact and coil symbol and every rung line is lost."""

LADDER: dict = {
    "location": "appendix 程序清单 item 1, pp. 31-35",
    "recoverable": {
        "first_scan_reset": "M8002 followed by five RST (the counters, presumably C235-C239)",
        "counters": {"C235": "K1", "C236": "K2", "C237": "K3", "C238": "K4", "C239": "K5"},
        "direction_relays": ["M8235", "M8236", "M8237", "M8238", "M8239"],
        "step_relays": {"M1": "C235", "M2": "C236", "M3": "C237"},
        "direction_bits": ["M11", "M12", "M13", "M14", "M15"],
        "motor_output_pairs": {
            "M1": [("Y0", "Y5"), ("Y1", "Y4")],
            "M2": [("Y2", "Y7"), ("Y3", "Y6")],
            "M3": [("Y10", "Y15"), ("Y11", "Y14")],
            "M4": [("Y12", "Y17"), ("Y13", "Y16")],
            "M5": [("Y20", "Y31"), ("Y21", "Y30")],
        },
        "two_programs": "pp. 31-32 and pp. 33-34 are the same sequence with each motor's "
        "output pair swapped (one direction each, presumably)",
        "manual_section": "X21 -> Y41; X6 -> Y1 Y4, X7 -> Y3 Y6, X10 -> Y11 Y14, "
        "X11 -> Y13 Y16, X12 -> Y20 Y31 (one input per motor, one direction only)",
        "other": ["X20", "Y40", "Y41", "END"],
    },
    "not_recoverable": [
        "contact types (normally open / closed), coils vs contacts, SET/RST targets",
        "rung boundaries, series/parallel structure, rung order",
        "which output pair turns a motor forward; what Y40 and Y41 drive",
        "how the step relays M4, M5 (never seen) or the sequence M1 -> M2 -> ... are set",
        "'Y114' on p. 34 (not a valid FX2N output in the series; Y14 with a stray digit?)",
    ],
    "presets_vs_table2_3": "the ladder's counter constants are K1..K5, not Table 2-3's "
    "4, 147, 118, 31, 16 (sec. 6.4 says the 写入 PLC button writes the data to the counters; "
    "that code is not in the listing)",
    "sequence_claim": "c2.3.4-sequential",
}
"""What the ladder diagram says as far as the extraction lets one read it."""
