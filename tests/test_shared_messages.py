"""Socket messages that another task reads: the domain follows the shared PERS data.

A socket task often keeps the last command in a PERS string and the motion task compares
it (the Hanoi cells' ``SocketStr``).  The messages a receive is offered come from the
code the received text reaches; that code includes every task that names a PERS datum the
text is copied into, or the motion task's commands are never sent, its branches are
reported "never reached" and a property about them HOLDS wrongly.
"""
from __future__ import annotations

import pytest

from rapidmc import api
from rapidmc.check import native
from rapidmc.load.message_domains import message_domains

from cli_capture import run_cli, two_task_verdicts

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

RECEIVER = """MODULE Recv
  VAR socketdev sock;
  VAR string msg := "";
  {storage} string cmd := "";
  PROC main()
    SocketCreate sock;
    SocketConnect sock, "10.0.0.2", 5000;
    SocketReceive sock \\Str:=msg;
    IF msg <> "" THEN
      cmd := msg;
    ENDIF
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ERROR
    RETRY;
  ENDPROC
ENDMODULE
"""

ROBOT = """MODULE Robot
  {storage} string cmd := "";
  VAR num x := 0;
  PROC main()
    WaitUntil cmd <> "";
    IF cmd = "go" THEN
      x := 1;
    ENDIF
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


def domain_of(tmp_path, *tasks: str) -> tuple:
    """The messages of the one receive of a program whose tasks are the module ``tasks``
    (the first is the main task)."""
    paths = []
    for number, text in enumerate(tasks):
        path = tmp_path / f"task{number}.mod"
        path.write_text(text)
        paths.append(str(path))
    program = api.load_program(paths[:1], add_tasks=paths[1:])
    [domain] = message_domains(program)
    return domain.messages


def test_a_command_only_another_task_compares_is_offered(tmp_path):
    messages = domain_of(tmp_path, RECEIVER.format(storage="PERS"),
                         ROBOT.format(storage="PERS"))
    assert "go" in messages


def test_a_task_pers_of_the_same_name_is_not_followed(tmp_path):
    """``TASK PERS`` data is each task's own: the robot's ``cmd`` never holds a message."""
    messages = domain_of(tmp_path, RECEIVER.format(storage="TASK PERS"),
                         ROBOT.format(storage="TASK PERS"))
    assert "go" not in messages


@pytest.mark.parametrize("engine", ENGINES)
def test_the_other_tasks_branch_is_reached_and_its_property_refuted(tmp_path, engine):
    program = (RECEIVER.format(storage="PERS"), ROBOT.format(storage="PERS"))
    found = two_task_verdicts(tmp_path, program, ['never_one: G "x = 0"'],
                              "--engine", engine)
    assert found["never_one"][0] == "VIOLATED"
    text = run_cli(["check", "prog.mod", "--add-task", "other.mod", "--quiet",
                    "--engine", engine], cwd=tmp_path)
    assert "never reached" not in text.err, text.err


RELAY = """MODULE Relay
  PERS string cmd := "";
  PERS string order := "";
  PROC main()
    WaitUntil cmd <> "";
    order := cmd;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
"""

LAST = """MODULE Last
  PERS string order := "";
  VAR num y := 0;
  PROC main()
    WaitUntil order <> "";
    IF order = "stop" THEN
      y := 1;
    ENDIF
  ENDPROC
ENDMODULE
"""


def test_the_text_is_followed_through_a_task_that_passes_it_on(tmp_path):
    """The receiver's PERS reaches a relay task, whose PERS reaches a third task."""
    messages = domain_of(tmp_path, RECEIVER.format(storage="PERS"), RELAY, LAST)
    assert "stop" in messages


HANDLER_RECEIVER = RECEIVER.format(storage="PERS").replace(
    "ENDMODULE", """  PROC Handle(string text)
    IF text = "other" THEN
      TPWrite "other";
    ENDIF
  ENDPROC
ENDMODULE""")

HANDLER_ROBOT = """MODULE Robot
  PERS string cmd := "";
  VAR num x := 0;
  PROC main()
    WaitUntil cmd <> "";
    Handle cmd;
  ENDPROC
  PROC Handle(string order)
    IF order = "go" THEN
      x := 1;
    ENDIF
  ENDPROC
ENDMODULE
"""


