"""Socket servers in several tasks, as the public MultiMove and YuMi backups run them: the
partial-order reduction keeps their verdicts (issue 27).

Each task serves its own socket (SocketCreate, Bind, Listen, Accept with a time limit,
Receive into its own string, Send), logs with ErrWrite, tunes motion with AccSet, packs a
reply in its own rawbytes, and shares a PERS flag with the next task; the generated programs
differ in which of these steps they take, whether a receive may time out without a handler,
and whether a task waits on the flag.  ``syntax_footprint`` makes those steps independent;
the verdicts with the reduction must be those of ``--no-por`` on both engines, and the
reduced search must store fewer states where several servers start side by side.
"""
from __future__ import annotations

import json
import random

import pytest

from rapidmc.check import native

from cli_capture import run_cli

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)


def server_task(number: int, rnd: random.Random, tasks: int) -> str:
    """One server task; ``flag{number}`` is its own to set, the next one's it may wait on."""
    lines = ["SocketCreate server;", "SocketBind server, \"127.0.0.1\", %d;" % (1024 + number),
             "SocketListen server;",
             "SocketAccept server, client \\Time:=5;"]
    steps = [
        "SocketReceive client \\Str:=message \\Time:=5;",
        "IF SocketGetStatus(client) = SOCKET_CONNECTED SocketSend client \\Str:=message;",
        'ErrWrite \\W, "server", message;',
        "AccSet 50, 50;",
        "ClearRawBytes reply;",
        "PackRawBytes count, reply, 1 \\IntX:=DINT;",
        "count := count + 1;",
        f"flag{number} := TRUE;",
        f"WaitUntil flag{(number + 1) % tasks} = TRUE;",
        "IF message = \"stop\" SocketClose client;",
    ]
    lines += rnd.sample(steps, rnd.randint(3, 6))
    handler = "\n  ERROR\n    RETURN;" if rnd.random() < 0.5 else ""
    flags = "\n".join(f"  PERS bool flag{i} := FALSE;" for i in range(tasks))
    body = "\n".join(f"    {line}" for line in lines)
    return (f"MODULE Server{number}\n{flags}\n  VAR socketdev server;\n  VAR socketdev client;\n"
            f"  VAR string message := \"\";\n  VAR rawbytes reply;\n  VAR num count := 0;\n"
            f"  PROC main()\n{body}{handler}\n  ENDPROC\nENDMODULE\n")


def write_servers(folder, seed: int) -> list[str]:
    rnd = random.Random(seed)
    tasks = rnd.randint(2, 3)
    argv = []
    for number in range(tasks):
        path = folder / f"server{number}.mod"
        path.write_text(server_task(number, rnd, tasks))
        argv += [str(path)] if number == 0 else ["--add-task", str(path)]
    return argv + ["--socket-messages", "go", "--socket-messages", "stop",
                   "--formula", "Flagged: F flag0", "--max-states", "60000"]


def check(argv: list[str]) -> dict:
    document = json.loads(run_cli(["check", *argv, "--format", "json", "--quiet"]).out)
    return {p["name"]: (p["verdict"], p["stats"]["model_states"]) for p in document["properties"]}


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("seed", range(12))
def test_socket_servers_keep_their_verdicts(tmp_path, seed, engine):
    argv = write_servers(tmp_path, seed) + ["--engine", engine]
    reduced, full = check(argv), check(argv + ["--no-por"])
    assert {name: verdict for name, (verdict, _) in reduced.items()} == \
        {name: verdict for name, (verdict, _) in full.items()}
    assert "UNKNOWN" not in {verdict for verdict, _ in full.values()}


def test_servers_starting_side_by_side_are_not_interleaved(tmp_path):
    """Three servers that only set up their own sockets and log: without the reduction every
    interleaving of their steps is stored."""
    argv = []
    for number in range(3):
        path = tmp_path / f"server{number}.mod"
        path.write_text(
            f"MODULE Server{number}\n  VAR socketdev server;\n  VAR socketdev client;\n"
            f"  PROC main()\n    SocketCreate server;\n"
            f"    SocketBind server, \"127.0.0.1\", {1024 + number};\n    SocketListen server;\n"
            f"    AccSet 50, 50;\n    SocketAccept server, client \\Time:=5;\n"
            f"    ErrWrite \\W, \"server\", \"connected\";\n  ERROR\n    RETURN;\n"
            f"  ENDPROC\nENDMODULE\n")
        argv += [str(path)] if number == 0 else ["--add-task", str(path)]
    reduced = check(argv + ["--no-merge"])
    full = check(argv + ["--no-merge", "--no-por"])
    assert {name: verdict for name, (verdict, _) in reduced.items()} == \
        {name: verdict for name, (verdict, _) in full.items()}
    assert reduced["no_runtime_error"][1] * 4 < full["no_runtime_error"][1]
