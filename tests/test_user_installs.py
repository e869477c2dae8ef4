"""colcon-mros installed without root, and into a venv (issue 8).

An ordinary user (nobody, through setpriv) runs `pip install --user`; a venv
made with --system-site-packages gets its own install. Each install runs its
own genmros, finds its own CMake files, and `colcon build --mros-export`
writes an mros_export.cmake that include()s that install's CMake module,
which then configures and builds a firmware. Both sit beside the system's
Debian package, which they hide for their user or venv.
"""

import os
import shutil
import subprocess

import pytest

from conftest import TEST_WS
from user_install import NOBODY, Install, copy_sources, install_as_nobody, pip_flags

FIRMWARE_CMAKE = '''\
cmake_minimum_required(VERSION 3.10)
project(user_firmware CXX)
include("{export}/mros_export.cmake")
add_executable(firmware main.cpp)
mros_import_messages(TARGET firmware EXPORT_DIR "${{MROS_EXPORT_DIR}}" TYPES mros_test_base/Vector3i)
'''
FIRMWARE_MAIN = '''\
#include <mros_test_base/Vector3i.h>
#include "message_headers.h"
int main() {
  mros_test_base::Vector3i v;
  v.x = 7;
  uint8_t buffer[64];
  return v.serialize(buffer, sizeof buffer) == 12 ? 0 : 1;
}
'''


@pytest.fixture(scope='module')
def user_install():
    install = install_as_nobody()
    yield install
    shutil.rmtree(install.root)


@pytest.fixture(scope='module')
def venv_install(tmp_path_factory):
    root = str(tmp_path_factory.mktemp('venv_install'))
    venv = os.path.join(root, 'venv')
    subprocess.run(['/usr/bin/python3', '-m', 'venv', '--system-site-packages', venv], check=True)
    install = Install(root, os.environ.get('HOME', '/root'), venv)
    install.run(['python3', '-m', 'pip', 'install'] + pip_flags() + [copy_sources(root)], root)
    return install


@pytest.fixture(params=['user', 'venv'])
def install(request):
    return request.getfixturevalue(request.param + '_install')


def test_genmros_is_the_install_own(install):
    cmake_dir = install.run(['genmros', 'cmake-dir'], install.root).stdout.strip()
    assert cmake_dir == os.path.join(install.prefix, 'share', 'genmros', 'cmake')
    assert os.path.isfile(os.path.join(cmake_dir, 'mros_generate.cmake'))
    assert install.run(['genmros', 'make-fragment'], install.root).stdout.strip() == os.path.join(
        cmake_dir, 'genmros.mk')


def test_colcon_export_points_a_firmware_at_the_install(install):
    workspace = os.path.join(install.root, 'ws_%d' % os.getpid())
    os.makedirs(os.path.join(workspace, 'src'))
    shutil.copytree(os.path.join(TEST_WS, 'src', 'mros_test_base'),
                    os.path.join(workspace, 'src', 'mros_test_base'))
    firmware = os.path.join(install.root, 'firmware_%d' % os.getpid())
    os.makedirs(firmware)
    export = os.path.join(workspace, 'mros_export')
    with open(os.path.join(firmware, 'CMakeLists.txt'), 'w') as stream:
        stream.write(FIRMWARE_CMAKE.format(export=export))
    with open(os.path.join(firmware, 'main.cpp'), 'w') as stream:
        stream.write(FIRMWARE_MAIN)
    if install.as_nobody:
        for path in (workspace, firmware):
            subprocess.run(['chown', '-R', '%d:%d' % (NOBODY, NOBODY), path], check=True)
    colcon = ['python3', '-m', 'colcon'] if not install.as_nobody else ['colcon']
    install.run(colcon + ['build', '--mros-export', export], workspace)
    with open(os.path.join(export, 'mros_export.cmake')) as stream:
        cmake_file = stream.read()
    module = os.path.join(install.prefix, 'share', 'genmros', 'cmake', 'mros_generate.cmake')
    assert 'include("%s")' % module in cmake_file
    build = os.path.join(firmware, 'build')
    install.run(['cmake', '-S', firmware, '-B', build], firmware)
    install.run(['cmake', '--build', build], firmware)
    assert install.run([os.path.join(build, 'firmware')], firmware, check=False).returncode == 0
