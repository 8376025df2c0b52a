"""RMC820: input from outside reaching a sensitive argument without a check on the way.

A static taint analysis over the syntax tree (after Pogliani et al., "Detecting
Insecure Code Patterns in Industrial Robot Programs", AsiaCCS 2020):

* sources: what a socket, a file or serial channel, the FlexPendant or an analog or
  group input delivers (``SOURCE_OUTPUTS``, ``SOURCE_FUNCTIONS``, signals declared
  ``signalai``/``signalgi`` read by name);
* propagation: an assignment taints its target (the whole data object, components
  and elements alike) when its value reads tainted data; a predefined routine's
  by-reference arguments (StrToVal's ``Val``, UnpackRawBytes's ``Value``) and its
  result when another argument is tainted; a user routine's parameters from its
  arguments, its by-reference arguments from its parameters and its calls from its
  RETURN values;
* sanitiser: a comparison that bounds the data (``<``, ``<=``, ``>``, ``>=``, ``=``,
  or TEST) in a condition around the use, or in an earlier IF of the routine that
  leaves it; a comparison's own result is never tainted;
* sinks (``sink_parameters``): a move instruction's target, speed, zone, tool and
  work object; a file or directory path; CallByVar and ``%name%`` calls; the value of
  SetDO, SetGO, SetAO (and of the moves that set outputs).

The analysis is flow-insensitive within a routine (a datum once tainted is tainted at
every use that no check guards) and context-insensitive across routines.  ``check
--flows`` verifies the same flows on the state graph (docs/checking.md, "Unchecked
input flows").
"""
from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Optional

from ... import ast
from ...diagnostics import UNCHECKED_INPUT, Diagnostic
from ...semantics.library import lookup_function, lookup_procedure
from .arguments import bind_predefined, bind_user
from .context import name_of, subexpressions, top_expressions
from .registry import rule
from .checks import checked

# procedure -> (what delivers the data, the parameters it writes)
SOURCE_OUTPUTS = {
    "SOCKETRECEIVE": ("a socket", ("STR", "RAWDATA", "DATA")),
    "SOCKETRECEIVEFROM": ("a socket", ("STR", "RAWDATA", "DATA")),
    "READRAWBYTES": ("a file or serial channel", ("RAWDATA",)),
    "READANYBIN": ("a file or serial channel", ("DATA",)),
    "TPREADNUM": ("the FlexPendant", ("TPANSWER",)),
    "TPREADDNUM": ("the FlexPendant", ("TPANSWER",)),
    "TPREADFK": ("the FlexPendant", ("TPANSWER",)),
}
SOURCE_FUNCTIONS = {
    "READSTR": "a file or serial channel", "READNUM": "a file or serial channel",
    "READBIN": "a file or serial channel", "READSTRBIN": "a file or serial channel",
    "UINUMENTRY": "the FlexPendant", "UINUMTUNE": "the FlexPendant",
    "UIALPHAENTRY": "the FlexPendant", "UILISTVIEW": "the FlexPendant",
    "AINPUT": "an analog input", "GINPUT": "a group input", "GINPUTDNUM": "a group input",
}
SOURCE_SIGNAL_TYPES = {"SIGNALAI": "an analog input", "SIGNALGI": "a group input"}
_DEVICES = ("iodev", "socketdev", "dir", "signaldo", "signalgo", "signalao", "signaldi",
            "signalgi", "signalai")

MOTION_TYPES = {"robtarget": "target", "jointtarget": "target", "speeddata": "speed",
                "zonedata": "zone", "tooldata": "tool", "wobjdata": "work object"}
MOTION_OVERRIDES = {"V": "speed", "T": "time", "Z": "zone"}
PATH_ROUTINES = {"OPEN": ("OBJECT", "FILE"), "LOAD": ("FILEPATH", "FILE"),
                 "STARTLOAD": ("FILEPATH", "FILE"), "UNLOAD": ("FILEPATH", "FILE"),
                 "SAVE": ("FILEPATH", "FILE"), "ERASEMODULE": ("MODULENAME",)}
