"""Seed 002 as printed: Yang Hanjiang, Li Lijun, Gao Zicheng (2016), *Forward kinematics
analysis and experiment of hybrid harvesting robot based on screw theory* (Transactions of
the CSAE 32(9): 53-59): a 2P4R camellia-fruit picker, product of exponentials (POE).

Data only: what survives of the paper in the text extraction, as close to the print as a
machine-readable form allows; nothing here is corrected or inferred without saying so (the
reconstruction of the mechanism is :mod:`analysis.kinematics.picker`, the checks are
:mod:`analysis.audit.picker_checks`). Imports only the standard library and SymPy.

Source: the seed's text extraction (:data:`SOURCE`, kept outside the repository). It kept
the running text (with pinyin readings in parentheses after some characters, e.g.
聯(lián)) and lost every displayed equation (eqs. 1-22: no body survives, not even
the numbers, which are counted from the text's lead-ins, :data:`EQUATION_NUMBERS`), Table 1
(dimensions), Table 2 (errors) and Figures 1-4. :data:`EXTRACTED` holds the verbatim runs
each item rests on.
"""

from __future__ import annotations

import sympy as sp

__all__ = [
    "CHAINS",
    "CLAIMS",
    "CROSS_REFERENCES",
    "DIMENSIONS",
    "EQUATION_NUMBERS",
    "EXPERIMENT",
    "EXTRACTED",
    "JOINTS",
    "LOST",
    "SOURCE",
    "TOPOLOGY",
    "UNCERTAIN",
    "joint_law",
]

SOURCE = "002_9c33c7a2088bff5e.txt"
"""The text extraction this module transcribes (outside the repository, read-only)."""

