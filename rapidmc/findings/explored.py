"""What a complete search of a program's states shows besides the verdicts.

``ExploredFacts`` watches a breadth-first search over the program's state
graph (it is the search's ``observe`` callback) and records the source
lines executed and which combinations of the properties' trigger atoms
occur.  Once a search has covered every reachable state (``complete``),
it answers two questions soundly:

* coverage: which statements no input sequence reaches (``warnings``);
* vacuity: which trigger of a holding property is never true (``vacuous``).

Before that it answers nothing: a bounded search proves neither.
"""
from __future__ import annotations

from typing import Hashable, Iterable, Optional, Sequence

from ..check import HOLDS, VIOLATED, find_reachable
from ..check.result import SearchResult
from .vacuity import TriggerWatch, to_text
from .coverage import StatementWatch, coverage_warnings
from .tried_inputs import (PEERS_OPEN, PORT_FREE, START, UNWRITTEN, TriedInput,
                           called_routines, probed, qualifier, reached, varied)
from ..diagnostics import Diagnostic
from ..ltl import Formula
from ..model.properties import AtomCompiler
from ..semantics.program import Program


class ExploredFacts:
    """Observer of a breadth-first search; see the module docstring."""

    def __init__(self, program: Program, formulas: Iterable[Formula], atoms: AtomCompiler,
                 sampled: Sequence[TriedInput] = ()):
        """``sampled``: the reading instructions whose inputs were offered a sample only."""
        self.program = program
        self.sampled = tuple(sampled)
        self.statements = StatementWatch(program)
        self.triggers = TriggerWatch(formulas)
        # no trigger to watch: no atom to evaluate (evaluating costs a machine per state)
        self.valuation = atoms.valuation(self.triggers.atoms, {}) if self.triggers.atoms \
            else _no_atoms
        self.complete = False
        # a complete coverage probe let peers close their sockets: no unreached line rests
        # on "no peer closing its socket" (vacuity still does: the probe watches no trigger)
        self.closures_tried = False
        # a complete readings probe read OpMode, RobOS, ... and the outputs no loaded code
        # sets at every value: no unreached line rests on those (tried_inputs.probed)
        self.readings_tried = False

    def __call__(self, state: Hashable, successors: Sequence[tuple[Hashable, Hashable]]) -> None:
        self.statements(state, successors)
        self.triggers.seen.add(self.valuation(state))

    @property
    def labels_wanted(self) -> bool:
        """Whether the next state's labels may still tell something (a line not yet run);
        once not, the search hands over states only (``states``)."""
        return not self.statements.saturated

    def states(self, state: Hashable, targets: Sequence[Hashable]) -> None:
        """``__call__`` once every line has run: only the state's atoms remain to watch."""
        self.triggers.seen.add(self.valuation(state))

    def note_spans(self, spans) -> bool:
        """The lines of ``spans`` ran (named by a search without labels); whether the
        labels are still wanted."""
        self.statements.note_spans(spans)
        return self.labels_wanted

    def packed_watch(self) -> tuple:
        """For a search in the compiled core (``reachability``): the valuation whose bits
        ``states`` collects and the set it adds them to."""
        return self.valuation, self.triggers.seen

    def finish(self, system, search: SearchResult, **bounds) -> None:
        """Mark complete after ``search`` (a search this watched) covered every state.

        A search that stopped at a run-time error is followed by one that looks
        for nothing and so covers every state unless a bound stops it; one that
        a bound stopped leaves the facts incomplete (the same bound would stop
        another).
        """
        if search.verdict == VIOLATED:
            self.watch(system, **bounds)
        else:
            self.complete = search.verdict == HOLDS

    def watch(self, system, **bounds) -> None:
        """Watch a search of ``system`` that looks for nothing; complete unless a bound stops it."""
        self.statements.clear()
        self.triggers.seen.clear()
        search = find_reachable(system, _nothing, observe=self, **bounds)
        self.complete = search.verdict == HOLDS

    def executed(self) -> Optional[frozenset]:
        """The (file, line) of every statement some reachable step runs; None unless the
        search was complete."""
        return frozenset(self.statements.executed) if self.complete else None

    def warnings(self) -> list[Diagnostic]:
        """Coverage warnings (RMC701); none unless the search was complete."""
        if not self.complete:
            return []
        sampled = [t for t in self.sampled
                   if not (self.closures_tried and t.kind in (PEERS_OPEN, PORT_FREE))
                   and not (self.readings_tried and probed(t))]
        inputs = qualifier(reached(sampled, self.statements.executed))
        called = called_routines(self.program)
        return coverage_warnings(self.program, self.statements.executed, inputs, called)

    def waits_for_closures(self) -> bool:
        """Whether some unreached-code warning would rest on no peer closing its socket (a
        SocketSend or SocketReceive that could raise ERR_SOCK_CLOSED into a handler ran) or
        on the server's port being free (a SocketBind ran)."""
        return any(t.kind in (PEERS_OPEN, PORT_FREE)
                   for t in reached(self.sampled, self.statements.executed))

    def waits_for_readings(self) -> bool:
        """Whether some unreached-code warning would rest on a reading the readings probe
        varies (``tried_inputs.varied``: OpMode, an output no loaded code sets, ...)."""
        return any(varied(t) for t in reached(self.sampled, self.statements.executed))

    def waits_for_start(self) -> bool:
        """Whether some unreached-code warning would rest on where the robot starts (a
        position read back for more than a move's target ran: ``tried_inputs.START``)."""
        return any(t.kind == START for t in reached(self.sampled, self.statements.executed)) \
            and bool(self.warnings())

    def waits_for_other_tasks(self) -> bool:
        """Whether some unreached-code warning would rest on no other task writing shared
        PERS data that a condition read (``tried_inputs.UNWRITTEN``)."""
        return any(t.kind == UNWRITTEN for t in reached(self.sampled, self.statements.executed)) \
            and bool(self.warnings())

    def inputs_tried(self) -> str:
        """``under any input``, or which sampled inputs the search's findings rest on
        (those whose reading instruction ran)."""
        return qualifier(reached(self.sampled, self.statements.executed))

    def vacuous(self, formula: Formula) -> Optional[str]:
        """The text of a trigger of ``formula`` that is never true, or None (or incomplete)."""
        if not self.complete:
            return None
        trigger = self.triggers.never_true(formula)
        return to_text(trigger) if trigger is not None else None

    def vacuous_inputs(self) -> str:
        """What a vacuity note rests on: "" when every input's values were tried, else
        ``with the socket messages tried (...)``."""
        inputs = self.inputs_tried()
        return "" if inputs == qualifier(()) else inputs


def _no_atoms(state: Hashable) -> int:
    return 0


_no_atoms.fused_atoms = []      # (no atom for the compiled core to evaluate either)


def _nothing(state: Hashable) -> bool:
    return False
