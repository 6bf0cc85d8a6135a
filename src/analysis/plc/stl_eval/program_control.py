"""Program control instructions of the S7-200: jumps, FOR/NEXT, CRET, END, STOP and CALL
(mixed into :class:`~.cpu.S7200`).

``JMP n``/``LBL n`` within one block [S2M, Jump]; ``FOR``/``NEXT``; ``CRET``, ``END``,
``STOP``. Subroutines by ``CALL`` with IN, IN_OUT, OUT parameters copied by value into the
callee's L memory from LB0 (bits packed, bytes/words/double words on byte boundaries) and
back after the return [manualshelf p.324]; at most 8 nested levels (error 0008: ENO = 0, the
call is not made) [same]; the logic stack is saved at the call, the callee starts with its
top = 1, and the stack is restored at the return (~ S7-200 System Manual, Call Subroutine;
page not retrieved). OUT and TEMP locals are not initialised at a call: they hold what the
last call at that depth left (~ tecnoplc.com). Sources as named in :mod:`.instructions`.
"""

from __future__ import annotations

import math

from analysis.plc.stl_eval.operands import F32, FMT

__all__ = ["EndScan", "ProgramControl", "Return", "Stop"]


class Stop(Exception):
    """The CPU went to STOP (a STOP instruction or a fatal error) during the scan."""


class Return(Exception):
    """CRET: back to the caller."""


class EndScan(Exception):
    """END: the rest of the main program is not run this scan."""


class ProgramControl:
    """The builders of the program control family."""

    def _b_jump(self, st, classes, o, pou, idx):
        target = pou.labels[o[0].value]
        cpu = self

        def f():
            return target if cpu.s & 1 else None

        return f

    def _b_label(self, st, classes, o, pou, idx):
        return lambda: None

    def _b_cret(self, st, classes, o, pou, idx):
        cpu = self

        def f():
            if cpu.s & 1:
                raise Return

        return f

    def _b_end(self, st, classes, o, pou, idx):
        cpu = self

        def f():
            if cpu.s & 1:
                raise EndScan

        return f

    def _b_wdr(self, st, classes, o, pou, idx):
        cpu = self

        def f():
            if cpu.s & 1:
                cpu._wdr = True  # the next budget overrun renews the budget (cpu.spend)

        return f

    def _b_stop(self, st, classes, o, pou, idx):
        cpu = self

        def f():
            if cpu.s & 1:
                cpu.stopped_by = f"STOP instruction at line {st.line} ({pou.block.label})"
                raise Stop

        return f

    def _b_for(self, st, classes, o, pou, idx):
        s_idx = self.setter(o[0], "I")
        g_idx = self.getter(o[0], "I")
        g_init, g_final = self.getter(o[1], "I"), self.getter(o[2], "I")
        # the matching NEXT
        depth, end = 0, None
        for k in range(idx + 1, len(pou.code)):
            op = pou.code[k][0].op
            if op == "FOR":
                depth += 1
            elif op == "NEXT":
                if depth == 0:
                    end = k
                    break
                depth -= 1
        cpu = self

        def f():
            if not cpu.s & 1:
                cpu.eno = 0
                return end + 1
            init, final = g_init(), g_final()
            s_idx(init)
            cpu.eno = 1
            if init > final:
                return end + 1
            cpu._for.append((idx, g_idx, s_idx, g_final))
            return None

        return f

    def _b_next(self, st, classes, o, pou, idx):
        cpu = self

        def f():
            if not cpu._for:
                return None
            start, g_idx, s_idx, g_final = cpu._for[-1]
            v = g_idx() + 1
            if v > 32767 or v > g_final():
                cpu._for.pop()
                if v <= 32767:
                    s_idx(v)
                return None
            s_idx(v)
            return start + 1

        return f

    def _b_call(self, st, classes, o, pou, idx):
        key, target, params, ops = o
        cpu = self
        getters, setters = [], []
        for (section, _name, typ, off, bit), op in zip(params, ops, strict=True):
            t = {
                "BOOL": "x",
                "BYTE": "B",
                "WORD": "W",
                "INT": "I",
                "DWORD": "D",
                "DINT": "L",
                "REAL": "R",
            }[typ]
            if typ == "REAL" and op.kind == "const":
                v = op.value
                getters.append((section, off, bit, t, lambda v=v: v))
            else:
                getters.append((section, off, bit, t, self.getter(op, "x" if t == "x" else t)))
            setters.append(self.setter(op, "x" if t == "x" else t) if section != "IN" else None)
        if key is None:
            lib = self.loaded.libraries.get(target.upper()) or self.loaded.libraries[target]
            n_in = len(lib.inputs)

            def body():
                args = [g() for _, _, _, _, g in getters[:n_in]]
                outs = lib.fn(*args)
                outs = outs if isinstance(outs, tuple) else (outs,)
                for s, v in zip(setters[n_in:], outs, strict=True):
                    try:
                        s(F32.unpack(F32.pack(v))[0])
                    except OverflowError:
                        s(math.copysign(math.inf, v))
                cpu.eno = 1

            return self._box(body, st, pou)
        callee = self.loaded.pous[key]
        caller, cost = f"{pou.block.kind}{pou.block.number}", len(callee.code)

        def body():
            cpu.spend(cost, caller, idx)  # the watchdog counts the subroutine's statements
            if cpu.depth >= 8:
                cpu.eno = 0  # error 0008: maximum subroutine nesting exceeded
                cpu.events.setdefault("nesting", 0)
                cpu.events["nesting"] += 1
                return
            frame = cpu.frames[cpu.depth + 1]
            for (section, _off, _bit, t, g), (_, _, _, loff, lbit) in zip(
                getters, callee.params, strict=True
            ):
                if section == "OUT":
                    continue
                v = g()
                if t == "x":
                    frame[loff] = (
                        frame[loff] | (1 << lbit) if v else frame[loff] & ~(1 << lbit) & 0xFF
                    )
                else:
                    FMT[t].pack_into(frame, loff, v)
            saved = cpu.s
            cpu.s = 1
            cpu.depth += 1
            try:
                cpu._run(key)
            except Return:
                pass
            finally:
                cpu.depth -= 1
                cpu.s = saved
            for (section, _off, _bit, t, _), s, (_, _, _, loff, lbit) in zip(
                getters, setters, callee.params, strict=True
            ):
                if section == "IN":
                    continue
                if t == "x":
                    s(frame[loff] >> lbit & 1)
                else:
                    s(FMT[t].unpack_from(frame, loff)[0])
            cpu.eno = 1

        return self._box(body, st, pou)
