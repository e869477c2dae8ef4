# SPDX-License-Identifier: BSD-3-Clause
"""The RTPS fuzzer's findings, replayed (bench/fuzz/rtps_fuzz.py --replay) against a
sanitized board of mros2-posix' echoreply_string on MROS2_ROOT: mros2 with only
accept-fast-dds-3-discovery and reader-catches-up-at-once
reports each, hardened (with the finding's patch) reports
nothing and goes on echoing.

tests/fixtures/rtps_findings/acknack.txt (checked-acknack): an ACKNACK cut after its
entity ids, at a datagram's end (embeddedRTPS read its sequence number set past the
datagram), and one of 256 bits (its bitmap copied into a field of 32).

tests/fixtures/rtps_findings/participant_table.txt (full-participant-table-refuses): the
SPDP announcement of the wheels' rclpy node (Fast DDS 3), as a recording took it, from 8
participants of fresh GUID prefixes (genmros-sp 0 1 to 8), each with a lease of 1 s: more
than mros2-posix' table holds (SPDP_MAX_NUMBER_FOUND_PARTICIPANTS, 5). As it is, the reader
thread spins for ever and the board takes nothing more; hardened, the participants it could
not add are refused, the others leave when their leases end, and the echo's node finds a
place.

tests/fixtures/rtps_findings/acknack_count.txt (large-acknack-counts): that announcement
from one more participant (genmros-ack 1), then two ACKNACKs of it to the board's SEDP
publications writer, of counts 0x7fffffff and 0xffffffff: as it is, the writer's unused text
of the two counts does not fit its 20 characters and the reader thread spins for ever.

tests/fixtures/rtps_findings/submessage_length.txt (bounded-submessage-lengths): one datagram
of a header and a GAP whose length, 0xfffc, brings embeddedRTPS' 16-bit position back to
itself: as it is, the reader thread reads that submessage for ever.

tests/fixtures/rtps_findings/acknack_base.txt (acknack-within-the-history): the announcement
from one more participant (genmros-sn 0 1), then an ACKNACK of it to the SEDP publications
writer whose set starts at sequence number (-2, 0): as it is, the reader thread steps
through the 2^32 and more numbers up to the writer's newest, for hours.

tests/fixtures/rtps_findings/lease.txt (lease-in-milliseconds): the announcement from one
more participant (genmros-ls 0 1) with a lease of 11927572 s, as the fuzzer sent it: as it
is, the SPDP writer thread's liveliness check overflows int turning it into milliseconds.

tests/fixtures/rtps_findings/data_fields.txt (data-holds-its-fields): one datagram of a
header and a DATA of length 0 at its end: as it is, the reader reads DATA's 20 bytes of
fields past the datagram."""

import os
import subprocess
import sys

import pytest

from support.checkout import REPO

pytestmark = [pytest.mark.needs_mros2, pytest.mark.slow]

FUZZER = os.path.join(REPO, 'bench', 'fuzz', 'rtps_fuzz.py')
FINDINGS = os.path.join(REPO, 'tests', 'fixtures', 'rtps_findings')
# What the board does with each finding, as it is (with mros2_pc.TALKING_PATCHES alone).
AS_IT_IS = {'acknack.txt': "the board reports: ['AddressSanitizer']",
            'acknack_base.txt': 'the board reports nothing and no longer echoes',
            'acknack_count.txt': 'the board reports nothing and no longer echoes',
            'data_fields.txt': "the board reports: ['AddressSanitizer']",
            'lease.txt': "the board reports: ['runtime error:']",
            'participant_table.txt': 'the board reports nothing and no longer echoes',
            'submessage_length.txt': 'the board reports nothing and no longer echoes'}


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
        assert (result.returncode, last) == (1, AS_IT_IS[finding])
