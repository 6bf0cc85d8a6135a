"""The appendix VB6 listing (程序清单, pp. 36-46) of the GR-1 thesis with line breaks restored,
what was restored, how its near-identical blocks differ, and the input check of the 计算
button (Command1_Click, p. 36)."""

from __future__ import annotations

_LISTING_LINES: tuple[str, ...] = (
    "Dim a2, a3, a4, PI, a, b, c, d, h, m, n, max, min As Double",
    "Private Sub Command1_Click()",
    "Dim Px0, Py0, Pz0, α0, β0, γ0 As Single",
    "Dim θ1, θ2, θ3, θ4, θ5, θ234 As Single, c3 As Double",
    "Dim Px1, Py1, Pz1, α1, β1, γ1 As Single",
    "Dim θf1, θf2, θf3, θf4, θf5, θf234 As Single, cf3 As Double",
    "a2 = 228",
    "a3 = 228",
    "a4 = 73",
    "PI = 3.141593",
    "Px0 = Val(Text1.Text)",
    "Py0 = Val(Text2.Text)",
    "Pz0 = Val(Text3.Text)",
    "α0 = Val(Text4.Text)",
    "β0 = Val(Text5.Text)",
    "γ0 = Val(Text6.Text)",
    "Px1 = Val(Text7.Text)",
    "Py1 = Val(Text8.Text)",
    "Pz1 = Val(Text9.Text)",
    "α1 = Val(Text10.Text)",
    "β1 = Val(Text11.Text)",
    "γ1 = Val(Text12.Text)",
    "Command3.Enabled = True",
    "If Sqr((Px0 - Px1) * (Px0 - Px1) + (Py0 - Py1) * (Py0 - Py1)) > 850 Then",
    "Command3 = False",
    "ElseIf Abs(Pz0 - Pz1) > 600 Then",
    "Command3.Enabled = False",
    "End If",
    "θ1 = (180 / PI) * (Atn(Py0 / Px0))",
    'Text13.Text = Format(θ1, "####.###")',
    (
        "θ5 = (180 / PI) * (Atn((Sin(θ1) * Cos(α0) * Cos(β0) - Cos(θ1) * Sin(α0) *"
        " Cos(β0)) / (Sin(θ1) * (Cos(α0) * Sin(β0) * Sin(γ0) - Sin(α0) * Cos(γ0)) -"
        " Cos(θ1) * (Sin(α0) * Sin(β0) * Sin(γ0) + Cos(α0) * Cos(γ0)))))"
    ),
    'Text17.Text = Format(θ5, "####.###")',
    (
        "θ234 = (180 / PI) * (Atn((Cos(β0) * Sin(γ0)) / (Cos(θ1) * (Cos(α0) * Sin(β0) *"
        " Sin(γ0) - Sin(α0) * Cos(γ0)) + Sin(θ1) * (Sin(α0) * Sin(β0) * Sin(γ0) +"
        " Cos(α0) * Cos(γ0)))))"
    ),
    (
        "c3 = ((Px0 * Cos(θ1) + Py0 * Sin(θ1) - Cos(θ234) * a4) * (Px0 * Cos(θ1) + Py0 *"
        " Sin(θ1) - Cos(θ234) * a4) + (Pz0 - Sin(θ234) * a4) * (Pz0 - Sin(θ234) * a4) -"
        " a2 * a2 - a3 * a3) / (2 * a2 * a3)"
    ),
    "θ3 = (180 / PI) * (Atn(Sqr(Abs(1 - c3 * c3)) / c3))",
    'Text15.Text = Format(θ3, "####.###")',
    (
        "θ2 = (180 / PI) * (Atn(((Cos(θ3) * a3 + a2) * (Pz0 - Sin(θ234) * a4) - Sin(θ3)"
        " * a3 * (Px0 * Cos(θ1) + Py0 * Sin(θ1) + Cos(θ234) * a4)) / ((Cos(θ3) * a3 +"
        " a2) * (Px0 * Cos(θ1) + Py0 * Sin(θ1) + Cos(θ234) * a4) + Sin(θ3) * a3 * (Pz0 -"
        " Sin(θ234) * a4))))"
    ),
    'Text14.Text = Format(θ2, "####.###")',
    "θ4 = θ234 - θ2 - θ3",
    'Text16.Text = Format(θ4, "####.###")',
    "θf1 = (180 / PI) * (Atn(Py1 / Px1))",
    'Text18.Text = Format(θf1, "####.###")',
    (
        "θf5 = (180 / PI) * (Atn((Sin(θf1) * Cos(α0) * Cos(β0) - Cos(θf1) * Sin(α0) *"
        " Cos(β0)) / (Sin(θf1) * (Cos(α0) * Sin(β0) * Sin(γ0) - Sin(α0) * Cos(γ0)) -"
        " Cos(θf1) * (Sin(α0) * Sin(β0) * Sin(γ0) + Cos(α0) * Cos(γ0)))))"
    ),
    'Text22.Text = Format(θf5, "####.###")',
    (
        "θf234 = (180 / PI) * (Atn((Cos(β0) * Sin(γ0)) / (Cos(θf1) * (Cos(α0) * Sin(β0)"
        " * Sin(γ0) - Sin(α0) * Cos(γ0)) + Sin(θf1) * (Sin(α0) * Sin(β0) * Sin(γ0) +"
        " Cos(α0) * Cos(γ0)))))"
    ),
    (
        "cf3 = ((Px1 * Cos(θf1) + Py1 * Sin(θf1) - Cos(θf234) * a4) * (Px1 * Cos(θf1) +"
        " Py1 * Sin(θf1) Cos(θf234) * a4) + (Pz1 - Sin(θf234) * a4) * (Pz1 - Sin(θf234)"
        " * a4) - a2 * a2 - a3 * a3) / (2 * a2 * a3)"
    ),
    "θf3 = (180 / PI) * (Atn(Sqr(Abs(1 - cf3 * cf3)) / cf3))",
    'Text20.Text = Format(θf3, "####.###")',
    (
        "θf2 = (180 / PI) * (Atn(((Cos(θf3) * a3 + a2) * (Pz1 - Sin(θf234) * a4) -"
        " Sin(θf3) * a3 * (Px1 * Cos(θf1) + Py1 * Sin(θf1) + Cos(θf234) * a4)) /"
        " ((Cos(θf3) * a3 + a2) * (Px1 * Cos(θf1) + Py1 * Sin(θf1) + Cos(θf234) * a4) +"
        " Sin(θf3) * a3 * (Pz1 - Sin(θf234) * a4))))"
    ),
    'Text19.Text = Format(θf2, "####.###")',
    "θf4 = θf234 - θf2 - θf3",
    'Text21.Text = Format(θf4, "####.###")',
    "End Sub",
    "Private Sub Command3_Click()",
    "Dim m1, m2, m3, m4, m5, n1, n2, n3, n4, n5 As Double",
    "Frame6.Visible = True",
    "'关节 1 轨迹",
    "'取值",
    "a = Text13.Text",
    "b = Text18.Text",
    "c = 10",
    ("d = a + (3 / (c * c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b - a) * (10 * 10 * 10)"),
    "If Val(a) > Val(d) Then",
    "m1 = a",
    "n1 = d",
    "Else",
    "m1 = d",
    "n1 = a",
    "End If",
    "Picture1.Cls '清空画图区域",
    ("Picture1.Scale (0, m1 + (m1 - n1) / 5)-(12, n1) '设置画图区域 根据需要进行设置大小"),
    "Picture1.ForeColor = &H0",
    "Picture1.DrawWidth = 1",
    "'画 X 轴",
    "'Picture1.Line (0, n1)-(5, n1)",
    "'标记 t 轴",
    "Picture1.CurrentX = 11.5",
    "Picture1.CurrentY = n1 + (m1 - n1) / 10",
    'Picture1.Print "t"',
    "'画 Y 轴",
    "Picture1.Line (0, n1 - 5)-(0, m1 + (m1 - n1) / 5)",
    "'标记 Y 轴",
    "Picture1.CurrentX = 0.2",
    "Picture1.CurrentY = m1 + (m1 - n1) / 5",
    'Picture1.Print "Y"',
    "'画坐标",
    "Dim i As Single",
    "For i = 1 To 10",
    "Picture1.CurrentX = i: Picture1.CurrentY = n1 + (m1 - n1) / 10: Picture1.Print i",
    "Picture1.Line (i, n1)-(i, n1 + (m1 - n1) / 15)",
    "Next i",
    "Dim j As Integer",
    "For j = 1 To 5",
    "Picture1.Line (0, n1 + (m1 - n1) / 5 * j)-(0.1, n1 + (m1 - n1) / 5 * j)",
    (
        "Picture1.CurrentX = 0.1: Picture1.CurrentY = n1 + (m1 - n1) / 5 * j:"
        " Picture1.Print Fix(n1 + ((m1 - n1) / 5) * j)"
    ),
    "Next j",
    "Picture1.DrawWidth = 2",
    "Picture1.Line (0, 0)-(0, 0) '归零收笔",
    "'开始画图",
    "For X = 0 To 10 Step 0.001 '0.001 改小可以获得更高的精度",
    (
        "Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * (X *"
        " X * X) '输入函数 可以写入自己的函数"
    ),
    "Picture1.CurrentY = (m1 + n1) / 2",
    "Picture1.CurrentX = 0.5",
    "Picture1.PSet (X, Y), vbRed '标记 X,Y 轴",
    "Next",
    "Picture1.CurrentX = 4",
    "Picture1.CurrentY = m1",
    'Picture1.Print "Y = θ 1(t)" \'将函数显示在图形上',
    "'关节 2 轨迹",
    "'取值",
    "a = Text14.Text",
    "b = Text19.Text",
    "c = 10",
    ("d = a + (3 / (c * c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b - a) * (10 * 10 * 10)"),
    "If Val(a) > Val(d) Then",
    "m2 = a",
    "n2 = d",
    "Else",
    "m2 = d",
    "n2 = a",
    "End If",
    "Picture2.Cls '清空画图区域",
    ("Picture2.Scale (0, m2 + (m2 - n2) / 5)-(12, n2) '设置画图区域 根据需要进行设置大小"),
    "Picture2.ForeColor = &H0",
    "Picture2.DrawWidth = 1",
    "'画 X 轴",
    "Picture2.Line (0, n2)-(12, n2)",
    "'标记 t 轴",
    "Picture2.CurrentX = 11.5",
    "Picture2.CurrentY = n2 + (m2 - n2) / 10",
    'Picture2.Print "t"',
    "'画 Y 轴",
    "Picture2.Line (0, n2 - 5)-(0, m2 + (m2 - n2) / 5)",
    "'标记 Y 轴",
    "Picture2.CurrentX = 0.2",
    "Picture2.CurrentY = m2 + (m2 - n2) / 5",
    'Picture2.Print "Y"',
    "'画坐标",
    "For i = 1 To 10",
    "Picture2.CurrentX = i: Picture2.CurrentY = n2 + (m2 - n2) / 10: Picture2.Print i",
    "Picture2.Line (i, n2)-(i, n2 + (m2 - n2) / 15)",
    "Next i",
    "For j = 1 To 5",
    "Picture2.Line (0, n2 + (m2 - n2) / 5 * j)-(0.1, n2 + (m2 - n2) / 5 * j)",
    (
        "Picture2.CurrentX = 0.1: Picture2.CurrentY = n2 + (m2 - n2) / 5 * j:"
        " Picture2.Print Fix(n2 + ((m2 - n2) / 5) * j)"
    ),
    "Next j",
    "Picture2.DrawWidth = 2",
    "Picture2.Line (0, 0)-(0, 0) '归零收笔",
    "'开始画图",
    "For X = 0 To 10 Step 0.001 '0.005 改小可以获得更高的精度",
    (
        "Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * (X *"
        " X * X) '输入函数 可以写入自己的函数"
    ),
    "Picture2.CurrentY = (m2 + n2) / 2",
    "Picture2.CurrentX = 0.5",
    "Picture2.PSet (X, Y), vbRed '标记 X,Y 轴",
    "Next",
    "Picture2.CurrentX = 4",
    "Picture2.CurrentY = m2",
    'Picture2.Print "Y = θ 2(t)"',
    "'关节 3 轨迹",
    "'取值",
    "a = Text15.Text",
    "b = Text20.Text",
    "c = 10",
    ("d = a + (3 / (c * c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b - a) * (10 * 10 * 10)"),
    "If Val(a) > Val(d) Then",
    "m3 = a",
    "n3 = d",
    "Else",
    "m3 = d",
    "n3 = a",
    "End If",
    "Picture3.Cls '清空画图区域",
    ("Picture3.Scale (0, m3 + (m3 - n3) / 5)-(12, n3) '设置画图区域 根据需要进行设置大小"),
    "Picture3.ForeColor = &H0",
    "Picture3.DrawWidth = 1",
    "'画 X 轴",
    "Picture3.Line (0, n3)-(12, n3)",
    "'标记 t 轴",
    "Picture3.CurrentX = 11.5",
    "Picture3.CurrentY = n3 + (m3 - n3) / 10",
    'Picture3.Print "t"',
    "'画 Y 轴",
    "Picture3.Line (0, n3 - 5)-(0, m3 + (m3 - n3) / 5) '将函数显示在图形上",
    "'标记 Y 轴",
    "Picture3.CurrentX = 0.2",
    "Picture3.CurrentY = m3 + (m3 - n3) / 5",
    'Picture3.Print "Y"',
    "'画坐标",
    "For i = 1 To 10",
    "Picture3.CurrentX = i: Picture3.CurrentY = n3 + (m3 - n3) / 10: Picture3.Print i",
    "Picture3.Line (i, n3)-(i, n3 + (m3 - n3) / 15)",
    "Next i",
    "For j = 1 To 5",
    "Picture3.Line (0, n3 + (m3 - n3) / 5 * j)-(0.1, n3 + (m3 - n3) / 5 * j)",
    (
        "Picture3.CurrentX = 0.1: Picture3.CurrentY = n3 + (m3 - n3) / 5 * j:"
        " Picture3.Print Fix(n3 + ((m3 - n3) / 5) * j)"
    ),
    "Next j",
    "Picture3.DrawWidth = 2",
    "Picture3.Line (0, 0)-(0, 0) '归零收笔",
    "'开始画图",
    "For X = 0 To 10 Step 0.001 '0.001 改小可以获得更高的精度",
    (
        "Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * (X *"
        " X * X) '输入函数 可以写入自己的函数"
    ),
    "Picture3.CurrentY = (m3 + n3) / 2",
    "Picture3.CurrentX = 0.5",
    "Picture3.PSet (X, Y), vbRed '标记 X,Y 轴",
    "Next",
    "Picture3.CurrentX = 4",
    "Picture3.CurrentY = m3",
    'Picture3.Print "Y = θ 3(t)" \'将函数显示在图形',
    "'关节 4 轨迹",
    "'取值",
    "a = Text16.Text",
    "b = Text21.Text",
    "c = 10",
    ("d = a + (3 / (c * c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b - a) * (10 * 10 * 10)"),
    "If Val(a) > Val(d) Then",
    "m4 = a",
    "n4 = d",
    "Else",
    "m4 = d",
    "n4 = a",
    "End If",
    "Picture4.Cls '清空画图区域",
    ("Picture4.Scale (0, m4 + (m4 - n4) / 5)-(12, n4) '设置画图区域 根据需要进行设置大小"),
    "Picture4.ForeColor = &H0",
    "Picture4.DrawWidth = 1",
    "'画 X 轴",
    "Picture4.Line (0, n4)-(12, n4)",
    "'标记 t 轴",
    "Picture4.CurrentX = 11.5",
    "Picture4.CurrentY = n4 + (m4 - n4) / 10",
    'Picture4.Print "t"',
    "'画 Y 轴",
    "Picture4.Line (0, n4 - 5)-(0, m4 + (m4 - n4) / 5)",
    "'标记 Y 轴",
    "Picture4.CurrentX = 0.2",
    "Picture4.CurrentY = m4 + (m4 - n4) / 5",
    'Picture4.Print "Y"',
    "'画坐标",
    "For i = 1 To 10",
    "Picture4.CurrentX = i: Picture4.CurrentY = n4 + (m4 - n4) / 10: Picture4.Print i",
    "Picture4.Line (i, n4)-(i, n4 + (m4 - n4) / 15)",
    "Next i",
    "For j = 1 To 5",
    "Picture4.Line (0, n4 + (m4 - n4) / 5 * j)-(0.1, n4 + (m4 - n4) / 5 * j)",
    (
        "Picture4.CurrentX = 0.1: Picture4.CurrentY = n4 + (m4 - n4) / 5 * j:"
        " Picture4.Print Fix(n4 + ((m4 - n4) / 5) * j)"
    ),
    "Next j",
    "Picture4.DrawWidth = 2",
    "Picture4.Line (0, 0)-(0, 0) '归零收笔",
    "'开始画图",
    "For X = 0 To 10 Step 0.001 '0.005 改小可以获得更高的精度",
    (
        "Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * (X *"
        " X * X) '输入函数 可以写入自己的函数"
    ),
    "Picture4.CurrentY = (m4 + n4) / 2",
    "Picture4.CurrentX = 0.5",
    "Picture4.PSet (X, Y), vbRed '标记 X,Y 轴",
    "Next",
    "Picture4.CurrentX = 4",
    "Picture4.CurrentY = m4",
    'Picture4.Print "Y = θ 4(t)"',
    "'关节 5 轨迹",
    "'取值",
    "a = Text17.Text",
    "b = Text22.Text",
    "c = 10",
    ("d = a + (3 / (c * c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b - a) * (10 * 10 * 10)"),
    "If Val(a) > Val(d) Then",
    "m5 = a",
    "n5 = d",
    "Else",
    "m5 = d",
    "n5 = a",
    "End If '将函数显示在图形上",
    "Picture5.Cls '清空画图区域",
    ("Picture5.Scale (0, m5 + (m5 - n5) / 5)-(12, n5) '设置画图区域 根据需要进行设置大小"),
    "Picture5.ForeColor = &H0",
    "Picture5.DrawWidth = 1",
    "'画 X 轴",
    "Picture5.Line (0, n5)-(12, n5)",
    "'标记 t 轴",
    "Picture5.CurrentX = 11.5",
    "Picture5.CurrentY = n5 + (m5 - n5) / 10",
    'Picture5.Print "t"',
    "'画 Y 轴",
    "Picture5.Line (0, n5 - 5)-(0, m5 + (m5 - n5) / 5)",
    "'标记 Y 轴",
    "Picture5.CurrentX = 0.2",
    "Picture5.CurrentY = m5 + (m5 - n5) / 5",
    'Picture5.Print "Y"',
    "'画坐标",
    "For i = 1 To 10",
    "Picture5.CurrentX = i: Picture5.CurrentY = n5 + (m5 - n5) / 10: Picture5.Print i",
    "Picture5.Line (i, n5)-(i, n5 + (m5 - n5) / 15)",
    "Next i",
    "For j = 1 To 5",
    "Picture5.Line (0, n5 + (m5 - n5) / 5 * j)-(0.1, n5 + (m5 - n5) / 5 * j)",
    (
        "Picture5.CurrentX = 0.1: Picture5.CurrentY = n5 + (m5 - n5) / 5 * j:"
        " Picture5.Print Fix(n5 + ((m5 - n5) / 5) * j)"
    ),
    "Next j",
    "Picture5.DrawWidth = 2",
    "Picture5.Line (0, 0)-(0, 0) '归零收笔",
    "'开始画图",
    "For X = 0 To 10 Step 0.001 '0.005 改小可以获得更高的精度",
    (
        "Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * (X *"
        " X * X) '输入函数 可以写入自己的函数"
    ),
    "Picture5.CurrentY = (m5 + n5) / 2",
    "Picture5.CurrentX = 0.5",
    "Picture5.PSet (X, Y), vbRed '标记 X,Y 轴",
    "Next",
    "Picture5.CurrentX = 4",
    "Picture5.CurrentY = m5",
    'Picture5.Print "Y = θ 5(t)" \'将函数显示在图形上',
    "End Sub",
    "Private Sub Command4_Click()",
    'Text1.Text = ""',
    'Text2.Text = ""',
    'Text3.Text = ""',
    'Text4.Text = ""',
    'Text5.Text = ""',
    'Text6.Text = ""',
    'Text7.Text = ""',
    'Text8.Text = ""',
    'Text9.Text = ""',
    'Text10.Text = ""',
    'Text11.Text = ""',
    'Text12.Text = ""',
    'Text13.Text = ""',
    'Text14.Text = ""',
    'Text15.Text = ""',
    'Text16.Text = ""',
    'Text17.Text = ""',
    'Text18.Text = ""',
    'Text19.Text = ""',
    'Text20.Text = ""',
    'Text21.Text = ""',
    'Text22.Text = ""',
    "End Sub",
)
"""The listing with line breaks restored, one string per VB line."""

