# SPDX-License-Identifier: BSD-3-Clause
"""What genmros mros2-pc reads before it builds: the app's sources and endpoints, the
board's config and the one change it makes to fit mros2, the tcpip thread's stack, and the
stand-ins' settings header."""

import pytest

from colcon_mros.errors import GenmrosError
from colcon_mros.library_tools.mros2.pc_target import build

CONFIG = '''namespace rtps {
namespace Config {
const uint8_t DOMAIN_ID = 3;
const std::array<uint8_t, 4> IP_ADDRESS = {
    10, 0, 0, 7}; // the board's
const int THREAD_POOL_READER_STACKSIZE = 4096;
}
}
'''


def test_the_apps_sources_from_its_filelists_and_its_endpoints_from_its_calls(tmp_path):
    (tmp_path / 'Filelists.cmake').write_text(
        'set(apl_SRCS\n  ${PROJECT_SOURCE_DIR}/workspace/${MROS2_APPNAME}/app.cpp\n)\n')
    (tmp_path / 'app.cpp').write_text(
        'auto pub = node.create_publisher<std_msgs::msg::String>("to_linux", 10);\n'
        'auto sub = node.create_subscription< geometry_msgs::msg::Pose >( "cmd_vel", 10, f);\n'
        'node.create_service<std_srvs::srv::SetBool>("enable", on_enable);\n'
        'auto client = node.create_client<std_srvs::srv::Trigger>( "reset");\n')
    (tmp_path / 'other.cpp').write_text('')
    sources = build.app_sources(str(tmp_path))
    assert sources == [str(tmp_path / 'app.cpp')]
    assert build.app_endpoints(sources) == (['to_linux:std_msgs/msg/String'],
                                            ['cmd_vel:geometry_msgs/msg/Pose'],
                                            ['enable:std_srvs/srv/SetBool'],
                                            ['reset:std_srvs/srv/Trigger'])


def test_the_config_declares_the_address_mros2_defines(tmp_path):
    config = tmp_path / 'board' / 'rtps' / 'config.h'
    config.parent.mkdir(parents=True)
    config.write_text(CONFIG)
    mros2 = tmp_path / 'mros2' / 'src' / 'mros2.cpp'
    mros2.parent.mkdir(parents=True)
    mros2.write_text('namespace rtps {\nnamespace Config {\n    std::array<uint8_t, 4> IP_ADDRESS;'
                     '\n}\n}\n')
    board = build.BoardConfig(str(config), str(tmp_path / 'mros2'))
    assert board.address == '10.0.0.7' and board.sets_address
    assert board.change == (
        '%s:4: rtps::Config::IP_ADDRESS is defined by this mros2 too (%s:3), which sets it at '
        'start-up: the copy declares it, extern std::array<uint8_t, 4> IP_ADDRESS;'
        % (config, mros2))
    copy = tmp_path / 'build'
    assert board.directory(str(copy)) == str(copy / 'config')
    text = (copy / 'config' / 'rtps' / 'config.h').read_text()
    assert '\nextern std::array<uint8_t, 4> IP_ADDRESS;\n' in text
    assert '10, 0, 0, 7' not in text and config.read_text() == CONFIG
    mros2.write_text('// v0.4.1 defines no address\n')
    unchanged = build.BoardConfig(str(config), str(tmp_path / 'mros2'))
    assert unchanged.change is None and unchanged.directory(str(copy)) == str(tmp_path / 'board')


def test_the_tcpip_threads_stack_from_lwipopts_or_the_stated_default(tmp_path):
    assert build._tcpip_stack(None) == (1024, "TCPIP_THREAD_STACKSIZE, genmros' default 1024 "
                                              "(--lwipopts gives the port's)")
    lwipopts = tmp_path / 'lwipopts.h'
    lwipopts.write_text('#define TCPIP_THREAD_PRIO 24\n#define TCPIP_THREAD_STACKSIZE (512 * 4)\n')
    assert build._tcpip_stack(str(lwipopts)) == (2048, 'TCPIP_THREAD_STACKSIZE, %s:2' % lwipopts)
    lwipopts.write_text('#define TCPIP_THREAD_PRIO 24\n')
    with pytest.raises(GenmrosError, match='sets no TCPIP_THREAD_STACKSIZE'):
        build._tcpip_stack(str(lwipopts))


def test_the_settings_header_escapes_what_it_quotes():
    header = build.settings_header('192.168.11.3', 4096, 1024,
                                   [('ReaderThread', 'rtps::Config::X, "/a b/config.h":3')], 0)
    assert '#define MROS2_PC_RECEIVE_LIMIT 4096\n' in header
    assert '{"ReaderThread", "rtps::Config::X, \\"/a b/config.h\\":3"}' in header
