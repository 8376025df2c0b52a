"""Domains of socket messages, file lines and FlexPendant numbers derived from the program
(``rapidmc.load.message_domains``), and coverage warnings that say what they rest on.

The verdicts these domains reach are pinned by check cases (tests/check/socket_test_cases,
socket_strtoval_array, socket_raw_header, file_lines_derived, tp_answers_derived), which
test_native_engine also runs on both engines.  Here: the domains themselves, their notes
(RMC515), ``--socket-messages`` replacing them, and the wording of RMC701 and of vacuity
when an input was offered a sample of its values only.
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

from rapidmc import api
from rapidmc.check.result import SearchStats
from rapidmc.load import message_domains as message_domains_module
from rapidmc.load.message_domains import message_domains, well_formed
from rapidmc.load.run_time_offsets import walked_starts
from rapidmc.semantics.types import NUM, ArrayType
from rapidmc.syntax import parse_text

CHECK = Path(__file__).resolve().parent / "check"

SERVER = """MODULE Server
    VAR socketdev server;
    VAR socketdev client;
    VAR string request := "";
    VAR num joints{{2}};
    VAR num state := 0;

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 1025;
        SocketListen server;
        SocketAccept server, client \\Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \\Str:=request \\Time:=WAIT_MAX;
{body}
        ENDWHILE
    ENDPROC
{extra}
ENDMODULE
"""

# only compared with strings: the messages tried tell apart all a peer could send
EXACT = """            IF request = "A" THEN
                state := 1;
                IF request = "B" THEN
                    state := 2;
                ENDIF
            ENDIF"""

# parsed: a peer's other texts parse into other values
PARSED = """            IF StrToVal(request, joints) THEN
                IF joints{1} = 99 THEN
                    state := 3;
                ENDIF
            ENDIF"""


def domains_of(folder: str) -> list:
    program = api.load_program([str(CHECK / folder / "prog.mod")])
    return [(d.instruction, d.site.line, d.messages, d.exact) for d in message_domains(program)]


def test_test_on_a_received_string_offers_every_case_and_one_more():
    assert domains_of("socket_test_cases") == [
        ("SocketReceive", 14, ("PNP", "INK", "?"), True)]


def test_strtoval_into_an_array_offers_a_good_and_a_bad_text_after_its_prefix():
    [(_, _, messages, exact)] = domains_of("socket_strtoval_array")
    assert "JNT:[1,2,3,4,5]" in messages and "JNT:#" in messages and not exact


def test_a_header_read_with_unpackrawbytes_offers_one_value_per_dispatch_class():
    [(_, _, messages, exact)] = domains_of("socket_raw_header")
    headers = {bytes.fromhex(m.replace(" ", "")) for m in messages}
    values = {int.from_bytes(h, "little", signed=True) for h in headers}
    assert {10, 11, 101} <= values and values - {10, 11} and not exact


def test_file_reads_and_typed_numbers_get_their_own_domains():
    assert domains_of("file_lines_derived") == [
        ("ReadStr", 10, ("FAST", "SLOW", "?"), True),
        ("ReadNum", 11, ("9", "10", "11", "#"), True)]
    assert domains_of("tp_answers_derived") == [("TPReadNum", 10, (6.0, 7.0, 8.0), True)]


def test_a_well_formed_text_parses_into_its_type():
    assert well_formed(ArrayType(NUM, (5,))) == "[1,2,3,4,5]"


def check_server(tmp_path, body: str, extra: str = "", **options) -> api.CheckReport:
    path = tmp_path / "server.mod"
    path.write_text(SERVER.format(body=body, extra=extra))
    prop = api.property_from_text('never3: G("state = 3" -> F "state = 0")')
    return api.check(api.load_program([str(path)]), [prop], api.CheckOptions(**options))


def coverage(report: api.CheckReport) -> list[str]:
    return [w.message for w in report.warnings if w.code.code == "RMC701"]


def test_dead_code_behind_an_exact_domain_is_never_reached_under_any_input(tmp_path):
    report = check_server(tmp_path, EXACT)
    assert coverage(report) == ["never reached under any input"]      # state := 2
    notes = [w.message for w in report.warnings if w.code.code == "RMC515"]
    assert notes == ["SocketReceive at line 14: messages 'A', 'B', '?' (compared with 'A', "
                     "'B'; and one the program does not expect)"]


def test_code_unreached_with_sampled_messages_says_so_and_names_the_receive(tmp_path):
    report = check_server(tmp_path, PARSED)
    assert coverage(report) == [
        "never reached with the socket messages tried (SocketReceive at line 14)"]
    [result] = [r for r in report.results if r.name == "never3"]
    assert result.vacuous is not None
    assert result.vacuous_inputs == "with the socket messages tried (SocketReceive at line 14)"


@pytest.mark.parametrize("body", [EXACT, PARSED])
def test_socket_messages_given_replace_the_derived_domain(tmp_path, body):
    report = check_server(tmp_path, body, socket_messages=("A",))
    assert not [w for w in report.warnings if w.code.code == "RMC515"]
    assert all("with the socket messages tried (SocketReceive at line 14)" in message
               for message in coverage(report))


def test_a_routine_no_call_leads_to_is_never_reached_under_any_input(tmp_path):
    unused = "    PROC Unused()\n        state := 5;\n    ENDPROC"
    report = check_server(tmp_path, PARSED, unused)
    assert coverage(report) == [
        "never reached with the socket messages tried (SocketReceive at line 14)",
        "never reached under any input (routine Unused never runs)"]


def test_a_parsed_code_dispatched_by_test_gets_each_case_number_as_fields():
    [(_, _, messages, exact)] = domains_of("socket_parsed_code")
    assert {"1 1 #", "2 2 #", "99 99 #"} <= set(messages) and not exact


def test_a_further_tasks_receives_get_their_domains_and_honest_coverage(tmp_path):
    """A socket server in the second task of a controller: its receive is offered the
    messages its code tells apart, as the main task's are, and code it leaves unreached is
    said to rest on the messages tried (not 'under any input')."""
    (tmp_path / "robot.mod").write_text(
        "MODULE Robot\n  PERS bool go := FALSE;\n  PROC main()\n    WaitUntil go;\n"
        "  ENDPROC\nENDMODULE\n")
    (tmp_path / "link.mod").write_text(
        "MODULE Link\n  PERS bool go := FALSE;\n  VAR socketdev server;\n"
        "  VAR socketdev client;\n  VAR string data := \"\";\n  VAR num parsed := 0;\n"
        "  PROC main()\n    SocketCreate server;\n    SocketBind server, \"127.0.0.1\", 1025;\n"
        "    SocketListen server;\n    SocketAccept server, client \\Time:=WAIT_MAX;\n"
        "    SocketReceive client \\Str:=data \\Time:=WAIT_MAX;\n"
        "    IF data = \"TRUE\" THEN\n      go := TRUE;\n    ENDIF\n"
        "    IF StrToVal(data, parsed) AND parsed > 7 THEN\n      go := FALSE;\n    ENDIF\n"
        "  ENDPROC\nENDMODULE\n")
    program = api.load_program([str(tmp_path / "robot.mod")],
                               add_tasks=[str(tmp_path / "link.mod")])
    report = api.check(program, [])
    notes = [w.message for w in report.warnings if w.code.code == "RMC515"]
    assert len(notes) == 1 and notes[0].startswith("SocketReceive at line 12: messages 'TRUE'")
    assert all("under any input" not in message for message in coverage(report))


def test_a_count_of_fields_compared_in_a_commands_branch_gets_probe_messages():
    """``TEST code CASE 1: IF nParams = 3``, nParams counted by a loop over the message's
    fields: a probe per count a command compares (and one other count), tried one at a
    time for coverage; the code no CASE names ('3') is among the messages of the search."""
    program = api.load_program([str(CHECK / "socket_field_count" / "prog.mod")])
    [domain] = message_domains(program)
    assert {"1 1 1 1 #", "1 #", "2 #", "2 1 #"} <= set(domain.probes)
    assert "3 3 #" in domain.messages and not set(domain.probes) & set(domain.messages)
    assert "for coverage also each of" in domain.note().message


def test_probe_messages_reach_the_branches_coverage_would_report(monkeypatch):
    """Without the probes' searches, the branch for three parameters is reported; with
    them it is reached (tests/check/socket_field_count has no ``unreached`` file)."""
    program = api.load_program([str(CHECK / "socket_field_count" / "prog.mod")])
    assert coverage(api.check(program)) == []
    monkeypatch.setattr(api, "_probed_lines", lambda model, bound: set())
    assert coverage(api.check(program)) == [
        "never reached with the socket messages tried (SocketReceive at line 53)"]


def test_probes_try_an_extra_field_the_values_compared_and_a_pose():
    """mcubelab's pattern: an id field before the counted parameters, a parameter compared
    with 1 (its ELSE), a pose whose quaternion must be a unit one: each is a probe."""
    program = api.load_program([str(CHECK / "socket_field_values" / "prog.mod")])
    [domain] = message_domains(program)
    assert {"9 1 1 1 1 1 #", "9 1 2 1 1 1 #", "12 1 1 1 1 1 1 1 1 #",
            "12 1 0 0 0 1 0 0 0 #"} <= set(domain.probes)
    assert not set(domain.probes) & set(domain.messages)


def test_without_the_probes_the_branches_are_reported(monkeypatch):
    """The probes reach both branches of each command (the case has no ``unreached``
    file); with no probe tried (``PROBE_TOTAL`` 0: the probes' budget spent at once), the
    loop over the parameters and each command's inner branches are reported, with the
    messages tried."""
    program = api.load_program([str(CHECK / "socket_field_values" / "prog.mod")])
    assert coverage(api.check(program)) == []
    monkeypatch.setattr(api, "PROBE_TOTAL", 0)
    assert coverage(api.check(program)) == [
        "lines 46-48 of Parse are never reached with the socket messages tried "
        "(SocketReceive at line 61)",
        "lines 67-70 of main are never reached with the socket messages tried "
        "(SocketReceive at line 61)",
        "lines 75-79 of main are never reached with the socket messages tried "
        "(SocketReceive at line 61)"]


def test_messages_the_cap_leaves_out_are_probes(tmp_path):
    """Thirty commands' numbers fill the domain (``MAX_MESSAGES``); the texts left out,
    the malformed code among them ('#### ': ``IF NOT StrToVal(...)``), are probes, and
    reach the branch no message of the domain does."""
    cases = "\n".join(f"            CASE {n}:\n                state := {n};"
                      for n in range(1, 31))
    body = ("            IF StrMatch(request, 1, \"#\") > StrLen(request) THEN\n"
            "                state := -1;\n"
            "            ELSEIF NOT StrToVal(StrPart(request, 1, StrMatch(request, 1, \" \") - 1),"
            " state) OR StrMatch(request, 1, \" \") = 0 THEN\n                state := -2;\n"
            "            ELSE\n"
            f"            TEST state\n{cases}\n            ENDTEST\n            ENDIF")
    (tmp_path / "server.mod").write_text(SERVER.format(body=body, extra=""))
    [domain] = message_domains(derived_program(tmp_path))
    malformed = [text for text in domain.probes if set(text) <= {"#", " "}]
    assert len(domain.messages) == 24 and malformed
    assert not set(malformed) & set(domain.messages)
    report = api.check(derived_program(tmp_path))
    assert coverage(report) == []


# Texts a peer might send besides the derived ones: empty, numbers, each CASE word in other
# cases and with more after it, lists, parameters after a code, separators alone.
OTHER_MESSAGES = ("", " ", "0", "1", "-1", "3", "99", "1.5", "a", "A", "B", "pnp", "PNP ",
                  "INK;", "[1,2,3]", "[99,99]", "[1,2,3,4,5]", "JNT:[1,2,3,4,5]", "1 #", "1 1 1 1 #",
                  "2 #", "2 1 #", "3 3 #", "99 99 #", "# # #", "#", ",", "?")

TEXT_SERVERS = ["socket_test_cases", "socket_parsed_code", "socket_strtoval_array",
                "socket_field_count", "defect_socket_receive_no_time", "socket_matched_words",
                "socket_field_values", "socket_command_sequence"]


def unreached_under_any_input(report: api.CheckReport) -> set:
    return {(span.file, line) for w in report.warnings if w.code.code == "RMC701"
            and "under any input" in w.message for span in (w.span, *w.places)
            for line in range(span.line, (span.end_line or span.line) + 1)}


@pytest.mark.parametrize("body", [EXACT, PARSED])
def test_no_line_said_unreached_under_any_input_is_reached_by_other_messages(tmp_path, body):
    """Lines reported 'never reached under any input' stay unreached when the peer sends
    the derived messages and many others besides (a differential test of that wording)."""
    unused = "    PROC Unused()\n        state := 5;\n    ENDPROC"
    derived = check_server(tmp_path, body, unused)
    claimed = unreached_under_any_input(derived)
    assert claimed                   # each program has such lines: state := 2, or Unused
    derived_messages = tuple(m for d in message_domains(derived_program(tmp_path))
                             for m in d.messages)
    widened = check_server(tmp_path, body, unused,
                           socket_messages=derived_messages + OTHER_MESSAGES)
    assert not claimed & set(widened.executed)


@pytest.mark.parametrize("case", TEXT_SERVERS)
def test_check_cases_claim_no_line_other_messages_reach(case, monkeypatch):
    monkeypatch.chdir(CHECK / case)
    program = api.load_program(["prog.mod"])
    claimed = unreached_under_any_input(api.check(program))
    derived_messages = tuple(m for d in message_domains(program) for m in d.messages)
    widened = api.check(program, [], api.CheckOptions(
        socket_messages=derived_messages + OTHER_MESSAGES))
    assert widened.executed is not None and not claimed & set(widened.executed)


def derived_program(tmp_path):
    return api.load_program([str(tmp_path / "server.mod")])


# a routine the server runs after each message: it reports and waits for an answer
EXCHANGE = """    VAR num lost := 0;
    VAR num mode := 0;
    VAR string ack := "";

    PROC Exchange()
        SocketSend client \\Str:="state";
        SocketReceive client \\Str:=ack \\Time:=WAIT_MAX;
    ERROR
        IF ERRNO = ERR_SOCK_CLOSED THEN
            lost := 1;
        ENDIF
    ENDPROC

    PROC Report()
        TEST OpMode()
        CASE OP_MAN_PROG:
            mode := 1;
        ENDTEST
    ENDPROC"""


def test_a_handler_a_closing_peer_reaches_is_shown_reached_by_the_closure_probe(tmp_path):
    """After each message the server reports and waits for an acknowledgement it does not
    read: a peer closing the connection makes SocketSend or SocketReceive raise
    ERR_SOCK_CLOSED, which the handler catches.  The verdicts' search never closes (closures
    are opt-in), but a coverage probe lets peers close: the handler's lines count as reached,
    and the other unreached lines no longer rest on "no peer closing its socket"."""
    path = tmp_path / "server.mod"
    text = SERVER.format(body="            Exchange;\n            Report;", extra=EXCHANGE)
    path.write_text(text)
    program = api.load_program([str(path)])
    report = api.check(program)
    lost = text.splitlines().index("            lost := 1;") + 1
    assert report.executed is not None and (str(path), lost) in report.executed
    assert coverage(report) == []   # mode := 1 runs in manual mode: the readings probe
    assert report.verdicts == api.check(program, [], api.CheckOptions(
        reuse_explored=False)).verdicts
    closing = api.check(program, [], api.CheckOptions(socket_closures=True))
    assert closing.executed is not None and (str(path), lost) in closing.executed


def test_a_closure_probe_the_bound_stops_keeps_the_wording(tmp_path, monkeypatch):
    """A closure probe stopped by its bound shows nothing about the lines it did not run:
    their warnings still say they rest on no peer closing its socket and on the server's
    port being free (the probe also lets SocketBind fail).  (No walks: they now take the
    closing step to the handler, which runs new lines.)"""
    monkeypatch.setattr(api, "PROBE_STATES", 3)
    monkeypatch.setattr(api, "WALK_LIMIT", 0)
    path = tmp_path / "server.mod"
    path.write_text(SERVER.format(body="            Exchange;", extra=EXCHANGE))
    messages = coverage(api.check(api.load_program([str(path)])))
    assert messages == [
        "lines 26-27 of Exchange are never reached with no peer closing its socket and the "
        "server's port free (SocketBind at line 10; SocketReceive at lines 14, 24; SocketSend "
        "at line 23)",
        "never reached under any input (routine Report never runs)"]


def test_no_line_said_unreached_under_any_input_runs_when_peers_close(tmp_path):
    """The differential test of the wording for closures: with --socket-closures in the
    verdicts' own search, no line the default check called unreached under any input runs."""
    path = tmp_path / "server.mod"
    unused = EXCHANGE + "\n    PROC Unused(num n)\n        state := n;\n    ENDPROC"
    path.write_text(SERVER.format(body=EXACT + "\n            Exchange;", extra=unused))
    program = api.load_program([str(path)])
    claimed = unreached_under_any_input(api.check(program))
    assert len(claimed) > 2                          # state := 2, Unused
    closing = api.check(program, [], api.CheckOptions(socket_closures=True))
    assert closing.executed is not None and not claimed & set(closing.executed)


