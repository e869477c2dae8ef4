# SPDX-License-Identifier: BSD-3-Clause
"""The mros2 fit check (colcon_mros.mros2.fit, genmros mros2-fit): each rule
with its exact line, a firmware that fits, and mros2-export refusing a
misfit before it writes anything.

The board's rtps/config.h here is written as embeddedRTPS' configs are
(namespace rtps::Config, const members, a value on the next line), with
small values so that each rule has a misfit.
"""

import os
import subprocess

import pytest

from colcon_mros.errors import GenmrosError
from colcon_mros.export.mros2_export import Board, firmware_fit
from colcon_mros.mros2.render import templates_header

from support.checkout import run_genmros
from testing.ros_paths import prefix_arguments, ros2_prefixes

CONFIG = '''\
#ifndef RTPS_CONFIG_H
#define RTPS_CONFIG_H
namespace rtps {
namespace Config {
const uint8_t MAX_NUM_PARTICIPANTS = 1;
const uint8_t NUM_STATELESS_WRITERS =
    MAX_NUM_PARTICIPANTS + 1; // Required + Additional
const uint8_t NUM_STATELESS_READERS = MAX_NUM_PARTICIPANTS + 1;
const uint8_t NUM_WRITERS_PER_PARTICIPANT = 4;
const uint8_t NUM_READERS_PER_PARTICIPANT = 5;
const uint8_t MAX_TYPENAME_LENGTH = 40;
const uint8_t MAX_TOPICNAME_LENGTH = 20;
const int THREAD_POOL_READER_STACKSIZE = 1600; // byte
}  // namespace Config
}  // namespace rtps
#endif
'''
ROOMY = {'= 4;': '= 8;', '= 5;': '= 8;', '= 40;': '= 64;', '= 20;': '= 32;',
         'MAX_NUM_PARTICIPANTS + 1;': 'MAX_NUM_PARTICIPANTS + 4;'}
# mros2 v0.5.4's Publisher (include/mros2.h) has a topic name and no writer.
PUBLISHER_WITHOUT_WRITER = '''\
namespace mros2 {
  class Publisher;
  class Publisher
  {
  public:
    std::string topic_name;
    template <class T>
    void publish(T &msg);
  };
}
'''
# embeddedRTPS' receiver header as it is, and with the patch data-frag-for-best-effort-readers
# (the lines the fit check looks for).
RECEIVER_AS_IT_IS = 'namespace rtps {\nclass MessageReceiver {\n};\n}\n'
RECEIVER_PATCHED = ('namespace rtps {\nnamespace FragmentDefaults {\n'
                    'const DataSize_t FRAGMENT_BUFFER_SIZE = 0;\n}\n}\n')
TIF = 'test_interface_files/msg/'
WAY_OUT = ('; or apply the mros2 patch data-frag-for-best-effort-readers (genmros mros2-harden) '
           'to take it in fragments')


def _write(path, text):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return str(path)


def _fit(tmp_path, publish, subscribe, config=CONFIG, limit=None, publisher=None,
         receiver=RECEIVER_AS_IT_IS, peer_max_message=65500, serve=(), call=()):
    mros2_root = None
    if publisher is not None:
        _write(tmp_path / 'mros2' / 'include' / 'mros2.h', publisher)
        _write(tmp_path / 'mros2' / 'embeddedRTPS' / 'include' / 'rtps' / 'messages' /
               'MessageReceiver.h', receiver)
        mros2_root = str(tmp_path / 'mros2')
    board = Board(_write(tmp_path / 'rtps' / 'config.h', config), limit, mros2_root,
                  peer_max_message)
    return firmware_fit(board, prefixes=ros2_prefixes(), publish=publish, subscribe=subscribe,
                        serve=serve, call=call)


def _roomy():
    config = CONFIG
    for small, roomy in ROOMY.items():
        config = config.replace(small, roomy)
    return config


