"""Parsing speed: generate a large RAPID module and report lines per second.

Usage: python bench/parse.py [--stages] [LINES] [RUNS]   (default 100000 lines, 3 runs)

The generated code is typical robot code: declarations with multi-line
aggregates, moves with optional arguments, IF/FOR/WHILE/TEST, assignments
with arithmetic and logic.  The figure covers the whole front end (lexing,
LALR parsing, lowering to rapidmc.ast); the one-off parser construction is
timed separately.  The module is parsed RUNS times, alternately on the fast
path (the scanner and lark_cython's compiled LALR loop, the default when
lark_cython is installed) and with Lark's own driver, so that both figures
come from the same process under the same load; the figures are processor
time (the machine is shared: wall time varies by 20% and more), and the
best of the runs is the one to quote.  ``--stages`` times each stage of the
fast path instead, and the floor of the design (each irreducible part alone).

Figures on the project machine (2 cores, loaded), median of 3 runs of
100,000 lines: 8,100 lines/s with a Lark parse tree lowered by a
Transformer afterwards; 24,600 lines/s with the one-pass front end (own
lexer, AST built on reduction, flat expression rules).  Same process, best
of 8 runs of 20,000 lines: 27,200 lines/s before lark_cython (commit
766b20b), 42,000 with its compiled loop fed by the per-token lexer.
lark-rust 0.2.1 was measured too: its compiled loop runs only with its own
lexer, and fed from this lexer by a Python loop it gave 42,400 lines/s
against lark_cython's 43,900 in the same process, so it is not used.

Now (issue 9), best of 5 runs of 20,000 lines, CPU time, the code before
and after run alternately under the same load: 38,000-42,000 lines/s
before, 57,000-63,000 after (x1.5); Lark's driver, the path of files with
errors, 30,000 -> 34,500.  A file of five lines parses in half the time
(the callbacks are decided once per process).  Stages, best of 5 (before:
lexing 129 ms, LALR loop 106, AST construction 262, whole 519):

    scanning            92 ms   one findall (39 ms) and a loop counting lines
    LALR loop alone     67 ms   105 without the shortcuts (shortcuts.py)
    AST construction   183 ms   of which building the 206,000 nodes: 62 ms
    whole parse        350 ms   57,000 lines/s

The gains: the scanner (scanner.py) against the per-token lexer; callbacks
written per rule as straight-line code, built-in functions for rules that
pass a child on, and lowering methods as the callbacks of one-token rules;
nodes filled in as unfrozen drafts of the same slots (construct.py, half
the cost per node); and the shortcut table, which skips the reductions that
only pass a child on (term: postfix, sum: term, expression: sum: 45% of all
reductions).

Second round (issue 9, target 100,000 lines/s), same machine, 20,000 lines,
the code before (0b597d9) and after run alternately in separate processes:
eight rounds of the best of 5 parses, median 300 ms before, 282 ms after
(66,600 -> 70,900 lines/s, +6%; the after code won 7 of 8 rounds); this
script's figure (best of 3) over nine rounds, 60,400-66,900 lines/s
before, 65,000-72,100 after; Lark's driver about +4%.  The gains:
identifier keys and number values read once per distinct text in a file
(lower.py), the nodes of the hottest rules (identifier, reference, number,
positional argument, token span) filled in as drafts inline, the node
builders calling their draft class instead of ``object.__new__``.  The
compiled table with its shortcuts is built in 11 ms instead of 17 (the same
table), which the start-up of every ``rapidmc check`` pays: importing the
front end and parsing a five-line file take 119 ms instead of 125.  Tried and dropped: every token
made before parsing and handed over by C iterators (15 ms slower: with all
tokens alive lark_cython's token freelist no longer recycles them); one
regular expression with the one-character terminals as a class (no
change); the scanner's loop and the feed as one generator (within noise).

Stages now (``--stages``, best of 5 to 7, four runs on the loaded machine;
``scanning`` drops each token as the parser does):

    scanning           72-79 ms   one findall (44-46 ms), making the tokens (19-21)
    LALR loop alone    66-70 ms   102-110 without the shortcuts (shortcuts.py)
    AST construction  149-167 ms  of which making the 205,000 nodes: 76-95
    whole parse       296-305 ms  66,000-68,000 lines/s

100,000 lines/s is out of reach in this design, and ``--stages`` shows why
(the "floor" lines): the regular expression alone (44-46 ms), making
lark_cython's tokens from their fields (19-21 ms), the compiled loop with
no-op callbacks (66-70 ms) and making the AST's 205,000 frozen-dataclass
nodes from their fields by the cheapest Python known (drafts filled by
straight-line code, 76-95 ms) take 205-229 ms for 20,000 lines:
87,000-98,000 lines/s before any Python runs per token (line counting) or
per rule (selecting children, spans, names: about 70-90 ms today).
Reaching the target needs the scanning and the node construction compiled
(a Cython or Rust front end that builds the nodes, against the rule of a
pure-Python package), or AST nodes cheaper to build than frozen
dataclasses (a change of rapidmc.ast that every later stage would see).

Fourth round (docs/architecture.md, "Parsing speed"): the scanner splits the
text into a flat list of strings (``re.split``), matches identifiers without
the ``i`` flag and leaves the tokens' offsets out; the compiled table gives
the states most often entered by a token CPython's shared small ints and
interns its symbol names; the lowering writes the hottest rules out and
reads a token's line as its ``end_line``.  Five rounds, the code before and
after alternately: 92,300-94,000 -> 104,500-108,800 lines/s (best of 3);
stages (best of 7): scanning 42 ms, LALR loop 49, AST construction 88,
whole parse 180 (215 before).
"""
from __future__ import annotations

