"""Where the files genmros installs beside its Python package are.

pip installs the CMake package (genmrosConfig.cmake), the CMake module
(mros_generate.cmake) and the make fragment (genmros.mk) under
``share/genmros/cmake/`` of whatever prefix the install used (/usr for
setup.sh's Debian package, /usr/local, ~/.local, a venv); the
distribution's own record of its files says where, so no prefix is
assumed. A source checkout has the module and the fragment in ``cmake/``.
"""

import os
from importlib import metadata

from colcon_mros.errors import GenmrosError

DISTRIBUTION = 'colcon-mros'
# A source checkout: the directory that holds the colcon_mros package.
REPOSITORY_ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MAKE_FRAGMENT = 'genmros.mk'
CMAKE_MODULE = 'mros_generate.cmake'
# find_package(genmros) reads it; its directory is what genmros_DIR names.
CMAKE_CONFIG = 'genmrosConfig.cmake'
# Marks share/genmros/catkin_prefix as a catkin workspace, whose
# etc/ros/genmsg/genmros registers the catkin generator once the prefix is
# on CMAKE_PREFIX_PATH.
CATKIN_MARKER = '.catkin'


def _checkout_file(name):
    path = os.path.join(REPOSITORY_ROOT, 'cmake', name)
    return path if os.path.isfile(path) else None


def _installed_file(name):
    try:
        files = metadata.files(DISTRIBUTION) or []
    except metadata.PackageNotFoundError:
        return None
    for record in files:
        if record.name == name:
            path = os.path.normpath(str(record.locate()))
            if os.path.isfile(path):
                return path
    return None


def installed_file(name):
    """The absolute path of one of genmros' CMake/make files, from this
    checkout or from the install."""
    path = _checkout_file(name) or _installed_file(name)
    if path is None:
        raise GenmrosError('%s is not installed with genmros (reinstall colcon-mros)' % name)
    return path
