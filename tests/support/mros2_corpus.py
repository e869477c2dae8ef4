# SPDX-License-Identifier: BSD-3-Clause
"""The mros2 test corpora, shared by the tests of this directory: every
type of ROS 2's test interface files (Debian's ros2-test-interface-files)
and std_msgs, geometry_msgs and sensor_msgs as ROS 2 defines them (from
rosbags' type store, written out as packages), each exported with
``genmros mros2-export`` and modelled by genmros' rosidl front end. Its
fixtures are every test's (tests/conftest.py names it a plugin)."""

import shutil

import pytest

from support.checkout import run_genmros
from testing import fastcdr, mros2_harness, ros2_messages

from colcon_mros.core.storage import HeapStorage
from colcon_mros.ros2.interfaces import all_packages
from colcon_mros.ros2.model import ModelBuilder
from testing.ros_paths import prefix_arguments, ros2_prefixes

TEST_INTERFACE_PACKAGE = 'test_interface_files'
ROSBAGS_PACKAGES = ('std_msgs', 'geometry_msgs', 'sensor_msgs')


# Where the echo program runs: (runner, compiler) of each target.
ECHO_TARGETS = {
    'host': ((), ('g++',)),
    'arm': (('qemu-arm', '-L', '/usr/arm-linux-gnueabihf'), ('arm-linux-gnueabihf-g++',)),
    's390x': (('qemu-s390x', '-L', '/usr/s390x-linux-gnu'), ('s390x-linux-gnu-g++',)),
}


class Corpus:
    """The types of one export: their models, headers and C++ names, and
    the echo program of them (testing/mros2_harness) per target."""

    def __init__(self, include_dir, messages, workspace=None):
        self.include_dir = include_dir
        self.workspace = workspace  # the ROS 2 workspace the types come from, if any
        self.messages = messages
        from colcon_mros.mros2.cpp import CppMessageName
        names = [CppMessageName(m) for m in messages]
        self.headers = [n.header for n in names]
        self.cpp_names = [n.cpp_name for n in names]
        self._echoes = {}

    def echo(self, target='host'):
        """The echo program for target, built the first time a test asks."""
        if target not in self._echoes:
            runner, compiler = ECHO_TARGETS[target]
            for tool in [compiler[0]] + list(runner[:1]):
                if shutil.which(tool) is None:
                    pytest.fail('%s is not installed (scripts/setup.sh --tests installs it)'
                                % tool)
            program = mros2_harness.build_echo(
                self.include_dir, self.headers, self.cpp_names,
                '%s-echo-%s' % (self.include_dir, target), compiler,
                extra_flags=['-static'] if runner else [])
            self._echoes[target] = mros2_harness.Echo(program, runner)
        return self._echoes[target]


def typestore():
    from rosbags.typesys import Stores, get_typestore
    return get_typestore(Stores.ROS2_HUMBLE)


@pytest.fixture(scope='module')
def test_interface_corpus(tmp_path_factory):
    include_dir = str(tmp_path_factory.mktemp('tif_export'))
    run_genmros('mros2-export', *prefix_arguments(ros2_prefixes()),
                '--package', TEST_INTERFACE_PACKAGE, '-o', include_dir)
    builder = ModelBuilder(all_packages((), ros2_prefixes()), HeapStorage())
    names = sorted(n for k, n in builder.packages[TEST_INTERFACE_PACKAGE].interfaces
                   if k == 'msg')
    messages = [builder.message('%s/msg/%s' % (TEST_INTERFACE_PACKAGE, n)) for n in names]
    services = [builder.service('%s/srv/%s' % (TEST_INTERFACE_PACKAGE, n)) for n in
                sorted(n for k, n in builder.packages[TEST_INTERFACE_PACKAGE].interfaces
                       if k == 'srv')]
    messages += [half for service in services for half in (service.request, service.response)]
    return Corpus(include_dir, messages)


@pytest.fixture(scope='module')
def rosbags_corpus(tmp_path_factory):
    store = typestore()
    names = sorted(n for n in store.types if n.split('/')[0] in ROSBAGS_PACKAGES)
    workspace = ros2_messages.write_packages(store, names,
                                             str(tmp_path_factory.mktemp('rosbags_ws')))
    include_dir = str(tmp_path_factory.mktemp('rosbags_export'))
    run_genmros('mros2-export', '--workspace', workspace, '--prefix', workspace, '-o',
                include_dir, *['--package=%s' % p for p in ROSBAGS_PACKAGES])
    builder = ModelBuilder(all_packages([workspace], []), HeapStorage())
    return Corpus(include_dir, [builder.message(name) for name in names], workspace)


@pytest.fixture(scope='module')
def fastcdr_program(tmp_path_factory):
    return fastcdr.build(str(tmp_path_factory.mktemp('fastcdr')))
