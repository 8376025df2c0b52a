"""The pieces of a readable counterexample: values per part, shortening, folding, literals.

The whole text is pinned by tests/test_counterexample_text.py on RAPID programs; these
tests pin each rule on its own, with the cases the rule distinguishes.
"""
from __future__ import annotations

import re

import pytest

from rapidmc.check.trace import INITIAL, TRANSITION, Change, Composite, Trace, TraceStep, \
    TransitionInfo, changes_between
from rapidmc.model.value_text import value_text
from rapidmc.diagnostics import source_window
from rapidmc.report.counterexample import Folded, SlicedAway, change_text, fold_repeats, sliced_line, \
    step_lines
from rapidmc.report.line_width import wrapped
from rapidmc.report.headline import headline_lines, indexed_data
from rapidmc.report.trace_slice import read_part
from rapidmc.report.trace_text import SOURCE_WIDTH, file_names, shorten, shown_location, shown_value
from rapidmc.semantics.types import NON_VALUE_TYPES, NUM, POS, ROBTARGET, ArrayType

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py


def array(*values: str) -> Composite:
    return Composite("[" + ",".join(values) + "]",
                     tuple((f"{{{i}}}", v) for i, v in enumerate(values, start=1)))


def pos(x: str, y: str, z: str) -> Composite:
    return Composite(f"[{x},{y},{z}]", ((".x", x), (".y", y), (".z", z)))


@pytest.mark.parametrize("old, new, expected", [
    # one element of an array: that element
    (array("0", "0", "0", "0"), array("0", "7", "0", "0"), [("a{2}", "0", "7")]),
    # a few elements: each; most of them: the whole array
    (array("0", "0", "0", "0"), array("1", "0", "2", "0"), [("a{1}", "0", "1"),
                                                          ("a{3}", "0", "2")]),
    (array("0", "0", "0", "0"), array("1", "2", "3", "4"), [("a", "[0,0,0,0]", "[1,2,3,4]")]),
    # one component of a record: that component; two: the whole record
    (pos("1", "2", "3"), pos("1", "5", "3"), [("a.y", "2", "5")]),
    (pos("1", "2", "3"), pos("4", "5", "3"), [("a", "[1,2,3]", "[4,5,3]")]),
    # nested: down to the one part that changed
    (Composite("[[1,2,3]]", (("{1}", pos("1", "2", "3")),)),
     Composite("[[1,9,3]]", (("{1}", pos("1", "9", "3")),)), [("a{1}.y", "2", "9")]),
    # plain text: as a whole
    ("0", "1", [("a", "0", "1")]),
])
def test_changes_name_the_part_that_changed(old, new, expected):
    changes = changes_between({"a": old}, {"a": new})
    assert [(c.name, c.old, c.new) for c in changes] == expected


def test_value_text_names_parts_as_rapid_does():
    grid = value_text(((1.0, 2.0), (3.0, 4.0)), ArrayType(NUM, (2, 2)))
    assert grid == "[[1,2],[3,4]]"
    assert [suffix for suffix, _ in grid.parts] == ["{1,1}", "{1,2}", "{2,1}", "{2,2}"]
    target = value_text(((1.0, 2.0, 3.0), (1.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0),
                         (9e9,) * 6), ROBTARGET)
    assert [suffix for suffix, _ in target.parts] == [".trans", ".rot", ".robconf", ".extax"]
    assert target.parts[0][1].parts[2] == (".z", "3")


def test_data_without_a_literal_shows_its_type():
    assert value_text((None, None, None), ArrayType(NON_VALUE_TYPES["SYNCIDENT"], (3,))) == \
        "[<syncident>,<syncident>,<syncident>]"
    assert value_text(b"\x00\x01", NON_VALUE_TYPES["RAWBYTES"]) == "<rawbytes: 2 bytes>"
    assert value_text((1.0, 2.0, "x"), POS) == '[1,2,"x"]'         # by what it holds


@pytest.mark.parametrize("text, width, expected", [
    ("[1,2,3]", 10, "[1,2,3]"),
    ("[[932.4,1557.5,2189.5],[1,0,0,0],[1,1,0,0]]", 30, "[[932.4,1557.5,2189.5],...]"),
    ("[[932.4,1557.5,2189.5],[1,0,0,0],[1,1,0,0]]", 20, "[[932.4,1557.5,...]]"),
    ('["a,b","c,d","e,f"]', 12, '["a,b",...]'),                # commas in strings are text
    ('"' + "x" * 50 + '"', 20, '"' + "x" * 15 + '..."'),
])
def test_shorten_cuts_at_an_element_boundary(text, width, expected):
    assert shorten(text, width) == expected


