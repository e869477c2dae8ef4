# SPDX-License-Identifier: BSD-3-Clause
"""genmros mros2-peer-profile: the Fast DDS profile of the ROS nodes that talk to an mros2
board, valid against the Fast DDS schema the ROS 2 wheels ship, with the numbers given. The
PC-target tests run rclpy with it (tests/library_tools/mros2/pc_target/test_large_samples.py)."""

import os

from lxml import etree

from support.checkout import run_genmros
from testing.mros2_pc import WHEELS_VENV

SCHEMA = os.path.join(WHEELS_VENV, 'share', 'fastdds', 'fastdds_profiles.xsd')
FAST_DDS = {'dds': 'http://www.eprosima.com'}


def test_the_profile_is_fast_dds_xml_with_the_numbers_given(tmp_path):
    profile = tmp_path / 'board_peer.xml'
    result = run_genmros('mros2-peer-profile', '--peer-max-message', '1472', '--receive-buffer',
                         '1048576', '-o', str(profile))
    assert result.stdout == 'genmros: wrote %s\n' % profile
    document = etree.parse(str(profile))
    etree.XMLSchema(etree.parse(SCHEMA)).assertValid(document)
    assert [document.findtext('.//dds:%s' % name, namespaces=FAST_DDS)
            for name in ('maxMessageSize', 'receiveBufferSize', 'useBuiltinTransports')] == [
        '1472', '1048576', 'false']
    assert run_genmros('mros2-peer-profile', '--peer-max-message', '1472').stdout == \
        profile.read_text().replace('1048576', '4194304')


def test_a_limit_below_the_discovery_announcement_is_refused(tmp_path):
    profile = tmp_path / 'board_peer.xml'
    result = run_genmros('mros2-peer-profile', '--peer-max-message', '500', '-o', str(profile),
                         check=False)
    assert (result.returncode, result.stderr) == (1, (
        "genmros: error: --peer-max-message 500: below 572 bytes, a ROS 2 node's SPDP "
        'announcement as Fast DDS 3 sends it: the board would discover no such node\n'))
    assert not profile.exists()
