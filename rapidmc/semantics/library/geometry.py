"""Geometry functions: Offs, RelTool, OrientZYX, EulerZYX, NOrient, PoseMult,
PoseInv, PoseVect, VectMagn, DotProd, CrossProd, Distance, DefFrame.

Angles are degrees; quaternions are normalised before they rotate anything.
Records are tuples: pose = (pos, orient), robtarget = (pos, orient,
confdata, extjoint).
"""
from __future__ import annotations

import math

from ..errors import RapidError
from ..values import to_num
from .registry import function
from .vector_math import (
    as_orient,
    as_pos,
    axis_rotation,
    orient_normalise,
    pos_cross,
    pos_dot,
    pos_magnitude,
    quaternion_from_axes,
    quaternion_multiply,
    quaternion_normalised,
    quaternion_rotate,
    vector_add,
    vector_sub,
)

X_AXIS, Y_AXIS, Z_AXIS = 0, 1, 2


@function("robtarget Offs(robtarget Point, num XOffset, num YOffset, num ZOffset)")
def offs(point: tuple, dx: float, dy: float, dz: float) -> tuple:
    trans, rot, conf, extax = point
    return (as_pos(vector_add(trans, (dx, dy, dz))), rot, conf, extax)


@function("robtarget RelTool(robtarget Point, num Dx, num Dy, num Dz \\num Rx \\num Ry \\num Rz)")
def rel_tool(point: tuple, dx: float, dy: float, dz: float,
             rx: float | None, ry: float | None, rz: float | None) -> tuple:
    """Displace and rotate in the tool frame: x first, then the new y, then the new z."""
    trans, rot, conf, extax = point
    q = quaternion_normalised(rot)
    new_trans = vector_add(trans, quaternion_rotate(q, (dx, dy, dz)))
    for axis, angle in ((X_AXIS, rx), (Y_AXIS, ry), (Z_AXIS, rz)):
        if angle is not None:
            q = quaternion_multiply(q, axis_rotation(axis, angle))
    return (as_pos(new_trans), as_orient(q), conf, extax)


@function("orient OrientZYX(num ZAngle, num YAngle, num XAngle)")
def orient_zyx(z_angle: float, y_angle: float, x_angle: float) -> tuple:
    zy = quaternion_multiply(axis_rotation(Z_AXIS, z_angle), axis_rotation(Y_AXIS, y_angle))
    q = quaternion_multiply(zy, axis_rotation(X_AXIS, x_angle))
    return as_orient(q)


def euler_zyx_angles(rotation: tuple) -> tuple[float, float, float]:
    """(z, y, x) Euler ZYX angles in degrees of a quaternion (double precision)."""
    w, x, y, z = quaternion_normalised(rotation)
    r00 = 1 - 2 * (y * y + z * z)
    r10 = 2 * (x * y + w * z)
    r20 = 2 * (x * z - w * y)
    r21 = 2 * (y * z + w * x)
    r22 = 1 - 2 * (x * x + y * y)
    y_angle = math.asin(max(-1.0, min(1.0, -r20)))
    if abs(r20) < 1 - 1e-12:
        z_angle, x_angle = math.atan2(r10, r00), math.atan2(r21, r22)
    else:                                   # gimbal lock: put all of it into z
        r01 = 2 * (x * y - w * z)
        r11 = 1 - 2 * (x * x + z * z)
        z_angle, x_angle = math.atan2(-r01, r11), 0.0
    return (math.degrees(z_angle), math.degrees(y_angle), math.degrees(x_angle))


@function("num EulerZYX(\\switch X | switch Y | switch Z, orient Rotation)")
def euler_zyx(x: bool, y: bool, z: bool, rotation: tuple) -> float:
    if not (x or y or z):
        raise RapidError("ERR_ARGVALERR", "EulerZYX needs one of \\X, \\Y, \\Z")
    z_angle, y_angle, x_angle = euler_zyx_angles(rotation)
    return to_num(x_angle if x else y_angle if y else z_angle)


@function("orient NOrient(orient Rotation)")
def n_orient(rotation: tuple) -> tuple:
    return orient_normalise(rotation)


@function("pose PoseMult(pose Pose1, pose Pose2)")
def pose_mult(pose1: tuple, pose2: tuple) -> tuple:
    (t1, q1), (t2, q2) = pose1, pose2
    trans = vector_add(t1, quaternion_rotate(quaternion_normalised(q1), t2))
    return (as_pos(trans), as_orient(quaternion_multiply(q1, q2)))


@function("pose PoseInv(pose Pose)")
def pose_inv(pose: tuple) -> tuple:
    trans, rot = pose
    inverse = quaternion_normalised((rot[0], -rot[1], -rot[2], -rot[3]))
    moved = quaternion_rotate(inverse, trans)
    return (as_pos((-moved[0], -moved[1], -moved[2])), as_orient(inverse))


@function("pos PoseVect(pose Pose, pos Pos)")
def pose_vect(pose: tuple, point: tuple) -> tuple:
    trans, rot = pose
    return as_pos(vector_add(trans, quaternion_rotate(quaternion_normalised(rot), point)))


@function("num VectMagn(pos Vector)")
def vect_magn(vector: tuple) -> float:
    return pos_magnitude(vector)


