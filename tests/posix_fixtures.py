"""pytest fixtures of the POSIX tests: the built test_ws and firmware (built
once per session: posix_builds caches them) and a fresh rosmaster per test
whose processes are all stopped when the test ends, passed or failed.

Test modules import them: from posix_fixtures import ros_workspace, ..."""

import functools

import pytest

import posix_builds
from ros_processes import RosGraph, sourced_environment


@functools.lru_cache(maxsize=None)
def _environment(setup_bash):
    return sourced_environment(setup_bash)


@pytest.fixture(scope='session')
def ros_workspace():
    return posix_builds.workspace()


@pytest.fixture(scope='session')
def mros_firmware(ros_workspace):
    return posix_builds.firmware(ros_workspace.mros_export)


@pytest.fixture
def ros_graph(ros_workspace, mros_firmware):
    with RosGraph(_environment(ros_workspace.setup_bash)) as graph:
        yield graph
