"""Names of ABB's reference added for issue 8, item 1: MirPos's geometry, the signatures of
the new entries, and the outcomes a model check explores."""
from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from rapidmc.semantics.library.documentation import signature_text
from rapidmc.semantics.library import lookup_function, lookup_procedure, parse_signature
from rapidmc.semantics.library.registry import SignatureSyntaxError, register
from rapidmc.semantics.types import PREDEFINED_TYPES
from rapidmc.semantics.library.geometry import mir_pos
from rapidmc.semantics.library.vector_math import quaternion_rotate
from tests.test_realworld import cli

CONF, EXTAX = (0.0, 0.0, 0.0, 0.0), (9e9,) * 6
NO_FRAME = ((0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0))
WOBJ0 = (False, True, "", NO_FRAME, NO_FRAME)
DOWN = (0.0, 0.0, 1.0, 0.0)           # tool z along world -z, tool x along world -x


def axes(q):
    return [quaternion_rotate(q, axis) for axis in ((1, 0, 0), (0, 1, 0), (0, 0, 1))]


def test_mirpos_in_the_world_xy_plane_reverses_z_and_the_tool_y_axis():
    trans, rot, conf, extax = mir_pos(((100.0, 20.0, 50.0), DOWN, CONF, EXTAX), WOBJ0, None, False)
    assert trans == pytest.approx((100.0, 20.0, -50.0)) and (conf, extax) == (CONF, EXTAX)
    x, y, z = axes(rot)
    assert x == pytest.approx((-1, 0, 0), abs=1e-6)     # mirrored x: unchanged by this plane
    assert y == pytest.approx((0, -1, 0), abs=1e-6)     # turned to keep a right-handed frame
    assert z == pytest.approx((0, 0, 1), abs=1e-6)      # mirrored z: now up


def test_mirpos_mir_y_mirrors_the_y_axis_and_turns_x():
    _, rot, _, _ = mir_pos(((100.0, 20.0, 50.0), DOWN, CONF, EXTAX), WOBJ0, None, True)
    x, y, z = axes(rot)
    assert x == pytest.approx((1, 0, 0), abs=1e-6) and y == pytest.approx((0, 1, 0), abs=1e-6)
    assert z == pytest.approx((0, 0, 1), abs=1e-6)


def test_mirpos_of_a_point_in_a_work_object_stays_in_that_work_object():
    # work object 100 mm up: the world xy-plane is 100 mm below its origin
    wobj = (False, True, "", ((0.0, 0.0, 100.0), (1.0, 0.0, 0.0, 0.0)), NO_FRAME)
    trans, _, _, _ = mir_pos(((0.0, 0.0, 10.0), DOWN, CONF, EXTAX), WOBJ0, wobj, False)
    assert trans == pytest.approx((0.0, 0.0, -210.0))


coordinate = st.floats(min_value=-500, max_value=500)
unit = st.floats(min_value=-1, max_value=1)


@settings(max_examples=60, deadline=None)
@given(st.tuples(coordinate, coordinate, coordinate),
       st.tuples(unit, unit, unit, unit).filter(lambda q: sum(c * c for c in q) > 0.1),
       st.tuples(coordinate, coordinate, coordinate),
       st.tuples(unit, unit, unit, unit).filter(lambda q: sum(c * c for c in q) > 0.1),
       st.booleans())
def test_mirroring_twice_gives_the_point_back(trans, rot, origin, frame_rot, mir_y):
    norm = sum(c * c for c in rot) ** 0.5
    rot = tuple(c / norm for c in rot)
    frame_norm = sum(c * c for c in frame_rot) ** 0.5
    plane = (False, True, "", (origin, tuple(c / frame_norm for c in frame_rot)), NO_FRAME)
    point = (trans, rot, CONF, EXTAX)
    back = mir_pos(mir_pos(point, plane, None, mir_y), plane, None, mir_y)
    assert back[0] == pytest.approx(trans, abs=0.05)
    assert axes(back[1]) == [pytest.approx(a, abs=1e-3) for a in axes(rot)]


@pytest.mark.parametrize("lookup, name, shape", [
    (lookup_procedure, "TRIGGLIOS", [("TriggData1", "triggios", True, 1),
                                     ("TriggData2", "triggstrgo", True, 1),
                                     ("TriggData3", "triggiosdnum", True, 1)]),
    (lookup_procedure, "SOCKETRECEIVEFROM", [("RemoteAddress", "string", False, 0),
                                             ("RemotePort", "num", False, 0)]),
    (lookup_function, "GETSIGNALORIGIN", [("Signal", "anytype", False, 0),
                                          ("SignalName", "string", False, 0)]),
    (lookup_function, "MIRPOS", [("WObj", "wobjdata", True, 0), ("MirY", "switch", True, 0)]),
    (lookup_function, "CALCROTAXISFRAME", [("TargetList", "robtarget", False, 1),
                                           ("MaxErr", "num", False, 0)]),
])
def test_signatures_of_reference_entries(lookup, name, shape):
    signature = lookup(name).signature
    for parameter, type_name, optional, rank in shape:
        spec = signature.parameter(parameter.upper())
        assert (spec.type_name, spec.optional, spec.array_rank) == (type_name, optional, rank)