def test_a_long_array_written_whole_shows_only_its_changed_elements():
    old = array(*[str(i) for i in range(1, 61)])
    new = array(*[("0" if i in (3, 30) else str(i)) for i in range(1, 61)])
    text = change_text(Change("table", old, new))
    assert text == "table: 2 of 60 elements changed: {3} = 0 (was 3), {30} = 0 (was 30)"
    # with most elements changed the value itself, shortened, and its length
    mostly = array(*["9"] * 60)
    # (every element one value: the first says it)
    assert change_text(Change("table", old, mostly)).startswith(
        "table = [9,...] (60 elements, all 9)  (was [1,2,3,")
    # a matrix of one value: its first element, nested
    matrix = Composite("[" + ",".join(["[FALSE,FALSE,FALSE,FALSE]"] * 20) + "]",
                       tuple((f"{{{row},{column}}}", "FALSE") for row in range(1, 21)
                             for column in range(1, 5)))
    assert shown_value(matrix, 100) == "[[FALSE,...]] (80 elements, all FALSE)"
    # more changed elements than are listed: a count (--full-trace shows them all)
    many = array(*[("0" if i % 10 == 0 else str(i)) for i in range(1, 61)])
    assert change_text(Change("table", old, many)).endswith(
        "{40} = 0 (was 40) and 2 more")
    assert change_text(Change("table", old, many), full=True) == f"table = {many}  (was {old})"


def test_a_long_string_is_shortened_with_its_length():
    message = '"The gripper reported a fault while the part was released at station four"'
    assert shown_value(message, 100, 48) == \
        '"The gripper reported a fault while the part..." (72 characters)'
    assert shown_value('"short"', 100, 48) == '"short"'
    assert shown_value('"say ""hi"" now"', 100, 8) == '"say..." (12 characters)'


def test_no_line_is_longer_than_the_width_and_nothing_is_lost():
    line = "        table = [" + ",".join(str(i) for i in range(1, 400)) + "]  (was [])"
    pieces = wrapped(line).split("\n")
    assert len(pieces) > 1 and max(map(len, pieces)) <= 300
    assert "".join(piece.removeprefix("            ") for piece in pieces[1:]) == \
        line[len(pieces[0]):]
    assert wrapped("short line\n  another") == "short line\n  another"


def test_a_long_source_line_is_shown_around_its_caret():
    source = "x := " + " + ".join(f'"part {i}"' for i in range(60)) + ";"
    shown, column = source_window(source, source.index('"part 50"'))
    assert len(shown) <= 206 and shown.startswith("...")
    assert shown[column:].startswith('"part 50"')


@pytest.mark.parametrize("source, read", [
    ('IF n{1} <> 0 AND s = "Weld" rec.cpm := w{n{1}}.cpm;', ["IF", "n", "1", "0", "AND", "s", "Weld",
                                                          "w", "n", "1", "cpm"]),
    ("IF ok c{i}.x := 1;", ["IF", "ok", "i", "1"]),
    ("IF ok Foo \\Arg:=x;", ["IF", "ok", "Foo", "Arg", "x"]),     # a named argument: all
    ("IF n > 0 THEN", ["IF", "n", "0", "THEN"]),
])
def test_read_part_of_a_one_line_if_leaves_out_the_data_it_assigns(source, read):
    assert re.findall(r"[A-Za-z0-9]+", read_part(source)) == read


def test_read_part_of_an_assignment_is_its_value_and_target_indexes():
    assert read_part("waypoints{count + 1}.trans.x := n / d;").split() == \
        ["count", "+", "1", "n", "/", "d;"]
    assert read_part("MoveL p, v, z, tool0;") == "MoveL p, v, z, tool0;"


def _step(index: int, line: int, *changes: Change) -> TraceStep:
    return TraceStep(index, TRANSITION, TransitionInfo("p.mod", line, f"line {line}"), changes)


@pytest.mark.parametrize("source, indexed", [
    ("nTemp := Welds1{i}.cpm / 6", {"WELDS1"}),
    ("x := a{b{i}} + c{2}", {"A", "C"}),     # b's element is an index: its value tells
    ("x := s{i, j}.v", {"S"}),
    ("x := y + 1", set()),
    # the datum whose element is the index stays
    ('IF step{1} <> 0 AND s = "Weld" v := speeds{step{1}};', {"SPEEDS"}),
])
def test_an_index_error_leaves_out_the_values_of_the_arrays_the_line_indexes(source, indexed):
    """The headline of ERR_OUTOFBND shows the index, not the elements of the array it
    indexes (the error gives its bounds)."""
    assert indexed_data(read_part(source)) == indexed


