"""A WaitUntil's reads of outside data choose one value per outcome of the comparisons
(``semantics.wait_outcomes``, issue 28).

The taeyangshim head, checked alone, waits for the three arms with ``WaitUntil
stReact=["Ready","Ready","Ready"]``: each element took each of the data's 14 values,
2,744 transitions from one waiting state to two successors.  The generated programs here
have the same shape: a task waits on PERS data written from outside the loaded code (by a
task left out of the check, or by no loaded code at all), a whole array, an element, a
record or a component, compared with constants (equality, ordering, AND/OR, the constant on
either side), beside waits whose reads go elsewhere (a function's argument, another read);
after the wait the values are read on (an IF, a TEST, an index that may be out of range, an
assignment) or never; waits with ``\\MaxTime`` and ``\\TimeFlag``; an interrupt (IPers) whose
trap reads the data.  Each program is checked with the reduction and without it
(``expressions.BY_OUTCOME``), on both engines: the verdicts and the states of every search
must be equal, the reduced search never takes more transitions, and over all programs far
fewer.
"""
from __future__ import annotations

import json
import random
from pathlib import Path

import pytest

from rapidmc.check import native
from rapidmc.semantics import expressions

from cli_capture import run_cli

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

WAITS = [
    'stReact = ["Ready", "Ready", "Ready"]',
    '(stReact = ["Ack", "Ack", "Ack"]) OR (stReact = ["Error", "Error", "Error"])',
    'stReact{2} = "WeldOk" OR stReact{2} = "Error"',
    '"Ready" = stReact{1} AND stReact{3} <> "Busy"',
    'stReact{1} <> "Busy"',
    'nCmd > 2',
    '3 <= nCmd OR nCmd = 1',
    'rec.mode = 2 AND rec.on = TRUE',
    'rec = [2, TRUE]',
    '(stCommand = "") AND (stReact = ["Ready", "Ready", "Ready"])',
    'stReact{1} = stReact{2}',
    'StrLen(stReact{3}) > 4',
    'Done()',
]
LIMITS = ["", " \\MaxTime:=1", " \\MaxTime:=1 \\TimeFlag:=late"]
AFTER = [
    'IF stReact{1} = "Busy" count := count + 1;',
    'TEST nCmd CASE 1: count := 1; CASE 3: count := 2; ENDTEST',
    'count := arr{nCmd};',
    'text := stReact{2};',
    'IF rec.mode > 1 count := 0;',
    'stCommand := "go";',
    'stCommand := "";',
    '',
]

OTHER_TASK = """MODULE Arms
  RECORD mode_rec
    num mode;
    bool on;
  ENDRECORD
  PERS string stReact{3} := ["Ready", "Ready", "Ready"];
  PERS num nCmd := 0;
  PERS mode_rec rec := [0, FALSE];
  PROC main()
    stReact := ["Ack", "Ack", "Ack"];
    stReact{2} := "WeldOk";
    stReact{1} := "Busy";
    stReact{3} := "Error";
    stReact := ["Ready", "Ready", "Ready"];
    nCmd := 3;
    rec.mode := 2;
    rec.on := TRUE;
  ENDPROC
ENDMODULE
"""


def head(seed: int) -> str:
    rnd = random.Random(seed)
    body = []
    for _ in range(rnd.randint(2, 4)):
        body.append(f"WaitUntil {rnd.choice(WAITS)}{rnd.choice(LIMITS)};")
        body.append(rnd.choice(AFTER))
    trap = ""
    connect = ""
    if rnd.random() < 0.3:
        connect = "CONNECT tick WITH trTick;\n    IPers stCommand, tick;"
        trap = """  TRAP trTick
    IF stReact{3} = "Busy" count := 0;
  ENDTRAP
"""
    loop = "\n      ".join(line for line in body if line)
    return f"""MODULE Head
  RECORD mode_rec
    num mode;
    bool on;
  ENDRECORD
  PERS string stReact{{3}} := ["Ready", "Ready", "Ready"];
  PERS string stCommand := "";
  PERS num nCmd := 0;
  PERS mode_rec rec := [0, FALSE];
  VAR num count := 0;
  VAR num arr{{3}} := [1, 2, 3];
  VAR string text := "";
  VAR bool late := FALSE;
  VAR intnum tick;
  FUNC bool Done()
    RETURN stReact{{2}} = "WeldOk" OR nCmd = 1;
  ENDFUNC
  PROC main()
    {connect}
    WHILE TRUE DO
      {loop}
      IF count > 3 count := 0;
    ENDWHILE
  ENDPROC
{trap}ENDMODULE
"""


