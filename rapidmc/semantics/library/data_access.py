"""Data objects reached by name at run time: GetDataVal, SetDataVal, ErrRaise.

The name is looked up where the call is, as the controller does: the
routine's data, the module's, then the task's global data and the
predefined ones.  A name that is not data there raises ERR_SYM_ACCESS; data
of another type than the argument's raises ERR_SYMBOL_TYPE.

GetDataVal into signal data also finds the I/O signals of the controller's
configuration, as AliasIO does: ``GetDataVal "c"+ValToStr(n)+"DropWObj", doDrop``
connects ``doDrop`` to that configured output (ABB's own conveyor-tracking
modules name their ``c1..c6`` signals so).  With the backup's EIO.cfg loaded,
a name it does not configure raises ERR_SYM_ACCESS.  Without one, which
names are configured is not known: a name computed at run time that no
known signal has connects to a stand-in signal of that call, an input read
as a free one and a digital output read as one set outside the loaded code
(either value), so the verdicts rest on no value of it; the stand-in is
named under ``assumes:``.

Type names the data type of its argument, known when the program is linked; ArgName and
SetAllDataVal, which need the names of data at run time, stop the run (RMC305).
"""
from __future__ import annotations

from ... import ast
from ...diagnostics import ARGUMENT, error
from ..errors import RapidError
from ..instructions import Action
from ..machine import ABSENT, GLOBAL
from ..scope import CONSTANT, GLOBAL_DATA, SIGNAL
from ..expressions import constant
from ..types import SEMI_VALUE, STRING, RapidType, element_type, same_type
from .arguments import Arguments, argument_expression, fixed, no_effect, not_modelled
from .registry import FIXED, NO_EFFECT, NOT_MODELLED, compiled

_WHERE = "string Object \\VAR datapos Block | REF taskid TaskRef | string TaskName"


def named_data(scope, name: str, wanted_type, what: str):
    """The global data object or constant ``name`` visible in ``scope``: (symbol, ref or None)."""
    symbol = scope.lookup(name.upper())
    if symbol is None or symbol.kind not in (GLOBAL_DATA, CONSTANT):
        raise RapidError("ERR_SYM_ACCESS", f"{what}: no data object named '{name}' here")
    if wanted_type is not None and not same_type(symbol.type, wanted_type):
        raise RapidError("ERR_SYMBOL_TYPE", f"{what}: '{name}' is {symbol.type}, not {wanted_type}")
    if symbol.kind == CONSTANT:
        return symbol, None
    return symbol, (GLOBAL, symbol.slot, ())


def _value_reference(compiler, call, what: str):
    target = argument_expression(call, "Value", 1)
    if target is None:
        raise error(ARGUMENT, f"{call.name.text} needs a Value", call.span)
    return compiler.reference(target, what)


