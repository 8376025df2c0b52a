r"""Whole controllers as cells are made: multi-task backups with big buffers (issue 27).

Usage: python bench/controllers.py [--sizes 512] [--motion 2] [--loggers 1] [--kinds 3]
                                   [--engines native,python] [--max-seconds 60] [--max-states N]
                                   [--no-por]
                                   [--no-counters] [--no-sorter] [--keep DIR] [--profile]

The family: a RobotWare backup (BACKINFO/backinfo.txt, SYSPAR/SYS.cfg and EIO.cfg,
RAPID/TASKn/PROGMOD and SYSMOD) of 2-4 tasks, written as real cells are:

* ``--motion`` motion tasks (1 or 2), each serving commands from a socket: it keeps buffers of
  N robtargets, speeddata and jointtargets (``--sizes``), a write slot and a read slot;
  "store" teaches the next slot (the taught position depends on the slot, so the buffers
  cycle through N fillings), "run" moves through the next stored position, "home" moves
  home and rewinds the read slot, further kinds ("speedK") retune the current slot's
  speed: ``--kinds`` commands in all (at least 3);
* ``--loggers`` tasks (0 to 2; the first a logger, the second a PLC handshake): the logger
  waits (at most a minute, then it reports that it is alive) for a PERS flag a motion task
  raises after each move and reports the move over a socket;
  the PLC task answers a start request on digital signals;
* PERS flags between the tasks and a WaitSyncTask barrier between the motion tasks at
  every "home".

N and the number of command kinds scale the state space (about 2N fillings x N read slots
per motion task).  Each model is checked in a fresh process with ``rapidmc check BACKUP``
(the built-in properties and one LTL property; ``--no-por``: without the partial-order
reduction), per engine: reachable states, CPU seconds, states per CPU second, bytes per
state (the process's maximum resident set size / states) and the share of steps the
native step machine took (a second, in-process run of the run-time error search, which
counts them; with several tasks, the single tasks' steps).  The same rows follow for the
counters (bench/native.py's family, N=8) and for case_studies/sorter.

A search that reaches ``--max-seconds`` ends UNKNOWN; its row says so (the states/s are
then those of the truncated search).  ``--keep DIR`` writes the backups there;
``--profile`` prints the top of a cProfile of one native check per model instead.

Measured on 2026-11-28 (a shared 2-core machine; CPU seconds, so load matters little;
N=512, 2 motion tasks + logger, 3 kinds, 40 s per search, every search ends UNKNOWN):
before the tree-compressed table, native 47 states/s and 10,721 bytes/state (walking the
stored components for the memory statistic took most of the time), Python 143 and
16,769; after, native 929 and 7,030, Python 517 and 9,296.  The step machine takes none
of these steps (several tasks).  N=2 with 2 motion tasks completes: 23,916 states with
both engines, every property HOLDS.  Counters N=8 native: 377,626 states/s and 137 bytes
before, 336,168 and 136 after (within the noise of the shared machine).

Later the same day (issue 31: each motion task keeps its own robot position), N=2 with 2
motion tasks and the logger (the default ``--loggers 1``), native, 420 s per search:
391,951 states, 76 CPU seconds, no_deadlock VIOLATED, the other two HOLD; with one TCP for
the whole controller, 355,639 states and the same verdicts.  Neither figure is comparable
with the 23,916 above: that row was measured with ``--loggers 0`` (two tasks, "T=2"; the
commit it was measured at, 787c6fe, gives 23,916 again with ``--loggers 0`` and more than
30,000 states and the same VIOLATED with the logger; 87b13e6, before the robot per motion
task, 22,802; today 24,770, the second robot's position).  The logger multiplies the
states by about 14: its own position in its loop, the flags it clears and the
interleavings of its steps with the robots'.

The VIOLATED was the generated program's, at every commit since the family was written:
the logger waited for a flag with a plain ``WaitUntil``, and a flag comes only after the
PC sends "run"; in a run where the PC sends "store" for ever (the buffers full, nothing
taught) the robots go on and the logger waits for ever, which is what ``no_deadlock``
means with several tasks (docs/checking.md: "a flag no other task sets while a background
task loops").  The report said so: ``waits forever: T_LOG waits at .../Logger.mod:9
(WaitUntil log_request1;), while the other tasks go on``, with a loop of T_ROB1 receiving
"store".  A logger in a cell does not hang on its source, so the generator now gives its
``WaitUntil`` a ``\MaxTime`` with a ``\TimeFlag`` and an "alive" report: the family models
a correct cell and every property HOLDS (N=1, 1 motion task: 3,975 states).  N=2 with 2
motion tasks was not measured to the end with it (a 250 s search on the loaded machine did
not finish).

Measured on 2026-11-28 after the identity fast paths (one ``map`` pass over a tuple's
children, the projection's known-equal objects), under heavy load (load average 17-20 on
2 cores; CPU seconds still vary by 1.5x from run to run): N=512, 3 tasks, each search
bounded at 3,000 states (12,627 model states over the three searches, the same with both
engines), whole command: before 712 and 573 model states per CPU second, after 793 and
740 (native; Python engine 781); maximum RSS 62-64 MB either way.  The profiled split of
a native check (``costs`` row; a profile weighs calls heavily): steps about 11 %,
interning nodes about 36 %, the memory statistic 0.0 %; the largest single cost left is
the deep ``hash`` of whole states in the partial-order reduction's proviso (about 27 %).
Counters, ``bench/native.py --sizes 8,9``: N=8 search 0.48 + 0.18 CPU s (pan 8.29 s
wall under that load), whole check 371,557 states/s and 138 bytes/state; N=9 834,085 and
1,742,132 states/s in the two searches, whole check 534,095 states/s and 81 bytes/state.

Measured on 2026-11-28 at 23:00 (issue 27: the node table and the reduction's remembered
hashes in C, one node table for the searches of a check), each search bounded by states
(``--max-states 5000``: the same work on every run, which a wall-clock bound under load is
not), N=512, 3 tasks, 3 kinds, load average 24-29 on 2 cores, CPU seconds of the whole
command (about 0.9 s of it loading): 11,042 model states with both engines, before and
after.  Before (main at 002c842), two runs: native 5.78 and 4.92 s (1,909 and 2,243 model
states per CPU second), Python 6.33 and 5.13 s; after: native 3.04 and 2.34 s (3,628 and
4,714), Python 4.01 and 3.98 s (2,757 and 2,776).  The run-time error search alone,
in-process, 20,000 states: 4.01 s on main, 3.15 with the node table in C, 2.42 (best of 4,
against 3.20) with the hashes in C; the table counts 142-150 bytes per state there (the
RSS column above is the interpreter's at such small bounds).  The profiled split of a
native check (``costs`` row, same bound): steps 17.1 %, interning 48.9 % before; steps
43.7 %, interning 5.0 % after; the memory statistic 0.0 % in both.  The step machine takes
none of these steps (several tasks): the Python step is now the largest cost.

Measured on 2026-11-29 (issue 27 item 2: the packed table and the step machine for
several tasks, searches without the partial-order reduction, ``--no-por``; load 10-20 on
2 cores, CPU seconds).  The ``machine`` column now counts single tasks' steps when there
are several (a state's step is one per running task).  ``--max-states 5000 --no-por``
(13,109 model states, both engines alike): native 19.01 s (689 states/s: the packed
table hashed the 512-element arrays of every state Python stepped, and the machine took
no step) -> 2.75 s (4,770 states/s, machine 41 %); Python engine 3.61 s.  With
``--max-states 20000 --no-por`` (50,894): native 13.4-15.1 s, machine 40 %, Python 18.6 s.
The reduced search (the default) is unchanged: 10.7 s for 46,488 states at 20,000 per
search.  The in-process run-time error search, 20,000 states: 32.2 s -> 2.54 s unreduced
(88 bytes per state in the table), 4.62 s reduced, 6.25 s on the Python engine.  What the
machine leaves to Python (WaitSyncTask, WaitUntil, the call of ``teach`` and its writes of
array elements and record components, MoveJ, sockets) is now nearly all the time.

Measured on 2026-11-29 at 05:00 (the default reduced check; load 11-14 on 2 cores, CPU
seconds of the whole command, ``--max-states 5000``, 12,005 model states with both
engines before and after): the reduction's test whether the ample task can go on from
its successor asked every task's step there; it asks that task's alone now
(``PartialOrder._goes_on``): native 4.00, 3.64, 3.87 s -> 3.13, 3.13, 3.34 s (runs taken
alternately); Python engine 5.2-5.9 s either way.  The profiled split of the reduced
check: the Python step about a third, the reduction's choices about 15 % (keys, the local
runs, the go-on test), the rest the searches' own work; the machine takes no step there.
The reduction's proviso and the system's cache of successors now key states with one
``StateKeys`` (they key the very same states): 31,617 -> 24,055 hashes of the global data
in that check, 0.86 -> 0.50 profiled seconds in ``StateKeys.key`` (about 3 % of it).
Of the single tasks' steps the machine leaves to Python in ``--no-por`` (5,000 states),
WaitSyncTask is the largest share (3,618 of about 8,300), then the logger's WaitUntil
(846) and its socket set-up, the call of ``teach`` and its element writes.

Measured on 2026-11-29 at 07:50 (issue 27: WaitUntil, WaitSyncTask and the sockets'
set-up, connection and constant sends in the step machine as one task's step among
several; load 13-21 on 2 cores, CPU seconds, main and the branch run alternately).
The run-time error search alone, in-process, ``--no-por``, 20,000 states: 1.66-2.61 s
-> 0.86-1.31 s (15,000-23,000 states/s; 69 bytes per state in the table), the machine
taking 83 % of the single tasks' steps (22,804 of 57,399 before; 47,910 of 57,399
after).  The whole command ``--max-states 5000 --no-por`` (13,109 model states): native
3.22-3.85 s -> 2.22-2.68 s, machine 41 % -> 85 %; Python engine 4.39-5.00 s.  The default
reduced check (12,005 model states) is unchanged: native 2.55-3.59 s, Python 4.08 s,
the machine takes none of its steps (the reduced search keeps Python's collapsed
table).  What Python steps there now: the call of ``teach`` and its writes of array
elements and record components, MoveJ, the socket receive and accept.  Counters
(``bench/native.py --sizes 8,9``, three alternate runs): N=8 run-time error search
0.42-0.47 s (main 0.42-0.54), whole command 1.23-1.31 s CPU (main 1.23-1.53) at 141
bytes per state; N=9 2.36-2.84 s (main 2.17-2.54) at 81-82 bytes per state.

Measured on 2026-11-29 at 11:15 (issue 27: one packed table per check under the
partial-order reduction, the default; each search its own set of states, the machine
choosing ample sets, the proviso numbering states in the table, rows of reduced steps
kept for later searches; load 12-17 on 2 cores, CPU seconds, the base 7abe0dd and the
branch run alternately).  The default check, ``--max-states 20000`` (20,000 + 20,000 +
46,488 model states before, 46,825 for the property after: the numbering expands a few
more states fully), both engines' JSON reports identical: native 10.93 s -> 6.11-6.58 s
(7,500-7,900 model states per CPU second over the check's 86,825), Python engine 18.6 ->
21.2 s (it numbers the targets of each step too).  ``--max-states 5000`` (12,005 both):
1.98-2.28 s either way, start-up and loading dominate.  The reduced run-time error search
alone, in-process, 20,000 states: 3.37-3.65 -> 2.14-2.48 s (8,100-9,300 states/s), 216 ->
155 bytes per state in the table (its numbers and kept rows included); the machine takes
64 % of the single tasks' steps there (none before).  The rest are Python's: a state
where one task calls ``teach``, writes array elements or record components, moves or
receives is stepped whole in Python (its row kept all the same).  Counters N=8
(``bench/native.py``, three alternate runs): run-time error search 0.40-0.66 s before,
0.41-0.63 after; whole command 1.21-1.37 / 1.30-1.38 s at 141 bytes per state.

Measured on 2026-11-29 at 13:45 (issue 27: a reduced state stepped task by task, Python
taking only the tasks the machine does not, ``python_task_successors`` and
``python_task_ample``; one task's Python answers kept by the state's segments; rows kept
while the coverage watch wants lines; load 13-20 on 2 cores, CPU seconds, the base
ec2abec and the branch run alternately).  ``--max-states 20000`` (86,825 model states,
JSON reports identical to the base's and to the Python engine's): whole command 6.09,
8.07, 6.32 s -> 4.91, 4.53, 3.76 s (17,700-23,100 model states per CPU second); no state
is stepped whole in Python any more (18,873 in the property search and 7,084 in the
run-time error search before).  The run-time error search alone, in-process: 1.48-1.97
-> 0.97-1.06 s (18,900-20,600 states/s), the machine's share of the single tasks' steps
62 -> 81 %, 152 bytes per state in the table (unchanged).  The memory statistic: 3 calls
of ``memory_bytes``, 0.000 % of the profiled check.  Python's single-task steps take 74 %
of the check's CPU (in-process, timed around ``_task_step``): ``teach``'s call, its element
and component writes (each interns a new 512-element tuple, hashed whole: about 75 us),
MoveJ and SocketReceive.  The Python engine: 17.6-18.2 s either way.  Counters
(``bench/native.py --sizes 8,9``, two alternate runs each; before the array hashing below,
which the counters never reach): N=8 whole command 1.27-1.28 s
(base 1.30-1.42), 141 bytes per state; N=9 run-time error search 2.31-3.05 s (base
2.47-2.60), whole command 4.24-5.52 s (base 4.68-5.02), 83 bytes per state (base 84).
Then (13:55, load 12-16): arrays found by their items' hashes in the packed table
(``big_tuple_id``; ``value_ids`` took 1.41 of the 4.59 s of the in-process check, now
0.20): whole command 5.93, 6.39, 6.63 s on the base -> 2.87, 2.98, 3.03 s (28,700-30,200
model states per CPU second), the run-time error search alone 1.54-1.87 -> 0.67-0.69 s
(28,800-29,800 states/s), 152 bytes per state in the table; Python's single-task steps
are 65 % of the check (2.0 of 3.06 s).

Measured on 2026-11-29 at 16:10 (issue 27: SocketReceive \Str, moves where the robot's
position is left out and writes of array elements in the step machine as one task's
step among several; a routine without a fused block, the family's ``teach``, gets code
for them; load 13-15 on 2 cores, CPU seconds, main bc3fc6c and the branch run
alternately).  ``--max-states 20000`` (86,825 model states; the JSON reports of both
engines identical but for the engine's name, as on main): whole command 3.17, 2.58,
2.81 s -> 1.81, 1.65, 1.75 s (27,400-33,700 -> 47,900-52,700 model states per CPU
second); maximum RSS 63 -> 61-62 MB.  In-process, timed around each Python single-task
step (``_task_answer``): Python's single-task steps 20,659 -> 8,840, 58 % -> 33-40 % of
the check; the machine's share of the single tasks' steps in the run-time error search
81 -> 90 % (40,963 of 45,590).  What Python still steps: ``teach``'s call (with its
argument) and return, the write of a component of an element (``targets{slot}.trans.x``)
and the aggregate written to ``joints{slot}``, each 45-95 us.  The table's bytes per
state in the run-time error search alone (20,000 states): 152.4 -> 110.8 (a kept row's
count beside its offset; arrays grown by half, not doubled: 125.5 -> 133.0 at 16,000
states, 110.3 -> 112.1 at 30,000, the figure moves with where the bound falls between
two growths).  Counters (``bench/native.py --sizes 8,9 --engines native``, two alternate
runs): N=8 run-time error search 0.44, 0.70 s -> 0.46, 0.45 s, whole command 2.02, 1.37
-> 1.27, 1.31 s CPU, 142 -> 137 bytes per state; N=9 search 3.59, 2.73 -> 2.28, 2.73 s,
whole command 4.97, 5.41 -> 6.11, 4.45 s CPU, 83 -> 85 bytes per state.
Then (16:30, aggregates with a source, built by the machine; load 7-12): whole command
2.61, 3.61, 2.82, 3.07 s on main -> 1.65, 2.47, 1.61, 1.94 s (44,800-54,100 model states
per CPU second, one run of 35,200), the machine's share of the single tasks' steps in
the run-time error search 92 % (42,049 of 45,590).  Python's steps left: ``teach``'s
call and return and the component write, about a third of the in-process check.  (A
Python-engine row with fewer model states than the native one is its ``--max-seconds``
wall-clock limit under load: the Python engine needs 18 CPU s here.)

Measured on 2026-11-29 at 19:35 (issue 27: calls of procedures with IN arguments and
procedures' ends, and writes of a record component of an array element, in the step
machine; the deadlock search's stuck check in the packed loop; load 10-11 on 2 cores, CPU
seconds, main a6b2411 and the branch run alternately).  ``--max-states 20000 --engines
native`` (86,825 model states over the check; 46,825 in the property search, the row's
figure), whole command: 1.25, 1.30, 1.32 s on main -> 0.83, 0.84, 0.83 s (65,800-69,500
-> 103,400-104,600 model states per CPU second; the row: 35,500-37,400 -> 55,800-56,800),
the machine's share of the single tasks' steps in the run-time error search 92 -> 100 %
(45,576 of 45,590: what is left is the socket's accept).  The JSON reports of both
engines are the same but for the engine's name.  In-process: the run-time error search
alone (20,000 states) 0.254 -> 0.062 s, 110.8 bytes per state in the table either way,
``memory_bytes`` under 0.1 ms; the run-time error and deadlock searches together 0.17 s
before the native stuck check (calls already in the machine), 0.06 s after; the whole
``cli.main`` about 0.33 s, of which loading the backup is 0.11.  Of the
whole command's 0.83 s, importing rapidmc takes about 0.45 s (many modules, none large)
and is now the largest share; the property search's per-state Python calls
(``Product.successor_keys`` through ``ModelStore.successor_ids``) are the largest part of
the searches left.  Counters, run-time error search in-process, N=9, four alternate runs:
1.84, 1.78, 1.88, 1.90 s on main, 1.81, 1.71, 2.01, 1.74 s on the branch.

Measured on 2026-11-29 at 22:30 (issue 27: the machine's local runs go on through its
calls and returns; the property search steps the machine in C; Python's answers for a
call's or a return's context kept; an element write of a big array hashed in one step
and its tuple untracked; load 8-10 on 2 cores, CPU seconds, main 5412ce9 in a clone of
its own and the branch run alternately, three rounds).  ``--engines native --max-states
20000 --no-counters --no-sorter --no-costs``, the row (48,040 model states in the
property search): with the modules' bytecode cached, as an installed package has it,
0.77-0.81 s on main -> 0.35-0.36 s (59,600-62,100 -> 133,100-137,600 states/s); in this
environment, whose ``PYTHONDONTWRITEBYTECODE=1`` and editable install make every start
compile rapidmc's 211 modules (about 1.9 MB of source, 0.55 s) again, 1.35-1.43 ->
0.92-0.93 s (33,600-35,600 -> 51,500-52,400).  The machine takes 100 % of the single
tasks' steps of the run-time error search (98 % on main: a run through ``teach``'s call
was Python's).  Split of the in-process check (bytecode cached): loading 0.07-0.08 s,
run-time error search 0.05 -> 0.035 s, deadlock search 0.006 s, property search 0.13 ->
0.058 s; what is left is start-up (importing rapidmc, about 0.17 s) and loading.  Both
engines give the same verdicts and counts (N=8: 32,763 states; N=512: 48,040); the
memory statistic 0.0 % of the profiled check; 146 bytes per state in the table for the
run-time error search (141 on main).  Counters (``bench/native.py --sizes 8,9 --engines
native``, alternate runs): N=9 run-time error search 2.06, 2.23, 2.27 s on main, 2.04,
2.30, 2.20 s on the branch, whole command 3.49-4.07 / 3.74-4.07 s, 88 / 82-89 bytes per
state; the property search that steps the program itself 8.0 -> 3.5 s (N=8: 1.5 -> 0.6).
"""
from __future__ import annotations

