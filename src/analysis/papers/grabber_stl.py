"""The STL listings of the paper (seed 000, Figures 3-6): as extracted, and reconstructed.

Data only, like :mod:`analysis.papers.grabber` (which re-exports both names): Figures 3-4
survived the extraction line by line; Figures 5-6 came out as multi-column text interleaved
line by line and are put back together here (see ``UNCERTAIN`` in the paper module).
"""

from __future__ import annotations

__all__ = ["FIGURE_STL", "FIGURE_STL_EXTRACTED"]

FIGURE_STL_EXTRACTED: dict[int, str] = {
    3: "LD\t上电置1\nMOVD\t100,VD0\nMOVD\t100,VD4\nMOVD\t600,VD8\n",
    4: (
        "LD\t上电置1\nMOVR\tVD4,VD12\n/R\tVD0,VD12\nCALL\tARCTAN,VD12,VD12\n/R\t360.0,VD12\n"
        "MOVR\tVD12,VD16\nAENO\t\n*R\t4000.0,VD16\nAENO\t\nROUND\tVD16,VD16\n"
    ),
    5: """MOVR VD104, VD110 +R VD84, VD88 COS VD12, VD56
-R VD106, VD110 AENO SIN VD12, VD60
LRD MOVR VD68, VD92 COS VD48, VD64
MOVR VD100, VD114 AENO SIN VD48, VD68
AENO *R 310.0, VD92 MOVR 310.0, VD68
/R VD110, VD114 AENO MOVR VD88, VD96
AENO *R VD64, VD68
CALLARCTAN, VD114, AENO AENO
LRD *R VD92, VD96 +R 200.0, VD68
MOVR VD114, VD118 AENO LRD
AENO MOVR VD76, VD100 MOVR VD8, VD72
-R VD48, VD118 +R VD96, VD100 AENO
AENO LRD -R 660.0, VD72
/R 360.0, VD118 MOVR VD68, VD104 AENO
AENO AENO MOVR VD68, VD76
MOVR VD118, VD122 *R VD88, VD104 *R VD72, VD76
*R 4000.0, VD122 AENO LRD
LPP MOVR VD72, VD106 MOVR VD56, VD80
ROUNDVD122, VD122 AENO AENO
*R VD4, VD84 *R VD92, VD106 *R VD0, VD80
AENO AENO AENO
MOVR VD80, VD88 LD 上电置1 AENO VD60, VD84
AENO LPS AENO
""",
    6: """LD 上电置1 AENO AENO MOVR VD176, VD28
LPS *R VD4, VD200 +R VD216, VD44 *R VD176, VD28
COS VDD0, VD180 AENO AENO *R VD32, VD44 LRD
AENO MOVR VD196, VD24 -R VD32, VD44 MOVR 310.0, VD32
MOVR VD180, VD184 *R VD200, VD24 -R VD36, VD44 *R 310.0, VD32
AENO LRD LRD MOVR 200.0, VD36
AENO MOVR VD192, VD204 LRD MOVR 200.0, VD36
AENO *R VD180, VD204 AENO *R 200.0, VD36
AENO MOVR VD204, VD208 AENO /R LRD
AENO AENO CALL ARCCOS, VD48, VD48 *R 310.0, VD40
AENO *R VDD0, VD188 AENO MOVR VD44, VD48 MOVR 310.0, VD40
AENO MOVR VD184, VD20 *R VDD0, VD208 LRD +R VD40, VD40
AENO *R VD188, VD20 AENO MOVR VD208, VD212 LRD MOVR VD40, VD40
LRD AENO LPP MOVR VD48, VD52 LRD
SIN VDD0, VD192 AENO *R VD4, VD212 AENO *R 4000.0, VD52 MOVR VD212, VD216 AENO
AENO MOVR VD192, VD196 AENO *R 2.0, VD216 ROUNDVD52, VD52 +R VD24, VD44
AENO *R VD192, VD196 LRD AENO AENO
MOVR VD4, VD200 MOVR VD8, VD176 AENO -R 660.0, VD176 AENO
""",
}
"""Figures 3-6 exactly as the text extraction gives them (Figures 5-6 scrambled)."""

