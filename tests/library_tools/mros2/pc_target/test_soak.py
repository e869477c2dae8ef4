# SPDX-License-Identifier: BSD-3-Clause
"""The soak, short (bench/mros2/soak.py runs 50 starts a case): 5 fresh starts of arm-small
(three_echoes under qemu-arm, 20 samples per topic each way) and 5 of native-large
(fragment_echo with --sanitize, 10 strings of 30 KB in fragments at a receive limit of
1472), hardened, each against a fresh plain node that sends each sample once; starts
alternate between two addresses and between board first and node first, and every sample
of every start must come back (testing/mros2_soak.py)."""

import pytest

from support import mros2_pc_boards
from testing import mros2_soak
from support.user_checkouts import MROS2_ROOT

pytestmark = [pytest.mark.needs_mros2, pytest.mark.slow]

STARTS = 5

# The fixtures, shared.
posix_root = mros2_pc_boards.posix_root
typestore = mros2_pc_boards.typestore


@pytest.mark.parametrize('name', ['arm-small', 'native-large'])
def test_every_sample_of_every_start(name, posix_root, typestore, tmp_path):
    case = mros2_soak.CASES[name]
    programs = mros2_soak.build_programs(case, posix_root, MROS2_ROOT, str(tmp_path))
    failed = []
    for index in range(STARTS):
        program = programs[mros2_soak.ADDRESSES[index % len(mros2_soak.ADDRESSES)]]
        start = mros2_soak.run_start(program, case, typestore, str(tmp_path / str(index)),
                                     index)
        if not start.passed:
            failed.append('start %d (%s, %s): %s' % (index, start.address, start.order,
                                                     start.problem))
    assert failed == []
