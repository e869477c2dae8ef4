"""The opt-in patch series for the user's mros2 library: the fixes as
unified diffs (``*.patch``, each named for what it fixes, its first lines
saying so) in the order of ``series``, applied, checked and reverted by
:mod:`colcon_mros.library_tools.patch_series` (``genmros mros2-harden``).
The checked receive needs genmros' message headers (their
``copyFromBuf(data, size)``)."""

import os

from colcon_mros.errors import GenmrosError
from colcon_mros.library_tools.patch_series import PatchSeries, read_series

# Every path a patch names lies below these directories of the checkout.
LIBRARY_DIRS = ('include', 'src', 'embeddedRTPS')
MROS2_SERIES = PatchSeries(os.path.dirname(os.path.abspath(__file__)), LIBRARY_DIRS)
# What an mros2 checkout has.
LIBRARY_SOURCE = os.path.join('src', 'mros2.cpp')


def mros2_patches():
    """The series' patches, in order."""
    return read_series(MROS2_SERIES)


def check_root(root):
    """root, if it is an mros2 checkout (with src/mros2.cpp); else a GenmrosError."""
    if not os.path.isfile(os.path.join(root, LIBRARY_SOURCE)):
        raise GenmrosError('no %s here: not an mros2 checkout' % LIBRARY_SOURCE, root)
    return root
