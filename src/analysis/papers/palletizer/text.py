"""Seed 001's running text as printed: the statements the audit checks, the sections, the
references, what the extraction lost and the readings it leaves open."""

from __future__ import annotations

# --- statements in running text ---------------------------------------------------------------
CLAIMS: dict[str, dict] = {
    "isosceles": {
        "extracted": [
            "已知目標(biāo)點(diǎn)、大臂、小臂參數(shù),那么一定可以構(gòu)成如圖3中紅色虛線部分所示的等腰三角形",
            "至此,圖3中的等腰三角形三邊長(zhǎng)均已知",
        ],
        "location": "sec. 3, before eq. 1 and after eq. 2",
        "printed": "已知目標點、大臂、小臂參數,那麼一定可以構成如圖3中紅色虛線部分所示的等腰三角形"
        " ... 至此,圖3中的等腰三角形三邊長均已知",
        "meaning": "given the target and the arm lengths, the red dashed triangle of Figure 3 "
        "(sides L1', L2', L4') can always be formed and is isosceles",
    },
    "unique_pose": {
        "extracted": [
            "械結(jié)構(gòu)的限制,小臂和大臂之間的夾角小于900,所以其抓取時(shí)的位置狀態(tài)是唯一的"
        ],
        "location": "sec. 2, third paragraph",
        "printed": "因為機械結構的限制,小臂和大臂之間的夾角小於900,所以其抓取時的位置狀態是唯一的",
        "meaning": "the angle between forearm and upper arm is below 90° (printed '900', the "
        "degree sign extracted as 0), therefore the grasping pose is unique",
        "limit_deg": 90.0,
    },
    "fk_equals_target": {
        "extracted": [
            "編碼測(cè)試[9],基于幾何法的碼垛機(jī)械臂逆向求解方法得出的角度帶入D-H正向解算公式的結(jié)果完全等于待抓取點(diǎn)Gi"
        ],
        "location": "sec. 5, last paragraph",
        "printed": "基於幾何法的碼垛機械臂逆向求解方法得出的角度帶入D-H正向解算公式的"
        "結果完全等於待抓取點Gi",
        "meaning": "eq. 11 evaluated at the eq. 12 angles of the IK (eqs. 1-6) equals the "
        "target G_i exactly, for all four targets",
    },
    "targets_in_metres": {
        "extracted": ["表中Gi和Ti的單位為米(m),角度單位為度"],
        "location": "sec. 5, second paragraph",
        "printed": "表中Gi和Ti的單位為米(m),角度單位為度",
        "meaning": "Tables 2-3 give G_i and T_i in metres, angles in degrees",
        "unit": "m",
    },
    "four_quadrants": {
        "extracted": [
            "在Z軸正方向所在的空間分別選擇了四個(gè)待抓取目標(biāo)點(diǎn),分別所處四個(gè)不同象限"
        ],
        "location": "sec. 5, second paragraph",
        "printed": "在Z軸正方向所在的空間分別選擇了四個待抓取目標點,分別所處四個不同象限",
        "meaning": "four targets with Z > 0, one in each quadrant of the XOY plane",
        "n_targets": 4,
    },
    "quadrant_rule": {
        "extracted": [
            "G投影位于一、二象限時(shí),電機(jī)M1為向左正轉(zhuǎn),反之三、四象限為反轉(zhuǎn)"
        ],
        "location": "sec. 3, before eq. 6",
        "printed": "當G投影位於一、二象限時,電機M1為向左正轉,反之三、四象限為反轉",
        "meaning": "gamma > 0 (M1 turns left) in quadrants 1-2, gamma < 0 in quadrants 3-4",
    },
    "sign_conventions": {
        "extracted": [
            "γ>0表示M1左轉(zhuǎn);α>0表示M2繞坐標(biāo)軸+Y2順時(shí)針旋轉(zhuǎn)、β>0表示M3繞坐標(biāo)軸+Y3旋轉(zhuǎn)順時(shí)針旋轉(zhuǎn);θ>0表示M4繞坐標(biāo)+Y4軸旋轉(zhuǎn)"
        ],
        "location": "sec. 3, second paragraph",
        "printed": "γ>0表示M1左轉;α>0表示M2繞坐標軸+Y2順時針旋轉、"
        "β>0表示M3繞坐標軸+Y3旋轉順時針旋轉;θ>0表示M4繞坐標+Y4軸旋轉。",
        "meaning": "alpha and beta are both clockwise about +Y2, +Y3 (axes drawn in the lost "
        "Figure 2); theta's sense about +Y4 is not stated",
    },
    "initial_pose": {
        "extracted": ["位于初始位置時(shí),大臂與基座保持垂直,小臂與大臂保持垂直"],
        "location": "sec. 3, second paragraph",
        "printed": "機械臂位於初始位置時,大臂與基座保持垂直,小臂與大臂保持垂直",
        "meaning": "at the initial pose (all motor angles 0) the upper arm is vertical and the "
        "forearm perpendicular to it",
    },
    "gripper_level": {
        "extracted": [
            "末端抓手始終與基座所處的平面保持平行",
            "X5和X4軸之間的方向永遠(yuǎn)保持不變,即:θ5=0",
        ],
        "location": "sec. 3 (assumptions) and sec. 4.2 (before 4_5T)",
        "printed": "末端抓手始終與基座所處的平面保持平行 ... "
        "X5和X4軸之間的方向永遠保持不變,即:θ5=0",
        "meaning": "the gripper stays parallel to the base plane; theta5 = 0",
    },
    "gripper_geometry": {
        "extracted": [
            "大臂、小臂、末端夾具的長(zhǎng)度分別為:L1、L2、L3",
            "末端夾具的垂直高度是h",
        ],
        "location": "sec. 2 and sec. 3",
        "printed": "大臂、小臂、末端夾具的長度分別為:L1、L2、L3 ... 末端夾具的垂直高度是h",
        "meaning": "L1, L2, L3 are the lengths of upper arm, forearm and gripper; h is the "
        "vertical height of the L-shaped gripper",
    },
    "shoulder_at_origin": {
        "extracted": ["上述坐標(biāo)系0、1、2的坐標(biāo)原點(diǎn)重合,故L0=0"],
        "location": "sec. 4.1",
        "printed": "上述坐標系0、1、2的坐標原點重合,故L0=0",
        "meaning": "frames 0, 1, 2 share their origin: the shoulder is at the base origin",
    },
    "xref_section": {
        "extracted": ["第2節(jié)中的逆向解算方法求出的角度(γ、α、β、θ)"],
        "location": "sec. 5, third paragraph",
        "printed": "第2節中的逆向解算方法求出的角度(γ、α、β、θ)",
        "refers_to_section": 2,
        "meaning": "the angles come from the IK method of section 2",
    },
    "xref_reference": {
        "extracted": ["參照第5篇文獻(xiàn)簡(jiǎn)述的方法[6]"],
        "location": "sec. 4.1",
        "printed": "參照第5篇文獻簡述的方法[6]",
        "refers_to_reference": (5, 6),
        "meaning": "the method of 'the 5th reference', cited as [6]",
    },
    "eq12_purpose": {
        "extracted": [
            "在帶入式(11)時(shí),需要結(jié)合D-H參數(shù)法中θi的幾何意義對(duì)其轉(zhuǎn)換"
        ],
        "location": "sec. 5, before eq. 12",
        "printed": "在帶入式(11)時,需要結合D-H參數法中θi的幾何意義對其轉換",
        "meaning": "eq. 12 converts the motor angles (gamma, alpha, beta, theta) to D-H theta_i",
    },
}
"""Checkable claims of the running text: ``extracted`` holds the verbatim runs of the seed
(which carries pinyin readings in parentheses after some characters, e.g. 目標(biāo), and
mis-decoded characters such as 因?yàn)闄C for 因為機); ``printed`` is the same text read
without those artefacts; ``meaning`` is ours."""