@function("num DotProd(pos Vector1, pos Vector2)")
def dot_prod(vector1: tuple, vector2: tuple) -> float:
    return pos_dot(vector1, vector2)


@function("pos CrossProd(pos Vector1, pos Vector2)")
def cross_prod(vector1: tuple, vector2: tuple) -> tuple:
    return pos_cross(vector1, vector2)


@function("num Distance(pos Point1, pos Point2)")
def distance(point1: tuple, point2: tuple) -> float:
    return pos_magnitude(vector_sub(point1, point2))


@function("robtarget ORobT(robtarget OrgPoint \\switch InPDisp | switch InEOffs)")
def original_robtarget(point, in_pdisp, in_eoffs):
    """The point without program displacement and external axes offsets: rapidmc models
    neither (PDispOn, EOffsOn change nothing), so none is active and the point is unchanged."""
    return point


# --- reference coverage (issue 8, item 1) -------------------------------------------------
# Half turns about z, y and x as quaternions: the reflection in the mirror frame's xy-plane,
# diag(1, 1, -1), is -Rz(180); negating the tool's y-axis (default) is -Ry(180), negating
# its x-axis (\\MirY) is -Rx(180), and the two signs cancel.
_HALF_TURN_Z, _HALF_TURN_Y, _HALF_TURN_X = (0.0, 0.0, 0.0, 1.0), (0.0, 0.0, 1.0, 0.0), \
    (0.0, 1.0, 0.0, 0.0)
_NO_FRAME = ((0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0))


def _object_frame(wobj: tuple) -> tuple:
    """The object frame of a wobjdata relative to the world: uframe, then oframe."""
    return pose_mult(wobj[3], wobj[4])


@function("robtarget MirPos(robtarget Point, wobjdata MirPlane \\wobjdata WObj \\switch MirY)")
def mir_pos(point: tuple, mir_plane: tuple, wobj: tuple | None, mir_y: bool) -> tuple:
    """Point mirrored in the xy-plane of MirPlane's object frame (Point relative to WObj's
    object frame, or to the world without WObj; the result relative to the same frame).
    The tool frame is mirrored as regards its x- and z-axes, or its y- and z-axes with
    \\MirY; the other axis turns so that the frame stays right-handed."""
    trans, rot, conf, extax = point
    frame = _NO_FRAME if wobj is None else _object_frame(wobj)
    to_mirror = pose_mult(pose_inv(_object_frame(mir_plane)), frame)
    (x, y, z), q = pose_mult(to_mirror, (trans, rot))
    turned = quaternion_multiply(quaternion_multiply(_HALF_TURN_Z, quaternion_normalised(q)),
                                 _HALF_TURN_X if mir_y else _HALF_TURN_Y)
    new_trans, new_rot = pose_mult(pose_inv(to_mirror), ((x, y, -z), as_orient(turned)))
    leading = next((c for c in new_rot if c != 0), 1.0)      # q and -q: the same rotation
    return (new_trans, new_rot if leading > 0 else tuple(-c for c in new_rot), conf, extax)


# Survey round 6 (docs/realworld-survey.md): a work object taught with three points
# (``DefFrame(pX1, pX2, pY1 \Origin:=3)`` in a public teach routine; lib_rob's PSFrame of
# the ernell utility library).  The frame's x-axis runs from NewP1 towards NewP2, its
# xy-plane holds NewP3 on the positive y side; \Origin places the origin in NewP1 (1, the
# default), in NewP2 (2), or on the line NewP1-NewP2 where NewP3 is on the y-axis (3).
_FRAME_TOLERANCE = 1e-6


@function("pose DefFrame(robtarget NewP1, robtarget NewP2, robtarget NewP3 \\num Origin)")
def def_frame(p1: tuple, p2: tuple, p3: tuple, origin: float | None) -> tuple:
    """The frame (pose) the three positions define, in their coordinate system; positions
    too close together or on one line raise ERR_FRAME; an \\Origin other than 1, 2 or 3
    raises ERR_ARGVALERR (our choice)."""
    a, b, c = p1[0], p2[0], p3[0]
    along = vector_sub(b, a)
    length = math.sqrt(sum(v * v for v in along))
    if length < _FRAME_TOLERANCE:
        raise RapidError("ERR_FRAME", "DefFrame: NewP1 and NewP2 are the same position")
    x = tuple(v / length for v in along)
    to_third = vector_sub(c, a)
    foot = sum(u * v for u, v in zip(to_third, x))
    across = vector_sub(to_third, tuple(foot * v for v in x))
    width = math.sqrt(sum(v * v for v in across))
    if width < _FRAME_TOLERANCE:
        raise RapidError("ERR_FRAME", "DefFrame: the three positions lie on one line")
    y = tuple(v / width for v in across)
    z = (x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0])
    place = 1 if origin is None else origin
    if place == 1:
        start = a
    elif place == 2:
        start = b
    elif place == 3:
        start = vector_add(a, tuple(foot * v for v in x))
    else:
        raise RapidError("ERR_ARGVALERR", f"DefFrame: \\Origin must be 1, 2 or 3, not {place}")
    return (as_pos(start), as_orient(quaternion_from_axes(x, y, z)))
