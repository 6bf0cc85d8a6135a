"""What the GR-1 thesis's text says and the extraction leaves open: the claims the audit
checks, numbering slips of the print, what was lost and what cannot be decided."""

from __future__ import annotations

# --- claims in the text ----------------------------------------------------------------------
TEXT_CLAIMS: dict[str, dict] = {
    "c1.3-dh": {
        "location": "sec. 1.3 item 1, p. 4",
        "printed": "对机械手进行位姿描述,应用 D-H 参数法建立串联关节机器人杆件坐标系,求解位姿正解",
        "statement": "the thesis sets up the D-H link frames of the arm and solves its "
        "forward kinematics",
    },
    "c2.3.2-encoder": {
        "location": "sec. 2.3.2, p. 7",
        "printed": "码盘为 6 孔均匀分布的金属盘 ... 从 A、B 输出信号, 码盘每旋转一周发送 12 次信号",
        "statement": "6 holes, channels A and B: 12 signals per revolution of the motor",
    },
    "c2.3.4-sequential": {
        "location": "sec. 2.3.4 item 1 and Figure 2-1, p. 7-8",
        "printed": "程序启动后,各个电机按照程序要求逐个开始运动 ... 计数器计满数据后,PLC 输出控制"
        "指令,使 M1 停止转动,同时依次逐个启动控制电机 M2、M3、M4、M5 开始转动",
        "statement": "the motors run one after another, M1 to M5, each until its counter is full",
    },
    "c2.3.4-presets": {
        "location": "sec. 2.3.4 item 2, p. 8",
        "printed": "转动角度由计数器计数控制,计数器值满后断电使电机停止运转。各计数器的值由"
        "表 2-1 和轨迹规划的结果表 5-4 确定如表 2-3。",
        "statement": "each counter preset follows from the joint angle change (Table 5-4) "
        "and the resolution (Table 2-1)",
    },
    "c4.2-source": {
        "location": "sec. 4.2, p. 18",
        "printed": "参考同组同学论文逆向运动学部分可得如下结果",
        "statement": "the inverse kinematics is taken from a group-mate's thesis",
    },
    "c4.2-any-pose": {
        "location": "sec. 4.2, p. 19",
        "printed": "以上结果,给出了机械手置于任何期望位姿时所需的关节值,为下一章轨迹规划所用。",
        "statement": "the results give the joint values for any desired pose",
    },
    "c5.4.1-unique": {
        "location": "sec. 5.4.1, p. 22",
        "printed": "上面给出的四个约束条件可以惟一地确定一个三次多项式",
        "statement": "the four conditions 5.1-5.2 determine one cubic",
    },
    "c5.4.2-acc": {
        "location": "sec. 5.4.2, p. 23",
        "printed": "为了使实际生成的轨迹平滑,在机械手的整个工作期间,除了保证其运动和速度的连续之外,"
        "还应该保证加速度不发生突变,使运动平稳。根据已知条件和前文的讨论,选用三次多项式轨迹规划"
        "方法进行规划。",
        "statement": "besides continuous motion and velocity the acceleration must not jump; "
        "the cubic is chosen on that basis",
    },
    "c5.4.2-forward": {
        "location": "sec. 5.4.2, p. 23",
        "printed": "本文所研究的是五自由度机械手的正运动问题",
        "statement": "the problem studied is the forward motion problem of a 5-DOF arm",
    },
    "c6.2-buttons": {
        "location": "sec. 6.2, p. 25",
        "printed": "其中命令控制区有 5 个控件:计算、轨迹规划、输出、写入 PLC 和清除。",
        "statement": "five buttons: compute, trajectory, output, write to PLC, clear",
    },
    "c6.3-grey": {
        "location": "sec. 6.3 item 3, p. 26",
        "printed": "该控件在计算前,或在数据超出范围时呈现灰色,不能对其进行操作",
        "statement": "the trajectory button is grey before computing or when the data are "
        "out of range",
    },
    "c6.4-check": {
        "location": "sec. 6.4 item 1, p. 26",
        "printed": "按计算控件,对输入机械手起点和终点的位姿参数进行判断,当数据符合要求就会得出"
        "计算出并显示关节变量角数值,同时,轨迹控制控件回到可控状态",
        "statement": "the compute button checks the input poses and shows joint values only "
        "when they meet the requirements",
    },
    "c6.4-plc": {
        "location": "sec. 6.4 item 4, p. 27",
        "printed": "写入 PLC 控件的运行是将前一步输出的控制数据写入 PLC 计数器中",
        "statement": "the write-to-PLC button writes the control data into the PLC counters",
    },
}
"""Statements in the text that the audit checks, by id."""

