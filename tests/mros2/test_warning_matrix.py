# SPDX-License-Identifier: BSD-3-Clause
"""Every message type of test_ws_ros2 and of ROS 2's test interface files,
and the type the warning was first found with (float64[64]), published in
fragments by a caller written as mros2's publish is (an array
``uint8_t frag_buf[N]``, N 16, 64 and 100, the encapsulation header in the
first fragment), compiles without a warning under -Wall -Wextra -Wpedantic
-Wconversion -Wsign-conversion -Werror, and its fragments carry the bytes
copyToBuf writes (testing/mros2_warning_matrix.py).

The part of the matrix run here: g++ -O2 -std=c++11 and -Os -std=c++17
(the levels the warning was reported at that boards build with) and
clang++ -O2 -std=c++17, each built and run (about a minute of CPU, two
builds at a time: the flattened walks are slow to compile);
arm-none-eabi-g++ -Os -std=c++14 for a Cortex-M4, compiled only (slow: a
cross compiler). All types are in one translation unit per configuration.
bench/mros2/warning_matrix.py builds the whole matrix (3 compilers x 5
levels x 4 standards) and prints its table.
"""

import glob
import os
from concurrent.futures import ThreadPoolExecutor

import pytest

from testing import mros2_warning_matrix as matrix
from testing import ros_paths
from testing.mros2_warning_matrix import Configuration

HOST_PART = [Configuration('g++', '-O2', 'c++11'), Configuration('g++', '-Os', 'c++17'),
             Configuration('clang++', '-O2', 'c++17')]
BOARD_PART = [Configuration('arm-none-eabi-g++', '-Os', 'c++14')]


@pytest.fixture(scope='module')
def caller(tmp_path_factory):
    """(include dir, the caller's source, its types) of one export."""
    root = tmp_path_factory.mktemp('warning_matrix')
    include_dir = matrix.export_headers(str(root / 'include'))
    types = matrix.message_types(include_dir)
    return include_dir, matrix.write_program(types, str(root / 'fragment_caller.cpp')), types


def _defined_type_count():
    """Every .msg of the packages is one type, every .srv two (request and response)."""
    directories = glob.glob(os.path.join(matrix.TEST_WS_ROS2, 'src', '*')) + [
        ros_paths.ros2_package_dir('test_interface_files', '')]
    return sum(len(glob.glob(os.path.join(directory, 'msg', '*.msg')))
               + 2 * len(glob.glob(os.path.join(directory, 'srv', '*.srv')))
               for directory in directories)


def _build_all(configurations, caller, out_dir):
    include_dir, source, _ = caller
    # Two at a time: the machine's two cores.
    with ThreadPoolExecutor(max_workers=2) as pool:
        return list(pool.map(lambda configuration: matrix.build(
            configuration, include_dir, source, str(out_dir)), configurations))


def test_the_caller_publishes_every_type(caller):
    _, _, types = caller
    assert len(types) == _defined_type_count() + len(matrix.FIRST_FINDING_MESSAGES) > 20


def test_fragments_compile_warning_free_and_carry_copytobufs_bytes(caller, tmp_path):
    builds = _build_all(HOST_PART, caller, tmp_path)
    assert [(build.configuration, build.stderr[-3000:]) for build in builds
            if build.stderr or build.output is None] == []
    for build in builds:
        types, sizes, failures, lines = matrix.run(build.output)
        assert (types, sizes, failures, lines) == (
            len(caller[2]), len(matrix.FRAGMENT_BUFFER_SIZES), 0, []), build.configuration


@pytest.mark.slow
def test_fragments_compile_warning_free_for_a_board(caller, tmp_path):
    """arm-none-eabi-g++ also prints -Wpsabi notes (std::move_iterator's
    parameter passing changed in GCC 7.1): notes, not warnings."""
    builds = _build_all(BOARD_PART, caller, tmp_path)
    assert [(build.configuration, build.stderr[-3000:]) for build in builds
            if build.warnings or build.errors or build.output is None] == []