def test_search_ext_j_and_datagram_alternatives_share_groups():
    search = lookup_procedure("SEARCHEXTJ").signature
    assert search.parameter("STOP").alternative_group == search.parameter("SUP").alternative_group
    receive = lookup_procedure("SOCKETRECEIVEFROM").signature
    assert receive.parameter("STR").alternative_group == receive.parameter("RAWDATA").alternative_group
    assert receive.parameter("REMOTEADDRESS").mode == "VAR"


PROGRAM = str(Path(__file__).resolve().parent / "library_outcomes" / "ReferenceOutcomes.mod")


@pytest.mark.parametrize("atom", ['"nSearch = 1"', '"nSearch = 2"', '"nDatagram = 1"',
                                  '"nDatagram = 2"'])
def test_every_outcome_is_reachable(atom, tmp_path):
    properties = tmp_path / "p.ltl"
    properties.write_text(f"never: G !{atom}\n")
    code, out, err = cli(["check", PROGRAM, "--ltl", str(properties)])
    assert code == 1 and "never: VIOLATED" in out, out + err


@pytest.mark.parametrize("lookup, name, shape", [
    (lookup_procedure, "CSSACT", [("RefFrame", "num", True, 0), ("SoftDir", "css_soft_dir", False, 0),
                                  ("AllowMove", "switch", True, 0)]),
    (lookup_procedure, "CSSOFFSETTUNE", [("OffsetDir", "css_offset_dir", False, 0),
                                         ("ForceOffset", "num", False, 0)]),
    (lookup_procedure, "PRXSETSYNCALARM", [("MechUnit", "mecunit", False, 0),
                                           ("Time", "num", False, 0), ("NoPulse", "switch", True, 0)]),
    (lookup_procedure, "CAMGETPARAMETER", [("ParName", "string", False, 0),
                                           ("BoolVar", "bool", True, 0)]),
    (lookup_function, "PRXGETMAXRECORDPOS", [("MechUnit", "mecunit", False, 0)]),
])
def test_signatures_of_entries_from_public_evidence(lookup, name, shape):
    test_signatures_of_reference_entries(lookup, name, shape)


def test_camera_parameter_values_are_one_alternative_group():
    signature = lookup_procedure("CAMSETPARAMETER").signature
    groups = {signature.parameter(key).alternative_group for key in ("NUMVAL", "BOOLVAL", "STRVAL")}
    assert len(groups) == 1 and None not in groups


def test_an_open_parameter_list_takes_no_declared_parameters():
    signature = parse_signature("IndCnvInit(...)")
    assert signature.open_parameters and signature.parameters == ()
    assert signature_text(signature) == "IndCnvInit(...)"
    assert not parse_signature("Incr(INOUT anynum Name)").open_parameters
    with pytest.raises(SignatureSyntaxError):
        parse_signature("IndCnvInit(..., num Speed)")


def test_an_open_parameter_list_needs_a_factory_that_does_not_bind():
    with pytest.raises(SignatureSyntaxError):
        register("NotARapidName(...)", lambda: None)
    assert lookup_procedure("RAISETOUSER").signature.open_parameters


def test_the_processing_times_of_cap_have_their_components():
    assert [c.name for c in PREDEFINED_TYPES["PROC_TIMES"].components] == ["pre", "post1", "post2"]
    assert len(PREDEFINED_TYPES["SUP_TIMEOUTS"].components) == 5


def test_a_name_only_routine_loads_with_any_arguments_and_stops_where_it_is_reached():
    program = str(Path(__file__).resolve().parent / "library_outcomes" / "RaiseToUser.mod")
    code, out, err = cli(["run", program])
    assert code == 2 and out == "start\nlibrary handler\n", out + err
    assert "RaiseToUser from the name list of ABB's reference only" in err and "[RMC305]" in err
    assert ":21:7:" in err


def test_undeclared_names_in_the_arguments_of_a_name_only_routine_are_reported(tmp_path):
    program = tmp_path / "Typo.mod"
    program.write_text("MODULE Typo\n  VAR socketdev sock;\n  PROC main()\n"
                       "    IndCnvInit sock, nTypo \\Speed:=Foo(3);\n    TPWrite \"never\";\n"
                       "  ENDPROC\nENDMODULE\n")
    code, out, err = cli(["run", str(program)])
    assert code == 2 and out == ""
    assert "unknown name 'nTypo' [RMC201]" in err and "unknown function 'Foo' [RMC203]" in err
    assert "RMC305" not in err
