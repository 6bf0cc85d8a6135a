"""Chapter 2 of the GR-1 thesis as printed: the arm (section 2.1, Table 2-1), the motors and
encoders (sections 2.1, 2.3.2), the PLC and its counters (sections 2.3.1-2.3.4, Tables 2-2,
2-3)."""

from __future__ import annotations

# --- section 2.1: the arm, the motors, Table 2-1 ---------------------------------------------
ARM: dict[str, dict] = {
    "dof": {
        "location": "sec. 2.1 item a, p. 5",
        "printed": "a、自由度:5(不包括手指开闭控制)",
        "value": 5,
        "note": "five joints, the gripper's open/close not counted",
    },
    "joint_ranges": {
        "location": "sec. 2.1 item b, p. 5",
        "printed": "b、各关节活动范围: 腰: ≥ ? 180 肩: 肘: 手俯仰: ≥ 200 ≥270。 ≥ 270 "
        "手指旋转:≥ 360",
        "reading_deg": {
            "腰 (waist)": "≥ ±180 (symbol lost)",
            "肩 (shoulder)": 200,
            "肘 (elbow)": 270,
            "手俯仰 (wrist pitch)": 270,
            "手指旋转 (finger roll)": 360,
        },
        "note": "ranges (spans), not limits: no zero positions are printed; the order of "
        "the three values after 肩: 肘: 手俯仰: is the extraction's (see UNCERTAIN)",
    },
    "work_area": {
        "location": "sec. 2.1 item c, p. 5",
        "printed": "c、最大活动区域: 垂直方向:850mm 水平方向:600mm",
        "vertical_mm": 850,
        "horizontal_mm": 600,
        "note": "whether these are spans or radii is not said",
    },
    "dimensions": {
        "location": "sec. 2.1 item d, p. 5",
        "printed": "d、基本尺寸: 上、下臂长:228mm 手后部:73mm",
        "upper_arm_mm": 228,
        "lower_arm_mm": 228,
        "hand_mm": 73,
        "note": "the listing uses a2 = 228, a3 = 228, a4 = 73; no base height is printed",
    },
    "joints": {
        "location": "sec. 2.2, p. 6",
        "printed": "整个机械手分 5 个自由度:腰、肩关节、肘关节、腕关节和手指,全部有直流电机驱动",
        "order": ["腰 waist", "肩 shoulder", "肘 elbow", "腕 wrist", "手指 finger"],
    },
}
"""Section 2.1 item by item (dimensions, ranges, work area) and section 2.2's joint list."""

MOTOR: dict = {
    "location": "sec. 2.1 item 2 (printed inside the Table 2-1 text), p. 5",
    "printed": "2 电机 工作电压:U = ? 12 V 空载转速:n = 3000 r/min 空载电流:I = 0.15 A",
    "voltage_V": 12,
    "voltage_sign": "lost ('?': ± or =)",
    "no_load_speed_rpm": 3000,
    "no_load_current_A": 0.15,
    "kind": "DC motor (sec. 2.2: 全部有直流电机驱动)",
}
"""Motor data of section 2.1."""

TABLE2_1: dict = {
    "location": "Table 2-1 各轴分辨率参数, sec. 2.1 item e, p. 5",
    "printed": "表 2-1 各轴分辨率参数 轴 躯干 上臂 下臂 手俯仰 手指旋转 ... 电机代号 M1 M2 M3 "
    "M4 M5 分辨率(度/脉冲) 0.14 0.11 0.11 0.11 0.24",
    "columns": ["axis", "motor", "resolution_deg_per_pulse"],
    "rows": [
        ("躯干 torso (waist)", "M1", 0.14),
        ("上臂 upper arm", "M2", 0.11),
        ("下臂 lower arm", "M3", 0.11),
        ("手俯仰 wrist pitch", "M4", 0.11),
        ("手指旋转 finger roll", "M5", 0.24),
    ],
    "note": "rows matched by order (the table grid is lost); joint k is driven by motor Mk",
}
"""Table 2-1: per-axis resolution in degrees per encoder pulse."""

ENCODER: dict = {
    "location": "sec. 2.3.2, p. 6-7",
    "printed": "光电编码器输出包括 A、B 两个频道的信号,码盘为 6 孔均匀分布的金属盘 ... "
    "码盘每旋转一周发送 12 次信号",
    "holes": 6,
    "channels": ["A", "B"],
    "signals_per_rev": 12,
    "mounting": "每个直流电机输出轴上都装有光电编码器 (on every motor's output shaft)",
}
"""The incremental encoder of section 2.3.2."""

PLC: dict = {
    "model": {
        "location": "sec. 2.3.1, p. 6",
        "printed": "最后选定用三菱公司生产的 FX2N—64MR 型 PLC",
        "value": "Mitsubishi FX2N-64MR",
    },
    "sizing_rule": {
        "location": "sec. 2.3.1, p. 6",
        "printed": "指令条数=(输入点数+输出点数) ? (10--12) 再留有 15%左右的备用量",
        "reading": "instructions = (inputs + outputs) x (10..12), plus about 15 % spare",
    },
    "high_speed_counters": {
        "location": "sec. 2.3.3, p. 7",
        "printed": "FX2N—64MR 提供 21 个高速计数器,即 C235 至 C255,但它们共享同一个 PLC 上的 "
        "6 个高速计数器输入端(X0~X5) ... 最多同时用 6 个高速计数器。在本文中将用到的是没有"
        "启动/复位的单相高速计数器 C235~C239。",
        "counters": 21,
        "first": "C235",
        "last": "C255",
        "inputs": ["X0", "X1", "X2", "X3", "X4", "X5"],
        "used": ["C235", "C236", "C237", "C238", "C239"],
    },
    "outputs_per_motor": {
        "location": "sec. 2.3.3 item 2, p. 7",
        "printed": "由于五个电机都要实现正反转,即能实现正反向供电,每个电机分配 4 个输出端口",
        "value": 4,
    },
}
"""PLC facts of sections 2.3.1-2.3.3."""

TABLE2_2: dict = {
    "location": "Table 2-2 高计数器表, sec. 2.3.3, p. 7",
    "printed": "表 2-2 高计数器表 输入 C235 C236 C237 C238 C239 X0 U/D X1 U/D X2 U/D X3 U/D "
    "X4 U/D 注:U—增计数输入;D—减计数输入。",
    "inputs": {"C235": "X0", "C236": "X1", "C237": "X2", "C238": "X3", "C239": "X4"},
    "mode": "U/D (up/down) for each",
}
"""Table 2-2: high-speed counter to input assignment."""

TABLE2_3: dict = {
    "location": "Table 2-3 各计数器数值, sec. 2.3.4, p. 8",
    "printed": "表 2-3 各计数器数值 计数器 数值 ... C235 4 C236 147 C237 118 C238 31 C239 16",
    "presets": {"C235": 4, "C236": 147, "C237": 118, "C238": 31, "C239": 16},
    "derivation_printed": "各计数器的值由表 2-1 和轨迹规划的结果表 5-4 确定如表 2-3",
    "counter_of_joint": {1: "C235", 2: "C236", 3: "C237", 4: "C238", 5: "C239"},
    "note": "counter k counts motor Mk's encoder (Figure 2-1: C235 腰部, C236 上臂, "
    "C238 手腕, C239 手指; the C237 box is lost)",
}
"""Table 2-3: counter presets, said to follow from Table 2-1 and Table 5-4."""
