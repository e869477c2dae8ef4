# SPDX-License-Identifier: BSD-3-Clause
"""libFuzzer over the decoders of every test_ws type and of Image, PointCloud2,
JointState, Odometry and MarkerArray, for 12 s (bench/fuzz/fuzz.py runs it as long
as asked), seeded with genpy's bytes.

The harness (bench/fuzz/fuzz_messages.cpp) checks the safe API, reused
messages and mROS v1 delivery under AddressSanitizer and
UndefinedBehaviorSanitizer; bench/fuzz/fuzz.py runs it longer by hand.
"""

import os
import re
import subprocess
import sys

from support.checkout import REPO

import pytest

pytestmark = pytest.mark.slow

FUZZ_SECONDS = 12


def test_fuzzing_finds_no_crash(tmp_path):
    result = subprocess.run([sys.executable, os.path.join(REPO, 'bench', 'fuzz', 'fuzz.py'),
                             '--seconds', str(FUZZ_SECONDS), '--build-dir', str(tmp_path)],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr[-8000:]
    assert '| result | no crash |' in result.stdout
    assert '| types | 15 |' in result.stdout
    seeds = int(re.search(r'\| seed inputs \(genpy\) \| (\d+) \|', result.stdout).group(1))
    executions = int(re.search(r'\| executions \| (\d+) \|', result.stdout).group(1))
    assert seeds >= 2 * 15
    assert executions > 10000, result.stdout
    assert not [name for name in os.listdir(
        str(tmp_path)) if name.startswith(('crash-', 'leak-', 'oom-'))]
