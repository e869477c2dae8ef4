# SPDX-License-Identifier: BSD-3-Clause
"""genmros as a catkin message generator, with catkin_make, catkin_make_isolated
and catkin build, on fresh copies of test_ws's message packages.

Each build is checked against what `genmros mros-v1-export` writes for the same
sources: the headers exist, compile with strict flags, are byte-identical,
are installed, and are copied to MROS_EXPORT_DIR.
"""

import os
import re
import shutil

import pytest

from colcon_mros.mros_v1.aggregates import FIRMWARE_FILES
from colcon_mros.mros_v1.cpp import SUPPORT_HEADERS
from support.build_integration import (
    MESSAGE_PACKAGES, TEST_WS_SRC,
    build_firmware_of_whole_export, compile_headers, expected_header_names, genmros_export,
    genmsg_md5, genpy_default_size, headers_under, imported_firmware_output, new_workspace,
    package_headers, run, search_path_of, unwrapped, user_environment)
from testing.ros_paths import prefix_arguments, ros1_prefixes

pytestmark = pytest.mark.slow

GENMROS_INCLUDE = os.path.join('share', 'genmros', 'include')


def _add_package_copy(workspace, source_package, new_name):
    """A copy of a test_ws package under another name: a package that builds
    beside the original in parallel (nothing orders the two)."""
    target = os.path.join(workspace, 'src', new_name)
    shutil.copytree(os.path.join(workspace, 'src', source_package), target)
    for file_name in ('package.xml', 'CMakeLists.txt'):
        path = os.path.join(target, file_name)
        with open(path) as stream:
            text = stream.read()
        with open(path, 'w') as stream:
            stream.write(text.replace(source_package, new_name))


def _declare_genmros(workspace, package):
    """Declare genmros in package.xml and find_package() as a user may."""
    root = os.path.join(workspace, 'src', package)
    for file_name, old, new in (
            ('package.xml', '  <build_depend>message_generation</build_depend>',
             '  <build_depend>genmros</build_depend>\n'
             '  <build_depend>message_generation</build_depend>'),
            ('CMakeLists.txt', 'COMPONENTS message_generation',
             'COMPONENTS genmros message_generation')):
        path = os.path.join(root, file_name)
        with open(path) as stream:
            text = stream.read()
        assert old in text
        with open(path, 'w') as stream:
            stream.write(text.replace(old, new))


class Build:
    """A built workspace: where each tool put the devel and install headers."""

    def __init__(self, workspace, devel_roots, install_root, export_dir, log):
        self.workspace = workspace
        self.devel_roots = devel_roots
        self.install_root = install_root
        self.export_dir = export_dir
        self.log = log
        self.reference = genmros_export(os.path.join(workspace, 'reference'), '--workspace',
                                        workspace, *prefix_arguments(ros1_prefixes()))

    def devel_headers(self):
        headers = {}
        for root in self.devel_roots:
            headers.update(headers_under(root))
        return headers

    def packages(self):
        source = os.path.join(self.workspace, 'src')
        return sorted(name for name in os.listdir(source)
                      if os.path.isfile(os.path.join(source, name, 'package.xml')))


def _catkin_make(workspace, export_dir):
    log = run(['catkin_make', '-DMROS_EXPORT_DIR=%s' % export_dir], workspace).stdout
    log += run(['catkin_make', 'install'], workspace).stdout
    return Build(workspace, [os.path.join(workspace, 'devel', GENMROS_INCLUDE)],
                 os.path.join(workspace, 'install', GENMROS_INCLUDE), export_dir, log)


def _catkin_make_isolated(workspace, export_dir):
    log = run(['catkin_make_isolated', '--install'], workspace,
              env=user_environment(MROS_EXPORT_DIR=export_dir)).stdout
    devel = os.path.join(workspace, 'devel_isolated')
    return Build(workspace, [os.path.join(devel, package, GENMROS_INCLUDE)
                             for package in MESSAGE_PACKAGES],
                 os.path.join(workspace, 'install_isolated', GENMROS_INCLUDE), export_dir, log)


