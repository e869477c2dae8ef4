# SPDX-License-Identifier: BSD-3-Clause
"""colcon build --mros-export DIR on a fresh copy of test_ws's message packages.

DIR sits inside the workspace, where a user is likely to put it; the second
build in the module also shows that colcon does not take DIR/share for
packages. The steps share one workspace and run in file order. The last
test builds ROS 2 interface packages, one without the mros2 generator.
"""

import os
import shutil

import pytest

from support.checkout_install import checkout_install
from support.checkout import REPO
from testing.ros_paths import prefix_arguments, ros1_prefixes

from colcon_mros.mros_v1.cpp import SUPPORT_HEADERS
from support.build_integration import (
    MESSAGE_PACKAGES, TEST_WS_SRC,
    build_firmware_of_whole_export, compile_headers, expected_header_names, genmros_export,
    genmsg_md5, genpy_default_size, headers_under, imported_firmware_output, mtimes,
    new_workspace, run, search_path_of, unwrapped, user_environment)

# cmake, colcon, catkin or make builds: more than half a minute.
pytestmark = pytest.mark.slow

# The packages the export holds: the built ones and the installed message
# packages they depend on.
EXPORTED_PACKAGES = ('geometry_msgs', 'mros_test', 'mros_test_base', 'std_msgs')


class Workspace:
    def __init__(self, root):
        self.root = new_workspace(root)
        self.export_dir = os.path.join(root, 'mros_export')
        self.include = os.path.join(self.export_dir, 'include')

    def colcon_build(self, *arguments, check=True):
        return run(['colcon', 'build', '--event-handlers', 'console_direct+'] + list(arguments),
                   self.root, check=check)

    def reference(self, output_dir):
        arguments = (['--workspace', self.root, '--only', 'headers']
                     + prefix_arguments(ros1_prefixes()))
        for package in EXPORTED_PACKAGES:
            arguments += ['--package', package]
        return genmros_export(output_dir, *arguments)


@pytest.fixture(scope='module')
def workspace(tmp_path_factory):
    workspace = Workspace(str(tmp_path_factory.mktemp('colcon_ws')))
    workspace.colcon_build('--mros-export', workspace.export_dir)
    return workspace


def test_colcon_build_help_lists_the_flag():
    help_text = run(['colcon', 'build', '--help'], '/').stdout
    assert '--mros-export DIR' in help_text


def test_export_holds_every_built_type_and_its_installed_dependencies(workspace):
    headers = headers_under(workspace.include)
    assert set(SUPPORT_HEADERS) <= set(headers)
    for package in MESSAGE_PACKAGES:
        assert expected_header_names(package) <= set(headers)
    assert os.path.join('std_msgs', 'Header.h') in headers
    assert os.path.join('geometry_msgs', 'Twist.h') in headers
    assert 'message_headers.h' not in headers, 'aggregates are per firmware'


def test_export_equals_genmros_export(workspace, tmp_path):
    assert headers_under(workspace.include) == headers_under(workspace.reference(str(tmp_path)))


def test_exported_headers_compile_with_strict_flags(workspace, tmp_path):
    headers = [path for path in headers_under(workspace.include)
               if path.split(os.sep)[0] in MESSAGE_PACKAGES]
    compile_headers([workspace.include], headers, str(tmp_path))


def test_cmake_file_lists_the_types_and_definitions_are_exported(workspace):
    with open(os.path.join(workspace.export_dir, 'mros_export.cmake')) as stream:
        cmake_file = stream.read()
    for type_name in ('mros_test/PersonalData', 'mros_test/LookupPerson', 'std_msgs/Header'):
        assert '\n  %s\n' % type_name in cmake_file
    for package in EXPORTED_PACKAGES:
        assert os.path.isfile(os.path.join(workspace.export_dir, 'share', package, 'package.xml'))
    assert os.path.isfile(os.path.join(workspace.export_dir, 'share', 'mros_test', 'srv',
                                       'LookupPerson.srv'))


def test_firmware_imports_the_export_through_its_cmake_file(workspace, tmp_path):
    values = imported_firmware_output(workspace.export_dir, str(tmp_path))
    search_path = search_path_of(TEST_WS_SRC)
    assert values['md5'] == genmsg_md5('mros_test/NestedTypes', search_path)
    assert values['serialized'] == str(genpy_default_size('mros_test/NestedTypes', search_path))


