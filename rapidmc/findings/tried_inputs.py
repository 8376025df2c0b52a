"""The inputs a check tried only some values of: what "never reached" and vacuity rest on.

A complete search shows what happens for the values each input was offered.
For most inputs those are all the values the program can tell apart (digital
inputs, TPReadFK buttons, derived analog and group domains, socket messages
that are only compared with strings).  Others were given a sample: socket
messages the program parses or searches, lines of files, numbers typed on the
FlexPendant.  Code that is never reached in such a check may still be reached
by another message, line or answer, so its warning says "with the ... tried"
and names the reading instruction instead of "under any input".

An input counts when its reading instruction ran in the search (an input the
program never reads cannot explain anything), and only for code some call could
reach: a routine that no entry, TRAP or late-bound call leads to is never
reached under any input (``called_routines``).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Iterable, Optional, Sequence

from .. import ast
from ..semantics.program import ENVIRONMENT_NAMESPACE, Program

# instruction or function (canonical name) -> what a check offers it only some of
SAMPLED = {
    "SOCKETRECEIVE": "socket messages", "SOCKETRECEIVEFROM": "socket messages",
    "READSTR": "file lines", "READNUM": "file lines", "READBIN": "file lines",
    "READANYBIN": "file lines", "READSTRBIN": "file lines", "READRAWBYTES": "file lines",
    "TPREADNUM": "FlexPendant answers", "TPREADDNUM": "FlexPendant answers",
    "UINUMENTRY": "FlexPendant answers", "UIDNUMENTRY": "FlexPendant answers",
    "UINUMTUNE": "FlexPendant answers", "UIDNUMTUNE": "FlexPendant answers",
    "UIALPHAENTRY": "FlexPendant answers",
}


@dataclass(frozen=True)
class TriedInput:
    """A reading instruction whose input the check offered only a sample of values."""

    kind: str                  # "socket messages"
    instruction: str           # "SocketReceive", as written
    span: ast.Span


def sampled_inputs(program: Program, exact: Iterable[tuple] = ()) -> tuple:
    """Every reading instruction of the program's code whose input is sampled, in source
    order; ``exact``: (file, line, column) of sites whose domain covers every value."""
    exact = set(exact)
    found = []
    for routine in program.routines:
        if routine.ast is None or routine.namespace == ENVIRONMENT_NAMESPACE:
            continue                # every task's code: the environment model is no input
        for node, _ in ast.walk(routine.ast):
            if isinstance(node, (ast.ProcedureCall, ast.FunctionCall)) \
                    and node.name.key in SAMPLED \
                    and (node.span.file, node.span.line, node.span.column) not in exact:
                found.append(TriedInput(SAMPLED[node.name.key], node.name.text, node.span))
    return tuple(sorted(set(found), key=lambda t: (t.span.file, t.span.line, t.span.column)))


def reached(inputs: Sequence[TriedInput], executed: set) -> tuple:
    """The inputs whose reading instruction ran (``executed``: (file, line) pairs)."""
    return tuple(t for t in inputs if (t.span.file, t.span.line) in executed)


def called_routines(program: Program) -> Optional[frozenset]:
    """Names of the routines some chain of calls from an entry routine or a TRAP reaches
    (None: a late-bound call may name any routine).  Calls are matched by name, across
    tasks and modules: a name reaches every routine so named."""
    by_name: dict[str, list] = {}
    for routine in program.routines:
        if routine.ast is not None:
            by_name.setdefault(routine.key, []).append(routine)
    starts = [program.routines[i] for i in (program.entry, *program.task_entries)
              if isinstance(i, int)]
    pending = starts + [r for r in program.routines if r.ast is not None and r.kind == "TRAP"]
    seen: set = set()
    while pending:
        routine = pending.pop()
        if routine.index in seen or routine.ast is None:
            continue
        seen.add(routine.index)
        for node, _ in ast.walk(routine.ast):
            if isinstance(node, ast.LateBindingCall) or (
                    isinstance(node, ast.ProcedureCall) and node.name.key == "CALLBYVAR"):
                return None
            if isinstance(node, (ast.ProcedureCall, ast.FunctionCall)):
                pending.extend(by_name.get(node.name.key, ()))
            elif isinstance(node, ast.Connect):
                pending.extend(by_name.get(node.trap.key, ()))
    return frozenset(program.routines[index].name for index in seen)


def qualifier(inputs: Sequence[TriedInput]) -> str:
    """``under any input``, or ``with the socket messages tried (SocketReceive at line 191)``."""
    if not inputs:
        return "under any input"
    kinds = list(dict.fromkeys(t.kind for t in inputs))
    kinds_text = kinds[0] if len(kinds) == 1 else ", ".join(kinds[:-1]) + " and " + kinds[-1]
    places = []
    for name in dict.fromkeys(t.instruction for t in inputs):
        lines = sorted({t.span.line for t in inputs if t.instruction == name})
        places.append(f"{name} at line{'s' if len(lines) > 1 else ''} "
                      + ", ".join(map(str, lines)))
    return f"with the {kinds_text} tried ({'; '.join(places)})"