def test_a_call_reaches_the_routine_of_its_own_task(tmp_path):
    """Both tasks declare ``Handle`` (their parameters named apart): the robot's call
    passes the command to its own."""
    messages = domain_of(tmp_path, HANDLER_RECEIVER, HANDLER_ROBOT)
    assert "go" in messages


COMMANDS = [f"cmd{number}" for number in range(15)]

PARSING_ROBOT = """MODULE Robot
  PERS string cmd := "";
  VAR num values{{30}};
  VAR num x := 0;
  PROC main()
    WaitUntil cmd <> "";
{branches}
    Numbers cmd;
  ENDPROC
  PROC Numbers(string text)
    VAR num at := 1;
    VAR num comma := 0;
    VAR bool ok;
{parses}
  ENDPROC
ENDMODULE
"""


def test_a_long_list_parsed_leaves_room_for_the_commands(tmp_path):
    """A routine that parses thirty numbers gives lists of every length; they are one
    value's forms and do not push the commands another task compares out of the cap."""
    branches = "\n".join(f'    IF cmd = "{command}" x := {number};'
                         for number, command in enumerate(COMMANDS))
    parses = "\n".join(f'    comma := StrFind(text, at, ",");\n'
                       f'    ok := StrToVal(StrPart(text, at, comma - at), values{{{k}}});\n'
                       f'    at := comma + 1;' for k in range(1, 31))
    robot = PARSING_ROBOT.format(branches=branches, parses=parses)
    messages = domain_of(tmp_path, RECEIVER.format(storage="PERS"), robot)
    assert set(COMMANDS) <= set(messages), messages
    assert ",".join(["1"] * 30) in messages


LOCAL_FIRST = """MODULE Other
  PROC Idle()
    Handle "x";
  ENDPROC
  LOCAL PROC Handle(string other)
    IF other = "stop" THEN
      TPWrite "stop";
    ENDIF
  ENDPROC
ENDMODULE
"""

LOCAL_RECEIVER = """MODULE Recv
  VAR socketdev sock;
  VAR string msg := "";
  PROC main()
    SocketCreate sock;
    SocketConnect sock, "10.0.0.2", 5000;
    SocketReceive sock \\Str:=msg;
    Handle msg;
  ERROR
    RETRY;
  ENDPROC
  LOCAL PROC Handle(string text)
    IF text = "go" THEN
      TPWrite "go";
    ENDIF
  ENDPROC
ENDMODULE
"""


def test_a_call_reaches_the_local_routine_of_its_own_module(tmp_path):
    """Two modules of one task each have a LOCAL ``Handle`` (the other module's first):
    the receiver's call passes the message to its own module's."""
    first, second = tmp_path / "other.mod", tmp_path / "recv.mod"
    first.write_text(LOCAL_FIRST)
    second.write_text(LOCAL_RECEIVER)
    [domain] = message_domains(api.load_program([str(first), str(second)]))
    assert "go" in domain.messages, domain.messages


def test_a_long_list_is_shown_with_its_count(tmp_path):
    """The note shows a run of equal fields as two of them, an ellipsis, the last and the
    count, not thirty fields one by one."""
    branches = '    IF cmd = "cmd0" x := 0;'
    parses = "\n".join(f'    comma := StrFind(text, at, ",");\n'
                       f'    ok := StrToVal(StrPart(text, at, comma - at), values{{{k}}});\n'
                       f'    at := comma + 1;' for k in range(1, 31))
    for number, text in enumerate([RECEIVER.format(storage="PERS"),
                                   PARSING_ROBOT.format(branches=branches, parses=parses)]):
        (tmp_path / f"task{number}.mod").write_text(text)
    program = api.load_program([str(tmp_path / "task0.mod")],
                               add_tasks=[str(tmp_path / "task1.mod")])
    [domain] = message_domains(program)
    note = domain.note().message
    assert "'1,1,...,1' (30 x '1')" in note and "1,1,1" not in note, note