def test_each_rule_names_the_setting_its_line_and_the_value_it_needs(tmp_path):
    config = str(tmp_path / 'rtps' / 'config.h')
    header = str(tmp_path / 'mros2' / 'include' / 'mros2.h')
    fit = _fit(tmp_path, ['chatter:%sEmpty' % TIF, 'eighteen_bytes_abc:%sEmpty' % TIF],
               ['state:%sBasicTypes' % TIF, 'samples:%sUnboundedSequences' % TIF],
               limit='100', publisher=PUBLISHER_WITHOUT_WRITER)
    assert fit.misfits == [
        '%s:11: test_interface_files::msg::dds_::BasicTypes_: its DDS type name and its NUL '
        'needs MAX_TYPENAME_LENGTH >= 45 (it is 40)' % config,
        '%s:11: test_interface_files::msg::dds_::UnboundedSequences_: its DDS type name and its '
        'NUL needs MAX_TYPENAME_LENGTH >= 53 (it is 40)' % config,
        "%s:12: topic eighteen_bytes_abc: 'rt/eighteen_bytes_abc' and its NUL needs "
        'MAX_TOPICNAME_LENGTH >= 22 (it is 20)' % config,
        "%s:9: the firmware: its 2 publishers (one per topic) and the participant's 3 built-in "
        'ones (SPDP, SEDP publications, SEDP subscriptions) needs NUM_WRITERS_PER_PARTICIPANT '
        '>= 5 (it is 4)' % config,
        "%s:6: the firmware: its 2 publishers (one per topic), best-effort, and the "
        "participant's SPDP one needs NUM_STATELESS_WRITERS >= 3 (it is 2)" % config,
        "%s:8: the firmware: its 2 subscribers (one per topic), best-effort, and the "
        "participant's SPDP one needs NUM_STATELESS_READERS >= 3 (it is 2)" % config,
        # 48 bytes of BasicTypes, RTPS' 76 around them.
        '--receive-limit 100: test_interface_files/msg/BasicTypes: a sample of up to 48 bytes '
        'in one datagram, RTPS around it needs the receive limit >= 124 (it is 100)' + WAY_OUT,
        "%s:3: the firmware: its 2 publishers need a Publisher with a writer of its own; this "
        "mros2 sends every message through the last one created (mros2::pub_ptr): apply "
        "genmros' mros2 patch set (genmros mros2-harden)" % header,
    ]
    assert fit.warnings == [
        "--receive-limit 100: the receive limit 100 is below 572 bytes, a ROS 2 node's SPDP "
        'announcement as Fast DDS 3 sends it (measured; it grows with the host and user '
        'names): the board discovers no such node',
        '--receive-limit 100: test_interface_files/msg/UnboundedSequences: a sample has no '
        'largest size (unbounded): one larger than the receive limit 100 does not arrive; '
        'bounded storage gives the exact need' + WAY_OUT]
    assert fit.notes == []


def test_a_firmware_that_fits_has_no_line(tmp_path):
    fit = _fit(tmp_path, ['chatter:%sEmpty' % TIF, 'eighteen_bytes_abc:%sEmpty' % TIF],
               ['state:%sBasicTypes' % TIF], config=_roomy(), limit='572',
               publisher=PUBLISHER_WITHOUT_WRITER.replace(
                   'std::string topic_name;',
                   'std::string topic_name;\n    rtps::Writer* writer;'))
    assert (fit.misfits, fit.warnings, fit.notes) == ([], [], [])
    assert 'Every endpoint fits.' in fit.report()


def test_types_alone_skip_the_topic_rules_and_say_what_was_not_checked(tmp_path):
    fit = _fit(tmp_path, [TIF + 'Empty', TIF + 'Nested', TIF + 'Empty'], [TIF + 'Empty'],
               config=_roomy())
    assert fit.misfits == []
    assert fit.notes == [
        'topics not given for every endpoint (--publish/--subscribe TOPIC:TYPE): topic names not '
        'checked, one endpoint counted per type',
        'no receive limit given (--receive-limit): the largest samples not checked',
        'whether this mros2 takes samples in fragments (the mros2 patch '
        'data-frag-for-best-effort-readers) is not known here (--mros2-root): checked as '
        'without it',
        '2 publishers: whether this mros2 gives each its own writer is not known here '
        '(--mros2-root)']


