"""FlexPendant dialogs: UIMessageBox, UIMsgBox, UINumEntry, UINumTune, UIAlphaEntry,
UIListView, UIShow (and their dnum variants).

The operator's answer is the world's decision.  When model checking, every
button the dialog shows is a possible answer (a nondeterministic choice);
number entries take the ``--tp-answers`` values within the dialog's
\\MinValue..\\MaxValue; a dialog with \\MaxTime may also time out
(ERR_TP_MAXTIME, or written to \\BreakFlag).  In ``run`` each answer is one
line of standard input, like TPReadFK's: a button's number (its result
code, or its position in \\BtnArray), a number, or a text.
"""
from __future__ import annotations

from ...diagnostics import BAD_INPUT_VALUE, error
from .. import values
from ..errors import ERROR_NUMBERS, RapidError
from ..expressions import Compiled
from ..instructions import Action
from ..machine import ABSENT
from .arguments import Arguments, fixed, no_effect
from .data import PREDEFINED_DATA
from .environment_model import where
from .registry import CHOICE, FIXED, NO_EFFECT, compiled
from .sockets import environment_text

_TEXT = "\\string Header \\string Message | string MsgArray{*} \\switch Wrap"
_BREAKS = ("\\num MaxTime \\VAR signaldi DIBreak \\switch DIPassive \\VAR signaldo DOBreak "
           "\\switch DOPassive \\PERS bool PersBoolBreak \\switch PersBoolPassive "
           "\\VAR errnum BreakFlag")
TIMEOUT = "timeout"


def _value(name: str) -> float:
    return PREDEFINED_DATA[name.upper()].value


# buttondata -> the btnres answers its buttons give
BUTTON_RESULTS = {
    _value("btnNone"): (), _value("btnOK"): ("resOK",),
    _value("btnAbrtRtryIgn"): ("resAbort", "resRetry", "resIgnore"),
    _value("btnOKCancel"): ("resOK", "resCancel"), _value("btnRetryCancel"): ("resRetry", "resCancel"),
    _value("btnYesNo"): ("resYes", "resNo"), _value("btnYesNoCancel"): ("resYes", "resNo", "resCancel"),
}


def operator_answer(m, kind: str, span, domain: tuple, may_time_out: bool):
    """Check mode: one of ``domain`` (or TIMEOUT); run mode: a number read from stdin."""
    if m.chooser.check_mode:
        return m.choose(f"{kind} at {where(span)}", domain + ((TIMEOUT,) if may_time_out else ()))
    value = m.chooser.tp_answers(kind)[0]
    if domain and value not in domain:
        shown = ", ".join(values.format_num(v) for v in domain)
        raise error(BAD_INPUT_VALUE, f"{kind} answers are {shown}, got {values.format_num(value)}",
                    span)
    return value


class Dialog:
    """The arguments every dialog shares: time limit and break flag."""

    def __init__(self, arguments: Arguments):
        self.max_time = arguments.value("MaxTime")
        self.break_flag = arguments.fn("BreakFlag")

    def timed_out(self, m, answer) -> bool:
        """After a TIMEOUT answer: the flag is set, or ERR_TP_MAXTIME raised."""
        if answer != TIMEOUT:
            return False
        flag = self.break_flag(m)
        if flag is ABSENT:
            raise RapidError("ERR_TP_MAXTIME", "the operator did not answer within \\MaxTime")
        m.write_ref(flag, float(ERROR_NUMBERS["ERR_TP_MAXTIME"]))
        return True

    def may_time_out(self, m) -> bool:
        return self.max_time(m) is not ABSENT


def _button_domain(buttons, button_array) -> tuple:
    if button_array is not ABSENT:
        return tuple(float(i) for i, text in enumerate(button_array, start=1) if text)
    code = _value("btnOK") if buttons is ABSENT else buttons
    return tuple(_value(name) for name in BUTTON_RESULTS.get(code, ("resOK",)))


@compiled(f"btnres UIMessageBox({_TEXT} \\buttondata Buttons | string BtnArray{{*}} "
              f"\\btnres DefaultBtn \\icondata Icon \\string Image {_BREAKS} "
              "\\VAR signaldo UIActiveSignal)",
          modelled=CHOICE)
def _ui_message_box(calls, compiler, call, entry) -> Compiled:
    arguments = Arguments(calls, compiler, call, entry)
    dialog = Dialog(arguments)
    buttons, button_array = arguments.value("Buttons"), arguments.value("BtnArray")

    def answer(m):
        chosen = operator_answer(m, "UIMessageBox", call.span,
                                 _button_domain(buttons(m), button_array(m)), dialog.may_time_out(m))
        return _value("resUnkwn") if dialog.timed_out(m, chosen) else chosen
    return Compiled(answer, calls.return_type(entry))


# \Result (UIMsgBox, UIListView) is INOUT: the manual calls it "the variable" that gets the
# button, but controllers load PERS btnres data given to it (Production Manager menus, issue 19),
# and INOUT takes a variable or a persistent, as TPReadFK's answer does.
@compiled("UIMsgBox(\\string Header, string MsgLine1 \\string MsgLine2 \\string MsgLine3 "
              "\\string MsgLine4 \\string MsgLine5 \\switch Wrap \\buttondata Buttons "
              f"\\icondata Icon \\string Image \\INOUT btnres Result {_BREAKS})",
          modelled=CHOICE)
