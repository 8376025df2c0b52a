"""The RAPID type system: atomic, record, alias, semi-value and non-value types.

Types are interned ``RapidType`` values keyed by canonical name.  Aliases
resolve to their base type at lookup (RAPID: an alias is equal to its base),
but keep the alias name for printing.  Array types carry their dimensions.

Example::

    >>> PREDEFINED_TYPES["POS"].components[0].name
    'x'
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Optional

ATOMIC = "atomic"
RECORD = "record"
SEMI_VALUE = "semi-value"     # signals: readable as a value, not assignable
NON_VALUE = "non-value"       # clock, iodev, ...: only passed by reference
SWITCH_KIND = "switch"
ANY_KIND = "anytype"


@dataclass(frozen=True, slots=True)
class ComponentType:
    name: str            # as written in the definition
    key: str             # canonical
    type: "RapidType"


@dataclass(frozen=True, slots=True)
class RapidType:
    """A RAPID data type.  ``key`` is the canonical name of the base type."""

    key: str
    name: str
    kind: str
    components: tuple[ComponentType, ...] = ()
    value_type: Optional["RapidType"] = None     # semi-value: the type read from it
    signal_kind: str = ""                        # DI, DO, AI, AO, GI, GO for signal types

    def component_index(self, key: str) -> int:
        for i, component in enumerate(self.components):
            if component.key == key:
                return i
        return -1

    @property
    def is_value(self) -> bool:
        return self.kind in (ATOMIC, RECORD)

    def __str__(self) -> str:
        return self.name


@dataclass(frozen=True, slots=True)
class ArrayType:
    """An array of ``element`` with fixed ``dims`` (or ``None`` per ``*`` dimension)."""

    element: RapidType
    dims: tuple[Optional[int], ...]

    @property
    def rank(self) -> int:
        return len(self.dims)

    @property
    def key(self) -> str:
        return f"{self.element.key}{{{','.join('*' if d is None else str(d) for d in self.dims)}}}"

    def __str__(self) -> str:
        return f"{self.element.name} array{{{','.join('*' if d is None else str(d) for d in self.dims)}}}"


AnyType = RapidType | ArrayType

NUM = RapidType("NUM", "num", ATOMIC)
DNUM = RapidType("DNUM", "dnum", ATOMIC)
BOOL = RapidType("BOOL", "bool", ATOMIC)
STRING = RapidType("STRING", "string", ATOMIC)
SWITCH = RapidType("SWITCH", "switch", SWITCH_KIND)
ANYTYPE = RapidType("ANYTYPE", "anytype", ANY_KIND)


def _record(name: str, *components: tuple[str, RapidType]) -> RapidType:
    return RapidType(name.upper(), name, RECORD,
                     tuple(ComponentType(n, n.upper(), t) for n, t in components))


def _nums(*names: str) -> tuple[tuple[str, RapidType], ...]:
    return tuple((n, NUM) for n in names)


POS = _record("pos", *_nums("x", "y", "z"))
ORIENT = _record("orient", *_nums("q1", "q2", "q3", "q4"))
POSE = _record("pose", ("trans", POS), ("rot", ORIENT))
CONFDATA = _record("confdata", *_nums("cf1", "cf4", "cf6", "cfx"))
EXTJOINT = _record("extjoint", *_nums("eax_a", "eax_b", "eax_c", "eax_d", "eax_e", "eax_f"))
ROBJOINT = _record("robjoint", *_nums("rax_1", "rax_2", "rax_3", "rax_4", "rax_5", "rax_6"))
ROBTARGET = _record("robtarget", ("trans", POS), ("rot", ORIENT), ("robconf", CONFDATA),
                    ("extax", EXTJOINT))
JOINTTARGET = _record("jointtarget", ("robax", ROBJOINT), ("extax", EXTJOINT))
SPEEDDATA = _record("speeddata", *_nums("v_tcp", "v_ori", "v_leax", "v_reax"))
ZONEDATA = _record("zonedata", ("finep", BOOL), *_nums("pzone_tcp", "pzone_ori", "pzone_eax",
                                                       "zone_ori", "zone_leax", "zone_reax"))
LOADDATA = _record("loaddata", ("mass", NUM), ("cog", POS), ("aom", ORIENT),
                   *_nums("ix", "iy", "iz"))
TOOLDATA = _record("tooldata", ("robhold", BOOL), ("tframe", POSE), ("tload", LOADDATA))
WOBJDATA = _record("wobjdata", ("robhold", BOOL), ("ufprog", BOOL), ("ufmec", STRING),
                   ("uframe", POSE), ("oframe", POSE))
INPOSDATA = _record("inposdata", *_nums("position", "speed", "mintime", "maxtime"))
STOPPOINTDATA = _record("stoppointdata", ("type", NUM), ("progsynch", BOOL),
                        ("inpos", INPOSDATA), ("stoptime", NUM), ("followtime", NUM),
                        ("signal", STRING), ("relation", NUM), ("checkvalue", NUM))
TASKS = _record("tasks", ("taskname", STRING))
ERRSTR_RECORD = None


def _signal(name: str, kind: str) -> RapidType:
    return RapidType(name.upper(), name, SEMI_VALUE, value_type=NUM, signal_kind=kind)


SIGNAL_TYPES = {t.key: t for t in (
    _signal("signaldi", "DI"), _signal("signaldo", "DO"), _signal("signalai", "AI"),
    _signal("signalao", "AO"), _signal("signalgi", "GI"), _signal("signalgo", "GO"),
)}

NON_VALUE_NAMES = (
    "clock", "iodev", "dir", "socketdev", "rawbytes", "triggdata", "shapedata",
    "mecunit", "taskid", "syncident", "rmqslot",
    "intnum_obsolete", "restartdata", "corrdescr", "pathrecid", "jointtype",
    "egmident", "trapdata", "cameradev", "datapos", "itmsrc", "jointgroup",
    "speedlimdata", "rmqmessage", "loadsession",
)
NON_VALUE_TYPES = {n.upper(): RapidType(n.upper(), n, NON_VALUE) for n in NON_VALUE_NAMES}

NUM_ALIASES = (
    "byte", "dionum", "errnum", "intnum", "symnum", "opnum", "opcalc", "errdomain",
    "errtype", "event_type", "handler_type", "exec_level", "tpnum", "btnres",
    "icondata", "buttondata", "socketstatus", "identno", "stoppoint", "iounit_state",
    "listitem_num", "sensorstate", "num_limit", "triggmode", "paridnum", "loadidnum",
    "errstr_num", "opmode", "runmode",
    "inttypes", "egmstate", "egmstopmode", "egmframetype",
    "testsignal", "tunetype", "uishownum", "signalorigin", "aiotrigg",
    # reference coverage (issue 8, item 1): I/O bus states, configuration domains, motion
    # process modes, load identification results, conveyor commands
    "busstate", "cfgdomain", "motionprocessmode", "paridvalidnum", "cnvcmd", "tunegtype",
    "tsp_status",
    # SoftMove directions (css_soft_dir, css_offset_dir: named in a public SoftMove note, and
    # passed as num by a public program that calls CSSAct)
    "css_soft_dir", "css_offset_dir",
)
STRING_ALIASES = ("stringdig", "errstr")

PREDEFINED_TYPES: dict[str, RapidType] = {t.key: t for t in (
    NUM, DNUM, BOOL, STRING, SWITCH, ANYTYPE, POS, ORIENT, POSE, CONFDATA, EXTJOINT,
    ROBJOINT, ROBTARGET, JOINTTARGET, SPEEDDATA, ZONEDATA, LOADDATA, TOOLDATA, WOBJDATA,
    INPOSDATA, STOPPOINTDATA, TASKS,
)}
PREDEFINED_TYPES.update(SIGNAL_TYPES)
EGM_MINMAX = _record("egm_minmax", *_nums("min", "max"))
# FlexPendant list items, the sensor interface, RAPID Message Queues, Integrated Vision,
# program displacement, and the arc welding data of RobotWare Arc (components as in the
# manuals and in controller backups).
ARCDATA = _record("arcdata", *_nums("sched", "mode", "voltage", "wirefeed", "control", "current",
                                    "voltage2", "wirefeed2", "control2"))
OPTION_RECORDS = (
    EGM_MINMAX,
    _record("listitem", ("image", STRING), ("text", STRING)),
    _record("sensor", *_nums("id", "type", "state")),
    _record("rmqheader", ("datatype", STRING), *_nums("ndim", "dim1", "dim2", "dim3")),
    _record("cameratarget", ("name", STRING), ("cframe", POSE),
            *_nums("val1", "val2", "val3", "val4", "val5"), ("string1", STRING),
            ("string2", STRING), *_nums("type", "sceneid")),
    _record("progdisp", ("pdisp", POSE), ("eoffs", EXTJOINT)),
    # World zones: the manual's examples declare `PERS wzstationary equip1 := [0];` and
    # `VAR wztemporary service;`, and backups do the same: one num component, the zone's
    # identity (wz).
    _record("wztemporary", ("wz", NUM)),
    _record("wzstationary", ("wz", NUM)),
    # Production Manager's service-menu entries: a value record of eleven components, as
    # controller backups declare it (`TASK PERS menudata md := ["Move to Home", "",
    # "MovetoHome", 1, "", 255, TRUE, 1, 0, FALSE, 210];`). The first is the entry's text:
    # public code sets `md.description := TextGet(...)`. No text found names the others, so
    # they are c2 .. c11, with the types the backups' values show.
    _record("menudata", ("description", STRING), ("c2", STRING), ("c3", STRING), ("c4", NUM),
            ("c5", STRING), ("c6", NUM), ("c7", BOOL), ("c8", NUM), ("c9", NUM), ("c10", BOOL),
            ("c11", NUM)),
    ARCDATA,
    _record("welddata", *_nums("weld_speed", "org_weld_speed"), ("main_arc", ARCDATA),
            ("org_arc", ARCDATA)),
    _record("seamdata", *_nums("purge_time", "preflow_time"), ("ign_arc", ARCDATA),
            *_nums("ign_move_delay", "scrape_start", "heat_speed", "heat_time", "heat_distance"),
            ("heat_arc", ARCDATA), *_nums("cool_time", "fill_time"), ("fill_arc", ARCDATA),
            *_nums("bback_time", "rback_time"), ("rback_arc", ARCDATA), ("postflow_time", NUM)),
    _record("weavedata", *_nums("weave_shape", "weave_type", "weave_length", "weave_width",
                                "weave_height", "dwell_left", "dwell_center", "dwell_right",
                                "weave_dir", "weave_tilt", "weave_ori", "weave_bias",
                                "org_weave_width", "org_weave_height", "org_weave_bias")),
)
PREDEFINED_TYPES.update({t.key: t for t in OPTION_RECORDS})


def _trigg_io(name: str, set_value: RapidType) -> RapidType:
    return _record(name, ("used", BOOL), ("distance", NUM), ("start", BOOL), ("equiptime", NUM),
                   ("signalname", STRING), ("setvalue", set_value), ("xxx", NUM))


# Reference coverage (issue 8, item 1): the components of the motion settings (motsetdata,
# the type of the system data C_MOTSET, and its parts), the trigger tables of TriggLIOs and
# TriggJIOs, and the original positions of ORobT/CJointT-style data, as the manual lists them.
VELDATA = _record("veldata", *_nums("oride", "max"))
ACCDATA = _record("accdata", *_nums("acc", "ramp", "finepramp"))
SINGDATA = _record("singdata", ("wrist", BOOL), ("arm", BOOL), ("base", BOOL))
CONFSUPDATA = _record("confsupdata", ("jsup", BOOL), ("lsup", BOOL), *_nums("ax1", "ax4", "ax6"))
REFERENCE_RECORDS = (
    VELDATA, ACCDATA, SINGDATA, CONFSUPDATA,
    _record("motsetdata", ("vel", VELDATA), ("acc", ACCDATA), ("sing", SINGDATA),
            ("conf", CONFSUPDATA), ("pathresol", NUM), ("motionsup", BOOL), ("tunevalue", NUM),
            ("acclim", BOOL), ("accmax", NUM), ("decellim", BOOL), ("decelmax", NUM),
            ("cirpathreori", NUM), ("worldacclim", BOOL), ("worldaccmax", NUM),
            ("evtbufferact", BOOL), ("prefetchtime", NUM)),
    _trigg_io("triggios", NUM), _trigg_io("triggiosdnum", DNUM),
    _trigg_io("triggstrgo", STRING),
    RapidType("O_ROBTARGET", "o_robtarget", RECORD, ROBTARGET.components),
    RapidType("O_JOINTTARGET", "o_jointtarget", RECORD, JOINTTARGET.components),
)
# Reference coverage (issue 8, item 1): the process and supervision times of the Continuous
# Application Platform; components as the public re-implementation jasky1640/Tenon-IDE
# declares them (tenon/module/base.t, records processtimes and supervtimeouts, the types of
# capdata's components proc_times and sup_timeouts).
REFERENCE_RECORDS += (
    _record("proc_times", *_nums("pre", "post1", "post2")),
    _record("sup_timeouts", *_nums("pre_cond", "start_cond", "end_main_cond", "end_post1_cond",
                                   "end_post2_cond")),
)
PREDEFINED_TYPES.update({t.key: t for t in REFERENCE_RECORDS})
PREDEFINED_TYPES.update(NON_VALUE_TYPES)
PREDEFINED_ALIASES: dict[str, tuple[str, RapidType]] = {}
for _name in NUM_ALIASES:
    PREDEFINED_ALIASES[_name.upper()] = (_name, NUM)
for _name in STRING_ALIASES:
    PREDEFINED_ALIASES[_name.upper()] = (_name, STRING)


def is_numeric(t: Optional[AnyType]) -> bool:
    return t is NUM or t is DNUM


def same_type(a: Optional[AnyType], b: Optional[AnyType]) -> bool:
    """Type equality after alias resolution; ``None`` (unknown) is compatible with anything."""
    if a is None or b is None or a is ANYTYPE or b is ANYTYPE:
        return True
    if isinstance(a, ArrayType) or isinstance(b, ArrayType):
        if not (isinstance(a, ArrayType) and isinstance(b, ArrayType)):
            return False
        if a.rank != b.rank or not same_type(a.element, b.element):
            return False
        return all(x is None or y is None or x == y for x, y in zip(a.dims, b.dims))
    if a.key == b.key:
        return True
    # num and dnum mix implicitly (widening / narrowing on assignment)
    return is_numeric(a) and is_numeric(b)


# A clock's value (running, started at, accumulated seconds): declared clocks are stopped at 0.
STOPPED_CLOCK = (False, 0.0, 0.0)


def default_value(t: AnyType):
    """The value of an uninitialised VAR of type ``t`` (0, FALSE, "", component-wise; a
    stopped clock, also as the elements of a clock array)."""
    if isinstance(t, ArrayType):
        return _default_array(t.element, t.dims)
    if t.key == "CLOCK":
        return STOPPED_CLOCK
    if t.kind == RECORD:
        return tuple(default_value(c.type) for c in t.components)
    if t is BOOL:
        return False
    if t is STRING:
        return ""
    if t.kind == NON_VALUE:
        return None
    if t.kind == SEMI_VALUE:
        return -1                       # a signal data object not bound to any signal
    return 0.0


def _default_array(element: RapidType, dims: tuple) -> tuple:
    # (one default element, shared: values are immutable, and a 512-element array of
    # records is then built in one step, not element by element)
    item = default_value(element) if len(dims) == 1 else _default_array(element, dims[1:])
    return (item,) * (dims[0] or 0)


def element_type(t: AnyType) -> AnyType:
    return t.element if isinstance(t, ArrayType) else t