def _catkin_build(workspace, export_dir):
    # Two more packages with no dependency on each other: catkin build runs
    # them in parallel, all writing the shared devel space and export dir.
    _add_package_copy(workspace, 'mros_test_base', 'mros_parallel_a')
    _add_package_copy(workspace, 'mros_test_base', 'mros_parallel_b')
    _declare_genmros(workspace, 'mros_test_base')
    run(['catkin', 'init'], workspace)
    run(['catkin', 'config', '--install'], workspace)
    log = run(['catkin', 'build', '-j4', '-p4', '--verbose', '--no-status', '--no-notify'],
              workspace, env=user_environment(MROS_EXPORT_DIR=export_dir)).stdout
    return Build(workspace, [os.path.join(workspace, 'devel', GENMROS_INCLUDE)],
                 os.path.join(workspace, 'install', GENMROS_INCLUDE), export_dir, log)


BUILD_TOOLS = {
    'catkin_make': _catkin_make,
    'catkin_make_isolated': _catkin_make_isolated,
    'catkin build': _catkin_build,
}


@pytest.fixture(scope='module', params=sorted(BUILD_TOOLS))
def build(request, tmp_path_factory):
    workspace = new_workspace(str(tmp_path_factory.mktemp('catkin_ws')))
    return BUILD_TOOLS[request.param](workspace, os.path.join(workspace, 'mros_export'))


def test_every_type_has_a_header_in_the_devel_space(build):
    headers = build.devel_headers()
    assert set(SUPPORT_HEADERS) <= set(headers)
    for package in ('mros_test_base', 'mros_test'):
        expected = expected_header_names(package)
        assert expected <= set(headers), 'missing: %s' % sorted(expected - set(headers))
    assert 'Using these message generators: gencpp;genlisp;genmros;genpy' in build.log


def test_devel_headers_equal_genmros_export(build):
    reference = package_headers(build.reference, build.packages())
    assert build.devel_headers() == reference


def test_devel_headers_compile_with_strict_flags(build, tmp_path):
    headers = [path for path in build.devel_headers() if path not in SUPPORT_HEADERS]
    # Nested std_msgs/geometry_msgs types come from the reference export:
    # catkin generates only the workspace's packages.
    compile_headers(build.devel_roots + [build.reference], headers, str(tmp_path))


def test_devel_headers_alone_meet_gencpp_with_one_clear_line(build, tmp_path):
    # The devel space holds the workspace's types only: the std_msgs/ColorRGBA
    # that Labeled contains is found in /usr/include, and it is gencpp's.
    source = tmp_path / 'firmware.cpp'
    source.write_text('#include <mros_test_base/Labeled.h>\nint main() { return 0; }\n')
    result = run(['g++', '-std=c++11', '-fsyntax-only']
                 + ['-I' + root for root in build.devel_roots] + [str(source)],
                 str(tmp_path), check=False)
    errors = [line for line in result.stdout.splitlines() if ': error: ' in line]
    assert result.returncode != 0
    assert errors[0].endswith(
        "#error \"the std_msgs/ColorRGBA.h found first is not genmros' (gencpp's?): "
        "compile against a genmros export dir's include/, which holds every type its headers "
        "include\""), errors[0]


def test_install_space_holds_the_same_headers(build):
    assert headers_under(build.install_root) == build.devel_headers()


def test_export_dir_collects_every_package(build):
    exported = headers_under(os.path.join(build.export_dir, 'include'))
    # Every type of the workspace and every type they contain, installed
    # packages' included: what genmros mros-v1-export writes, less the per-firmware files.
    assert exported == {path: text for path, text in headers_under(build.reference).items()
                        if path not in FIRMWARE_FILES}
    assert 'std_msgs/Header.h' in exported
    assert os.path.isfile(os.path.join(build.export_dir, 'share', 'std_msgs', 'msg', 'Header.msg'))
    assert not [name for _, _, names in os.walk(build.export_dir)
                for name in names if name.startswith('.genmros-')], 'temporary files left'
    for package in build.packages():
        share = os.path.join(build.export_dir, 'share', package)
        assert os.path.isfile(os.path.join(share, 'package.xml'))
        assert sorted(os.listdir(os.path.join(share, 'msg'))) == sorted(
            os.listdir(os.path.join(build.workspace, 'src', package, 'msg')))


def test_firmware_imports_the_export_through_its_cmake_file(build, tmp_path):
    values = imported_firmware_output(build.export_dir, str(tmp_path))
    search_path = search_path_of(TEST_WS_SRC)
    assert values['md5'] == genmsg_md5('mros_test/NestedTypes', search_path)
    assert values['serialized'] == str(genpy_default_size('mros_test/NestedTypes', search_path))


