# SPDX-License-Identifier: BSD-3-Clause
"""What genmros' libFuzzer runs share (fuzz.py, fuzz_mros2.py): running a
harness over its corpus for a while, and the table a run ends with."""

import os
import re
import subprocess
import sys

# The files libFuzzer keeps of an input that failed.
ARTIFACT_PREFIXES = ('crash-', 'leak-', 'oom-', 'timeout-')


def run(program, corpus_dir, seconds, build_dir, max_len):
    """(exit status, libFuzzer's final stats {name: value}, its log) of a run
    of program over corpus_dir for seconds, inputs up to max_len bytes; an
    input that fails is kept in build_dir."""
    result = subprocess.run(
        [program, '-max_total_time=%d' % seconds, '-print_final_stats=1', '-rss_limit_mb=2048',
         '-artifact_prefix=%s/' % build_dir, '-max_len=%d' % max_len, corpus_dir],
        capture_output=True, text=True)
    return (result.returncode, dict(re.findall(r'^stat::(\w+):\s+(\d+)', result.stderr, re.M)),
            result.stderr)


def report(title, rows, build_dir, returncode, log):
    """Print the run's table (rows: (label, value)), its result and where it
    built; returns the script's exit status."""
    if returncode == 0:
        result = 'no crash'
    else:
        artifacts = sorted(name for name in os.listdir(build_dir)
                           if name.startswith(ARTIFACT_PREFIXES))
        result = 'FAILED (exit %d%s)' % (returncode,
                                         ': ' + ', '.join(artifacts) if artifacts else '')
    print('| %s | |\n|---|---|' % title)
    for label, value in list(rows) + [('result', result)]:
        print('| %s | %s |' % (label, value))
    print('build dir: %s' % build_dir)
    if returncode != 0:
        print(log[-8000:], file=sys.stderr)
    return 0 if returncode == 0 else 1