SECTIONS: dict[int, str] = {
    1: "引言 (Introduction)",
    2: "機械臂模型的簡化 (Simplified Robotic Arm Model)",
    3: "逆向運動學解算 (Inverse kinematics Solution)",
    4: "正向運動學解算 (Forward kinematics Solution)",
    5: "數值算例 (Numerical Verification)",
    6: "結論 (Conclusion)",
}
"""Section headings as printed (numbers and titles; the extraction keeps them)."""

REFERENCES: dict[int, dict[str, str]] = {
    1: {
        "printed": "《中國機器人產業發展報告2019》發布. 傳感器世界, 2019",
        "topic": "industry report",
    },
    2: {
        "printed": "Hartenburg R.S., Denavit J., Freudenstein F. Kinematic Synthesis of Linkages. "
        "Journal of Applied Mechanics, 1965",
        "topic": "D-H method",
    },
    3: {
        "printed": "冷舒, 吳克, 居鶴華. 機械臂運動學建模及解算方法綜述. 宇航學報, 2019",
        "topic": "survey",
    },
    4: {
        "printed": "趙毓, 管公順, 郭繼峰, 等. 基於多智能體強化學習的空間機械臂軌跡規劃. 航空學報",
        "topic": "reinforcement learning",
    },
    5: {
        "printed": "馮晨旭, 胡三寶. 基於改進天牛須搜索的機械臂運動學逆解. 武漢大學學報(工學版)",
        "topic": "search method (beetle antennae)",
    },
    6: {
        "printed": "Tony Owen. Introduction to Robotics. Robotica, 1991, 9(4)",
        "topic": "D-H method",
    },
    7: {
        "printed": "朱訓棟, 徐海港, 趙棟杰. 碼垛機械臂運動學位置正逆解分析. 農業工程, 2017",
        "topic": "palletizer kinematics",
    },
    8: {
        "printed": "彭光宇, 董洪波, 馬斌. 兩種DH模型的機器人運動學建模對比研究. "
        "機械研究與應用, 2019",
        "topic": "modified D-H",
    },
    9: {
        "printed": "潘磊, 錢煒, 張志艷, 等. 四自由度機械臂運動學分析及Matlab仿真. "
        "機械科學與技術, 2013",
        "topic": "4-DOF arm kinematics",
    },
}
"""The reference list as printed (without the extraction's pinyin artefacts), with a topic
tag of ours: what each cited work is about (for the cross-reference checks)."""

