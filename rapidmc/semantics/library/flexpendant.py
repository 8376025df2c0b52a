"""The FlexPendant: writing, and answers read from the operator."""
from __future__ import annotations

from ... import ast
from ...diagnostics import BAD_INPUT_VALUE, error
from .. import values
from ..errors import ERROR_NUMBERS, RapidError
from ..instructions import Action, ControlAction
from ..machine import ABSENT
from .arguments import Arguments, argument_expression
from .environment_model import site_domain
from .registry import CHOICE, NO_EFFECT, compiled
from .signature_parts import TP_BREAKS

FUNCTION_KEYS = (1.0, 2.0, 3.0, 4.0, 5.0)
TP_OPTIONS = (("NUM", "num"), ("BOOL", "bool"), ("POS", "num"), ("ORIENT", "num"),
              ("DNUM", "dnum"))

NUMBER_ANSWERS = ("TPReadNum", "TPReadDnum")   # answers derived per site (load.message_domains)


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
    keys = [arguments.value(f"TPFK{i}") for i in range(1, 6)] if kind == "TPReadFK" else None
    breaks = TPBreaks(arguments)
    # keys written as "" or stEmpty in the source: no key is meant to be offered
    unlabelled = keys is not None and all(
        _written_empty(argument_expression(call, f"TPFK{i}", i + 1)) for i in range(1, 6))

    def read(m, instruction):
        outcomes = _outcomes(m, kind, keys, breaks, call.span, unlabelled)
        if not outcomes:
            m.waiting = True            # no key to press and nothing that ends the wait
            return
        m.output.append(text(m))
        value = m.choose(kind, outcomes)
        if not breaks.ended(m, value):
            m.write_ref(answer(m), convert(value))
        m.goto(instruction.next)
    return ControlAction(call.span, read)


def _outcomes(m, kind: str, keys, breaks: "TPBreaks", span, unlabelled: bool) -> tuple:
    """Check: every answer allowed (for TPReadFK, the labelled keys among them) and every
    break given; run: the answer on stdin, or with no labelled key the time limit.

    When labels computed from data are all empty and no break is given, the dialog could
    never be left; rapidmc then takes the labels for data it does not know (a stub's
    neutral "", a text table of a module not given) and offers every key, as it did before
    labels counted.  Only keys written empty in the source make such a dialog wait for ever."""
    if m.chooser.check_mode:
        allowed = m.chooser.tp_answers(kind)
        if kind in NUMBER_ANSWERS:     # --tp-answers given: kept in "answer_domains" too
            allowed = site_domain(m, span, None, "answer_domains", allowed)
        offered = allowed if keys is None else labelled_keys(m, keys, allowed)
        ends = breaks.outcomes(m)
        if not offered and not ends and not unlabelled:
            return allowed
        return offered + ends
    if keys is not None and not labelled_keys(m, keys, FUNCTION_KEYS):
        return breaks.time_limit(m) if unlabelled else m.chooser.tp_answers(kind)
    answer = m.chooser.tp_answers(kind)
    return answer if keys is None else checked_key(m, keys, answer, span)


def _written_empty(expression) -> bool:
    """``""`` or ``stEmpty`` as written in the source."""
    if isinstance(expression, ast.StringLiteral):
        return expression.value == ""
    return isinstance(expression, ast.NameRef) and expression.name.key == "STEMPTY"


def labelled_keys(m, keys, allowed: tuple) -> tuple:
    """The function keys (of ``allowed``) whose label is not empty: a key without a label
    (stEmpty) is not offered on the FlexPendant."""
    labels = [key(m) for key in keys]
    return tuple(k for k in allowed if 1 <= k <= 5 and k == int(k) and labels[int(k) - 1] != "")


def checked_key(m, keys, answer: tuple, span) -> tuple:
    """Run: the key read from stdin must be one the dialog offers."""
    offered = labelled_keys(m, keys, FUNCTION_KEYS)
    if answer[0] not in offered:
        shown = ", ".join(values.format_num(k) for k in offered) or "none"
        raise error(BAD_INPUT_VALUE, f"TPReadFK offers the keys with a label ({shown}), got "
                    f"{values.format_num(answer[0])}", span)
    return answer


class TPBreaks:
    """\\MaxTime, \\DIBreak, \\DOBreak and \\PersBoolBreak of TPReadNum/TPReadFK: each given
    one may end the dialog without an answer; the error is raised, or written to
    \\BreakFlag (and the answer left as it was)."""

    ERRORS = (("MaxTime", "ERR_TP_MAXTIME"), ("DIBreak", "ERR_TP_DIBREAK"),
              ("DOBreak", "ERR_TP_DOBREAK"), ("PersBoolBreak", "ERR_TP_PERSBOOLBREAK"))

    def __init__(self, arguments: Arguments):
        self.given = [(arguments.fn(key), name) for key, name in self.ERRORS]
        self.flag = arguments.fn("BreakFlag")
        self.max_time = arguments.value("MaxTime")

    def outcomes(self, m) -> tuple:
        return tuple(name for fn, name in self.given if fn(m) is not ABSENT)

    def time_limit(self, m) -> tuple:
        """Run mode, no key offered: \\MaxTime passes and ends the dialog (inputs do not
        change in run mode, so no other break comes)."""
        seconds = self.max_time(m)
        if seconds is ABSENT:
            return ()
        m.chooser.advance_time(m, seconds)
        return ("ERR_TP_MAXTIME",)

    def ended(self, m, value) -> bool:
        if not isinstance(value, str):
            return False
        flag = self.flag(m)
        if flag is ABSENT:
            raise RapidError(value, "the FlexPendant dialog ended without an answer")
        m.write_ref(flag, float(ERROR_NUMBERS[value]))
        return True


@compiled(f"TPReadNum(INOUT num TPAnswer, string TPText {TP_BREAKS})",
          f"TPReadDnum(INOUT dnum TPAnswer, string TPText {TP_BREAKS})",
          "TPReadFK(INOUT num TPAnswer, string TPText, string TPFK1, string TPFK2, string TPFK3, "
              f"string TPFK4, string TPFK5 {TP_BREAKS})",
          modelled=CHOICE)
def _tp_read_any(calls, compiler, call, entry):
    return _tp_read(calls, compiler, call, entry, entry.signature.name)