def test_the_receive_limit_is_read_from_the_ports_setting(tmp_path):
    options = _write(tmp_path / 'port' / 'lwipopts.h', '#define PBUF_POOL_BUFSIZE 1024\n'
                     '#define RECEIVE_BUFFER_SIZE 64\n')
    fit = _fit(tmp_path, [], ['state:%sBasicTypes' % TIF],
               config=CONFIG.replace('= 40;', '= 64;'), limit=options + ':RECEIVE_BUFFER_SIZE')
    assert fit.misfits == [
        '%s:2: test_interface_files/msg/BasicTypes: a sample of up to 48 bytes in one datagram, '
        'RTPS around it needs RECEIVE_BUFFER_SIZE >= 124 (it is 64)' % options + WAY_OUT]


def test_genmros_mros2_fit_and_mros2_export_refuse_a_misfit(tmp_path):
    config = _write(tmp_path / 'rtps' / 'config.h', CONFIG)
    endpoints = [*prefix_arguments(ros2_prefixes()), '--rtps-config', config,
                 '--subscribe', 'state:%sBasicTypes' % TIF]
    result = run_genmros('mros2-fit', *endpoints, check=False)
    assert result.returncode == 1
    assert ('error: %s:11: test_interface_files::msg::dds_::BasicTypes_: its DDS type name and '
            'its NUL needs MAX_TYPENAME_LENGTH >= 45 (it is 40)\n' % config) in result.stdout
    output = tmp_path / 'export'
    result = run_genmros('mros2-export', '-o', str(output), *endpoints, check=False)
    assert result.returncode != 0
    assert result.stderr == ('genmros: error: %s:11: test_interface_files::msg::dds_::'
                             'BasicTypes_: its DDS type name and its NUL needs '
                             'MAX_TYPENAME_LENGTH >= 45 (it is 40)\n' % config)
    assert not os.path.exists(str(output))
    run_genmros('mros2-export', '-o', str(output), *endpoints[:-2], '--subscribe',
                'state:%sEmpty' % TIF)
    assert os.path.exists(str(output / 'templates.hpp'))


def test_a_missing_rtps_config_says_which_file_and_what_to_give(tmp_path):
    missing = str(tmp_path / 'rtps' / 'config.h')
    result = run_genmros('mros2-fit', '--prefix', '/usr', '--rtps-config', missing,
                         '--subscribe', 'state:%sEmpty' % TIF, check=False)
    assert result.returncode == 1
    assert result.stderr == (
        "genmros: error: %s: cannot read the board's rtps/config.h (--rtps-config, "
        'RTPS_CONFIG): No such file or directory; give the rtps/config.h the firmware compiles '
        "with (the mros2 port's include/rtps/config.h, or its own)\n" % missing)


# BoundedPlainSequences: up to 732 bytes (808 in one datagram, 736 as a DATA_FRAG's sample).
LARGE, SMALL, UNBOUNDED = (TIF + name
                           for name in ('BoundedPlainSequences', 'BasicTypes', 'Strings'))
ROOMY_WRITERS = PUBLISHER_WITHOUT_WRITER.replace(
    'std::string topic_name;', 'std::string topic_name;\n    rtps::Writer* writer;')


def _fragment_fit(tmp_path, limit, peer_max_message, receiver, buffer=None, queue=20):
    config = _roomy().replace('= 64;', '= 80;').replace(
        '}  // namespace Config',
        'const int THREAD_POOL_WORKLOAD_QUEUE_LENGTH = %d;\n}  // namespace Config' % queue)
    if buffer is not None:
        config = config.replace('}  // namespace Config',
                                'const uint16_t FRAGMENT_BUFFER_SIZE = %d;\n'
                                '}  // namespace Config' % buffer)
    return _fit(tmp_path, [], ['large:' + LARGE, 'small:' + SMALL, 'text:' + UNBOUNDED],
                config=config, limit=limit, publisher=ROOMY_WRITERS, receiver=receiver,
                peer_max_message=peer_max_message)


