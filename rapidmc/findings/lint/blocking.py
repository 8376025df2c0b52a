"""RMC804 (socket and file operations left unguarded) and RMC805 (an endless loop that
never waits): what a program does about time spent outside itself."""
from __future__ import annotations

from ... import ast
from ...diagnostics import BUSY_LOOP, IO_UNGUARDED, Diagnostic
from ...semantics.library import lookup_function, lookup_procedure
from .context import nested_bodies, subexpressions, top_expressions
from .registry import rule

SOCKET_OPERATIONS = {"SOCKETCONNECT", "SOCKETACCEPT", "SOCKETRECEIVE", "SOCKETRECEIVEFROM",
                     "SOCKETSEND", "SOCKETSENDTO", "SOCKETBIND", "SOCKETLISTEN"}
FILE_OPERATIONS = {"OPEN", "READSTR", "READNUM", "READBIN", "READSTRBIN", "READRAWBYTES",
                   "READANYBIN", "WRITE", "WRITESTRBIN", "WRITEBIN", "WRITERAWBYTES",
                   "WRITEANYBIN"}
SOCKET_ERRORS = ("ERR_SOCK_",)
FILE_ERRORS = ("ERR_FILEOPEN", "ERR_FILEACC", "ERR_FILNOTFND", "ERR_FILEEXIST", "ERR_FILEEOF",
               "ERR_DEV_MAXTIME", "ERR_RCVDATA", "ERR_FILESIZE")


def io_operations(context):
    """(call node, routine, module, error-name prefixes) of each socket or file operation."""
    for site in context.calls:
        key = site.statement.name.key
        if key in SOCKET_OPERATIONS or key in FILE_OPERATIONS:
            yield site.statement, site.routine, site.module, _errors_of(key)
    for call, site, routine, module in context.of_type(ast.FunctionCall):
        if call.name.key in FILE_OPERATIONS and routine is not None:
            yield call, routine, module, _errors_of(call.name.key)


def _has_time_parameter(key: str) -> bool:
    entry = lookup_procedure(key) or lookup_function(key)
    return entry is not None and entry.signature.parameter("TIME") is not None


def _errors_of(key: str) -> tuple:
    return SOCKET_ERRORS if key in SOCKET_OPERATIONS else FILE_ERRORS


@rule(IO_UNGUARDED, "warning",
      bad="""
          MODULE M
            VAR socketdev client;
            PROC main()
              VAR string message;
              SocketReceive client \\Str:=message;
            ENDPROC
          ENDMODULE
          """,
      good="""
          MODULE M
            VAR socketdev client;
            PROC main()
              VAR string message;
              SocketReceive client \\Str:=message \\Time:=5;
            ERROR
              IF ERRNO = ERR_SOCK_TIMEOUT THEN
                RETRY;
              ENDIF
            ENDPROC
          ENDMODULE
          """,
      why="Without \\Time a socket or file read waits up to 60 s (sockets) or forever; "
          "without an ERROR handler a closed connection, a timeout or a missing file stops "
          "the program.")
def io_unguarded(context):
    for call, routine, module, errors in io_operations(context):
        timed = any(a.name is not None and a.name.key == "TIME" for a in call.args)
        if timed or _handled(context, routine, errors, set()):
            continue
        waits = _has_time_parameter(call.name.key)
        missing = "no \\Time and no" if waits else "no"
        handle = "give \\Time, or handle " if waits else "handle "
        errors_text = ("ERR_SOCK_TIMEOUT and ERR_SOCK_CLOSED" if errors is SOCKET_ERRORS
                       else "ERR_FILEOPEN, ERR_FILEACC, ERR_DEV_MAXTIME")
        yield Diagnostic(
            IO_UNGUARDED, f"{call.name.text} has {missing} ERROR handler of "
            f"{routine.name.text} (or of its callers) that handles its errors",
            call.name.span, severity="warning",
            notes=(f"{handle}{errors_text} in an ERROR handler",))


