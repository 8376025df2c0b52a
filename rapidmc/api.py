"""rapidmc as a Python library: load a RAPID program, state properties, check, read results.

One check, stage by stage (``rapidmc check`` is exactly this, with its options
from the command line and its report printed by ``rapidmc.report``)::

    load      load_program(files, env)            -> Program      syntax, semantics, load
    model     prepare(program, properties, opts)  -> Model        automata, inputs, reduction plan
    search    check_model(model): the built-in    -> results      check (one search each; later
              checks, then every property                         ones walk the graph the first kept)
    findings  what the complete searches showed   -> warnings     unreached code, vacuity, fixed
                                                                   readings, assumed input domains
    report    CheckReport(results, warnings)      -> text, JSON, SARIF, JUnit, HTML (report/)

Each stage takes what the one before returns and nothing else; none calls back
into an earlier one.

Example (see docs/api.md)::

    from rapidmc import api

    program = api.load_program(["case_studies/sorter/sorter_b.mod"],
                               env=["case_studies/sorter/plant.mod"])
    report = api.check(program, api.read_properties("specs/sorter.ltl"))
    assert report.verdicts["P1"] == "HOLDS"
    trace = report.trace("P2")          # the counterexample, step by step

Input errors raise ``rapidmc.diagnostics.UserError`` carrying diagnostics.
"""
from __future__ import annotations

import contextlib
import functools
import os
from dataclasses import dataclass, field, replace
from types import SimpleNamespace
from typing import Callable, Iterable, Mapping, Optional, Sequence

from . import ast
from .check import HOLDS, UNKNOWN, VIOLATED, Progress, SearchResult, find_reachable
from .check import budget, native
from .check.budget import DEFAULT_MAX_STATES, time_check
from .check.distributed import Cluster
from .check.trace import Trace, build_trace
from .check.walks import random_walks
from .diagnostics import (AUTOMATON, DISTRIBUTED_SCOPE, EDGES_REPLAYED, ENVIRONMENT, EXIT_OK, EXIT_UNKNOWN, EXIT_VIOLATED,
                          TRACE_REPLAY, USAGE, Diagnostic, SourceCache,
                          error)
from .diagnostics.quoting import one_line, quoted
from .findings.assumptions import assumptions, for_verdict, stated_domains
from .findings.explored import ExploredFacts
from .findings.fixed_readings import fixed_readings
from .findings.start_positions import named_targets
from .findings.tried_inputs import (sampled_inputs, tests_axes, unset_digital_outputs,
                                    unwritten_pers_reads)
from .load.backup import link_options, resolve_program_files, with_interfaces
from .load.message_domains import (ANSWERS, FILE, PROBE_STATES, SOCKET, message_domains,
                                   site_key)
from .load.outside_data import observed_names, outside_data as find_outside_data
from .load.outside_outputs import outputs_set_by_both
from .load.outside_outputs import outside_outputs as find_outside_outputs
from .load.shared_data import pers_warnings
from .ltl import read_hoa, to_buchi
from .ltl.syntax import Not
from .model import reduction
from .model.fairness import TaskFairness, assumes_fairness, fair_or_plain_search
from .model.edge_inputs import edge_inputs, realizable, served_edges, shared_edges
from .semantics.resting_inputs import resting_inputs
from .model.inputs import free_input_domains, observed_inputs
from .model.robot_tracking import robot_untracked
from .model.waiting import waits_forever
from .model.properties import AtomCompiler, Property, check_unique, parse_property, read_property_file
from .model.rapid_system import RapidDescriber, RapidSystem, end_at_error, replay
from .report.results import PropertyResult
from .semantics.link import build
from .semantics.program import Program
from .semantics.step import CheckConfig, EnvironmentFault
from .syntax import load_program as _parse_files

__all__ = ["CheckOptions", "CheckReport", "Model", "check", "check_model", "flow_property",
           "load_program", "prepare",
           "property_from_text", "read_properties", "HOLDS", "VIOLATED", "UNKNOWN"]

BUILTIN_RUNTIME = "no_runtime_error"
BUILTIN_DEADLOCK = "no_deadlock"
# the states of the probe whose robot starts at the program's targets (_start_probe)
START_PROBE_STATES = 2000
# a coverage probe's bound grows with the check's own search up to this many PROBE_STATES
PROBE_GROWTH = 3.5
# a probe its bound stops walks at random (check.walks) this many steps per state of the
# bound, at most WALK_LIMIT steps in all (a walk's step costs about what a state of the
# breadth-first search costs; a program with several stopped probes pays for each)
WALK_STEPS = 5
WALK_LIMIT = 60_000
# the message probes of a check visit at most this many times a probe's bound in all
PROBE_TOTAL = 12
# who else writes shared PERS data in the shared data probe (a one-task program's coverage)
ANOTHER_TASK = "another task"