EXTRACTED: dict[str, tuple[str, ...]] = {
    "dof": ("2P4R6自由度混聯(lián)采摘機(jī)器人機(jī)械臂的三維模型",),
    "components": (
        "該機(jī)器人主要由腰部、手臂、腕部組成。腰部基座1為整個(gè)機(jī)器人的基礎(chǔ)部"
        "分,與手臂結(jié)構(gòu)通過(guò)旋轉(zhuǎn)關(guān)節(jié)連接,可驅(qū)動(dòng)除"
        "腰部以外的其余部分繞腰部關(guān)節(jié)旋轉(zhuǎn);手臂部分主要包括旋轉(zhuǎn)座2"
        "、前臂4、后臂7、后小臂8、下小臂10、上小臂11、三角形連接件9,旋轉(zhuǎn)座為整個(gè)"
        "手臂提供支撐,上面安裝有水平滑塊3和豎直滑塊6,其中水平滑塊與前臂下端通過(guò)鉸鏈連"
        "接,豎直滑塊與后臂下端通過(guò)鉸鏈連接,下小臂和上小臂的末端與腕部基座12鉸接;腕部則"
        "由3個(gè)串聯(lián)的旋轉(zhuǎn)關(guān)節(jié)組成",
    ),
    "parallelogram": (
        "手臂結(jié)構(gòu)中前臂和后臂下端通過(guò)主臂連桿5連接,前臂與后臂相互平行,主臂連"
        "桿與下小臂相互平行,四者構(gòu)成一個(gè)平行四邊形機(jī)構",
    ),
    "amplification": (
        "不僅增加了手臂結(jié)構(gòu)部分的剛度,而且可以通過(guò)較小的驅(qū)動(dòng)行程獲"
        "得末端執(zhí)行器較大的工作行程",
    ),
    "wrist_dof": ("這樣設(shè)計(jì)使得機(jī)器人腕部減少了2個(gè)自由度",),
    "chains": (
        "從腰部旋轉(zhuǎn)座到腕部基座bFF′的構(gòu)件組成了機(jī)械臂的手臂(并聯(lián)結(ji"
        "é)構(gòu)部分),腰部旋轉(zhuǎn)座為該并聯(lián)結(jié)構(gòu)的旋轉(zhuǎn)座、腕部"
        "基座bFF′為動(dòng)平臺(tái)[19],豎直滑塊、后臂lAD、下小臂lDF和水平滑塊、后小臂lC′E"
        "″、三角形連接件bEE′E″、上小臂lE′F′分別組成了并聯(lián)結(jié)構(gòu)的2條串聯(lián"
        ")運(yùn)動(dòng)鏈。本文中選擇垂直導(dǎo)軌滑塊所在的運(yùn)動(dòng)鏈為主運(yùn)"
        "動(dòng)鏈,水平導(dǎo)軌滑塊所在的運(yùn)動(dòng)鏈為副運(yùn)動(dòng)鏈",
    ),
    "reference_pose": ("圖3所示的機(jī)器人位形為θi=0時(shí)的參考位形",),
    "active_passive": (
        "水平滑塊和豎直滑塊為機(jī)械臂中并聯(lián)結(jié)構(gòu)中的主動(dòng)件,即β=[θ2,θ"
        "9]T為主動(dòng)關(guān)節(jié),α=[θ3,θ4,θ5,θ10,θ11,θ12,θ13]T為被動(dòng)關(guān)節",
    ),
    "mapping": (
        "當(dāng)給定主動(dòng)關(guān)節(jié)位置β時(shí),即可解出α。那么被動(dòng)關(guān"
        ")節(jié)旋轉(zhuǎn)角度θ3、θ5與主動(dòng)關(guān)節(jié)之間的映射關(guān)系為",
    ),
    "slider_variables": (
        "式中x為水平滑塊的位移量,在圖3中所對(duì)應(yīng)的運(yùn)動(dòng)旋量坐標(biāo)為ξ"
        "9,mm;z為豎直滑塊的位移量,在圖3中所對(duì)應(yīng)的運(yùn)動(dòng)旋量坐標(biāo)為"
        "ξ2,mm",
    ),
    "dimension_a": ("式中a為圖3中A、B之間的距離,mm;其余同理",),
    "dimension_f": ("式中f為圖3中鉸接點(diǎn)F與運(yùn)動(dòng)旋量ξ6之間的距離,mm;其余同理",),
    "xref_eq7_eq8": (
        "由式(8)可求解機(jī)器人水平滑塊、豎直滑塊的運(yùn)動(dòng)旋量坐標(biāo),由式(7)可"
        "求得其余關(guān)節(jié)的運(yùn)動(dòng)旋量坐標",
    ),
    "xref_eq9": ("由式(9)可求得主動(dòng)鏈中尚未求解的各關(guān)節(jié)運(yùn)動(dòng)旋量坐標",),
    "main_is_active_chain": ("由于選擇垂直滑塊所在的運(yùn)動(dòng)鏈為主動(dòng)鏈",),
    "xref_eq18": ("獲得了混聯(lián)采摘機(jī)器人機(jī)械臂運(yùn)動(dòng)學(xué)正解方程(18)",),
    "xref_eq15_16": (
        "將主運(yùn)動(dòng)鏈關(guān)節(jié)與主動(dòng)關(guān)節(jié)映射關(guān)系式(15"
        ")、式(16)",
    ),
    "xref_eq22": ("代入到機(jī)械臂運(yùn)動(dòng)學(xué)正解方程(22)中",),
    "base_frame": (
        "采摘機(jī)器人以腰部旋轉(zhuǎn)基座的中心軸線為基礎(chǔ)坐標(biāo)系S的Z軸,以機(jī"
        ")器人腰部旋轉(zhuǎn)基座的底面為XOY平面",
    ),
    "instrument": (
        "基礎(chǔ)坐標(biāo)系S′在采摘機(jī)器人基礎(chǔ)坐標(biāo)系S中的位置坐標(biāo)為("
        "1 500,0,0),其各坐標(biāo)軸方向與S系一致",
    ),
    "joint_laws": (
        "設(shè)定ω1=-5t,ω6=10t,ω7=-10t,ω8=-10t,νx=15t,νz=20t,其中ωi為第i個(gè)關(guān)節(j"
        "ié)的角速度,rad/s;νx為水平滑塊速度,mm/s;νz為豎直滑塊移動(dòng)速度,mm/s;t為時(shí)"
        "間變量,s",
    ),
    "samples": ("選取1、2、3、4、5 s時(shí)的5組關(guān)節(jié)變量值",),
    "max_error": ("末端執(zhí)行器在X、Y、Z軸上的最大絕對(duì)位置誤差為10.4 mm",),
    "proof_by_opening": (
        "其10.4 mm的末端執(zhí)行器最大絕對(duì)位置誤差遠(yuǎn)小于200 mm的最大開(kāi)度,"
        "滿足該機(jī)器人末端執(zhí)行器夾持樹(shù)干的作業(yè)要求,證明了本文所提出的基于"
        "旋量理論的混聯(lián)機(jī)器人運(yùn)動(dòng)學(xué)分析方法的可行性和正確性",
    ),
    "abstract_random": (
        "隨機(jī)選取5組關(guān)節(jié)變量值,得出末端執(zhí)行器在基礎(chǔ)坐標(biāo)系各"
        "坐標(biāo)軸上的最大絕對(duì)位置誤差為10.4 mm,遠(yuǎn)小于末端執(zhí)行器200 mm的"
        "開(kāi)度,滿足該機(jī)器人末端執(zhí)行器的采摘工作要求,驗(yàn)證了通過(guò)文中所"
        "提出的方法建立混聯(lián)采摘機(jī)器人運(yùn)動(dòng)學(xué)正解方程的可行性及方程"
        "的正確性",
    ),
    "conclusion_3": (
        "利用該方程和機(jī)器人運(yùn)動(dòng)學(xué)試驗(yàn)平臺(tái)分析得到末端工具坐標"
        "(biāo)系位置理論值和實(shí)際值之間最大絕對(duì)誤差為10.4 mm,遠(yuǎn)小于末端執(z"
        "hí)行器200 mm的開(kāi)度,滿足末端執(zhí)行器的夾持要求。由此驗(yàn)證了本文所提出"
        "方法對(duì)構(gòu)建混聯(lián)采摘機(jī)器人運(yùn)動(dòng)學(xué)正解方程的可行性"
        "及正確性",
    ),
    "discussion_error_large": (
        "試驗(yàn)得到的機(jī)器人末端執(zhí)行器的位置絕對(duì)誤差最大為10.4 mm,雖然滿足"
        "機(jī)器人末端執(zhí)行器對(duì)于夾取樹(shù)干的要求,但是誤差絕對(duì)值較大,會(h"
        "uì)造成對(duì)機(jī)器人其他系統(tǒng)(如視覺(jué)識(shí)別系統(tǒng))提出較高的精"
        "度要求",
    ),
    "r3_group": ("R3是以3維列向量作為單位元素的群",),
    "table1_caption": (
        "表1 機(jī)械臂結(jié)構(gòu)參數(shù)Table 1 Structure parameters of manipulator",
    ),
    "table2_caption": ("表2 末端執(zhí)行器位置誤差Table 2 Position error of end effector",),
    "english_closed_chain": (
        "thirdly, the position of the end effector was got from the kinematics analysis of "
        "the closed chain by using the Lie group, Lie algebra, screw theory and product-of-"
        "exponential formula",
    ),
}
"""Verbatim runs of the seed, by item (long runs split across string literals)."""