LISTING: str = "\n".join(_LISTING_LINES) + "\n"
"""The VB6 listing (appendix 程序清单, pp. 36-46: module Dim, ``Command1_Click`` "计算",
``Command3_Click`` "轨迹规划", ``Command4_Click`` "清除") with line breaks restored as
described in :data:`LISTING_RESTORATIONS`; otherwise verbatim, including the statement
that does not compile (``cf3 = ... Py1 * Sin(θf1) Cos(θf234) * a4 ...``)."""

LISTING_RESTORATIONS: list[dict] = [
    {
        "what": "line breaks",
        "detail": "the extraction joined each page's lines into one paragraph; a line break "
        "is put before every statement (Dim, If/ElseIf/Else/End If, For/Next, Sub/End Sub, "
        "assignments, PictureN.Cls/Scale/Line/PSet/Print) and before every comment that "
        "does not directly follow a statement; statements the print separated by ':' stay "
        "on one line",
    },
    {
        "what": "trailing comments",
        "detail": "a comment that follows a statement in the extraction stays on that "
        "statement's line ('清空画图区域, '设置画图区域..., '归零收笔, '0.001/'0.005 改小..., "
        "'输入函数..., '标记 X,Y 轴, '将函数显示在图形上); whether the print had them on "
        "the same line is not recoverable and does not change the program",
    },
    {
        "what": "page footers",
        "detail": "the page numbers 36, 37, 38, 39, 40, 41, 42, 43, 44, 45 that the extraction "
        "put inside the code are removed (46 follows the last End Sub)",
        "contexts": [
            "(Cos(α0) 36",
            "Command3_Click() 37",
            "To 10 38",
            "m2 = d 39",
            "可以写入自己的函数 40",
            "/ 5) 41 ",
            "Text21.Text 42",
            "* j) 43",
            "画 X 轴 44",
            "CurrentX = 4 45",
        ],
    },
    {
        "what": "heading",
        "detail": "the text '轨迹规划界面 VB 程序如下:' before the first Dim is not code",
    },
    {
        "what": "identifier spaces",
        "detail": "a space between a Greek letter and its index at the start of 18 "
        "assignments ('α 0 =', 'θ 234 =', 'θ f5 =' ...) is removed: the same names are "
        "written without the space in the Dim statements and in every expression; the "
        'spaces inside the five strings "Y = θ 1(t)" ... are kept',
    },
    {
        "what": "indentation",
        "detail": "none restored (not recoverable); VB ignores it",
    },
]
"""What was done to :data:`LISTING_EXTRACTED` to get :data:`LISTING` (nothing else)."""