OUTPUT_ROUTINES = {"SETDO", "SETGO", "SETAO"}


@functools.lru_cache(maxsize=None)
def written_parameters(key: str, procedure: bool) -> frozenset:
    """The keys of the parameters through which a predefined routine writes data
    (INOUT and VAR, devices and signals left out): they take the taint of its inputs."""
    entry = (lookup_procedure if procedure else lookup_function)(key)
    if entry is None or entry.signature.open_parameters:
        return frozenset()
    return frozenset(p.key for p in entry.signature.parameters
                     if p.mode in ("INOUT", "VAR") and p.type_name not in _DEVICES)


def predefined_data_flow(call, procedure: bool) -> tuple[list, list]:
    """(input expressions, written argument expressions) of a call of a predefined routine
    that writes through its arguments: the written ones take the taint of the inputs."""
    outputs = written_parameters(call.name.key, procedure)
    if not outputs:
        return [], []
    bound = bind_predefined(call, procedure)
    inputs = [argument.value for parameter, argument in bound.items()
              if parameter not in outputs and argument.value is not None]
    written = [bound[parameter].value for parameter in outputs
               if parameter in bound and bound[parameter].value is not None]
    return inputs, written


@functools.lru_cache(maxsize=None)
def sink_parameters(key: str) -> dict[str, str]:
    """Parameter key -> what it is (``target``, ``file path`` ...) for a predefined
    procedure's sensitive parameters (empty when it has none)."""
    if key == "CALLBYVAR":
        return {"NAME": "routine name", "NUMBER": "routine number"}
    if key in PATH_ROUTINES:
        return {parameter: "file path" for parameter in PATH_ROUTINES[key]}
    entry = lookup_procedure(key)
    if entry is None:
        return {}
    parameters = entry.signature.parameters
    if entry.topic == "file_system":
        return {p.key: "file path" for p in parameters if p.type_name == "string"}
    found = {}
    moves = any(p.type_name in ("robtarget", "jointtarget") for p in parameters)
    if moves:
        for p in parameters:
            if p.type_name in MOTION_TYPES:
                found[p.key] = MOTION_TYPES[p.type_name]
            elif p.key in MOTION_OVERRIDES and p.type_name == "num":
                found[p.key] = MOTION_OVERRIDES[p.key]
    if moves or key in OUTPUT_ROUTINES:
        for p in parameters:
            if p.key in ("VALUE", "DVALUE") and p.mode == "IN":
                found[p.key] = "output value"
    return found


@dataclass(frozen=True)
class Origin:
    """How a datum got tainted: where, what happened there, and the datum it came from."""

    span: ast.Span
    step: str
    parent: Optional["Origin"] = None      # how the datum it came from got tainted
    source: str = ""                       # what delivered the input