# --- section 2: the mechanism -------------------------------------------------------------
TOPOLOGY: dict = {
    "location": "sec. 2, Figure 2 (image lost)",
    "type": "2P4R",
    "dof": 6,
    "prismatic": 2,
    "revolute": 4,
    "parts": {
        1: ("腰部基座", "waist base"),
        2: ("旋轉座", "rotating seat"),
        3: ("水平滑塊", "horizontal slider"),
        4: ("前臂", "fore-arm"),
        5: ("主臂連桿", "main-arm link (link-bar)"),
        6: ("豎直滑塊", "vertical slider"),
        7: ("後臂", "back-arm"),
        8: ("後小臂", "back small-arm"),
        9: ("三角形連接件", "triangle connector"),
        10: ("下小臂", "lower small-arm"),
        11: ("上小臂", "upper small-arm"),
        12: ("腕部基座", "wrist base"),
    },
    "connections": (
        "waist base 1 -- revolute (waist) -- rotating seat 2 and everything above it",
        "rotating seat 2 carries the horizontal slider 3 and the vertical slider 6",
        "horizontal slider 3 -- hinge -- lower end of the fore-arm 4",
        "vertical slider 6 -- hinge -- lower end of the back-arm 7",
        "fore-arm 4 and back-arm 7: lower ends connected by the main-arm link 5",
        "fore-arm 4 parallel to back-arm 7; link 5 parallel to lower small-arm 10; the four "
        "form a parallelogram",
        "lower small-arm 10 and upper small-arm 11 hinged at their ends to the wrist base 12",
        "wrist: three revolute joints in series",
    ),
    "not_printed": (
        "where link 5 is hinged on the fore-arm and the back-arm",
        "which part the triangle connector 9 pivots on",
        "where the back small-arm 8 is hinged at its lower end",
        "the directions of the slider guides and of the wrist axes",
    ),
    "extracted": ("dof", "components", "parallelogram"),
}
"""Section 2's topology as printed (English names follow the English abstract)."""

