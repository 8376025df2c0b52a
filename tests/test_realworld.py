"""Real-world program styles (tests/realworld/): parse, run and check them.

The programs are ours, written in the styles surveyed in public RAPID code:
an open_abb-like socket server, a ROS-Industrial-like motion server, a
controller backup (.pgf with a SYSMODULE and configured I/O used without
declarations) and a library of utility FUNCs.  ``RUNS`` pins the console
output and exit code of ``rapidmc run`` with the given standard input
(socket messages and file lines come from stdin); ``CHECKS`` pins verdicts
of ``rapidmc check``.  The last tests model-check with configured socket
messages, which the CLI does not offer yet.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from rapidmc.check import find_reachable
from rapidmc.model.rapid_system import RapidDescriber, RapidSystem
from rapidmc.semantics.link import build
from rapidmc.semantics.step import CheckConfig
from rapidmc.syntax import load_program
from cli_capture import run_cli

HERE = Path(__file__).resolve().parent / "realworld"
SERVER = [str(HERE / "socket_server" / "RobotServer.mod")]
ROS = [str(HERE / "ros_motion" / "ROS_common.sys"), str(HERE / "ros_motion" / "ROS_motionServer.mod")]
BACKUP = [str(HERE / "backup" / "cell.pgf")]
LIBRARY = [str(HERE / "library" / "StrUtil.sys"), str(HERE / "library" / "LibDemo.mod")]
SURVEY2 = HERE / "survey2"          # one small program per cause found in the round-2 survey
REGISTERS = [str(SURVEY2 / "user_registers.mod")]
COMPARED = [str(SURVEY2 / "compared_signals.mod")]


def cli(argv, stdin: str = "") -> tuple[int, str, str]:
    return run_cli(argv, stdin=stdin)


@pytest.mark.parametrize("files", [SERVER, ROS, BACKUP, LIBRARY], ids=["server", "ros", "backup",
                                                                      "library"])
def test_realworld_programs_parse(files):
    code, out, err = cli(["parse", *files])
    assert code == 0, err
    assert "ok" in out


# (name, files, extra options, stdin file or text, exit code, expected stdout lines)
RUNS = [
    ("server session: ping, move, position, bad arguments, unknown command, shutdown",
     SERVER, [], HERE / "socket_server" / "session.in", 0,
     ["client 127.0.0.1", "[socket] 1 1 pong", "[socket] 2 1", "[socket] 3 1 100", "[socket] 2 0",
      "[socket] 7 0", "[socket] 0 bye"]),
    ("server: the client leaves (end of input), the ERROR handler listens again",
     SERVER, [], HERE / "socket_server" / "dropped.in", 2,
     ["client 127.0.0.1", "[socket] 1 1 pong", "[socket] 2 1", "client left, listening again"]),
    ("ROS-style trajectory: start, point, garbage, end; state packed as rawbytes",
     ROS, [], HERE / "ros_motion" / "session.in", 0,
     ["[MotionServer] client connected", "[socket] 08 00 00 00 00 00 00 03 00 00 a0 41"]),
    ("backup: three parts with configured I/O, log lines through a file",
     BACKUP, ["--io", "diPartPresent=1"], "", 0,
     ["[file HOME:/cell.log] placed part 1", "[file HOME:/cell.log] placed part 2",
      "[file HOME:/cell.log] placed part 3", "Cell done, parts: 3"]),
    ("library: field splitting, StrToVal defaults, padding",
     LIBRARY, [], "", 0,
     ["fields: 4", "second: 20", "third empty: TRUE", "fourth: abc", "fifth: []", "total: 28",
      "clamp: 100", "[  7]"]),
    ("USER module data: reg1..reg5 and clock1 used without declarations",
     REGISTERS, [], "4\n", 0,
     ["Dismiss the last cycle time?", "cycle 2", "answer 4", "count 1"]),
    ("undeclared names compared with numbers are configured signals (kind from the prefix)",
     COMPARED, ["--io", "DI_CONV_IN_POS=1", "--io", "giRecipe=7"], "", 0, ["recipe 7"]),
    ("stoppoint constants inpos, stoptime, fllwtime",
     [str(SURVEY2 / "stop_points.mod")], [], "", 0, ["follow time"]),
    ("errnum names of EGM and RMQ handled in ERROR",
     [str(SURVEY2 / "egm_errors.mod")], [], "", 0, ["timeouts 2"]),
    ("a command server links although one command needs CalcJointT",
     [str(SURVEY2 / "kinematics_server.mod")], [], "0\n", 0, ["command", "ping"]),
]


@pytest.mark.parametrize("name,files,options,stdin,exit_code,lines", RUNS, ids=[r[0] for r in RUNS])
def test_realworld_run(name, files, options, stdin, exit_code, lines):
    text = stdin.read_text() if isinstance(stdin, Path) else stdin
    code, out, err = cli(["run", *files, *options, "--max-steps", "5000"], text)
    assert out.splitlines() == lines, err
    assert code == exit_code, err


def test_server_run_ends_for_want_of_clients_with_a_diagnostic():
    code, out, err = cli(["run", *SERVER, "--max-steps", "5000"],
                         (HERE / "socket_server" / "dropped.in").read_text())
    assert "[RMC302]" in err and "SocketAccept" in err


# (files, extra options, formula, verdict)
CHECKS = [
    (SERVER, [], 'G "nMoves = 0"', "HOLDS"),            # no message decodes to a move by default
    (ROS, [], 'G "nExecuted = 0"', "HOLDS"),
    (BACKUP, [], 'G ("goCellState = 2" -> "nPartsTotal = 3")', "HOLDS"),
    (BACKUP, [], 'F "nPartsTotal = 3"', "VIOLATED"),    # the part sensor may stay off forever
    (BACKUP, [], 'G "doGripClose = 0"', "VIOLATED"),
    (REGISTERS, [], 'G "reg3 <= 1"', "HOLDS"),
    (COMPARED, ["--input-domain", "giRecipe=0,5"], 'F "nState = 3"', "VIOLATED"),  # sensor stays off
    (COMPARED, ["--input-domain", "giRecipe=0,5"], 'G ("nState = 3" -> "DO_ENABLE_CONV = 0")',
     "HOLDS"),
]


@pytest.mark.parametrize("files,options,formula,verdict", CHECKS,
                         ids=[c[2] + " " + c[3] for c in CHECKS])
def test_realworld_check(files, options, formula, verdict):
    code, out, err = cli(["check", *files, *options, "--formula", f"p: {formula}",
                          "--max-states", "20000", "--quiet", "--backend", "builtin"])
    assert f"p: {verdict}" in out, out + err
    assert "no_runtime_error: HOLDS" in out
    assert code == (0 if verdict == "HOLDS" else 1)


def _system(files, **domains) -> tuple[RapidSystem, RapidDescriber]:
    program = build(load_program(files))
    config = CheckConfig(program)
    for name, value in domains.items():
        setattr(config, name, value)
    return RapidSystem(program, config), RapidDescriber(program)


def _reachable(files, condition, **domains) -> bool:
    system, describer = _system(files, **domains)
    result = find_reachable(system, lambda s: condition(describer.describe_state(s)),
                            max_states=20000)
    return bool(result.prefix)


def test_configured_socket_messages_drive_the_server_to_a_move():
    messages = ("2 5 5 5 #", "0 #")
    assert _reachable(SERVER, lambda d: d.get("nMoves") == "2", socket_messages=messages)
    assert not _reachable(SERVER, lambda d: d.get("nMoves") == "1", socket_messages=("1 #",))


def test_ros_trajectory_runs_only_after_its_end_message():
    start, end = "-1 1 0 0 0 0 0", "-3 2 0 0 0 0 0"
    assert _reachable(ROS, lambda d: d.get("nExecuted") == "2", socket_messages=(start, end))
    assert not _reachable(ROS, lambda d: d.get("nExecuted") == "1", socket_messages=(start,))


def _choice_names(system, steps: int = 40) -> set:
    """Names of the choices made on the first ``steps`` levels of the state graph."""
    names, frontier, seen = set(), list(system.initial_states()), set()
    for _ in range(steps):
        following = []
        for state in frontier:
            for (choices, _, _), successor in system.successors(state):
                names.update(name for name, _ in choices)
                if successor not in seen:
                    seen.add(successor)
                    following.append(successor)
        frontier = following
    return names


def test_finite_receive_time_may_run_out_unless_timeouts_are_off():
    """With \\Time:=5 the ROS server's SocketReceive may time out (ERR_SOCK_TIMEOUT)."""
    messages = ("-1 1 0 0 0 0 0",)
    outcome = "SocketReceive outcome at ROS_motionServer.mod:16:7"
    assert outcome in _choice_names(_system(ROS, socket_messages=messages)[0])
    quiet = _choice_names(_system(ROS, socket_messages=messages, socket_timeouts=False)[0])
    assert outcome not in quiet and "SocketReceive at ROS_motionServer.mod:16:7" in quiet