def test_with_the_patch_fragmented_samples_need_the_buffer(tmp_path):
    config = str(tmp_path / 'rtps' / 'config.h')
    default = ('%s, which sets no FRAGMENT_BUFFER_SIZE (data-frag-for-best-effort-readers: 0)'
               % config)
    fit = _fragment_fit(tmp_path, '1472', 600, RECEIVER_PATCHED, queue=1)
    assert fit.misfits == [
        '%s: %s: a sample of up to 732 bytes and its encapsulation, put together from the '
        'fragments the ROS side sends (over --peer-max-message 600) needs FRAGMENT_BUFFER_SIZE '
        '>= 736 (it is 0)' % (default, LARGE),
        # 736 bytes in fragments of 424
        '%s:14: %s: the fragments of a sample of up to 732 bytes (424 bytes each: '
        '--peer-max-message 600 less 176), queued while the reader thread is busy needs '
        'THREAD_POOL_WORKLOAD_QUEUE_LENGTH >= 2 (it is 1)' % (config, LARGE)]
    assert fit.warnings == [
        '%s: %s: a sample has no largest size (unbounded): one larger than FRAGMENT_BUFFER_SIZE '
        '0 less its encapsulation (4) is refused and counted '
        '(mros2::Subscriber::refused_fragmented_samples); one of S bytes in fragments of 424 '
        '(--peer-max-message 600 less 176) needs FRAGMENT_BUFFER_SIZE >= S + 4 and '
        'THREAD_POOL_WORKLOAD_QUEUE_LENGTH >= (S + 4) / 424, rounded up: with 0 and 1, up to 0 '
        'bytes; bounded storage gives the exact need' % (default, UNBOUNDED)]
    fit = _fragment_fit(tmp_path, '1472', 600, RECEIVER_PATCHED, buffer=736)
    assert fit.misfits == [] and fit.notes == []
    assert fit.warnings[0].startswith(
        '%s:15: %s: a sample has no largest size (unbounded): one larger than '
        'FRAGMENT_BUFFER_SIZE 736 less' % (config, UNBOUNDED))
    templates = templates_header(fit.endpoints, fit.board_requirements)['templates.hpp']
    assert ('static_assert(736 <= rtps::Config::FRAGMENT_BUFFER_SIZE,\n              "%s: a '
            'sample of up to 732 bytes and its encapsulation, put together from the fragments '
            'the ROS side sends (over --peer-max-message 600) needs '
            'rtps::Config::FRAGMENT_BUFFER_SIZE >= 736 (rtps/config.h)");' % LARGE) in templates


def test_with_the_patch_the_peers_message_must_fit_the_receive_limit(tmp_path):
    fit = _fragment_fit(tmp_path, '600', 700, RECEIVER_PATCHED, buffer=736)
    assert fit.misfits == [
        "--receive-limit 600: the ROS side: its largest message (--peer-max-message 700), in "
        'which it sends %s in fragments, needs the receive limit >= 700 (it is 600); or give the '
        "ROS side's transport a maxMessageSize of at most 600 and --peer-max-message to match "
        '(docs/mros2.md)' % LARGE]
    assert fit.warnings[-1] == (
        '%s:15: %s: a sample has no largest size (unbounded): one of 601 to 700 bytes in one '
        'datagram is cut (the receive limit 600), one larger than FRAGMENT_BUFFER_SIZE 736 less '
        'its encapsulation (4) is refused and counted '
        '(mros2::Subscriber::refused_fragmented_samples); one of S bytes in fragments of 524 '
        '(--peer-max-message 700 less 176) needs FRAGMENT_BUFFER_SIZE >= S + 4 and '
        'THREAD_POOL_WORKLOAD_QUEUE_LENGTH >= (S + 4) / 524, rounded up: with 736 and 20, up to '
        '732 bytes; bounded storage gives the exact need'
        % (tmp_path / 'rtps' / 'config.h', UNBOUNDED))
    # sent whole by the ROS side (65500), over the limit
    fit = _fragment_fit(tmp_path, '600', 65500, RECEIVER_PATCHED, buffer=736)
    assert fit.misfits == [
        '--receive-limit 600: %s: a sample of up to 732 bytes in one datagram, RTPS around it '
        'needs the receive limit >= 808 (it is 600); or have the ROS side send it in fragments '
        "of at most that: its transport's maxMessageSize and --peer-max-message (docs/mros2.md)"
        % LARGE]