def test_a_calls_new_data_are_told_on_one_line_after_its_routine():
    step = TraceStep(3, TRANSITION, TransitionInfo("p.mod", 7, "Pick 2;"),
                     (Change("Pick.side", None, "2"), Change("Pick.no", None, "0"),
                      Change("count", "1", "2"), Change("Place.at", None, "4")))
    assert step_lines(step)[1:] == ["        Pick: side = 2, no = 0",
                                    "        count = 2  (was 1)",
                                    "        Place.at = 4"]


@pytest.mark.parametrize("source, output, shown", [
    ('TPWrite "Ready";', "Ready\n", False),
    ('TPReadFK n, "Load or unload?", "Load", "Unload", "", "", "";', "Load or unload?\n", False),
    ('TPWrite "Say ""hi""";', 'Say "hi"\n', False),
    ('TPWrite name + ": waiting";', "MS_Left: waiting\n", True),     # computed: told
    ('TPWrite "count " \\Num:=n;', "count 3\n", True),
])
def test_an_output_is_listed_only_when_the_line_does_not_show_its_text(source, output, shown):
    step = TraceStep(2, TRANSITION, TransitionInfo("p.mod", 2, source, {}, output), ())
    assert any(line.strip().startswith("output:") for line in step_lines(step)) == shown


def test_the_sockets_a_stopping_program_closes_are_not_listed_at_its_last_step():
    def stop(source):
        return TraceStep(9, TRANSITION, TransitionInfo("p.mod", 9, source),
                         (Change("client", "<socketdev: connected>", "<socketdev: closed>"),
                          Change("ERRNO", "0", "ERR_SOCK_CLOSED"),
                          Change("program", None, "stopped: uncaught ERR_SOCK_CLOSED")))
    assert [line.split(" =")[0].strip() for line in step_lines(stop("RAISE;"))[1:]] == \
        ["ERRNO", "program"]
    # a SocketClose of its own says what it closed
    assert "client" in step_lines(stop("SocketClose client;"))[1]


def test_a_calls_many_new_data_take_lines_of_at_most_the_source_width():
    changes = tuple(Change(f"Load.value{n}", None, "1" * 40) for n in range(6))
    lines = step_lines(TraceStep(2, TRANSITION, TransitionInfo("p.mod", 3, "Load;"), changes))[1:]
    assert len(lines) > 1 and all(len(line) <= 8 + SOURCE_WIDTH for line in lines)
    assert all(line.strip().startswith("Load: value") for line in lines)
    assert sum(line.count(" = ") for line in lines) == 6


def test_the_headline_tells_one_routines_data_of_one_origin_together():
    steps = [TraceStep(1, INITIAL, None, (Change("d", None, "0"),)),
             TraceStep(2, TRANSITION, TransitionInfo("p.mod", 5, "Get;"),
                       (Change("Get.n", None, "0"), Change("Get.m", None, "3"))),
             TraceStep(3, TRANSITION, TransitionInfo("p.mod", 9, "d := m / n + d;"),
                       (Change("ERRNO", None, "ERR_DIVZERO"),))]
    trace = Trace(tuple(steps), (), None, ending="uncaught ERR_DIVZERO")
    assert headline_lines(trace)[2:] == ["    Get: m = 3, n = 0  (set at step 2)",
                                         "    d = 0  (initial value)"]


def test_a_stretch_run_three_times_folds_into_one_line():
    steps = [TraceStep(1, INITIAL, None, (Change("n", None, "0"),))]
    for turn in range(4):           # lines 5, 6 four times; each time n and a{turn} change
        steps.append(_step(len(steps) + 1, 5, Change("n", str(turn), str(turn + 1))))
        steps.append(_step(len(steps) + 1, 6, Change(f"a{{{turn + 1}}}", "0", "1")))
    steps.append(_step(len(steps) + 1, 7))
    items = fold_repeats(steps)
    assert [getattr(item, "index", None) for item in items] == [1, 2, 3, None, 10]
    folded = items[3]
    assert isinstance(folded, Folded) and (folded.first, folded.last, folded.times) == (2, 3, 3)
    assert [step.index for step in folded.hidden] == [4, 5, 6, 7, 8, 9]


