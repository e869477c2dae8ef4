# SPDX-License-Identifier: BSD-3-Clause
"""The compile-time check (colcon_mros.mros_v1.fit_check_header): the rule
table rendered as #if/#error refuses, where the settings headers are on the
include path, exactly what the Python fit check refuses, for the small
settings in tests/fixtures/mros_v1_settings and copies with values changed;
it says so where it cannot check."""

import os
import re
import subprocess

import pytest

from colcon_mros.core.settings import read_settings
from colcon_mros.export.firmware_export import firmware_messages
from colcon_mros.mros_v1.fit import Fit
from support.checkout import TEST_WS, run_genmros
from support.settings_headers import header_paths, small_settings
from testing.ros_paths import prefix_arguments, ros1_prefixes

TYPES = ['std_msgs/String', 'mros_test_base/Vector3i', 'geometry_msgs/Quaternion',
         'mros_test/PersonalData', 'sensor_msgs/JointState']
# Bounded, so that every type has a largest frame for the pool rules.
BOUNDS = ('std_msgs/String.data max_size:300\n'
          '* max_size:8 max_count:4\n')


@pytest.fixture(scope='module')
def bounded_export(tmp_path_factory):
    root = tmp_path_factory.mktemp('fit_check_header')
    options = root / 'bounds.options'
    options.write_text(BOUNDS)
    include = str(root / 'include')
    arguments = ['mros-v1-export', '-o', include, '--workspace', TEST_WS,
                 *prefix_arguments(ros1_prefixes()),
                 '--storage', 'bounded', '--options', str(options)]
    for type_name in TYPES:
        arguments += ['--type', type_name]
    run_genmros(*arguments)
    return include, str(options)


def _python_refusals(options, settings_dir):
    """(type, setting) of each misfit of the Python check; a memory pool as
    'publishing' or 'receiving'."""
    messages = firmware_messages(TYPES, [TEST_WS] + ros1_prefixes(), 'bounded', [options])
    fit = Fit(messages, read_settings(header_paths(settings_dir)))
    return sorted((misfit.type_name,
                   misfit.what.split(', ')[1].rstrip(',') if 'frame' in misfit.what
                   else misfit.setting.name) for misfit in fit.misfits)


def _compile_time_refusals(include, settings_dir, *flags):
    """(type, setting) of each #error the check gives in a compile with the
    settings on the include path, and the compiler's exit status."""
    source = os.path.join(include, 'check.cpp')
    with open(source, 'w') as stream:
        stream.write('#include "mros_v1_fit_check.h"\n')
    result = subprocess.run(['g++', '-std=gnu++98', '-fsyntax-only', '-Wall', '-Wextra',
                             '-pedantic', '-I', include, '-I', settings_dir] + list(flags)
                            + [source], capture_output=True, text=True)
    refusals = []
    for message in re.findall(r'error: #error "([^"]*)"', result.stderr):
        type_name, what, setting = re.match(r'(\S+): (.*) needs (?:a )?(\w+|\S+<n>\S+) ',
                                            message).groups()
        refusals.append((type_name, what.split(', ')[1].rstrip(
            ',') if 'frame' in what else setting))
    return sorted(refusals), result.returncode, result.stderr