def test_a_peer_message_below_the_discovery_announcement_is_refused(tmp_path):
    with pytest.raises(GenmrosError) as refused:
        _fragment_fit(tmp_path, '1472', 500, RECEIVER_PATCHED)
    assert str(refused.value) == (
        "--peer-max-message 500: below 572 bytes, a ROS 2 node's SPDP announcement as Fast "
        'DDS 3 sends it: the board would discover no such node')


def test_without_the_patch_a_sample_the_peer_fragments_is_a_misfit(tmp_path):
    fit = _fragment_fit(tmp_path, '1472', 600, RECEIVER_AS_IT_IS)
    assert fit.misfits == [
        "--peer-max-message 600: %s: a sample of up to 732 bytes in one datagram, RTPS around "
        "it needs the ROS side's largest message >= 808 (it is 600); the ROS side sends a "
        "larger one in fragments, which this mros2 skips: raise its transport's "
        'maxMessageSize, or apply the mros2 patch data-frag-for-best-effort-readers (genmros '
        'mros2-harden)' % LARGE]
    assert fit.board_requirements == []


# The settings of the stateful (reliable) endpoints, after the config's last line.
STATEFUL = ('const uint8_t NUM_STATEFUL_WRITERS = 3;\nconst uint8_t NUM_STATEFUL_READERS = 2;\n'
            'const uint8_t HISTORY_SIZE_STATEFUL = 10;\n')
# mros2.h with one writer per publisher, and with the patches reliable-where-asked and
# node-in-the-ros-graph (the macros they define).
PUBLISHER_WITH_WRITER = PUBLISHER_WITHOUT_WRITER.replace(
    'std::string topic_name;', 'std::string topic_name;\n    rtps::Writer* writer;')
QOS_PATCHED = '#define MROS2_RELIABLE_WHERE_ASKED 1\n' + PUBLISHER_WITH_WRITER
GRAPH_PATCHED = '#define MROS2_NODE_IN_THE_ROS_GRAPH 1\n' + QOS_PATCHED
SERVICES_PATCHED = '#define MROS2_SERVICES_BOTH_WAYS 1\n' + QOS_PATCHED
TIS = 'test_interface_files/srv/'


def _stateful_config():
    return _roomy().replace('const int THREAD_POOL_READER_STACKSIZE',
                            STATEFUL + 'const int THREAD_POOL_READER_STACKSIZE')


def test_reliable_endpoints_take_stateful_slots_and_a_history_of_their_depth(tmp_path):
    config = str(tmp_path / 'rtps' / 'config.h')
    fit = _fit(tmp_path, ['a:%sEmpty:reliable' % TIF, 'b:%sEmpty:reliable:11' % TIF,
                          'c:%sEmpty' % TIF],
               ['d:%sEmpty:reliable' % TIF, 'e:%sEmpty:reliable:4' % TIF],
               config=_stateful_config(), publisher=QOS_PATCHED)
    assert fit.misfits == [
        "%s:13: the firmware: its 2 publishers (one per topic), reliable, and the participant's "
        '2 SEDP ones needs NUM_STATEFUL_WRITERS >= 4 (it is 3)' % config,
        "%s:14: the firmware: its 2 subscribers (one per topic), reliable, and the "
        "participant's 2 SEDP ones needs NUM_STATEFUL_READERS >= 4 (it is 2)" % config,
        '%s:15: topic b: a reliable publisher keeping its last 11 samples needs '
        'HISTORY_SIZE_STATEFUL >= 11 (it is 10)' % config]
    report = fit.report()
    assert '| publish b %sEmpty (reliable, depth 11) |' % TIF in report
    assert 'NUM_STATEFUL_WRITERS 3, NUM_STATEFUL_READERS 2, HISTORY_SIZE_STATEFUL 10' in report