def test_wait_max_never_times_out_and_closures_are_opt_in():
    messages = ("1 #",)
    names = _choice_names(_system(SERVER, socket_messages=messages)[0])
    assert not any("outcome" in name for name in names)
    names = _choice_names(_system(SERVER, socket_messages=messages, socket_closures=True)[0])
    assert any(name.startswith("SocketReceive outcome") for name in names)


# --- rawbytes layouts (rapidmc.semantics.rawbytes) ------------------------------------------

def test_rawbytes_pack_and_unpack_follow_byte_order_and_sizes():
    from rapidmc.semantics import rawbytes
    data = rawbytes.pack(b"", 1, 8.0, ("int", 4))
    data = rawbytes.pack(data, 5, -2.0, ("int", -4), network=True)
    data = rawbytes.pack(data, 9, 20.0, rawbytes.FLOAT4)
    assert rawbytes.to_text(data) == "08 00 00 00 ff ff ff fe 00 00 a0 41"
    assert rawbytes.unpack(data, 5, ("int", -4), network=True) == -2.0
    assert rawbytes.unpack(data, 5, ("int", 4), network=True) == 4294967294.0
    assert rawbytes.unpack(data, 9, rawbytes.FLOAT4) == 20.0
    assert rawbytes.copy(data, 9, b"ab", 3) == b"ab\x00\x00\xa0\x41"
    assert rawbytes.from_text("0a 1F") == b"\n\x1f" and rawbytes.from_text("hi") == b"hi"


