"""ReadCfgData of an instance rapidmc cannot look up: one outcome per run (issue 28).

A controller's configuration does not change while the program runs, so the first read of an
instance and attribute rapidmc does not know chooses found or ERR_CFG_NOTFND, and every later
read of the same instance and attribute gives that outcome.  On both engines.
"""
from __future__ import annotations

import pytest

from rapidmc.check import native
from rapidmc.semantics.library.configuration_outcomes import read_key, remember, remembered
from tests.test_realworld import cli

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

# the same instance read twice: the second read cannot fail once the first has found it
TWICE = """MODULE Twice
    VAR num value := 0;
    VAR num reads := 0;

    PROC main()
        ReadCfgData "MOC/ARM/rob_R_1", "upper_joint_bound", value;
        reads := 1;
        ReadCfgData "/MOC/ARM/rob_R_1", "upper_joint_bound", value;
        reads := 2;
    ENDPROC
ENDMODULE
"""

# another instance and another attribute are chosen on their own
OTHERS = """MODULE Others
    VAR num value := 0;
    VAR num found := 0;

    PROC main()
        ReadCfgData "MOC/ARM/rob_R_1", "upper_joint_bound", value;
        found := 1;
        ReadCfgData "MOC/ARM/rob_R_2", "upper_joint_bound", value;
        found := 2;
        ReadCfgData "MOC/ARM/rob_R_2", "lower_joint_bound", value;
        found := 3;
    ENDPROC
ENDMODULE
"""

# the pattern of a public program: retry the read while the instance is not found
RETRIED = """MODULE RetriedRead
    VAR num value := 0;

    PROC main()
        ReadCfgData "MOC/ARM/rob_R_1", "upper_joint_bound", value;
        TPWrite "read";
    ERROR
        IF ERRNO = ERR_CFG_NOTFND THEN
            RETRY;
        ENDIF
    ENDPROC
ENDMODULE
"""


# two tasks read the same instance; each notes whether it found it (1) or not (2)
TASK = """MODULE Task{name}
    PERS num a_found := 0;
    PERS num b_found := 0;
    VAR num value := 0;

    PROC main()
        ReadCfgData "MOC/ARM/rob_R_1", "upper_joint_bound", value;
        {name}_found := 1;
    ERROR
        {name}_found := 2;
        RETURN;
    ENDPROC
ENDMODULE
"""


def check(tmp_path, text: str, engine: str, *formulas: str, options=()) -> str:
    program = tmp_path / "prog.mod"
    program.write_text(text)
    arguments = ["check", str(program), "--engine", engine, "--quiet", *options]
    for formula in formulas:
        arguments += ["--formula", formula]
    _, out, err = cli(arguments)
    return out + err


@pytest.mark.parametrize("engine", ENGINES)
def test_a_second_read_gives_the_first_outcome(tmp_path, engine):
    out = check(tmp_path, TWICE, engine,
                'found_stays: G ("reads = 1" -> !F "Failed()")',
                'ends_or_fails_first: G ("Failed()" -> "reads = 0")')
    assert "found_stays: HOLDS" in out and "ends_or_fails_first: HOLDS" in out, out
    # both outcomes remain: the first read may fail, and the program may end
    assert "no_runtime_error: VIOLATED" in out, out
    out = check(tmp_path, TWICE, engine, 'never_ends: G !"Ended()"')
    assert "never_ends: VIOLATED" in out, out


@pytest.mark.parametrize("engine", ENGINES)
def test_other_instances_and_attributes_are_chosen_apart(tmp_path, engine):
    out = check(tmp_path, OTHERS, engine,
                'second_may_fail: G ("found = 1" -> !F "Failed()")',
                'third_may_fail: G ("found = 2" -> !F "Failed()")')
    assert "second_may_fail: VIOLATED" in out and "third_may_fail: VIOLATED" in out, out


@pytest.mark.parametrize("engine", ENGINES)
def test_retrying_a_missing_instance_still_exceeds_the_retries(tmp_path, engine):
    out = check(tmp_path, RETRIED, engine, 'may_read: G !"AtLine(6)"')
    assert "no_runtime_error: VIOLATED" in out and "ERR_EXCRTYMAX" in out, out
    assert "may_read: VIOLATED" in out, out


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("reduction", ((), ("--no-por",)))
def test_every_task_reads_the_same_outcome(tmp_path, engine, reduction):
    other = tmp_path / "b.mod"
    other.write_text(TASK.format(name="b"))
    out = check(tmp_path, TASK.format(name="a"), engine,
                'agree: G !(("a_found = 1" & "b_found = 2") | ("a_found = 2" & "b_found = 1"))',
                'both_fail: G !("a_found = 2" & "b_found = 2")',
                'both_find: G !("a_found = 1" & "b_found = 1")',
                options=("--add-task", str(other), *reduction))
    assert "agree: HOLDS" in out, out
    assert "both_fail: VIOLATED" in out and "both_find: VIOLATED" in out, out


def test_the_memory_is_kept_in_one_order():
    first, second = read_key("/MOC/ARM/b", "X"), read_key("MOC/ARM/a", " x ")
    assert read_key("moc/arm/a", "X") == second
    assert read_key("MOC/ARM/A", "X") != second          # an instance's name keeps its case
    one = remember(remember((), first, True), second, False)
    other = remember(remember((), second, False), first, True)
    assert one == other
    assert remembered(one, first) is True and remembered(one, second) is False
    assert remembered(one, read_key("/MOC/ARM/c", "x")) is None
