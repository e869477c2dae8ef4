# SPDX-License-Identifier: BSD-3-Clause
"""empy 3's stdout proxy under pytest's capture."""

import sys


def let_empy_take_stdout():
    """empy 3 wraps sys.stdout in a proxy when its first interpreter starts,
    and refuses to start another once sys.stdout has been replaced since.
    pytest's capture replaces it for every test; a genmros process, colcon's
    and rosidl's never do (tests/core/test_render.py runs two of them). So
    the next interpreter may wrap the stdout pytest gives now (a fixture of
    a wider scope, which runs before the test's own, calls this too)."""
    try:
        import em
    except ImportError:  # a test of a Python without ROS
        return
    if not hasattr(sys.stdout, '_testProxy'):
        em.Interpreter._wasProxyInstalled = False
