# SPDX-License-Identifier: BSD-3-Clause
"""The network fuzzer (bench/fuzz/network_fuzz.py), run for 45 s against
the relay app on the hardened library under ASan+UBSan: no report, the node
answering with its threads and memory bounded, and every type relayed
byte-exact afterwards. On the library as it is, the same fuzzer stops the
node within a few hundred inputs: the check can fail. bench/README.md has
the figures of a 10-minute run."""

import os
import re
import subprocess
import sys

import pytest

from support.checkout import REPO
from support.user_checkouts import MROS_V1_ROOT

pytestmark = [pytest.mark.needs_mros_v1, pytest.mark.slow]

FUZZER = os.path.join(REPO, 'bench', 'fuzz', 'network_fuzz.py')
ROW = re.compile(
    r'^\| (\d+) \| [\d.]+ \| (\d+) \| (\d+) \| (\d+) \| (\d+) \| (\d+)/(\d+) \|', re.M)


def _fuzz(build_dir, *arguments):
    return subprocess.run([sys.executable, FUZZER, '--build-dir', str(build_dir), '--seed', '1']
                          + list(arguments), env=dict(os.environ, MROS_V1_ROOT=MROS_V1_ROOT),
                          capture_output=True, text=True, timeout=900)


def test_45_seconds_of_network_fuzzing_leave_the_hardened_node_relaying_byte_exact(tmp_path):
    result = _fuzz(tmp_path, '--seconds', '45')
    assert result.returncode == 0, result.stdout[-4000:] + result.stderr[-4000:]
    inputs, slave, headers, publishers, reports, threads, most_threads = map(
        int, ROW.search(result.stdout).groups())
    assert reports == 0 and threads == most_threads, result.stdout
    # Every way in was taken, many times.
    assert inputs >= 100 and min(slave, headers, publishers) >= 20, result.stdout
    assert 'every type relayed byte-exact afterwards' in result.stdout
    assert 'FAIL' not in result.stdout


def test_the_same_fuzzing_stops_the_library_as_it_is(tmp_path):
    result = _fuzz(tmp_path, '--as-it-is', '--seconds', '120')
    assert result.returncode == 1, result.stdout[-4000:] + result.stderr[-4000:]
    failure = re.search(r'^FAIL: after (\d+) inputs: (.*)$', result.stdout, re.M)
    assert failure, result.stdout
    assert failure.group(2).startswith(('a sanitizer report', 'the node exited',
                                        'the node did not answer requestTopic')), result.stdout
    # The node's log and the inputs that led there are kept.
    assert os.path.exists(tmp_path / 'node.log') and os.path.exists(tmp_path / 'last_inputs.json')