import argparse
import contextlib
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

from check import counters_formula, counters_program  # noqa: E402  (bench/check.py)

MESSAGES = ("store", "run", "home")
HEADER = (f"{'model':24} {'engine':7} {'states':>9} {'cpu s':>7} {'states/s':>10} "
          f"{'B/state':>8} {'machine':>8}  verdicts")


# ------------------------------------------------------------------ the family
def robtarget(x: float, y: float, z: float) -> str:
    return f"[[{x:g},{y:g},{z:g}],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]]"


def motion_module(index: int, size: int, kinds: int, motion: int, logger: bool) -> str:
    """The module of motion task ``index`` (1-based).  Task 1 serves a socket and hands
    each command on to the other motion task (a PERS string and a WaitSyncTask barrier),
    as a MultiMove cell's leading task does; both keep the same buffers and serialise
    their buffer runs by an interlock flag."""
    tunings = [f"speed{k}" for k in range(1, kinds - len(MESSAGES) + 1)]
    retune = "".join(f'      CASE "{name}":\n        speed := [{100 * k},500,5000,1000];\n'
                     for k, name in enumerate(tunings, 1))
    tasks = ", ".join(f'["T_ROB{i}"]' for i in range(1, motion + 1))
    barriers = motion > 1
    # every motion task's counters, seen by all (PERS data is shared by name)
    shared = "".join(f"  PERS num moves{i} := 0;\n" for i in range(1, motion + 1))
    if logger:
        shared += "".join(f"  PERS bool log_request{i} := FALSE;\n"
                          for i in range(1, motion + 1))
    if index == 1:
        serve = ("      SocketReceive client \\Str:=command;\n" +
                 ("      order := command;\n      WaitSyncTask sync_order, motion_tasks;\n"
                  if barriers else ""))
        connect = ("    SocketCreate server;\n    SocketBind server, \"192.168.125.1\", 1025;\n"
                   "    SocketListen server;\n    SocketAccept server, client;\n")
    else:
        serve = "      WaitSyncTask sync_order, motion_tasks;\n      command := order;\n"
        connect = ""
    done = "      WaitSyncTask sync_done, motion_tasks;\n" if barriers else ""
    report = (f"          WaitUntil NOT log_request{index};\n"
              f"          log_request{index} := TRUE;\n") if logger else ""
    return f"""MODULE Cell{index}
  ! buffers the cell's PC fills over the socket: taught positions, speeds and axes
  VAR robtarget targets{{{size}}};
  VAR speeddata speeds{{{size}}};
  VAR jointtarget joints{{{size}}};
  VAR num taught := 0;
  VAR speeddata speed := [100,500,5000,1000];
  VAR socketdev server;
  VAR socketdev client;
  VAR string command := "";
  VAR syncident sync_order;
  VAR syncident sync_done;
  PERS tasks motion_tasks{{{motion}}} := [{tasks}];
  PERS string order := "";
  PERS bool zone_busy := FALSE;
{shared}  CONST robtarget home := {robtarget(500, 0, 600)};

  PROC main()
{connect}    WHILE TRUE DO
{serve}      TEST command
      CASE "store":
        IF taught < {size} THEN
          taught := taught + 1;
          teach taught;
        ENDIF
      CASE "run":
        IF taught = {size} THEN
          WaitUntil NOT zone_busy;
          zone_busy := TRUE;
          FOR i FROM 1 TO {size} DO
            MoveJ targets{{i}}, speeds{{i}}, fine, tool0;
          ENDFOR
          zone_busy := FALSE;
          moves{index} := (moves{index} + 1) MOD 4;
{report}        ENDIF
      CASE "home":
        MoveJ home, speed, fine, tool0;
        taught := 0;
{retune}      ENDTEST
{done}    ENDWHILE
  ENDPROC

  PROC teach(num slot)
    targets{{slot}} := home;
    targets{{slot}}.trans.x := 400 + slot;
    speeds{{slot}} := speed;
    joints{{slot}} := [[slot,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  ENDPROC
ENDMODULE
"""


