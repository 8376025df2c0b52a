"""The module ``rapidmc stubs`` writes always loads (issue 28).

Whatever the program, the written module parses and declares every type it uses: an
error ``stubs`` reports with exit 2 is the program's (a name whose type nothing tells,
a mistake of its own), never one inside the written module. With exit 0 the program and
the module load together (they build, as for ``check`` and ``run``). Checked on every program of
tests/stubs/ and on generated programs (tests/fuzz_programs.py) from which declarations
of data, types and routines were removed, as when modules of a backup are missing.
"""
from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

sys.path.insert(0, str(Path(__file__).parent))

from fuzz_invoke import DIAGNOSTIC_HEAD, ScratchFolder, assert_acceptable, invoke  # noqa: E402
from fuzz_programs import programs  # noqa: E402
from test_fuzz import fuzz_settings  # noqa: E402

from rapidmc.diagnostics import UserError, render_all  # noqa: E402
from rapidmc.semantics.link import build  # noqa: E402
from rapidmc.syntax import load_program  # noqa: E402

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

HERE = Path(__file__).resolve().parent / "stubs"
PROGRAMS = sorted(p for p in HERE.iterdir() if p.is_dir())
WORK = ScratchFolder("rapidmc-stubs-")     # WORK / name: a file in it
scratch_folder = WORK.fixture()
DECLARATION = re.compile(r"\s*(VAR|PERS|CONST|LOCAL|TASK|ALIAS)\b")
BLOCK = {"RECORD": "ENDRECORD", "PROC": "ENDPROC", "FUNC": "ENDFUNC", "TRAP": "ENDTRAP"}


def assert_written_module_loads(files: list[str], output: Path) -> None:
    """Run stubs on ``files`` writing ``output``; the module must load (see the top)."""
    output.unlink(missing_ok=True)
    outcome = invoke(["stubs", *files, "-o", str(output)])
    assert_acceptable(outcome)
    assert outcome.exit_code in (0, 2), outcome.describe()
    in_module = [line for line in outcome.stderr.splitlines()
                 if DIAGNOSTIC_HEAD.match(line) and line.startswith(f"{output}:")]
    assert not in_module, outcome.describe()
    if outcome.exit_code == 0 and output.exists():
        try:
            build(load_program([*files, str(output)]))
        except UserError as failure:
            raise AssertionError(render_all(failure.diagnostics)) from None


@pytest.mark.parametrize("folder", PROGRAMS, ids=[p.name for p in PROGRAMS])
def test_the_module_written_for_each_stubs_program_loads(folder, tmp_path):
    files = [str(p) for p in sorted(folder.glob("*.mod"))]
    assert_written_module_loads(files, tmp_path / "Missing.mod")


def declarations(lines: list[str]) -> list[tuple[int, int]]:
    """``(first, last)`` line ranges of the module's declarations: data, ALIAS, RECORD
    and routines other than ``main``."""
    found, number = [], 1
    while number < len(lines) - 1:
        words = lines[number].split()
        head = words[0] if words else ""
        if head in BLOCK and not (head == "PROC" and words[1].startswith("main(")):
            end = next(i for i in range(number, len(lines))
                       if lines[i].split()[:1] == [BLOCK[head]])
            found.append((number, end))
            number = end + 1
            continue
        if DECLARATION.match(lines[number]) and not found_routine(lines, number):
            found.append((number, number))
        number += 1
    return found


def found_routine(lines: list[str], number: int) -> bool:
    """Whether line ``number`` lies inside a routine (routine data, not module data)."""
    opened = 0
    for line in lines[:number]:
        head = line.split()[:1]
        if head and head[0] in ("PROC", "FUNC", "TRAP"):
            opened += 1
        elif head and head[0] in ("ENDPROC", "ENDFUNC", "ENDTRAP"):
            opened -= 1
    return opened > 0


@fuzz_settings(40)
@given(programs(), st.data())
def test_the_module_written_for_a_program_missing_declarations_loads(program, data):
    lines = program.text.splitlines()
    ranges = declarations(lines)
    removed = data.draw(st.sets(st.sampled_from(ranges), min_size=1)) if ranges else set()
    dropped = {i for first, last in removed for i in range(first, last + 1)}
    text = "\n".join(line for i, line in enumerate(lines) if i not in dropped) + "\n"
    source = WORK / "Program.mod"
    source.write_text(text, encoding="latin-1")
    assert_written_module_loads([str(source)], WORK / "Missing.mod")


# Values of a record type of a module not given, and component names the code reads:
# the record must take the values and, where they fit, the names (issue 28).
ATOMIC_PARTS = ("120", "-2.5", "TRUE", '"box"', "nSpeed", "sLabel", "bFlag")
NESTED_PARTS = ("[0, 0, 100]", "[1, 0, 0, 0]",
                "[[10, -17, 0, 0, 45, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]]")
USES = ("TPWrite {d}.{c};", "nValue := {d}.{c} + 1;", "IF {d}.{c} THEN\n    Stop;\n  ENDIF",
        "{d}.{c}.extax.eax_a := 0;", "MoveAbsJ {d}.{c}, v100, fine, tool0;",
        "{d}.{c}.x := 5;", "TPWrite \"n\" \\Num:={d}.{c};", "{d}.{c} := {d}.{c};")
COMPONENTS = ("length", "label", "ok", "c2", "c3", "joints", "trans", "count")

record_values = st.lists(st.sampled_from(ATOMIC_PARTS + NESTED_PARTS), min_size=1, max_size=6)


@fuzz_settings(60)
@given(record_values, st.booleans(),
       st.lists(st.tuples(st.sampled_from(USES), st.sampled_from(COMPONENTS)), max_size=8),
       st.booleans())
def test_the_module_written_for_a_record_known_by_value_and_names_loads(parts, second, uses,
                                                                      data_first):
    value = "[" + ", ".join(parts) + "]"
    data = [f"  PERS celldata cell1 := {value};"]
    if second:   # another value of the type, literals where the first has names
        literal = {"nSpeed": "3", "sLabel": '"a"', "bFlag": "FALSE"}
        data.append("  PERS celldata cell2 := [" +
                    ", ".join(literal.get(p, p) for p in parts) + "];")
    body = "\n  ".join(use.format(d="cell1", c=name) for use, name in uses)
    main = f"MODULE CellMain\n  PROC main()\n  {body}\n  ENDPROC\nENDMODULE\n"
    teach = "MODULE CellData\n" + "\n".join(data) + "\nENDMODULE\n"
    files = []
    for name, text in (("A.mod", teach), ("B.mod", main)) if data_first else \
            (("A.mod", main), ("B.mod", teach)):
        (WORK / name).write_text(text, encoding="latin-1")
        files.append(str(WORK / name))
    assert_written_module_loads(files, WORK / "Missing.mod")