def test_build_without_the_flag_leaves_the_export_alone(workspace):
    cmake_file = os.path.join(workspace.export_dir, 'mros_export.cmake')
    before = mtimes(workspace.include), os.stat(cmake_file).st_mtime_ns
    workspace.colcon_build()
    assert (mtimes(workspace.include), os.stat(cmake_file).st_mtime_ns) == before


def test_second_run_updates_the_export(workspace):
    source = os.path.join(workspace.root, 'src', 'mros_test')
    with open(os.path.join(source, 'msg', 'PersonalData.msg'), 'a') as stream:
        stream.write('float32 height_m\n')
    os.remove(os.path.join(source, 'msg', 'Constants.msg'))
    cmake_lists = os.path.join(source, 'CMakeLists.txt')
    with open(cmake_lists) as stream:
        text = stream.read()
    with open(cmake_lists, 'w') as stream:
        stream.write(text.replace('  Constants.msg\n', ''))
    unchanged = os.path.join('mros_test_base', 'Vector3i.h')
    before = mtimes(workspace.include)

    workspace.colcon_build('--mros-export', workspace.export_dir)
    headers = headers_under(workspace.include)
    assert b'height_m' in headers[os.path.join('mros_test', 'PersonalData.h')]
    assert os.path.join('mros_test', 'Constants.h') not in headers
    assert not os.path.exists(os.path.join(workspace.export_dir, 'share', 'mros_test', 'msg',
                                           'Constants.msg'))
    assert mtimes(workspace.include)[unchanged] == before[unchanged]


def test_a_build_that_changed_no_definition_leaves_the_export_as_it_is(workspace):
    cmake_file = os.path.join(workspace.export_dir, 'mros_export.cmake')
    before = mtimes(workspace.include), os.stat(cmake_file).st_mtime_ns
    result = workspace.colcon_build('--mros-export', workspace.export_dir)
    assert 'genmros: the export in %s is up to date' % workspace.export_dir in result.stdout
    assert (mtimes(workspace.include), os.stat(cmake_file).st_mtime_ns) == before

    # A new definition in a package is exported, as the others stay.
    source = os.path.join(workspace.root, 'src', 'mros_test_base')
    with open(os.path.join(source, 'msg', 'Scale.msg'), 'w') as stream:
        stream.write('float64 factor\n')
    cmake_lists = os.path.join(source, 'CMakeLists.txt')
    with open(cmake_lists) as stream:
        text = stream.read()
    with open(cmake_lists, 'w') as stream:
        stream.write(text.replace('  Vector3i.msg\n', '  Vector3i.msg\n  Scale.msg\n'))
    result = workspace.colcon_build('--mros-export', workspace.export_dir)
    assert 'up to date' not in result.stdout
    assert b'double factor;' in headers_under(workspace.include)[
        os.path.join('mros_test_base', 'Scale.h')]


def test_selected_packages_add_to_the_export_and_never_shrink_it(workspace):
    with open(os.path.join(workspace.export_dir, 'mros_export.cmake')) as stream:
        before = stream.read()
    run(['colcon', 'build', '--packages-select', 'mros_test_base', '--mros-export',
         workspace.export_dir],
        workspace.root)
    with open(os.path.join(workspace.export_dir, 'mros_export.cmake')) as stream:
        after = stream.read()
    assert after == before
    for type_name in ('mros_test/PersonalData', 'mros_test_base/Vector3i', 'std_msgs/Header'):
        assert '\n  %s\n' % type_name in after
    assert os.path.isfile(os.path.join(workspace.include, 'mros_test', 'PersonalData.h'))


def test_unwritable_export_dir_fails_before_building(tmp_path):
    workspace = Workspace(str(tmp_path / 'ws'))
    blocker = os.path.join(workspace.root, 'not_a_directory')
    with open(blocker, 'w') as stream:
        stream.write('a file where the export dir should go\n')
    export_dir = os.path.join(blocker, 'export')
    result = workspace.colcon_build('--mros-export', export_dir, check=False)
    assert result.returncode != 0
    assert ('genmros: error: %s: output directory is not a directory: %s'
            % (export_dir, blocker)) in unwrapped(result.stdout)
    assert not os.path.exists(os.path.join(workspace.root, 'install', 'mros_test'))