def test_a_stretch_run_twice_or_with_other_lines_stays():
    twice = [_step(1, 5), _step(2, 6), _step(3, 5), _step(4, 6)]
    assert fold_repeats(twice) == twice
    varied = [_step(1, 5), _step(2, 5, Change("n", "0", "1")), _step(3, 5)]
    assert fold_repeats(varied) == varied


def test_files_are_shown_relative_to_the_current_folder_or_their_common_folder(
        tmp_path, monkeypatch):
    from rapidmc.report.trace_text import FileNames
    (tmp_path / "here").mkdir()
    monkeypatch.chdir(tmp_path / "here")
    inside = str(tmp_path / "here" / "a" / "prog.mod")
    assert file_names([inside]) == FileNames(str(tmp_path / "here"))
    assert shown_location(TransitionInfo(inside, 7, ""), file_names([inside])) == \
        "a/prog.mod:7"
    backup = [str(tmp_path / "b" / "RAPID" / "T_ROB1" / "PROGMOD" / "m.mod"),
              str(tmp_path / "b" / "RAPID" / "T_ROB1" / "SYSMOD" / "s.sys")]
    names = file_names(backup)
    assert names.legend() == [f"(files relative to {tmp_path / 'b' / 'RAPID' / 'T_ROB1'})"]
    assert shown_location(TransitionInfo(backup[1], 3, ""), names) == "SYSMOD/s.sys:3"


def test_a_backup_deep_below_the_current_folder_names_its_folders_once(tmp_path, monkeypatch):
    """``rapidmc check cells/line_4/Controller1_240820-161154`` run from the folder above:
    each step names the file below the backup's common folder, and the legend names that
    folder once, relative to the current folder (no absolute path in a report a README
    quotes)."""
    monkeypatch.chdir(tmp_path)
    rapid = tmp_path / "cells" / "line_4" / "Controller1_240820-161154" / "RAPID"
    backup = [str(rapid / "TASK1" / "PROGMOD" / "Module1.mod"),
              str(rapid / "TASK2" / "PROGMOD" / "Module1.mod")]
    names = file_names(backup)
    assert shown_location(TransitionInfo(backup[1], 54, ""), names) == \
        "TASK2/PROGMOD/Module1.mod:54"
    assert names.legend() == ["(files relative to cells/line_4/Controller1_240820-161154/RAPID)"]
    # a short path below the current folder stays as it is, with no legend
    assert file_names(["cell/prog.mod"]).shown("cell/prog.mod") == "cell/prog.mod"
    assert file_names(["cell/prog.mod"]).legend() == []


def test_files_in_far_apart_folders_are_shown_by_their_names(tmp_path, monkeypatch):
    # a program given by absolute path and the stubs module written in the current folder:
    # each by its name in the steps, each folder named once
    monkeypatch.chdir(tmp_path)
    program = "/srv/robots/cell_3/backup_2024/RAPID/TASK1/PROGMOD/Server.mod"
    names = file_names([program, "Missing.mod"])
    assert shown_location(TransitionInfo(program, 31, ""), names) == "Server.mod:31"
    assert names.shown(str(tmp_path / "Missing.mod")) == "Missing.mod"
    assert names.legend() == ["(files in /srv/robots/cell_3/backup_2024/RAPID/TASK1/PROGMOD: "
                              f"Server.mod; in {tmp_path}: Missing.mod)"]
    # two files of one name: relative to their common folder, or as given
    same = ["/srv/a/long_folder_name_one/x/prog.mod", "/srv/a/long_folder_name_two/y/prog.mod"]
    assert file_names(same).shown(same[0]) == "long_folder_name_one/x/prog.mod"
    assert file_names(["/a/prog.mod", "/b/prog.mod"]).shown("/b/prog.mod") == "/b/prog.mod"


def step(index: int, source: str, *changed: str) -> TraceStep:
    return TraceStep(index, TRANSITION, TransitionInfo("p.mod", index, source),
                     tuple(Change(name, "0", "1") for name in changed))


