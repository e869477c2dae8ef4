"""colcon_mros.library_tools.mros2.patches: the opt-in patch set for a user's
mros2, applied with genmros mros2-harden to a copy of the real checkout
(MROS2_ROOT), and mros2's real src/mros2.cpp compiled, as it is and
patched, against a stand-in of embeddedRTPS (testing/mros2_library): two
publishers, and samples that do not decode."""

import filecmp
import os
import shutil
import subprocess

import pytest

from colcon_mros.library_tools.mros2.patches import LIBRARY_DIRS
from colcon_mros.library_tools.mros2.pc_target.build import TARGET_DIR
from support.checkout import REPO, run_genmros
from support.user_checkouts import MROS2_ROOT
from testing.ros_paths import prefix_arguments, ros2_prefixes

pytestmark = [pytest.mark.needs_mros2, pytest.mark.slow]

STAND_IN = os.path.join(REPO, 'testing', 'mros2_library')
# CMSIS-RTOS2's and lwIP's declarations, as the PC target has them.
PC_TARGET_HEADERS = os.path.join(TARGET_DIR, 'include')
TIF = 'test_interface_files/msg/'
ENDPOINTS = ['--publish', 'alpha:%sBasicTypes' % TIF, '--publish', 'beta:%sStrings' % TIF,
             '--subscribe', 'gamma:%sBasicTypes' % TIF, '--subscribe', 'delta:%sStrings' % TIF]


def _copy(root):
    for part in LIBRARY_DIRS:
        shutil.copytree(os.path.join(MROS2_ROOT, part), str(root / part))
    return root


def _differing(left, right):
    comparison = filecmp.dircmp(left, right)

    def walk(node, prefix):
        return [os.path.join(prefix, name)
                for name in node.diff_files + node.left_only + node.right_only] + [
            name for sub, child in node.subdirs.items()
            for name in walk(child, os.path.join(prefix, sub))]
    return sorted(walk(comparison, ''))


def test_apply_check_revert_on_a_checkout(tmp_path):
    checkout = _copy(tmp_path / 'mros2')
    before = run_genmros('mros2-harden', '--mros2-root', str(checkout), '--check', check=False)
    assert before.returncode == 1
    assert [line.split(':')[0] for line in before.stdout.splitlines()] == [
        'not applied   one-writer-per-publisher', 'not applied   checked-receive',
        'not applied   publish-keeps-a-copy', 'not applied   accept-fast-dds-3-discovery',
        'not applied   checked-acknack', 'not applied   full-participant-table-refuses',
        'not applied   large-acknack-counts', 'not applied   bounded-submessage-lengths',
        'not applied   acknack-within-the-history', 'not applied   lease-in-milliseconds',
        'not applied   data-holds-its-fields', 'not applied   sedp-parameters-within-their-length',
        'not applied   best-effort-writer-after-a-burst',
        'not applied   data-frag-for-best-effort-readers',
        'not applied   reader-catches-up-at-once',
        'not applied   acknacks-on-the-writer-threads', 'not applied   reliable-where-asked',
        'not applied   node-in-the-ros-graph', 'not applied   services-both-ways']
    applied = run_genmros('mros2-harden', '--mros2-root', str(checkout))
    assert applied.stdout == ('genmros: applied one-writer-per-publisher, checked-receive, '
                              'publish-keeps-a-copy, accept-fast-dds-3-discovery, '
                              'checked-acknack, full-participant-table-refuses, '
                              'large-acknack-counts, bounded-submessage-lengths, '
                              'acknack-within-the-history, lease-in-milliseconds, '
                              'data-holds-its-fields, sedp-parameters-within-their-length, '
                              'best-effort-writer-after-a-burst, '
                              'data-frag-for-best-effort-readers, '
                              'reader-catches-up-at-once, acknacks-on-the-writer-threads, '
                              'reliable-where-asked, node-in-the-ros-graph, '
                              'services-both-ways\n')
    changed = {'include': ['mros2.h'], 'src': ['mros2.cpp'],
               'embeddedRTPS': ['include/rtps/ThreadPool.h',
                                'include/rtps/common/types.h',
                                'include/rtps/discovery/ParticipantProxyData.h',
                                'include/rtps/discovery/SEDPAgent.h',
                                'include/rtps/discovery/SPDPAgent.h',
                                'include/rtps/entities/Domain.h',
                                'include/rtps/entities/Participant.h',
                                'include/rtps/entities/Reader.h',
                                'include/rtps/entities/ReaderProxy.h',
                                'include/rtps/entities/StatefulReader.h',
                                'include/rtps/entities/StatefulReader.tpp',
                                'include/rtps/entities/StatefulWriter.h',
                                'include/rtps/entities/StatefulWriter.tpp',
                                'include/rtps/entities/StatelessWriter.tpp',
                                'include/rtps/entities/WriterProxy.h',
                                'include/rtps/messages/MessageReceiver.h',
                                'include/rtps/messages/MessageTypes.h',
                                'include/rtps/storages/CacheChange.h',
                                'include/rtps/storages/SimpleHistoryCache.h',
                                'src/ThreadPool.cpp',
                                'src/discovery/ParticipantProxyData.cpp',
                                'src/discovery/SEDPAgent.cpp',
                                'src/discovery/SPDPAgent.cpp',
                                'src/discovery/TopicData.cpp',
                                'src/entities/Domain.cpp',
                                'src/entities/Participant.cpp',
                                'src/messages/MessageReceiver.cpp',
                                'src/messages/MessageTypes.cpp']}
    for part in LIBRARY_DIRS:
        assert _differing(os.path.join(MROS2_ROOT, part), str(checkout / part)) == changed[part]
    assert run_genmros('mros2-harden', '--mros2-root', str(checkout), '--check').returncode == 0
    assert run_genmros('mros2-harden', '--mros2-root', str(checkout)).stdout == \
        'genmros: nothing to do: the patches are in\n'
    run_genmros('mros2-harden', '--mros2-root', str(checkout), '--revert')
    for part in LIBRARY_DIRS:
        assert _differing(os.path.join(MROS2_ROOT, part), str(checkout / part)) == []