class TaintAnalysis:
    """The tainted data of a program, each with the first way found it got tainted."""

    MAX_ROUNDS = 50

    def __init__(self, context, sanitise: bool = True, every_round_everything: bool = False):
        self.context = context
        self.sanitise = sanitise
        self.every_round_everything = every_round_everything    # (the tests' reference)
        self.tainted: dict[object, Origin] = {}
        self.returns: dict[str, Origin] = {}        # user function key -> tainted RETURN
        self._writes: dict[int, frozenset] = {}
        self._names: dict[object, tuple] = {}       # taint key -> the names that mention it
        self._mentioned: dict[int, frozenset] = {}
        self._fresh: set = set()
        self._run()

    # ------------------------------------------------------------ keys
    def key(self, name: ast.Name, routine, module):
        declaration = self.context.declaration(name.key, routine, module)
        key = id(declaration) if declaration is not None else ("?", name.key)
        if isinstance(declaration, ast.Parameter):      # its callers read it back
            self._names[key] = (name.key, routine.name.key)
        else:
            self._names[key] = (name.key,)
        return key

    # ------------------------------------------------------------ fixpoint
    def _run(self) -> None:
        """Visit every statement, then again only those that name something tainted in
        the round before, until nothing new is tainted."""
        pending = self.context.sites
        for _ in range(self.MAX_ROUNDS):
            self._fresh = set()
            for site in pending:
                self._visit(site)
            if not self._fresh:
                return
            fresh = self._fresh
            pending = self.context.sites if self.every_round_everything else \
                [site for site in self.context.sites if self._mentions(site) & fresh]

    def _mentions(self, site) -> frozenset:
        """The names a statement mentions: data, routines it calls (their parameters and
        results carry taint to and from it)."""
        found = self._mentioned.get(id(site))
        if found is None:
            names = set()
            statement = site.statement
            if type(statement) is ast.ProcedureCall:
                names.add(statement.name.key)
            for top in top_expressions(statement):
                for expression in subexpressions(top):
                    kind = type(expression)
                    if kind is ast.NameRef or kind is ast.FunctionCall:
                        names.add(expression.name.key)
            if site.routine.kind == ast.FUNC or site.routine.parameters:
                names.add(site.routine.name.key)      # its parameters, its result
            found = self._mentioned[id(site)] = frozenset(names)
        return found

    def _taint(self, key, origin: Origin) -> None:
        if key not in self.tainted:
            self.tainted[key] = origin
            self._fresh.update(self._names.get(key, ()))

    def _visit(self, site) -> None:
        statement = site.statement
        kind = type(statement)
        if kind is ast.Assignment:
            found = self.expression_taint(statement.value, site)
            name = name_of(statement.target)
            if found is not None and name is not None:
                self._taint(self.key(name, site.routine, site.module),
                            Origin(statement.span, f"{name.text} is assigned from it",
                                   found, found.source))
        elif kind is ast.ProcedureCall:
            self._call(statement, site, procedure=True)
        elif kind is ast.Return and statement.value is not None \
                and site.routine.kind == ast.FUNC:
            found = self.expression_taint(statement.value, site)
            if found is not None and site.routine.name.key not in self.returns:
                self.returns[site.routine.name.key] = Origin(
                    statement.span, f"{site.routine.name.text} returns it", found,
                    found.source)
                self._fresh.add(site.routine.name.key)
        for call in self.context.function_calls(site):
            self._call(call, site, procedure=False)

    def _call(self, call, site, procedure: bool) -> None:
        key = call.name.key
        if procedure and key in SOURCE_OUTPUTS:
            what, outputs = SOURCE_OUTPUTS[key]
            bound = bind_predefined(call)
            for parameter in outputs:
                argument = bound.get(parameter)
                name = name_of(argument.value) if argument and argument.value else None
                if name is not None:
                    self._taint(self.key(name, site.routine, site.module), Origin(
                        call.span, f"{call.name.text} reads {name.text} from {what}",
                        None, what))
            return
        user = self.context.routines.get(key)
        if user is not None:
            self._user_call(call, user, site)
            return
        inputs, outputs = predefined_data_flow(call, procedure)
        if not outputs:
            return
        found = self._first_tainted(inputs, site)
        if found is None:
            return
        for output in outputs:
            name = name_of(output)
            if name is not None:
                self._taint(self.key(name, site.routine, site.module), Origin(
                    call.span, f"{call.name.text} writes {name.text} from it", found,
                    found.source))

    def _user_call(self, call, user, site) -> None:
        routine, module = user
        bound = bind_user(call, routine)
        for parameter in routine.parameters:
            argument = bound.get(parameter.name.key)
            if argument is None or argument.value is None:
                continue
            found = self.expression_taint(argument.value, site)
            if found is not None:
                self._names[id(parameter)] = (parameter.name.key, routine.name.key)
                self._taint(id(parameter), Origin(
                    call.span, f"passed to {routine.name.text} as {parameter.name.text}",
                    found, found.source))
            if parameter.mode != ast.IN and id(parameter) in self.tainted \
                    and parameter.name.key in self.writes(routine):
                name = name_of(argument.value)
                if name is not None:
                    self._taint(self.key(name, site.routine, site.module), Origin(
                        call.span, f"{routine.name.text} writes it to {name.text}",
                        self.tainted[id(parameter)], self.tainted[id(parameter)].source))

    def writes(self, routine: ast.Routine) -> frozenset:
        """The names ``routine`` may write: assignment targets, and the arguments it passes
        by reference (to a user routine's VAR, PERS or INOUT parameter, or a predefined
        routine's written one)."""
        found = self._writes.get(id(routine))
        if found is None:
            found = frozenset(self._written_names(routine))
            self._writes[id(routine)] = found
        return found

    def _written_names(self, routine: ast.Routine):
        for site in self.context.sites_by_routine.get(id(routine), ()):
            statement = site.statement
            if type(statement) is ast.Assignment:
                name = name_of(statement.target)
                if name is not None:
                    yield name.key
            calls = list(self.context.function_calls(site))
            if type(statement) is ast.ProcedureCall:
                calls.append(statement)
            for call in calls:
                yield from self._passed_by_reference(call, call is statement)

    def _passed_by_reference(self, call, procedure: bool):
        user = self.context.routines.get(call.name.key)
        if user is not None:
            bound = bind_user(call, user[0])
            written = {p.name.key for p in user[0].parameters if p.mode != ast.IN}
        else:
            bound = bind_predefined(call, procedure)
            written = set(written_parameters(call.name.key, procedure))
            written.update(SOURCE_OUTPUTS.get(call.name.key, ("", ()))[1] if procedure else ())
        for parameter, argument in bound.items():
            name = name_of(argument.value) if argument.value is not None else None
            if parameter in written and name is not None:
                yield name.key

    def _first_tainted(self, expressions, site):
        for expression in expressions:
            found = self.expression_taint(expression, site)
            if found is not None:
                return found
        return None

    # ------------------------------------------------------------ expressions
    def expression_taint(self, expression, site):
        """The Origin of the first tainted part of ``expression`` at ``site`` that no
        check guards; None when it is clean."""
        pending = [expression]
        while pending:
            current = pending.pop()
            kind = type(current)
            if kind is ast.NameRef:
                found = self._name_taint(current.name, site)
                if found is not None:
                    return found
            elif kind is ast.FunctionCall:
                found = self._function_taint(current, site)
                if found is not None:
                    return found
                if self.context.routines.get(current.name.key) is None:
                    pending.extend(a.value for a in current.args if a.value is not None)
            elif kind is ast.Binary:
                if current.op not in _RELATIONS:
                    pending.append(current.right)
                    pending.append(current.left)
            elif kind is ast.Unary:
                if current.op != "NOT":
                    pending.append(current.operand)
            elif kind is ast.Component:
                pending.append(current.base)
            elif kind is ast.Index:
                pending.append(current.base)
            elif kind is ast.Aggregate:
                pending.extend(reversed(current.items))
        return None

    def _name_taint(self, name: ast.Name, site):
        declaration = self.context.declaration(name.key, site.routine, site.module)
        key = id(declaration) if declaration is not None else ("?", name.key)
        origin = self.tainted.get(key)
        if origin is None and isinstance(declaration, ast.DataDeclaration):
            what = SOURCE_SIGNAL_TYPES.get(declaration.type.name.key)
            if what is not None:
                origin = Origin(name.span, f"{name.text} is read from {what}", None, what)
                return origin if not self._checked(site, name.key) else None
        if origin is None or self._checked(site, name.key):
            return None
        return origin

    def _checked(self, site, key: str) -> bool:
        return self.sanitise and checked(self.context, site, key)

    def _function_taint(self, call: ast.FunctionCall, site):
        key = call.name.key
        if key in SOURCE_FUNCTIONS:
            what = SOURCE_FUNCTIONS[key]
            return Origin(call.span, f"{call.name.text} reads from {what}", None, what)
        return self.returns.get(key)

    # ------------------------------------------------------------ flows
    @staticmethod
    def chain(origin: Origin) -> list[tuple[ast.Span, str]]:
        """The steps from the source to ``origin``, source first."""
        steps = []
        while origin is not None:
            steps.append((origin.span, origin.step))
            origin = origin.parent
        return steps[::-1]


