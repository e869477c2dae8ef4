# SPDX-License-Identifier: BSD-3-Clause
"""colcon-mros' build: setup.cfg holds everything but one step.

At install, each data file named ``*.in`` is written without the suffix,
with ``@VERSION@`` replaced by ``colcon_mros.__version__``, where the
version is written once: rosidl_generator_mros2's CMake version file.
"""

import os
import re

from setuptools import setup

try:
    from setuptools.command.install_data import install_data
except ImportError:  # setuptools before 69 uses distutils' command
    from distutils.command.install_data import install_data

HERE = os.path.dirname(os.path.abspath(__file__))
TEMPLATE_SUFFIX = '.in'


def _version():
    with open(os.path.join(HERE, 'colcon_mros', '__init__.py')) as stream:
        return re.search(r"^__version__ = '([^']+)'", stream.read(), re.M).group(1)


class InstallDataWithVersion(install_data):
    """install_data, with each *.in file rendered first into the build dir."""

    def run(self):
        rendered_dir = os.path.join(self.get_finalized_command('build').build_base, 'rendered')
        self.data_files = [(target, [self._rendered(path, rendered_dir) for path in paths])
                           for target, paths in self.data_files]
        super().run()

    @staticmethod
    def _rendered(path, rendered_dir):
        if not path.endswith(TEMPLATE_SUFFIX):
            return path
        with open(os.path.join(HERE, path)) as stream:
            text = stream.read().replace('@VERSION@', _version())
        output = os.path.join(rendered_dir, os.path.basename(path)[:-len(TEMPLATE_SUFFIX)])
        os.makedirs(rendered_dir, exist_ok=True)
        with open(output, 'w') as stream:
            stream.write(text)
        return output


setup(cmdclass={'install_data': InstallDataWithVersion})