import collections
import dataclasses
import gc
import itertools
import os
import statistics
import sys
import tempfile
import time

from rapidmc.load.source import read_source
from rapidmc.syntax import accelerated, parse_text, parser
from rapidmc.syntax.construct import draft_class
from rapidmc.syntax.parser import rapid_parser
from rapidmc.syntax.tokens import CompiledToken

ROUTINE_TEMPLATE = """\
  PROC cycle{n}()
    VAR num count := 0;
    VAR bool done := FALSE;
    ! pick part {n} and place it on the conveyor
    MoveJ Offs(pHome, 0, 0, {n} MOD 100), v1000, z50, tool0;
    MoveL pPick, v200, fine, tGripper \\WObj:=wobjTable;
    SetDO doGrip, 1;
    WaitTime 0.25;
    FOR i FROM 1 TO 10 DO
      count := count + i * 2 - (i DIV 3);
      IF count > 100 AND NOT done THEN
        done := TRUE;
      ELSEIF count < 0 THEN
        TPWrite "negative count "\\Num:=count;
      ENDIF
    ENDFOR
    TEST count
      CASE 1, 2, 3:
        MoveL pPlace, v500, z10, tGripper;
      DEFAULT:
        MoveL RelTool(pPlace, 0, 0, -50), v100, fine, tGripper \\WObj:=wobjTable;
    ENDTEST
    WHILE diPartPresent = 1 AND count < 1000 DO
      count := count + 1;
    ENDWHILE
    IF done SetDO doGrip, 0;
    nTotal := nTotal + 1;
  ERROR
    IF ERRNO = ERR_PATH_STOP THEN
      RETRY;
    ENDIF
  ENDPROC

"""

HEADER = """\
MODULE Bench
  CONST robtarget pHome := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0],
                            [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PERS num nTotal := 0;

"""