CHAINS: dict = {
    "location": "sec. 3.2, Figure 3 (image lost)",
    "parallel_part": "rotating seat to wrist base bFF' (the moving platform)",
    "main": ("vertical slider", "back-arm l_AD", "lower small-arm l_DF"),
    "secondary": (
        "horizontal slider",
        "back small-arm l_C'E''",
        "triangle connector b_EE'E''",
        "upper small-arm l_E'F'",
    ),
    "platform": "wrist base b_FF'",
    "main_is": "the chain of the vertical guide's slider (主運動鏈); the other is 副運動鏈",
    "points": ("A", "B", "C'", "D", "E", "E'", "E''", "F", "F'"),
    "extracted": ("chains",),
}
"""The two serial chains of the parallel part (sec. 3.2) and the points Figure 3 names."""

JOINTS: dict = {
    "location": "sec. 3.2 and sec. 4",
    "active": ("theta2", "theta9"),
    "passive": ("theta3", "theta4", "theta5", "theta10", "theta11", "theta12", "theta13"),
    "sliders": {
        "theta9": {"name": "x", "part": "horizontal slider", "screw": "xi9", "unit": "mm"},
        "theta2": {"name": "z", "part": "vertical slider", "screw": "xi2", "unit": "mm"},
    },
    "mapped": ("theta3", "theta5"),
    "mapping_equations": (15, 16),
    "commanded": ("omega1", "omega6", "omega7", "omega8", "nu_x", "nu_z"),
    "twist_equations": {"revolute": 7, "prismatic": 8},
    "extracted": ("active_passive", "mapping", "slider_variables", "xref_eq7_eq8"),
}
"""Active and passive joints as printed: beta = [theta2, theta9]^T, alpha = [theta3, theta4,
theta5, theta10, theta11, theta12, theta13]^T; eqs. 15-16 give theta3, theta5 from x, z."""

DIMENSIONS: dict[str, dict] = {
    "a": {
        "meaning": "distance between A and B in Figure 3",
        "unit": "mm",
        "value": None,
        "location": "sec. 3.2, after eq. 13",
        "extracted": "dimension_a",
    },
    "f": {
        "meaning": "distance between the hinge F and the screw xi6 in Figure 3",
        "unit": "mm",
        "value": None,
        "location": "sec. 3.3, after eq. 17",
        "extracted": "dimension_f",
    },
}
"""Named dimensions; every value is in the lost Table 1 ('其余同理': the others likewise)."""

# --- section 4: the experiment ------------------------------------------------------------
_t = sp.Symbol("t", nonnegative=True)

