# SPDX-License-Identifier: BSD-3-Clause
"""The RTPS fuzzer's findings, replayed (bench/fuzz/rtps_fuzz.py --replay) against a
sanitized board of mros2-posix' echoreply_string on MROS2_ROOT: mros2 with only
accept-fast-dds-3-discovery reports each, hardened (with the finding's patch) reports
nothing and goes on echoing.

tests/fixtures/rtps_findings/acknack.txt (checked-acknack): an ACKNACK cut after its
entity ids, at a datagram's end (embeddedRTPS read its sequence number set past the
datagram), and one of 256 bits (its bitmap copied into a field of 32)."""

import os
import subprocess
import sys

import pytest

from conftest import REPO

pytestmark = [pytest.mark.needs_mros2, pytest.mark.slow]

FUZZER = os.path.join(REPO, 'bench', 'fuzz', 'rtps_fuzz.py')
FINDINGS = os.path.join(REPO, 'tests', 'fixtures', 'rtps_findings')


@pytest.mark.parametrize('hardened', [False, True], ids=['as-it-is', 'hardened'])
@pytest.mark.parametrize('finding', sorted(os.listdir(FINDINGS)))
def test_a_finding_replayed(tmp_path, finding, hardened):
    if not os.path.isfile(os.path.join(os.environ.get('MROS2_POSIX_ROOT', ''), 'workspace',
                                       'echoreply_string', 'app.cpp')):
        pytest.skip('needs mros2-posix (its workspace/ example apps and include/rtps/config.h):'
                    ' set MROS2_POSIX_ROOT (docs/testing.md)')
    result = subprocess.run([sys.executable, FUZZER, '--build-dir', str(tmp_path), '--replay',
                             os.path.join(FINDINGS, finding)] + ([] if hardened else
                                                                 ['--as-it-is']),
                            capture_output=True, text=True, timeout=900)
    last = result.stdout.splitlines()[-1] if result.stdout else result.stderr[-2000:]
    if hardened:
        assert (result.returncode, last) == (0, 'the board reports nothing and echoes')
    else:
        assert (result.returncode, last) == (1, "the board reports: ['AddressSanitizer']")