@dataclass(frozen=True)
class CheckOptions:
    """What ``rapidmc check`` takes as options besides files and properties."""

    tp_answers: tuple = (1.0, 2.0, 3.0)
    fk_answers: tuple = (1.0, 2.0, 3.0, 4.0, 5.0)
    input_domains: Mapping[str, tuple] = field(default_factory=dict)   # signal -> values
    # refuse (RMC502) a free AI/GI input with no exact default, instead of taking the
    # values the program singles out as a stated assumption (load.stated_domains)
    exact_input_domains: bool = False
    socket_messages: tuple = ()            # () keeps the default: one empty message
    socket_closures: bool = False
    socket_timeouts: bool = True
    file_lines: tuple = ()
    automata: Mapping[str, str] = field(default_factory=dict)   # property -> HOA file of ¬φ
    backend: Optional[str] = None          # LTL translator: "spot", "builtin", None = best
    max_states: Optional[int] = DEFAULT_MAX_STATES
    max_seconds: Optional[float] = None
    reductions: reduction.Reductions = reduction.ALL   # sliced data, dead data, merged steps
    storage: Optional[tuple] = None        # None: exact; --compact / --bitstate (never HOLDS)
    fairness: bool = True                  # weak fairness between tasks (several tasks only)
    # keep the robot's position in every state even where nothing but moves reads it
    # (model.robot_tracking; False: moves leave the robot where it is then)
    track_robot: bool = False
    # inputs that only interrupts watch keep their resting value in states, an edge may
    # come at any step (model.edge_inputs; False: their values are stored, exact)
    edge_inputs: bool = True
    # a step leaves those inputs and the ones at rest unchosen where it reads no signal and
    # no active interrupt watches them (semantics.unread_inputs; False: every step chooses
    # every stored input's value)
    inputs_where_read: bool = True
    # the property searches walk the state graph the run-time error search explored, when
    # that search was complete (False: each steps the program again; same answers)
    reuse_explored: bool = True
    # --workers / --ray / --swarm: the built-in checks' searches on a Ray cluster
    # (rapidmc.check.distributed, docs/distributed.md); None: in this process
    cluster: Optional[Cluster] = None


# --- loading -----------------------------------------------------------------------


def load_program(files: Sequence[str], env: Sequence[str] = (), *, entry: str = "main",
                 task: Optional[str] = None, all_tasks: bool = False,
                 add_tasks: Sequence[str] = (), eio: Optional[str] = None,
                 flows: bool = False, outside_data: bool = True,
                 outside_writes_anytime: bool = False,
                 properties: Sequence[Property] = (),
                 other_task_writes: Sequence[str] = (), stubs: bool = False) -> Program:
    """Parse and link a program: module files or a controller backup folder, as ``check`` takes.

    ``env``: environment model modules; ``task``/``all_tasks``: which tasks of a
    backup; ``add_tasks``: further tasks, each ``"a.mod,b.mod"``; ``eio``: an
    I/O configuration whose signals the program uses by name; ``flows``: keep taint
    marks in the state, for ``flow_property`` (findings.lint.marks); ``outside_data``:
    each read of PERS data no loaded code writes takes any value of its domain
    (load.outside_data), else it keeps its initial value (``--fixed-outside-data``), as
    it does when one of ``properties`` may name it (atoms read stored values);
    ``outside_writes_anytime``: such data changes between any two reads, also where a wait
    reads it (else only while a task waits for it, ``load.waited_data``);
    ``other_task_writes``: upper-case names of shared PERS data that a task not loaded
    may write too (the shared data probe, ``_shared_data_probe``); ``stubs``: each task's
    names that none of its modules declares are declared from their uses (``--stubs``).
    """
    files_given = list(files)
    files = resolve_program_files(SimpleNamespace(files=list(files), task=task, eio=eio,
                                                  all_tasks=all_tasks, add_task=list(add_tasks),
                                                  entry=entry, stubs=stubs))
    environment = _parse_files(list(env)) if env else None
    parsed, tasks = with_interfaces(_parse_files(files.modules), files)
    options = link_options(files)
    if other_task_writes:
        options["outside_writers"] = {**{key: ANOTHER_TASK for key in other_task_writes},
                                      **options["outside_writers"]}
    if outside_data:
        options["outside_data"] = find_outside_data
        options["outside_outputs"] = find_outside_outputs
        options["outputs_set_by_both"] = outputs_set_by_both
        options["observed_names"] = observed_names(properties)
        options["outside_writes_anytime"] = outside_writes_anytime
    if flows:
        from .findings.lint.marks import instrument as instrument_flows  # (only for --flows)
        marks = instrument_flows(parsed)
        parsed, options["flow_marks"] = marks.program, marks
    program = build(parsed, entry=files.main_entry if entry == "main" else entry,
                    environment=environment, tasks=tasks, options=options)
    program.load_notes = files.notes + pers_warnings(program, files)
    # what a worker of a distributed check loads to build the same system in its own process
    program.load_arguments = dict(
        files=[os.path.abspath(path) for path in files_given], env=[os.path.abspath(path) for path in env],
        entry=entry, task=task, all_tasks=all_tasks, add_tasks=[
            ",".join(os.path.abspath(path) for path in group.split(",")) for group in add_tasks],
        eio=os.path.abspath(eio) if eio is not None else None, flows=flows,
        outside_data=outside_data, outside_writes_anytime=outside_writes_anytime,
        properties=tuple(properties), stubs=stubs)
    return program


def flow_property(program: Program) -> Property:
    """The built-in property ``no_unchecked_input`` of a program loaded with ``flows``:
    no run takes input from a socket, file, FlexPendant or analog/group input to a
    motion, file path, late-bound call or output argument without a check that bounds it."""
    marks = program.options.get("flow_marks")
    if marks is None:
        raise ValueError("the program was not loaded with flows=True")
    SourceCache.remember("<flows>", marks.property_text)
    return parse_property(marks.property_text, "<flows>", 1)


def read_properties(*paths: str) -> list[Property]:
    """The properties of property files (``NAME: FORMULA`` per line)."""
    properties = [prop for path in paths for prop in read_property_file(path)]
    check_unique(properties)
    return properties


def property_from_text(text: str, number: int = 1) -> Property:
    """One property ``NAME: FORMULA``; diagnostics name it ``<formula-NUMBER>``."""
    name = f"<formula-{number}>"   # no space: diagnostics open with FILE:LINE:COL
    SourceCache.remember(name, text)
    return parse_property(text, name, 1)


# --- preparing the search -----------------------------------------------------------


@dataclass
class Model:
    """A program with its properties' automata: the transition system to search."""

    program: Program
    properties: list[Property]
    options: CheckOptions
    atoms: AtomCompiler
    jobs: list            # (property, automaton of its negation, valuation of its atoms)
    config: CheckConfig
    system: RapidSystem
    describer: RapidDescriber
    plan: reduction.Plan = reduction.NO_PLAN
    assumed: tuple = ()   # input_domains.Assumed: default domains of free AI/GI inputs
    messages: tuple = ()  # message_domains.MessageDomain: derived socket message domains