EXPERIMENT: dict = {
    "location": "sec. 4",
    "laws": {
        "omega1": {
            "expr": "-5*t",
            "joint": "theta1",
            "quantity": "angular velocity",
            "unit": "rad/s",
        },
        "omega6": {
            "expr": "10*t",
            "joint": "theta6",
            "quantity": "angular velocity",
            "unit": "rad/s",
        },
        "omega7": {
            "expr": "-10*t",
            "joint": "theta7",
            "quantity": "angular velocity",
            "unit": "rad/s",
        },
        "omega8": {
            "expr": "-10*t",
            "joint": "theta8",
            "quantity": "angular velocity",
            "unit": "rad/s",
        },
        "nu_x": {"expr": "15*t", "joint": "theta9", "quantity": "slider velocity", "unit": "mm/s"},
        "nu_z": {"expr": "20*t", "joint": "theta2", "quantity": "slider velocity", "unit": "mm/s"},
    },
    "time_unit": "s",
    "times": (1.0, 2.0, 3.0, 4.0, 5.0),
    "n_sets": 5,
    "fk_equation": 22,
    "computed_with": "Matlab",
    "measured_with": "three-dimensional coordinate measuring instrument",
    "instrument_origin_in_S_mm": (1500.0, 0.0, 0.0),
    "instrument_axes": "parallel to S",
    "base_frame": "Z on the waist axis; XOY the bottom face of the waist base",
    "max_abs_error_mm": 10.4,
    "error_per": "axis (X, Y, Z), not Euclidean",
    "jaw_opening_mm": 200.0,
    "target": "tree trunk (clamped)",
    "extracted": (
        "joint_laws",
        "samples",
        "xref_eq22",
        "base_frame",
        "instrument",
        "max_error",
        "proof_by_opening",
    ),
}
"""The kinematic experiment as printed: joint laws with their printed units, sample times,
the measuring set-up, the 10.4 mm result and the 200 mm jaw opening."""


def joint_law(name: str) -> sp.Expr:
    """A joint law of :data:`EXPERIMENT` as a SymPy expression in ``t`` (printed form)."""
    laws = EXPERIMENT["laws"]
    if name not in laws:
        raise ValueError(f"unknown joint law {name!r}; expected one of {sorted(laws)}")
    return sp.parse_expr(laws[name]["expr"], local_dict={"t": _t})


# --- equations: numbers only ------------------------------------------------------------------
EQUATION_NUMBERS: tuple[dict, ...] = (
    {"n": 1, "section": "1.1", "leadin": "剛體在A上的位姿變換集合可表示為", "holds": "SE(3)"},
    {"n": 2, "section": "1.1", "leadin": "可以用矩陣指數表示為", "holds": "rotation exp"},
    {"n": 3, "section": "1.1", "leadin": "Rodriguez公式計算矩陣指數", "holds": "Rodrigues"},
    {
        "n": 4,
        "section": "1.1",
        "leadin": "剛體位姿變換g用矩陣指數表示為",
        "holds": "exp of a twist",
    },
    {"n": 5, "section": "1.1", "leadin": "根據式(3),可以將式(4)展開", "holds": "exp expanded"},
    {"n": 6, "section": "1.1", "leadin": "瞬時位姿變換為", "holds": "g_ab(theta)"},
    {"n": 7, "section": "1.2", "leadin": "對於轉動關節", "holds": "revolute twist"},
    {"n": 8, "section": "1.2", "leadin": "對於移動關節", "holds": "prismatic twist"},
    {"n": 9, "section": "1.2", "leadin": "指數積方程", "holds": "POE g_st(theta)"},
    {"n": 10, "section": "3.2", "leadin": "一般位形的結構方程為", "holds": "structure equation"},
    {"n": 11, "section": "3.2", "leadin": "整理式(10),可得", "holds": "rearranged"},
    {"n": 12, "section": "3.2", "leadin": "各關節軸單位矢量為", "holds": "axis directions"},
    {"n": 13, "section": "3.2", "leadin": "取各軸線上的點為", "holds": "axis points (a, ...)"},
    {"n": 14, "section": "3.2", "leadin": "結構方程(11)調整為", "holds": "active/passive split"},
    {"n": 15, "section": "3.2", "leadin": "映射關係為", "holds": "theta3(x, z)"},
    {"n": 16, "section": "3.2", "leadin": "映射關係為", "holds": "theta5(x, z)"},
    {"n": 17, "section": "3.3", "leadin": "T系與S系的初始位姿變換為", "holds": "g_st(0) (f, ...)"},
    {"n": 18, "section": "3.3", "leadin": "未求解的各關節軸單位矢量為", "holds": "axis directions"},
    {"n": 19, "section": "3.3", "leadin": "取各軸線上的點為", "holds": "axis points"},
    {"n": 20, "section": "3.3", "leadin": "主運動鏈運動學正解方程為", "holds": "main-chain POE"},
    {"n": 21, "section": "3.3", "leadin": "展開可得", "holds": "p(theta), c_i, s_i"},
    {"n": 22, "section": "3.4", "leadin": "(display before 式中pe(θ))", "holds": "p_e(theta)"},
)
"""The 22 displayed equations, numbered by counting the text's lead-ins (every body and
every number is lost). The count is anchored by the references that survive: 式(3), 式(4)
(sec. 1.1), 式(7), 式(8), 式(9) (secs. 1.2, 3.2-3.3), 式(10), 式(11) (sec. 3.2), 式(15),
式(16) (sec. 3.4) and 方程(22) (sec. 4)."""

