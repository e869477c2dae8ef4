# SPDX-License-Identifier: BSD-3-Clause
"""Rebuilds with genmros in catkin: nothing runs when nothing changed, a
touched .msg regenerates its type and the types that include it, an edited
.msg reaches the devel space and the export dir, a removed export dir comes
back, a deleted .msg loses its headers in both, a type that no definition
contains any more leaves the export dir, and a broken .msg stops its package
only, whose headers stay as they were. catkin runs one genmros process per
package, and after an edit it generates only the files whose definitions
changed (a package of eight messages shows it, with make and with ninja).

The steps share one catkin_make workspace and run in file order.
"""

import os
import shutil
import time

import pytest

from support.build_integration import (
    GENERATOR_LOG_LINE, MESSAGE_PACKAGES, genmros_export, headers_under, mtimes,
    new_workspace, run)
from testing.ros_paths import prefix_arguments, ros1_prefixes

pytestmark = pytest.mark.slow

# Types that contain mros_test_base/Vector3i, directly or through another type.
VECTOR3I_HEADERS = {
    os.path.join('mros_test_base', 'Vector3i.h'),
    os.path.join('mros_test', 'ArrayTypes.h'),
    os.path.join('mros_test', 'NestedTypes.h'),
}


class Workspace:
    def __init__(self, root):
        self.root = new_workspace(root)
        self.export_dir = os.path.join(root, 'mros_export')
        self.devel = os.path.join(root, 'devel', 'share', 'genmros', 'include')

    def source(self, *parts):
        return os.path.join(self.root, 'src', *parts)

    def build(self):
        return run(['catkin_make', '-DMROS_EXPORT_DIR=%s' % self.export_dir], self.root).stdout

    def edit(self, relative_path, old, new):
        path = self.source(relative_path)
        with open(path) as stream:
            text = stream.read()
        assert old in text
        with open(path, 'w') as stream:
            stream.write(text.replace(old, new))


def _generated_types(log):
    return sorted(line.split(GENERATOR_LOG_LINE)[1].strip()
                  for line in log.splitlines() if GENERATOR_LOG_LINE in line)


@pytest.fixture(scope='module')
def workspace(tmp_path_factory):
    workspace = Workspace(str(tmp_path_factory.mktemp('incremental_ws')))
    workspace.build()
    return workspace


def test_rebuild_without_changes_runs_no_generator(workspace):
    before = mtimes(workspace.devel)
    log = workspace.build()
    assert _generated_types(log) == []
    assert mtimes(workspace.devel) == before


def test_touched_msg_regenerates_its_type_and_the_types_including_it(workspace):
    before = mtimes(workspace.devel)
    exported_before = mtimes(os.path.join(workspace.export_dir, 'include'))
    time.sleep(0.01)
    os.utime(workspace.source('mros_test_base', 'msg', 'Vector3i.msg'))
    log = workspace.build()
    assert _generated_types(log) == ['mros_test/ArrayTypes.msg', 'mros_test/NestedTypes.msg',
                                     'mros_test_base/Vector3i.msg']
    after = mtimes(workspace.devel)
    changed = {path for path in before if after[path] != before[path]}
    assert changed == VECTOR3I_HEADERS
    exported_after = mtimes(os.path.join(workspace.export_dir, 'include'))
    changed = {path for path in exported_before if exported_after[path] != exported_before[path]}
    assert changed == VECTOR3I_HEADERS


def test_edited_msg_reaches_devel_space_and_export_dir(workspace, tmp_path):
    workspace.edit(os.path.join('mros_test', 'msg', 'PersonalData.msg'),
                   'int32 score', 'int32 score\nfloat32 height_m')
    log = workspace.build()
    assert 'mros_test/PersonalData.msg' in _generated_types(log)
    reference = genmros_export(str(tmp_path), '--workspace', workspace.root,
                               *prefix_arguments(ros1_prefixes()))
    header = os.path.join('mros_test', 'PersonalData.h')
    expected = headers_under(reference)[header]
    assert b'height_m' in expected
    assert headers_under(workspace.devel)[header] == expected
    assert headers_under(os.path.join(workspace.export_dir, 'include'))[header] == expected


