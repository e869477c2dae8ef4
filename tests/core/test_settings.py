# SPDX-License-Identifier: BSD-3-Clause
"""The mROS v1 settings (colcon_mros.core.settings): #defines read from C
headers as the preprocessor reads a number, with the file and line of each."""

from colcon_mros.core.settings import read_settings


def test_settings_are_read_as_the_preprocessor_reads_numbers(tmp_path):
    first = tmp_path / 'first.h'
    first.write_text('#define A 512\n#define B\t50U  /* comment */\n#define C (1024U) // c\n'
                     '#define D A\n#define E "text"\n#define F(x) x\n  #  define G 7\n')
    second = tmp_path / 'second.h'
    second.write_text('#define A 4096\n#define H 3\n')
    settings = read_settings([str(first), str(second)])
    assert {name: (s.value, s.line) for name, s in settings.items()} == {
        'A': (512, 1), 'B': (50, 2), 'C': (1024, 3), 'D': (512, 4), 'G': (7, 7), 'H': (3, 2)}
    assert settings['A'].where() == '%s:1' % first


def test_cpp_constants_and_their_arithmetic_are_read(tmp_path):
    config = tmp_path / 'config.h'
    config.write_text(
        'namespace rtps {\nnamespace Config {\n'
        'const VendorId_t VENDOR_ID = {13, 37};\n'
        'const uint8_t MAX_NUM_PARTICIPANTS = 2;\n'
        'const uint8_t NUM_STATELESS_WRITERS =\n    MAX_NUM_PARTICIPANTS + 1; // Required\n'
        'const int THREAD_POOL_READER_STACKSIZE = 1600; // byte\n'
        'static constexpr uint16_t SPDP_WRITER_STACKSIZE = 550u;\n'
        'constexpr int OVERALL = 2 * (THREAD_POOL_READER_STACKSIZE - 100);\n'
        'const std::array<uint8_t, 4> IP_ADDRESS = {\n'
        'const uint8_t LOOP = LOOP + 1;\n'
        'const float RATE = 0.5;\n'
        '#define USER_LIMIT 4096\n}\n}\n')
    settings = read_settings([str(config)])
    assert {name: (s.value, s.line) for name, s in settings.items()} == {
        'MAX_NUM_PARTICIPANTS': (2, 4), 'NUM_STATELESS_WRITERS': (3, 5),
        'THREAD_POOL_READER_STACKSIZE': (1600, 7), 'SPDP_WRITER_STACKSIZE': (550, 8),
        'OVERALL': (3000, 9), 'USER_LIMIT': (4096, 13)}