def test_a_length_prefix_frames_each_message_of_the_receive_it_sizes():
    """ROS-style frames: the 4-byte receive whose value sizes the next receive is offered
    each of that receive's messages after its length, and a length of 0; the header's
    fields unpacked into record components (followed out of the VAR parameter) and the
    data copied from byte 9 give the dispatch's values."""
    program = api.load_program([str(CHECK / "socket_length_prefixed" / "prog.mod")])
    prefix, body = message_domains(program)
    frames = [bytes.fromhex(m.replace(" ", "")) for m in prefix.messages]
    assert frames[-1] == bytes(4)
    assert all(int.from_bytes(f[:4], "little") == len(f) - 4 for f in frames)
    bodies = [bytes.fromhex(m.replace(" ", "")) for m in body.messages]
    typed = [b for b in bodies if int.from_bytes(b[:4], "little", signed=True) == 11]
    assert {int.from_bytes(b[8:12], "little", signed=True) for b in typed} >= {-1, -3}


def test_a_routine_no_call_reaches_gives_no_values(tmp_path):
    """What only an uncalled routine compares the data with chooses nothing a search can
    reach: it adds no message (each would multiply the states for nothing)."""
    unused = ("    PROC Unused()\n        IF request = \"NEVER\" THEN\n            state := 5;\n"
              "        ENDIF\n    ENDPROC")
    path = tmp_path / "server.mod"
    path.write_text(SERVER.format(body=EXACT, extra=unused))
    [domain] = message_domains(api.load_program([str(path)]))
    assert domain.messages == ("A", "B", "?")


