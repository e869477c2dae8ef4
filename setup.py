# SPDX-License-Identifier: BSD-3-Clause
"""colcon-mros' build: setup.cfg holds everything but one step.

At install, each CMake package file among the data files
(``<Name>Config.cmake``, ``<name>-config.cmake``: genmros',
rosidl_generator_mros2's) gets its version file beside it
(``<Name>Config-version.cmake``), rendered from cmake/config-version.cmake.in
with ``@VERSION@`` replaced by ``colcon_mros.__version__``, where the version
is written once; so ``find_package(genmros 0.1)`` works.
"""

import os
import re

from setuptools import setup

try:
    from setuptools.command.install_data import install_data
except ImportError:  # setuptools before 69 uses distutils' command
    from distutils.command.install_data import install_data

HERE = os.path.dirname(os.path.abspath(__file__))
VERSION_TEMPLATE = os.path.join('cmake', 'config-version.cmake.in')
_PACKAGE_FILE = re.compile(r'(.+(?:Config|-config))\.cmake$')


def _version():
    with open(os.path.join(HERE, 'colcon_mros', '__init__.py')) as stream:
        return re.search(r"^__version__ = '([^']+)'", stream.read(), re.M).group(1)


class InstallDataWithVersion(install_data):
    """install_data, with a version file rendered into the build dir beside
    each CMake package file."""

    def run(self):
        rendered_dir = os.path.join(self.get_finalized_command('build').build_base, 'rendered')
        self.data_files = [(target, paths + self._version_files(paths, rendered_dir))
                           for target, paths in self.data_files]
        super().run()

    @staticmethod
    def _version_files(paths, rendered_dir):
        with open(os.path.join(HERE, VERSION_TEMPLATE)) as stream:
            text = stream.read().replace('@VERSION@', _version())
        rendered = []
        for path in paths:
            match = _PACKAGE_FILE.match(os.path.basename(path))
            if match:
                output = os.path.join(rendered_dir, match.group(1) + '-version.cmake')
                os.makedirs(rendered_dir, exist_ok=True)
                with open(output, 'w') as stream:
                    stream.write(text)
                rendered.append(output)
        return rendered


setup(cmdclass={'install_data': InstallDataWithVersion})
