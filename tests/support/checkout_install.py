# SPDX-License-Identifier: BSD-3-Clause
"""This checkout installed as a user installs it (pip), once per test run, in
a temporary prefix: the builds the tests run (catkin, colcon, the firmware's
CMake) use the code being edited, not the Debian package setup.sh
installed. tests/install/test_install.py checks that package on its own."""

import atexit
import functools
import os
import shutil
import subprocess
import tempfile

from support.user_install import copy_sources, pip_flags


class CheckoutInstall:
    """Where pip put the checkout: bin/, share/genmros/ and the Python package."""

    def __init__(self, prefix, site_packages):
        self.prefix = prefix
        self.bin = os.path.join(prefix, 'bin')
        self.site_packages = site_packages
        self.catkin_prefix = os.path.join(prefix, 'share', 'genmros', 'catkin_prefix')

    def environment(self, base):
        """base with this install first: genmros on PATH, its package on
        PYTHONPATH, and its catkin prefix (the generator marker) and its
        CMake package on CMAKE_PREFIX_PATH."""
        environment = dict(base)
        for name, first in (('PATH', self.bin), ('PYTHONPATH', self.site_packages),
                            ('CMAKE_PREFIX_PATH', self.catkin_prefix + os.pathsep + self.prefix)):
            rest = environment.get(name)
            environment[name] = first + (os.pathsep + rest if rest else '')
        return environment


@functools.lru_cache(maxsize=None)
def checkout_install():
    """The CheckoutInstall of this run (removed when the process exits)."""
    root = tempfile.mkdtemp(prefix='genmros-checkout-')
    atexit.register(shutil.rmtree, root, True)
    source = copy_sources(root)
    target = os.path.join(root, 'install')
    subprocess.run(['/usr/bin/python3', '-m', 'pip', 'install', '--prefix', target] + pip_flags()
                   + [source], check=True, capture_output=True)
    # Debian's pip puts a --prefix install under <prefix>/local. The first
    # share/genmros found is the prefix's (os.walk goes top-down); the catkin
    # prefix inside it has one too.
    prefix = None
    for directory, names, _ in os.walk(target):
        if 'colcon_mros' in names:
            site_packages = directory
        if os.path.basename(directory) == 'share' and 'genmros' in names and prefix is None:
            prefix = os.path.dirname(directory)
    return CheckoutInstall(prefix, site_packages)