@pytest.mark.parametrize("read", ["DOutput(doCycleOn)", "doCycleOn"])
@pytest.mark.parametrize("setter, probe_states, wording", [
    ("", 20_000, []),
    ("", 1, ["never reached with the outputs no loaded code sets at their first value "
             "({reader} at line 4)"]),
    ("        Set doCycleOn;\n", 20_000, ["never reached under any input"])])
def test_an_output_no_loaded_code_sets_is_an_input(tmp_path, monkeypatch, setter,
                                                     probe_states, wording, read):
    """A task that waits for an output the controller sets (a system output: cycle on) or
    another task sets reads its first value in the check; the readings probe reads it at 0
    and 1, so the code after the wait counts as reached (while a probe the bound stops
    leaves the warning naming the read).  Set by the program itself (in a routine nothing
    calls), the output is no input: the code after the wait is dead.  Read by name
    (``WaitUntil doCycleOn = 1``, a world zone's output in public code) as by DOutput."""
    monkeypatch.setattr(api, "PROBE_STATES", probe_states)
    monkeypatch.setattr(api, "PROBE_GROWTH", 1)          # (the bound is PROBE_STATES)
    monkeypatch.setattr(api, "WALK_STEPS", 0)            # (no walks after a stopped probe)
    path = tmp_path / "cell.mod"
    path.write_text("MODULE Cell\n    VAR num state := 0;\n    PROC main()\n"
                    f"        WaitUntil {read} = 1;\n        state := 1;\n"
                    f"    ENDPROC\n    PROC Start()\n{setter}        state := 2;\n"
                    "    ENDPROC\nENDMODULE\n")
    messages = [m for m in coverage(api.check(api.load_program([str(path)])))
                if "Start" not in m]
    reader = read.partition("(")[0]
    assert messages == [text.format(reader=reader) for text in wording]