def logger_module(motion: int) -> str:
    """A task reporting each move over a socket (the flags the motion tasks raise).  It
    waits for a flag at most a minute and then reports that it is alive: a move comes only
    when the PC sends "run", which it may never do again, and a logger waiting for one
    without a time-out would wait for ever while the robots go on (``no_deadlock``)."""
    polls = "".join(f"""      IF log_request{i} THEN
        SocketSend log_socket \\Str:="moved {i}";
        log_request{i} := FALSE;
      ENDIF
""" for i in range(1, motion + 1))
    flags = "".join(f"  PERS bool log_request{i} := FALSE;\n" for i in range(1, motion + 1))
    return f"""MODULE Logger
{flags}  VAR socketdev log_socket;
  VAR bool idle := FALSE;

  PROC main()
    SocketCreate log_socket;
    SocketConnect log_socket, "192.168.125.10", 2000;
    WHILE TRUE DO
      WaitUntil {" OR ".join(f"log_request{i}" for i in range(1, motion + 1))} \\MaxTime:=60 \\TimeFlag:=idle;
      IF idle SocketSend log_socket \\Str:="alive";
{polls}    ENDWHILE
  ENDPROC
ENDMODULE
"""


def plc_module() -> str:
    """A PLC handshake: the PLC asks to start, the task answers busy, then ready."""
    return """MODULE Plc
  PERS num handshakes := 0;

  PROC main()
    WHILE TRUE DO
      WaitDI diStart, 1;
      SetDO doBusy, 1;
      handshakes := (handshakes + 1) MOD 4;
      WaitDI diStart, 0;
      SetDO doBusy, 0;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


SYSMOD = """MODULE CellData(SYSMODULE)
  ! cell constants as a system module holds them
  CONST num cell_id := 7;