LOST: dict[str, str] = {
    "Table 1": "the D-H parameter table (sec. 4.1, '如下表1'): body lost. The five printed "
    "matrices of sec. 4.2 imply alpha_{i-1} = 0, -90, 0, 0, 90 deg, a_{i-1} = 0, 0, L1, L2, h, "
    "d_i = 0, 0, 0, 0, L3 (theta5 = 0); the table's own values are not in the extraction.",
    "Table 2": "(gamma, alpha, beta, theta) for the four targets G1..G4 [deg]: body lost.",
    "Table 3": "theta1..theta4 by eq. 12 and the FK results T1..T4 [m]: body lost.",
    "targets": "the four targets G_i [m] (one per quadrant, Z > 0) appear only in the lost "
    "Tables 2-3.",
    "lengths": "L1, L2, L3 and h are never printed as numbers anywhere in the text.",
    "Figure 1": "photograph/drawing of the palletizer with motors M1..M4: image lost.",
    "Figure 2": "the simplified 3D model with the axes Y2, Y3, Y4 of the sign conventions and "
    "the point G: image lost.",
    "Figure 3": "the coplanar red triangle (L1', L2', L4') and H: image lost.",
    "Figure 4": "the quadrants and gamma: image lost.",
    "Figure 5": "the D-H frames at the pose of eq. 7: image lost.",
    "Figure 6": "not referred to in the text; image lost.",
    "Figure 7": "the aluminium arm with stepper motors near a target (sec. 5): image lost.",
    "sec. 4.1 steps": "'其步驟如下:' (the steps follow) is followed by nothing.",
}
"""What the extraction lost, by item."""

UNCERTAIN: dict[str, str] = {
    "eq. 2 grouping": "radicals and parentheses are inferred; the literal run "
    "X0²+Y0²-L3'²+Z0+h² mixes mm² and mm.",
    "eq. 3 H": "H is never defined. Read as the vertical leg Z0 + h of the red triangle "
    "(eq. 2) it makes alpha2 the elevation of the shoulder-wrist line; read as a depth below "
    "the shoulder (if Figure 3 drew the target low) it is -(Z0 + h). The two readings change "
    "the sign of alpha2 in eq. 4.",
    "eq. 3 beta1": "printed without arccos (the same run keeps arccos for alpha1), so the print "
    "probably omitted it; it could also be the extraction's loss.",
    "eq. 1 arctan": "arctan(Y0/X0) may mean the signed arctangent or the acute angle "
    "arctan|Y0/X0| of Figure 4; eq. 6 is checked under both.",
    "eq. 6 -π/2": "'-π2+γ'' is read as -π/2 + γ' as 'π2' is π/2 in eqs. 4 and 12; -π + γ' "
    "would be a different (also partial) rule.",
    "eq. 7 split": "the flattened vector '0-π2π2π20' is split as 0, -π/2, π/2, π/2, 0.",
    "eq. 8 glyph": "'sinai-1', 'cosai-1' print the length a_{i-1} where the twist "
    "alpha_{i-1} belongs, while 'cosαi-1' in the same run shows that α can be extracted; a "
    "misprint is likely but a font-mapping loss cannot be excluded.",
    "eq. 11 parentheses": "restored by analogy across rows; the run is consistent in "
    "'s4h-s4L3' (all three rows) and in the row labels 't14, t34, t34'.",
    "eq. 12 parentheses": "θ4 = π/2 - θ2 + θ3 as extracted; π/2 - (θ2 + θ3) would differ only "
    "by lost parentheses.",
    "sec. 2 '900'": "read as 90° (degree sign extracted as 0).",
    "sec. 2 'r弧度'": "'當基座電機(M1)旋轉r弧度後': r is presumably γ (a lost glyph).",
    "sec. 2 point G": "'目標點G在基座平面的投影為點G': the projection carries the same name as "
    "G (a prime G' was probably lost).",
    "axes Y2, Y3, Y4": "drawn in the lost Figure 2: whether +Y2 and +Y3 point the same way (so "
    "that 'clockwise' means the same sense for alpha and beta) cannot be read from the text.",
}
"""What the text extraction leaves undecidable, by item."""