def generated_module(lines: int) -> str:
    """A module of about ``lines`` lines."""
    routine_lines = ROUTINE_TEMPLATE.count("\n")
    routines = [ROUTINE_TEMPLATE.format(n=n) for n in range(max(1, lines // routine_lines))]
    return HEADER + "".join(routines) + "ENDMODULE\n"


def cpu_seconds(action) -> float:
    """The processor time ``action()`` takes (the machine is shared: wall time varies more),
    with the cycle collector paused as ``parse_text`` pauses it."""
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        started = time.process_time()
        action()
        return time.process_time() - started
    finally:
        if was_enabled:
            gc.enable()
        gc.collect()


def compare_paths(text: str, runs: int) -> None:
    """Whole front end, alternately on the fast path and on Lark's driver."""
    count = text.count("\n")
    loops = {"fast path": True, "Lark driver": False} if accelerated.AVAILABLE else {
        "Lark driver": False}
    speeds: dict[str, list[float]] = {name: [] for name in loops}
    for _ in range(runs):
        for name, compiled in loops.items():
            accelerated.AVAILABLE = compiled
            started = time.perf_counter()
            cpu = cpu_seconds(lambda: parse_text(text, "bench.mod"))
            wall = time.perf_counter() - started
            speeds[name].append(count / cpu)
            print(f"{name:12} parsed {count} lines ({len(text) / 1e6:.1f} MB) in "
                  f"{cpu:.2f} s CPU ({wall:.2f} s wall): {count / cpu:,.0f} lines/s")
    for name, figures in speeds.items():
        print(f"{name:12} best of {runs}: {max(figures):,.0f} lines/s (CPU), "
              f"median {statistics.median(figures):,.0f}")


def stage_times(text: str, runs: int) -> None:
    """CPU time of each stage of the fast path, best of ``runs``: reading the file,
    scanning, the compiled LALR loop alone (no-op callbacks), and the whole parse; the
    AST construction is what the whole parse takes beyond scanning and the loop (with the
    shortcuts the fast path takes, see ``rapidmc.syntax.shortcuts``)."""
    count = text.count("\n")
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "bench.mod")
        with open(path, "w", encoding="latin-1") as stream:
            stream.write(text)
        reading = min(cpu_seconds(lambda: read_source(path)) for _ in range(runs))
    scanner = parser._scanner()
    tokens = list(scanner.scan(text, CompiledToken))
    # Each token dropped once made, as the parser drops it: kept in a list, the tokens
    # would take a quarter more time (lark_cython recycles a dropped token's memory).
    scanning = min(cpu_seconds(lambda: collections.deque(scanner.scan(text, CompiledToken), 0))
                   for _ in range(runs))
    table = rapid_parser().parser.parser._parse_table
    ignored = {rule: _ignore for rule in parser._reduced_rules()}

    def loop_alone(pass_through):
        feed = accelerated.TokenFeed(tokens, parser.MAX_STACK_DEPTH, None)
        accelerated.parse(table, ignored, feed, parser.START_RULE, pass_through)
    looping = min(cpu_seconds(lambda: loop_alone(parser._pass_through())) for _ in range(runs))
    unshortened = min(cpu_seconds(lambda: loop_alone(frozenset())) for _ in range(runs))
    whole = min(cpu_seconds(lambda: parse_text(text, "bench.mod")) for _ in range(runs))
    stages = [("reading", reading), ("scanning", scanning), ("LALR loop alone", looping),
              ("  without shortcuts", unshortened),
              ("AST construction", whole - scanning - looping), ("whole parse", whole)]
    print(f"{count} lines, {len(tokens)} tokens; CPU time, best of {runs}:")
    for name, seconds in stages:
        print(f"  {name:17} {seconds * 1000:7.1f} ms  {count / seconds:12,.0f} lines/s")
    floor_times(text, tokens, looping, runs)


def floor_times(text: str, tokens: list, looping: float, runs: int) -> None:
    """What the fast path cannot do without, each measured alone: the scanner's regular
    expression (its ``split`` of the text), making lark_cython's tokens (from their fields, in C), the compiled loop
    (no-op callbacks) and making the AST's nodes (from their fields, by ``construct``'s
    builders).  Their sum is the floor of this design, with no Python run per token or
    per rule beyond the feed and one call per reduction."""
    count = text.count("\n")
    pattern = parser._scanner().pattern
    matching = min(cpu_seconds(lambda: pattern.split(text)) for _ in range(runs))
    fields = [(t.type, t.value, t.start_pos, t.line, t.column, t.end_line, t.end_column,
               t.end_pos) for t in tokens]
    making = min(cpu_seconds(lambda: list(itertools.starmap(CompiledToken, fields)))
                 for _ in range(runs))
    built = _node_fields(parse_text(text, "bench.mod"))
    by_class: dict[type, list] = collections.defaultdict(list)
    for cls, values in built:
        by_class[cls].append(values)
    fillers = [(_filler(cls), values) for cls, values in by_class.items()]
    building = min(cpu_seconds(lambda: [fill(values) for fill, values in fillers])
                   for _ in range(runs))
    floor = [("regular expression", matching), ("token objects", making),
             ("LALR loop alone", looping), (f"{len(built):,} AST nodes", building)]
    print("floor of this design (each part alone):")
    for name, seconds in floor + [("sum", sum(seconds for _, seconds in floor))]:
        print(f"  {name:17} {seconds * 1000:7.1f} ms  {count / seconds:12,.0f} lines/s")


def _node_fields(tree) -> list[tuple]:
    """(class, field values) of every distinct node of ``tree``, children first."""
    found: dict[int, tuple] = {}

    def visit(value):
        if isinstance(value, (tuple, list)):
            for item in value:
                visit(item)
        elif dataclasses.is_dataclass(value) and id(value) not in found:
            values = tuple(getattr(value, f.name) for f in dataclasses.fields(value))
            visit(values)
            found[id(value)] = (type(value), values)
    visit(tree)
    return list(found.values())


def _filler(cls: type):
    """A function making a ``cls`` node from each tuple of field values, in a loop of
    straight-line code that fills drafts as the front end's hot paths do (the least
    Python can spend on a frozen dataclass node)."""
    names = [f.name for f in dataclasses.fields(cls)]
    source = (f"def fill(rows):\n    made = []\n    for {', '.join(names)}, in rows:\n"
              f"        node = draft()\n"
              + "".join(f"        node.{name} = {name}\n" for name in names)
              + "        node.__class__ = cls\n        made.append(node)\n    return made\n")
    namespace = {"draft": draft_class(cls), "cls": cls}
    exec(source, namespace)
    return namespace["fill"]


def _ignore(entries):
    return None


def main(argv: list[str]) -> int:
    stages = "--stages" in argv
    argv = [argument for argument in argv if argument != "--stages"]
    lines = int(argv[1]) if len(argv) > 1 else 100_000
    runs = int(argv[2]) if len(argv) > 2 else 3
    started = time.perf_counter()
    rapid_parser()
    print(f"parser construction: {time.perf_counter() - started:.2f} s")
    text = generated_module(lines)
    parse_text(text, "bench.mod")               # warm up (the scanner, the compiled table)
    if stages:
        stage_times(text, runs)
    else:
        compare_paths(text, runs)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