def test_rawbytes_pack_past_the_bytes_held_leaves_a_gap_of_zeros():
    from rapidmc.semantics import rawbytes
    from rapidmc.semantics.errors import RapidError
    assert rawbytes.pack(b"\x01", 4, 2.0, ("int", 1)) == b"\x01\x00\x00\x02"
    assert rawbytes.pack(b"", 1024, 7.0, ("int", 1)) == bytes(1023) + b"\x07"
    for start, value in ((1025, 1.0), (1024, 258.0), (0, 1.0)):
        with pytest.raises(RapidError, match="ERR_OUTOFBND"):
            rawbytes.pack(b"", start, value, ("int", 2) if value > 255 else ("int", 1))


# --- gaps found in real code, now closed -------------------------------------------------

def _link_error(tmp_path, text: str) -> str:
    path = tmp_path / "gap.mod"
    path.write_text(text)
    code, out, err = cli(["run", str(path), "--max-steps", "100"])
    return err if code != 0 else ""


def test_rawbytes_record_component_links(tmp_path):
    assert _link_error(tmp_path, "MODULE M\nRECORD msg\n  num kind;\n  rawbytes data;\nENDRECORD\n"
                       "VAR msg m;\nPROC main()\n  ClearRawBytes m.data;\n"
                       "  TPWrite \"n\" \\Num:=RawBytesLen(m.data);\nENDPROC\nENDMODULE\n") == ""


def test_configured_signal_read_before_it_is_set_links(tmp_path):
    assert _link_error(tmp_path, "MODULE M\nPROC main()\n  IF doLamp = 1 TPWrite \"on\";\n"
                       "  InvertDO doLamp;\nENDPROC\nENDMODULE\n") == ""


def test_signal_kind_follows_the_name_prefix():
    from rapidmc.semantics.configured_signals import kind_from_prefix
    cases = {"diPart": "DI", "DI_CONV": "DI", "DI1": "DI", "doLamp": "DO", "GO_CODE": "GO",
             "aiLevel": "AI", "aoSpeed": "AO", "giRecipe": "GI", "DOOR_CLOSED": "DI",
             "dial": "DI", "sensor": "DI"}
    assert {name: kind_from_prefix(name) for name in cases} == cases


def test_compared_output_signal_is_an_output(tmp_path):
    path = tmp_path / "lamp.mod"
    path.write_text("MODULE M\nPROC main()\n  IF doLamp = 0 TPWrite \"off\";\nENDPROC\nENDMODULE\n")
    code, out, err = cli(["check", str(path), "--quiet", "--formula", 'p: G "doLamp = 0"'])
    assert "p: HOLDS" in out, out + err       # nobody sets an output: it stays 0


def test_missing_tool_explains_where_tools_live(tmp_path):
    err = _link_error(tmp_path, "MODULE M\nCONST robtarget p:=[[0,0,0],[1,0,0,0],[0,0,0,0],"
                      "[9E9,9E9,9E9,9E9,9E9,9E9]];\nPROC main()\n  MoveL p, v100, fine, tGripper;\n"
                      "ENDPROC\nENDMODULE\n")
    assert "unknown name 'tGripper'" in err and "'tGripper' would be tooldata" in err
    assert "CalibData.mod" in err


def test_user_module_data_is_not_in_programs_that_do_not_use_it(tmp_path):
    program = build(load_program([str(SURVEY2 / "stop_points.mod")]))
    assert not any(data.key.startswith("REG") for data in program.globals)
    program = build(load_program(REGISTERS))
    assert sorted(d.key for d in program.globals if d.module == "user") == [
        "CLOCK1", "REG1", "REG2", "REG3"]


def test_calc_joint_t_answers_the_robot_axes_the_robot_has_and_says_so():
    """Issue 19: CalcJointT no longer stops the run; without kinematics it answers the robot
    axes of the modelled robot (0 at the start), an assumption RMC702 names when checking."""
    code, out, err = cli(["run", str(SURVEY2 / "kinematics_server.mod")], "12\n")
    assert code == 0, err
    assert out.splitlines() == ["command", "ik 0"]
    code, out, err = cli(["check", str(SURVEY2 / "kinematics_server.mod")])
    assert "CalcJointT reads a fixed value when checking" in err and "[RMC702]" in err


def test_modules_of_two_tasks_report_the_duplicate_entry_clearly():
    files = sorted(str(p) for p in (SURVEY2 / "two_tasks").glob("*.mod"))
    code, out, err = cli(["run", *files])
    assert code == 2 and "routine 'main' is declared twice" in err
    assert "every RAPID task has its own entry routine" in err
    robot_task = str(SURVEY2 / "two_tasks" / "T_ROB1_Main.mod")
    code, out, err = cli(["run", robot_task])         # the PLC task that sets the flag is absent,
    assert "[RMC301]" in err and "WaitUntil" in err   # so the robot task alone waits forever