CROSS_REFERENCES: tuple[dict, ...] = (
    {"location": "sec. 1.1", "printed": "根據式(3),可以將式(4)展開", "refers_to": (3, 4)},
    {
        "location": "sec. 3.2",
        "printed": "由式(8)可求解機器人水平滑塊、豎直滑塊的運動旋量坐標,"
        "由式(7)可求得其余關節的運動旋量坐標",
        "refers_to": (8, 7),
        "extracted": "xref_eq7_eq8",
    },
    {"location": "sec. 3.2", "printed": "整理式(10),可得", "refers_to": (10,)},
    {"location": "sec. 3.2", "printed": "並聯部分的結構方程(11)調整為", "refers_to": (11,)},
    {
        "location": "sec. 3.3",
        "printed": "由式(9)可求得主動鏈中尚未求解的各關節運動旋量坐標",
        "refers_to": (9,),
        "extracted": "xref_eq9",
    },
    {
        "location": "sec. 3.4",
        "printed": "將主運動鏈關節與主動關節映射關係式(15)、式(16)代入到p(θ)中",
        "refers_to": (15, 16),
        "extracted": "xref_eq15_16",
    },
    {
        "location": "sec. 3.4",
        "printed": "獲得了混聯采摘機器人機械臂運動學正解方程(18)",
        "refers_to": (18,),
        "extracted": "xref_eq18",
    },
    {
        "location": "sec. 4",
        "printed": "代入到機械臂運動學正解方程(22)中",
        "refers_to": (22,),
        "extracted": "xref_eq22",
    },
)
"""Every reference to a numbered equation in the running text."""

