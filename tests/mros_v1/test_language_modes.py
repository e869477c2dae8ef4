# SPDX-License-Identifier: BSD-3-Clause
"""One firmware, two language modes: mROS v1's Makefiles build ros.cpp at
-std=gnu++98, and an app may build at C++11. Every message type must then
have one definition in both: GCC's link-time check of the one-definition
rule (-flto -Wodr) finds no type that differs between a gnu++98 and a C++11
translation unit of every test_ws header. In bounded storage, since heap
storage's std::vector is libstdc++'s, whose own definition differs between
the two modes."""

import subprocess

from support.compile_checks import every_header_translation_unit
from support.checkout import TEST_WS, run_genmros
from testing.ros_paths import prefix_arguments, ros1_prefixes


def test_every_type_has_one_definition_in_gnu98_and_cxx11(tmp_path):
    options = tmp_path / 'bounds.options'
    options.write_text('* max_size:8 max_count:4\n')
    export = str(tmp_path / 'include')
    run_genmros('mros-v1-export', '--workspace', TEST_WS, *prefix_arguments(ros1_prefixes()), '-o',
                export, '--storage', 'bounded', '--options', str(options))
    source = str(tmp_path / 'every_header.cpp')
    assert every_header_translation_unit(export, source) > 10
    main = tmp_path / 'main.cpp'
    main.write_text('#include <stdint.h>\n'
                    'int exerciseAll(uint8_t* buffer, uint32_t size);\n'
                    'int exerciseAllCxx11(uint8_t* buffer, uint32_t size);\n'
                    'static uint8_t buffer[65536];\n'
                    'int main() { return exerciseAll(buffer, sizeof buffer) + '
                    'exerciseAllCxx11(buffer, sizeof buffer) > 0 ? 0 : 1; }\n')
    objects = []
    for mode, flags in (('gnu++98', []), ('c++11', ['-DexerciseAll=exerciseAllCxx11'])):
        objects.append(str(tmp_path / ('%s.o' % mode)))
        subprocess.run(['g++', '-std=' + mode, '-O1', '-flto', '-c', '-I', export] + flags
                       + [source, '-o', objects[-1]], check=True)
    linked = subprocess.run(['g++', '-std=c++11', '-O1', '-flto', '-Wodr', '-Werror', str(main)]
                            + objects + ['-o', str(tmp_path / 'firmware')],
                            capture_output=True, text=True)
    assert linked.returncode == 0, linked.stderr[-3000:]
    assert 'One Definition Rule' not in linked.stderr