@compiled(f"GetDataVal({_WHERE}, VAR anytype Value)")
def _get_data_val(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    name = arguments.value("Object")
    value_ref, value_type, _ = _value_reference(compiler, call, "written by GetDataVal")
    scope = compiler.scope
    if isinstance(value_type, RapidType) and value_type.kind == SEMI_VALUE and \
            value_type.signal_kind:
        signal = _named_signal(compiler, call, value_type)

        def get_signal(m):
            m.write_ref(value_ref(m), signal(m, name(m)))
        return Action(call.span, get_signal)

    def get(m):
        symbol, ref = named_data(scope, name(m), value_type, "GetDataVal")
        m.write_ref(value_ref(m), symbol.value if ref is None else m.read_ref(ref))
    return Action(call.span, get)


def _named_signal(compiler, call, signal_type: RapidType):
    """``(m, name) -> signal index`` for GetDataVal into data of ``signal_type``: signal data
    of that name, else the configured signal, else (no EIO.cfg loaded, a name computed at
    run time) the call's stand-in signal; ERR_SYM_ACCESS when none is."""
    linker, scope, kind = compiler.linker, compiler.scope, signal_type.signal_kind
    configured = bool(linker.options.get("configured_signals"))
    source = compiler.value(argument_expression(call, "Object", 0))
    stand_in = None
    if source.is_constant:
        symbol = scope.lookup(source.constant.upper())
        if symbol is None and not configured:      # a name used as a signal: configured
            linker.note_signal_named(linker.physical_signal(source.constant, kind,
                                                            call.span).index)
        elif symbol is not None and symbol.kind == SIGNAL:
            linker.note_signal_named(symbol.slot)
    elif configured:
        linker.note_signal_named(None)             # any configured signal may be named
    else:
        where = f"{call.span.file.rsplit('/', 1)[-1]}:{call.span.line}"
        stand_in = linker.physical_signal(f"[GetDataVal at {where}]", kind, call.span)
        if kind == "DO":
            stand_in.outside = ("whichever configured signal that call names at run time "
                                "(no EIO.cfg is loaded)")
        linker.note_signal_named(stand_in.index)

    def index(m, name: str) -> int:
        symbol = scope.lookup(name.upper())
        if symbol is not None and symbol.kind == SIGNAL:
            found = m.program.signal_index.get(name.upper())
            if found.kind != kind:
                raise RapidError("ERR_SYMBOL_TYPE", f"GetDataVal: signal {found.name} is a "
                                 f"{found.kind}, not a {kind}")
            return found.index
        if symbol is None and stand_in is not None:
            return stand_in.index
        found, ref = named_data(scope, name, signal_type, "GetDataVal")
        return found.value if ref is None else m.read_ref(ref)
    return index


@compiled(f"SetDataVal({_WHERE}, anytype Value)")
def _set_data_val(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    name, value = arguments.value("Object"), arguments.value("Value")
    value_type = compiler.value(argument_expression(call, "Value", 1)).type
    scope = compiler.scope

    def set_value(m):
        symbol, ref = named_data(scope, name(m), value_type, "SetDataVal")
        if ref is None:
            raise RapidError("ERR_SYM_ACCESS", f"SetDataVal: '{symbol.name}' is a constant")
        m.write_ref(ref, value(m))
    return Action(call.span, set_value)


@compiled("ErrRaise(\\switch W, string ErrorName, num ErrorId, errstr Title, errstr Str1, "
              "errstr Str2, errstr Str3, errstr Str4 \\errstr Str5)")
def _err_raise(calls, compiler, call, entry):
    """Logs and raises the error number held by the errnum data named ErrorName (booked
    with BookErrNo); with \\W it only logs (the log is not modelled)."""
    arguments = Arguments(calls, compiler, call, entry)
    name, warning = arguments.value("ErrorName"), arguments.value("W")
    scope = compiler.scope

    def raise_error(m):
        if warning(m) is True:
            return
        symbol, ref = named_data(scope, name(m), None, "ErrRaise")
        number = symbol.value if ref is None else m.read_ref(ref)
        if number is ABSENT or not number:
            raise RapidError("ERR_ILLRAISE", f"ErrRaise: '{name(m)}' holds no error number")
        raise RapidError(int(number), f"raised by ErrRaise \"{name(m)}\"")
    return Action(call.span, raise_error)


# Searching the program's data by type and name pattern: the search finds nothing (rapidmc
# keeps no symbol table at run time), so GetNextSym answers FALSE.
compiled("SetDataSearch(string Type \\string TypeMod \\string Object \\switch PersSym "
             "\\switch VarSym \\switch ConstSym \\switch InTask | string InMod "
             "\\string InRout \\switch GlobalSym | switch LocalSym)",
         modelled=NO_EFFECT)(no_effect)
compiled("bool GetNextSym(INOUT string Object, VAR datapos Block \\switch Recursive)",
         modelled=FIXED)(fixed(False))


# --- reference coverage (issue 8, item 1) -------------------------------------------------

@compiled("string Type(anytype Data \\switch BaseName)")
def _type(calls, compiler, call, entry):
    """The name of the argument's data type, known when the program is linked (of an array:
    its element type).  rapidmc resolves alias types to their base type, so an alias gives
    the base type's name with or without \\BaseName."""
    Arguments(calls, compiler, call, entry)
    data = argument_expression(call, "Data", 0)
    if data is None:
        raise error(ARGUMENT, "Type takes one data object", call.span)
    rapid_type = element_type(_declared_type(compiler, data))
    if rapid_type is None:
        raise error(ARGUMENT, "Type cannot tell the type of this argument", data.span)
    return constant(rapid_type.name, STRING)


def _declared_type(compiler, data):
    """The declared type of a named data object (a signal's is its signal type, not the value
    read from it), else the type of the expression's value."""
    if isinstance(data, ast.NameRef):
        symbol = compiler.scope.lookup(data.name.key) or compiler.linker.system_symbol(data.name)
        if symbol is not None and symbol.type is not None:
            return symbol.type
    return compiler.value(data).type


compiled("string ArgName(anytype Parameter \\VAR errnum ErrorNumber)",
         modelled=NOT_MODELLED)(not_modelled("names the data given for a parameter, which "
                                             "rapidmc does not keep at run time"))
compiled("SetAllDataVal(string Type \\string TypeMod \\string Object \\switch Hidden, "
             "anytype Value)",
         modelled=NOT_MODELLED)(not_modelled("sets every data object of a type found by a "
                                             "pattern, which rapidmc does not model"))
