"""What ROS tools and nodes see of an mROS POSIX node: rostopic info/echo,
the slave API (getPid, getBusInfo, getPublications, requestTopic), the
refusal of a peer whose type or MD5 sum differs, and the unregistration when
the node is stopped."""

import subprocess
import xmlrpc.client


PERSONAL_DATA_MD5 = 'db8764b0e4c604ae579ade5118a6958c'  # gencpp's, for the refusal texts


def start_talker(graph, firmware):
    talker = graph.start('mROS talker', firmware.node('mros_personal_talker'))
    graph.wait_for_graph(publishers=[('/mros_str', '/mros_node')])
    return talker


def rostopic(graph, *arguments):
    result = subprocess.run(['rostopic'] + list(arguments), env=graph.env, capture_output=True,
                            text=True, timeout=30)
    assert result.returncode == 0, result.stdout + result.stderr
    return result.stdout


def slave(graph, node):
    code, message, uri = graph.master_proxy().lookupNode('/test', node)
    assert code == 1, message
    return xmlrpc.client.ServerProxy(uri)


def test_rostopic_info_and_echo_see_the_mros_topic(ros_graph, mros_firmware):
    start_talker(ros_graph, mros_firmware)
    info = rostopic(ros_graph, 'info', '/mros_str')
    assert 'Type: mros_test/PersonalData' in info
    assert ' * /mros_node (http://127.0.0.1:' in info
    echoed = rostopic(ros_graph, 'echo', '-n', '2', '/mros_str')
    assert echoed.count('first_name: "Phil"') == 2
    assert echoed.count('last_name: "Woods"') == 2
    assert echoed.count('age: 83') == 2
    scores = [int(line.split(':')[1]) for line in echoed.splitlines() if line.startswith('score:')]
    assert len(scores) == 2 and scores[1] == scores[0] + 1 and scores[0] >= 100000


def test_slave_api_answers_as_ros_nodes_do(ros_graph, ros_workspace, mros_firmware):
    talker = start_talker(ros_graph, mros_firmware)
    ros_graph.start('roscpp listener', ros_workspace.roscpp('personal_data_listener'))
    talker.wait_for(r'subscriber /ros_personal_listener connected to /mros_str')
    node = slave(ros_graph, '/mros_node')
    assert node.getPid('/test') == [1, '', talker.popen.pid]
    assert node.getMasterUri('/test')[2] == ros_graph.uri
    assert node.getPublications('/test')[2] == [['/mros_str', 'mros_test/PersonalData']]
    code, _, (protocol, host, port) = node.requestTopic('/test', '/mros_str', [['TCPROS']])
    assert (code, protocol, host) == (1, 'TCPROS', '127.0.0.1') and 0 < port < 65536
    assert node.requestTopic('/test', '/not_published', [['TCPROS']])[0] == 0
    connections = node.getBusInfo('/test')[2]
    assert [(c[1], c[2], c[3], c[4]) for c in connections] == [
        ('/ros_personal_listener', 'o', 'TCPROS', '/mros_str')]


def test_subscriber_with_another_type_is_refused(ros_graph, ros_workspace, mros_firmware):
    # The mROS relay publishes BuiltinTypes on /src_back/BuiltinTypes; a roscpp
    # PersonalData listener is pointed at it.
    relay = ros_graph.start('mROS relay', mros_firmware.node(
        'mros_type_relay', '/src', '/back', '__name:=mros_relay'))
    relay.wait_for(r'relaying')
    listener = ros_graph.start('roscpp listener', ros_workspace.roscpp(
        'personal_data_listener', 'mros_str:=/back/BuiltinTypes'))
    relay.wait_for(r'Client \[/ros_personal_listener\] wants topic /back/BuiltinTypes to have '
                   r'datatype/md5sum \[mros_test/PersonalData/%s\], but our version has '
                   r'\[mros_test/BuiltinTypes/[0-9a-f]{32}\]\. Dropping connection\.'
                   % PERSONAL_DATA_MD5)
    assert relay.alive() and listener.alive()
    assert 'subscriber /ros_personal_listener connected' not in relay.output()


def test_publisher_with_another_type_is_refused(ros_graph, mros_firmware):
    listener = ros_graph.start('mROS listener', mros_firmware.node(
        'mros_personal_listener', 'test_msg:=/wrong_type'))
    ros_graph.wait_for_graph(subscribers=[('/wrong_type', '/mros_node2')])
    ros_graph.start('rostopic pub', ['rostopic', 'pub', '-r', '5', '/wrong_type',
                                     'std_msgs/String', 'data: not a person'])
    # rospy's reason, passed on in its error header.
    listener.wait_for(r'/wrong_type: publisher http://127\.0\.0\.1:\d+/ refused the connection: '
                      r'topic types do not match: \[mros_test/PersonalData\] vs\. '
                      r'\[std_msgs/String\]', timeout=20)
    assert 'I heard a msg' not in listener.output()
    assert listener.alive()


