"""The mROS v1 patch series' file: it names the library commit its patches
are made for, and every patch it lists is read (names, descriptions and the
files each changes, all below mros-lib/), without a checkout."""

import os
import re

from colcon_mros.library_tools.mros_v1.patches import MROS_V1_SERIES, mros_v1_patches
from colcon_mros.library_tools.patch_series import SERIES


def test_the_series_header_names_the_library_commit():
    with open(os.path.join(MROS_V1_SERIES.directory, SERIES)) as stream:
        header = ''.join(line for line in stream if line.startswith('#'))
    assert 'mROS-base/mROS' in header
    assert re.search(r'\bcommit 741b884 \(741b8840b8a0394233942086688e1a98ec267bc6\)', header)


def test_every_listed_patch_is_read_with_what_it_fixes():
    patches = mros_v1_patches()
    assert len(patches) == 18
    for patch in patches:
        assert patch.description, patch.name
        assert patch.files and all(path.startswith('mros-lib/') for path in patch.files)
