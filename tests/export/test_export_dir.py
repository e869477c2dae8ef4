# SPDX-License-Identifier: BSD-3-Clause
"""colcon_mros.export.export_dir, called directly: an export dir's type list and
CMake file, colcon's replacement of packages, and catkin's claims."""

import os

from colcon_mros.export.export_dir import ExportDir
from colcon_mros.ros1.definition import Definition
from colcon_mros.ros1.workspace import Package

MODULE = '/opt/genmros/mros_generate.cmake'


def _package(root, name, files):
    for relative, text in files.items():
        path = os.path.join(root, name, relative)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, 'w') as stream:
            stream.write(text)
    with open(os.path.join(root, name, 'package.xml'), 'w') as stream:
        stream.write('<package><name>%s</name></package>\n' % name)
    return Package(name, [os.path.join(root, name, 'msg')], [os.path.join(root, name, 'srv')])


def test_colcon_export_lists_every_importable_type(tmp_path):
    sources = str(tmp_path / 'src')
    demo = _package(sources, 'demo', {'msg/Lamp.msg': 'uint8 on\n',
                    'srv/Switch.srv': 'bool on\n---\n'})
    export = ExportDir(str(tmp_path / 'export'))
    export.replace_packages({'demo': demo}, MODULE)
    assert export.types() == ['demo/Lamp', 'demo/SwitchRequest',
                              'demo/SwitchResponse', 'demo/Switch']
    with open(export.cmake_file) as stream:
        cmake = stream.read()
    assert ('set(MROS_EXPORT_TYPES\n  demo/Lamp\n  demo/SwitchRequest\n'
            '  demo/SwitchResponse\n  demo/Switch\n)' in cmake)
    assert 'include("%s")' % MODULE in cmake
    assert os.path.isfile(str(tmp_path / 'export' / 'COLCON_IGNORE'))
    assert os.path.isfile(str(tmp_path / 'export' / 'share' / 'demo' / 'package.xml'))

    os.remove(os.path.join(sources, 'demo', 'srv', 'Switch.srv'))
    other = _package(sources, 'other', {'msg/Note.msg': 'string text\n'})
    export.replace_packages({'demo': demo}, MODULE)
    export.replace_packages({'other': other}, MODULE)  # adds, never shrinks
    assert export.types() == ['demo/Lamp', 'other/Note']


def test_catkin_claims_remove_what_no_definition_contains(tmp_path):
    sources = str(tmp_path / 'src')
    _package(sources, 'demo', {'msg/Lamp.msg': 'Color c\n', 'msg/Color.msg': 'uint8 r\n',
                               'msg/Stamp.msg': 'uint32 t\n'})
    lamp = Definition('demo', os.path.join(sources, 'demo', 'msg', 'Lamp.msg'))
    color = Definition('demo', os.path.join(sources, 'demo', 'msg', 'Color.msg'))
    stamp = Definition('demo', os.path.join(sources, 'demo', 'msg', 'Stamp.msg'))
    export = ExportDir(str(tmp_path / 'export'))
    export.add_generated(lamp, {'demo/Lamp.h': 'lamp\n',
                         'demo/Color.h': 'color\n'}, [color], MODULE)
    export.add_generated(stamp, {'demo/Stamp.h': 'stamp\n'}, [], MODULE)
    foreign = tmp_path / 'export' / 'include' / 'demo' / 'Notes.h'
    foreign.write_text('by hand\n')
    assert export.types() == ['demo/Color', 'demo/Lamp', 'demo/Stamp']
    assert export.outputs_of(stamp) == [os.path.join(export.include_dir, 'demo', 'Stamp.h'),
                                        os.path.join(export.share_dir, 'demo', 'msg', 'Stamp.msg')]

    # Lamp no longer contains Color: Color's header and copy leave.
    export.add_generated(lamp, {'demo/Lamp.h': 'lamp 2\n'}, [], MODULE)
    assert export.types() == ['demo/Lamp', 'demo/Stamp']
    assert not os.path.exists(os.path.join(export.include_dir, 'demo', 'Color.h'))

    # catkin configures the package without Stamp.msg.
    removed = export.forget_other_definitions('demo', {lamp.key}, MODULE)
    assert sorted(removed) == ['include/demo/Stamp.h', 'share/demo/msg/Stamp.msg']
    assert export.types() == ['demo/Lamp']
    assert foreign.read_text() == 'by hand\n'
    with open(export.cmake_file) as stream:
        assert 'set(MROS_EXPORT_TYPES\n  demo/Lamp\n)' in stream.read()