def test_catkin_lint_is_clean_with_genmros_declared(tmp_path):
    workspace = new_workspace(str(tmp_path))
    _declare_genmros(workspace, 'mros_test_base')
    result = run(['catkin_lint', os.path.join(workspace, 'src')], workspace)
    assert not re.search(r': (error|warning):', result.stdout), result.stdout


def test_ros_lang_disable_turns_genmros_off(tmp_path):
    workspace = new_workspace(str(tmp_path))
    log = run(['catkin_make'], workspace,
              env=user_environment(ROS_LANG_DISABLE='genmros')).stdout
    assert 'Disabling the following message generators: genmros' in log
    assert 'Using these message generators: gencpp;genlisp;genpy\n' in log
    assert not os.path.exists(os.path.join(workspace, 'devel', 'share', 'genmros'))
    assert os.path.isfile(os.path.join(workspace, 'devel', 'include', 'mros_test',
                                       'PersonalData.h')), 'gencpp must still run'


def test_unwritable_export_dir_fails_the_configure_step(tmp_path):
    workspace = new_workspace(str(tmp_path))
    blocker = os.path.join(workspace, 'not_a_directory')
    with open(blocker, 'w') as stream:
        stream.write('a file where the export dir should go\n')
    export_dir = os.path.join(blocker, 'export')
    result = run(['catkin_make', '-DMROS_EXPORT_DIR=%s' % export_dir], workspace, check=False)
    assert result.returncode != 0
    assert ("genmros: MROS_EXPORT_DIR '%s' cannot be created: '%s' is not a directory"
            % (export_dir, blocker)) in unwrapped(result.stdout)
    assert not os.path.exists(os.path.join(workspace, 'devel', 'share', 'genmros'))


def test_export_dir_from_the_environment_holds_until_turned_off(tmp_path):
    """MROS_EXPORT_DIR=DIR catkin build: a later build that reconfigures
    without the variable (a CMakeLists.txt edit) still fills the export; the
    export stops with -DMROS_EXPORT_DIR=, and the variable alone does not
    bring it back, saying so."""
    workspace = str(tmp_path / 'ws')
    shutil.copytree(os.path.join(TEST_WS_SRC, 'mros_test_base'),
                    os.path.join(workspace, 'src', 'mros_test_base'))
    package = os.path.join(workspace, 'src', 'mros_test_base')
    export_dir = str(tmp_path / 'export')
    build = ['catkin', 'build', '--no-status', '--no-notify', '--verbose']
    run(['catkin', 'init'], workspace)
    run(build, workspace, env=user_environment(MROS_EXPORT_DIR=export_dir))
    exported = os.path.join(export_dir, 'include', 'mros_test_base')
    assert sorted(os.listdir(exported)) == ['Labeled.h', 'Vector3i.h']

    def replace_message(old, new):
        os.remove(os.path.join(package, 'msg', old + '.msg'))
        with open(os.path.join(package, 'msg', new + '.msg'), 'w') as stream:
            stream.write('int32 value\n')
        with open(os.path.join(package, 'CMakeLists.txt')) as stream:
            text = stream.read()
        with open(os.path.join(package, 'CMakeLists.txt'), 'w') as stream:
            stream.write(text.replace(old + '.msg', new + '.msg'))

    replace_message('Labeled', 'Added')
    log = run(build, workspace).stdout
    assert 'Generating mROS headers from mros_test_base/Added.msg' in log
    assert sorted(os.listdir(exported)) == ['Added.h', 'Vector3i.h']

    run(build + ['--cmake-args', '-DMROS_EXPORT_DIR='], workspace)
    replace_message('Added', 'Later')
    log = run(build + ['--force-cmake'], workspace,
              env=user_environment(MROS_EXPORT_DIR=export_dir)).stdout
    assert ("genmros: MROS_EXPORT_DIR in the environment ('%s') is ignored" % export_dir
            in unwrapped(log))
    assert os.path.isfile(os.path.join(workspace, 'devel',
                          GENMROS_INCLUDE, 'mros_test_base', 'Later.h'))
    assert sorted(os.listdir(exported)) == ['Added.h', 'Vector3i.h']


def test_a_firmware_imports_the_whole_export_with_its_services(build, tmp_path):
    types = build_firmware_of_whole_export(build.export_dir, str(tmp_path))
    assert {'mros_test/LookupPerson', 'mros_test/LookupPersonRequest',
            'mros_test/LookupPersonResponse', 'std_msgs/Header'} <= set(types)
