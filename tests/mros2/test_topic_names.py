# SPDX-License-Identifier: BSD-3-Clause
"""Topic names held to ROS 2's rules as mros2 uses them
(colcon_mros.mros2.endpoints): mros2 sends ``"rt/" + name`` and expands
nothing, so genmros mros2-export and mros2-fit refuse a name no ROS node
would match, one line for each, with the rule it breaks, and write nothing;
a leading '/' is taken with a note.
"""

import os

import pytest

from colcon_mros.errors import GenmrosError
from colcon_mros.mros2.endpoints import split_endpoint, split_qos, topic_name_problems

from support.checkout import run_genmros

EMPTY = 'test_interface_files/msg/Empty'
BAD_NAMES = {
    'bat tery': "' ' (a ROS 2 name holds only A-Z, a-z, 0-9, _ and /)",
    '9battery': "'9battery' starting with a digit",
    'bat-tery': "'-' (a ROS 2 name holds only A-Z, a-z, 0-9, _ and /)",
    'a//b': "'//' (an empty token)",
    '~/x': "'~' (mros2 expands no node namespace: write the name out)",
    'robot/{node}/odom': "'{}' (mros2 expands no substitution: write the name out)",
    'battery/': "a trailing '/'",
    'arm/2nd_joint': "'2nd_joint' starting with a digit",
}


@pytest.mark.parametrize('name', sorted(BAD_NAMES))
def test_each_rule_is_named(name):
    assert topic_name_problems(name) == [BAD_NAMES[name]]


def test_a_name_breaking_several_rules_names_each():
    assert topic_name_problems('9a b//') == [
        "' ' (a ROS 2 name holds only A-Z, a-z, 0-9, _ and /)", "'//' (an empty token)",
        "'9a b' starting with a digit", "a trailing '/'"]


@pytest.mark.parametrize('name', ['battery', 'robot_1/odom', '_private', 'a/b/c_d'])
def test_good_names_pass(name):
    assert split_endpoint('%s:%s' % (name, EMPTY)) == (name, EMPTY, [])


def test_a_leading_slash_is_taken_off_with_a_note():
    assert split_endpoint('/battery:%s' % EMPTY) == ('battery', EMPTY, [
        "topic '/battery': the app passes it to mros2 as 'battery' (mros2 sends \"rt/\" and the "
        "name as given: '/battery' would go out as 'rt//battery', which no ROS node matches)"])


def test_a_bad_name_is_one_line():
    with pytest.raises(GenmrosError) as error:
        split_endpoint('bat tery:%s' % EMPTY)
    assert str(error.value) == (
        "topic 'bat tery' (in 'bat tery:%s'): ROS 2 refuses a name with ' ' (a ROS 2 name holds "
        'only A-Z, a-z, 0-9, _ and /), so no ROS node would match it' % EMPTY)


@pytest.mark.parametrize('subcommand', ['mros2-export', 'mros2-fit'])
def test_genmros_refuses_every_bad_name_at_once_and_writes_nothing(tmp_path, subcommand,
                                                                   ros2_prefixes):
    config = tmp_path / 'config.h'
    config.write_text('const uint8_t MAX_TYPENAME_LENGTH = 64;\n')
    output = tmp_path / 'out'
    arguments = [subcommand, '--rtps-config', str(config)]
    for prefix in ros2_prefixes:
        arguments += ['--prefix', prefix]
    if subcommand == 'mros2-export':
        arguments += ['-o', str(output)]
    arguments += ['--publish', 'bat tery:%s' % EMPTY, '--subscribe', '~/x:%s' % EMPTY,
                  '--publish', 'ok:%s' % EMPTY]
    result = run_genmros(*arguments, check=False)
    assert result.returncode == 1
    assert result.stderr.splitlines() == [
        "genmros: error: --publish topic 'bat tery' (in 'bat tery:%s'): ROS 2 refuses a name "
        "with ' ' (a ROS 2 name holds only A-Z, a-z, 0-9, _ and /), so no ROS node would match "
        'it' % EMPTY,
        "genmros: error: --subscribe topic '~/x' (in '~/x:%s'): ROS 2 refuses a name with '~' "
        '(mros2 expands no node namespace: write the name out), so no ROS node would match it'
        % EMPTY]
    assert not os.path.exists(str(output))


def test_mros2_export_notes_a_leading_slash_and_writes_the_name_without_it(tmp_path,
                                                                           ros2_prefixes):
    arguments = ['mros2-export', '-o', str(tmp_path), '--publish', '/battery:%s' % EMPTY]
    for prefix in ros2_prefixes:
        arguments += ['--prefix', prefix]
    result = run_genmros(*arguments)
    assert result.stderr.startswith("genmros: note: topic '/battery': the app passes it to "
                                    "mros2 as 'battery'"), result.stderr
    assert 'rt//' not in (tmp_path / 'templates.hpp').read_text()


@pytest.mark.parametrize('text,split', [
    ('chatter:%s' % EMPTY, ('chatter:%s' % EMPTY, False, 10)),
    ('chatter:%s:reliable' % EMPTY, ('chatter:%s' % EMPTY, True, 10)),
    ('chatter:%s:reliable:3' % EMPTY, ('chatter:%s' % EMPTY, True, 3)),
    ('chatter:%s:best_effort' % EMPTY, ('chatter:%s' % EMPTY, False, 10)),
    (EMPTY, (EMPTY, False, 10))])
def test_a_qos_follows_the_type(text, split):
    assert split_qos(text) == split


@pytest.mark.parametrize('text,error', [
    ('%s:reliable' % EMPTY, "a QoS needs the topic: TOPIC:TYPE:reliable"),
    ('chatter:%s:reliabel' % EMPTY, "'reliabel' is no QoS (reliable, reliable:DEPTH or "
                                    'best_effort)'),
    ('chatter:%s:5' % EMPTY, "'5' is no QoS"),
    ('chatter:%s:best_effort:5' % EMPTY, 'a depth goes with reliable (a best-effort endpoint '
                                         'keeps no samples)'),
    ('chatter:%s:reliable:0' % EMPTY, 'a depth of 0 keeps nothing (1 or more)')])
def test_a_bad_qos_is_refused_with_its_text(text, error):
    with pytest.raises(GenmrosError) as raised:
        split_qos(text)
    assert str(raised.value).startswith("'%s': %s" % (text, error))


def test_one_endpoint_given_with_two_qos_is_refused(tmp_path, ros2_prefixes):
    arguments = ['mros2-export', '-o', str(tmp_path / 'out')]
    for prefix in ros2_prefixes:
        arguments += ['--prefix', prefix]
    result = run_genmros(*arguments + ['--publish', 'chatter:%s' % EMPTY,
                                       '--publish', 'chatter:%s:reliable' % EMPTY], check=False)
    assert result.returncode == 1
    assert result.stderr.splitlines() == [
        'genmros: error: --publish chatter:%s: given with two QoS; mros2 makes one writer per '
        'topic and type' % EMPTY]
    assert not os.path.exists(str(tmp_path / 'out'))
