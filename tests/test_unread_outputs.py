"""Outputs no loaded code reads back are reset in stored states
(``model.reduction.unread_outputs``, issue 28).

A monitoring task of a public gantry backup sets and resets outputs every round for other
tasks to watch; checked alone, its 35,972 states were 621 once those values are not kept.
The generated programs are monitoring loops of that shape: outputs set from free inputs and
from data another party writes, beside outputs the program reads back (``DOutput``, a wait,
``InvertDO``, ``PulseDO``, an interrupt order, a delayed ``SetDO``), reads that can fail
only when an output read back has some value, and properties over data and over an output.
Each is checked with the reduction and with it off (``unread_outputs`` returning nothing),
on both engines: the verdicts must be equal and the reduced search never larger.
"""
from __future__ import annotations

import json
import random

import pytest

from rapidmc.check import native
from rapidmc.model import reduction

from cli_capture import run_cli

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

SIGNALS = [("diA", "DI"), ("diB", "DI"), ("doA", "DO"), ("doB", "DO"), ("doC", "DO"),
           ("doRead", "DO"), ("goCode", "GO")]
EIO = "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n" + "".join(
    f'\n      -Name "{name}" -SignalType "{kind}" -Device "d" -DeviceMap "{i}"\n'
    for i, (name, kind) in enumerate(SIGNALS))

WRITES = [
    "IF diA = 1 THEN Set doA; ELSE Reset doA; ENDIF",
    "IF stReact = \"Error\" THEN Set doB; ELSE Reset doB; ENDIF",
    "SetDO doC, diB;",
    "IF diA = 1 AND diB = 1 SetGO goCode, 3;",
    "IF diB = 0 SetGO goCode, 0;",
    "IF diA = 1 THEN Set doRead; ELSE Reset doRead; ENDIF",
    "count := count + 1; IF count > 2 count := 0;",
]
READS = [
    "IF DOutput(doRead) = 1 count := arr{count + 1};",
    "IF DOutput(doRead) = 1 AND count = 2 count := arr{4};",
    "WaitDO doRead, 1 \\MaxTime:=1;",
    "InvertDO doRead;",
    "PulseDO doRead;",
    "SetDO \\SDelay:=0.1, doRead, 1;",
    "IF count = 1 AND doRead = 1 count := arr{5};",
]
PROPERTIES = ["p_data: G (count < 3)", "p_output: G !(doA = 1 & count = 2)"]


def program(seed: int) -> str:
    rnd = random.Random(seed)
    body = [rnd.choice(WRITES) for _ in range(rnd.randint(3, 6))]
    if rnd.random() < 0.8:
        body.insert(rnd.randrange(len(body) + 1), rnd.choice(READS))
    loop = "\n      ".join(body)
    trap = ""
    if rnd.random() < 0.3:
        trap = ("  TRAP tWatch\n    count := 0;\n  ENDTRAP\n")
        loop = "IDelete iWatch;\n      CONNECT iWatch WITH tWatch;\n      " \
               "ISignalDO doRead, 1, iWatch;\n      " + loop
    return f"""MODULE Monitor
  PERS string stReact := "";
  VAR num count := 0;
  VAR num arr{{3}} := [1, 2, 3];
  VAR intnum iWatch;
{trap}  PROC main()
    WHILE TRUE DO
      {loop}
      WaitTime 0.1;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


def searches(path, eio, engine: str, properties: list[str]) -> dict:
    words = ["check", str(path), "--eio", str(eio), "--engine", engine, "--format", "json",
             "--quiet"]
    for prop in properties:
        words += ["--formula", prop]
    document = json.loads(run_cli(words).out)
    return {p["name"]: (p["verdict"], p["stats"]["model_states"])
            for p in document["properties"]}


def write(tmp_path, text: str):
    path, eio = tmp_path / "monitor.mod", tmp_path / "EIO.cfg"
    path.write_text(text)
    eio.write_text(EIO)
    return path, eio


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("seed", range(20))
def test_reset_outputs_keep_verdicts(tmp_path, monkeypatch, seed, engine):
    path, eio = write(tmp_path, program(seed))
    properties = PROPERTIES if seed % 2 else []
    reduced = searches(path, eio, engine, properties)
    with monkeypatch.context() as patch:
        patch.setattr(reduction, "unread_outputs", lambda *args, **kwargs: ())
        kept = searches(path, eio, engine, properties)
    assert {name: verdict for name, (verdict, _) in reduced.items()} == \
        {name: verdict for name, (verdict, _) in kept.items()}
    assert all(reduced[name][1] <= kept[name][1] for name in kept if kept[name][1])


def test_outputs_only_set_are_not_kept(tmp_path, monkeypatch):
    """The monitoring pattern: three outputs set from inputs and outside data, never read."""
    path, eio = write(tmp_path, program(0).replace(
        program(0).split("WHILE TRUE DO")[1].split("WaitTime")[0],
        "\n      " + "\n      ".join(WRITES[:3]) + "\n      "))
    reduced = searches(path, eio, native.PYTHON, [])
    with monkeypatch.context() as patch:
        patch.setattr(reduction, "unread_outputs", lambda *args, **kwargs: ())
        kept = searches(path, eio, native.PYTHON, [])
    assert reduced["no_runtime_error"][0] == kept["no_runtime_error"][0] == "HOLDS"
    assert 4 * reduced["no_runtime_error"][1] <= kept["no_runtime_error"][1]


@pytest.mark.parametrize("read", READS)
def test_an_output_read_back_is_kept(tmp_path, read):
    """Every way of reading ``doRead`` back keeps it; the outputs only set are reset."""
    path, eio = write(tmp_path, program(0))
    from rapidmc import api
    text = program(0).replace("WaitTime 0.1;", read + "\n      WaitTime 0.1;")
    path.write_text(text)
    loaded = api.load_program([str(path)], eio=str(eio))
    index = loaded.signal("DOREAD").index
    assert index not in reduction.unread_outputs(loaded, set())
    assert loaded.signal("DOA").index in reduction.unread_outputs(loaded, set()) or \
        "doA" not in text
