"""Free inputs kept in the states when interrupts are ordered: tests/interrupt_inputs/<case>/.

``model.inputs.observed_inputs`` keeps only the inputs an interrupt is ordered on (and those
the properties read); the program's other inputs are chosen where it reads them.  Each case
(``prog.mod``, ``props.ltl``, ``args``, ``expected``: ``NAME VERDICT`` lines) is checked
with that reduction and without it (every free input kept, as before): the verdicts must be
the expected ones both ways, and the reduced search may not store more states.
"""
from __future__ import annotations

import json
import shlex
from pathlib import Path

import pytest

import rapidmc.api
from cli_capture import run_cli
from rapidmc.model.inputs import observed_inputs
from rapidmc.model.properties import AtomCompiler

CASES = Path(__file__).resolve().parent / "interrupt_inputs"


def lines(path: Path) -> list[str]:
    return [line.strip() for line in path.read_text().splitlines()
            if line.strip() and not line.startswith("#")] if path.exists() else []


def run(case: Path) -> dict:
    argv = ["check", "prog.mod", "--ltl", "props.ltl", "--format", "json", "--quiet"]
    argv += [arg for line in lines(case / "args") for arg in shlex.split(line)]
    out = run_cli(argv, cwd=case).out
    return {p["name"]: p for p in json.loads(out)["properties"]}


@pytest.mark.parametrize("case", sorted(p for p in CASES.iterdir() if p.is_dir()),
                         ids=lambda p: p.name)
def test_kept_inputs_keep_the_verdicts(case, monkeypatch):
    expected = dict(line.split() for line in lines(case / "expected"))
    reduced = run(case)
    monkeypatch.setattr(rapidmc.api, "observed_inputs", lambda program, atoms: None)
    every_input = run(case)
    assert {n: p["verdict"] for n, p in reduced.items()} == expected
    assert {n: p["verdict"] for n, p in every_input.items()} == expected
    for name in ("no_runtime_error", "no_deadlock"):
        if expected[name] == "HOLDS":      # complete searches: comparable state counts
            assert reduced[name]["stats"]["model_states"] <= \
                every_input[name]["stats"]["model_states"]


ALIAS_PROGRAM = """MODULE Aliases
    VAR intnum reset_int;
    VAR signaldi alias_diReset;
    VAR bool was_reset := FALSE;

    PROC main()
        VAR string signalName;
        signalName := "diReset";
        {binding}
        CONNECT reset_int WITH OnReset;
        ISignalDI alias_diReset, 1, reset_int;
        WaitDI diStart, 1;
    ENDPROC

    TRAP OnReset
        was_reset := TRUE;
    ENDTRAP
ENDMODULE
"""


def _observed(tmp_path, binding: str):
    (tmp_path / "prog.mod").write_text(ALIAS_PROGRAM.replace("{binding}", binding))
    program = rapidmc.api.load_program([str(tmp_path / "prog.mod")],
                                       eio=str(CASES / "reset_trap" / "EIO.cfg"))
    observed = observed_inputs(program, AtomCompiler(program))
    return observed if observed is None else {program.signals[i].name for i in observed}


@pytest.mark.parametrize("binding, expected", [
    ("AliasIO signalName, alias_diReset;", {"diReset"}),
    ('AliasIO "diStart", alias_diReset;', {"diStart"}),
    ("AliasIO diPart, alias_diReset;", {"diPart"}),
    # a second binding: either signal may be the one watched
    ('AliasIO signalName, alias_diReset; AliasIO "diPart", alias_diReset;',
     {"diReset", "diPart"}),
    # the name's value is not known where the binding is: every input kept
    ("signalName := signalName + \"\"; AliasIO signalName, alias_diReset;", None),
    ('WHILE TRUE DO AliasIO signalName, alias_diReset; signalName := "diPart"; ENDWHILE',
     None),
    ("lbl: AliasIO signalName, alias_diReset;", None),
], ids=["variable", "literal", "signal", "two", "computed", "loop", "label"])
def test_an_interrupt_on_signal_data_keeps_the_signals_its_aliasio_names(
        tmp_path, binding, expected):
    """``alias_bindings``: the signals an interrupt on signal data may watch, read from the
    AliasIO calls; every input is kept when one of them cannot be read."""
    assert _observed(tmp_path, binding) == expected