def test_slice_keeps_what_the_failing_line_reads_and_every_branch():
    from rapidmc.check.trace import Trace
    from rapidmc.report.trace_slice import needed_steps
    steps = (TraceStep(1, INITIAL, None, ()),
             step(2, "k{1} := 1;", "k{1}"),            # not read: left out
             step(3, "n := m + 1;", "n"),              # read by the branch at 5
             step(4, "d := 0;", "d"),                  # read by the failing line
             step(5, "IF n > 0 THEN", ),               # a branch: always kept
             step(6, "x := k{2} + 1;", "x"),           # writes x, which nobody reads
             step(7, "y := 1 / d;"))
    trace = Trace(steps, (), None, "uncaught ERR_DIVZERO")
    assert sorted(needed_steps(trace)) == [1, 3, 4, 5, 7]
    # an atom that reads x keeps its writer
    assert 6 in needed_steps(trace, {"X"})


def test_slice_reads_the_arguments_of_an_instruction_with_an_optional_argument():
    # ``\Str:=request`` is an argument, not an assignment: the socket is read too
    from rapidmc.check.trace import Trace
    from rapidmc.report.trace_slice import needed_steps
    steps = (TraceStep(1, INITIAL, None, ()),
             step(2, "SocketCreate client;", "client"),
             step(3, "SocketConnect client, \"10.0.0.1\", 1025;", "client"),
             step(4, "SocketReceive client \\Str:=request;"))
    assert sorted(needed_steps(Trace(steps, (), None, "uncaught ERR_SOCK_TIMEOUT"))) == \
        [1, 2, 3, 4]


def test_slice_ends_the_need_for_a_datum_at_its_whole_assignment_only_where_unambiguous():
    from rapidmc.check.trace import Trace
    from rapidmc.report.trace_slice import needed_steps
    steps = (TraceStep(1, INITIAL, None, ()),
             step(2, "x := 1;", "x"),                  # overwritten at 3 before the read
             step(3, "x := 2;", "x"),
             step(4, "y := 1 / (x - 2);"))
    assert sorted(needed_steps(Trace(steps, (), None, "uncaught ERR_DIVZERO"))) == [1, 3, 4]
    # a routine's own x is in the trace too: the name may mean either, both writes stay
    local = steps[:3] + (step(4, "x := 5;", "main.x"), step(5, "y := 1 / (x - 2);"))
    assert sorted(needed_steps(Trace(local, (), None, "uncaught ERR_DIVZERO"))) == \
        [1, 2, 3, 4, 5]


def test_slice_keeps_a_step_that_raised_an_error_and_one_that_chose_an_input():
    # the error handler at line 9 reads ERRNO; step 3 raised (ERRNO unchanged: the same
    # error again), so it and the socket it reads stay shown; the answer TPReadNum gave n
    # (n's value already: no change) is what the failing line divides by
    from rapidmc.check.trace import Trace
    from rapidmc.report.trace_slice import needed_steps
    steps = (TraceStep(1, INITIAL, None, ()),
             step(2, "SocketCreate s;", "s"),
             step(3, "SocketReceive s \\Str:=text;"),
             TraceStep(9, TRANSITION, TransitionInfo("p.mod", 9, "RETRY;"), ()),
             step(10, "k := 1;", "k"),
             TraceStep(11, TRANSITION, TransitionInfo("p.mod", 11, "TPReadNum n, \"n?\";",
                                                      {"TPReadNum": "0"}), ()),
             step(12, "k := 2;", "k"),
             step(13, "y := 1 / n;"))
    trace = Trace(steps, (), None, "uncaught ERR_DIVZERO")
    assert sorted(needed_steps(trace)) == [1, 9, 11, 13]
    assert sorted(needed_steps(trace, handler_starts=frozenset({("p.mod", 9)}))) == \
        [1, 2, 3, 9, 11, 13]


def test_slice_counts_an_input_a_plain_statement_names_by_what_it_writes():
    # ServerConnect ip_pers: the PERS read from outside goes into the call's parameters,
    # which nothing kept reads: the step is left out.  An input the statement does not name
    # (an interrupt's edge at that step) and one a branch reads stay kept.
    from rapidmc.check.trace import Trace
    from rapidmc.report.trace_slice import needed_steps

    def chose(index: int, source: str, inputs: dict, *changed: str) -> TraceStep:
        return TraceStep(index, TRANSITION, TransitionInfo("p.mod", index, source, inputs),
                         tuple(Change(name, None, "1") for name in changed))
    steps = (TraceStep(1, INITIAL, None, ()),
             chose(2, "ServerConnect ip_pers, 5000;", {"ip_pers": '"10.0.0.2"'},
                   "ServerConnect.ip"),
             chose(3, "count := count + 1;", {"di_alarm": "1"}, "count"),
             chose(4, "IF mode_pers = 2 THEN", {"mode_pers": "2"}),
             step(5, "y := 1 / 0;"))
    assert sorted(needed_steps(Trace(steps, (), None, "uncaught ERR_DIVZERO"))) == [1, 3, 4, 5]
    # the parameter read later: the call and the input it chose count
    read = steps[:4] + (step(5, "y := 1 / ip;"),)
    assert 2 in needed_steps(Trace(read, (), None, "uncaught ERR_DIVZERO"))