_RELATIONS = ("<", "<=", ">", ">=", "=", "<>")


def sink_arguments(call: ast.ProcedureCall):
    """(argument expression, what it is) for each sensitive argument of a call."""
    parameters = sink_parameters(call.name.key)
    if not parameters:
        return
    bound = bind_predefined(call)
    for parameter, what in parameters.items():
        argument = bound.get(parameter)
        if argument is not None and argument.value is not None:
            yield argument.value, what


def sinks(context):
    """(site, the sink's expression, what it is, the routine it goes to) for every sink."""
    for site in context.calls:
        for expression, what in sink_arguments(site.statement):
            yield site, expression, what, site.statement.name.text
    for site in context.sites:
        if type(site.statement) is ast.LateBindingCall:
            yield site, site.statement.name_expr, "routine name", "a late-bound call %...%"


@rule(UNCHECKED_INPUT, "warning",
      bad="""
          MODULE M
            VAR socketdev client;
            PROC main()
              VAR string message;
              VAR robtarget place := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
              VAR pos goal;
              SocketReceive client \\Str:=message \\Time:=5;
              IF StrToVal(message, goal) THEN
                place.trans := goal;
                MoveL place, v100, fine, tool0;
              ENDIF
            ERROR
              RETURN;
            ENDPROC
          ENDMODULE
          """,
      good="""
          MODULE M
            VAR socketdev client;
            PROC main()
              VAR string message;
              VAR robtarget place := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
              VAR pos goal;
              SocketReceive client \\Str:=message \\Time:=5;
              IF StrToVal(message, goal) THEN
                place.trans := goal;
                IF place.trans.x > 0 AND place.trans.x < 800 THEN
                  MoveL place, v100, fine, tool0;
                ENDIF
              ENDIF
            ERROR
              RETURN;
            ENDPROC
          ENDMODULE
          """,
      why="A robot that moves to, opens, calls or switches whatever arrives over the network "
          "or from an operator's keyboard can be driven anywhere: bound each value first "
          "(Pogliani et al., AsiaCCS 2020).")
