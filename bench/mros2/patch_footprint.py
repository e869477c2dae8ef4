#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""What each of genmros' mros2 patches costs in a Cortex-M4 build.

    MROS2_ROOT=<mros2 checkout> /usr/bin/python3 bench/mros2/patch_footprint.py [--jobs N]

mros2's src/mros2.cpp and every embeddedRTPS source, compiled as a Cortex-M4
firmware compiles them (arm-none-eabi-g++ -Os -mcpu=cortex-m4 -mthumb
-mfloat-abi=hard -mfpu=fpv4-sp-d16 -fno-exceptions -fno-rtti, sections per
function), with the series' first patches applied one more at a time
(colcon_mros.library_tools.mros2.patches, on a copy): text, data and bss of
the objects (arm-none-eabi-size, before the link drops what is unused), and
what each patch adds to the row before it. The app is one publisher and one
subscriber of std_msgs/String (genmros mros2-export from the ROS 2 wheels,
templates.hpp included); the board config is the main job's (evaluation/mros2_app). The
RTOS and lwIP declarations are the PC target's stand-ins; their uint32_t is
an unsigned int, as mros2's FreeRTOS layer declares it (newlib's would be an
unsigned long), which changes no size.
"""

import argparse
import concurrent.futures
import glob
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, REPO)

from colcon_mros.library_tools.mros2.patches import LIBRARY_DIRS, mros2_patches  # noqa: E402
from colcon_mros.library_tools.mros2.pc_target.build import TARGET_DIR  # noqa: E402
from colcon_mros.library_tools.patch_series import apply_patches  # noqa: E402
from testing.ros_paths import prefix_arguments, ros2_wheels  # noqa: E402

CONFIG = os.path.join(REPO, 'evaluation', 'mros2_app', 'rtps', 'config.h')
FLAGS = ['-Os', '-std=gnu++14', '-mcpu=cortex-m4', '-mthumb', '-mfloat-abi=hard',
         '-mfpu=fpv4-sp-d16', '-fno-exceptions', '-fno-rtti', '-ffunction-sections',
         '-fdata-sections', '-U__UINT32_TYPE__', '-D__UINT32_TYPE__=unsigned int',
         '-U__INT32_TYPE__', '-D__INT32_TYPE__=int']


def export(work):
    """genmros' headers and templates.hpp for the app; their directory."""
    directory = os.path.join(work, 'export')
    subprocess.run([sys.executable, '-m', 'colcon_mros', 'mros2-export',
                    *prefix_arguments([ros2_wheels()]), '--publish',
                    'chatter:std_msgs/msg/String', '--subscribe', 'command:std_msgs/msg/String',
                    '-o', directory], check=True, cwd=REPO, stdout=subprocess.DEVNULL)
    return directory


def sizes(tree, includes, objects, jobs):
    """(text, data, bss) of mros2.cpp and embeddedRTPS' sources in tree."""
    sources = [os.path.join(tree, 'src', 'mros2.cpp')] + sorted(
        glob.glob(os.path.join(tree, 'embeddedRTPS', 'src', '**', '*.cpp'), recursive=True))
    rtps = os.path.join(tree, 'embeddedRTPS')
    include_flags = [flag for directory in includes + [
        os.path.join(rtps, 'include'), os.path.join(rtps, 'thirdparty', 'Micro-CDR', 'include'),
        os.path.join(tree, 'include')] for flag in ('-I', directory)]
    os.makedirs(objects, exist_ok=True)

    def compile_one(index_source):
        index, source = index_source
        target = os.path.join(objects, '%02d.o' % index)
        subprocess.run(['arm-none-eabi-g++', *FLAGS, *include_flags, '-c', source, '-o', target],
                       check=True)
        return target

    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        targets = list(pool.map(compile_one, enumerate(sources)))
    total = subprocess.run(['arm-none-eabi-size', '-t', *targets], check=True,
                           capture_output=True, text=True).stdout.splitlines()[-1].split()
    return tuple(int(value) for value in total[:3])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--jobs', type=int, default=2)
    options = parser.parse_args()
    root = os.environ.get('MROS2_ROOT')
    if not root or not os.path.isfile(os.path.join(root, 'src', 'mros2.cpp')):
        sys.exit('%s: needs an mros2 checkout: set MROS2_ROOT' % sys.argv[0])
    with tempfile.TemporaryDirectory(prefix='genmros-patch-footprint-') as work:
        config = os.path.join(work, 'config', 'rtps')
        os.makedirs(config)
        shutil.copy(CONFIG, config)
        includes = [os.path.dirname(config), export(work), os.path.join(TARGET_DIR, 'include')]
        series = mros2_patches()
        rows = []
        for count in range(len(series) + 1):
            tree = os.path.join(work, 'tree%d' % count)
            for part in LIBRARY_DIRS:
                shutil.copytree(os.path.join(root, part), os.path.join(tree, part))
            apply_patches(tree, series[:count])
            name = series[count - 1].name if count else '(mros2 as it is)'
            rows.append((name, sizes(tree, includes, os.path.join(work, 'objects%d' % count),
                                     options.jobs)))
            shutil.rmtree(tree)
            print('%s: text %d, data %d, bss %d' % ((name,) + rows[-1][1]), file=sys.stderr,
                  flush=True)
    print('Bytes of mros2.cpp and embeddedRTPS (Cortex-M4, -Os, objects before the link), '
          'each patch applied after those above it\n')
    print('| patch | text | data | bss | text added | bss added |')
    print('|---|---:|---:|---:|---:|---:|')
    previous = rows[0][1]
    for name, (text, data, bss) in rows:
        print('| %s | %d | %d | %d | %+d | %+d |'
              % (name, text, data, bss, text - previous[0], bss - previous[2]))
        previous = (text, data, bss)
    first, last = rows[0][1], rows[-1][1]
    print('| **the series** | %d | %d | %d | %+d | %+d |'
          % (last + (last[0] - first[0], last[2] - first[2])))


if __name__ == '__main__':
    main()
