"""Geometry builtins, predefined data, and the pos/orient operators."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, strategies as st

from rapidmc.semantics.library import lookup_function
from rapidmc.semantics.library.data import PREDEFINED_DATA
from rapidmc.semantics.library.geometry_ops import operator_for
from rapidmc.semantics.errors import RapidError
from rapidmc.semantics.values import to_num

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py


def call(name, *args):
    return lookup_function(name.upper()).impl(*args)


IDENTITY = (1.0, 0.0, 0.0, 0.0)
CONF, EXTAX = (0.0, 0.0, 0.0, 0.0), (9e9,) * 6
angle = st.floats(min_value=-179, max_value=179)
coordinate = st.floats(min_value=-1000, max_value=1000)
vectors = st.tuples(coordinate, coordinate, coordinate).map(lambda v: tuple(map(to_num, v)))


def approx(values, tolerance=1e-3):
    return pytest.approx(values, abs=tolerance)


def test_offs_moves_only_the_position():
    point = ((100.0, 200.0, 300.0), IDENTITY, CONF, EXTAX)
    assert call("Offs", point, 1.0, -2.0, 0.5) == ((101.0, 198.0, 300.5), IDENTITY, CONF, EXTAX)


def test_reltool_displaces_in_the_tool_frame():
    # tool rotated 90 degrees about z: tool x points along world y
    rot = call("OrientZYX", 90.0, 0.0, 0.0)
    point = ((0.0, 0.0, 0.0), rot, CONF, EXTAX)
    moved = call("RelTool", point, 10.0, 0.0, 0.0, None, None, None)
    assert moved[0] == approx((0.0, 10.0, 0.0))
    turned = call("RelTool", point, 0.0, 0.0, 0.0, None, None, 90.0)
    assert call("EulerZYX", False, False, True, turned[1]) == approx(180.0)


@given(angle, st.floats(min_value=-89, max_value=89), angle)
def test_orient_zyx_and_euler_zyx_are_inverse(z, y, x):
    q = call("OrientZYX", z, y, x)
    assert sum(c * c for c in q) == approx(1.0, 1e-5)
    assert call("EulerZYX", False, False, True, q) == approx(z, 1e-2)
    assert call("EulerZYX", False, True, False, q) == approx(y, 1e-2)
    assert call("EulerZYX", True, False, False, q) == approx(x, 1e-2)


def test_euler_zyx_needs_an_axis():
    with pytest.raises(RapidError):
        call("EulerZYX", False, False, False, IDENTITY)


def test_norient_normalises_and_rejects_zero():
    assert call("NOrient", (2.0, 0.0, 0.0, 0.0)) == IDENTITY
    with pytest.raises(RapidError):
        call("NOrient", (0.0, 0.0, 0.0, 0.0))


@given(vectors, angle, angle, vectors)
def test_pose_inverse_undoes_the_pose(trans, z, x, point):
    pose = (trans, call("OrientZYX", z, 0.0, x))
    moved = call("PoseVect", pose, point)
    back = call("PoseVect", call("PoseInv", pose), moved)
    assert back == approx(point, 0.1)
    identity = call("PoseMult", pose, call("PoseInv", pose))
    assert identity[0] == approx((0.0, 0.0, 0.0), 0.1)


@given(vectors, vectors)
def test_vector_functions_against_python(a, b):
    assert call("DotProd", a, b) == approx(sum(x * y for x, y in zip(a, b)), 1.0)
    assert call("VectMagn", a) == approx(math.hypot(*a), 1e-2)
    assert call("Distance", a, b) == approx(math.dist(a, b), 1e-2)
    cross = call("CrossProd", a, b)
    assert call("DotProd", cross, a) == approx(0.0, 1e3)


def test_operators_on_pos_and_orient():
    from rapidmc.semantics import types
    add, result = operator_for("+", types.POS, types.POS)
    assert add((1.0, 2.0, 3.0), (1.0, 1.0, 1.0)) == (2.0, 3.0, 4.0) and result is types.POS
    scale, _ = operator_for("*", types.POS, types.NUM)
    assert scale((1.0, 2.0, 3.0), 2.0) == (2.0, 4.0, 6.0)
    cross, _ = operator_for("*", types.POS, types.POS)
    assert cross((1.0, 0.0, 0.0), (0.0, 1.0, 0.0)) == (0.0, 0.0, 1.0)
    compose, result = operator_for("*", types.ORIENT, types.ORIENT)
    assert compose(IDENTITY, IDENTITY) == IDENTITY and result is types.ORIENT
    divide, result = operator_for("/", types.POS, types.NUM)      # controllers load pos / num
    assert divide((2.0, 4.0, 6.0), 2.0) == (1.0, 2.0, 3.0) and result is types.POS
    assert operator_for("/", types.NUM, types.POS) == (None, None)
    assert operator_for("/", types.POS, types.POS) == (None, None)


@pytest.mark.parametrize("name, type_name, value", [
    ("V100", "speeddata", (100.0, 500.0, 5000.0, 1000.0)),
    ("FINE", "zonedata", (True, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)),
    ("Z10", "zonedata", (False, 10.0, 15.0, 15.0, 1.5, 15.0, 1.5)),
    ("TOOL0", "tooldata", (True, ((0.0, 0.0, 0.0), IDENTITY),
                           (to_num(0.001), (0.0, 0.0, to_num(0.001)), IDENTITY, 0.0, 0.0, 0.0))),
    ("WAIT_MAX", "num", 8388608.0),
    ("STR_DIGIT", "string", "0123456789"),
])
def test_predefined_data(name, type_name, value):
    data = PREDEFINED_DATA[name]
    assert (data.type_name, data.value) == (type_name, value)


# --- DefFrame (survey round 6): a frame from three taught positions -----------------------

def _target(p):
    return (tuple(map(float, p)), IDENTITY, CONF, EXTAX)


def _local(frame, world_point):
    """``world_point`` in the coordinates of ``frame`` (PoseVect of the inverse frame)."""
    return call("PoseVect", call("PoseInv", frame), tuple(map(float, world_point)))


@given(vectors, vectors, vectors)
def test_defframe_puts_the_x_axis_through_p2_and_p3_on_the_positive_y_side(p1, p2, p3):
    x_len = math.dist(p1, p2)
    foot = sum((c - a) * (b - a) for a, b, c in zip(p1, p2, p3)) / x_len if x_len > 1 else 0
    side = math.dist(p3, tuple(a + foot * (b - a) / x_len for a, b in zip(p1, p2))) \
        if x_len > 1 else 0
    if x_len < 1 or side < 1:              # nearly the same or collinear points: ERR_FRAME
        return
    for origin, expected_x in ((None, 0.0), (2.0, -x_len), (3.0, -foot)):
        frame = call("DefFrame", _target(p1), _target(p2), _target(p3), origin)
        assert _local(frame, p1) == approx((expected_x, 0.0, 0.0), 1e-2)     # p1 on the x-axis
        assert _local(frame, p2) == approx((expected_x + x_len, 0.0, 0.0), 1e-2)
        local3 = _local(frame, p3)
        assert local3[1] == pytest.approx(side, abs=1e-2) and local3[2] == approx(0.0, 1e-2)


@pytest.mark.parametrize("points, origin, error", [
    (((0, 0, 0), (0, 0, 0), (0, 100, 0)), None, "ERR_FRAME"),      # NewP1 = NewP2
    (((0, 0, 0), (100, 0, 0), (300, 0, 0)), None, "ERR_FRAME"),    # all on one line
    (((0, 0, 0), (100, 0, 0), (0, 100, 0)), 4.0, "ERR_ARGVALERR"),
])
def test_defframe_refuses_positions_that_define_no_frame(points, origin, error):
    with pytest.raises(RapidError) as raised:
        call("DefFrame", *map(_target, points), origin)
    assert raised.value.name == error


def test_defframe_of_a_public_teach_routine_style_call():
    # x from (100,0,0) to (300,0,0), the third point at negative y: the frame is turned
    # half a turn about x, and \Origin:=3 puts the origin under the third point
    frame = call("DefFrame", _target((100, 0, 0)), _target((300, 0, 0)),
                 _target((200, -50, 0)), 3.0)
    assert frame[0] == approx((200.0, 0.0, 0.0)) and frame[1] == approx((0.0, 1.0, 0.0, 0.0))
