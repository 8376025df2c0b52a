"""Signature parsing and the registry of predefined routines."""
from __future__ import annotations

import inspect

import pytest
from hypothesis import given, strategies as st

from rapidmc.semantics.library import all_entries, lookup_function, lookup_procedure
from rapidmc.semantics.library.registry import (
    FUNCTION, PROCEDURE, SignatureSyntaxError, parse_signature, register,
)

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

# (signature text, expected kind, return type,
#  [(name, type, mode, optional, group, rank), ...])
CASES = [
    ("num Round(num Val \\num Dec)", FUNCTION, "num",
     [("Val", "num", "IN", False, None, 0), ("Dec", "num", "IN", True, None, 0)]),
    ("Incr(INOUT anynum Name)", PROCEDURE, None, [("Name", "anynum", "INOUT", False, None, 0)]),
    ("P(num a, VAR num b, PERS tooldata t, INOUT num c, num arr{*}, num m{*,*})", PROCEDURE, None,
     [("a", "num", "IN", False, None, 0), ("b", "num", "VAR", False, None, 0),
      ("t", "tooldata", "PERS", False, None, 0), ("c", "num", "INOUT", False, None, 0),
      ("arr", "num", "IN", False, None, 1), ("m", "num", "IN", False, None, 2)]),
    ("P2(robtarget pt \\switch Fast | num Speed, \\num Timeout, \\VAR errnum Flag)", PROCEDURE, None,
     [("pt", "robtarget", "IN", False, None, 0), ("Fast", "switch", "IN", True, 1, 0),
      ("Speed", "num", "IN", True, 1, 0), ("Timeout", "num", "IN", True, None, 0),
      ("Flag", "errnum", "VAR", True, None, 0)]),
    ("SetGO(\\num SDelay, VAR signalgo Signal, num Value | dnum Dvalue)", PROCEDURE, None,
     [("SDelay", "num", "IN", True, None, 0), ("Signal", "signalgo", "VAR", False, None, 0),
      ("Value", "num", "IN", False, 1, 0), ("Dvalue", "dnum", "IN", False, 1, 0)]),
    ("num Dim(REF anytype ArrPar, num DimNo)", FUNCTION, "num",
     [("ArrPar", "anytype", "REF", False, None, 0), ("DimNo", "num", "IN", False, None, 0)]),
    ("symnum OpMode()", FUNCTION, "symnum", []),
    ("S(\\a x | b y \\c z | d w)", PROCEDURE, None,
     [("x", "a", "IN", True, 1, 0), ("y", "b", "IN", True, 1, 0),
      ("z", "c", "IN", True, 2, 0), ("w", "d", "IN", True, 2, 0)]),
]


@pytest.mark.parametrize("text, kind, return_type, parameters", CASES)
def test_parse_signature(text, kind, return_type, parameters):
    signature = parse_signature(text)
    assert signature.kind == kind and signature.return_type == return_type
    assert signature.key == signature.name.upper()
    assert [(p.name, p.type_name, p.mode, p.optional, p.alternative_group, p.array_rank)
            for p in signature.parameters] == parameters


@pytest.mark.parametrize("text", [
    "num Round(num Val", "Round num Val)", "P(switch Flag)", "P(num)", "P(num a) x", "P(num a; num b)",
])
def test_malformed_signatures_are_rejected(text):
    with pytest.raises(SignatureSyntaxError):
        parse_signature(text)


names = st.from_regex(r"[A-Za-z][A-Za-z0-9_]{0,8}", fullmatch=True).filter(
    lambda s: s.upper() not in ("VAR", "PERS", "INOUT", "REF", "SWITCH"))
parameters = st.tuples(st.sampled_from(["", "VAR ", "PERS ", "INOUT "]), names, names,
                       st.booleans(), st.integers(0, 3))


@given(names, st.lists(parameters, max_size=6))
def test_rendered_parameter_lists_parse_back(routine, specs):
    parts = []
    for mode, type_name, name, optional, rank in specs:
        dims = "{" + ",".join("*" * rank) + "}" if rank else ""
        parts.append(("\\" if optional else "") + f"{mode}{type_name} {name}{dims}")
    signature = parse_signature(f"{routine}({', '.join(parts)})")
    assert [(p.mode, p.type_name, p.name, p.optional, p.array_rank) for p in signature.parameters] == [
        ((mode.strip() or "IN"), type_name.lower(), name, optional, rank)
        for mode, type_name, name, optional, rank in specs]


def test_anynum_accepts_num_and_dnum_and_anytype_everything():
    spec = parse_signature("P(anynum a, anytype b, \\switch c)").parameters
    assert spec[0].accepted_types == ("num", "dnum")
    assert spec[1].accepted_types == ()
    assert spec[2].is_switch and not spec[2].by_reference


def test_registering_a_name_twice_is_a_bug():
    assert lookup_function("ABS") is not None      # loads the registry
    with pytest.raises(SignatureSyntaxError):
        register("num Abs(num Value)", abs)


def test_lookup_is_by_canonical_name_and_kind():
    assert lookup_function("ROUND").signature.name == "Round"
    assert lookup_function("Round") is None
    assert lookup_procedure("ROUND") is None
    assert lookup_procedure("INCR").signature.kind == PROCEDURE


def test_every_implementation_takes_one_argument_per_parameter():
    for entry in all_entries():
        if entry.special:
            assert entry.impl is None
            continue
        for impl in {entry.impl, entry.dnum_impl} - {None}:
            arity = len(inspect.signature(impl).parameters)
            assert arity == len(entry.signature.parameters), entry.signature.name


