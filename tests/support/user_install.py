# SPDX-License-Identifier: BSD-3-Clause
"""Installing colcon-mros outside the system package, for the tests that do
(test_user_installs.py, test_install.py, test_noetic_layout.py): a copy of
the sources to build from, and one install and how to run a command with it."""

import os
import shutil
import subprocess
import sys
import tempfile

from support.checkout import REPO


NOBODY = 65534


class Install:
    """One install of colcon-mros: how to run a command with it."""

    def __init__(self, root, home, prefix, as_nobody=False):
        self.root = root
        self.home = home
        self.prefix = prefix  # where pip put bin/ and share/
        self.as_nobody = as_nobody

    def run(self, command, cwd, check=True, bin_on_path=True, **variables):
        """command with only HOME, PATH (the install's bin/ first, unless
        bin_on_path is false: ~/.local/bin before the next login) and
        variables set."""
        path = '/usr/bin:/bin'
        if bin_on_path:
            path = '%s:%s' % (os.path.join(self.prefix, 'bin'), path)
        environment = ['HOME=%s' % self.home, 'PATH=%s' % path]
        environment += ['%s=%s' % item for item in sorted(variables.items())]
        prefix = ['env', '-i'] + environment
        if self.as_nobody:
            prefix = ['setpriv', '--reuid=%d' % NOBODY, '--regid=%d' %
                      NOBODY, '--clear-groups'] + prefix
        result = subprocess.run(prefix + command, cwd=cwd, capture_output=True, text=True)
        if check:
            assert result.returncode == 0, ' '.join(
                command) + '\n' + (result.stdout + result.stderr)[-3000:]
        return result


def copy_sources(root):
    source = os.path.join(root, 'source')
    shutil.copytree(REPO, source, ignore=shutil.ignore_patterns('.git', 'build', '*.egg-info'))
    return source


def pip_flags():
    flags = ['--quiet', '--no-deps', '--no-build-isolation']
    help_text = subprocess.run([sys.executable, '-m', 'pip', 'install', '--help'],
                               capture_output=True, text=True).stdout
    return flags + (['--break-system-packages'] if '--break-system-packages' in help_text else [])


def install_as_nobody():
    """colcon-mros installed with `pip install --user` by the user nobody,
    in a home of its own under /tmp (remove install.root when done)."""
    root = tempfile.mkdtemp(prefix='genmros-user-')
    home = os.path.join(root, 'home')
    os.mkdir(home)
    source = copy_sources(root)
    subprocess.run(['chown', '-R', '%d:%d' % (NOBODY, NOBODY), root], check=True)
    install = Install(root, home, os.path.join(home, '.local'), as_nobody=True)
    install.run(['/usr/bin/python3', '-m', 'pip', 'install',
                '--user'] + pip_flags() + [source], root)
    return install