def prepare(program: Program, properties: Sequence[Property],
            options: CheckOptions = CheckOptions()) -> Model:
    """Translate the properties and set up the program's transition system."""
    properties = list(properties)
    check_unique(properties)
    if options.cluster is not None and options.reductions.partial_order:
        # its cycle proviso depends on the order states are expanded in, which a partitioned
        # search does not keep: the workers search unreduced (a note says so)
        options = replace(options, reductions=replace(options.reductions, partial_order=False))
    atoms = AtomCompiler(program)
    jobs = [_automaton(prop, atoms, options) for prop in properties]
    messages = _derived_domains(program, options)
    config, assumed = _check_config(program, atoms, options, messages)
    unknown = set(options.automata) - {p.name for p in properties}
    if unknown:
        raise error(USAGE, f"--automaton names no property: "
                    f"{', '.join(quoted(name) for name in sorted(unknown))}")
    plan = reduction.plan_reductions(
        program, config, [atom for _, buchi, _ in jobs for atom in buchi.atoms],
        [None if prop.name in options.automata else prop.formula for prop in properties],
        options.reductions)
    return Model(program, properties, options, atoms, jobs, config,
                 RapidSystem(program, config, plan), RapidDescriber(program, config), plan,
                 assumed, messages)


def _check_config(program: Program, atoms: AtomCompiler, options: CheckOptions,
                  messages: tuple) -> tuple:
    """The environment a check offers the program: the options' inputs and answers, the
    derived ``messages`` per reading site; and the default input domains assumed."""
    domains, assumed = free_input_domains(program, atoms, options.input_domains,
                                          options.exact_input_domains)
    facts = _input_facts(program, atoms)
    observed = None if facts.observed is None else set(facts.observed)
    config = CheckConfig(program, options.tp_answers, options.fk_answers, domains,
                         observed=observed)
    if options.edge_inputs:
        config.edge_inputs = dict(facts.edges)
        config.served_edges = facts.served_edges
        config.shared_edges = facts.shared_edges
        config.resting_inputs = resting_inputs(config, atoms)
        config.inputs_where_read = options.inputs_where_read
    config.time_check = time_check       # the running search's time limit, inside a step
    config.robot_untracked = not options.track_robot and facts.robot_untracked
    if options.socket_messages:
        config.socket_messages = tuple(options.socket_messages)
    for kind, name in DERIVED_DOMAINS.items():
        setattr(config, name, {site_key(d.site): d.messages for d in messages if d.kind == kind})
    config.socket_closures = options.socket_closures
    config.socket_timeouts = options.socket_timeouts
    if options.file_lines:
        config.file_lines = tuple(options.file_lines)
    return config, assumed


@dataclass(frozen=True)
class _InputFacts:
    """What the code's walks tell about the inputs and the robot, for ``_check_config``."""
    observed: Optional[frozenset]        # observed_inputs (None: every input)
    edges: dict                          # edge_inputs
    served_edges: tuple                  # edge_inputs.served_edges of those
    shared_edges: tuple                  # edge_inputs.shared_edges: served by several tasks
    robot_untracked: bool                # robot_tracking.robot_untracked


def _input_facts(program: Program, atoms: AtomCompiler) -> _InputFacts:
    """``_InputFacts`` of ``program`` against the atoms ``atoms`` has compiled, computed once
    per program, atoms and what those atoms read: a check's coverage probes build a config
    for each probe message (over a hundred in a socket server), and these walks of the whole
    program were a third of such a check's time."""
    key = (frozenset(atoms.observed), atoms.observes_signal_data, atoms.observes_robot,
           None if atoms.observed_data is None else frozenset(atoms.observed_data))
    memo = atoms.input_facts if atoms.program is program else {}
    facts = memo.get(key)
    if facts is None:
        observed = observed_inputs(program, atoms)
        edges = edge_inputs(program, atoms, observed)
        facts = _InputFacts(None if observed is None else frozenset(observed), edges,
                            served_edges(program, edges), shared_edges(program, edges),
                            robot_untracked(program, atoms))
        memo[key] = facts
    return facts


def _probe_bound(results: list) -> int:
    """The states a coverage probe may visit: ``PROBE_STATES``, or twice the states of the
    check's own search when that is larger (a probe adds choices to the same program, so a
    bound below the check's own states stops it before the code the check ran), at most
    ``PROBE_GROWTH`` times ``PROBE_STATES``."""
    explored = max((r.result.stats.model_states for r in results), default=0)
    return int(min(PROBE_STATES * PROBE_GROWTH, max(PROBE_STATES, 2 * explored)))


def _probed_lines(model: Model, bound: int) -> set:
    """The lines that searches offering one probe message at a site (each site's other
    messages as derived) run: each search is small where the derived messages together
    multiply the states (``MessageDomain.probes``).  A line one of them runs is reachable,
    complete or not, so its lines count even when ``_probe_bound`` stops it.  The probes
    visit at most ``PROBE_TOTAL`` times ``bound`` states in all: the rest are not tried
    (their lines keep the wording of the messages tried)."""
    lines: set = set()
    spent: list = []
    for domain in model.messages:
        for probe in domain.probes:
            if sum(spent) >= PROBE_TOTAL * bound:
                return lines
            offered = probe if isinstance(probe, tuple) else (probe,)   # (a pair: both)
            messages = tuple(replace(d, messages=offered) if d is domain else d
                             for d in model.messages)
            config, _ = _check_config(model.program, model.atoms, model.options, messages)
            lines |= _probe_search(model.program, model.atoms, config, bound, walks=False,
                                   spent=spent)[0]
    return lines