ENDMODULE
"""

EIO = """EIO:CFG_1.0:6:1::
#
EIO_SIGNAL:
      -Name "diStart" -SignalType "DI" -Device "plc" -DeviceMap "0"
      -Name "doBusy" -SignalType "DO" -Device "plc" -DeviceMap "0"
"""


def write_backup(folder: Path, size: int, motion: int = 2, loggers: int = 1,
                 kinds: int = 3) -> list[str]:
    """Write the family's backup into ``folder``; the names of its tasks."""
    if not 1 <= motion <= 2 or not 0 <= loggers <= 2 or kinds < len(MESSAGES):
        raise ValueError("1-2 motion tasks, 0-2 logger/PLC tasks, at least 3 command kinds")
    tasks: list[tuple[str, str, str, str]] = []     # (name, options, module file, text)
    for index in range(1, motion + 1):
        tasks.append((f"T_ROB{index}", " -MotionTask", f"Cell{index}.mod",
                      motion_module(index, size, kinds, motion, loggers >= 1)))
    if loggers >= 1:
        tasks.append(("T_LOG", "", "Logger.mod", logger_module(motion)))
    if loggers >= 2:
        tasks.append(("T_PLC", "", "Plc.mod", plc_module()))
    info = [">>SYSTEM_ID:", "rapidmc bench cell (generated by bench/controllers.py)", ""]
    cab = ["SYS:CFG_1.0:6:0::", "#", "CAB_TASKS:", ""]
    for number, (name, options, file, text) in enumerate(tasks, 1):
        task = folder / "RAPID" / f"TASK{number}"
        (task / "PROGMOD").mkdir(parents=True)
        (task / "SYSMOD").mkdir()
        (task / "PROGMOD" / file).write_text(text)
        (task / "SYSMOD" / "CellData.sys").write_text(SYSMOD)
        info += [f">>TASK{number}: ({name},,)", ""]
        cab += [f'      -Name "{name}" -Type "NORMAL"{options}', ""]
    (folder / "BACKINFO").mkdir(parents=True)
    (folder / "BACKINFO" / "backinfo.txt").write_text("\n".join(info + [">>EOF:", ""]))
    (folder / "SYSPAR").mkdir()
    (folder / "SYSPAR" / "SYS.cfg").write_text("\n".join(cab))
    (folder / "SYSPAR" / "EIO.cfg").write_text(EIO)
    return [name for name, *_ in tasks]


