"""A hypothesis strategy for random, mostly well-formed RAPID programs (fuzzing support).

``programs()`` draws a ``Program``: the module text and the names of its global data, so
a test can also write LTL atoms over them.  Expressions are drawn for a wanted type
from the names in scope, so most programs pass the static checks and run; some do not
(a division by zero, an index out of bounds, a wait that never ends), which is what
the fuzzer wants to see handled.  The generator covers data of many types, records,
arrays, routines with parameters of every mode, optional and switch parameters, every
statement and operator, predefined routines, error handlers, interrupts, signals
(AliasIO and configured names), FlexPendant reads and waits.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass, field
from typing import Callable

from hypothesis import strategies as st

NUM, DNUM, BOOL, STRING, POS, ORIENT, RECORD = "num", "dnum", "bool", "string", "pos", \
    "orient", "part"
VALUE_TYPES = (NUM, DNUM, BOOL, STRING, POS, ORIENT, RECORD)
NUM_LITERALS = ("0", "1", "2", "3", "(-1)", "0.5", "10", "100", "1E3", "3.4E38", "1E-7",
                "8388608", "4294967295")
STRING_LITERALS = ('""', '"a"', '"hello"', '"12.5"', '"TRUE"', '"[1,2,3]"', '"x""y"',
                   '"\\\\"', '"' + "z" * 80 + '"', '"line\\0Anext"', '"\\0D\\09\\FF"')
ARITHMETIC = ("+", "-", "*", "/", "DIV", "MOD")
RELATIONS = ("<", "<=", "=", ">", ">=", "<>")
LOGICAL = ("AND", "OR", "XOR")
ALIAS_NAMES = ('"DI1"', '"di3"', '""', "sigName")


@dataclass
class Scope:
    """Names usable at one point: readable data by type, writable data by type."""

    readable: dict[str, list[str]] = field(default_factory=dict)
    writable: dict[str, list[str]] = field(default_factory=dict)
    optional: list[str] = field(default_factory=list)     # optional parameters (Present)
    functions: list[str] = field(default_factory=list)    # user FUNC num names, one num arg
    procedures: list[str] = field(default_factory=list)   # user PROC names (see PROC_CALLS)
    in_handler: bool = False
    in_function: bool = False
    labels: list[str] = field(default_factory=list)

    def add(self, rapid_type: str, name: str, writable: bool = True) -> None:
        self.readable.setdefault(rapid_type, []).append(name)
        if writable:
            self.writable.setdefault(rapid_type, []).append(name)

    def child(self) -> "Scope":
        return Scope({k: list(v) for k, v in self.readable.items()},
                     {k: list(v) for k, v in self.writable.items()}, list(self.optional),
                     list(self.functions), list(self.procedures), self.in_handler,
                     self.in_function, list(self.labels))


@dataclass(frozen=True)
class Program:
    """A generated module and what LTL atoms may read."""

    text: str
    atoms: tuple[str, ...]


# ---------------------------------------------------------------- strategies made once
# Hypothesis checks each new strategy object before its first draw (emptiness, labels);
# made afresh at every draw, that was about half the time of drawing a program.  Made once
# per distinct arguments, they draw the same programs.

MADE_KEPT = 4096            # composite strategies kept, at most


def composite(function) -> Callable[..., st.SearchStrategy]:
    """``st.composite``, whose strategy for the same arguments (a scope by identity) is
    made once."""
    make = st.composite(function)
    made: dict = {}

    @functools.wraps(function)
    def strategy(*arguments, **keywords) -> st.SearchStrategy:
        key = tuple(id(argument) if isinstance(argument, Scope) else argument
                    for argument in arguments) + tuple(sorted(keywords.items()))
        try:
            found = made.get(key)
        except TypeError:                       # (an argument that cannot be a key)
            return make(*arguments, **keywords)
        if found is None:
            if len(made) >= MADE_KEPT:
                made.clear()                    # (the scopes of earlier programs)
            # (the arguments are kept with it: an id stays that scope's)
            found = made[key] = (arguments, make(*arguments, **keywords))
        return found[1]
    return strategy


def sampled(elements) -> st.SearchStrategy:
    """``st.sampled_from(elements)``, made once per distinct elements."""
    return _sampled(tuple(elements))


@functools.lru_cache(maxsize=None)
def _sampled(elements: tuple) -> st.SearchStrategy:
    return st.sampled_from(elements)


@functools.lru_cache(maxsize=None)
def one_of(*strategies: st.SearchStrategy) -> st.SearchStrategy:
    """``st.one_of(*strategies)``, made once for the same strategy objects."""
    return st.one_of(*strategies)


@functools.lru_cache(maxsize=None)
def integers(low: int, high: int) -> st.SearchStrategy:
    """``st.integers(low, high)``, made once."""
    return st.integers(low, high)


# ---------------------------------------------------------------- expressions

@composite
def expression(draw, scope: Scope, rapid_type: str, depth: int = 2) -> str:
    """An expression of ``rapid_type`` (most of the time) over the names in ``scope``."""
    names = scope.readable.get(rapid_type, [])
    leaves = [_literal(rapid_type)]
    if names:
        leaves.append(sampled(names))
    if depth <= 0:
        return draw(one_of(*leaves))
    builders = {NUM: _num_expression, DNUM: _dnum_expression, BOOL: _bool_expression,
                STRING: _string_expression, POS: _pos_expression}
    build = builders.get(rapid_type)
    if build is None or draw(integers(0, 3)) == 0:
        return draw(one_of(*leaves))
    return draw(build(scope, depth - 1))


@functools.lru_cache(maxsize=None)
def _literal(rapid_type: str):
    num = sampled(NUM_LITERALS)
    if rapid_type in (NUM, DNUM):
        return num
    if rapid_type == BOOL:
        return sampled(("TRUE", "FALSE"))
    if rapid_type == STRING:
        return sampled(STRING_LITERALS)
    if rapid_type == POS:
        return st.tuples(num, num, num).map(lambda t: "[" + ", ".join(t) + "]")
    if rapid_type == ORIENT:
        return sampled(("[1, 0, 0, 0]", "[0, 0, 0, 1]", "[0.7071, 0, 0.7071, 0]"))
    return st.tuples(num, sampled(("TRUE", "FALSE")), sampled(STRING_LITERALS)) \
        .map(lambda t: "[" + ", ".join(t) + "]")


@composite
def _num_expression(draw, scope: Scope, depth: int) -> str:
    sub = lambda t=NUM: expression(scope, t, depth)  # noqa: E731
    choice = draw(integers(0, 11))
    if choice == 0:
        return f"({draw(sub())} {draw(sampled(ARITHMETIC))} {draw(sub())})"
    if choice == 1:
        return f"(-({draw(sub())}))"
    if choice == 2:
        function = draw(sampled(("Abs", "Sqrt", "Exp", "Trunc", "Round", "Sin", "ACos")))
        return f"{function}({draw(sub())})"
    if choice == 3:
        return f"Round({draw(sub())}\\Dec:={draw(integers(-1, 7))})"
    if choice == 4:
        return f"StrLen({draw(sub(STRING))})"
    if choice == 5:
        if draw(st.booleans()):
            return f"arr{{{draw(sub())}}}"
        return f"grid{{{draw(sub())}, {draw(sub())}}}"
    if choice == 6:
        return f"{draw(sampled(scope.readable[POS]))}.{draw(sampled('xyz'))}"
    if choice == 7:
        return f"{draw(sampled(('Pow', 'ATan2', 'BitAnd', 'BitLSh', 'BitXOr')))}" \
               f"({draw(sub())}, {draw(sub())})"
    if choice == 8 and scope.functions:
        return f"{draw(sampled(scope.functions))}({draw(sub())})"
    if choice == 9:
        return draw(sampled(("DInput(diStart)", "DOutput(doLamp)", "DInput(DI1)",
                                     "DOutput(DO1)", "AInput(AI1)", "GInput(GI1)",
                                     "ClkRead(clk)", "Dim(arr, 1)", "Dim(grid, 2)", "ERRNO",
                                     "INTNO", "rec.id", "StrFind(\"abc\", 1, \"b\")",
                                     "NumToDnum(1)")))
    if choice == 10:
        return f"DnumToNum({draw(sub(DNUM))})"
    return draw(_literal(NUM))


@composite
def _dnum_expression(draw, scope: Scope, depth: int) -> str:
    left, right = draw(expression(scope, DNUM, depth)), draw(expression(scope, DNUM, depth))
    return draw(sampled((f"({left} {draw(sampled(ARITHMETIC))} {right})",
                                 f"NumToDnum({draw(expression(scope, NUM, depth))})",
                                 "4294967295")))


@composite
def _bool_expression(draw, scope: Scope, depth: int) -> str:
    choice = draw(integers(0, 6))
    if choice == 0:
        rapid_type = draw(sampled((NUM, NUM, STRING, DNUM, BOOL)))
        relations = RELATIONS if rapid_type in (NUM, DNUM) else ("=", "<>")
        left, right = (draw(expression(scope, rapid_type, depth)) for _ in range(2))
        return f"({left} {draw(sampled(relations))} {right})"
    if choice == 1:
        return (f"({draw(expression(scope, BOOL, depth))} {draw(sampled(LOGICAL))} "
                f"{draw(expression(scope, BOOL, depth))})")
    if choice == 2:
        return f"(NOT {draw(expression(scope, BOOL, depth))})"
    if choice == 3 and scope.optional:
        return f"Present({draw(sampled(scope.optional))})"
    if choice == 4:
        return draw(sampled(("rec.ok", "StrToVal(\"3\", numVar)", "IsPers(numVar)",
                                     "(OpMode() = OP_AUTO)", "ValidIO(diStart)")))
    if choice == 5:
        return f"({draw(expression(scope, POS, depth))} = {draw(expression(scope, POS, depth))})"
    return draw(_literal(BOOL))


@composite
def _string_expression(draw, scope: Scope, depth: int) -> str:
    choice = draw(integers(0, 5))
    if choice == 0:
        return f"{draw(expression(scope, STRING, depth))} + {draw(expression(scope, STRING, depth))}"
    if choice == 1:
        return f"NumToStr({draw(expression(scope, NUM, depth))}, {draw(integers(-1, 7))})"
    if choice == 2:
        rapid_type = draw(sampled(VALUE_TYPES))
        return f"ValToStr({draw(expression(scope, rapid_type, depth))})"
    if choice == 3:
        return (f"StrPart({draw(expression(scope, STRING, depth))}, "
                f"{draw(expression(scope, NUM, depth))}, {draw(expression(scope, NUM, depth))})")
    if choice == 4:
        return draw(sampled(("rec.name", "StrMap(\"abc\", \"a\", \"b\")", "CTime()",
                                     "GetSysInfo(\\SerialNo)",
                                     "ByteToStr(12)")))
    return draw(_literal(STRING))


@composite
def _pos_expression(draw, scope: Scope, depth: int) -> str:
    choice = draw(integers(0, 3))
    left = draw(sampled(scope.readable[POS]))       # aggregates have no type here
    if choice == 0:
        return f"({left} {draw(sampled(('+', '-')))} {draw(sampled(scope.readable[POS]))})"
    if choice == 1:
        return f"({left} * {draw(expression(scope, NUM, depth))})"
    if choice == 2:
        return f"(-({left}))"
    return f"[{draw(expression(scope, NUM, depth))}, 0, {draw(expression(scope, NUM, depth))}]"


# ------------------------------------------------------------------ statements

@composite
def statements(draw, scope: Scope, depth: int, count: tuple[int, int] = (1, 6)) -> list[str]:
    return [draw(statement(scope, depth)) for _ in range(draw(integers(*count)))]


@composite
def statement(draw, scope: Scope, depth: int) -> str:
    kinds = ["predefined", "predefined", "assign", "assign", "call", "call", "write", "read", "wait", "io", "interrupt",
             "raise", "misc"]
    if depth > 0:
        kinds += ["if", "compact_if", "for", "while", "test"]
    kind = draw(sampled(kinds))
    return draw(STATEMENTS[kind](scope, depth))


@composite
def _assign(draw, scope: Scope, depth: int) -> str:
    rapid_type = draw(sampled([t for t in scope.writable if scope.writable[t]]))
    target = draw(sampled(scope.writable[rapid_type]))
    return f"{target} := {draw(expression(scope, rapid_type))};"


@composite
def _call(draw, scope: Scope, depth: int) -> str:
    num = lambda: draw(expression(scope, NUM, 1))  # noqa: E731
    target = draw(sampled(scope.writable[NUM]))
    variable = draw(sampled(("numVar", "arr{2}", "rec.id")))    # VAR, not PERS
    calls = [f"Incr {target};", f"Decr {target};", f"Add {target}, {num()};",
             f"Clear {target};", f"numVar := {target};", "ClkStart clk;", "ClkStop clk;",
             "ClkReset clk;", f"WaitTime {draw(sampled(('0', '0.1', '1', '-1')))};",
             f"ErrWrite \\W, \"head\", {draw(expression(scope, STRING, 1))};",
             "TPErase;", f"BitSet byteVar, {num()};", f"BitClear byteVar, {num()};"]
    if scope.procedures:
        calls.extend(draw(sampled(scope.procedures)).format(
            num=num(), var=variable, bool=draw(expression(scope, BOOL, 1))) for _ in range(2))
    calls += [f"%\"work\" + NumToStr({num()}, 0)%;", "CallByVar \"work\", 1;",
              f"%{draw(expression(scope, STRING, 1))}%;", f"CallByVar strVar, {num()};"]
    return draw(sampled(calls))


@composite
def _write(draw, scope: Scope, depth: int) -> str:
    text = draw(expression(scope, STRING, 1))
    option = draw(sampled(("", "\\Num:=", "\\Bool:=", "\\Pos:=", "\\Orient:=",
                                   "\\Dnum:=")))
    if not option:
        return f"TPWrite {text};"
    rapid_type = {"\\Num:=": NUM, "\\Bool:=": BOOL, "\\Pos:=": POS, "\\Orient:=": ORIENT,
                  "\\Dnum:=": DNUM}[option]
    return f"TPWrite {text}{option}{draw(expression(scope, rapid_type, 2))};"


@composite
def _read(draw, scope: Scope, depth: int) -> str:
    target = draw(sampled(scope.writable[NUM]))
    return draw(sampled((
        f"TPReadNum {target}, \"number?\";",
        f"TPReadFK {target}, \"key?\", \"A\", \"B\", stEmpty, stEmpty, \"E\";",
        f"TPReadFK {target}, \"key?\", stEmpty, stEmpty, stEmpty, stEmpty, \"E\""
        f" \\MaxTime:=1;",
        "TPReadDnum dnumVar, \"dnum?\";")))


@composite
def _wait(draw, scope: Scope, depth: int) -> str:
    condition = draw(expression(scope, BOOL, 1))
    limit = draw(sampled(("", " \\MaxTime:=1", " \\MaxTime:=0.5 \\TimeFlag:=flag")))
    return draw(sampled((f"WaitUntil {condition}{limit};",
                                 f"WaitDI {draw(sampled(('diStart', 'DI1')))}, "
                                 f"{draw(sampled(('0', '1')))}{limit};",
                                 f"WaitDO doLamp, 1{limit};",
                                 f"WaitTime {draw(sampled(('0.1', '2')))};")))


@composite
def _io(draw, scope: Scope, depth: int) -> str:
    output = draw(sampled(("doLamp", "DO1", "do2")))
    return draw(sampled((
        f"Set {output};", f"Reset {output};",
        f"SetDO {output}, {draw(sampled(('0', '1', '2', 'high')))};",
        f"PulseDO \\PLength:=0.2, {output};", f"InvertDO {output};",
        f"AliasIO {draw(sampled(ALIAS_NAMES))}, diStart;",
        "AliasIO \"DO1\", doLamp;", "AliasIOReset doLamp;",
        f"SetGO GO1, {draw(expression(scope, NUM, 1))};")))


@composite
def _interrupt(draw, scope: Scope, depth: int) -> str:
    return draw(sampled((
        "IDelete ir;", "CONNECT ir WITH onTick;", "ITimer 0.5, ir;", "ITimer \\Single, 1, ir;",
        "ISignalDI diStart, 1, ir;", "ISignalDI \\Single, DI1, 0, ir;", "ISleep ir;",
        "IWatch ir;", "IDisable;", "IEnable;", "ISignalDO doLamp, 1, ir;")))


@composite
def _raise(draw, scope: Scope, depth: int) -> str:
    options = ["RAISE ERR_MINE;", "RAISE ERR_DIVZERO;", "RAISE 55;",
               f"RAISE {draw(expression(scope, NUM, 0))};", "BookErrNo ERR_MINE;",
               "RETURN;" if not scope.in_function else
               f"RETURN {draw(expression(scope, NUM, 1))};",
               "EXIT;", "Stop;", "ExitCycle;"]
    if scope.in_handler:
        options += ["RETRY;", "TRYNEXT;", "RAISE;", "SkipWarn;", "ERRNO := 1;"]
    if scope.labels:
        options.append(f"GOTO {draw(sampled(scope.labels))};")
    return draw(sampled(options))


@composite
def _misc(draw, scope: Scope, depth: int) -> str:
    return draw(sampled((
        f"strVar := StrPart({draw(expression(scope, STRING, 1))}, 1, 2);",
        f"ok := StrToVal({draw(expression(scope, STRING, 0))}, numVar);",
        "posVar := Offs(target, 1, 2, 3).trans;", "grid{1, 2} := arr{3};",
        f"arr{{{draw(expression(scope, NUM, 0))}}} := 1;", "rec.name := \"n\";",
        f"dnumVar := {draw(expression(scope, DNUM, 1))};", "ori := OrientZYX(90, 0, 0);",
        "posVar := target.trans;", "target.trans.z := 5;",
        "ok := IsPers(count);", "level1 := level1 + 1;")))


@composite
def _if(draw, scope: Scope, depth: int) -> str:
    lines = [f"IF {draw(expression(scope, BOOL))} THEN", *draw(statements(scope, depth - 1))]
    for _ in range(draw(integers(0, 2))):
        lines += [f"ELSEIF {draw(expression(scope, BOOL))} THEN",
                  *draw(statements(scope, depth - 1))]
    if draw(st.booleans()):
        lines += ["ELSE", *draw(statements(scope, depth - 1))]
    return "\n".join(lines + ["ENDIF"])


@composite
def _compact_if(draw, scope: Scope, depth: int) -> str:
    simple = draw(one_of(_assign(scope, 0), _call(scope, 0), _raise(scope, 0),
                            _write(scope, 0)))
    return f"IF {draw(expression(scope, BOOL))} {simple}"


@composite
def _for(draw, scope: Scope, depth: int) -> str:
    inner = scope.child()
    variable = draw(sampled(("i", "k", "j")))
    inner.add(NUM, variable, writable=False)
    step = draw(sampled(("", " STEP 2", " STEP -1", " STEP 0.5")))
    return "\n".join([f"FOR {variable} FROM {draw(expression(scope, NUM, 1))} TO "
                      f"{draw(expression(scope, NUM, 1))}{step} DO",
                      *draw(statements(inner, depth - 1)), "ENDFOR"])


@composite
def _while(draw, scope: Scope, depth: int) -> str:
    return "\n".join([f"WHILE {draw(expression(scope, BOOL))} DO",
                      *draw(statements(scope, depth - 1)), "ENDWHILE"])


@composite
def _test(draw, scope: Scope, depth: int) -> str:
    rapid_type = draw(sampled((NUM, NUM, STRING, BOOL)))
    lines = [f"TEST {draw(expression(scope, rapid_type, 1))}"]
    for _ in range(draw(integers(0, 3))):
        values = ", ".join(draw(expression(scope, rapid_type, 0))
                           for _ in range(draw(integers(1, 3))))
        lines += [f"CASE {values}:", *draw(statements(scope, depth - 1, (0, 3)))]
    if draw(st.booleans()):
        lines += ["DEFAULT:", *draw(statements(scope, depth - 1, (0, 3)))]
    return "\n".join(lines + ["ENDTEST"])


# ------------------------------------------------------- predefined routines

#: arguments for parameters whose type the expression generator does not build
DATA_OF_TYPE = {"robtarget": ("target", "CRobT()", "Offs(target, 1, 2, 3)"),
                "jointtarget": ("joints", "CJointT()"), "pose": ("frame", "[posVar, ori]"),
                "speeddata": ("v100", "vmax", "[1, 2, 3, 4]"), "zonedata": ("z10", "fine"),
                "tooldata": ("tool0",), "wobjdata": ("wobj0",),
                "loaddata": ("load0", "ld"), "stoppointdata": ("sp",), "taskid": ("tid",),
                "triggdata": ("trig",), "clock": ("clk",), "errnum": ("ERR_MINE",),
                "intnum": ("ir",), "signaldi": ("diStart", "DI1"), "signaldo": ("doLamp", "DO1"),
                "signalao": ("AO1",), "signalgi": ("GI1",), "signalgo": ("GO1",),
                "opcalc": ("LT", "EQ"), "confdata": ("[0, 0, 0, 0]",)}
#: parameter types drawn as expressions of one of the generator's types
EXPRESSION_TYPE = {"num": NUM, "anynum": NUM, "dionum": NUM, "byte": NUM, "symnum": NUM,
                   "opnum": NUM, "identno": NUM, "dnum": DNUM, "bool": BOOL, "string": STRING,
                   "stringdig": STRING, "pos": POS, "orient": ORIENT}


def _predefined_entries():
    """Predefined routines whose every parameter the generator can fill, by kind."""
    from rapidmc.semantics.library.registry import all_entries
    known = set(DATA_OF_TYPE) | set(EXPRESSION_TYPE) | {"anytype", "switch"}
    usable = [entry.signature for entry in all_entries()
              if entry.signature.key not in ("PRESENT", "DIM") and all(p.type_name in known and not p.array_rank
                     for p in entry.signature.parameters)]
    return sorted(usable, key=lambda signature: signature.key)


PREDEFINED = _predefined_entries()


@composite
def _argument(draw, scope: Scope, parameter) -> str:
    type_name = parameter.type_name
    if type_name == "anytype":
        type_name = draw(sampled(("num", "bool", "string", "pos", "robtarget")))
    rapid_type = EXPRESSION_TYPE.get(type_name)
    if rapid_type is None:
        return draw(sampled(DATA_OF_TYPE[type_name]))
    if parameter.by_reference:
        names = scope.writable.get(rapid_type) or scope.readable.get(rapid_type) or ["numVar"]
        return draw(sampled(names))
    return draw(expression(scope, rapid_type, 1))


@composite
def _arguments(draw, scope: Scope, signature) -> str:
    """Required arguments in order (first of each required group), some optional ones."""
    parts, groups_used = [], set()
    for parameter in signature.parameters:
        group = parameter.alternative_group
        if group is not None and group in groups_used:
            continue
        if parameter.optional:
            if draw(integers(0, 2)) != 0:
                continue
            value = "" if parameter.is_switch else ":=" + draw(_argument(scope, parameter))
            parts.append(f" \\{parameter.name}{value}")
        else:
            parts.append((", " if parts else "") + draw(_argument(scope, parameter)))
        if group is not None:
            groups_used.add(group)
    return "".join(parts).lstrip(", ")


@composite
def _predefined(draw, scope: Scope, depth: int) -> str:
    """A call of any predefined routine the generator can fill, with random arguments."""
    signature = draw(sampled(PREDEFINED))
    arguments = draw(_arguments(scope, signature))
    if signature.kind == "function":
        return f"strVar := ValToStr({signature.name}({arguments}));"
    return f"{signature.name} {arguments};".replace(" ;", ";")


STATEMENTS = {"predefined": _predefined, "assign": _assign, "call": _call, "write": _write, "read": _read, "wait": _wait,
              "io": _io, "interrupt": _interrupt, "raise": _raise, "misc": _misc, "if": _if,
              "compact_if": _compact_if, "for": _for, "while": _while, "test": _test}


# -------------------------------------------------------------------- programs

GLOBAL_DATA = (
    "RECORD part\n  num id;\n  bool ok;\n  string name;\nENDRECORD",
    "ALIAS num level;",
    "CONST num N := 3;",
    "VAR errnum ERR_MINE := -1;",
    "CONST pos home := [0, 0, 100];",
    "VAR num numVar := 1;",
    "PERS num count := 0;",
    "VAR num arr{N} := [1, 2, 3];",
    "VAR num grid{2, 3};",
    "VAR bool ok;",
    "VAR bool flag := TRUE;",
    "VAR string strVar := \"s\";",
    "VAR dnum dnumVar := 2;",
    "VAR pos posVar := [1, 2, 3];",
    "VAR orient ori := [1, 0, 0, 0];",
    "VAR part rec := [1, TRUE, \"r\"];",
    "VAR level level1 := 2;",
    "VAR byte byteVar := 3;",
    "VAR intnum ir;",
    "VAR clock clk;",
    "VAR signaldi diStart;",
    "VAR signaldo doLamp;",
    "VAR string sigName := \"DI1\";",
    "VAR pose frame;", "VAR jointtarget joints;", "VAR triggdata trig;", "VAR loaddata ld;",
    "VAR stoppointdata sp;", "VAR taskid tid;", "VAR tooldata tl;", "VAR wobjdata wo;",
    "VAR robtarget target := [[100, 0, 50], [1, 0, 0, 0], [0, 0, 0, 0],"
    " [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];",
)
GLOBAL_SCOPE = {NUM: ["numVar", "count", "arr{1}", "grid{2, 3}", "rec.id", "level1"],
                DNUM: ["dnumVar"], BOOL: ["ok", "flag", "rec.ok"], POS: ["posVar"],
                STRING: ["strVar", "rec.name"], ORIENT: ["ori"],
                RECORD: ["rec"]}
#: user procedures and how to call them (filled in with a num, a num variable and a bool)
PROC_CALLS = ("work1 {num}, {var}, {var};", "work1 {num}, {var}, {var} \\opt:={num};",
              "work1 {num}, {var}, {var} \\sw \\flagged;", "work2 arr;",
              "work1 {bool}, {var}, {var};")
ATOM_TEMPLATES = ("{bool}", "\"{bool}\"", "\"numVar > {num}\"", "\"DOutput(doLamp) = 1\"",
                  "\"DOutput(DO1) = 1\"", "\"DInput(DI1) = 0\"", "\"count = {num}\"",
                  "\"arr{{2}} < {num}\"", "\"rec.ok\"", "unknownAtom",
                  "\"InRoutine(work1)\"", "\"AtLabel(again)\"", "\"AtLine({num})\"",
                  "\"Ended() OR Failed()\"", "\"AtTarget(target)\"", "\"InRoutine(onTick)\"", "\"StrLen(strVar) = 1\"")


def global_scope() -> Scope:
    scope = Scope()
    for rapid_type, names in GLOBAL_SCOPE.items():
        for name in names:
            scope.add(rapid_type, name)
    scope.add(NUM, "N", writable=False)
    scope.add(POS, "home", writable=False)
    scope.functions = ["work3"]
    scope.procedures = list(PROC_CALLS)
    return scope


@composite
def _routine(draw, header: str, footer: str, scope: Scope, handler: bool = True,
             local_data: tuple[str, ...] = ()) -> str:
    body = draw(statements(scope, 2))
    if scope.labels:
        body.insert(draw(integers(0, len(body))), f"{scope.labels[0]}:")
    lines = [header, *local_data, *body]
    if handler and draw(st.booleans()):
        handler_scope = scope.child()
        handler_scope.in_handler = True
        errors = draw(sampled(("", "", " (ERR_DIVZERO, 55)", " (LONG_JMP_ALL_ERR)")))
        lines += [f"ERROR{errors}", *draw(statements(handler_scope, 1, (1, 3)))]
    if handler and not scope.in_function and draw(integers(0, 4)) == 0:
        lines += ["UNDO", "count := count + 1;"]
    return "\n".join(lines + [footer])


@composite
def programs(draw) -> Program:
    """A module with main, two procedures, a function and a trap, over fixed global data."""
    scope = global_scope()
    main_scope = scope.child()
    if draw(st.booleans()):
        main_scope.labels = ["again"]
    work1 = scope.child()
    work1.procedures = []
    for rapid_type, name in ((NUM, "a"), (NUM, "b"), (NUM, "c"), (NUM, "opt")):
        work1.add(rapid_type, name, writable=name != "a")
    work1.optional = ["opt", "sw", "flagged"]
    work3 = scope.child()
    work3.in_function = True
    work3.procedures = []
    work3.add(NUM, "x")
    trap = scope.child()
    trap.procedures = []
    setup = ["AliasIO \"DI1\", diStart;", "AliasIO \"DO1\", doLamp;",
             "CONNECT ir WITH onTick;"][:draw(integers(0, 3))]
    setup += draw(st.lists(sampled((
        "AliasIO \"DI1\", diStart;", "AliasIO \"DO1\", doLamp;", "CONNECT ir WITH onTick;",
        "ISignalDI diStart, 1, ir;", "ITimer 1, ir;", "AliasIO \"di2\", diStart;",
        "BookErrNo ERR_MINE;")),
        max_size=4))
    routines = [
        draw(_routine("PROC main()", "ENDPROC", main_scope,
                      local_data=("VAR num i;", "VAR num k;", *setup))),
        draw(_routine("PROC work1(num a, VAR num b, INOUT num c \\num opt | switch sw, "
                      "\\switch flagged)", "ENDPROC", work1)),
        draw(_routine("PROC work2(num m{*})", "ENDPROC", scope.child(), handler=False)),
        draw(_routine("FUNC num work3(num x)", "ENDFUNC", work3)),
        draw(_routine("TRAP onTick", "ENDTRAP", trap)),
    ]
    text = "MODULE Fuzz\n" + "\n".join(GLOBAL_DATA + tuple(routines)) + "\nENDMODULE\n"
    atoms = tuple(draw(st.lists(_atom(scope), min_size=1, max_size=3)))
    return Program(text, atoms)


@composite
def _atom(draw, scope: Scope) -> str:
    template = draw(sampled(ATOM_TEMPLATES))
    return template.format(bool=draw(sampled(scope.readable[BOOL][:2])),
                           num=draw(sampled(("0", "1", "2.5"))))