def test_a_handler_an_egm_session_failure_reaches_names_the_egm_instructions(tmp_path):
    """An EGM session may fail on a controller (ERR_UDPUC_COMM when the sensor stops
    answering); the check never fails one, so the handler is not unreached under any input."""
    path = tmp_path / "egm.mod"
    path.write_text(
        "MODULE Egm\n    VAR egmident egm_id;\n    VAR num lost := 0;\n    PROC main()\n"
        "        EGMGetId egm_id;\n"
        "        EGMSetupUC ROB_1, egm_id, \"default\", \"UCdevice\", \\Joint;\n"
        "        EGMRunJoint egm_id, EGM_STOP_HOLD \\J1 \\CondTime:=5;\n"
        "        EGMReset egm_id;\n    ERROR\n        IF ERRNO = ERR_UDPUC_COMM THEN\n"
        "            lost := 1;\n        ENDIF\n    ENDPROC\nENDMODULE\n")
    assert coverage(api.check(api.load_program([str(path)]))) == [
        "lines 10-11 of main are never reached with no EGM session failing "
        "(EGMSetupUC at line 6; EGMRunJoint at line 7)"]


def test_code_waiting_for_another_tasks_write_names_the_persistent_data(tmp_path):
    """A socket task checked alone acts on ``SocketStr`` only when it holds a command
    (``IF SocketStr = "go"``, no wait) and empties it after: it never writes a command
    itself, another task or a PC may.  The shared data probe lets waits and polls see such writes, not this branch, so
    the code stays unreached and the warning names the persistent data instead of "under
    any input"."""
    path = tmp_path / "socket.mod"
    path.write_text("MODULE Socket\n    PERS string SocketStr := \"\";\n"
                    "    VAR num sent := 0;\n    PROC main()\n"
                    "        IF SocketStr = \"go\" THEN\n            sent := 1;\n"
                    "        ENDIF\n        SocketStr := \"\";\n    ENDPROC\nENDMODULE\n")
    assert coverage(api.check(api.load_program([str(path)]))) == [
        "never reached with no other task writing the persistent data (SocketStr at line 5)"]


