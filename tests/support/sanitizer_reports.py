# SPDX-License-Identifier: BSD-3-Clause
"""Sanitizer reports in the output of an app built with genmros mros-v1-pc
--sanitize, each placed in the file it belongs to: an overflow of a global
variable belongs where the variable is defined; any other report to its
first frame in a source file (below the sanitizer's own interceptors), and a
UBSan report to the line it starts with. A report placed in the PC target's
own files fails the test that reads it."""

import os
import re

UBSAN_REPORT = re.compile(r'^(\S+?):(\d+):\d+: runtime error: (.*)$', re.M)
ASAN_REPORT = re.compile(r'ERROR: AddressSanitizer: (\S+)((?:.|\n)*?)(?:^SUMMARY|\Z)', re.M)
FIRST_SOURCE_FRAME = re.compile(r'#\d+ 0x[0-9a-f]+ in \S+ (/(?!\S*libsanitizer)\S+?):(\d+)')
OVERFLOWED_GLOBAL = re.compile(r"to the right of global variable '\w+' defined in '([^':]+):(\d+)")
# The library's own reports in ordinary runs (see the README's limits of
# the library): its TCPROS header decoder reads each field's length as a
# uint32 at whatever offset the field starts.
LIBRARY_REPORTS = {('mros_packet_decoder_cimpl.c', 504,
                    "load of misaligned address for type 'mRosSizeType', which requires 4 byte "
                    "alignment")}


def _asan_place(kind, report):
    match = OVERFLOWED_GLOBAL.search(report) or FIRST_SOURCE_FRAME.search(report)
    return (match.group(1), int(match.group(2)), kind) if match else ('?', 0, kind)


def sanitizer_reports(output):
    """{(file name, line, problem)} of every report in output, addresses
    left out."""
    reports = {(path, int(line), re.sub(r' 0x[0-9a-f]+', '', problem))
               for path, line, problem in UBSAN_REPORT.findall(output)}
    reports |= {_asan_place(kind, report) for kind, report in ASAN_REPORT.findall(output)}
    ours = [report for report in reports if '/colcon_mros/' in report[0]]
    assert not ours, 'sanitizer reports from the PC target itself: %s\n%s' % (ours, output)
    return {(os.path.basename(path), line, problem) for path, line, problem in reports}