def _closure_probe(model: Model, bound: int, readings_free: bool = False) -> tuple:
    """The lines a search run with peers closing their sockets (``--socket-closures``:
    ERR_SOCK_CLOSED at any SocketReceive or SocketSend), the derived messages as in the
    check, and whether that search was complete.  Closures stay out of the verdicts (the
    issue's "closures stay as now"); a closing peer is a real input, so a line this search
    runs is reachable, complete or not, and when it is complete no unreached line waits for
    a closure any more.  A server's SocketBind may also find its port taken
    (ERR_SOCK_ADDR_INUSE: the previous run still holds it), for the handlers that
    catch it or pass it on.  Bounded by ``_probe_bound`` as the message probes are.
    ``readings_free``: the readings free as well (``_readings_probe``), for a handler only
    a closure reaches behind a wait for a reading (the Hanoi socket task connects only
    once an output no loaded code sets is 1)."""
    options = replace(model.options, socket_closures=True)
    config = _free_readings_config(model, model.program, model.atoms, options) \
        if readings_free else _check_config(model.program, model.atoms, options,
                                            model.messages)[0]
    config.socket_setup_failures = True      # a server's port may be taken as well
    return _probe_search(model.program, model.atoms, config, bound)


def _readings_probe(model: Model, bound: int) -> tuple:
    """The lines a search runs in which the controller's readings the check fixes read
    any value at each call (OpMode, RunMode, RobOS, IsSysId: ``probed_readings``) and each
    DOutput of an output no loaded code sets reads 0 or 1 (the controller, another task
    or the FlexPendant's I/O view sets it), and whether that search was complete.  Each
    value is one a real controller gives, so a line this search runs is reachable; the
    verdicts keep the fixed readings (RMC702 says so).  Bounded by ``_probe_bound``."""
    return _probe_search(model.program, model.atoms,
                         _free_readings_config(model, model.program, model.atoms), bound)


def _start_probe(model: Model) -> set:
    """The lines a search runs whose robot starts at home or at one of the targets the code
    names (``findings.start_positions``: a real robot starts anywhere, so each run is
    real), with the readings free as in ``_readings_probe`` and the inputs held (a cell
    whose signals stay put: no interrupt multiplies the steps): a start-up routine's
    branch for a robot found at a taught position.  Breadth-first only, at most
    ``START_PROBE_STATES``: such a branch comes early, and a bigger or walking probe would
    share its steps among the starts."""
    targets = named_targets(model.program)
    if not targets:
        return set()
    config = _free_readings_config(model, model.program, model.atoms).with_inputs_held()
    config.start_targets = targets
    return _probe_search(model.program, model.atoms, config, START_PROBE_STATES,
                         walks=False)[0]


def _free_readings_config(model: Model, program: Program, atoms: AtomCompiler,
                          options: Optional[CheckOptions] = None) -> CheckConfig:
    """The check's environment for ``program`` (with ``options``, else the model's) with
    the controller's readings and the outputs no loaded code sets free
    (``_readings_probe``)."""
    config, _ = _check_config(program, atoms, options or model.options, model.messages)
    config.free_readings = True
    config.axes_probed = tests_axes(program)
    config.lazy_inputs = {**config.lazy_inputs, **{
        signal.index: (signal.name, (0.0, 1.0)) for signal in unset_digital_outputs(program)}}
    return config


def _shared_data_probe(model: Model, bound: int) -> set:
    """The lines a search runs in which another task may write the shared PERS data that a
    program of one task reads in a condition (``tried_inputs.unwritten_pers_reads``): the
    program loaded again with that data written by a party left out, so that each wait and
    polling loop reading it may see any value of its domain (``load.outside_data``: the
    values the code compares it with, and one other), with the readings free as in
    ``_readings_probe`` (a task that waits for the operator's mode before it reads its
    mailbox needs both).  A task checked alone often is one
    half of a mailbox: the other task puts a command into ``SocketStr`` and waits for
    ``SocketStr = ""``; each such value is one another task can write, so a line this search
    runs is reachable, complete or not.  The verdicts keep the loaded code's writes only
    (the warning still names the data for what this probe did not reach: its domain is a
    sample, and only waits choose).  Needs a program from ``load_program``; bounded by
    ``_probe_bound``."""
    arguments = getattr(model.program, "load_arguments", None)
    keys = sorted({ref.name.key for ref in unwritten_pers_reads(model.program)})
    if arguments is None or not keys or not arguments.get("outside_data", True):
        return set()
    program = load_program(**arguments, other_task_writes=keys)
    atoms = AtomCompiler(program)
    executed, _ = _probe_search(program, atoms, _free_readings_config(model, program, atoms),
                                bound)
    # the program was loaded from absolute paths: name its lines as the checked program does
    named = {os.path.abspath(routine.ast.span.file): routine.ast.span.file
             for routine in model.program.routines if routine.ast is not None}
    return {(named.get(file, file), line) for file, line in executed}