def _handled(context, routine: ast.Routine, errors: tuple, seen: set) -> bool:
    """Does the ERROR handler of ``routine``, or of every routine calling it, handle them?"""
    if routine.error is not None and handler_covers(routine.error, errors):
        return True
    if id(routine) in seen:
        return False
    seen.add(id(routine))
    callers = context.callers.get(routine.name.key, [])
    return bool(callers) and all(_handled(context, caller, errors, seen) for caller in callers)


def handler_covers(handler: ast.ErrorHandler, errors: tuple) -> bool:
    """A handler covers errors when it lists none of its own or lists one of them, and its
    body tests none or one of them (a handler of ERR_DIVZERO only handles ERR_DIVZERO)."""
    names = set()
    for statement in _statements(handler.body):
        for top in top_expressions(statement):
            names.update(e.name.key for e in subexpressions(top) if type(e) is ast.NameRef
                         and e.name.key.startswith("ERR_"))
    if handler.numbers is not None:
        names.update(e.name.key for e in handler.numbers if type(e) is ast.NameRef)
    return not names or any(name.startswith(errors) for name in names)


def _statements(body):
    for statement in body:
        yield statement
        for inner, _ in nested_bodies(statement):
            yield from _statements(inner)


# ------------------------------------------------------------------ busy loops

WAITING_TOPICS = {"waits", "motion", "arc_welding", "search", "conveyor", "flexpendant",
                  "flexpendant_ui", "message_queues"}
WAITING_ROUTINES = {"SOCKETACCEPT", "SOCKETRECEIVE", "SOCKETRECEIVEFROM", "READSTR",
                    "READNUM", "READBIN", "READSTRBIN", "READRAWBYTES", "READANYBIN", "STOP",
                    "BREAK", "EXITCYCLE", "WAITSYNCTASK", "WAITTESTANDSET", "WAITLOAD",
                    "SYNCMOVEON", "SYNCMOVEOFF", "STOPMOVE"}


@rule(BUSY_LOOP, "warning",
      bad="""
          MODULE Watch
            PERS num count := 0;
            PROC main()
              WHILE TRUE DO
                IF DInput(di_door) = 1 count := count + 1;
              ENDWHILE
            ENDPROC
          ENDMODULE
          """,
      good="""
          MODULE Watch
            PERS num count := 0;
            PROC main()
              WHILE TRUE DO
                IF DInput(di_door) = 1 count := count + 1;
                WaitTime 0.05;
              ENDWHILE
            ENDPROC
          ENDMODULE
          """,
      why="A background (non-motion) task's main loop runs as fast as the controller lets "
          "it: without a wait it takes processor time from the motion task and floods "
          "whatever it writes.")
def busy_loop(context):
    loops = [site.statement for site in context.sites
             if type(site.statement) is ast.While and _endless(site.statement.condition)]
    if not loops:
        return
    waiting = context.waiting_routines(_waits)
    for loop in loops:
        if not _body_waits(loop.body, waiting):
            yield Diagnostic(
                BUSY_LOOP, "this endless loop never waits (no WaitTime, WaitUntil, move or "
                "blocking read in it or the routines it calls): it runs flat out",
                loop.span, severity="warning")


def _endless(condition) -> bool:
    return type(condition) is ast.BoolLiteral and condition.value


def _waits(statement, waiting: set) -> bool:
    """Does this one statement (not the statements in it) wait, or call a routine that does?"""
    kind = type(statement)
    if kind is ast.ProcedureCall:
        key = statement.name.key
        if key in waiting or key in WAITING_ROUTINES:
            return True
        entry = lookup_procedure(key)
        if entry is not None and entry.topic in WAITING_TOPICS:
            return True
    elif kind is ast.LateBindingCall:
        return True                      # the routine is chosen at run time: assume it may
    for top in top_expressions(statement):
        for expression in subexpressions(top):
            if type(expression) is ast.FunctionCall:
                key = expression.name.key
                if key in waiting or key in WAITING_ROUTINES:
                    return True
                entry = lookup_function(key)
                if entry is not None and entry.topic in WAITING_TOPICS:
                    return True
    return False


def _body_waits(body, waiting: set) -> bool:
    return any(_waits(statement, waiting) for statement in _statements(body))
