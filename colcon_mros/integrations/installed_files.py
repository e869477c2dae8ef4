# SPDX-License-Identifier: BSD-3-Clause
"""Where the files genmros installs beside its Python package are.

An install puts the CMake package (genmrosConfig.cmake), the CMake module
(mros_generate.cmake), the make fragment (genmros.mk) and the catkin prefix
under ``share/genmros/`` of the prefix its Python package went into: /usr
for setup.sh's Debian package (``/usr/lib/python3/dist-packages``),
/usr/local, ~/.local, a venv (``<prefix>/lib/pythonX.Y/site-packages``).
The prefix is found from where this package is, three directories above
its site directory, so no prefix is assumed and no install record is
needed (the Debian package, built by pybuild, keeps none). A source
checkout has the module and the fragment in ``cmake/``.
"""

import os

from colcon_mros.errors import GenmrosError

# A source checkout: the directory that holds the colcon_mros package; in
# an install, its site directory.
REPOSITORY_ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MAKE_FRAGMENT = 'genmros.mk'
CMAKE_MODULE = 'mros_generate.cmake'
# find_package(genmros) reads it; its directory is what genmros_DIR names.
CMAKE_CONFIG = 'genmrosConfig.cmake'
# Marks share/genmros/catkin_prefix as a catkin workspace, whose
# etc/ros/genmsg/genmros registers the catkin generator once the prefix is
# on CMAKE_PREFIX_PATH.
CATKIN_MARKER = '.catkin'
# Where each is below the install prefix.
INSTALLED_PATHS = {
    MAKE_FRAGMENT: ('share', 'genmros', 'cmake', MAKE_FRAGMENT),
    CMAKE_MODULE: ('share', 'genmros', 'cmake', CMAKE_MODULE),
    CMAKE_CONFIG: ('share', 'genmros', 'cmake', CMAKE_CONFIG),
    CATKIN_MARKER: ('share', 'genmros', 'catkin_prefix', CATKIN_MARKER),
}
# <prefix>/lib/python3/dist-packages, <prefix>/lib/pythonX.Y/site-packages.
_SITE_DEPTH = 3


def _checkout_file(name):
    path = os.path.join(REPOSITORY_ROOT, 'cmake', name)
    return path if os.path.isfile(path) else None


def install_prefix():
    """The prefix this package's install went into (for a source checkout:
    a directory above it, where nothing of genmros is)."""
    prefix = REPOSITORY_ROOT
    for _ in range(_SITE_DEPTH):
        prefix = os.path.dirname(prefix)
    return prefix


def _installed_file(name):
    path = os.path.join(install_prefix(), *INSTALLED_PATHS[name])
    return path if os.path.isfile(path) else None


def installed_file(name):
    """The absolute path of one of genmros' CMake/make files, from this
    checkout or from the install."""
    path = _checkout_file(name) or _installed_file(name)
    if path is None:
        raise GenmrosError('%s is not installed with genmros (reinstall colcon-mros)' % name)
    return path
