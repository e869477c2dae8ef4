# SPDX-License-Identifier: BSD-3-Clause
"""libFuzzer over the checked copyFromBuf of every mros2 message type and
service half of test_ws_ros2 and of ROS 2's test interface files, for 12 s
(bench/fuzz/fuzz_mros2.py runs it as long as asked),
seeded with Fast-CDR's bytes.

The harness (bench/fuzz/fuzz_mros2_messages.cpp) checks, under
AddressSanitizer and UndefinedBehaviorSanitizer, that the checked decode
reads only what it is given and that what it accepts is written back
consistently: copyToBuf within calcRawTotalSize(), a fixed point on decoding
again, refused when cut by a byte, copyToFragBuf's fragments the same bytes,
a reused message the same as a fresh one. bench/fuzz/fuzz_mros2.py runs it longer by hand.
"""

import glob
import os
import re
import subprocess
import sys

from support.checkout import REPO

import pytest
from testing.ros_paths import ros2_package_dir

pytestmark = pytest.mark.slow

FUZZ_SECONDS = 12
# Where the fuzzed definitions are: test_ws_ros2's packages and Debian's
# ros2-test-interface-files.
DEFINITION_DIRS = glob.glob(os.path.join(REPO, 'test_ws_ros2', 'src', '*')) + [
    os.path.dirname(ros2_package_dir('test_interface_files'))]


def _fuzzed_type_count():
    """Every .msg is one type, every .srv two (request and response)."""
    count = 0
    for directory in DEFINITION_DIRS:
        count += len(glob.glob(os.path.join(directory, 'msg', '*.msg')))
        count += 2 * len(glob.glob(os.path.join(directory, 'srv', '*.srv')))
    return count


def test_fuzzing_finds_no_crash(tmp_path):
    result = subprocess.run([sys.executable, os.path.join(REPO, 'bench', 'fuzz', 'fuzz_mros2.py'),
                             '--seconds', str(FUZZ_SECONDS), '--build-dir', str(tmp_path)],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr[-8000:]
    assert '| result | no crash |' in result.stdout
    types = _fuzzed_type_count()
    assert '| types | %d |' % types in result.stdout
    seeds = int(re.search(r'\| seed inputs \| (\d+) \|', result.stdout).group(1))
    executions = int(re.search(r'\| executions \| (\d+) \|', result.stdout).group(1))
    assert seeds >= types
    assert executions > 10000, result.stdout
    assert not [name for name in os.listdir(str(tmp_path))
                if name.startswith(('crash-', 'leak-', 'oom-'))]
