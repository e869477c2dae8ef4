"""The opt-in patch series for the user's mROS v1 library: the fixes as
unified diffs (``*.patch``, each named for what it fixes, its first lines
saying so) in the order of ``series``, applied, checked and reverted by
:mod:`colcon_mros.library_tools.patch_series` (``genmros mros-v1-harden``,
``genmros mros-v1-pc --hardened``)."""

import os

from colcon_mros.errors import GenmrosError
from colcon_mros.library_tools.patch_series import PatchSeries, read_series

# Every path a patch names lies below this directory of the checkout.
LIBRARY_DIR = 'mros-lib'
MROS_V1_SERIES = PatchSeries(os.path.dirname(os.path.abspath(__file__)), (LIBRARY_DIR,))


def mros_v1_patches():
    """The series' patches, in order."""
    return read_series(MROS_V1_SERIES)


def check_root(root):
    """root, if it is an mROS v1 checkout (with mros-lib/); else a GenmrosError."""
    if not os.path.isdir(os.path.join(root, LIBRARY_DIR)):
        raise GenmrosError('no %s/ here: not an mROS v1 checkout' % LIBRARY_DIR, root)
    return root