MAILBOX = """MODULE Mailbox
    PERS string command := "";
    PERS string reply := "";
    VAR num picked := 0;
    VAR num placed := 0;
    PROC main()
        WHILE TRUE DO
            WHILE command <> "" DO
                IF command = "pick" THEN
                    picked := picked + 1;
                    reply := "ok";
                    command := "";
                    WaitUntil reply = "";
                    picked := picked + 10;
                ELSEIF command = "place" THEN
                    placed := placed + 1;
                    command := "";
                ELSE
                    command := "";
                ENDIF
            ENDWHILE
            WaitTime 0.1;
        ENDWHILE
        placed := -1;
    ENDPROC
ENDMODULE
"""


def test_a_mailbox_another_task_fills_is_reached_by_the_shared_data_probe(tmp_path):
    """One half of a two-task mailbox checked alone: the task polls ``command``, which
    only the other task fills, and waits for ``reply = ""``, which only the other task
    clears.  The shared data probe lets each poll and wait see what another task may
    write (the strings compared, and one other), so every command's branch and the code
    after the wait for the reply run; code after the endless loop stays unreached, under
    any input: no GOTO leaves a ``WHILE TRUE`` (``findings.dead_code``).  The verdicts keep this task's own
    writes (the probe only shows lines), except for ``reply``: no write of the loaded code
    ends ``WaitUntil reply = ""``, so the check itself takes it as written by a client
    too (``load.awaited_from_outside``) and the warning no longer names it."""
    path = tmp_path / "mailbox.mod"
    path.write_text(MAILBOX)
    report = api.check(api.load_program([str(path)]))
    assert report.verdicts == {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS"}
    for code in ("picked := picked + 1;", "picked := picked + 10;", "placed := placed + 1;",
                 "        ELSE"):
        number = next(n for n, line in enumerate(MAILBOX.splitlines(), 1) if code in line)
        assert (str(path), number) in report.executed, code
    assert coverage(report) == ["never reached under any input: the code after the endless "
                                "WHILE loop at line 7"]


def test_without_the_shared_data_probe_the_mailbox_polls_are_the_clients(tmp_path):
    """The same program built without ``load_program`` (no files to load again): the
    probe cannot run, yet the mailbox code is reached.  The IFs in the loop poll
    ``command`` for "pick" and "place", which no write of the loaded code gives (it writes
    only ""), so the check itself takes a client as writing it too
    (``load.awaited_from_outside``: a poll), as for the WaitUntil on ``reply``; only the
    code after the endless loop stays dead."""
    path = tmp_path / "mailbox.mod"
    path.write_text(MAILBOX)
    program = api.load_program([str(path)])
    program.load_arguments = None
    report = api.check(program)
    assert coverage(report) == ["never reached under any input: the code after the endless "
                                "WHILE loop at line 7"]
    assert any("PERS command: no write of the loaded code ends the poll at mailbox.mod:9"
               in text for text in report.results[0].assumes), report.results[0].assumes


GUARDED_MAILBOX = """MODULE Guarded
    PERS string command := "";
    VAR intnum reset_int;
    VAR intnum door_int;
    VAR intnum stop_int;
    VAR num picked := 0;
    VAR num warm := 0;
    PROC main()
        IDelete reset_int;
        CONNECT reset_int WITH Restart;
        ISignalDI diReset, 1, reset_int;
        IDelete door_int;
        CONNECT door_int WITH Restart;
        ISignalDI diDoor, 1, door_int;
        IDelete stop_int;
        CONNECT stop_int WITH Restart;
        ISignalDI diStop, 1, stop_int;
        FOR i FROM 1 TO 12 DO
            warm := warm + 1;
        ENDFOR
        WHILE TRUE DO
            WHILE command <> "" DO
                IF command = "pick" THEN
                    picked := picked + 1;
                ENDIF
                command := StrPart(command, 1, 0);
            ENDWHILE
            WaitTime 0.1;
        ENDWHILE
    ENDPROC
    TRAP Restart
        warm := 0;
        ExitCycle;
    ENDTRAP
ENDMODULE
"""


@pytest.mark.parametrize("probe_states, reached", [(150, True), (1, False)])
def test_a_probe_the_inputs_make_broad_searches_again_with_them_held(
        tmp_path, monkeypatch, probe_states, reached):
    """Three interrupts on digital inputs (each may fire at any step) multiply every step
    of the shared data probe by 8: breadth-first, it spends its bound on the warm-up loop
    before the first poll of the mailbox (Hanoi TASK1's four interrupts and long start-up
    routine).  A probe stopped by its bound searches again with those inputs held (no
    interrupt fires: a cell whose signals stay put), and each line that search runs is
    reachable: the command's branch counts as reached.  A bound too small for that search
    too leaves the branch reported, naming the data.  (The mailbox is emptied by a computed
    write, ``StrPart(command, 1, 0)``, so ``awaited_from_outside`` does not take its polls
    as a client's: only the probe reaches the branch.)"""
    monkeypatch.setattr(api, "PROBE_STATES", probe_states)
    monkeypatch.setattr(api, "PROBE_GROWTH", 1)          # (the bound is PROBE_STATES)
    path = tmp_path / "guarded.mod"
    path.write_text(GUARDED_MAILBOX)
    report = api.check(api.load_program([str(path)]))
    line = next(n for n, text in enumerate(GUARDED_MAILBOX.splitlines(), 1)
                if "picked := picked + 1;" in text)
    assert ((str(path), line) in report.executed) == reached
    assert bool(coverage(report)) != reached


RELAY = """MODULE Relay
    PERS string command := "";
    PERS string logged{30} := ["","","","","","","","","","","","","","","",
                               "","","","","","","","","","","","","","",""];
    VAR num count := 1;
    VAR socketdev client;
    VAR string received;
    PROC main()
        SocketCreate client;
        SocketConnect client, "10.0.0.2", 5000 \\Time:=WAIT_MAX;
        WHILE TRUE DO
            WHILE command = "" DO
                SocketReceive client \\Str:=received \\Time:=WAIT_MAX;
                command := received + "#";
                count := count + 1;
                logged{count} := received;
                IF count > 24 THEN
                    count := 1;
                    TPWrite "first logged: " + logged{1};
                ENDIF
                IF received = "stop" OR received = "home" THEN
                    TPWrite "command " + received;
                ENDIF
            ENDWHILE
            WaitTime 0.1;
        ENDWHILE
    ENDPROC
ENDMODULE
"""


@pytest.mark.parametrize("walk_steps, reached", [(api.WALK_STEPS, True), (0, False)])
def test_a_counter_wrapping_after_many_messages_is_reached_by_the_probes_walks(
        tmp_path, monkeypatch, walk_steps, reached):
    """The Hanoi socket task's pattern: each message goes into a mailbox another task
    empties, and into a log whose counter wraps after 24 messages.  Checked alone, the
    task stops after one message; the shared data probe lets the mailbox's poll see it
    emptied, but the log keeps every message, so its breadth-first search spends its
    20,000 states on the first few messages.  Random walks (``check.walks``) then go
    as deep as they are long, and the wrap-around runs.  Without the walks it stays
    reported, naming the messages and the data the probe chose."""
    monkeypatch.setattr(api, "WALK_STEPS", walk_steps)
    path = tmp_path / "relay.mod"
    path.write_text(RELAY)
    report = api.check(api.load_program([str(path)]))
    line = next(n for n, text in enumerate(RELAY.splitlines(), 1) if text.strip() == "count := 1;")
    assert ((str(path), line) in report.executed) == reached
    assert coverage(report) == ([] if reached else [
        f"lines {line}-{line + 1} of main are never reached with the socket messages tried "
        "and no other task writing the persistent data (command at line 12; SocketReceive "
        "at line 13)"])


def test_a_handler_a_closure_reaches_behind_a_wait_for_an_output_is_reached(tmp_path):
    """The Hanoi socket task connects only once an output no loaded code sets is 1, and
    handles a closed connection in ``main``'s ERROR handler.  The closure probe alone waits
    forever at the output, the readings probe alone never closes: a closure probe with the
    readings free reaches the handler, and nothing is left unreached."""
    path = tmp_path / "client.mod"
    path.write_text(
        "MODULE Client\n    VAR socketdev link;\n    VAR string text := \"\";\n"
        "    VAR num lost := 0;\n    PROC main()\n"
        "        WaitUntil DOutput(doRobotReady) = 1;\n        SocketCreate link;\n"
        "        SocketConnect link, \"10.0.0.2\", 5000;\n        WHILE TRUE DO\n"
        "            SocketReceive link \\Str:=text;\n        ENDWHILE\n    ERROR\n"
        "        IF ERRNO = ERR_SOCK_CLOSED THEN\n            lost := lost + 1;\n"
        "            SocketClose link;\n        ENDIF\n    ENDPROC\nENDMODULE\n")
    report = api.check(api.load_program([str(path)]))
    assert (str(path), 14) in report.executed
    assert coverage(report) == []


BIND = """MODULE Server
    VAR socketdev listener;
    VAR socketdev client;
    VAR string text := "";
    VAR num failures := 0;
    PROC main()
        OpenServer;
        SocketAccept listener, client \\Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \\Str:=text \\Time:=WAIT_MAX;
            SocketSend client \\Str:="ok";
        ENDWHILE
    ERROR (ERR_SOCK_CLOSED)
        SocketClose client;
        RETRY;
    ENDPROC
    PROC OpenServer()
        SocketCreate listener;
        SocketBind listener, "127.0.0.1", 1100;
        SocketListen listener;
    ERROR
        failures := failures + 1;
        RAISE;
    ENDPROC
ENDMODULE
"""


def test_a_handler_for_a_port_in_use_is_reached_by_the_closure_probe(tmp_path):
    """A ROS-style server opens its socket in a routine whose handler passes errors on
    (``ERROR ... RAISE``).  A closing peer never reaches that handler: ERR_SOCK_CLOSED
    comes after the socket is open.  A port the previous run still holds does
    (ERR_SOCK_ADDR_INUSE at SocketBind), so the closure probe lets SocketBind fail too:
    the handler counts as reached instead of "never reached under any input".  The
    verdicts keep a free port."""
    path = tmp_path / "bind.mod"
    path.write_text(BIND)
    report = api.check(api.load_program([str(path)]))
    assert report.verdicts == {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS"}
    number = next(n for n, line in enumerate(BIND.splitlines(), 1) if "failures := failures" in line)
    assert (str(path), number) in report.executed
    assert coverage(report) == []


def test_a_probe_may_visit_twice_the_states_of_the_check_up_to_a_limit(monkeypatch):
    """A probe adds choices to the program the check searched: its bound is twice the
    check's own states when that exceeds PROBE_STATES, at most PROBE_GROWTH times it."""
    def results(states):
        stats = SearchStats(model_states=states)
        return [SimpleNamespace(result=SimpleNamespace(stats=stats))]
    monkeypatch.setattr(api, "PROBE_STATES", 100)
    monkeypatch.setattr(api, "PROBE_GROWTH", 2.5)
    assert api._probe_bound(results(10)) == 100
    assert api._probe_bound(results(70)) == 140
    assert api._probe_bound(results(1000)) == 250


def test_with_socket_closures_a_port_in_use_is_still_tried(tmp_path):
    """``--socket-closures`` closes peers in the verdicts' own search but never takes a
    port: the handler a taken port reaches is still shown reached by the closure probe,
    not "never reached under any input"."""
    path = tmp_path / "bind.mod"
    path.write_text(BIND)
    report = api.check(api.load_program([str(path)]), [],
                       api.CheckOptions(socket_closures=True))
    number = next(n for n, line in enumerate(BIND.splitlines(), 1)
                  if "failures := failures" in line)
    assert (str(path), number) in report.executed
    assert coverage(report) == []


def test_a_list_between_brackets_is_also_tried_with_its_last_part_malformed():
    """A routine that cuts a list between brackets and parses each part fails at the part
    that does not parse: "[1,1]" fails at its missing part, "[1,1,?]" at the last one (the
    handler of MARC-HT25's fourth orientation value)."""
    program = api.load_program([str(CHECK / "socket_bracket_list" / "prog.mod")])
    [domain] = message_domains(program)
    assert domain.messages[:3] == ("[1,1,1]", "[1,1,?]", "[1,1]")


def test_words_matched_at_the_start_are_tried_alone_and_heading_a_list_of_numbers():
    """``StrMatch(cmd, 1, "PICK,") = 1`` names a command, not a field separator: the
    messages hold each word alone ("HOME") and heading as many numbers as the command's
    routine parses ("PICK,1,1"); before, the words were taken as separators and the
    24 messages' cap left none starting with a word, so no command's code was reached."""
    [(_, _, messages, exact)] = domains_of("socket_matched_words")
    assert {"HOME", "PICK,", "PAUSE", "PICK,1,1", "PICK,1,?"} <= set(messages) and not exact
    program = api.load_program([str(CHECK / "socket_matched_words" / "prog.mod")])
    assert coverage(api.check(program)) == []


def test_a_trap_only_an_unmodelled_interrupt_runs_names_the_instruction_ordering_it(tmp_path):
    """IError (like ISignalGI, TriggInt ...) has no effect in the check: its interrupt never
    comes there, while a real controller runs the TRAP once such an error is logged, so
    the TRAP is not unreached under any input (review of session 5)."""
    path = tmp_path / "press.mod"
    path.write_text(
        "MODULE Press\n    VAR intnum irq;\n    VAR num hits := 0;\n"
        "    PROC main()\n        CONNECT irq WITH OnError;\n"
        "        IError COMMON_ERR, TYPE_ALL, irq;\n        WaitTime 1;\n"
        "    ENDPROC\n    TRAP OnError\n        hits := hits + 1;\n    ENDTRAP\nENDMODULE\n")
    report = api.check(api.load_program([str(path)]), (), api.CheckOptions())
    assert coverage(report) == [
        "never reached with no interrupt coming that the check does not model "
        "(IError at line 6) (routine OnError never runs)"]


PRESS = ("MODULE Press\n    VAR signalai ai_press;\n    VAR intnum irq;\n    VAR num hits := 0;\n"
         "    PROC main()\n        AliasIO \"AI_PRESS\", ai_press;\n"
         "        CONNECT irq WITH OnHigh;\n"
         "        ISignalAI ai_press, AIO_ABOVE_HIGH, {limit}, 0, 0, irq;\n        WaitTime 1;\n"
         "    ENDPROC\n    TRAP OnHigh\n        hits := hits + 1;\n    ENDTRAP\nENDMODULE\n")


@pytest.mark.parametrize("limit, expected", [
    (5, []),
    (50, ["never reached under any input (routine OnHigh never runs)"])])
def test_an_isignalai_trap_is_unreached_only_when_no_value_of_the_domain_meets_it(
        tmp_path, limit, expected):
    """ISignalAI is modelled (ABB's aiotrigg rule): over {0, 10} the TRAP of an interrupt
    above 5 runs, and one above 50 never does, which the coverage warning says without
    blaming an unmodelled interrupt (review of session 5)."""
    path = tmp_path / "press.mod"
    path.write_text(PRESS.format(limit=limit))
    report = api.check(api.load_program([str(path)]), (),
                       api.CheckOptions(input_domains={"AI_PRESS": (0.0, 10.0)}))
    assert coverage(report) == expected


AFTER_RETURN = """    FUNC num Parsed()
        IF StrToVal(request, joints) THEN
            IF joints{1} + joints{2} = 1234 THEN
                RETURN 3;
            ENDIF
            RETURN 1;
            state := 2;
        ENDIF
        RETURN 0;
lost:
        RETURN -1;
    ENDFUNC"""


def test_code_after_a_return_is_unreached_under_any_input_beside_sampled_code(tmp_path):
    """A statement after RETURN in its own list runs under no input (unless a GOTO leads to
    a label before it: ``lost:`` is such a label, so what follows it keeps the wording of
    the inputs tried), while the arm that rests on a sum of parsed values no message tried
    gives names the receive."""
    report = check_server(tmp_path, "            state := Parsed();", extra=AFTER_RETURN)
    tried = "never reached with the socket messages tried (SocketReceive at line 14)"
    assert coverage(report) == [
        tried, "never reached under any input: the code after the RETURN at line 23", tried]


@pytest.mark.parametrize("condition, wording", [
    # cut by StrMatch: a PC may write "move ..." although no value tried starts so
    ('StrMatch(command, 1, "move") = 1', "never reached with the values written from "
     'outside tried (command at lines 7, 8, 10)'),
    # compared with constants only: the domain tells every branch apart, and the second
    # test of "a" is dead whatever a PC writes
    ('command = "a"', "never reached under any input")])
def test_code_unreached_with_data_written_from_outside_names_it_when_its_domain_is_a_sample(
        tmp_path, condition, wording):
    """A PC writes ``command`` (no loaded write ends the wait, ``awaited_from_outside``);
    its domain is the texts the code compares it with and one other.  Where the code
    does more with it than compare (StrMatch, StrPart, StrFind, StrToVal, arithmetic),
    that domain is a sample, so code it leaves unreached is not "under any input": the
    warning names the data's reads."""
    path = tmp_path / "pc.mod"
    path.write_text(f"""MODULE Pc
    PERS string command := "";
    VAR num moved := 0;
    PROC main()
        command := "";
        moved := 0;
        WaitUntil command <> "";
        IF {condition} THEN
            moved := 1;
        ELSEIF command = "a" THEN
            moved := 2;
        ENDIF
    ENDPROC
ENDMODULE
""")
    assert coverage(api.check(api.load_program([str(path)])))[0] == wording


def test_sub_messages_at_run_time_starts_get_long_messages_and_pairs_as_probes(monkeypatch):
    """pac48's pattern (tests/check/socket_sub_messages): sub-messages read at an index
    each one moves on by its length.  Each header's message also comes followed by bytes 0
    for three sub-messages (the header alone stays: a real message too short); the probes
    put a second header where the index stands after the first sub-message, and reach the
    branch that needs both.  Without the probes that branch is reported, with the
    messages tried."""
    program = api.load_program([str(CHECK / "socket_sub_messages" / "prog.mod")])
    [domain] = message_domains(program)
    joint, force = "01 00 00 00", "02 00 00 00"
    assert {joint, force, joint + " 00" * 20, force + " 00" * 20} <= set(domain.messages)
    # joint (4-byte type, 8 bytes from 5) then force: its type at 13 (i = 5 + 8)
    assert joint + " 00" * 8 + " 02" + " 00" * 11 in domain.probes
    assert not set(domain.probes) & set(domain.messages)
    assert "'01' and 23 bytes 00" in domain.note().message
    assert coverage(api.check(program)) == []
    monkeypatch.setattr(api, "PROBE_TOTAL", 0)
    assert coverage(api.check(program)) == [
        "never reached with the socket messages tried (SocketReceive at line 24)"]


@pytest.mark.parametrize("write", ["FOR i FROM 1 TO 3 DO\n        ENDFOR",
                                   "i := 2 * i;", "i := i - 4;", "Bump i;",
                                   "UnpackRawBytes buffer, 1, i \\IntX:=DINT;"])
def test_an_index_written_otherwise_leaves_the_start_unknown(write):
    """Only a local index moved on by positive numbers gives run-time starts."""
    text = f"""MODULE M
    VAR rawbytes buffer;
    VAR num field;
    PROC Bump(VAR num n)
        n := 0;
    ENDPROC
    PROC Read()
        VAR num i := 1;
        i := i + 4;
        {write}
        UnpackRawBytes buffer, i + 2, field \\IntX:=DINT;
    ENDPROC
ENDMODULE
"""
    routine = next(r for r in parse_text(text, "m.mod")[0].routines if r.name.key == "READ")
    call = routine.body[-1]
    assert walked_starts(call.args[1].value, routine, None) is None
    plain = parse_text(text.replace(write, ""), "m.mod")[0]
    routine = next(r for r in plain.routines if r.name.key == "READ")
    assert walked_starts(routine.body[-1].args[1].value, routine, None) == (
        frozenset({3}), frozenset({7}), frozenset({11}))


def test_a_command_writing_what_anothers_condition_reads_is_probed_before_it(monkeypatch):
    """open_abb's buffer (tests/check/socket_command_sequence): command 30 adds a point,
    33 loops over the points added.  No one message reaches the loop's body; the pair of
    the two commands' probes, offered together, does (31 clears what 30's IF reads)."""
    program = api.load_program([str(CHECK / "socket_command_sequence" / "prog.mod")])
    [domain] = message_domains(program)
    pairs = [probe for probe in domain.probes if isinstance(probe, tuple)]
    assert ("30 1 1 1 1 #", "33 1 #") in pairs and ("31 1 #", "30 1 1 1 1 #") in pairs
    assert "'30 1 1 1 1 #' with '33 1 #'" not in domain.note().message   # (first 4 shown)
    assert coverage(api.check(program)) == []
    monkeypatch.setattr(message_domains_module, "MAX_SEQUENCES", 0)
    assert coverage(api.check(api.load_program(
        [str(CHECK / "socket_command_sequence" / "prog.mod")]))) == [
        "never reached with the socket messages tried (SocketReceive at line 62)"]


# ``word`` takes the message whole, a part of it at two places and a text built from it
# (an unknown view): a set of views whose order the string hash seed and None's address set
VIEWS = """            word := request;
            IF state = 1 word := StrPart(request, 1, 3);
            IF state = 2 word := request + "!";
            IF state = 3 word := StrPart(request, 4, 2);
            IF word = "GO" state := 1;
            IF word = "RUN" state := 2;
            IF word = "STOP" state := 3;"""

SHOW_DOMAINS = """import sys
from rapidmc.api import load_program
from rapidmc.load.message_domains import message_domains
print([d.messages for d in message_domains(load_program([sys.argv[1]]))])
"""


def test_the_messages_and_their_order_do_not_depend_on_the_run(tmp_path):
    """The cap keeps the first messages, so their order decides the domain: it must be the
    same in every process (it was not when a name held several views: session 20's
    SpGantry kept '10G10GT' in one run and '         10G10GT' in the next)."""
    program = tmp_path / "server.mod"
    program.write_text(SERVER.format(body=VIEWS, extra="").replace(
        'VAR string request := "";', 'VAR string request := "";\n    VAR string word := "";'))
    shown = set()
    for seed in range(1, 9):
        run = subprocess.run([sys.executable, "-c", SHOW_DOMAINS, str(program)],
                             capture_output=True, text=True, check=True,
                             env={**os.environ, "PYTHONHASHSEED": str(seed)})
        shown.add(run.stdout)
    assert len(shown) == 1, shown
    assert "'GO', '   GO'" in shown.pop()
