# SPDX-License-Identifier: BSD-3-Clause
"""empy 3's stdout proxy across pytest's capture (a plugin: tests/conftest.py).

empy 3 (Debian's python3-empy) puts a proxy in place of sys.stdout when its
first interpreter starts, and documents that nothing may rebind sys.stdout
after: a later interpreter refuses to start ("interpreter stdout proxy
lost"). A process of genmros, colcon or rosidl never rebinds it;
pytest's capture puts its stream back as sys.stdout at each phase of each
test, and rosidl_adapter starts an interpreter for every .msg and .srv it
reads. So at each phase, where sys.stdout is pytest's stream, the proxy
empy 3 put around that stream takes its place again. empy 4's proxy lives
only as long as its interpreter: there is none to keep.
"""

import io
import sys

import pytest

# [(pytest's capture stream, empy 3's proxy around it or None)], made at
# the first phase, the session's first test's setup: no test's own capture
# (capsys) is in place yet.
_PROXIED = []


def _proxied(stream):
    try:
        import em
    except ImportError:  # a test of a Python without ROS
        return stream, None
    em.Interpreter(output=io.StringIO()).shutdown()
    return stream, (sys.stdout if sys.stdout is not stream else None)


def _put_the_proxy_back():
    if not _PROXIED:
        _PROXIED.append(_proxied(sys.stdout))
    stream, proxy = _PROXIED[0]
    if proxy is not None and sys.stdout is stream:
        sys.stdout = proxy


# trylast: inside the capture's own wrappers, after they put the stream back.
@pytest.hookimpl(hookwrapper=True, trylast=True)
def pytest_runtest_setup(item):
    _put_the_proxy_back()
    yield


@pytest.hookimpl(hookwrapper=True, trylast=True)
def pytest_runtest_call(item):
    _put_the_proxy_back()
    yield


@pytest.hookimpl(hookwrapper=True, trylast=True)
def pytest_runtest_teardown(item):
    _put_the_proxy_back()
    yield
