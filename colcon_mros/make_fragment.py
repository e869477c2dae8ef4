"""Where genmros.mk is: the make fragment that mROS v1 apps include.

pip installs it beside the CMake module (``share/genmros/cmake/``) under
whatever prefix the install used; the distribution's own record of its files
says where, so no prefix is assumed. A source checkout has it in ``cmake/``.
"""

import os
from importlib import metadata

from colcon_mros.errors import GenmrosError

FRAGMENT = 'genmros.mk'
DISTRIBUTION = 'colcon-mros'


def _checkout_fragment():
    path = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'cmake', FRAGMENT)
    return path if os.path.isfile(path) else None


def _installed_fragment():
    try:
        files = metadata.files(DISTRIBUTION) or []
    except metadata.PackageNotFoundError:
        return None
    for record in files:
        if record.name == FRAGMENT:
            path = os.path.normpath(str(record.locate()))
            if os.path.isfile(path):
                return path
    return None


def make_fragment_path():
    """The absolute path of genmros.mk, from this checkout or from the install."""
    path = _checkout_fragment() or _installed_fragment()
    if path is None:
        raise GenmrosError('%s is not installed with genmros (reinstall colcon-mros)' % FRAGMENT)
    return path
