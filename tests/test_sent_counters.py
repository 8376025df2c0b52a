"""Counters that only fill bytes sent (model/reduction/sent_counters.py) keep every verdict.

A sender counts its messages into a header packed with ``PackRawBytes ... \\IntX`` and
sends it with ``SocketSend \\RawData``.  Generated senders of that pattern vary what
the reduction must notice: the packed size (4 and 8 bytes are slices, 1 and 2 bytes can
overflow), the step (at most 32), a start that is no integer, a count also read by a
condition, a routine or a message on the FlexPendant, bytes that are read back, and a
division that may fail on data the bytes carry.  For each:

* the counter is sliced exactly when the module's rules say so;
* the projection commutes with the step (as ``test_dead_data.commuting_failures``
  checks, but for the bytes a ``SocketSend`` shows in the transition's output, which the
  reduced model shows as zeros): the stored states are the classes of the program's own,
  so verdicts and counterexamples (rebuilt on the plain program) are kept;
* the verdicts with every reduction, with ``--no-slice``, with ``--no-reduce`` and on
  the Python engine agree, and every counterexample replays.

The senders loop a bounded number of times, so the plain search ends too; an endless
sender ends only with the counter sliced.
"""
from __future__ import annotations

import random
from pathlib import Path

import pytest

from rapidmc import api
from rapidmc.check import native
from rapidmc.model.reduction.relevance import find_slicing

from test_dead_data import (check_report, commuting_failures, verdicts,
                            verdicts_agree_and_replay)

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

SEEDS = range(30)

SLICED_SIZES = ("UDINT", "DINT", "ULINT", "LINT")
KEPT_SIZES = ("UINT", "USINT", "INT")


def sender(seed: int) -> tuple[str, bool]:
    """(a sender's module text, whether its counter only fills bytes sent)."""
    rng = random.Random(seed)
    sliced = True
    # each way to keep the counter comes in about one sender of eight
    size = rng.choice(KEPT_SIZES if rng.random() < 0.12 else SLICED_SIZES)
    sliced &= size in SLICED_SIZES
    step = rng.choice(("Add sent, 40;", "Decr sent;") if rng.random() < 0.12 else
                      ("Incr sent;", "sent := sent + 32;", "Add sent, 3;"))
    sliced &= step in ("Incr sent;", "sent := sent + 32;", "Add sent, 3;")
    start = "0.5" if rng.random() < 0.12 else rng.choice(("0", "7"))
    sliced &= start != "0.5"
    read = rng.choice(("IF sent > 2 THEN\n            mark := 1;\n        ENDIF",
                       "TPWrite \"sent \" + ValToStr(sent);")) if rng.random() < 0.12 else \
        rng.choice(("", "copy := sent;"))
    sliced &= read in ("", "copy := sent;")
    read_back = rng.random() < 0.12
    sliced &= not read_back
    buffer_global = rng.random() < 0.5
    rounds = rng.randint(2, 4)
    divisor = rng.choice(("mark", "kind - 1", "2"))
    local = "" if buffer_global else "        VAR rawbytes buffer;\n"
    back = "        UnpackRawBytes buffer, 5, got \\IntX:=" + size + ";\n" \
        "        IF got = 3 THEN\n            mark := 1;\n        ENDIF\n" if read_back else ""
    text = f"""MODULE Sender
    VAR socketdev sock;
    PERS num sent := {start};
    VAR num mark := 0;
    VAR num copy := 0;
    VAR num got := 0;
    VAR num ratio := 0;
{"    VAR rawbytes buffer;" if buffer_global else ""}

    PROC SendOne(num kind)
{local}        {step}
        ClearRawBytes buffer;
        PackRawBytes kind, buffer, 1 \\IntX:=UDINT;
        PackRawBytes sent, buffer, RawBytesLen(buffer) + 1 \\IntX:={size};
        SocketSend sock \\RawData:=buffer;
        {read}
{back}        ratio := 10 / ({divisor});
    ENDPROC

    PROC main()
        SocketCreate sock;
        SocketConnect sock, "127.0.0.1", 1025 \\Time:=WAIT_MAX;
        FOR i FROM 1 TO {rounds} DO
            SendOne i;
        ENDFOR
    ENDPROC
ENDMODULE
"""
    return text, sliced


