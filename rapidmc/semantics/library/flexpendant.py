"""The FlexPendant: writing, and answers read from the operator."""
from __future__ import annotations

from .. import values
from ..instructions import Action
from ..machine import ABSENT
from .arguments import Arguments
from .registry import CHOICE, NO_EFFECT, compiled
from .signature_parts import TP_BREAKS

TP_OPTIONS = (("NUM", "num"), ("BOOL", "bool"), ("POS", "num"), ("ORIENT", "num"),
              ("DNUM", "dnum"))


@compiled("TPWrite(string String \\num Num | bool Bool | pos Pos | orient Orient | dnum Dnum)")
def _tp_write(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    text = arguments.fn("String")
    options = [(arguments.value(key), kind) for key, kind in TP_OPTIONS]

    def write(m):
        line = text(m)
        for fn, kind in options:
            value = fn(m)
            if value is not ABSENT:
                line += values.format_value(value, kind)
        m.output.append(line)
    return Action(call.span, write)


@compiled("TPErase()",
          modelled=NO_EFFECT)
def _tp_erase(calls, compiler, call, entry):
    Arguments(calls, compiler, call, entry)
    return Action(call.span, lambda m: None)


@compiled("ErrWrite(\\switch W | switch I, string Header, string Reason "
              "\\string RL2 \\string RL3 \\string RL4)",
          modelled=NO_EFFECT)
def _err_write(calls, compiler, call, entry):
    Arguments(calls, compiler, call, entry)
    return Action(call.span, lambda m: None)


def _tp_read(calls, compiler, call, entry, kind: str):
    arguments = Arguments(calls, compiler, call, entry)
    answer = arguments.fn("TPAnswer")
    text = arguments.fn("TPText")
    convert = values.to_dnum if kind == "TPReadDnum" else values.to_num

    def read(m):
        m.output.append(text(m))
        value = m.choose(kind, m.chooser.tp_answers(kind))
        m.write_ref(answer(m), convert(value))
    return Action(call.span, read)


@compiled(f"TPReadNum(INOUT num TPAnswer, string TPText {TP_BREAKS})",
          f"TPReadDnum(INOUT dnum TPAnswer, string TPText {TP_BREAKS})",
          "TPReadFK(INOUT num TPAnswer, string TPText, string TPFK1, string TPFK2, string TPFK3, "
              f"string TPFK4, string TPFK5 {TP_BREAKS})",
          modelled=CHOICE)
def _tp_read_any(calls, compiler, call, entry):
    return _tp_read(calls, compiler, call, entry, entry.signature.name)

