"""Every test message type through mROS POSIX nodes and real ROS nodes, both
directions: every built-in type, every array form, nested and cross-package
types, Header with time stamps. A rospy node sends samples (message_samples.py)
and checks that the same bytes come back through the relays."""


TYPES = ['ArrayTypes', 'BuiltinTypes', 'Constants', 'Empty', 'Header', 'NestedTypes',
         'PersonalData']


def mros_relay(graph, firmware, name, source, sink):
    relay = graph.start(name, firmware.node('mros_type_relay', source, sink, '__name:=' + name))
    relay.wait_for(r'relaying %s/\* to %s/\*' % (source, sink))
    return relay


def run_check(graph, workspace, *arguments):
    check = graph.start('roundtrip_check', workspace.rospy('roundtrip_check.py', *arguments))
    check.popen.wait(timeout=120)
    return check


def test_rospy_to_mros_to_rospy_keeps_every_field(ros_graph, ros_workspace, mros_firmware):
    relay = mros_relay(ros_graph, mros_firmware, 'mros_relay', '/src', '/back')
    check = run_check(ros_graph, ros_workspace, '/src', '/back')
    assert check.popen.returncode == 0, check.output() + '\n' + relay.output()
    for name in TYPES:
        check.wait_for(r'^PASS %s: \d+ samples' % name, timeout=0)
    assert relay.alive()


def test_chain_rospy_mros_roscpp_mros_rospy(ros_graph, ros_workspace, mros_firmware):
    # roscpp renumbers header.seq of every message with a header it publishes.
    mros_relay(ros_graph, mros_firmware, 'mros_relay_a', '/src', '/m1')
    ros_graph.start('roscpp type_relay', ros_workspace.roscpp('type_relay', '/m1', '/c1'))
    mros_relay(ros_graph, mros_firmware, 'mros_relay_b', '/c1', '/m2')
    check = run_check(ros_graph, ros_workspace, '/src', '/m2', '--ignore-header-seq')
    assert check.popen.returncode == 0, check.output()
    for name in TYPES:
        check.wait_for(r'^PASS %s: \d+ samples' % name, timeout=0)