@pytest.mark.parametrize('values', [
    {},
    {'MROS_PACKET_MAXSIZE_REQ_TCPROS': 4096, 'MROS_PACKET_MAXSIZE_RES_TCPROS': 300,
     'MROS_TOPIC_TYPENAME_MAXLEN': 26, 'ROS_OUTER_TOPIC_PUBLISHER_CONFIG_NUM': 0},
    {'MROS_PACKET_MAXSIZE_REQ_TCPROS': 4096, 'MROS_PACKET_MAXSIZE_RES_TCPROS': 4096,
     'MROS_TOPIC_TYPENAME_MAXLEN': 32, 'ROS_INNER_TOPIC_PUBLISHER_CONFIG_NUM': 3,
     'ROS_OUTER_TOPIC_PUBLISHER_MEMPOOL1_SIZE': 4096},
], ids=['small', 'mixed', 'large'])
def test_both_renderings_of_the_rules_refuse_the_same(bounded_export, tmp_path, values):
    include, options = bounded_export
    settings_dir = small_settings(tmp_path / 'settings', **values)
    expected = _python_refusals(options, settings_dir) if values.get(
        'ROS_OUTER_TOPIC_PUBLISHER_CONFIG_NUM', 1) else None
    refusals, status, stderr = _compile_time_refusals(include, settings_dir)
    if expected is None:  # no receiving pool at all: Python names the settings
        with pytest.raises(Exception, match='define none of ROS_OUTER_TOPIC_PUBLISHER_MEMPOOL1'):
            _python_refusals(options, settings_dir)
        assert ('sensor_msgs/JointState', 'receiving from ROS nodes') in refusals
        return
    assert refusals == expected, stderr
    assert (status != 0) == bool(expected)
    assert 'warning' not in stderr
    if values == {}:  # the small settings refuse something of every rule
        assert {setting for _, setting in expected} >= {
            'MROS_PACKET_MAXSIZE_REQ_TCPROS', 'MROS_PACKET_MAXSIZE_RES_TCPROS',
            'MROS_TOPIC_TYPENAME_MAXLEN', 'publishing', 'receiving from ROS nodes'}


def test_delivery_must_remember_every_publishing_block(bounded_export, tmp_path):
    # The small settings' two publishing pools hold 16 + 8 blocks (the third
    # pool's 100 are beyond ..._CONFIG_NUM): within on-board delivery's 32
    # slots. One more block than the slots stops the compile, with the setting
    # to define; defining it lets the compile through, and so does a library
    # that passes the frame size (the patch set's ros.cpp), which has no slots.
    include, _ = bounded_export
    source = os.path.join(include, 'aggregate.cpp')
    with open(source, 'w') as stream:
        stream.write('#include "message_headers.h"\n')
    command = ['g++', '-std=gnu++98', '-fsyntax-only', '-I', include]
    for values, extra, refused in (({}, [], False),
                                   ({'ROS_INNER_TOPIC_PUBLISHER_MEMPOOL2_QUELEN': 17}, [], True),
                                   ({'ROS_INNER_TOPIC_PUBLISHER_MEMPOOL2_QUELEN': 17},
                                    ['-DMROS_ONBOARD_FRAME_SLOTS=33'], False),
                                   ({'ROS_INNER_TOPIC_PUBLISHER_MEMPOOL2_QUELEN': 17},
                                    ['-DMROS_LIBRARY_PASSES_FRAME_SIZE'], False)):
        directory = tmp_path / ('%d%s' % (len(values), ''.join(extra)))
        directory.mkdir()
        settings_dir = small_settings(directory / 'settings', **values)
        result = subprocess.run(command + ['-I', settings_dir] + extra + [source],
                                capture_output=True, text=True)
        messages = re.findall(r'error: #error "(the publishing pools[^"]*)"', result.stderr)
        assert messages == ([
            'the publishing pools hold more blocks than on-board delivery remembers: define '
            'MROS_ONBOARD_FRAME_SLOTS to at least the sum of '
            'ROS_INNER_TOPIC_PUBLISHER_MEMPOOL<n>_QUELEN (mros_usr_config.h), the same in every '
            "file, or apply genmros' patch set (the library passes the frame size)"]
            if refused else []), result.stderr


def test_the_check_can_be_skipped(bounded_export, tmp_path):
    include, _ = bounded_export
    refusals, status, stderr = _compile_time_refusals(include,
                                                      small_settings(tmp_path / 'settings'),
                                                      '-DMROS_SKIP_FIT_CHECK')
    assert (refusals, status) == ([], 0), stderr
