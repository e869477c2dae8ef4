# SPDX-License-Identifier: BSD-3-Clause
"""Sample messages for the round-trip checks: for every test message type,
values that reach the edges of each field's range (extreme integers, exact
float32 values, empty and non-ASCII strings, empty and full arrays, times
with nanoseconds, negative durations, nested and cross-package messages)."""
import math

import genpy
from geometry_msgs.msg import Point, Pose, Quaternion, Twist, Vector3
from mros_test.msg import (ArrayTypes, BuiltinTypes, Constants, Empty, NestedTypes,
                           PersonalData)
from mros_test_base.msg import Labeled, Vector3i
from std_msgs.msg import ColorRGBA, Header


def _builtins():
    return [
        BuiltinTypes(b=True, i8=-128, u8=255, i16=-32768, u16=65535, i32=-2147483648,
                     u32=4294967295, i64=-9223372036854775808, u64=18446744073709551615,
                     f32=1.5, f64=math.pi, s='Phil Woods, alto sax',
                     t=genpy.Time(1700000000, 999999999), d=genpy.Duration(-5, 500),
                     legacy_byte=-7, legacy_char=200),
        BuiltinTypes(b=False, i8=127, u8=0, i16=32767, u16=0, i32=2147483647, u32=0,
                     i64=9223372036854775807, u64=0, f32=-0.15625, f64=-1e-300, s='',
                     t=genpy.Time(0, 0), d=genpy.Duration(2147483647, 999999999),
                     legacy_byte=127, legacy_char=0),
        BuiltinTypes(s='Zoë, 日本語 and a NUL \x00 inside', f32=float('inf'),
                     f64=float('-inf')),
    ]


def _labeled(label, weights):
    return Labeled(label=label, color=ColorRGBA(r=0.5, g=0.25, b=1.0, a=0.0), weights=weights)


def _arrays():
    return [
        ArrayTypes(bytes=b'\x00\x01\xfe\xff', fixed_bytes=b'mROS', ints=[-1, 0, 2147483647],
                   fixed_floats=[1.5, -2.0, 0.25], doubles=[1e300, -0.5], flags=[True, False],
                   names=['first', '', 'ünïcödé'], fixed_names=['fixed', ''],
                   times=[genpy.Time(1, 2), genpy.Time(4294967295, 999999999)],
                   durations=[genpy.Duration(-1, 5), genpy.Duration(3, 0)],
                   vectors=[Vector3i(1, -2, 3), Vector3i(-2147483648, 0, 2147483647)],
                   fixed_vectors=[Vector3i(4, 5, 6), Vector3i(7, 8, 9)],
                   labeled=[_labeled('one', [1.0, 2.5]), _labeled('', [])],
                   fixed_labeled=[_labeled('left', [0.125]), _labeled('right', [])],
                   empties=[Empty(), Empty(), Empty()]),
        ArrayTypes(fixed_bytes=b'\x00\x00\x00\x00', fixed_floats=[0.0, 0.0, 0.0],
                   flags=[False, False], fixed_names=['', ''],
                   durations=[genpy.Duration(), genpy.Duration()],
                   fixed_vectors=[Vector3i(), Vector3i()],
                   fixed_labeled=[_labeled('', []), _labeled('', [])]),
    ]


def _nested():
    arrays = _arrays()
    return [
        NestedTypes(header=Header(seq=7, stamp=genpy.Time(1700000123, 456789012),
                                  frame_id='base_link'),
                    person=PersonalData('Charlie', 'Parker', 32, 100175),
                    position=Vector3i(10, 20, 30),
                    pose=Pose(Point(1.0, 2.0, 3.0), Quaternion(0.0, 0.0, 0.70710678, 0.70710678)),
                    twists=[Twist(Vector3(1, 0, 0), Vector3(0, 0, 0.5)), Twist()],
                    arrays=arrays[0]),
        NestedTypes(header=Header(frame_id=''), arrays=arrays[1]),
    ]


def samples():
    """Type name (the topic's last element) -> list of distinct messages."""
    return {
        'PersonalData': [PersonalData('Phil', 'Woods', 83, 100000),
                         PersonalData('', 'Ünïcode', 65535, -2147483648)],
        'BuiltinTypes': _builtins(),
        'ArrayTypes': _arrays(),
        'NestedTypes': _nested(),
        'Constants': [Constants(value=Constants.U8_MAX), Constants(value=0)],
        'Empty': [Empty()],
        'Header': [Header(seq=4294967295, stamp=genpy.Time(1700000000, 123456789),
                          frame_id='map'),
                   Header(seq=0, stamp=genpy.Time(0, 1), frame_id='')],
    }