def test_slice_tells_one_routines_data_from_anothers_of_the_same_name():
    # Main's loop counter i is not Fill's i: the error in Fill reads Fill's own, so Main's
    # writes are left out; a routine without an i of its own reads the global one
    from rapidmc.check.trace import CallFrame, Trace
    from rapidmc.report.trace_slice import needed_steps

    def in_(routines, index, source, *changed):
        frames = tuple(CallFrame(name, "p.mod", line) for name, line in routines)
        return TraceStep(index, TRANSITION, TransitionInfo("p.mod", index, source),
                         tuple(Change(name, "0", "1") for name in changed), frames)
    main, fill = ("Main", 4), ("Fill", 6)
    steps = (TraceStep(1, INITIAL, None, ()),
             in_([main], 2, "i := 1;", "Main.i"),
             in_([main], 3, "i := 2;", "Main.i"),
             in_([main], 4, "Fill;", "Fill.i"),
             in_([main, fill], 5, "i := 0;", "Fill.i"),
             in_([main, fill], 6, "y := 1 / i;"))
    assert sorted(needed_steps(Trace(steps, (), None, "uncaught ERR_DIVZERO"))) == [1, 4, 5, 6]
    # Show has no i of its own: the i it reads is a global one, which a write of the
    # global i keeps and Main's writes do not
    show = ("Show", 6)
    shown = steps[:3] + (in_([main], 4, "i := 3;", "i"), in_([main], 5, "Show;"),
                         in_([("Main", 5), show], 6, "y := 1 / i;"))
    assert sorted(needed_steps(Trace(shown, (), None, "uncaught ERR_DIVZERO"))) == \
        [1, 4, 5, 6]
    # names a trace does not qualify by task stay plain (as a cycle's and a property's)
    tasks = tuple(TraceStep(s.index, s.kind, s.transition, s.changes,
                            tuple(CallFrame(f.routine, f.file, f.line, "T_ROB1") for f in s.stack))
                  for s in steps)
    assert sorted(needed_steps(Trace(tasks, (), None, "uncaught ERR_DIVZERO"))) == \
        [1, 2, 3, 4, 5, 6]


def test_slice_tells_one_tasks_data_from_anothers_of_the_same_name():
    # Two tasks each have an i: the error in T1 reads T1's own, so T2's writes of its i and
    # T2's wait (it decides only T2's path) are left out; the shared PERS flag, written by
    # T2 and read by T1, keeps T2's write
    from rapidmc.check.trace import CallFrame, Trace
    from rapidmc.report.trace_slice import needed_steps, running_tasks

    def at(task, index, source, *changed):
        files = {"T1": "a.mod", "T2": "b.mod"}
        frames = tuple(CallFrame("main", files[name], index if name == task else 1, name)
                       for name in ("T1", "T2"))
        stops = (Change("program", None, "stopped: uncaught ERR_DIVZERO"),) \
            if source.startswith("y :=") else ()
        return TraceStep(index, TRANSITION, TransitionInfo(files[task], index, source),
                         tuple(Change(name, "0", "1") for name in changed) + stops, frames)
    steps = (TraceStep(1, INITIAL, None, ()),
             at("T2", 2, "WaitTime 0.5;"),
             at("T2", 3, "i := 5;", "T2.i"),
             at("T1", 4, "i := 0;", "T1.i"),
             at("T2", 5, "i := 7;", "T2.i"),
             at("T1", 6, "y := 1 / i;"))
    assert running_tasks(steps) == [None, "T2", "T2", "T1", "T2", "T1"]
    assert sorted(needed_steps(Trace(steps, (), None, "uncaught ERR_DIVZERO"))) == [1, 4, 6]
    shared = steps[:4] + (at("T2", 5, "flag := 7;", "flag"), at("T1", 6, "y := 1 / flag;"))
    assert sorted(needed_steps(Trace(shared, (), None, "uncaught ERR_DIVZERO"))) == \
        [1, 2, 5, 6]
    # a cycle (or a property) reads plain names: every task's i counts
    assert sorted(needed_steps(Trace(steps[:5], steps[5:], None))) == [1, 2, 3, 4, 5, 6]