def family_property(motion: int) -> str:
    """Each motion task's move counter stays in range (holds: the whole space is searched)."""
    return " & ".join(f'G "moves{i} < 4"' for i in range(1, motion + 1))


def family_arguments(kinds: int, reduced: bool = True) -> list[str]:
    messages = list(MESSAGES) + [f"speed{k}" for k in range(1, kinds - len(MESSAGES) + 1)]
    arguments = ["--no-socket-timeouts"] + ([] if reduced else ["--no-por"])
    for message in messages:
        arguments += ["--socket-messages", message]
    return arguments


# -------------------------------------------------------------- measuring
def run_measured(command: list[str]) -> tuple[int, float, int, str]:
    """(exit code, CPU s, max RSS bytes, stdout) of one child process."""
    with tempfile.TemporaryFile("w+") as out:
        child = subprocess.Popen(command, stdout=out, stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(child.pid, 0)
        out.seek(0)
        return (os.waitstatus_to_exitcode(status), usage.ru_utime + usage.ru_stime,
                usage.ru_maxrss * 1024, out.read())


def check_command(target: list[str], ltl: Path, engine: str, max_seconds: float,
                  max_states: int) -> list[str]:
    return [sys.executable, "-m", "rapidmc", "check", *target, "--ltl", str(ltl),
            "--engine", engine, "--format", "json", "--quiet", "--max-states", str(max_states),
            "--max-seconds", str(max_seconds)]


def machine_share(target: list[str], max_states: int) -> str:
    """The share of the run-time error search's steps the native step machine took (run
    in a child process: ``--child-share``)."""
    code, _, _, out = run_measured([sys.executable, __file__, "--child-share",
                                    json.dumps([target, max_states])])
    if code != 0:
        return "?"
    counts = json.loads(out)
    if counts is None:
        return "none"
    if counts.get("task_machine_steps", 0) + counts.get("task_python_steps", 0):
        # several tasks: the share of single tasks' steps (a state's step is one per task)
        machine, python = counts["task_machine_steps"], counts["task_python_steps"]
    else:
        machine, python = counts["machine_steps"], counts["python_steps"]
    return f"{100 * machine / max(machine + python, 1):.0f}%"


def child_share(target: list[str], max_states: int) -> None:
    from rapidmc.check import find_reachable, native, reachability
    from rapidmc.cli import build_parser
    from rapidmc.commands.check import prepare_model
    args = build_parser("check").parse_args(["check", *target, "--engine", "native"])
    model = prepare_model(args)
    native.use_engine("native")
    tables: list = []
    made = native.state_table

    def kept(*given, **named):          # (the search's table, even when it stops at a bound)
        tables.append(made(*given, **named))
        return tables[-1]
    reachability.state_table = kept
    find_reachable(model.system, model.system.failed, max_states=max_states, max_seconds=60.0)
    table = tables[0] if tables else None
    print(json.dumps(table.counts() if hasattr(table, "counts") else None))


# where a check's CPU time goes (a profile in CPU time, in a child process)
COSTS = {
    "steps": lambda file, name: (file.endswith("semantics/step.py") and name == "successors") or
    (file.endswith("semantics/fused_step.py") and name == "plain_successor_states") or
    (file.endswith("semantics/staged_step.py") and name == "task_transitions"),
    "intern": lambda file, name: file.endswith("check/nodes.py"),
    "memory statistic": lambda file, name: name in ("memory_bytes", "component_bytes",
                                                    "rows_bytes", "native_bytes"),
}


def outer_seconds(stats, matches) -> float:
    """CPU seconds spent in the functions ``matches(file, name)`` picks, each call counted
    once (calls from one picked function to another are inside the outer one)."""
    total = 0.0
    for (file, _, name), (_, _, _, _, callers) in stats.stats.items():
        if matches(file, name):
            total += sum(figures[3] for (caller_file, _, caller), figures in callers.items()
                         if not matches(caller_file, caller))
    return total


def child_costs(target: list[str], ltl: str, max_seconds: float, max_states: int) -> None:
    import cProfile
    import io
    import pstats
    from rapidmc import cli
    argv = ["check", *target, "--ltl", ltl, "--engine", "native", "--quiet", "--format", "json",
            "--max-states", str(max_states), "--max-seconds", str(max_seconds)]
    profiler = cProfile.Profile(time.process_time)
    with contextlib.redirect_stdout(io.StringIO()):
        try:
            profiler.runcall(cli.main, argv)
        except SystemExit:
            pass
    stats = pstats.Stats(profiler)
    print(json.dumps({"total": stats.total_tt, **{name: outer_seconds(stats, matches)
                                                   for name, matches in COSTS.items()}}))


def costs(target: list[str], ltl: Path, max_seconds: float, max_states: int) -> str:
    """The shares of a native check's CPU time (profiled, so calls weigh more than they
    do unprofiled) in the steps, in interning nodes and in the memory statistic."""
    code, _, _, out = run_measured([sys.executable, __file__, "--child-costs",
                                    json.dumps([target, str(ltl), max_seconds, max_states])])
    if code != 0:
        return "costs: ?"
    found = json.loads(out)
    total = max(found.pop("total"), 1e-9)
    return "costs (profiled, share of CPU): " + ", ".join(
        f"{name} {100 * seconds / total:.1f}%" for name, seconds in found.items())


def row(model: str, target: list[str], ltl: Path, engine: str, max_seconds: float,
        max_states: int, share: bool) -> str:
    code, cpu, rss, out = run_measured(check_command(target, ltl, engine, max_seconds,
                                                     max_states))
    try:
        found = json.loads(out)
        found["properties"][0]
    except (ValueError, KeyError, IndexError):
        return f"{model:24} {engine:7} check exited {code} without a report"
    states = max(p["stats"]["model_states"] for p in found["properties"])
    verdicts = " ".join(f"{p['name']}={p['verdict']}" for p in found["properties"])
    machine = machine_share(target, max_states) if share and engine == "native" else ""
    return (f"{model:24} {engine:7} {states:>9,} {cpu:>7.2f} {states / max(cpu, 1e-9):>10,.0f} "
            f"{rss / max(states, 1):>8,.0f} {machine:>8}  {verdicts}")


def models(args, folder: Path):
    """(name, check arguments, property file) of each model the bench measures."""
    for size in (int(n) for n in args.sizes.split(",")):
        backup = folder / f"cell{size}"
        write_backup(backup, size, args.motion, args.loggers, args.kinds)
        ltl = folder / f"cell{size}.ltl"
        ltl.write_text(f"moves_in_range: {family_property(args.motion)}\n")
        name = f"cell N={size} T={args.motion + args.loggers} K={args.kinds}"
        if args.no_por:
            name += " no POR"
        yield name, [str(backup), *family_arguments(args.kinds, not args.no_por)], ltl
    if not args.no_counters:
        program = folder / "counters.mod"
        program.write_text(counters_program(8, 4))
        ltl = folder / "counters.ltl"
        ltl.write_text(f"bounded: {counters_formula(8, 4)}\n")
        yield "counters N=8", [str(program)], ltl
    if not args.no_sorter:
        sorter = ROOT / "case_studies" / "sorter"
        yield "sorter B + plant", [str(sorter / "sorter_b.mod"), "--env",
                                   str(sorter / "plant.mod")], ROOT / "specs" / "sorter.ltl"


def profile(target: list[str], ltl: Path, max_seconds: float, max_states: int) -> None:
    import cProfile
    import pstats
    from rapidmc import cli
    argv = ["check", *target, "--ltl", str(ltl), "--engine", "native", "--quiet",
            "--max-states", str(max_states), "--max-seconds", str(max_seconds)]
    profiler = cProfile.Profile(time.process_time)     # CPU time: the machine is shared
    started = time.process_time()
    try:
        profiler.runcall(cli.main, argv)
    except SystemExit:
        pass
    print(f"  ({time.process_time() - started:.1f} CPU s)")
    stats = pstats.Stats(profiler).sort_stats("tottime")
    stats.print_stats(14)
    stats.print_callers(4)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="512", help="buffer sizes N of the family")
    parser.add_argument("--motion", type=int, default=2, help="motion tasks (1-2)")
    parser.add_argument("--loggers", type=int, default=1, help="logger/PLC tasks (0-2)")
    parser.add_argument("--kinds", type=int, default=3, help="command kinds (3 or more)")
    parser.add_argument("--engines", default="native,python")
    parser.add_argument("--max-seconds", type=float, default=60.0)
    parser.add_argument("--max-states", type=int, default=10 ** 9,
                        help="bound each search by states (the same work on every run, "
                        "whatever the load; the wall-clock --max-seconds is not)")
    parser.add_argument("--no-por", action="store_true",
                        help="check the family without the partial-order reduction (the "
                        "packed table and the step machine serve only unreduced searches)")
    parser.add_argument("--no-counters", action="store_true")
    parser.add_argument("--no-sorter", action="store_true")
    parser.add_argument("--keep", help="write the backups into this folder")
    parser.add_argument("--profile", action="store_true")
    parser.add_argument("--no-costs", action="store_true",
                        help="skip the profiled run that splits a check's time")
    parser.add_argument("--child-share", help=argparse.SUPPRESS)
    parser.add_argument("--child-costs", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child_share:
        child_share(*json.loads(args.child_share))
        return
    if args.child_costs:
        child_costs(*json.loads(args.child_costs))
        return
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(args.keep) if args.keep else Path(scratch)
        folder.mkdir(parents=True, exist_ok=True)
        if not args.profile:
            print(HEADER, flush=True)
        for name, target, ltl in models(args, folder):
            if args.profile:
                print(f"== {name}", flush=True)
                profile(target, ltl, args.max_seconds, args.max_states)
                continue
            for engine in args.engines.split(","):
                print(row(name, target, ltl, engine, args.max_seconds, args.max_states,
                          share=True), flush=True)
            if not args.no_costs:
                print(f"{'':24} {costs(target, ltl, args.max_seconds, args.max_states)}",
                      flush=True)


if __name__ == "__main__":
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    main()
