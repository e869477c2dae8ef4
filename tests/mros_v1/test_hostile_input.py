# SPDX-License-Identifier: BSD-3-Clause
"""deserialize under AddressSanitizer and UndefinedBehaviorSanitizer.

Every proper prefix of a valid wire image, each in a heap block of exactly
its size, must be refused with -1; corrupted images must stay in bounds.
Covers every Debian message type and every test_ws type.
"""

import glob
import os
import subprocess

import pytest

from support import cpp_harness
from support.checkout import TEST_WS
from support.debian_messages import DEBIAN_MESSAGE_PACKAGES
from testing import ros_paths

# -O0: a third of -O1's compile time for this one large unit, and no access optimized away.
SANITIZERS = ['-O0', '-fsanitize=address,undefined',
              '-fno-sanitize-recover=all', '-fno-omit-frame-pointer', '-g']
INSTANCES_PER_TYPE = 4


def _all_types():
    search_path = cpp_harness.search_path()
    messages = []
    services = []
    for package in cpp_harness.TEST_WS_PACKAGES:
        msg_dir = search_path[package][0]
        messages.extend('%s/%s' % (package, os.path.basename(p)[:-4])
                        for p in sorted(glob.glob(os.path.join(msg_dir, '*.msg'))))
    for package in DEBIAN_MESSAGE_PACKAGES:
        messages.extend('%s/%s' % (package, os.path.basename(p)[:-4])
                        for p in ros_paths.ros1_definitions(package, 'msg'))
        services.extend((package, p) for p in ros_paths.ros1_definitions(package, 'srv'))
    services.extend(('mros_test', p) for p in sorted(
        glob.glob(os.path.join(TEST_WS, 'src', 'mros_test', 'srv', '*.srv'))))
    return cpp_harness.TypeSet(search_path, messages, services)


@pytest.fixture(scope='module')
def truncation_program(tmp_path_factory, debian_export, test_ws_export):
    type_set = _all_types()
    directory = str(tmp_path_factory.mktemp('truncation'))
    sources = cpp_harness.write_sources(directory, type_set, with_roscpp=False)
    objects = [
        cpp_harness.compile_object(sources['mros_side.cpp'], directory,
                                   [test_ws_export, debian_export, directory], flags=SANITIZERS),
        cpp_harness.compile_object(
            os.path.join(cpp_harness.RANDOM_HEADER_DIR, 'truncation_check.cpp'),
            directory, [directory], flags=SANITIZERS),
    ]
    return type_set, cpp_harness.link_program(objects, os.path.join(directory, 'truncation_check'),
                                              flags=SANITIZERS)


def test_every_proper_prefix_is_refused_cleanly(truncation_program):
    type_set, program = truncation_program
    assert len(type_set.messages) > 190
    environment = dict(os.environ, ASAN_OPTIONS='detect_leaks=1:abort_on_error=0',
                       UBSAN_OPTIONS='print_stacktrace=1')
    result = subprocess.run([program, str(INSTANCES_PER_TYPE)],
                            capture_output=True, text=True, env=environment)
    assert result.returncode == 0, result.stdout[-4000:] + result.stderr[-4000:]
    assert 'runtime error' not in result.stderr
    assert ': 0 failures' in result.stdout