def test_reliable_endpoints_need_the_patch(tmp_path):
    header = str(tmp_path / 'mros2' / 'include' / 'mros2.h')
    fit = _fit(tmp_path, ['a:%sEmpty:reliable' % TIF], [], config=_stateful_config(),
               publisher=PUBLISHER_WITH_WRITER)
    assert fit.misfits == [
        '%s:3: the firmware: its reliable endpoints (publish a %sEmpty (reliable, depth 10)) '
        'need mros2 with the patch reliable-where-asked; this one makes every endpoint '
        "best-effort: apply genmros' mros2 patch set (genmros mros2-harden)" % (header, TIF)]
    unknown = _fit(tmp_path, ['a:%sEmpty:reliable' % TIF], [], config=_stateful_config())
    assert unknown.misfits == []
    assert unknown.notes == [
        'whether this mros2 makes reliable endpoints (the mros2 patch reliable-where-asked) is '
        'not known here (--mros2-root): templates.hpp stops the build without it']


def test_the_graph_patch_counts_its_writer(tmp_path):
    config = str(tmp_path / 'rtps' / 'config.h')
    small = _stateful_config().replace('MAX_TYPENAME_LENGTH = 64', 'MAX_TYPENAME_LENGTH = 51')
    fit = _fit(tmp_path, ['a:%sEmpty:reliable' % TIF], [], config=small, publisher=GRAPH_PATCHED)
    # Without room for its type name the board runs, unlisted: a warning.
    assert fit.warnings == [
        '%s:11: rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_: its DDS type name and its '
        'NUL (the writer on ros_discovery_info of the mros2 patch node-in-the-ros-graph, without '
        "which ROS 2 does not list the board's node) needs MAX_TYPENAME_LENGTH >= 52 (it is 51)"
        % config]
    # A writer it takes before the firmware's is one the firmware lacks: a misfit.
    assert fit.misfits == [
        "%s:13: the firmware: its 1 publisher (one per topic), reliable, and its writer on "
        "ros_discovery_info (the mros2 patch node-in-the-ros-graph) and the participant's 2 "
        'SEDP ones needs NUM_STATEFUL_WRITERS >= 4 (it is 3)' % config]
    # Without the patch, the same firmware fits.
    assert _fit(tmp_path, ['a:%sEmpty:reliable' % TIF], [], config=small,
                publisher=QOS_PATCHED).misfits == []


def test_templates_hpp_compiles_against_either_mros2_and_holds_the_graph_writers_rules(
        tmp_path):
    """templates.hpp's instantiations take the signatures of the mros2.h they meet (a stand-in
    of each: as released, int and void; patched, mros2::QoS and bool); a reliable endpoint
    stops the build without the patch, with its line; the graph writer's rules hold where
    mros2.h says that patch is in."""
    fit = _fit(tmp_path, ['a:%sEmpty:reliable' % TIF, 'b:%sEmpty' % TIF], [],
               config=_stateful_config())
    text = templates_header(fit.endpoints, fit.board_requirements)['templates.hpp']
    assert ('#ifndef MROS2_NODE_IN_THE_ROS_GRAPH' not in text and
            '#ifdef MROS2_NODE_IN_THE_ROS_GRAPH' in text)
    body = text[text.index('// mros2 with genmros'):]
    released = ('namespace mros2 {\nclass Publisher {\n public:\n  template <class T> void '
                'publish(T &msg);\n};\nclass Node {\n public:\n  template <class T> Publisher '
                'create_publisher(std::string topic_name, int qos);\n};\n'
                'template <class T> Publisher Node::create_publisher(std::string, int) '
                '{ return Publisher(); }\ntemplate <class T> void Publisher::publish(T &) {}\n}\n')
    patched = ('#define MROS2_RELIABLE_WHERE_ASKED 1\n' + released.replace(
        'void publish', 'bool publish').replace(
        'template <class T> void Publisher::publish(T &) {}',
        'template <class T> bool Publisher::publish(T &) { return true; }').replace(
        'int qos', 'QoS qos').replace('std::string, int', 'std::string, QoS').replace(
        'namespace mros2 {\n', 'namespace mros2 {\nstruct QoS { QoS(int) {} };\n'))
    message = 'namespace test_interface_files { namespace msg { struct Empty {}; } }\n'
    results = {}
    for name, header in (('released', released), ('patched', patched)):
        source = tmp_path / ('%s.cpp' % name)
        source.write_text('#include <string>\n' + header + message + body)
        results[name] = subprocess.run(
            ['g++', '-std=c++14', '-Wall', '-Wextra', '-pedantic', '-fsyntax-only', str(source)],
            capture_output=True, text=True)
    assert results['patched'].returncode == 0, results['patched'].stderr
    assert results['released'].returncode != 0
    assert ("#error \"reliable endpoints (publish a %sEmpty (reliable, depth 10)) need mros2 "
            "with genmros' patch reliable-where-asked: apply genmros' mros2 patch set (genmros "
            'mros2-harden)"' % TIF) in results['released'].stderr
    assert results['released'].stderr.count('error:') == 1, results['released'].stderr


