"""A step leaves the stored inputs it does not read and no interrupt watches unchosen
(``semantics.unread_inputs``).

Differential: small two-task programs of the Hanoi and Kraker1 pattern (an edge input only
an ISignalDI watches; an input the code reads that an interrupt watches now and then,
connected, slept and deleted inside a routine; an input only the code reads beside them;
an input a property's atom reads) are checked with inputs left unchosen (the default) and
with ``--inputs-every-step`` (every step chooses every value) on both engines: the
verdicts are the same wherever the second search ends, and both verdicts occur.  A mutant
that leaves the inputs unchosen at steps that read them loses a violation.
"""
from __future__ import annotations

import random

import pytest

from rapidmc import api
from rapidmc.check import native
from rapidmc.semantics import unread_inputs
from rapidmc.semantics.resting_inputs import watched_inputs

from cli_capture import assert_reduction_keeps_verdicts, other_task_module, two_task_verdicts

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

FIRST_LINES = [
    "rWatch TRUE;",
    "rWatch FALSE;",
    "IF diW = 1 n := 1 - n;",
    "IF diR = 1 hits := 0;",
    "WaitDI diR, {V};",
    "IDelete iE; CONNECT iE WITH tE; ISignalDI diE, {T}, iE;",
    "ISleep iE;",
    "IWatch iE;",
    "flag := TRUE;",
    "IF hits > 1 THEN x := 10 / (hits - 2); hits := 0; ENDIF",
    "n := (n + 1) MOD 2;",
]
OTHER_LINES = [
    "IF flag THEN flag := FALSE; m := 1 - m; ENDIF",
    "WaitUntil flag OR m > 0;",
    "m := 0;",
    "IF diR = 1 m := 1;",
    "n := 0;",
]
FORMULAS = ['few: G "hits < 2"', 'bounded: G "m < 3"', 'calm: G F "n = 0"', 'seen: G ("m = 2" -> F diA)']
NAMES = {"no_runtime_error", "no_deadlock", "few", "bounded", "calm", "seen"}


def two_tasks(seed: int) -> tuple[str, str]:
    """(a task with an edge input ``diE``, an input ``diW`` it reads and watches now and
    then, and ``diR`` it reads; another task reading ``diR`` and ``diA``, which a
    property reads)."""
    rnd = random.Random(seed)
    edge, watch = rnd.choice([1, 2]), rnd.choice([0, 1, 2])
    cycle = [rnd.choice(FIRST_LINES).format(T=edge, V=rnd.randint(0, 1))
             for _ in range(rnd.randint(2, 4))]
    first = ("MODULE Prog\n  PERS bool flag := FALSE;\n  PERS num n := 0;\n"
             "  VAR num hits := 0;\n  VAR num x := 0;\n  VAR intnum iE;\n  VAR intnum iW;\n"
             "  VAR intnum iR;\n"
             "  PROC main()\n"
             f"    CONNECT iE WITH tE; ISignalDI diE, {edge}, iE;\n"
             "    CONNECT iR WITH tR; ISignalDI diR, 1, iR; IDelete iR;\n"
             "    WHILE TRUE DO\n" + "".join(f"      {line}\n" for line in cycle) +
             "    ENDWHILE\n  ENDPROC\n"
             "  PROC rWatch(bool on)\n    IF on THEN\n"
             f"      IDelete iW; CONNECT iW WITH tW; ISignalDI diW, {watch}, iW;\n"
             "    ELSE\n      ISleep iW;\n    ENDIF\n  ENDPROC\n"
             "  TRAP tE\n    hits := (hits + 1) MOD 3;\n  ENDTRAP\n"
             "  TRAP tW\n    n := 2;\n  ENDTRAP\n"
             "  TRAP tR\n    n := 1;\n  ENDTRAP\nENDMODULE\n")
    lines = [rnd.choice(OTHER_LINES) for _ in range(rnd.randint(0, 2))] + \
        ["IF diA = 0 m := 2;"]
    return first, other_task_module(lines)