def test_headline_reads_the_failing_tasks_own_routine_data():
    # both tasks run Receive, whose msg_length each sets; T1's line fails: the headline
    # shows T1's msg_length (0, set at step 3), not T2's later one
    from rapidmc.check.trace import CallFrame
    from rapidmc.report.headline import read_data

    def at(task, index, source, *changes):
        frames = tuple(CallFrame("Receive", "sock.sys", index if name == task else 1, name)
                       for name in ("T1", "T2"))
        return TraceStep(index, TRANSITION, TransitionInfo("sock.sys", index, source),
                         tuple(Change(name, "4", new) for name, new in changes), frames)
    steps = [TraceStep(1, INITIAL, None, ()),
             at("T2", 2, "msg_length := 4;", ("T2.Receive.msg_length", "4")),
             at("T1", 3, "msg_length := 0;", ("T1.Receive.msg_length", "0")),
             at("T2", 4, "msg_length := 9;", ("T2.Receive.msg_length", "9")),
             at("T1", 5, "y := 1 / msg_length;")]
    assert read_data(steps) == [("T1.Receive.msg_length", "0", "set at step 3")]


def test_a_long_assumption_is_cut_with_its_place_kept():
    from rapidmc.report.results import short_assumption
    text = "PERS Welds1 is written outside the loaded code; its reads take " + \
        "; ".join(f"Welds1.c{i}: 0" for i in range(40)) + " (Teaching.mod:25)"
    short = short_assumption(text)
    assert len(short) < 300 and short.endswith("; ... (--format json lists it whole) "
                                               "(Teaching.mod:25)")
    assert short_assumption("stub GripOpen is empty (Missing.mod:12)") == \
        "stub GripOpen is empty (Missing.mod:12)"


def test_steps_left_out_count_each_output_by_where_it_went():
    # a socket message or a file line is not a FlexPendant line (the library marks them)
    outputs = ("[socket] alive\n", "part ok\n", "[file log.txt] cycle 1\n[file log.txt] cycle 2\n",
               "[socket] alive\n")
    steps = tuple(TraceStep(index, TRANSITION, TransitionInfo("p.mod", index, "x", {}, output), ())
                  for index, output in enumerate(outputs, start=2))
    line = sliced_line(SlicedAway(steps, "the error"))
    assert "1 FlexPendant line written, 2 socket messages sent, 2 file lines written" in line


def test_assumptions_differing_in_one_string_or_in_their_numbers_are_told_once():
    from rapidmc.report.results import merged_assumptions
    texts = ['CRobT reads the calling task\'s robot for \\TaskName:="T_ROB_L", which names no '
             'loaded task (RMC702)',
             'stub GripOpen is empty (Missing.mod:12)',
             'CRobT reads the calling task\'s robot for \\TaskName:="T_ROB_R", which names no '
             'loaded task (RMC702)',
             'the signal AliasIO names at run time at Hand.sys:1092 is taken as configured, '
             'shown as <AliasIO at file:line>',
             'the signal AliasIO names at run time at Hand.sys:1094 is taken as configured, '
             'shown as <AliasIO at file:line>',
             'the signal AliasIO names at run time at Hand.sys:1096 is taken as configured, '
             'shown as <AliasIO at file:line>']
    assert merged_assumptions(texts) == [
        'CRobT reads the calling task\'s robot for \\TaskName:="T_ROB_L", "T_ROB_R", which '
        'names no loaded task (RMC702)',
        'stub GripOpen is empty (Missing.mod:12)',
        'the signal AliasIO names at run time at Hand.sys:1092 (and 1094, 1096) is taken as '
        'configured, shown as <AliasIO at file:line>']


def test_the_same_assumption_twice_is_told_once_with_or_without_a_quoted_string():
    # a backup of ten tasks, each loading the stubs module, gave the same texts several
    # times, with no quoted string: the merge must neither fail nor repeat them
    from rapidmc.report.results import merged_assumptions
    texts = ["stub max returns a neutral value (Missing.mod:39)",
             "stub max returns a neutral value (Missing.mod:39)",
             'PERS stCommand is written outside ("Weld")', 'PERS stCommand is written outside ("Weld")',
             "a lone quote \" in a text", "a lone quote \" in a text"]
    assert merged_assumptions(texts) == [
        "stub max returns a neutral value (Missing.mod:39)",
        'PERS stCommand is written outside ("Weld")', "a lone quote \" in a text"]