# --- claims -------------------------------------------------------------------------------
CLAIMS: dict[str, dict] = {
    "proof_by_opening": {
        "location": "abstract; sec. 4; conclusion 3",
        "printed": "10.4 mm的末端執行器最大絕對位置誤差遠小於200 mm的最大開度, ... 證明了 ... "
        "運動學分析方法的可行性和正確性",
        "meaning": "the 10.4 mm maximum error, far below the 200 mm jaw opening, proves the "
        "method feasible and the FK equation correct",
        "extracted": ("proof_by_opening", "abstract_random", "conclusion_3"),
    },
    "random_sets": {
        "location": "abstract",
        "printed": "隨機選取5組關節變量值",
        "meaning": "five sets of joint values chosen at random",
        "extracted": ("abstract_random",),
    },
    "error_large": {
        "location": "sec. 5 (discussion)",
        "printed": "位置絕對誤差最大為10.4 mm, ... 但是誤差絕對值較大",
        "meaning": "the same 10.4 mm is called large (it burdens the vision system)",
        "extracted": ("discussion_error_large",),
    },
    "amplification": {
        "location": "sec. 2",
        "printed": "可以通過較小的驅動行程獲得末端執行器較大的工作行程",
        "meaning": "the parallelogram arm turns small slider strokes into large end-effector "
        "travel",
        "extracted": ("amplification",),
    },
    "wrist_dof": {
        "location": "sec. 2",
        "printed": "這樣設計使得機器人腕部減少了2個自由度",
        "meaning": "positioning by waist and sliders saves the wrist two degrees of freedom",
        "extracted": ("wrist_dof",),
    },
    "main_chain_called_active": {
        "location": "sec. 3.3",
        "printed": "由於選擇垂直滑塊所在的運動鏈為主動鏈",
        "meaning": "sec. 3.3 calls the main chain (主運動鏈) the 'active chain' (主動鏈)",
        "extracted": ("xref_eq9", "main_is_active_chain"),
    },
    "english_closed_chain": {
        "location": "English abstract",
        "printed": "the position of the end effector was got from the kinematics analysis of "
        "the closed chain by using ... product-of-exponential formula",
        "meaning": "the POE is applied to the closed chain (the Chinese text: to the main, "
        "open chain)",
        "extracted": ("english_closed_chain",),
    },
    "r3_group": {
        "location": "sec. 1.1",
        "printed": "R3是以3維列向量作為單位元素的群",
        "meaning": "R^3 is 'the group with 3-vectors as identity element'",
        "extracted": ("r3_group",),
    },
}
"""Checkable statements of the running text (``printed`` without the pinyin artefacts)."""

LOST: dict[str, str] = {
    "eqs. 1-22": "every displayed equation: bodies and numbers (numbers are counted in "
    "EQUATION_NUMBERS). In particular the structure equations (10)-(14), the mappings "
    "theta3(x, z), theta5(x, z) (15)-(16), g_st(0) (17), the axes and points (12), (13), "
    "(18), (19) and the FK (20)-(22).",
    "Table 1": "structure parameters of the manipulator (a, f and 'the others'): body lost; "
    "only the caption '表1 機械臂結構參數' survives.",
    "Table 2": "position errors of the end effector on X, Y, Z for the five sets: body lost; "
    "only the caption and the 10.4 mm maximum survive.",
    "Figure 1": "screw motion of a rigid body: image lost.",
    "Figure 2": "3D model of the 2P4R arm with parts 1-12: image lost.",
    "Figure 3": "structure diagram and reference configuration (points A, B, C', D, E, E', "
    "E'', F, F', screws xi1..xi13): image lost.",
    "Figure 4": "kinematics test platform (measuring instrument and robot): image lost.",
    "measurements": "the five measured and the five computed end-effector positions.",
}
"""What the extraction lost, by item."""

UNCERTAIN: dict[str, str] = {
    "equation numbers": "counted from lead-in phrases; a display the extraction dropped with "
    "its lead-in would shift every later number. The surviving references (3), (4), (7)-(11), "
    "(15), (16), (22) fit the count; (18) in sec. 3.4 does not (see CROSS_REFERENCES).",
    "joint laws": "'ωi為第i個關節的角速度,rad/s' makes ω1 = -5t an angular velocity in rad/s "
    "(integrated: θ1 = -2.5 t² rad, -62.5 rad at 5 s), while '5組關節變量值' (five sets of "
    "joint values) reads the laws as the joint values themselves; neither says whether "
    "degrees were meant.",
    "initial values": "the joint values at t = 0 are not printed (the reference pose θi = 0 "
    "of Figure 3 is the natural reading).",
    "link 5 and the triangle": "section 2 does not say where link 5 and the triangle connector "
    "pivot; Figure 3 is lost.",
    "marker point": "the 'mark point on the end effector' that was measured is not located.",
}
"""What the text leaves undecidable, by item."""