def sliced_counters(text: str, tmp_path: Path, atoms=()) -> tuple:
    path = tmp_path / "sender.mod"
    path.write_text(text)
    program = api.load_program([str(path)], [])
    return tuple(name for name, _ in find_slicing(program, atoms).sent_counters)


@pytest.mark.parametrize("seed", SEEDS)
def test_a_counter_is_sliced_exactly_when_it_only_fills_bytes_sent(tmp_path, seed):
    text, sliced = sender(seed)
    assert sliced_counters(text, tmp_path) == (("sent",) if sliced else ())


@pytest.mark.parametrize("seed", SEEDS)
def test_generated_senders_project_as_the_program_steps(tmp_path, seed):
    text, _ = sender(seed)
    path = tmp_path / "sender.mod"
    path.write_text(text)
    # (the label without the text SocketSend shows: the reduced model shows zeros)
    compared, failures = commuting_failures([str(path), "--max-states", "20000"],
                                            compared_label=lambda label: label[:2])
    assert compared > 0
    assert not failures, f"{len(failures)} of {compared} states, first: {failures[0]}"


@pytest.mark.parametrize("seed", SEEDS)
def test_generated_senders_keep_their_verdicts_and_counterexamples_replay(tmp_path, seed):
    text, _ = sender(seed)
    path = tmp_path / "sender.mod"
    path.write_text(text)
    verdicts_agree_and_replay(tmp_path, [str(path), "--max-states", "20000"], "--no-slice")


ENDLESS = """MODULE Sender
    VAR socketdev sock;
    PERS num sent := 0;

    PROC main()
        VAR rawbytes buffer;
        SocketCreate sock;
        SocketConnect sock, "127.0.0.1", 1025 \\Time:=WAIT_MAX;
        WHILE TRUE DO
            Incr sent;
            ClearRawBytes buffer;
            PackRawBytes 7, buffer, 1 \\IntX:=UDINT;
            PackRawBytes sent, buffer, 5 \\IntX:=UDINT;
            SocketSend sock \\RawData:=buffer;
            WaitTime 0.1;
        ENDWHILE
    ENDPROC
ENDMODULE
"""


# the same with the counter a VAR of main, counted before the loop too
ENDLESS_LOCAL = ENDLESS.replace("    PERS num sent := 0;\n", "") \
    .replace("        VAR rawbytes buffer;\n",
             "        VAR rawbytes buffer;\n        VAR num sent := 3;\n") \
    .replace("        SocketCreate sock;\n", "        Add sent, 2;\n        SocketCreate sock;\n")


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("text, named", [(ENDLESS, "sent (sender.mod:3)"),
                                         (ENDLESS_LOCAL, "main.sent (sender.mod:4)")])
def test_an_endless_sender_holds_with_its_counter_left_out(tmp_path, engine, text, named):
    assert text is ENDLESS or "Add sent, 2;" in text and "PERS num sent" not in text
    path = tmp_path / "sender.mod"
    path.write_text(text)
    report = check_report([str(path), "--max-states", "20000", "--engine", engine])
    assert verdicts(report) == {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS"}
    assumed = [line for entry in report["properties"] for line in entry.get("assumes", [])]
    assert any(str(line).startswith(f"{named} only counts into bytes sent")
               for line in assumed), assumed
    plain = check_report([str(path), "--max-states", "2000", "--no-slice", "--engine", engine])
    assert set(verdicts(plain).values()) == {"UNKNOWN"}


def test_an_atom_naming_the_counter_or_its_bytes_keeps_it(tmp_path):
    text, sliced = next((t, s) for t, s in map(sender, range(100)) if s)
    assert sliced_counters(text, tmp_path) == ("sent",)
    assert sliced_counters(text, tmp_path, ["sent > 3"]) == ()
    assert sliced_counters(text, tmp_path, ["RawBytesLen(buffer) > 3"]) == ()