def test_stopped_node_unregisters_and_exits_cleanly(ros_graph, mros_firmware):
    talker = start_talker(ros_graph, mros_firmware)
    listener = ros_graph.start('mROS listener', mros_firmware.node('mros_personal_listener'))
    ros_graph.wait_for_graph(subscribers=[('/test_msg', '/mros_node2')])
    assert talker.stop() == 0 and listener.stop() == 0
    publishers, subscribers = ros_graph.system_state()
    assert '/mros_node' not in publishers.get('/mros_str', set())
    assert '/mros_node2' not in subscribers.get('/test_msg', set())
    talker.wait_for(r'shutting down node /mros_node: SIGINT', timeout=0)


def test_shutdown_call_of_the_slave_api_ends_the_node(ros_graph, mros_firmware):
    listener = ros_graph.start('mROS listener', mros_firmware.node('mros_personal_listener'))
    ros_graph.wait_for_graph(subscribers=[('/test_msg', '/mros_node2')])
    assert slave(ros_graph, '/mros_node2').shutdown('/test', 'test is over') == [1, 'shutdown', 0]
    assert listener.popen.wait(timeout=10) == 0
    listener.wait_for(r'shutting down node /mros_node2: shutdown requested by /test '
                      r'\(test is over\)', timeout=0)
    assert '/mros_node2' not in ros_graph.system_state()[1].get('/test_msg', set())


def test_namespace_and_remapping_from_the_command_line(ros_graph, mros_firmware):
    ros_graph.start('mROS talker', mros_firmware.node(
        'mros_personal_talker', '__ns:=/robot1', 'mros_str:=people'))
    ros_graph.wait_for_graph(publishers=[('/robot1/people', '/robot1/mros_node')])
    assert 'Type: mros_test/PersonalData' in rostopic(ros_graph, 'info', '/robot1/people')


def test_rosnode_and_rosmsg_see_the_mros_node(ros_graph, mros_firmware):
    start_talker(ros_graph, mros_firmware)
    info = subprocess.run(['rosnode', 'info', '/mros_node'], env=ros_graph.env, capture_output=True,
                          text=True, timeout=30)
    assert info.returncode == 0, info.stdout + info.stderr
    assert 'Node [/mros_node]' in info.stdout
    assert ' * /mros_str [mros_test/PersonalData]' in info.stdout
    assert 'Pid: ' in info.stdout  # answered by the node's own slave API
    show = subprocess.run(['rosmsg', 'show', 'mros_test/PersonalData'], env=ros_graph.env,
                          capture_output=True, text=True, timeout=30)
    assert show.stdout.split() == ['string', 'first_name', 'string', 'last_name', 'uint16', 'age',
                                   'int32', 'score'], show.stderr
    md5 = subprocess.run(['rosmsg', 'md5', 'mros_test/PersonalData'], env=ros_graph.env,
                         capture_output=True, text=True, timeout=30)
    assert md5.stdout.strip() == PERSONAL_DATA_MD5


COMPACT_PERSONAL_DATA = 'string first_name\nstring last_name\nuint16 age\nint32 score\n'


def test_compact_definition_text_reaches_rostopic_and_rosbag(ros_graph, ros_workspace, mros_firmware,
                                                               tmp_path):
    """A node whose headers carry the compact definition text: rostopic echo
    decodes it, rosbag records its text and decodes the bag from that text
    alone, and rosbag play delivers it to a rospy subscriber."""
    talker = ros_graph.start('mROS compact talker', mros_firmware.node('mros_compact_talker'))
    ros_graph.wait_for_graph(publishers=[('/mros_str', '/mros_node')])
    echoed = rostopic(ros_graph, 'echo', '-n', '2', '/mros_str')
    assert echoed.count('first_name: "Phil"') == 2 and echoed.count('age: 83') == 2

    bag_path = str(tmp_path / 'compact.bag')
    record = subprocess.run(['rosbag', 'record', '-O', bag_path, '-l', '3', '/mros_str'], env=ros_graph.env,
                            capture_output=True, text=True, timeout=60)
    assert record.returncode == 0, record.stdout + record.stderr
    assert talker.stop() == 0

    import rosbag  # Debian's python3-rosbag, importable by /usr/bin/python3
    with rosbag.Bag(bag_path) as bag:
        connections = bag._get_connections()
        definitions = {c.header['message_definition'].decode() for c in connections}
        assert definitions == {COMPACT_PERSONAL_DATA}
        messages = [message for _, message, _ in bag.read_messages(topics=['/mros_str'])]
    assert len(messages) == 3
    assert messages[0]._md5sum == PERSONAL_DATA_MD5 and messages[0]._type == 'mros_test/PersonalData'
    assert [(m.first_name, m.last_name, m.age) for m in messages] == [('Phil', 'Woods', 83)] * 3
    assert [m.score - messages[0].score for m in messages] == [0, 1, 2]

    listener = ros_graph.start('rospy listener', ros_workspace.rospy('personal_data_listener.py'))
    ros_graph.wait_for_graph(subscribers=[('/mros_str', '/rospy_personal_listener')])
    play = subprocess.run(['rosbag', 'play', bag_path], env=ros_graph.env, capture_output=True, text=True,
                          timeout=60)
    assert play.returncode == 0, play.stdout + play.stderr
    listener.wait_for(r'I heard from mROS: Phil Woods age:83 score:%d' % (messages[2].score))