def test_a_service_and_a_client_take_a_reliable_writer_and_reader_each(tmp_path):
    config = str(tmp_path / 'rtps' / 'config.h')
    fit = _fit(tmp_path, ['a:%sEmpty:reliable' % TIF], [], config=_stateful_config(),
               publisher=SERVICES_PATCHED, serve=['reset:%sEmpty' % TIS],
               call=['ask:%sBasicTypes' % TIS])
    assert fit.misfits == [
        "%s:13: the firmware: its 1 publisher (one per topic) and 2 writers of services and "
        "clients (one each), reliable, and the participant's 2 SEDP ones needs "
        'NUM_STATEFUL_WRITERS >= 5 (it is 3)' % config,
        "%s:14: the firmware: its 2 readers of services and clients (one each), reliable, and "
        "the participant's 2 SEDP ones needs NUM_STATEFUL_READERS >= 4 (it is 2)" % config]
    report = fit.report()
    for line in ('| serve reset %sEmpty (publish of %sEmpty_Response) | '
                 'test_interface_files::srv::dds_::Empty_Response_ | 1 |' % (TIS, TIS),
                 '| call ask %sBasicTypes (subscribe of %sBasicTypes_Response) | '
                 'test_interface_files::srv::dds_::BasicTypes_Response_ | unbounded |'
                 % (TIS, TIS)):
        assert line in report
    # Each writer keeps rmw's services default, 10: one short is a misfit.
    short = _stateful_config().replace('HISTORY_SIZE_STATEFUL = 10', 'HISTORY_SIZE_STATEFUL = 9')
    assert ('%s:15: serve reset %sEmpty: a reliable publisher keeping its last 10 samples '
            'needs HISTORY_SIZE_STATEFUL >= 10 (it is 9)' % (config, TIS)) in _fit(
        tmp_path, [], [], config=short, publisher=SERVICES_PATCHED,
        serve=['reset:%sEmpty' % TIS]).misfits


def test_services_need_the_patch(tmp_path):
    header = str(tmp_path / 'mros2' / 'include' / 'mros2.h')
    fit = _fit(tmp_path, [], [], config=_stateful_config(), publisher=QOS_PATCHED,
               serve=['reset:%sEmpty' % TIS])
    assert fit.misfits[-1] == (
        "%s:4: the firmware: its services (serve reset %sEmpty) need mros2 with the patch "
        "services-both-ways: apply genmros' mros2 patch set (genmros mros2-harden)"
        % (header, TIS))
    assert len(fit.misfits) == 2  # and NUM_STATEFUL_READERS 2, which the patched one misses too
    patched = _fit(tmp_path, [], [], config=_stateful_config(), publisher=SERVICES_PATCHED,
                   serve=['reset:%sEmpty' % TIS])
    assert patched.misfits == fit.misfits[:1]