def test_export_dir_removed_by_hand_comes_back_on_the_next_build(workspace):
    before = headers_under(os.path.join(workspace.export_dir, 'include'))
    shutil.rmtree(workspace.export_dir)
    workspace.build()
    assert headers_under(os.path.join(workspace.export_dir, 'include')) == before
    for package in MESSAGE_PACKAGES:
        assert os.path.isfile(os.path.join(workspace.export_dir, 'share', package, 'package.xml'))


def test_deleted_msg_loses_its_headers_and_definition(workspace):
    os.remove(workspace.source('mros_test', 'msg', 'Constants.msg'))
    workspace.edit(os.path.join('mros_test', 'CMakeLists.txt'), '  Constants.msg\n', '')
    workspace.build()
    header = os.path.join('mros_test', 'Constants.h')
    for root in (workspace.devel, os.path.join(workspace.export_dir, 'include')):
        headers = headers_under(root)
        assert header not in headers
        assert os.path.join('mros_test', 'BuiltinTypes.h') in headers
    exported_msgs = os.listdir(os.path.join(workspace.export_dir, 'share', 'mros_test', 'msg'))
    assert 'Constants.msg' not in exported_msgs
    assert 'BuiltinTypes.msg' in exported_msgs


def _exported(workspace):
    """The export dir's headers and definitions, relative to it."""
    found = set()
    for part in ('include', 'share'):
        for directory, _, names in os.walk(os.path.join(workspace.export_dir, part)):
            found.update(os.path.relpath(os.path.join(directory, name), workspace.export_dir)
                         for name in names)
    return found


COLOR_RGBA = {os.path.join('include', 'std_msgs', 'ColorRGBA.h'),
              os.path.join('share', 'std_msgs', 'msg', 'ColorRGBA.msg')}
STILL_NEEDED = {os.path.join('include', 'std_msgs', 'Header.h'),
                os.path.join('share', 'std_msgs', 'msg', 'Header.msg'),
                os.path.join('share', 'std_msgs', 'package.xml')}


def test_type_no_longer_contained_leaves_the_export_dir(workspace):
    # Only Labeled contains std_msgs/ColorRGBA; NestedTypes keeps std_msgs/Header.
    assert COLOR_RGBA | STILL_NEEDED <= _exported(workspace)
    workspace.edit(os.path.join('mros_test_base', 'msg', 'Labeled.msg'),
                   'std_msgs/ColorRGBA color', 'uint32 color')
    workspace.build()
    exported = _exported(workspace)
    assert not COLOR_RGBA & exported
    assert STILL_NEEDED <= exported
    assert os.path.join('include', 'mros_test', 'ArrayTypes.h') in exported


def test_type_of_a_deleted_msg_leaves_the_export_dir(workspace):
    with open(workspace.source('mros_test', 'msg', 'Painted.msg'), 'w') as stream:
        stream.write('std_msgs/ColorRGBA paint\n')
    workspace.edit(os.path.join('mros_test', 'CMakeLists.txt'),
                   '  Empty.msg\n', '  Empty.msg\n  Painted.msg\n')
    workspace.build()
    assert COLOR_RGBA <= _exported(workspace)
    os.remove(workspace.source('mros_test', 'msg', 'Painted.msg'))
    workspace.edit(os.path.join('mros_test', 'CMakeLists.txt'), '  Painted.msg\n', '')
    log = workspace.build()
    exported = _exported(workspace)
    assert not COLOR_RGBA & exported
    assert os.path.join('include', 'mros_test', 'Painted.h') not in exported
    assert STILL_NEEDED <= exported
    assert 'genmros: removed %s' % os.path.join(
        workspace.export_dir, 'include', 'std_msgs', 'ColorRGBA.h') in log


EIGHT_MESSAGES = {'msg/M%d.msg' %
                  index: 'uint32 value_%d\nstring label\n' % index for index in range(8)}
