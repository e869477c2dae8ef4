# SPDX-License-Identifier: BSD-3-Clause
"""The RTPS fuzzer (bench/fuzz/rtps_fuzz.py), run for 30 s against the hardened board of
mros2-posix' echoreply_string on MROS2_ROOT, built with sanitizers and gcov: no sanitizer
report, and the mutated datagrams reach the parsers (each of them ran), not only the length
checks before them, data-frag-for-best-effort-readers' DATA_FRAG ones included; and
afterwards the board still echoes an rclpy node's strings byte for byte (once the fuzzed
participants' leases have ended: embeddedRTPS keeps 5)."""

import os
import re
import subprocess
import sys

import pytest

from support.checkout import REPO

pytestmark = [pytest.mark.needs_mros2, pytest.mark.slow]

FUZZER = os.path.join(REPO, 'bench', 'fuzz', 'rtps_fuzz.py')
PARSERS = ('MessageReceiver: DATA', 'MessageReceiver: HEARTBEAT', 'MessageReceiver: ACKNACK',
           'MessageReceiver: ACKNACKs sorted out', 'StatefulWriter: ACKNACK',
           'ParticipantProxyData::readFromUcdrBuffer', 'TopicData::readFromUcdrBuffer',
           'SEDP: publications', 'SEDP: subscriptions', 'MessageReceiver: inline QoS',
           'SEDP: a dispose heeded', 'MessageReceiver: DATA_FRAG',
           'MessageReceiver: fragments taken', "mros2's callback")
NO_FINDING = 'no sanitizer report; the board went on echoing byte for byte afterwards'


@pytest.fixture(scope='module')
def fuzzed(tmp_path_factory):
    if not os.path.isfile(os.path.join(os.environ.get('MROS2_POSIX_ROOT', ''), 'workspace',
                                       'echoreply_string', 'app.cpp')):
        pytest.skip('needs mros2-posix (its workspace/ example apps and include/rtps/config.h):'
                    ' set MROS2_POSIX_ROOT (docs/testing.md)')
    work = tmp_path_factory.mktemp('rtps_fuzz')
    return subprocess.run([sys.executable, FUZZER, '--seconds', '30', '--seed', '1',
                           '--coverage', '--build-dir', str(work / 'build'),
                           '--findings', str(work / 'findings')],
                          capture_output=True, text=True, timeout=900)


def test_30_seconds_of_rtps_fuzzing_reach_the_parsers_and_the_board_echoes_after(fuzzed):
    assert fuzzed.returncode == 0, fuzzed.stdout[-4000:] + fuzzed.stderr[-2000:]
    assert NO_FINDING in fuzzed.stdout
    for parser in PARSERS:
        match = re.search(r'^  %s +(\d+)$' % re.escape(parser), fuzzed.stdout, re.M)
        assert match and int(match.group(1)) > 0, (parser, fuzzed.stdout[-3000:])
