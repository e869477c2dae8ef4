# SPDX-License-Identifier: BSD-3-Clause
"""colcon_mros.ros1.definition: the names one definition file gives."""

import os

from colcon_mros.ros1.definition import Definition, definitions_in
from testing.ros_paths import ros1_package_dir


def test_a_message_file_gives_one_type():
    definition = Definition('geometry_msgs',
                            os.path.join(ros1_package_dir('geometry_msgs'), 'Point.msg'))
    assert (definition.kind, definition.name, definition.full_name) == (
        'msg', 'Point', 'geometry_msgs/Point')
    assert definition.type_names == ['Point']
    assert definition.key == 'geometry_msgs/msg/Point.msg'
    assert not definition.is_service and definition.half_of('PointRequest') is None


def test_a_service_file_gives_the_service_and_its_halves():
    definition = Definition('std_srvs', '/somewhere/else/SetBool.srv')
    assert definition.is_service and definition.key == 'std_srvs/srv/SetBool.srv'
    assert definition.full_type_names == ['std_srvs/SetBool', 'std_srvs/SetBoolRequest',
                                          'std_srvs/SetBoolResponse']
    assert definition.half_of('SetBoolRequest') == 'Request'
    assert definition.half_of('SetBoolResponse') == 'Response'
    assert definition.half_of('SetBool') is None


def test_definitions_in_a_directory_are_sorted_and_of_one_kind(tmp_path):
    for name in ('B.msg', 'A.msg', 'C.srv', 'notes.txt'):
        (tmp_path / name).write_text('')
    assert [d.key for d in definitions_in('p', str(tmp_path), 'msg')] == [
                                          'p/msg/A.msg', 'p/msg/B.msg']
    assert [d.key for d in definitions_in('p', str(tmp_path / 'missing'), 'srv')] == []
