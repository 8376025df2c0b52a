"""Vector (pos) and quaternion (orient) arithmetic on tuples, results rounded to num.

Used by the geometry functions and by the interpreter for the operators
``pos + pos``, ``pos - pos``, ``-pos``, ``num * pos``, ``pos * pos`` (cross
product) and ``orient * orient`` (rotation composition).  Quaternions are
``(q1, q2, q3, q4)`` = (w, x, y, z); ``(1, 0, 0, 0)`` is the identity.

``vector_*`` and ``quaternion_*`` compute in double precision (for chains
of operations inside one routine); ``pos_*`` and ``orient_*`` round their
result with ``to_num``.
"""
from __future__ import annotations

import math

from ..errors import RapidError
from ..values import to_num

Pos = tuple[float, float, float]
Orient = tuple[float, float, float, float]


def as_pos(values) -> Pos:
    """Three numbers rounded to num."""
    x, y, z = values
    return (to_num(x), to_num(y), to_num(z))


def as_orient(values) -> Orient:
    """Four numbers rounded to num."""
    q1, q2, q3, q4 = values
    return (to_num(q1), to_num(q2), to_num(q3), to_num(q4))


# --- pos ----------------------------------------------------------------------


def vector_add(a: Pos, b: Pos) -> Pos:
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def vector_sub(a: Pos, b: Pos) -> Pos:
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def vector_cross(a: Pos, b: Pos) -> Pos:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def vector_dot(a: Pos, b: Pos) -> float:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def pos_add(a: Pos, b: Pos) -> Pos:
    return as_pos(vector_add(a, b))


def pos_sub(a: Pos, b: Pos) -> Pos:
    return as_pos(vector_sub(a, b))


def pos_negate(a: Pos) -> Pos:
    return (-a[0], -a[1], -a[2])


def pos_scale(factor: float, a: Pos) -> Pos:
    return as_pos((factor * a[0], factor * a[1], factor * a[2]))


def pos_cross(a: Pos, b: Pos) -> Pos:
    return as_pos(vector_cross(a, b))


def pos_dot(a: Pos, b: Pos) -> float:
    return to_num(vector_dot(a, b))


def pos_magnitude(a: Pos) -> float:
    return to_num(math.sqrt(vector_dot(a, a)))


# --- orient ----------------------------------------------------------------------


def quaternion_multiply(q: Orient, r: Orient) -> Orient:
    w1, x1, y1, z1 = q
    w2, x2, y2, z2 = r
    return (w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
            w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
            w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2)


def quaternion_conjugate(q: Orient) -> Orient:
    return (q[0], -q[1], -q[2], -q[3])


def quaternion_rotate(q: Orient, v: Pos) -> Pos:
    """``v`` rotated by the unit quaternion ``q`` (q v q*)."""
    rotated = quaternion_multiply(q, (0.0, v[0], v[1], v[2]))
    w, x, y, z = quaternion_multiply(rotated, quaternion_conjugate(q))
    return (x, y, z)


def quaternion_normalised(q: Orient) -> Orient:
    norm = math.sqrt(sum(c * c for c in q))
    if norm == 0:
        raise RapidError("ERR_ARGVALERR", "a zero quaternion has no orientation")
    return (q[0] / norm, q[1] / norm, q[2] / norm, q[3] / norm)


def axis_rotation(axis: int, degrees: float) -> Orient:
    """Unit quaternion of a rotation by ``degrees`` about axis 0=x, 1=y, 2=z."""
    half = math.radians(degrees) / 2
    q = [math.cos(half), 0.0, 0.0, 0.0]
    q[axis + 1] = math.sin(half)
    return (q[0], q[1], q[2], q[3])


def quaternion_from_axes(x: Pos, y: Pos, z: Pos) -> Orient:
    """Unit quaternion of the rotation whose matrix has the orthonormal columns x, y, z
    (a right-handed frame), with a non-negative first component."""
    m = ((x[0], y[0], z[0]), (x[1], y[1], z[1]), (x[2], y[2], z[2]))
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0:
        s = 2 * math.sqrt(1 + trace)
        q = (s / 4, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s)
    else:
        i = max(range(3), key=lambda k: m[k][k])
        j, k = (i + 1) % 3, (i + 2) % 3
        s = 2 * math.sqrt(1 + m[i][i] - m[j][j] - m[k][k])
        v = [0.0, 0.0, 0.0]
        v[i] = s / 4
        v[j] = (m[j][i] + m[i][j]) / s
        v[k] = (m[k][i] + m[i][k]) / s
        q = ((m[k][j] - m[j][k]) / s, v[0], v[1], v[2])
    q = quaternion_normalised(q)
    return q if q[0] >= 0 else tuple(-c for c in q)


def orient_multiply(q: Orient, r: Orient) -> Orient:
    return as_orient(quaternion_multiply(q, r))


def orient_normalise(q: Orient) -> Orient:
    return as_orient(quaternion_normalised(q))


def orient_rotate(q: Orient, v: Pos) -> Pos:
    return as_pos(quaternion_rotate(quaternion_normalised(q), v))
