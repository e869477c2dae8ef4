# SPDX-License-Identifier: BSD-3-Clause
"""colcon-mros installed without root, and into a venv.

An ordinary user (nobody, through setpriv) runs `pip install --user`; a venv
made with --system-site-packages gets its own install. Each install runs its
own genmros, finds its own CMake files, and `colcon build --mros-export`
writes an mros_export.cmake that include()s that install's CMake module,
which then configures and builds a firmware. Both sit beside the system's
Debian package, which they hide for their user or venv. The venv's genmros
also builds and runs an mROS v1 app with the PC target it installed.
"""

import os
import shutil
import subprocess

import pytest

from testing.ros_graph import Board, RosGraph
from support.user_checkouts import MROS_V1_ROOT
from support.checkout import REPO, TEST_WS
from support.user_install import NOBODY, Install, copy_sources, install_as_nobody, pip_flags

pytestmark = pytest.mark.slow

FIRMWARE_CMAKE = '''\
cmake_minimum_required(VERSION 3.10)
project(user_firmware CXX)
include("{export}/mros_export.cmake")
add_executable(firmware main.cpp)
mros_import_messages(TARGET firmware EXPORT_DIR "${{MROS_EXPORT_DIR}}" TYPES mros_test_base/Vector3i)
'''  # noqa: E501
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


@pytest.mark.needs_mros_v1
def test_the_pc_target_builds_and_runs_an_app_from_the_installed_package(venv_install, tmp_path):
    mros_root = MROS_V1_ROOT
    output = str(tmp_path / 'string_pubsub')
    built = venv_install.run(['genmros', 'mros-v1-pc', '--build-only', '-v', '--target', 'native',
                              '-j2', '-o', output,
                              os.path.join(mros_root, 'mros_ws', 'string_pubsub')],
                             venv_install.root)
    # The target's files, and the program, come from the venv's package.
    installed_target = venv_install.run(
        ['python3', '-c', 'import colcon_mros.library_tools.mros_v1.pc_target as t, os; '
                          'print(os.path.dirname(t.__file__))'], venv_install.root).stdout.strip()
    assert installed_target.startswith(venv_install.prefix + os.sep)
    assert '-I%s/asp' % installed_target in built.stdout, built.stdout[-3000:]
    assert REPO not in built.stdout
    program = os.path.join(output, 'string_pubsub')
    assert built.stdout.rstrip().endswith('run it with ROS_MASTER_URI and ROS_IP set: ' + program)
    with RosGraph() as graph:
        Board(graph, program, str(tmp_path), runner=[])
        graph.wait_for_graph(publishers=[('/mros_msg', '/mros_node')],
                             subscribers=[('/test_string', '/mros_node2')])