FIGURE_STL: dict[int, str] = {
    3: """\
// Figure 3  数据采集控制原理 (data acquisition): target (Px, Py, Pz) = (100, 100, 600) mm
LD     上电置1          // "power-on set to 1": a symbol name, printed as is (SM0.0 or SM0.1 meant)
MOVD   100, VD0         // Px
MOVD   100, VD4         // Py
MOVD   600, VD8         // Pz
""",
    4: """\
// Figure 4  θ1 控制原理: theta1 = ARCTAN(Py / Px), c1 = ROUND(theta1 / 360 * 4000)
LD     上电置1
MOVR   VD4, VD12        // VD12 := Py
/R     VD0, VD12        // VD12 := Py / Px
CALL   ARCTAN, VD12, VD12
/R     360.0, VD12      // VD12 := theta1 / 360 (VD12 no longer holds theta1)
MOVR   VD12, VD16
AENO
*R     4000.0, VD16
AENO
ROUND  VD16, VD16       // c1 (DINT) in VD16
""",
    5: """\
// Figure 5  θ2 控制原理 (reconstructed: three printed columns read top to bottom,
// left to right; the extraction interleaved them line by line)
LD     上电置1
LPS
COS    VD12, VD56       // cos theta1
AENO
SIN    VD12, VD60       // sin theta1
AENO
COS    VD48, VD64       // cos theta3 (VD48 is written by Figure 6)
AENO
SIN    VD48, VD68       // sin theta3
AENO
MOVR   310.0, VD68      // ? column/line placement uncertain; overwrites sin theta3
AENO                    // ? (AENO lines between instructions: count uncertain)
*R     VD64, VD68
AENO
+R     200.0, VD68      // VD68 := L2 cos theta3 + L3
LRD
MOVR   VD8, VD72
AENO
-R     660.0, VD72      // VD72 := Pz - L1
AENO
MOVR   VD68, VD76
*R     VD72, VD76       // VD76 := (L2 cos theta3 + L3)(Pz - L1)
LRD
MOVR   VD56, VD80
AENO
*R     VD0, VD80        // VD80 := cos theta1 Px
AENO
MOVR   VD60, VD84       // ? printed "AENO VD60, VD84": the mnemonic is lost, MOVR assumed
AENO
*R     VD4, VD84        // VD84 := sin theta1 Py
AENO
MOVR   VD80, VD88
AENO
+R     VD84, VD88       // VD88 := cos theta1 Px + sin theta1 Py
AENO
MOVR   VD68, VD92
AENO
*R     310.0, VD92      // VD92 := 310 * VD68 (eq. 18 needs L2 sin theta3)
AENO
MOVR   VD88, VD96       // ? placement uncertain (third printed column of line 6)
AENO
*R     VD92, VD96
AENO
MOVR   VD76, VD100
+R     VD96, VD100      // VD100 := numerator of eq. 18
LRD
MOVR   VD68, VD104
AENO
*R     VD88, VD104
AENO
MOVR   VD72, VD106
AENO
*R     VD92, VD106
AENO
MOVR   VD104, VD110
-R     VD106, VD110     // VD110 := denominator of eq. 18
LRD
MOVR   VD100, VD114
AENO
/R     VD110, VD114
AENO
CALL   ARCTAN, VD114, VD114   // ? printed "CALLARCTAN, VD114," (output operand lost)
LRD
MOVR   VD114, VD118
AENO
-R     VD48, VD118      // theta2 = theta23 - theta3 (eq. 19)
AENO
/R     360.0, VD118
AENO
MOVR   VD118, VD122
*R     4000.0, VD122
LPP
ROUND  VD122, VD122     // c2 (DINT) in VD122
""",
    6: """\
// Figure 6  θ3 控制原理 (reconstructed from five interleaved printed columns; the
// least certain listing: several instructions are visibly missing or garbled)
LD     上电置1
LPS
COS    VDD0, VD180      // printed VDD0: not a valid operand (theta1 is in VD12)
AENO
MOVR   VD180, VD184
AENO                    // ? "*R VD180, VD184" or "*R VD0, VD184" expected here: not printed
AENO
MOVR   VDD0, VD188      // ? not printed; "*R VDD0, VD188" alone needs a preceding load
*R     VDD0, VD188      // VD188 := Px * Px if VDD0 means VD0
AENO
MOVR   VD184, VD20
*R     VD188, VD20      // VD20 := cos^2 theta1 Px^2 (if VD184 = cos^2 theta1)
AENO
LRD
SIN    VDD0, VD192      // printed VDD0: should be theta1 (VD12)
AENO
MOVR   VD192, VD196
AENO
*R     VD192, VD196     // VD196 := sin^2 theta1
AENO
MOVR   VD4, VD200
*R     VD4, VD200       // VD200 := Py^2
AENO
MOVR   VD196, VD24
*R     VD200, VD24      // VD24 := sin^2 theta1 Py^2
LRD
MOVR   VD192, VD204
*R     VD180, VD204     // VD204 := sin theta1 cos theta1
MOVR   VD204, VD208
AENO
*R     VDD0, VD208      // VD208 := sin cos Px (if VDD0 means VD0)
AENO
MOVR   VD208, VD212
LPP
*R     VD4, VD212
AENO
MOVR   VD212, VD216
*R     2.0, VD216       // VD216 := 2 sin theta1 cos theta1 Px Py
LRD
MOVR   VD8, VD176
AENO
-R     660.0, VD176     // VD176 := Pz - L1
AENO
MOVR   VD176, VD28
*R     VD176, VD28      // VD28 := (Pz - L1)^2
LRD
MOVR   310.0, VD32
*R     310.0, VD32      // VD32 := L2^2
MOVR   200.0, VD36
MOVR   200.0, VD36      // printed twice (harmless repeat)
*R     200.0, VD36      // VD36 := L3^2
LRD
MOVR   310.0, VD40
*R     310.0, VD40      // ? printed "*R 310.0, VD40": 2 L2 L3 needs "*R 200.0, VD40"
+R     VD40, VD40       // VD40 := 2 * VD40
MOVR   VD40, VD40       // printed; a no-op
LRD
// ? printed, not placed: *R VD32, VD44   (VD44 * L2^2 has no role in eq. 10; misprint for -R?)
MOVR   VD28, VD44       // ? not printed; VD44 must be loaded before the sums
+R     VD20, VD44       // ? not printed (cos^2 theta1 Px^2 term)
+R     VD216, VD44
+R     VD24, VD44
-R     VD32, VD44
-R     VD36, VD44
/R     VD40, VD44       // ? printed "/R" without operands
MOVR   VD44, VD48
CALL   ARCCOS, VD48, VD48   // theta3 >= 0 only (eq. 10 branch)
MOVR   VD48, VD52
AENO                    // ? no "/R 360.0, VD52" is printed in Figure 6
*R     4000.0, VD52
AENO
ROUND  VD52, VD52       // c3 (DINT) in VD52
""",
}
"""The STL of Figures 3-6 as text, reconstructed for reading and execution.

Figures 3-4 are exact (the extraction kept their lines). Figures 5-6 are reconstructions
of scrambled multi-column text: lines carrying ``// ?`` are uncertain (placement, a lost
mnemonic or operand, or an instruction supplied because the data flow needs it); they
are listed in :data:`UNCERTAIN`. Everything else is printed verbatim (modulo spacing).
"""
