"""An environment model that goes wrong during a coverage probe is the same diagnostic as
in the verdicts' own search (RMC503, exit 2), never an internal error; so is one that goes
wrong while ``rapidmc graph`` explores.

The probes (``api._closure_probe``: peers may close their sockets; ``api._probed_lines``:
one probe message per reading site) run searches of their own after the verdicts'.  In
each program below only a probe reaches the code whose output makes the environment fail.
"""
from __future__ import annotations

from pathlib import Path

from rapidmc import api
from rapidmc.cli import main

CHECK = Path(__file__).resolve().parent / "check"

SERVER = """MODULE Server
    VAR socketdev server;
    VAR socketdev client;
    VAR string request := "";

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 1025;
        SocketListen server;
        SocketAccept server, client \\Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \\Str:=request \\Time:=WAIT_MAX;
        ENDWHILE
    ERROR
        IF ERRNO = ERR_SOCK_CLOSED THEN
            SetDO doLost, 1;
        ENDIF
    ENDPROC
ENDMODULE
"""

# fails once the server's handler has set doLost: only when a peer closes its socket
PLANT = """MODULE Plant
    VAR signaldo doLost;
    VAR num zero := 0;
    VAR num x := 0;
    PROC react()
        IF doLost = 1 THEN
            x := 1 / zero;
        ENDIF
    ENDPROC
ENDMODULE
"""

FAULT = ("environment model: environment routine react stopped with ERR_DIVZERO: "
         "division by zero [RMC503]")


def _check(tmp_path, capsys, *options) -> tuple[int, str]:
    (tmp_path / "prog.mod").write_text(SERVER)
    (tmp_path / "env.mod").write_text(PLANT)
    code = main(["check", str(tmp_path / "prog.mod"), "--env", str(tmp_path / "env.mod"),
                 "--quiet", *options])
    return code, capsys.readouterr().err


def test_a_fault_in_the_verdicts_search_is_rmc503(tmp_path, capsys):
    code, err = _check(tmp_path, capsys, "--socket-closures")
    assert code == 2 and FAULT in err, err


def test_a_fault_in_the_closure_probe_is_the_same_diagnostic(tmp_path, capsys):
    code, err = _check(tmp_path, capsys)
    assert "internal error" not in err, err
    assert code == 2 and FAULT in err, err


def test_a_fault_in_a_message_probe_is_the_same_diagnostic(tmp_path, capsys, monkeypatch):
    """tests/check/socket_field_count: only the probe message "1 1 1 1 #" reaches the
    branch for three parameters, which here sets the output the environment fails on."""
    text = (CHECK / "socket_field_count" / "prog.mod").read_text()
    branch = "                    done := 13;\n"
    assert text.count(branch) == 1
    (tmp_path / "prog.mod").write_text(
        text.replace(branch, branch + "                    SetDO doLost, 1;\n"))
    (tmp_path / "env.mod").write_text(PLANT)
    argv = ["check", str(tmp_path / "prog.mod"), "--env", str(tmp_path / "env.mod"), "--quiet"]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "internal error" not in err and FAULT in err, err
    monkeypatch.setattr(api, "_probed_lines", lambda model, bound: set())
    assert main(argv) == 0, capsys.readouterr().err     # the verdicts' search alone: no fault


def test_a_fault_while_writing_the_state_graph_is_the_same_diagnostic(tmp_path, capsys):
    (tmp_path / "prog.mod").write_text(SERVER)
    (tmp_path / "env.mod").write_text(PLANT)
    code = main(["graph", str(tmp_path / "prog.mod"), "--env", str(tmp_path / "env.mod"),
                 "--socket-closures", "--quiet", "-o", str(tmp_path / "states.dot")])
    err = capsys.readouterr().err
    assert code == 2 and "internal error" not in err and FAULT in err, err
