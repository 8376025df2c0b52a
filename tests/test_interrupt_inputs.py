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
{routines}
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

# reset_trap's three digital inputs and a group input, which no digital alias can be bound to
ALIAS_EIO = (CASES / "reset_trap" / "EIO.cfg").read_text() + \
    '      -Name "giCode" -SignalType "GI" -Device "PN_Internal_Device" -DeviceMap "3-6"\n'
EVERY_DI = {"diReset", "diStart", "diPart"}
OWN = """
    PROC Own()
        VAR signaldi mine;
        AliasIO "diPart", mine;
    ENDPROC
"""
BIND = """
    PROC Bind(string name, VAR signaldi sig)
        AliasIO name, sig;
    ENDPROC

    PROC BindOn(string name, VAR signaldi sig)
        Bind name, sig;
    ENDPROC
"""


def _observed(tmp_path, binding: str, routines: str = "", eio: bool = True):
    (tmp_path / "prog.mod").write_text(ALIAS_PROGRAM.replace("{binding}", binding)
                                       .replace("{routines}", routines))
    (tmp_path / "EIO.cfg").write_text(ALIAS_EIO)
    program = rapidmc.api.load_program([str(tmp_path / "prog.mod")],
                                       eio=str(tmp_path / "EIO.cfg") if eio else None)
    observed = observed_inputs(program, AtomCompiler(program))
    return observed if observed is None else {program.signals[i].name for i in observed}


@pytest.mark.parametrize("binding, routines, expected", [
    ("AliasIO signalName, alias_diReset;", "", {"diReset"}),
    ('AliasIO "diStart", alias_diReset;', "", {"diStart"}),
    ("AliasIO diPart, alias_diReset;", "", {"diPart"}),
    # a second binding: either signal may be the one watched
    ('AliasIO signalName, alias_diReset; AliasIO "diPart", alias_diReset;', "",
     {"diReset", "diPart"}),
    # the name's value is not known where the binding is: every digital input, not giCode
    ("signalName := signalName + \"\"; AliasIO signalName, alias_diReset;", "", EVERY_DI),
    ('WHILE TRUE DO AliasIO signalName, alias_diReset; signalName := "diPart"; ENDWHILE', "",
     EVERY_DI),
    ("lbl: AliasIO signalName, alias_diReset;", "", EVERY_DI),
    # a binding of a routine's own data binds no global data
    ("AliasIO signalName, alias_diReset; Own;", OWN, {"diReset"}),
    # through a parameter, and through a parameter passed on: the name is a parameter
    ("Bind signalName, alias_diReset;", BIND, EVERY_DI),
    ("BindOn signalName, alias_diReset;", BIND, EVERY_DI),
    # a parameter bound for other data only: this data's binding alone
    ('AliasIO signalName, alias_diReset; Bind "diPart", other;',
     BIND + "    VAR signaldi other;\n", {"diReset"}),
    # bindings that are not read: every input kept
    ('GetDataVal "diPart", alias_diReset; AliasIO signalName, alias_diReset;', "", None),
    ("AliasIO alias_other, alias_diReset;", "    VAR signaldi alias_other;\n", None),
    ('%"Bind"% signalName, alias_diReset;', BIND, None),
], ids=["variable", "literal", "signal", "two", "computed", "loop", "label", "own-data",
        "parameter", "parameter-passed-on", "parameter-other-data", "getdataval",
        "from-signal-data", "late-bound"])
def test_an_interrupt_on_signal_data_keeps_the_signals_its_aliasio_names(
        tmp_path, binding, routines, expected):
    """``alias_bindings``: the signals an interrupt on signal data may watch, read from the
    AliasIO calls; every input is kept when one of them cannot be read."""
    assert _observed(tmp_path, binding, routines) == expected


@pytest.mark.parametrize("binding, expected", [
    # a literal name no known signal has: the call's stand-in alone
    ("AliasIO signalName, alias_diReset;", {"<AliasIO at prog.mod:{line}>"}),
    # a name computed at run time: the stand-in, or a signal of the kind the program names
    ('AliasIO signalName + "_L", alias_diReset;', {"<AliasIO at prog.mod:{line}>", "diStart"}),
    # another AliasIO's stand-in is not found by a name: not this data's binding
    ('AliasIO signalName + "_L", alias_diReset; AliasIO "s" + signalName, other;',
     {"<AliasIO at prog.mod:{line}>", "diStart"}),
], ids=["literal", "computed", "other-stand-in"])
def test_with_no_configuration_an_interrupt_keeps_its_own_stand_in(tmp_path, binding, expected):
    """With no I/O configuration, an AliasIO naming its signal at run time binds a stand-in
    (``library.signals``): an interrupt on the data it binds keeps that stand-in, not the
    stand-ins of the program's other AliasIO calls."""
    routines = "    VAR signaldi other;\n" if "other" in binding else ""
    line = ALIAS_PROGRAM.splitlines().index("        {binding}") + 1 + routines.count("\n")
    assert _observed(tmp_path, binding, routines, eio=False) == \
        {name.replace("{line}", str(line)) for name in expected}
