"""PERS data a task checked alone reads and never writes.

Tasks share their (non-TASK) PERS data by name; so does a PC through its
interfaces.  When only some tasks of a backup are loaded (``--task``), data
the loaded program reads but never writes keeps its initial value in every
run checked, although another task or a PC may write it on the controller.
``pers_warnings`` names each such data object (RMC731), so a verdict says
what it assumes.  A name counts as written when it is assigned to or passed
to any routine (an argument may be INOUT or PERS): the warning names only
data nothing in the program can change.
"""
from __future__ import annotations

from .. import ast
from ..diagnostics import PERS_UNWRITTEN, Diagnostic
from ..diagnostics.quoting import quoted
from ..semantics.configured_signals import walk_routine
from ..semantics.program import PROGRAM_NAMESPACE
from ..semantics.library import lookup_function, lookup_procedure
from ..semantics.library.motion import PLAIN_MOVES
from ..semantics.library.registry import matched_parameters, mode_may_write
from ..semantics.scope import GLOBAL_DATA, ROUTINE
from ..semantics.values import format_value

# routines that write data named by a string: then any persistent may be written
DATA_BY_NAME = frozenset({"SETDATAVAL", "SETALLDATAVAL"})


def pers_warnings(program, files) -> tuple:
    """RMC731 per shared PERS data object the task checked alone reads and never writes
    (none unless ``files`` loaded one task of a backup with several)."""
    if files.alone is None:
        return ()
    read, written = data_uses(program)
    found = []
    for data in program.globals:
        if data.namespace != PROGRAM_NAMESPACE or data.storage != "PERS" or data.task_local \
                or data.is_task_list or data.slot not in read or data.slot in written:
            continue
        chosen = (getattr(program, "outside_data", None) or {}).get(data.slot)
        reading = f"its reads take {chosen.describe()}, as data written outside the loaded " \
            "code" if chosen is not None else \
            f"the check assumes it keeps its initial value {_shown(data.initial)}"
        found.append(Diagnostic(
            PERS_UNWRITTEN, f"PERS {data.name} is read but never written by task {files.alone}, "
            f"checked alone: another task or a PC may write it; {reading}", data.span,
            severity="warning",
            notes=("check the backup's tasks together (without --task) to follow the "
                   "writes of the other tasks",)))
    return tuple(found)


def data_uses(program, namespace: int = PROGRAM_NAMESPACE,
              moves_read: bool = False) -> tuple[set, set]:
    """The global slots the routines of one task (its ``namespace``) name (read), and
    those they may write (assigned, or passed to a routine by reference), in their
    bodies and their handlers; ``moves_read``: the PERS data (tool, work object, load) a
    plain move (``motion.PLAIN_MOVES``) or a robot reading (``CRobT`` ...) is passed are
    read, not written, as those routines do (``_PERS_READ_ONLY``)."""
    read, written = set(), set()
    for routine in program.routines:
        if routine.namespace != namespace or routine.ast is None:
            continue
        lookup = routine.scope.lookup
        for node in walk_routine(routine.ast):      # (its handlers write too)
            if isinstance(node, ast.NameRef):
                read.add(_slot(lookup, node))
            elif isinstance(node, (ast.Assignment, ast.Connect)):
                written.add(_slot(lookup, _root(node.target)))
            elif isinstance(node, ast.LateBindingCall):      # a procedure named at run time
                written.update(_slot(lookup, _root(arg.value)) for arg in node.args
                               if arg.value is not None)
            elif isinstance(node, (ast.ProcedureCall, ast.FunctionCall)):
                modes = _parameter_modes(program, lookup, node)
                read_only = moves_read and node.name.key in _PERS_READ_ONLY and \
                    lookup(node.name.key) is None
                written.update(_slot(lookup, _root(arg.value))
                               for arg, mode in zip(node.args, modes)
                               if arg.value is not None and (
                                   mode_may_write(mode) or _writes_in_argument(lookup, node))
                               and not (read_only and mode == "PERS"))
    read.discard(None)
    written.discard(None)
    return read, written


# predefined routines whose PERS parameters (a tool, a work object, a load) are only read:
# the plain moves (the robot goes to the target with that tool) and the robot readings
# (``library.position``, ``CalcRobT``, ``CalcJointT``: computed with that tool)
_PERS_READ_ONLY = PLAIN_MOVES | {"CROBT", "CJOINTT", "CPOS", "CALCROBT", "CALCJOINTT"}


# predefined procedures writing an argument of an IN parameter: IDelete writes 0 to its
# intnum (``library.interrupts``)
_IN_ARGUMENT_WRITTEN = frozenset({"IDELETE"})


def _writes_in_argument(lookup, call) -> bool:
    return call.name.key in _IN_ARGUMENT_WRITTEN and lookup(call.name.key) is None


def writes_data_by_name(routines) -> bool:
    """Whether any of ``routines`` writes data named by a string (``SetDataVal``,
    ``SetAllDataVal``): then any persistent may be written."""
    return trees_write_by_name(routine.ast for routine in routines if routine.ast is not None)


def trees_write_by_name(trees) -> bool:
    """``writes_data_by_name`` of routines' syntax trees (``ast.Routine``)."""
    return any(isinstance(node, ast.ProcedureCall) and node.name.key in DATA_BY_NAME
               for tree in trees for node, _ in ast.walk(tree))


def _parameter_modes(program, lookup, call) -> list:
    """The mode (IN, VAR, INOUT, PERS, REF) of the parameter each argument of ``call``
    binds, None where it is not known (a late-bound or unknown routine)."""
    symbol = lookup(call.name.key)
    if symbol is not None and symbol.kind == ROUTINE:
        parameters = program.routines[symbol.slot].parameters
    else:
        entry = lookup_procedure(call.name.key) if isinstance(call, ast.ProcedureCall) \
            else lookup_function(call.name.key)
        if entry is None:
            return [None] * len(call.args)
        parameters = entry.signature.parameters
    return [parameter.mode.upper() if parameter is not None else None
            for _, parameter in matched_parameters(call.args, parameters)]


def _root(expr):
    """The NameRef an assignment target or argument starts from (None: not data)."""
    while expr is not None and not isinstance(expr, ast.NameRef):
        expr = getattr(expr, "base", None)
    return expr


def _slot(lookup, name_ref):
    if name_ref is None:
        return None
    symbol = lookup(name_ref.name.key)
    return symbol.slot if symbol is not None and symbol.kind == GLOBAL_DATA else None


def _shown(value) -> str:
    try:
        return format_value(value)
    except Exception:
        return quoted(repr(value))