def test_templates_hpp_instantiates_services_and_clients_where_mros2_has_the_patch(tmp_path):
    """With a stand-in of the patched mros2.h, the service's and the client's calls compile at
    -Wall -Wextra -pedantic; without the patch, the build stops at one #error naming them."""
    fit = _fit(tmp_path, [], [], config=_stateful_config(), serve=['reset:%sEmpty' % TIS],
               call=['ask:%sBasicTypes' % TIS])
    text = templates_header(fit.endpoints, fit.board_requirements)['templates.hpp']
    assert '#include "test_interface_files/srv/basic_types.hpp"' in text
    body = text[text.index('// mros2 with genmros'):]
    patched = (
        '#define MROS2_RELIABLE_WHERE_ASKED 1\n#define MROS2_SERVICES_BOTH_WAYS 1\n'
        'namespace rtps { struct ReaderCacheChange; }\n'
        'namespace mros2 {\nstruct QoS { QoS(int) {} };\n'
        'class Service {\n public:\n  template <class T>\n  static void request_handler('
        'void *, const rtps::ReaderCacheChange &) {}\n};\n'
        'class Client {\n public:\n  template <class Request, class Response>\n  bool call('
        'Request &, Response &, uint32_t) { return true; }\n};\n'
        'class Node {\n public:\n  template <class T>\n  Service create_service(std::string, '
        'void (*)(typename T::Request *, typename T::Response *)) { return Service(); }\n'
        '  template <class T>\n  Client create_client(std::string) { return Client(); }\n};\n}\n')
    services = ''.join(
        'namespace test_interface_files { namespace srv {\nstruct %s_Request {};\n'
        'struct %s_Response {};\nstruct %s { typedef %s_Request Request; '
        'typedef %s_Response Response; };\n} }\n' % ((name,) * 5)
        for name in ('Empty', 'BasicTypes'))
    results = {}
    for name, header in (('released', 'namespace mros2 {}\n'), ('patched', patched)):
        source = tmp_path / ('%s.cpp' % name)
        source.write_text('#include <cstdint>\n#include <string>\n' + header + services + body)
        results[name] = subprocess.run(
            ['g++', '-std=c++14', '-Wall', '-Wextra', '-pedantic', '-fsyntax-only', str(source)],
            capture_output=True, text=True)
    assert results['patched'].returncode == 0, results['patched'].stderr
    assert ("#error \"services (call ask %sBasicTypes, serve reset %sEmpty) need mros2 with "
            "genmros' patch services-both-ways: apply genmros' mros2 patch set (genmros "
            'mros2-harden)"' % (TIS, TIS)) in results['released'].stderr
    assert results['released'].stderr.count('error:') == 1, results['released'].stderr


def test_the_report_gives_what_the_stateful_writers_histories_hold(tmp_path):
    """A reliable writer its depth of its largest sample (the encapsulation, the message, the
    padding); ros_discovery_info's writer its history of samples, each at most 32 bytes and
    the name's besides the GIDs (rosbags' ParticipantEntitiesInfo reaches that bound)."""
    fit = _fit(tmp_path, ['a:%sEmpty:reliable:3' % TIF], ['b:%sEmpty' % TIF],
               config=_roomy().replace('const int THREAD_POOL_READER_STACKSIZE',
                                       STATEFUL.replace('= 3', '= 5').replace('= 2', '= 5') +
                                       'const int THREAD_POOL_READER_STACKSIZE'),
               publisher='#define MROS2_SERVICES_BOTH_WAYS 1\n' + GRAPH_PATCHED,
               serve=['reset:%sEmpty' % TIS])
    report = fit.report()
    assert ("What the stateful writers' histories hold at most (pbufs):\n"
            '- topic a: 3 samples of up to 8 bytes: 24 bytes\n'
            '- serve reset %sEmpty: 10 samples of up to 8 bytes: 80 bytes\n'
            '- the writer on ros_discovery_info (the mros2 patch node-in-the-ros-graph): 10 '
            "samples of up to 112 + N or 152 + N bytes, N the node name's length (a GID of 16 "
            'or 24 bytes)\n' % TIS) in report, report