def test_where_whole_assumptions_are_is_said_once():
    from rapidmc.check.result import HOLDS, SearchResult
    from rapidmc.report.results import PropertyResult, assumption_lines
    long = [f"PERS {name} is written outside the loaded code; its reads take " +
            "; ".join(f"{name}.c{i}: {'FALSE' if n % 2 else '0'}" for i in range(40)) +
            f" (M.mod:{n})" for n, name in enumerate("abcdefgh")]
    checked = PropertyResult("p", "G x", SearchResult(HOLDS),
                             assumes=tuple(long))
    lines = assumption_lines(checked)
    assert sum("--format json" in line for line in lines) == 1
    assert lines[-1].endswith("(--format json lists them all, each whole)")
    two = PropertyResult("p", "G x", SearchResult(HOLDS),
                         assumes=tuple(long[:2]))
    lines = assumption_lines(two)
    assert "(--format json lists it whole) (M.mod:0)" in lines[0] and \
        "--format json" not in lines[1] and lines[1].endswith("... (M.mod:1)")


def test_many_assumptions_differing_in_their_numbers_list_three_and_count_the_rest():
    from rapidmc.report.results import merged_assumptions
    texts = [f"the signal AliasIO names at run time at Hand.sys:{line} is taken as configured"
             for line in range(1000, 1010)]
    assert merged_assumptions(texts) == [
        "the signal AliasIO names at run time at Hand.sys:1000 (and 1001, 1002, 1003 and 6 "
        "more) is taken as configured"]


def test_a_stretch_left_out_names_the_routines_that_returned_in_it():
    # a routine's data ends with it: its name, not its data (with several tasks the task's
    # name comes first: T_ROB1.Hold.t is routine Hold's t)
    ended = (TraceStep(4, TRANSITION, TransitionInfo("p.mod", 4, "ENDPROC"),
                       (Change("T_ROB1.Hold.t", "1", None), Change("T_ROB1.Hold.n", "0", None))),
             TraceStep(5, TRANSITION, TransitionInfo("p.mod", 5, "k := 2;"),
                       (Change("T_ROB1.k", "1", "2"),)))
    assert sliced_line(SlicedAway(ended, "the error")) == \
        "    -- steps 4-5: T_ROB1.k assigned, Hold returned, not read by the error --"


def test_rounds_fold_between_the_first_round_and_the_last():
    # a handler's round: the failing read (its outcome chosen in the first round only: it
    # stays the same for the run), the reconnect, a flag only the first round changes,
    # RETRY; five rounds: the first and the last stay steps, three fold
    from rapidmc.report.rounds import Rounds, fold_rounds

    def round_steps(first: int, number: int) -> list:
        inputs = {"ReadCfgData outcome": "ERR_CFG_NOTFND"} if number == 1 else {}
        return [TraceStep(first, TRANSITION, TransitionInfo("p.mod", 20, "ReadCfgData p, v;",
                                                            inputs), ()),
                TraceStep(first + 1, TRANSITION, TransitionInfo("p.mod", 30, "Reconnect;"), ()),
                TraceStep(first + 2, TRANSITION, TransitionInfo("p.mod", 31, "flag := TRUE;"),
                          (Change("flag", "FALSE", "TRUE"),) if number == 1 else ()),
                TraceStep(first + 3, TRANSITION, TransitionInfo("p.mod", 32, "RETRY;"), ())]
    steps = [TraceStep(1, INITIAL, None, ())]
    for number in range(1, 6):
        steps += round_steps(2 + 4 * (number - 1), number)
    items = fold_rounds(steps)
    folded = [item for item in items if isinstance(item, Rounds)]
    assert len(folded) == 1 and (folded[0].first, folded[0].last, folded[0].times) == (2, 5, 3)
    assert [step.index for step in folded[0].hidden] == list(range(6, 18))
    assert [item.index for item in items if not isinstance(item, Rounds)] == \
        [1, 2, 3, 4, 5, 18, 19, 20, 21]
    assert folded[0].jump == "RETRY" and folded[0].retries == (1, 4)
    # two rounds only, or rounds that run other lines: nothing folds
    assert fold_rounds(steps[:9]) == steps[:9]
    varied = steps[:10] + [step(11, "other;")] + steps[11:]     # the third round differs
    assert not any(isinstance(item, Rounds) for item in fold_rounds(varied))

