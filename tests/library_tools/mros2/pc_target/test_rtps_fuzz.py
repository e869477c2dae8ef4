# SPDX-License-Identifier: BSD-3-Clause
"""The RTPS fuzzer (bench/fuzz/rtps_fuzz.py), run for 30 s against the hardened board of
mros2-posix' echoreply_string on MROS2_ROOT, built with sanitizers and gcov: no sanitizer
report, the board still echoes byte for byte, and the mutated datagrams reach the parsers
(each of them ran), not only the length checks before them."""

import os
import re
import subprocess
import sys

import pytest

from conftest import REPO

pytestmark = [pytest.mark.needs_mros2, pytest.mark.slow]

FUZZER = os.path.join(REPO, 'bench', 'fuzz', 'rtps_fuzz.py')
PARSERS = ('MessageReceiver: DATA', 'MessageReceiver: HEARTBEAT', 'MessageReceiver: ACKNACK',
           'ParticipantProxyData::readFromUcdrBuffer', 'TopicData::readFromUcdrBuffer',
           'SEDP: publications', 'SEDP: subscriptions', "mros2's callback")


def test_30_seconds_of_rtps_fuzzing_reach_the_parsers_and_leave_the_board_echoing(tmp_path):
    if not os.path.isfile(os.path.join(os.environ.get('MROS2_POSIX_ROOT', ''), 'workspace',
                                       'echoreply_string', 'app.cpp')):
        pytest.skip('needs mros2-posix (its workspace/ example apps and include/rtps/config.h):'
                    ' set MROS2_POSIX_ROOT (docs/testing.md)')
    result = subprocess.run([sys.executable, FUZZER, '--seconds', '30', '--seed', '1',
                             '--coverage', '--build-dir', str(tmp_path / 'build'),
                             '--findings', str(tmp_path / 'findings')],
                            capture_output=True, text=True, timeout=900)
    assert result.returncode == 0, result.stdout[-4000:] + result.stderr[-2000:]
    assert 'no sanitizer report; the board went on echoing byte for byte afterwards' in \
        result.stdout
    for parser in PARSERS:
        match = re.search(r'^  %s +(\d+)$' % re.escape(parser), result.stdout, re.M)
        assert match and int(match.group(1)) > 0, (parser, result.stdout[-3000:])
