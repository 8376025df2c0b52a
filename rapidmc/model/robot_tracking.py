"""Whether a check keeps the robot's position in its states.

A move puts the robot somewhere; the check needs to know where only if
something reads it back and behaves differently for it.  Real programs read
the position mostly to move relative to it (``pos := CRobT();
pos.trans.z := pos.trans.z - 250; MoveL pos, ...``): then every cycle leaves
the robot somewhere new, and a program whose behaviour repeats after a few
hundred states never ends (a public backup's joints turned 90 degrees a
cycle: UNKNOWN at 300,000 states).

``load.input_flow.InputFlow.robot_unobserved`` proves that nothing but moves
reads the position: no property's atom reads a robot (``AtomCompiler
.observes_robot``), and each read in the code (``CRobT``, ``CPos``,
``CJointT``, ``CTool``, ``CWObj``) only shapes moves' targets, directly, as
an ``Offs`` argument, or through ``+ - *`` and task ``VAR`` data that no atom
reads and whose every read does the same; ``CalcJointT``, ``GetSysData``, a
read in a condition, an index or anything else keeps the position.  Then
two runs that differ only in where the robot is and in such data take the
same statements with the same choices, fail at the same steps and give every
atom the same values, so moves may leave the robot where it is
(``semantics.robots.robot_tracked``) without changing any verdict.
Arithmetic on those values cannot fail: the flow admits a ``+ - *`` only
where its result stays within num's range for any num a reading can give
(``input_flow._inert_result``: a sum with a term under 2**102 rounds to the
largest num; a product's factors are bounded), so no ERR_NUM_LIMIT (which
``values.to_num`` raises) is lost with them.

The counterexamples of such a check show the robot at its start position and
positions read back as that; ``findings.assumptions`` says so under
``assumes:``, and ``--track-robot`` keeps the position in every state.
"""
from __future__ import annotations

from ..load.input_flow import InputFlow
from ..semantics.program import Program
from .properties import AtomCompiler


def robot_untracked(program: Program, atoms: AtomCompiler) -> bool:
    """Whether nothing but moves reads the robot's position in ``program`` checked against
    the atoms ``atoms`` compiled (it must have compiled every property's atoms)."""
    if not program.motion_tasks:
        return False                 # no task moves a robot: nothing to leave out
    observed = None if atoms.observed_data is None else frozenset(atoms.observed_data)
    routines = [routine for routine in program.routines if routine.ast is not None]
    return InputFlow(routines, observed, atoms.observes_robot,
                     tuple(program.globals)).robot_unobserved()