REQUIRED_PURE = """Abs AbsDnum Sqrt SqrtDnum Exp Pow PowDnum Round RoundDnum Trunc TruncDnum Sin SinDnum
Cos CosDnum Tan TanDnum ASin ASinDnum ACos ACosDnum ATan ATanDnum ATan2 ATan2Dnum BitAnd BitOr BitXOr
BitNeg BitLSh BitRSh BitCheck BitAndDnum BitOrDnum BitXOrDnum BitNegDnum BitLShDnum BitRShDnum
BitCheckDnum StrDigCalc StrDigCmp NumToDnum DnumToNum StrPart StrLen StrFind StrMatch StrMemb StrOrder
StrMap NumToStr DnumToStr StrToByte ByteToStr DecToHex HexToDec Offs RelTool OrientZYX EulerZYX NOrient
PoseMult PoseInv PoseVect VectMagn DotProd CrossProd Distance""".split()
REQUIRED_PURE_PROCEDURES = "Add Incr Decr Clear TryInt BitSet BitClear".split()
REQUIRED_SPECIAL_FUNCTIONS = """Present Dim ValToStr StrToVal CPos CRobT CJointT CTool CWObj DInput DOutput
TestDI ValidIO AOutput GOutput ClkRead OpMode RunMode RemainingRetries""".split()
REQUIRED_SPECIAL_PROCEDURES = """TPWrite TPReadNum TPReadFK TPReadDnum TPErase Set Reset SetDO SetAO SetGO
PulseDO InvertDO AliasIO AliasIOReset WaitTime WaitDI WaitDO WaitUntil MoveJ MoveL MoveC MoveAbsJ MoveJDO
MoveLDO MoveCDO MoveJSync MoveLSync MoveCSync ClkReset ClkStart ClkStop ISignalDI ISignalDO ITimer IDelete
ISleep IWatch IEnable IDisable Stop Break ExitCycle ErrWrite ConfJ ConfL AccSet VelSet SingArea BookErrNo
CallByVar ResetRetryCount TriggIO""".split()


@pytest.mark.parametrize("lookup, names, special", [
    (lookup_function, REQUIRED_PURE, False),
    (lookup_procedure, REQUIRED_PURE_PROCEDURES, False),
    (lookup_function, REQUIRED_SPECIAL_FUNCTIONS, True),
    (lookup_procedure, REQUIRED_SPECIAL_PROCEDURES, True),
])
def test_required_routines_are_registered(lookup, names, special):
    missing = [n for n in names if lookup(n.upper()) is None or lookup(n.upper()).special != special]
    assert missing == []


# Optional arguments real programs use; the static checker rejects calls that name others.
@pytest.mark.parametrize("routine, optional", [
    ("MOVEL", "Conc ID V T Z Inpos WObj Corr TLoad"),
    ("MOVEJ", "Conc ID V T Z Inpos WObj TLoad"),
    ("MOVEABSJ", "Conc ID NoEOffs V T Z Inpos WObj TLoad"),
    ("TPREADFK", "MaxTime DIBreak DOBreak PersBoolBreak BreakFlag"),
    ("TPWRITE", "Num Bool Pos Orient Dnum"),
    ("WAITDI", "MaxTime TimeFlag Visualize Header Message MsgArray Wrap Icon Image VisualizeTime UIActiveSignal"),
    ("WAITUNTIL", "InPos PollRate MaxTime TimeFlag Visualize Header Message MsgArray Wrap Icon Image VisualizeTime UIActiveSignal"),
    ("ISIGNALDI", "Single SingleSafe"),
])
def test_motion_and_io_optional_parameters(routine, optional):
    signature = lookup_procedure(routine).signature
    assert [p.name for p in signature.parameters if p.optional] == optional.split()


def test_mutually_exclusive_speed_overrides_share_a_group():
    params = {p.name: p for p in lookup_procedure("MOVEL").signature.parameters}
    assert params["V"].alternative_group == params["T"].alternative_group is not None
    assert params["Tool"].mode == "PERS" and not params["Tool"].optional


def test_numeric_routines_pick_the_dnum_variant_by_type():
    entry = lookup_procedure("INCR")
    assert entry.implementation("num")(16777216.0) == {"Name": 16777216.0}   # float32 cannot add 1
    assert entry.implementation("dnum")(16777216.0) == {"Name": 16777217.0}


def test_a_signature_is_parsed_when_its_routine_is_first_looked_up(monkeypatch):
    from rapidmc.semantics.library import registry
    lookup_function("ABS")                          # loads the registry
    monkeypatch.setattr(registry, "FUNCTIONS", dict(registry.FUNCTIONS))
    registry.FUNCTIONS["SIN"] = registry._Declared(
        "num Sin(num Angle)", lambda angle: 0.0, False, None, None, registry.EXACT, "math")
    parsed = lookup_function("SIN")
    assert parsed.signature.name == "Sin" and parsed.signature.parameters[0].name == "Angle"
    assert registry.FUNCTIONS["SIN"] is parsed      # parsed once, kept
    # a signature that does not parse is refused when looked up
    registry.FUNCTIONS["COS"] = registry._Declared(
        "num Cos(num Angle", lambda angle: 0.0, False, None, None, registry.EXACT, "math")
    with pytest.raises(SignatureSyntaxError):
        lookup_function("COS")


@pytest.mark.parametrize("text", ["(num a)", "NoSuchP(num a, ..., num b)", "NoSuchQ(num a"])
def test_register_refuses_a_bad_signature_and_files_nothing(text):
    from rapidmc.semantics.library import registry
    with pytest.raises(SignatureSyntaxError):
        register(text, None, special=True, factory=lambda *args: None)
    assert not {"NOSUCHP", "NOSUCHQ"} & set(registry.PROCEDURES)