LISTING_BLOCK_DIFFERENCES: list[dict] = [
    {
        "where": "Command3_Click, joint 1 block",
        "difference": "the x axis line is commented out and shorter: "
        '"\'Picture1.Line (0, n1)-(5, n1)"; joints 2-5 draw "PictureK.Line (0, nK)-(12, nK)"',
    },
    {
        "where": "Command3_Click, joints 1-5",
        "difference": "'Dim i As Single' and 'Dim j As Integer' appear in block 1 only "
        "(procedure scope, so blocks 2-5 reuse them)",
    },
    {
        "where": "Command3_Click, 'For X = 0 To 10 Step 0.001' comments",
        "difference": "blocks 1 and 3 say '0.001 改小可以获得更高的精度, blocks 2, 4, 5 say "
        "'0.005 改小...' although every block steps 0.001",
    },
    {
        "where": 'Command3_Click, comment after PictureK.Print "Y = θ K(t)"',
        "difference": "block 1 and 5: '将函数显示在图形上; block 3: '将函数显示在图形 (cut); "
        "blocks 2 and 4 have none there, and two displaced copies of '将函数显示在图形上 "
        "appear after Picture3's y-axis Line and after block 5's End If",
    },
    {
        "where": "Command3_Click, 'Dim m1, m2, m3, m4, m5, n1, n2, n3, n4, n5 As Double'",
        "difference": "only n5 is a Double; m1-m5 and n1-n4 are Variants, so mK/nK hold the "
        "TextBox String or the Double d, while n5 = a converts the String to Double",
    },
    {
        "where": "Command1_Click, end pose",
        "difference": "the θf5 and θf234 statements are copies of the start-pose statements "
        "with θ1 -> θf1 but α0, β0, γ0 unchanged: the end orientation (α1, β1, γ1, Text10-12) "
        "is read and never used",
    },
    {
        "where": "Command1_Click, c3 vs θ2 statements",
        "difference": "c3 uses 'Px0 * Cos(θ1) + Py0 * Sin(θ1) - Cos(θ234) * a4', θ2 uses "
        "'... + Cos(θ234) * a4' for the same quantity (also in cf3 vs θf2)",
    },
    {
        "where": "copies",
        "difference": "the listing is printed once (appendix pp. 36-46); chapter 6 shows no "
        "code; the table of contents lists two 程序清单 appendices (pp. 34 and 50) but the "
        "body has one appendix holding the ladder (pp. 31-35) and this listing",
    },
]
"""How the near-identical parts of the listing differ from each other (as printed)."""

GUI_CHECK: dict = {
    "location": "appendix listing, Command1_Click, p. 36",
    "printed": (
        "Command3.Enabled = True\n"
        "If Sqr((Px0 - Px1) * (Px0 - Px1) + (Py0 - Py1) * (Py0 - Py1)) > 850 Then\n"
        "Command3 = False\n"
        "ElseIf Abs(Pz0 - Pz1) > 600 Then\n"
        "Command3.Enabled = False\n"
        "End If"
    ),
    "text_claims": ["c6.3-grey", "c6.4-check"],
    "work_area_claim": "ARM['work_area']: 垂直方向 850 mm, 水平方向 600 mm",
    "note": "Command3 is the 轨迹规划 (trajectory) button; the check compares the start and "
    "end poses with each other, after which Command1_Click goes on to compute and display "
    "the joint values whatever the outcome",
}