def _ui_msg_box(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    dialog = Dialog(arguments)
    buttons, result = arguments.value("Buttons"), arguments.fn("Result")

    def show(m):
        chosen = operator_answer(m, "UIMsgBox", call.span, _button_domain(buttons(m), ABSENT),
                                 dialog.may_time_out(m))
        if dialog.timed_out(m, chosen):
            chosen = _value("resUnkwn")
        target = result(m)
        if target is not ABSENT:
            m.write_ref(target, chosen)
    return Action(call.span, show)


def _number_entry(calls, compiler, call, entry, initial_key: str) -> Compiled:
    arguments = Arguments(calls, compiler, call, entry)
    dialog = Dialog(arguments)
    initial = arguments.value(initial_key)
    low, high = arguments.value("MinValue"), arguments.value("MaxValue")
    convert = values.to_dnum if entry.signature.return_type == "dnum" else values.to_num
    kind = entry.signature.name

    def within(m, number) -> bool:
        lo, hi = low(m), high(m)
        return (lo is ABSENT or number >= lo) and (hi is ABSENT or number <= hi)

    def answer(m):
        if m.chooser.check_mode:
            domain = tuple(v for v in m.chooser.tp_answers("TPReadNum") if within(m, v))
            start = initial(m)
            domain = domain or ((start,) if start is not ABSENT else (0.0,))
        else:
            domain = ()
        chosen = operator_answer(m, kind, call.span, domain, dialog.may_time_out(m))
        if dialog.timed_out(m, chosen):
            start = initial(m)
            return convert(0.0 if start is ABSENT else start)
        if not within(m, chosen):
            raise error(BAD_INPUT_VALUE, f"{kind}: {values.format_num(chosen)} is outside "
                        "\\MinValue..\\MaxValue", call.span)
        return convert(chosen)
    return Compiled(answer, calls.return_type(entry))


@compiled(f"num UINumEntry({_TEXT} \\icondata Icon \\num InitValue \\num MinValue "
              f"\\num MaxValue \\switch AsInteger {_BREAKS})",
          f"dnum UIDnumEntry({_TEXT} \\icondata Icon \\dnum InitValue \\dnum MinValue "
              f"\\dnum MaxValue \\switch AsInteger {_BREAKS})",
          modelled=CHOICE)
def _ui_num_entry(calls, compiler, call, entry) -> Compiled:
    return _number_entry(calls, compiler, call, entry, "InitValue")


@compiled(f"num UINumTune({_TEXT} \\icondata Icon, num InitValue, num Increment "
              f"\\num MinValue \\num MaxValue {_BREAKS})",
          f"dnum UIDnumTune({_TEXT} \\icondata Icon, dnum InitValue, dnum Increment "
              f"\\dnum MinValue \\dnum MaxValue {_BREAKS})",
          modelled=CHOICE)
def _ui_num_tune(calls, compiler, call, entry) -> Compiled:
    return _number_entry(calls, compiler, call, entry, "InitValue")


@compiled(f"string UIAlphaEntry({_TEXT} \\icondata Icon \\string InitString {_BREAKS})",
          modelled=CHOICE)
def _ui_alpha_entry(calls, compiler, call, entry) -> Compiled:
    """Run: a line of stdin; check: the initial text (one representative answer)."""
    arguments = Arguments(calls, compiler, call, entry)
    initial = arguments.value("InitString")

    def answer(m):
        start = initial(m)
        text = environment_text(m, "UIAlphaEntry", call.span, ("" if start is ABSENT else start,))
        if text is None:
            raise error(BAD_INPUT_VALUE, "UIAlphaEntry waits for a text but standard input has no "
                        "more lines", call.span)
        return values.checked_string(text)
    return Compiled(answer, calls.return_type(entry))


@compiled("num UIListView(\\INOUT btnres Result \\string Header, listitem ListItems{*} "
              "\\buttondata Buttons | string BtnArray{*} \\num DefaultIndex \\icondata Icon "
              f"{_BREAKS})",
          modelled=CHOICE)
def _ui_list_view(calls, compiler, call, entry) -> Compiled:
    """The chosen item's index (1..n); \\Result is resOK (the item was confirmed)."""
    arguments = Arguments(calls, compiler, call, entry)
    dialog = Dialog(arguments)
    items, result = arguments.value("ListItems"), arguments.fn("Result")

    def answer(m):
        domain = tuple(float(i) for i in range(1, len(items(m)) + 1))
        chosen = operator_answer(m, "UIListView", call.span, domain, dialog.may_time_out(m))
        timed_out = dialog.timed_out(m, chosen)
        target = result(m)
        if target is not ABSENT:
            m.write_ref(target, _value("resUnkwn" if timed_out else "resOK"))
        return 0.0 if timed_out else chosen
    return Compiled(answer, calls.return_type(entry))


compiled("UIShow(string AssemblyName, string TypeName \\string InitCmd "
             "\\VAR uishownum InstanceId \\VAR errnum Status \\switch NoCloseBtn)",
         modelled=NO_EFFECT)(no_effect)
compiled("bool UIClientExist()", modelled=FIXED)(fixed(True))


# --- reference coverage (issue 8, item 1): messages that wait for no answer ----------------
# Evidence: public RAPID code calls `UIMsgWriteAbort;` without arguments (a controller program
# in the index) and a public tutorial calls `UIMsgWrite "My Header", "Printed with
# UIMsgWrite...";` with a header and a message; ABB's OmniCore training slides say neither
# waits for the operator. Optional parameters of the manual are not known here, so calls
# with more arguments are rejected. Showing or removing the message changes nothing rapidmc
# observes.
compiled("UIMsgWrite(string Header, string Message)", "UIMsgWriteAbort()",
         modelled=NO_EFFECT)(no_effect)
