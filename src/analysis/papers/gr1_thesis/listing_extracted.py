"""The appendix VB6 listing (程序清单, pp. 36-46) of the GR-1 thesis exactly as extracted."""

from __future__ import annotations

# --- the appendix VB6 listing (pp. 36-46) ----------------------------------------------------
_LISTING_EXTRACTED_LINES: tuple[str, ...] = (
    ("轨迹规划界面 VB 程序如下: Dim a2, a3, a4, PI, a, b, c, d, h, m, n, max, min As Double"),
    "",
    (
        "Private Sub Command1_Click() Dim Px0, Py0, Pz0, α0, β0, γ0 As Single Dim θ1,"
        " θ2, θ3, θ4, θ5, θ234 As Single, c3 As Double Dim Px1, Py1, Pz1, α1, β1, γ1 As"
        " Single Dim θf1, θf2, θf3, θf4, θf5, θf234 As Single, cf3 As Double a2 = 228 a3"
        " = 228 a4 = 73 PI = 3.141593"
    ),
    "",
    (
        "Px0 = Val(Text1.Text) Py0 = Val(Text2.Text) Pz0 = Val(Text3.Text) α 0 ="
        " Val(Text4.Text) β 0 = Val(Text5.Text) γ 0 = Val(Text6.Text) Px1 ="
        " Val(Text7.Text) Py1 = Val(Text8.Text) Pz1 = Val(Text9.Text) α 1 ="
        " Val(Text10.Text) β 1 = Val(Text11.Text) γ 1 = Val(Text12.Text)"
        " Command3.Enabled = True If Sqr((Px0 - Px1) * (Px0 - Px1) + (Py0 - Py1) * (Py0"
        " - Py1)) > 850 Then Command3 = False ElseIf Abs(Pz0 - Pz1) > 600 Then"
        " Command3.Enabled = False End If θ 1 = (180 / PI) * (Atn(Py0 / Px0))"
        ' Text13.Text = Format(θ1, "####.###") θ 5 = (180 / PI) * (Atn((Sin(θ1) *'
        " Cos(α0) * Cos(β0) - Cos(θ1) * Sin(α0) * Cos(β0)) / (Sin(θ1) * (Cos(α0) 36"
    ),
    "",
    (
        "* Sin(β0) * Sin(γ0) - Sin(α0) * Cos(γ0)) - Cos(θ1) * (Sin(α0) * Sin(β0) *"
        ' Sin(γ0) + Cos(α0) * Cos(γ0))))) Text17.Text = Format(θ5, "####.###") θ 234 ='
        " (180 / PI) * (Atn((Cos(β0) * Sin(γ0)) / (Cos(θ1) * (Cos(α0) * Sin(β0) *"
        " Sin(γ0) - Sin(α0) * Cos(γ0)) + Sin(θ1) * (Sin(α0) * Sin(β0) * Sin(γ0) +"
        " Cos(α0) * Cos(γ0))))) c3 = ((Px0 * Cos(θ1) + Py0 * Sin(θ1) - Cos(θ234) * a4) *"
        " (Px0 * Cos(θ1) + Py0 * Sin(θ1) - Cos(θ234) * a4) + (Pz0 - Sin(θ234) * a4) *"
        " (Pz0 - Sin(θ234) * a4) - a2 * a2 - a3 * a3) / (2 * a2 * a3) θ 3 = (180 / PI) *"
        ' (Atn(Sqr(Abs(1 - c3 * c3)) / c3)) Text15.Text = Format(θ3, "####.###") θ 2 ='
        " (180 / PI) * (Atn(((Cos(θ3) * a3 + a2) * (Pz0 - Sin(θ234) * a4) - Sin(θ3) * a3"
        " * (Px0 * Cos(θ1) + Py0 * Sin(θ1) + Cos(θ234) * a4)) / ((Cos(θ3) * a3 + a2) *"
        " (Px0 * Cos(θ1) + Py0 * Sin(θ1) + Cos(θ234) * a4) + Sin(θ3) * a3 * (Pz0 -"
        ' Sin(θ234) * a4)))) Text14.Text = Format(θ2, "####.###") θ 4 = θ234 - θ2 - θ3'
        ' Text16.Text = Format(θ4, "####.###") θ f1 = (180 / PI) * (Atn(Py1 / Px1))'
        ' Text18.Text = Format(θf1, "####.###") θ f5 = (180 / PI) * (Atn((Sin(θf1) *'
        " Cos(α0) * Cos(β0) - Cos(θf1) * Sin(α0) * Cos(β0)) / (Sin(θf1) * (Cos(α0) *"
        " Sin(β0) * Sin(γ0) - Sin(α0) * Cos(γ0)) - Cos(θf1) * (Sin(α0) * Sin(β0) *"
        ' Sin(γ0) + Cos(α0) * Cos(γ0))))) Text22.Text = Format(θf5, "####.###") θ f234 ='
        " (180 / PI) * (Atn((Cos(β0) * Sin(γ0)) / (Cos(θf1) * (Cos(α0) * Sin(β0) *"
        " Sin(γ0) - Sin(α0) * Cos(γ0)) + Sin(θf1) * (Sin(α0) * Sin(β0) * Sin(γ0) +"
        " Cos(α0) * Cos(γ0))))) cf3 = ((Px1 * Cos(θf1) + Py1 * Sin(θf1) - Cos(θf234) *"
        " a4) * (Px1 * Cos(θf1) + Py1 * Sin(θf1) Cos(θf234) * a4) + (Pz1 - Sin(θf234) *"
        " a4) * (Pz1 - Sin(θf234) * a4) - a2 * a2 - a3 * a3) / (2 * a2 * a3) θ f3 = (180"
        " / PI) * (Atn(Sqr(Abs(1 - cf3 * cf3)) / cf3)) Text20.Text = Format(θf3,"
        ' "####.###") θ f2 = (180 / PI) * (Atn(((Cos(θf3) * a3 + a2) * (Pz1 - Sin(θf234)'
        " * a4) - Sin(θf3) * a3 * (Px1 * Cos(θf1) + Py1 * Sin(θf1) + Cos(θf234) * a4)) /"
        " ((Cos(θf3) * a3 + a2) * (Px1 * Cos(θf1) + Py1 * Sin(θf1) + Cos(θf234) * a4) +"
        " Sin(θf3) * a3 * (Pz1 - Sin(θf234) * a4)))) Text19.Text = Format(θf2,"
        ' "####.###") θ f4 = θf234 - θf2 - θf3 Text21.Text = Format(θf4, "####.###") End'
        " Sub Private Sub Command3_Click() 37"
    ),
    "",
    (
        "Dim m1, m2, m3, m4, m5, n1, n2, n3, n4, n5 As Double Frame6.Visible = True"
        " '关节 1 轨迹 '取值 a = Text13.Text b = Text18.Text c = 10 d = a + (3 / (c *"
        " c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b - a) * (10 * 10 * 10) If"
        " Val(a) > Val(d) Then m1 = a n1 = d Else m1 = d n1 = a End If Picture1.Cls"
        " '清空画图区域 Picture1.Scale (0, m1 + (m1 - n1) / 5)-(12, n1) '设置画图区域"
        " 根据需要进行设置大小 Picture1.ForeColor = &H0 Picture1.DrawWidth = 1 '画 X 轴"
        " 'Picture1.Line (0, n1)-(5, n1) '标记 t 轴 Picture1.CurrentX = 11.5"
        ' Picture1.CurrentY = n1 + (m1 - n1) / 10 Picture1.Print "t" \'画 Y 轴'
        " Picture1.Line (0, n1 - 5)-(0, m1 + (m1 - n1) / 5) '标记 Y 轴 Picture1.CurrentX"
        ' = 0.2 Picture1.CurrentY = m1 + (m1 - n1) / 5 Picture1.Print "Y" \'画坐标 Dim i'
        " As Single For i = 1 To 10 38"
    ),
    "",
    (
        "Picture1.CurrentX = i: Picture1.CurrentY = n1 + (m1 - n1) / 10: Picture1.Print"
        " i Picture1.Line (i, n1)-(i, n1 + (m1 - n1) / 15) Next i Dim j As Integer For j"
        " = 1 To 5 Picture1.Line (0, n1 + (m1 - n1) / 5 * j)-(0.1, n1 + (m1 - n1) / 5 *"
        " j) Picture1.CurrentX = 0.1: Picture1.CurrentY = n1 + (m1 - n1) / 5 * j:"
        " Picture1.Print Fix(n1 + ((m1 - n1) / 5) * j) Next j Picture1.DrawWidth = 2"
        " Picture1.Line (0, 0)-(0, 0) '归零收笔 '开始画图 For X = 0 To 10 Step 0.001"
        " '0.001 改小可以获得更高的精度 Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 /"
        " (c * c * c)) * (b - a) * (X * X * X) '输入函数 可以写入自己的函数"
        " Picture1.CurrentY = (m1 + n1) / 2 Picture1.CurrentX = 0.5 Picture1.PSet (X,"
        " Y), vbRed '标记 X,Y 轴 Next Picture1.CurrentX = 4 Picture1.CurrentY = m1"
        " Picture1.Print \"Y = θ 1(t)\" '将函数显示在图形上 '关节 2 轨迹 '取值 a ="
        " Text14.Text b = Text19.Text c = 10 d = a + (3 / (c * c)) * (b - a) * (10 * 10)"
        " - (2 / (c * c * c)) * (b - a) * (10 * 10 * 10) If Val(a) > Val(d) Then m2 = a"
        " n2 = d Else m2 = d 39"
    ),
    "",
    (
        "n2 = a End If Picture2.Cls '清空画图区域 Picture2.Scale (0, m2 + (m2 - n2) /"
        " 5)-(12, n2) '设置画图区域 根据需要进行设置大小 Picture2.ForeColor = &H0"
        " Picture2.DrawWidth = 1 '画 X 轴 Picture2.Line (0, n2)-(12, n2) '标记 t 轴"
        " Picture2.CurrentX = 11.5 Picture2.CurrentY = n2 + (m2 - n2) / 10"
        ' Picture2.Print "t" \'画 Y 轴 Picture2.Line (0, n2 - 5)-(0, m2 + (m2 - n2) / 5)'
        " '标记 Y 轴 Picture2.CurrentX = 0.2 Picture2.CurrentY = m2 + (m2 - n2) / 5"
        ' Picture2.Print "Y" \'画坐标 For i = 1 To 10 Picture2.CurrentX = i:'
        " Picture2.CurrentY = n2 + (m2 - n2) / 10: Picture2.Print i Picture2.Line (i,"
        " n2)-(i, n2 + (m2 - n2) / 15) Next i For j = 1 To 5 Picture2.Line (0, n2 + (m2"
        " - n2) / 5 * j)-(0.1, n2 + (m2 - n2) / 5 * j) Picture2.CurrentX = 0.1:"
        " Picture2.CurrentY = n2 + (m2 - n2) / 5 * j: Picture2.Print Fix(n2 + ((m2 - n2)"
        " / 5) * j) Next j Picture2.DrawWidth = 2 Picture2.Line (0, 0)-(0, 0) '归零收笔"
        " '开始画图 For X = 0 To 10 Step 0.001 '0.005 改小可以获得更高的精度 Y = a + (3"
        " / (c * c)) * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * (X * X * X)"
        " '输入函数 可以写入自己的函数 40"
    ),
    "",
    (
        "Picture2.CurrentY = (m2 + n2) / 2 Picture2.CurrentX = 0.5 Picture2.PSet (X, Y),"
        " vbRed '标记 X,Y 轴 Next Picture2.CurrentX = 4 Picture2.CurrentY = m2"
        " Picture2.Print \"Y = θ 2(t)\" '关节 3 轨迹 '取值 a = Text15.Text b = Text20.Text"
        " c = 10 d = a + (3 / (c * c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b -"
        " a) * (10 * 10 * 10) If Val(a) > Val(d) Then m3 = a n3 = d Else m3 = d n3 = a"
        " End If Picture3.Cls '清空画图区域 Picture3.Scale (0, m3 + (m3 - n3) / 5)-(12,"
        " n3) '设置画图区域 根据需要进行设置大小 Picture3.ForeColor = &H0"
        " Picture3.DrawWidth = 1 '画 X 轴 Picture3.Line (0, n3)-(12, n3) '标记 t 轴"
        " Picture3.CurrentX = 11.5 Picture3.CurrentY = n3 + (m3 - n3) / 10"
        ' Picture3.Print "t" \'画 Y 轴 Picture3.Line (0, n3 - 5)-(0, m3 + (m3 - n3) / 5)'
        " 41 '将函数显示在图形上"
    ),
    "",
    (
        "'标记 Y 轴 Picture3.CurrentX = 0.2 Picture3.CurrentY = m3 + (m3 - n3) / 5"
        ' Picture3.Print "Y" \'画坐标 For i = 1 To 10 Picture3.CurrentX = i:'
        " Picture3.CurrentY = n3 + (m3 - n3) / 10: Picture3.Print i Picture3.Line (i,"
        " n3)-(i, n3 + (m3 - n3) / 15) Next i For j = 1 To 5 Picture3.Line (0, n3 + (m3"
        " - n3) / 5 * j)-(0.1, n3 + (m3 - n3) / 5 * j) Picture3.CurrentX = 0.1:"
        " Picture3.CurrentY = n3 + (m3 - n3) / 5 * j: Picture3.Print Fix(n3 + ((m3 - n3)"
        " / 5) * j) Next j Picture3.DrawWidth = 2"
    ),
    "",
    (
        "Picture3.Line (0, 0)-(0, 0) '归零收笔 '开始画图 For X = 0 To 10 Step 0.001"
        " '0.001 改小可以获得更高的精度 Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 /"
        " (c * c * c)) * (b - a) * (X * X * X) '输入函数 可以写入自己的函数"
        " Picture3.CurrentY = (m3 + n3) / 2 Picture3.CurrentX = 0.5 Picture3.PSet (X,"
        " Y), vbRed '标记 X,Y 轴 Next Picture3.CurrentX = 4 Picture3.CurrentY = m3"
        ' Picture3.Print "Y = θ 3(t)" \'将函数显示在图形'
    ),
    "",
    "'关节 4 轨迹 '取值 a = Text16.Text b = Text21.Text 42",
    "",
    (
        "c = 10 d = a + (3 / (c * c)) * (b - a) * (10 * 10) - (2 / (c * c * c)) * (b -"
        " a) * (10 * 10 * 10) If Val(a) > Val(d) Then m4 = a n4 = d Else m4 = d n4 = a"
        " End If Picture4.Cls '清空画图区域 Picture4.Scale (0, m4 + (m4 - n4) / 5)-(12,"
        " n4) '设置画图区域 根据需要进行设置大小 Picture4.ForeColor = &H0"
        " Picture4.DrawWidth = 1 '画 X 轴 Picture4.Line (0, n4)-(12, n4) '标记 t 轴"
        " Picture4.CurrentX = 11.5 Picture4.CurrentY = n4 + (m4 - n4) / 10"
        ' Picture4.Print "t" \'画 Y 轴 Picture4.Line (0, n4 - 5)-(0, m4 + (m4 - n4) / 5)'
        " '标记 Y 轴 Picture4.CurrentX = 0.2 Picture4.CurrentY = m4 + (m4 - n4) / 5"
        ' Picture4.Print "Y" \'画坐标 For i = 1 To 10 Picture4.CurrentX = i:'
        " Picture4.CurrentY = n4 + (m4 - n4) / 10: Picture4.Print i Picture4.Line (i,"
        " n4)-(i, n4 + (m4 - n4) / 15) Next i For j = 1 To 5 Picture4.Line (0, n4 + (m4"
        " - n4) / 5 * j)-(0.1, n4 + (m4 - n4) / 5 * j) Picture4.CurrentX = 0.1:"
        " Picture4.CurrentY = n4 + (m4 - n4) / 5 * j: Picture4.Print Fix(n4 + ((m4 - n4)"
        " / 5) * j) 43"
    ),
    "",
    (
        "Next j Picture4.DrawWidth = 2 Picture4.Line (0, 0)-(0, 0) '归零收笔 '开始画图"
        " For X = 0 To 10 Step 0.001 '0.005 改小可以获得更高的精度 Y = a + (3 / (c * c))"
        " * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * (X * X * X) '输入函数"
        " 可以写入自己的函数 Picture4.CurrentY = (m4 + n4) / 2 Picture4.CurrentX = 0.5"
        " Picture4.PSet (X, Y), vbRed '标记 X,Y 轴 Next Picture4.CurrentX = 4"
        " Picture4.CurrentY = m4 Picture4.Print \"Y = θ 4(t)\" '关节 5 轨迹 '取值 a ="
        " Text17.Text b = Text22.Text c = 10 d = a + (3 / (c * c)) * (b - a) * (10 * 10)"
        " - (2 / (c * c * c)) * (b - a) * (10 * 10 * 10) If Val(a) > Val(d) Then m5 = a"
        " n5 = d Else m5 = d n5 = a End If '将函数显示在图形上"
    ),
    "",
    (
        "Picture5.Cls '清空画图区域 Picture5.Scale (0, m5 + (m5 - n5) / 5)-(12, n5)"
        " '设置画图区域 根据需要进行设置大小 Picture5.ForeColor = &H0 Picture5.DrawWidth"
        " = 1 '画 X 轴 44"
    ),
    "",
    (
        "Picture5.Line (0, n5)-(12, n5) '标记 t 轴 Picture5.CurrentX = 11.5"
        ' Picture5.CurrentY = n5 + (m5 - n5) / 10 Picture5.Print "t" \'画 Y 轴'
        " Picture5.Line (0, n5 - 5)-(0, m5 + (m5 - n5) / 5) '标记 Y 轴 Picture5.CurrentX"
        ' = 0.2 Picture5.CurrentY = m5 + (m5 - n5) / 5 Picture5.Print "Y" \'画坐标 For i'
        " = 1 To 10 Picture5.CurrentX = i: Picture5.CurrentY = n5 + (m5 - n5) / 10:"
        " Picture5.Print i Picture5.Line (i, n5)-(i, n5 + (m5 - n5) / 15) Next i"
    ),
    "",
    (
        "For j = 1 To 5 Picture5.Line (0, n5 + (m5 - n5) / 5 * j)-(0.1, n5 + (m5 - n5) /"
        " 5 * j) Picture5.CurrentX = 0.1: Picture5.CurrentY = n5 + (m5 - n5) / 5 * j:"
        " Picture5.Print Fix(n5 + ((m5 - n5) / 5) * j) Next j Picture5.DrawWidth = 2"
        " Picture5.Line (0, 0)-(0, 0) '归零收笔 '开始画图 For X = 0 To 10 Step 0.001"
        " '0.005 改小可以获得更高的精度 Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 /"
        " (c * c * c)) * (b - a) * (X * X * X) '输入函数 可以写入自己的函数"
        " Picture5.CurrentY = (m5 + n5) / 2 Picture5.CurrentX = 0.5 Picture5.PSet (X,"
        " Y), vbRed '标记 X,Y 轴 Next Picture5.CurrentX = 4 45"
    ),
    "",
    'Picture5.CurrentY = m5 Picture5.Print "Y = θ 5(t)" \'将函数显示在图形上',
    "",
    "End Sub",
    "",
    (
        'Private Sub Command4_Click() Text1.Text = "" Text2.Text = "" Text3.Text = ""'
        ' Text4.Text = "" Text5.Text = "" Text6.Text = "" Text7.Text = "" Text8.Text ='
        ' "" Text9.Text = "" Text10.Text = "" Text11.Text = "" Text12.Text = ""'
        ' Text13.Text = "" Text14.Text = "" Text15.Text = "" Text16.Text = ""'
        ' Text17.Text = "" Text18.Text = "" Text19.Text = "" Text20.Text = ""'
        ' Text21.Text = "" Text22.Text = ""'
    ),
    "",
    "End Sub",
    "",
)
"""Seed lines of the appendix listing, verbatim (one string per extracted line)."""

LISTING_EXTRACTED: str = "\n".join(_LISTING_EXTRACTED_LINES)
"""The VB6 listing exactly as extracted (seed lines 1001-1039: the heading
'轨迹规划界面 VB 程序如下:', page footers 36-45 inside the code, each page's lines joined)."""