STRUCTURE: list[dict] = [
    {
        "location": "heading before 3.4, p. 13",
        "printed": "3.3 点在空间直角坐标系中绕过原点任意轴的一般旋转变换",
        "note": "second section numbered 3.3 (after 3.3 空间齐次坐标变换)",
    },
    {
        "location": "sec. 3.4 heading, p. 15",
        "printed": "3.4 Denavt-Hartenberg(D-H)表示法",
        "note": "Denavit misspelt",
    },
    {
        "location": "sec. 3.4, p. 15",
        "printed": "如图 2.5 所示",
        "note": "no Figure 2.5 exists; the link-parameter figure is 图3-5",
    },
    {
        "location": "Figures 3-4, pp. 12 and 15",
        "printed": "图 3-4 平移变换与旋转变换 / 图 3-4 关节参数规定",
        "note": "two figures numbered 3-4",
    },
    {
        "location": "eqs. 3.3-3.4, p. 10",
        "printed": "(3.3) ... (3.3) (3.4)",
        "note": "eq. 3.3 is used twice, eq. 3.2 never",
    },
    {
        "location": "table of contents and appendices, pp. 31, 47",
        "printed": "附录错误!未找到引用源。程序清单",
        "note": "Word's 'Error! Reference source not found.' printed in the appendix headings",
    },
    {
        "location": "sec. 3.4.3, p. 17",
        "printed": "特别当 i=6 时,求得 T 矩阵,T ? A6",
        "note": "six links written for a five-joint arm (generic text)",
    },
    {
        "location": "table of contents vs chapter 6 heading",
        "printed": "第 6 章 系统交流界面设计 / 第 6 章 系统交互界面设计",
        "note": "different chapter titles",
    },
]
"""Numbering and cross-reference slips of the print (not used by the checks)."""

# --- what the extraction lost, and readings it leaves open -----------------------------------
LOST: dict[str, str] = {
    "sec. 4.1": "the forward-kinematics section has no body: no D-H table, frame figure or "
    "T matrix of the GR-1",
    "Table 2-1": "the grid: axis, motor code and resolution are matched by order only; the "
    "motor data (item 2) came out inside the table text",
    "sec. 2.1 item b": "the symbol after the waist's '≥' ('? 180': ± presumably) and the "
    "order of the three values printed after '肩: 肘: 手俯仰:'",
    "chapter 3 Greek letters": "every Greek letter of eqs. 3.5-3.19 and of the RPY "
    "definition is a '?' (names phi/theta/psi assumed)",
    "chapter 3 and 4 operators": "every +, -, = and bracket of eqs. 3.1-3.19 and of the "
    "section 4.2 results is a '?'",
    "eqs. 5.5-5.9": "bodies lost (numbers only): the coefficient system, its solution, the "
    "interpolation function, velocity and acceleration",
    "Table 5-3": "the three angle headers",
    "Table 5-4": "the body: ten numbers come out after the next paragraph; the header's "
    "joint order is scrambled",
    "Tables 5-1, 5-2": "grids (text only, scrambled)",
    "figures": "all drawings: Figs. 1-1, 3-1 to 3-5, 6-1 to 6-3 (GUI screenshots); "
    "Figure 2-1 (flow chart) survives as scattered labels without the C237 box",
    "ladder diagram": "contacts, coils and rung lines; only operand labels survive "
    "(LADDER_EXTRACTED)",
    "listing layout": "line breaks (restored, LISTING_RESTORATIONS) and indentation",
    "listing: buttons": "the 输出 (output) and 写入 PLC (write to PLC) handlers named in "
    "sec. 6.2 are not in the listing: no code path writes Table 2-3 to the PLC",
}
"""What the text extraction (or the print) does not contain, by location."""

UNCERTAIN: dict[str, str] = {
    "Table 5-4 cells": "see TABLE5_4['basis'] and ['uncertainty']: pair order from "
    "theta1 = atan(py/px), joint order from the listing",
    "Table 5-3 angle order": "the angle headers are lost; α, β, γ (RPY about z, y, x) in "
    "the listing's input order is assumed; the listing reproduces Table 5-4 with it",
    "listing cf3 operator": "'Py1 * Sin(θf1) Cos(θf234) * a4' has no operator between "
    "the terms: a syntax error as printed; whether the '-' was lost in the print or the "
    "extraction cannot be told (the extraction keeps every other '-' of the listing)",
    "sec. 4.2 signs": "every operator of the section 4.2 results is a '?'; EQUATIONS reads "
    "them as the listing's statements for the same quantities where the listing is "
    "self-consistent (c3), and as '-' before c234*a4 in s2, c2, theta2 where the listing "
    "has '+' (its theta2 and c3 disagree)",
    "sec. 4.2 second solutions": "theta' = theta ? 180: '+' read",
    "eq. 3.18 subscripts": "printed atan2(ox, nx) and atan2(ay, az) (for phi and psi) may "
    "carry subscripts displaced by the extraction; as extracted neither inverts eq. 3.15",
    "eq. 3.15 signs": "read from the column order of the extraction and the product 3.14",
    "joint ranges": "waist '≥ ? 180' (±180 read); the order 200, 270, 270 for shoulder, "
    "elbow, wrist pitch",
    "motor voltage": "'U = ? 12 V' (±12 V or 12 V)",
    "hand length": "'手后部:73mm' (rear part of the hand?) is used as a4 = 73 by the listing",
    "work area": "850 mm vertical and 600 mm horizontal: spans or radii is not said",
    "encoder counting": "12 signals per revolution come from two channels; a single-phase "
    "counter on one input (Table 2-2) sees one channel unless the interface circuit "
    "combines them (the circuit is in the group-mate's thesis)",
    "ladder Y114": "an operand 'Y114' on p. 34 where the pattern expects Y14",
    "displaced comments": "two copies of '将函数显示在图形上 sit after Picture3's y-axis Line "
    "and after block 5's End If (blocks 2 and 4 lack it after Print)",
}
"""Readings the text cannot decide, by item."""