def unchecked_input(context):
    if not has_sources(context):
        return
    analysis = TaintAnalysis(context)
    for site, expression, what, routine in sinks(context):
        found = analysis.expression_taint(expression, site)
        if found is None:
            continue
        origin = found
        steps = analysis.chain(origin)
        steps.append((expression.span, f"{routine} takes it as its {what}"))
        source_span, source_step = steps[0]
        # One finding per source and kind of use (grouping): its other sinks are places.
        yield Diagnostic(
            UNCHECKED_INPUT, f"input from {origin.source} (line {source_span.line}: "
            f"{source_step}) reaches the {what} of {routine} with no check on the way",
            expression.span, severity="warning",
            notes=("bound the value with a comparison (IF ... < ... THEN) before this use",),
            flow=tuple(steps),
            subject=f"{source_span.file}:{source_span.line}:{source_span.column} -> {what}")


def has_sources(context) -> bool:
    """Does the program read input at all (else no flow can start)?"""
    return any(site.statement.name.key in SOURCE_OUTPUTS for site in context.calls) or any(
        call.name.key in SOURCE_FUNCTIONS for call, *_ in context.of_type(ast.FunctionCall)) \
        or any(decl.type.name.key in SOURCE_SIGNAL_TYPES for module in context.modules
               for decl in module.data)