def _probe_search(program: Program, atoms: AtomCompiler, config: CheckConfig,
                  bound: int, walks: bool = True, spent: Optional[list] = None) -> tuple:
    """The lines a coverage probe's search of ``program`` under ``config`` runs, and whether
    it was complete.  One the bound stops while inputs change at every step (an interrupt
    on each of four digital inputs multiplies each step by 16: breadth-first, the probe
    spends its bound on the first hundred steps of a long start-up routine) searches again
    with those inputs held (``CheckConfig.with_inputs_held``): each state of that search
    is reachable too, so its lines count; completeness stays the first search's.  Then,
    unless ``walks`` is False (the many small per-message probes), it walks the program
    at random, held and not (``_walked_lines``).  ``spent``: a list the states of each
    breadth-first search are appended to."""
    spent = spent if spent is not None else []
    watch = ExploredFacts(program, (), atoms)
    search = find_reachable(_probe_system(program, config), _never,
                            observe=watch, max_states=bound)
    spent.append(search.stats.model_states)
    executed = set(watch.statements.executed)
    complete = search.verdict == HOLDS
    if complete:
        return executed, complete
    configs = [config]
    if config.free_inputs:
        held = ExploredFacts(program, (), atoms)
        configs.insert(0, config.with_inputs_held())
        again = find_reachable(_probe_system(program, configs[0]),
                               _never, observe=held, max_states=bound)
        spent.append(again.stats.model_states)
        executed |= held.statements.executed
    steps = min(bound * WALK_STEPS, WALK_LIMIT) if walks else 0
    for walked in configs:
        executed |= _walked_lines(program, atoms, walked, steps // len(configs))
    return executed, complete


def _probe_system(program: Program, config: CheckConfig) -> RapidSystem:
    """The model of one breadth-first probe: it keeps no successors for a next search, as
    none comes (the whole joseballester check: its probes kept 0.9M states' successors,
    each interned once more, for nothing)."""
    system = RapidSystem(program, config, reduction.NO_PLAN)
    system.shared_limit = 0
    return system


def _walked_lines(program: Program, atoms: AtomCompiler, config: CheckConfig,
                  steps: int) -> set:
    """The lines random walks of ``steps`` steps in all run (``check.walks``): where a
    bounded breadth-first probe stops shallow, a walk goes as deep as it is long (a counter
    wrapping after 98 messages, a command branch behind a long start-up).  Every step
    is one of the program's under ``config``, so each line counts as reached."""
    watch = ExploredFacts(program, (), atoms)
    lines = watch.statements
    random_walks(RapidSystem(program, config, reduction.NO_PLAN), lines, steps,
                 _step_choices, lambda: len(lines.executed), enough=lambda: lines.saturated,
                 novel=lines.novel)
    return watch.statements.executed


def _step_choices(label) -> tuple:
    """The environment's choices a step's label names (input, reading or message name,
    value), for the walks' preferences; none for a stutter step."""
    return label[0] if isinstance(label, tuple) else ()


def _never(state) -> bool:
    return False


# message_domains kind -> the CheckConfig attribute holding its domains per reading site
DERIVED_DOMAINS = {SOCKET: "socket_domains", FILE: "file_domains", ANSWERS: "answer_domains"}


def _derived_domains(program: Program, options: CheckOptions) -> tuple:
    """The domains ``message_domains`` derives, for the inputs whose values no option gives
    (``--socket-messages``, ``--file-lines``, ``--tp-answers`` replace them all)."""
    given = {SOCKET: bool(options.socket_messages), FILE: bool(options.file_lines),
             ANSWERS: options.tp_answers != CheckOptions.tp_answers}
    return tuple(d for d in message_domains(program) if not given[d.kind])


def _automaton(prop: Property, atoms: AtomCompiler, options: CheckOptions):
    """The automaton of the property's negation and the valuation of its atoms."""
    path = options.automata.get(prop.name)
    if path is not None:
        try:
            with open(path, encoding="latin-1") as handle:
                buchi = read_hoa(handle.read(), path)
        except OSError as exc:
            raise error(AUTOMATON, f"cannot read automaton file '{path}': {exc.strerror}") from None
    else:
        buchi = to_buchi(Not(prop.formula), backend=options.backend)
    spans = {atom: _atom_span(prop, atom) for atom in buchi.atoms}
    return prop, buchi, atoms.valuation(buchi.atoms, spans)


def _atom_span(prop: Property, atom: str) -> ast.Span:
    """Where the atom is written in the property (its column within the line)."""
    line = SourceCache.line(prop.file, prop.line) or prop.text
    for written in (f'"{atom}"', atom):
        column = line.find(written)
        if column >= 0:
            return ast.Span(prop.file, prop.line, column + 1, prop.line,
                            column + 1 + len(written))
    return ast.Span(prop.file, prop.line, 1)


# --- checking -------------------------------------------------------------------------


@dataclass
class CheckReport:
    """The verdicts of one check, with counterexamples, vacuity and coverage warnings."""

    results: list[PropertyResult]
    warnings: list[Diagnostic]
    describer: RapidDescriber
    # (file, line) of the statements the complete search ran (None: not complete)
    executed: Optional[frozenset] = None
    # the inputs coverage rests on: "under any input" or "with the ... tried (...)"
    inputs_tried: str = "under any input"

    @property
    def verdicts(self) -> dict[str, str]:
        """Property name -> ``"HOLDS"``, ``"VIOLATED"`` or ``"UNKNOWN"``, in check order."""
        return {r.name: r.result.verdict for r in self.results}

    def result(self, name: str) -> PropertyResult:
        return next(r for r in self.results if r.name == name)

    def trace(self, name: str) -> Trace:
        """The counterexample of a violated property, as ``rapidmc check`` prints it."""
        checked = self.result(name)
        if checked.result.verdict != VIOLATED:
            raise ValueError(f"{name} is {checked.result.verdict}: it has no counterexample")
        return build_trace(checked.result, self.describer)

    def exit_code(self, fail_on_vacuous: bool = False) -> int:
        """0 all hold, 1 a violation (or a vacuous property when asked), 3 UNKNOWN."""
        verdicts = self.verdicts.values()
        if VIOLATED in verdicts or (fail_on_vacuous and any(r.vacuous for r in self.results)):
            return EXIT_VIOLATED
        return EXIT_UNKNOWN if UNKNOWN in verdicts else EXIT_OK


ProgressFactory = Callable[[], Optional[Progress]]


def check(program: Program, properties: Iterable[Property] = (),
          options: CheckOptions = CheckOptions(),
          progress: ProgressFactory = lambda: None) -> CheckReport:
    """The built-in checks, then every property, each by its own search."""
    return check_model(prepare(program, list(properties), options), progress)


def check_model(model: Model, progress: ProgressFactory = lambda: None) -> CheckReport:
    """``check`` on a prepared model; ``progress()`` gives each search its progress line."""
    cluster = model.options.cluster
    with environment_faults():
        with cluster.session() if cluster is not None else contextlib.nullcontext() as ray:
            searches = _Searches(model, progress, ray)
            results = searches.builtin_checks() + [searches.property(*job) for job in model.jobs]
        if not _edges_realizable(model, results):
            return _with_edges_stored(model, progress)
        bound = _probe_bound(results)
        if _probing(searches) and any(d.probes for d in model.messages):
            searches.facts.statements.executed |= _probed_lines(model, bound)
        if _probing(searches) and searches.facts.waits_for_closures():
            lines, complete = _closure_probe(model, bound)
            searches.facts.statements.executed |= lines
            searches.facts.closures_tried = complete
        if _probing(searches) and searches.facts.waits_for_readings():
            lines, complete = _readings_probe(model, bound)
            searches.facts.statements.executed |= lines
            searches.facts.readings_tried = complete
            if searches.facts.waits_for_closures():
                lines, complete = _closure_probe(model, bound, readings_free=True)
                searches.facts.statements.executed |= lines
                searches.facts.closures_tried |= complete
        if _probing(searches) and searches.facts.waits_for_start():
            searches.facts.statements.executed |= _start_probe(model)
        if _probing(searches) and searches.facts.waits_for_other_tasks():
            searches.facts.statements.executed |= _shared_data_probe(model, bound)
    executed = searches.facts.statements.executed
    executed |= {line for guard, line in model.plan.slicing.undecided_lines if guard in executed}
    resting_on = stated_domains(model.assumed) \
        + assumptions(model.program, model.config.robot_untracked,
                      model.plan.slicing.move_shaping, model.plan.slicing.sent_counters)
    results = [replace(r, assumes=for_verdict(resting_on, r.result, model.describer))
               for r in results]
    return CheckReport(results, _findings(model, results, searches.facts, searches.notes),
                       model.describer, searches.facts.executed(), searches.facts.inputs_tried())


def _edges_realizable(model: Model, results: list) -> bool:
    """Whether every counterexample of a model with edge inputs (``model.edge_inputs``) is a
    run of the exact model (no input watched for its rising edge rises in two steps in a
    row)."""
    edges = model.config.edge_inputs
    if not edges:
        return True
    names = {signal.name: signal.index for signal in model.program.signals}
    return all(realizable(r.result, edges, names, model.program, model.config.served_edges,
                          model.config.shared_edges)
               for r in results
               if r.result.verdict == VIOLATED)


def _with_edges_stored(model: Model, progress: ProgressFactory) -> CheckReport:
    """The check again with the values of the edge inputs stored (exact), and a note why:
    a counterexample of the check with edges at any step needed two in a row."""
    exact = prepare(model.program, model.properties, replace(model.options, edge_inputs=False))
    report = check_model(exact, progress)
    names = ", ".join(sorted(model.program.signals[index].name
                             for index in model.config.edge_inputs))
    report.warnings.insert(0, Diagnostic(
        EDGES_REPLAYED, f"a counterexample needed an edge of {names} in two steps in a row, "
                        "which a real input cannot give (it must go back in between): the "
                        "check ran again with their values stored", None, severity="note"))
    return report


def _probing(searches: "_Searches") -> bool:
    """Whether the coverage probes go on: the check's facts are complete and no interrupt
    asked to stop (its verdicts are reached: the report comes first).  Probes only add
    lines that run, so a warning left by a probe not run keeps its qualifier (``with the
    readings fixed``): it stays true of the inputs it names."""
    return searches.facts.complete and budget.stop_requested is None


@contextlib.contextmanager
def environment_faults():
    """An environment model that goes wrong in any search (a check's verdicts, its coverage
    probes, ``rapidmc graph``) is the user's modelling error, RMC503, never an internal
    error."""
    try:
        yield
    except EnvironmentFault as exc:
        raise error(ENVIRONMENT, f"environment model: {one_line(str(exc))}") from None


def _findings(model: Model, results: list[PropertyResult],
              facts: ExploredFacts, notes: Sequence[Diagnostic] = ()) -> list[Diagnostic]:
    """What the check assumed or saw besides verdicts, in source order after the load and
    domain notes."""
    return list(model.program.load_notes) + list(model.plan.notes) + list(notes) + [
        assumed.note() for assumed in model.assumed + model.messages] + sorted(
        fixed_readings(model.program) + facts.warnings()
        + _flow_sinks(model, results),
        key=lambda d: (d.span.file, d.span.line, d.span.column))


def _flow_sinks(model: Model, results) -> list[Diagnostic]:
    """``findings.lint.marks.flow_sinks`` of a check with ``--flows`` (the taint analysis is
    loaded only then)."""
    if model.program.options.get("flow_marks") is None:
        return []
    from .findings.lint.marks import flow_sinks
    return flow_sinks(model.program, results, model.describer)


class _Searches:
    """The searches of one check, sharing what the first complete one explored.

    The run-time error search comes first: when it is complete it has seen every
    reachable state, so it answers the deadlock check, feeds coverage and vacuity
    (``facts``), and keeps the state graph that the property searches walk.
    """

    def __init__(self, model: Model, progress: ProgressFactory, ray=None):
        options = model.options
        self.model, self.progress = model, progress
        self.bounds = dict(max_states=options.max_states, max_seconds=options.max_seconds,
                           storage=options.storage)
        exact = [site_key(d.site) for d in model.messages if d.exact]
        self.facts = ExploredFacts(model.program, [prop.formula for prop in model.properties],
                                   model.atoms, sampled_inputs(
                                       model.program, exact, options.socket_closures,
                                       frozenset().union(*(a.read_as for a in model.assumed))))
        # Coverage and vacuity watch the run-time error search (merged steps name every line
        # they run); --compact / --bitstate searches are never complete, so they watch nothing;
        # nor do distributed searches (their states are expanded in other processes).
        self.watching = (options.storage is None or not model.plan.merge_points) and ray is None
        self.graphs: list = []    # the whole state graph, kept by the first complete search
        self.keep = dict(explored=self.graphs.append,
                         valuations=[valuation for _, _, valuation in model.jobs]) \
            if options.reuse_explored and model.jobs and ray is None else {}
        self.reach = _reach_here if ray is None else \
            _DistributedReach(ray, options.cluster, system_recipe(model))
        self.notes: list[Diagnostic] = []
        if ray is not None:
            self.notes.append(_one_process_note(
                "a distributed search does not report unreached code (RMC701) or vacuity: "
                "its states are expanded in other processes"))
        if ray is not None and model.program.task_entries:
            self.notes.append(_one_process_note(
                "partial-order reduction is off on a Ray cluster (its cycle proviso depends on "
                "the order states are expanded in): the state counts are those of --no-por"))
        self.fairness = TaskFairness(model.system) if assumes_fairness(model) else None
        # LTL properties on the cluster too (OWCTY), unless the cluster is a swarm's or the
        # states are stored by hash (those searches stay in this process)
        self.cycles = _DistributedCycles(ray, options.cluster, model_recipe(model)) \
            if ray is not None and model.jobs and not options.cluster.swarm and \
            options.storage is None else None
        if ray is not None and model.jobs and self.cycles is None:
            self.notes.append(_one_process_note(
                "LTL properties are checked in one process: a swarm or a --compact / "
                "--bitstate search distributes the built-in checks only"))

    def builtin_checks(self) -> list[PropertyResult]:
        """No reachable uncaught run-time error; no state where the program waits forever."""
        system = self.model.system
        stuck = _StuckWatch(system, self.facts if self.watching else None)
        runtime = _builtin(self.reach, system, BUILTIN_RUNTIME,
                           "no reachable uncaught run-time error", "failed",
                           dict(self.bounds, **self.keep), self.progress(), stuck)
        if self.watching:
            self.facts.finish(system, runtime.result, progress=self.progress(), **self.bounds,
                              **self.keep)
        deadlock = _deadlock(self.reach, system, runtime.result, stuck, self.bounds,
                             self.progress)
        if self.reach is not _reach_here and deadlock.name == BUILTIN_DEADLOCK and \
                deadlock.formula == _TASK_WAITS:
            self.notes.append(_one_process_note(
                "the search for a task that waits forever (several tasks) ran in one process"))
        return [runtime, deadlock]

    def property(self, prop: Property, buchi, valuation) -> PropertyResult:
        """One LTL property: the product with its negation's automaton, empty or a lasso."""
        searches = dict(self.bounds, explored=self.graphs[0]) if self.graphs else self.bounds
        first = None
        if self.cycles is not None:
            first = self.cycles(self.model.system, prop, buchi, valuation, self.bounds,
                                self.progress())
            if self.fairness is not None and first.verdict == VIOLATED and \
                    self.fairness.unfair_tasks(first.cycle, first.closing_label):
                self.notes.append(_one_process_note(
                    f"the cycle the cluster found for {prop.name} starves a task: the search "
                    "for a cycle fair to every task (weak fairness) ran in one process"))
        result = fair_or_plain_search(self.model.system, buchi, valuation, self.fairness,
                                      self.progress(), searches, first)
        _replayed(self.model.system, result)
        _with_deepest(self.model.system, result)
        vacuous = self.facts.vacuous(prop.formula) if result.verdict == HOLDS else None
        return PropertyResult(prop.name, prop.text, result, vacuous,
                              self.fairness.names if self.fairness is not None else (),
                              pattern=prop.pattern, atom_tasks=self._atom_tasks(buchi.atoms),
                              vacuous_inputs=self.facts.vacuous_inputs() if vacuous else "")

    def _atom_tasks(self, atoms) -> tuple:
        """(atom, its tasks) per atom, on a controller of several tasks (else empty)."""
        compiler = self.model.atoms
        if not compiler.tasks.several:
            return ()
        return tuple((atom, compiler.tasks_read(atom)) for atom in atoms)


class _StuckWatch:
    """Sees the states a search expands (passing them on to ``then``): does one wait forever?

    It needs no labels itself (a ``reachability.StatesObserver``); ``then`` says whether
    the search must build them."""

    def __init__(self, system: RapidSystem, then: Optional[ExploredFacts] = None):
        self.stuck_at = system.stuck_at
        self.then = then
        self.seen = False

    @property
    def labels_wanted(self) -> bool:
        return self.then is not None and self.then.labels_wanted

    def __call__(self, state, successors) -> None:
        if self.then is not None:
            self.then(state, successors)
        if not self.seen and self.stuck_at(state, [after for _, after in successors]):
            self.seen = True

    def note_spans(self, spans) -> bool:
        """``ExploredFacts.note_spans`` of ``then``; whether labels are still wanted."""
        return self.then.note_spans(spans) if self.then is not None else False

    def packed_watch(self) -> tuple:
        """For a search in the compiled core (``reachability``), which looks for states
        where the program may be stuck itself (asking ``states`` about those): what
        ``then`` watches (``ExploredFacts.packed_watch``), else nothing."""
        return self.then.packed_watch() if self.then is not None else (None, None)

    def states(self, state, targets) -> None:
        if self.then is not None:
            self.then.states(state, targets)
        if not self.seen and self.stuck_at(state, targets):   # (the search's own list)
            self.seen = True


def _deadlock(reach, system: RapidSystem, runtime: SearchResult, stuck: _StuckWatch, bounds,
              progress: ProgressFactory) -> PropertyResult:
    """The deadlock check: answered by the run-time error search when that one was complete.

    A breadth-first search that ends HOLDS has expanded every reachable state
    (an exact store, no bound reached), and ``stuck`` looked at each: if none
    waits forever, neither would a second search find one.  Otherwise a search
    of its own finds the shortest path to such a state.
    """
    description = "no reachable state where the program waits forever"
    if runtime.verdict == HOLDS and bounds.get("storage") is None and not stuck.seen:
        answer = SearchResult(HOLDS, stats=replace(runtime.stats, seconds=0.0))
        found = PropertyResult(BUILTIN_DEADLOCK, description, answer)
    else:
        found = _stuck_state(reach, system, description, bounds, progress)
    if found.result.verdict == HOLDS and len(system.program.task_names) > 1:
        # several tasks: one may wait forever while the others go on (model.waiting)
        waiting = waits_forever(system, bounds, progress())
        _replayed(system, waiting)
        found = PropertyResult(BUILTIN_DEADLOCK, _TASK_WAITS, waiting)
    return found


def _stuck_state(reach, system: RapidSystem, description: str, bounds,
                 progress: ProgressFactory) -> PropertyResult:
    found = _builtin(reach, system, BUILTIN_DEADLOCK, description, "stuck", bounds, progress())
    if found.result.verdict == VIOLATED:
        found.result.reason = system.describe_waits(
            (found.result.cycle or found.result.prefix)[0 if found.result.cycle else -1].state)
    return found


def _builtin(reach, system: RapidSystem, name: str, description: str, predicate: str, bounds,
             progress: Optional[Progress], observe=None) -> PropertyResult:
    result = reach(system, predicate, bounds, progress, observe)
    if result.verdict == VIOLATED:
        end_at_error(system, result)
        _replayed(system, result)
    _with_deepest(system, result)
    return PropertyResult(name, description, result)


def _with_deepest(system: RapidSystem, result: SearchResult) -> None:
    """An UNKNOWN search's last state stored told as where each task stands (how far it
    came: ``SearchResult.deepest``), the state itself let go."""
    if result.frontier is not None:
        result.deepest, result.frontier = system.task_places(result.frontier), None


_TASK_WAITS = "no task waits forever"


def _reach_here(system: RapidSystem, predicate: str, bounds, progress: Optional[Progress],
                observe) -> SearchResult:
    """The reachability search of a built-in check, in this process (``predicate`` names
    the system's method that marks the bad states)."""
    return find_reachable(system, getattr(system, predicate), progress=progress,
                          observe=observe, **bounds)


def system_recipe(model: Model):
    """How a worker builds the model's system in its own process: load and prepare the same
    files with the same properties and options (a system is not shipped whole: what its
    step functions set up while loading belongs to the process that loaded it)."""
    return functools.partial(_rebuilt_system, model_recipe(model))


def model_recipe(model: Model):
    """``system_recipe``, for the whole prepared model (its properties' automata and
    valuations too: what a worker of a distributed LTL search needs)."""
    arguments = getattr(model.program, "load_arguments", None)
    if arguments is None:
        raise ValueError("a distributed check needs a program from api.load_program")
    automata = {name: os.path.abspath(path) for name, path in model.options.automata.items()}
    return functools.partial(_rebuilt_model, arguments, tuple(model.properties),
                             replace(model.options, cluster=None, automata=automata),
                             native.engine())


def _rebuilt_model(arguments: dict, properties: tuple, options: CheckOptions,
                   engine: str) -> Model:
    native.use_engine(engine)
    return prepare(load_program(**arguments), list(properties), options)


def _rebuilt_system(model_recipe) -> RapidSystem:
    from .check.distributed.partition import built_once   # (in a worker: shares the model)
    return built_once(model_recipe).system


class _DistributedReach:
    """``_reach_here`` on a Ray cluster (``rapidmc.check.distributed``): the stuck watch runs
    in the workers (``stuck_at``), and only what it saw comes back."""

    def __init__(self, ray, cluster: Cluster, recipe):
        self.ray, self.cluster, self.recipe = ray, cluster, recipe

    def __call__(self, system: RapidSystem, predicate: str, bounds,
                 progress: Optional[Progress], observe) -> SearchResult:
        from .check.distributed.search import reachable
        result, watched = reachable(
            self.ray, self.cluster, system, predicate,
            watch="stuck_at" if observe is not None else None,
            max_states=bounds.get("max_states"), max_seconds=bounds.get("max_seconds"),
            progress=progress, storage=bounds.get("storage"), rebuild=self.recipe)
        if watched:
            observe.seen = True
        return result


class _DistributedCycles:
    """One LTL property's search on a Ray cluster (``check.distributed.owcty``)."""

    def __init__(self, ray, cluster: Cluster, recipe):
        self.ray, self.cluster, self.recipe = ray, cluster, recipe

    def __call__(self, system: RapidSystem, prop: Property, buchi, valuation, bounds,
                 progress: Optional[Progress]) -> SearchResult:
        from .check.budget import SearchBudget
        from .check.distributed.owcty import partitioned_accepting_cycle
        max_states = bounds.get("max_states")
        budget = SearchBudget(DEFAULT_MAX_STATES if max_states is None else max_states,
                              bounds.get("max_seconds"), progress)
        result, _ = partitioned_accepting_cycle(
            self.ray, self.cluster.partitions(self.ray), system, buchi, valuation, prop.name,
            self.recipe, budget=budget)
        return result


def _one_process_note(message: str) -> Diagnostic:
    return Diagnostic(DISTRIBUTED_SCOPE, message, None, severity="note")


def _replayed(system: RapidSystem, result) -> None:
    if result.verdict != VIOLATED:
        return
    try:
        replay(system, result)
    except AssertionError as exc:
        raise RuntimeError(f"internal error: {exc} [{TRACE_REPLAY.code}]") from None