@pytest.fixture(scope='module')
def export(tmp_path_factory):
    root = str(tmp_path_factory.mktemp('mros2_library_export'))
    run_genmros('mros2-export', *prefix_arguments(ros2_prefixes()), '-o', root, *ENDPOINTS)
    return root


def _run_check(checkout, export, out, patched, defines=()):
    program = str(out / 'library_check')
    command = ['g++', '-std=c++14', '-g', '-fsanitize=address,undefined',
               '-fno-sanitize-recover=all', '-DMROS2_LOG_MIN_SEVERITY=5',
               '-I', STAND_IN, '-I', PC_TARGET_HEADERS, '-I', str(checkout / 'include'),
               '-I', export,
               str(checkout / 'src' / 'mros2.cpp'), os.path.join(STAND_IN, 'stand_in.cpp'),
               os.path.join(STAND_IN, 'lwip_sys.cpp'), os.path.join(STAND_IN, 'library_check.cpp'),
               '-pthread', '-o', program]
    if patched:
        command.insert(1, '-DCHECK_DROPPED_SAMPLES')
    command[1:1] = ['-D%s' % define for define in defines]
    result = subprocess.run(command, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr[-4000:]
    result = subprocess.run([program], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0 and result.stderr == '', result.stderr[-4000:]
    return result.stdout.splitlines()


def _sent(lines, topic_prefix='rt/'):
    """(topic, type name) of each sample sent on a topic of the app (or on topics with
    topic_prefix)."""
    return [tuple(line.split()[1:3]) for line in lines
            if line.startswith('sent ' + topic_prefix)]


def _graph_samples(lines):
    return [bytes.fromhex(line.split()[3]) for line in lines
            if line.startswith('sent ros_discovery_info ')]


def test_as_it_is_one_publisher_sends_for_both_and_bad_samples_are_delivered(tmp_path, export):
    lines = _run_check(_copy(tmp_path / 'mros2'), export, tmp_path, patched=False)
    strings = 'test_interface_files::msg::dds_::Strings_'
    assert _sent(lines) == [('rt/beta', strings), ('rt/beta', strings)]
    assert lines[-1] == 'delivered 5'


def test_patched_each_publisher_has_its_topic_and_bad_samples_are_dropped(tmp_path, export):
    checkout = _copy(tmp_path / 'mros2')
    run_genmros('mros2-harden', '--mros2-root', str(checkout))
    lines = _run_check(checkout, export, tmp_path, patched=True)
    assert _sent(lines) == [('rt/alpha', 'test_interface_files::msg::dds_::BasicTypes_'),
                            ('rt/beta', 'test_interface_files::msg::dds_::Strings_')]
    assert lines[-2:] == ['delivered 1', 'dropped 4']


def test_the_fit_check_reads_the_checkouts_publisher(tmp_path, export):
    """The as-is Publisher has no writer: two publishers are a misfit; patched, none."""
    checkout = _copy(tmp_path / 'mros2')
    config = tmp_path / 'config.h'
    config.write_text('const uint8_t MAX_TYPENAME_LENGTH = 64;\nconst uint8_t '
                      'MAX_TOPICNAME_LENGTH = 64;\nconst uint8_t NUM_WRITERS_PER_PARTICIPANT = '
                      '8;\nconst uint8_t NUM_READERS_PER_PARTICIPANT = 8;\nconst uint8_t '
                      'NUM_STATELESS_WRITERS = 8;\nconst uint8_t NUM_STATELESS_READERS = 8;\n'
                      'const uint8_t NUM_STATEFUL_WRITERS = 8;\n')
    arguments = ['mros2-fit', *prefix_arguments(ros2_prefixes()), '--rtps-config', str(config),
                 '--mros2-root', str(checkout)] + ENDPOINTS
    as_it_is = run_genmros(*arguments, check=False)
    assert as_it_is.returncode == 1
    assert ('error: %s:66: the firmware: its 2 publishers need a Publisher with a writer of its '
            'own' % (checkout / 'include' / 'mros2.h')) in as_it_is.stdout
    run_genmros('mros2-harden', '--mros2-root', str(checkout))
    assert 'Every endpoint fits.' in run_genmros(*arguments).stdout


@pytest.mark.parametrize('store,defines', [('ROS2_JAZZY', ()),
                                           ('ROS2_HUMBLE', ['STAND_IN_RMW_GID_STORAGE_SIZE=24'])],
                         ids=['iron-and-later', 'humble'])
def test_patched_each_endpoint_made_announces_the_node_to_the_ros_graph(
        tmp_path, export, store, defines):
    """The samples on ros_discovery_info, byte for byte as rosbags serializes rmw_dds_common's
    ParticipantEntitiesInfo of that ROS 2 (a Gid of 16 bytes, or 24 where the board's config
    sets RMW_GID_STORAGE_SIZE 24, as Humble's Gid.msg is char[24]): one at create_node, then
    one more at each endpoint, with the stand-in's GUIDs (the participant's prefix 1 to 12;
    entity keys in the order made, ros_discovery_info's writer first)."""
    import numpy
    from rosbags.typesys import Stores, get_typestore
    checkout = _copy(tmp_path / 'mros2')
    run_genmros('mros2-harden', '--mros2-root', str(checkout))
    lines = _run_check(checkout, export, tmp_path, patched=True, defines=defines)
    typestore = get_typestore(getattr(Stores, store))
    types = typestore.types
    size = {'ROS2_JAZZY': 16, 'ROS2_HUMBLE': 24}[store]

    def gid(key, kind):
        data = list(range(1, 13)) + [0, 0, key, kind]
        return types['rmw_dds_common/msg/Gid'](
            data=numpy.array(data + [0] * (size - 16), dtype=numpy.uint8))

    writers = [gid(2, 0x03), gid(3, 0x03)]
    readers = [gid(4, 0x04), gid(5, 0x04)]
    steps = [([], []), ([], writers[:1]), ([], writers), (readers[:1], writers),
             (readers, writers)]
    expected = [typestore.serialize_cdr(types['rmw_dds_common/msg/ParticipantEntitiesInfo'](
        gid=gid(1, 0xc1),  # the participant's own entity id is 0.0.1.c1
        node_entities_info_seq=[types['rmw_dds_common/msg/NodeEntitiesInfo'](
            node_namespace='/', node_name='library_check', reader_gid_seq=node_readers,
            writer_gid_seq=node_writers)]), 'rmw_dds_common/msg/ParticipantEntitiesInfo')
        for node_readers, node_writers in steps]
    assert _graph_samples(lines) == [bytes(sample) for sample in expected]
    assert _sent(lines, 'ros_discovery_info') == [
        ('ros_discovery_info', 'rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_')] * 5
