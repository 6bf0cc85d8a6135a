"""Chapter 5 of the GR-1 thesis as printed: Tables 5-3 and 5-4 (section 5.4.2) and the cubic
trajectory (sections 5.4.1-5.4.2, eqs. 5.1-5.9)."""

from __future__ import annotations

# --- chapter 5 -----------------------------------------------------------------------------
TABLE5_3: dict = {
    "location": "Table 5-3 机械手起点、终点给定值, sec. 5.4.2, p. 23",
    "printed": "表 5-3 机械手起点、终点给定值 ? ? pz px py 控制点 ? 起点 151 231 250 32 45 60 "
    "终点 200 300 178 20 50 80",
    "columns": ["px", "py", "pz", "alpha", "beta", "gamma"],
    "rows": {"start": (151, 231, 250, 32, 45, 60), "end": (200, 300, 178, 20, 50, 80)},
    "units": "mm and degrees (not printed)",
    "listing_inputs": {
        "start": ("Text1", "Text2", "Text3", "Text4", "Text5", "Text6"),
        "end": ("Text7", "Text8", "Text9", "Text10", "Text11", "Text12"),
    },
    "note": "the three angle headers are lost ('?'); their order is taken as the "
    "listing's input order α, β, γ (RPY phi, theta, psi about z, y, x)",
}
"""Table 5-3: start and end poses (position mm, RPY angles deg)."""

TABLE5_4_EXTRACTED: dict = {
    "location": "Table 5-4 机械手起点、终点关节变量值, sec. 5.4.2, p. 23",
    "printed_header": "表 5-4 机械手起点、终点关节变量值 ?1 ?2 ?4 ?3 ?5 控制点 起点 终点",
    "numbers": (56.31, 56.828, 80.922, -66.006, -45.244, 73.282, -52.738, -83.861, -24.683, -9.074),
    "printed_numbers": "56.31 56.828 80.922 -66.006 -45.244 73.282 -52.738 -83.861 -24.683 -9.074",
    "where": "the ten numbers come out at the end of section 5.4.2, after the paragraph that "
    "follows the table, not inside the table",
}
"""Table 5-4 as extracted: a header with the joint names scrambled and ten loose numbers."""

TABLE5_4: dict = {
    "location": "Table 5-4, sec. 5.4.2, p. 23",
    "columns": ["theta1", "theta2", "theta3", "theta4", "theta5"],
    "rows": {
        "start": (56.828, -66.006, 73.282, -83.861, -9.074),
        "end": (56.31, 80.922, -45.244, -52.738, -24.683),
    },
    "units": "degrees",
    "assignment": "the extracted numbers read column by column, θ1 to θ5, the end value "
    "first in each pair: (end, start) = (56.31, 56.828), (80.922, -66.006), "
    "(-45.244, 73.282), (-52.738, -83.861), (-24.683, -9.074)",
    "basis": [
        "theta1 = atan(py/px) of Table 5-3 is 56.828 deg for the start (231/151) and 56.310 "
        "for the end (300/200): this fixes the pair order (end first) without the listing",
        "the listing's Command1_Click (Text13-17 start, Text18-22 end) reproduces all ten "
        "numbers in this assignment to the printed three decimals (tests/audit/test_vb6.py)",
        'Format(x, "####.###") drops trailing zeros: 56.310 prints as 56.31, as extracted',
    ],
    "uncertainty": "the printed table's own column order cannot be read (the extraction "
    "gives θ1 θ2 θ4 θ3 θ5); row-major readings fail the theta1 check (56.828 would be a "
    "theta2). The assignment rests on theta1 for the pair order and on the listing for "
    "the joint order.",
}
"""Table 5-4 with each extracted number assigned to a cell (see ``basis``/``uncertainty``)."""

CUBIC: dict = {
    "location": "sec. 5.4.1-5.4.2, eqs. 5.1-5.9, pp. 22-23",
    "equations": ["5.1a", "5.1b", "5.2a", "5.2b", "5.3", "5.4a", "5.4b"],
    "lost": {
        "5.5": "the system for a0..a3 (only its number survives)",
        "5.6": "its solution (only the number)",
        "5.7": "the interpolation function (text: 满足连续平稳运动要求的三次多项式插值函数为 ...)",
        "5.8": "velocity (named in the text, body lost)",
        "5.9": "acceleration (named in the text, body lost)",
    },
    "listing_form": {
        "location": "appendix listing, Command3_Click, each joint block",
        "printed": "Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * "
        "(X * X * X)",
        "reading": "theta(t) = theta_0 + 3/t_f**2*(theta_f - theta_0)*t**2 "
        "- 2/t_f**3*(theta_f - theta_0)*t**3",
    },
    "duration_s": 10,
    "duration_location": "listing only: 'c = 10' and 'For X = 0 To 10 Step 0.001' "
    "(the text gives no duration)",
    "claim": "c5.4.2-acc",
}