def backup(root: Path, seed: int) -> Path:
    """A backup of two tasks: the head (checked alone) and the arms that write its data."""
    (root / "BACKINFO").mkdir(parents=True)
    (root / "BACKINFO" / "backinfo.txt").write_text(
        ">>SYSTEM_ID:\nrapidmc test cell\n\n>>TASK1: (T_HEAD,,)\n\n>>TASK2: (T_ARMS,,)\n\n>>EOF:\n")
    (root / "SYSPAR").mkdir()
    (root / "SYSPAR" / "SYS.cfg").write_text(
        'SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name "T_HEAD" -Type "NORMAL" -MotionTask\n\n'
        '      -Name "T_ARMS" -Type "NORMAL" -MotionTask\n')
    for task, text in (("TASK1", head(seed)), ("TASK2", OTHER_TASK)):
        folder = root / "RAPID" / task / "PROGMOD"
        folder.mkdir(parents=True)
        (folder / f"{task}.mod").write_text(text)
    return root


def searches(argv: list, engine: str) -> dict:
    document = json.loads(run_cli(["check", *argv, "--engine", engine, "--format", "json",
                                   "--quiet", "--max-states", "30000"]).out)
    return {p["name"]: (p["verdict"], p["stats"]["model_states"], p["stats"]["transitions"])
            for p in document["properties"]}


def compared(argv: list, engine: str, monkeypatch) -> tuple[dict, dict]:
    reduced = searches(argv, engine)
    with monkeypatch.context() as patch:
        patch.setattr(expressions, "BY_OUTCOME", False)
        exact = searches(argv, engine)
    return reduced, exact


def same(reduced: dict, exact: dict) -> None:
    assert {name: verdict for name, (verdict, _, _) in reduced.items()} == \
        {name: verdict for name, (verdict, _, _) in exact.items()}
    for name, (verdict, states, transitions) in exact.items():
        if verdict == "HOLDS":       # (a violation's states depend on the order found)
            assert reduced[name][1] == states, name
        assert reduced[name][2] <= transitions, name


@pytest.mark.parametrize("engine", ENGINES)
# (seeds 2 and 6 give programs whose exact search takes minutes: hundreds of tries a state)
@pytest.mark.parametrize("seed", (0, 1, 3, 4, 5))
@pytest.mark.parametrize("shape", ["alone", "task"])
def test_waits_by_outcome_keep_verdicts_and_states(tmp_path, monkeypatch, seed, engine, shape):
    if shape == "alone":
        path = tmp_path / "head.mod"
        path.write_text(head(seed))
        argv = [str(path)]
    else:
        argv = [str(backup(tmp_path / "backup", seed)), "--task", "T_HEAD"]
    reduced, exact = compared(argv, engine, monkeypatch)
    same(reduced, exact)


def test_the_head_waits_for_three_arms_in_few_transitions(tmp_path, monkeypatch):
    """The head's wait of the taeyangshim backups, its data written by a task left out:
    each element's values were tried one by one (domain³ tries per waiting state), now
    one per outcome of its comparison."""
    root = backup(tmp_path / "backup", 0)
    (root / "RAPID" / "TASK1" / "PROGMOD" / "TASK1.mod").write_text(head(0).replace(
        head(0).split("WHILE TRUE DO")[1].split("ENDWHILE")[0],
        '\n      WaitUntil stReact = ["Ready", "Ready", "Ready"];\n'
        '      WaitUntil stReact = ["Ack", "Ack", "Ack"];\n    '))
    reduced, exact = compared([str(root), "--task", "T_HEAD"], native.PYTHON, monkeypatch)
    same(reduced, exact)
    assert exact["no_deadlock"][2] >= 5 * reduced["no_deadlock"][2]


def test_a_wait_that_ends_for_many_values_keeps_each(tmp_path, monkeypatch):
    """``stReact{1} <> "Busy"`` ends for every value but one, and the value is read on:
    each is still a state of its own (the classes are only tried where the wait keeps
    nothing)."""
    path = tmp_path / "head.mod"
    path.write_text(head(0).replace(
        head(0).split("WHILE TRUE DO")[1].split("ENDWHILE")[0],
        '\n      WaitUntil stReact{1} <> "Busy";\n'
        '      TEST stReact{1} CASE "Ready": count := 1; CASE "Ack": count := 2; '
        'CASE "WeldOk": count := arr{4}; ENDTEST\n      WaitUntil stReact{1} = "Busy";\n    '))
    for engine in ENGINES:
        reduced, exact = compared([str(path)], engine, monkeypatch)
        same(reduced, exact)
        assert reduced["no_runtime_error"][0] == "VIOLATED"