def check(tmp_path, program: tuple[str, str], *flags: str, bound: int = 4000) -> dict:
    """Property -> (verdict, model states) of one in-process check of both tasks."""
    return two_task_verdicts(tmp_path, program, FORMULAS, *flags, bound=bound)


PROGRAMS = [two_tasks(seed) for seed in range(8)]


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("number", range(len(PROGRAMS)))
def test_programs_of_the_pattern_keep_their_verdicts(tmp_path, number, engine):
    program = PROGRAMS[number]
    unchosen = check(tmp_path, program, "--engine", engine)
    every = check(tmp_path, program, "--engine", engine, "--inputs-every-step")
    assert_reduction_keeps_verdicts(unchosen, every, NAMES, "\n".join(program))


def test_the_pattern_programs_reach_both_verdicts(tmp_path):
    """The differential above compares something: the searches end and give both
    verdicts."""
    verdicts = []
    for program in PROGRAMS[:6]:
        verdicts += [verdict for verdict, _ in
                     check(tmp_path, program, "--inputs-every-step").values()]
    assert verdicts.count("UNKNOWN") < len(verdicts) // 2
    assert "HOLDS" in verdicts and "VIOLATED" in verdicts


SUPERVISED = ("MODULE Prog\n  PERS num n := 0;\n  VAR bool bad := FALSE;\n"
              "  VAR intnum iR;\n  PROC main()\n"
              "    CONNECT iR WITH tR; ISignalDI diR, 1, iR; ISleep iR;\n"
              "    WHILE TRUE DO\n      IF diR = 1 bad := TRUE;\n      n := (n + 1) MOD 2;\n"
              "    ENDWHILE\n  ENDPROC\n  TRAP tR\n    n := 0;\n  ENDTRAP\nENDMODULE\n",
              "MODULE Other\n  PERS num n := 0;\n  PROC main()\n    WHILE TRUE DO\n"
              "      WaitUntil n = 1;\n    ENDWHILE\n  ENDPROC\nENDMODULE\n")


def test_a_step_that_reads_the_input_chooses_it(tmp_path, monkeypatch):
    """The differential can fail: ``diR``, which an interrupt order names and then puts to
    sleep, is read by ``IF diR = 1``.  A mutant that leaves it unchosen there too reads
    only its first value, 0, and ``G !bad`` holds."""
    def good(*flags: str) -> str:
        return two_task_verdicts(tmp_path, SUPERVISED, ["good: G !bad"], *flags)["good"][0]

    assert good() == good("--inputs-every-step") == "VIOLATED"
    monkeypatch.setattr(unread_inputs.InputChoices, "unchosen",
                        lambda self, program, state, task:
                        self.reducible - watched_inputs(state[4]) if state[10] else frozenset())
    assert good() == "HOLDS"


def test_fewer_transitions_and_a_value_only_where_read(tmp_path):
    """On the supervised program: the transitions that choose ``diR`` are those of the
    step that reads it; the others name no value for it and leave it at rest."""
    for number, text in enumerate(SUPERVISED):
        (tmp_path / f"t{number}.mod").write_text(text)
    program = api.load_program([str(tmp_path / "t0.mod")],
                               add_tasks=[str(tmp_path / "t1.mod")])
    counts = {}
    for where_read in (True, False):
        model = api.prepare(program, [], api.CheckOptions(inputs_where_read=where_read))
        system, seen = model.system, set()
        todo = list(system.initial_states())
        transitions = naming = 0
        while todo:
            state = todo.pop()
            if state in seen:
                continue
            seen.add(state)
            found = system.successors(state)
            transitions += len(found)
            naming += sum(any(name == "diR" for name, _ in label[0])
                          for label, _ in found if label)
            todo += [after for _, after in found]
        counts[where_read] = (len(seen), transitions, naming)
    assert counts[True][1] < counts[False][1]
    assert 0 < counts[True][2] < counts[True][1]
    assert counts[False][2] == counts[False][1]