def test_a_firmware_imports_the_whole_export_with_its_services(workspace, tmp_path):
    types = build_firmware_of_whole_export(workspace.export_dir, str(tmp_path))
    assert {'mros_test/LookupPerson', 'mros_test/LookupPersonRequest',
            'mros_test/LookupPersonResponse', 'std_msgs/Header'} <= set(types)


# An interface package as Debian 12 lets one be written without the mros2
# generator: rosidl_generator_cpp alone, and rosidl_cmake for
# rosidl_generate_interfaces() (no rosidl_default_generators there to find
# generators in the ament index), so the mros2 generator never runs for it.
PLAIN_CMAKE = '''cmake_minimum_required(VERSION 3.16)
project(mros2_plain_msgs)
find_package(ament_cmake REQUIRED)
find_package(rosidl_cmake REQUIRED)
find_package(rosidl_generator_cpp REQUIRED)
rosidl_generate_interfaces(${PROJECT_NAME} "msg/Plain.msg")
ament_package()
'''


def test_a_ros2_package_built_without_the_mros2_generator_is_named_with_the_fix(tmp_path):
    root = str(tmp_path / 'ws')
    ros2_src = os.path.join(REPO, 'test_ws_ros2', 'src')
    shutil.copytree(os.path.join(ros2_src, 'mros2_base_msgs'),
                    os.path.join(root, 'src', 'mros2_base_msgs'))
    plain = os.path.join(root, 'src', 'mros2_plain_msgs')
    os.makedirs(os.path.join(plain, 'msg'))
    with open(os.path.join(ros2_src, 'mros2_base_msgs', 'package.xml')) as stream:
        manifest = stream.read().replace('mros2_base_msgs', 'mros2_plain_msgs').replace(
            '  <buildtool_depend>rosidl_generator_mros2</buildtool_depend>\n', '')
    for name, text in (('package.xml', manifest), ('CMakeLists.txt', PLAIN_CMAKE),
                       (os.path.join('msg', 'Plain.msg'), 'int32 value\n')):
        with open(os.path.join(plain, name), 'w') as stream:
            stream.write(text)
    export_dir = os.path.join(root, 'mros_export')
    # A Debian 12 user's environment: no AMENT_PREFIX_PATH names the generator.
    env = user_environment(AMENT_PREFIX_PATH=None)
    result = run(['colcon', 'build', '--merge-install', '--event-handlers', 'console_direct+',
                  '--mros-export', export_dir], root, env=env)
    warnings = [line for line in result.stdout.splitlines()
                if line.startswith('genmros: warning: ')]
    assert warnings == [
        'genmros: warning: mros2_plain_msgs was built without the mros2 generator (its install '
        'has no mros2 headers; they are exported all the same): add '
        'find_package(rosidl_generator_mros2 REQUIRED) before rosidl_generate_interfaces() in '
        '%s, or put %s on AMENT_PREFIX_PATH'
        % (os.path.join(plain, 'CMakeLists.txt'), checkout_install().prefix)], result.stdout
    install = os.path.join(root, 'install')
    assert os.path.isfile(os.path.join(install, 'include', 'mros2_base_msgs', 'mros2',
                                       'mros2_base_msgs', 'msg', 'stamp.hpp'))
    assert not os.path.exists(os.path.join(install, 'include', 'mros2_plain_msgs', 'mros2'))
    # Its headers are exported all the same, made from its sources.
    include = os.path.join(export_dir, 'mros2', 'include')
    for relative in (('mros2_plain_msgs', 'msg', 'plain.hpp'),
                     ('mros2_base_msgs', 'msg', 'stamp.hpp')):
        assert os.path.isfile(os.path.join(include, *relative)), relative

    # A second build, the generator found: the line is gone.
    with open(os.path.join(plain, 'CMakeLists.txt'), 'w') as stream:
        stream.write(PLAIN_CMAKE.replace(
            'find_package(rosidl_generator_cpp REQUIRED)\n',
            'find_package(rosidl_generator_cpp REQUIRED)\n'
            'find_package(rosidl_generator_mros2 REQUIRED)\n'))
    result = run(['colcon', 'build', '--merge-install', '--event-handlers', 'console_direct+',
                  '--mros-export', export_dir], root, env=env)
    assert 'genmros: warning: ' not in result.stdout
    assert os.path.isfile(os.path.join(install, 'include', 'mros2_plain_msgs', 'mros2',
                                       'mros2_plain_msgs', 'msg', 'plain.hpp'))