EIGHT_MESSAGES['msg/M4.msg'] = 'M3 inner\nuint32 value_4\n'  # M4 contains M3
EIGHT_CMAKE = '''cmake_minimum_required(VERSION 3.0.2)
project(eight)
find_package(catkin REQUIRED COMPONENTS message_generation std_msgs)
add_message_files(DIRECTORY msg)
generate_messages(DEPENDENCIES std_msgs)
catkin_package(CATKIN_DEPENDS message_runtime)
'''
EIGHT_PACKAGE = '''<?xml version="1.0"?>
<package format="2">
  <name>eight</name><version>0.0.1</version><description>Eight messages.</description>
  <maintainer email="dev@colcon-mros.invalid">colcon-mros developers</maintainer>
  <license>BSD</license><buildtool_depend>catkin</buildtool_depend>
  <build_depend>message_generation</build_depend><depend>std_msgs</depend>
  <exec_depend>message_runtime</exec_depend>
</package>
'''


@pytest.mark.parametrize('generator', ['make', 'ninja'])
def test_one_run_per_package_rewrites_only_the_headers_whose_text_changes(tmp_path, generator):
    root = str(tmp_path)
    package = os.path.join(root, 'src', 'eight')
    os.makedirs(os.path.join(package, 'msg'))
    for relative, text in dict(EIGHT_MESSAGES, **{'CMakeLists.txt': EIGHT_CMAKE,
                                                  'package.xml': EIGHT_PACKAGE}).items():
        with open(os.path.join(package, relative), 'w') as stream:
            stream.write(text)
    export_dir = os.path.join(root, 'mros_export')
    build = ['catkin_make', '-DMROS_EXPORT_DIR=%s' % export_dir]
    if generator == 'ninja':
        build.insert(1, '--use-ninja')
    log = run(build, root).stdout
    assert log.count('Generating mROS headers for package eight') == 1  # one genmros run
    assert len(_generated_types(log)) == 8
    devel = os.path.join(root, 'devel', 'share', 'genmros', 'include')
    exported = os.path.join(export_dir, 'include')
    before = mtimes(devel), mtimes(exported)
    time.sleep(0.01)
    with open(os.path.join(package, 'msg', 'M3.msg'), 'a') as stream:
        stream.write('float64 added\n')
    log = run(build, root).stdout
    assert log.count('Generating mROS headers for package eight') == 1
    assert _generated_types(log) == ['eight/M3.msg', 'eight/M4.msg']
    for root_dir, old in zip((devel, exported), before):
        new = mtimes(root_dir)
        assert {path for path in old if new[path] != old[path]} == {
            os.path.join('eight', 'M3.h'), os.path.join('eight', 'M4.h')}
        with open(os.path.join(root_dir, 'eight', 'M3.h')) as stream:
            assert 'double added;' in stream.read()
    assert _generated_types(run(build, root).stdout) == []


def test_a_broken_msg_stops_its_package_only_and_leaves_its_headers(workspace):
    before = headers_under(workspace.devel)
    for relative, added in ((('mros_test', 'msg', 'BuiltinTypes.msg'), 'uint8 added_field\n'),
                            (('mros_test_base', 'msg', 'Vector3i.msg'), 'int32 w\n'),
                            (('mros_test', 'msg', 'Empty.msg'), 'float32 TOO_BIG=1e39\n')):
        with open(workspace.source(*relative), 'a') as stream:
            stream.write(added)
    path = workspace.source('mros_test', 'msg', 'Empty.msg')
    with open(path) as stream:
        line = len(stream.read().splitlines())
    result = run(['catkin_make', '-k', '-DMROS_EXPORT_DIR=%s' % workspace.export_dir],
                 workspace.root, check=False)
    assert result.returncode != 0
    errors = [text for text in result.stdout.splitlines() if text.startswith('genmros: error:')]
    assert errors == ['genmros: error: %s:%d: float32 constant 1e39 is beyond the range of '
                      'float32 (largest finite value 3.4028234663852886e+38)' % (path, line)]
    after = headers_under(workspace.devel)
    # The other package was generated; the broken one kept every header as it was.
    assert b'int32_t w;' in after[os.path.join('mros_test_base', 'Vector3i.h')]
    for header, text in before.items():
        if header.startswith('mros_test' + os.sep):
            assert after[header] == text, header
