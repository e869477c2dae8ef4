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
