# SPDX-License-Identifier: BSD-3-Clause
"""Hostile definitions: what genmsg accepts either works in C++ or is refused.

Every accepted definition gives headers that compile alone and together at
-Wall -Wextra -Wshadow -Werror -pedantic in gnu++98, c++11, c++14 and c++17,
and whose messages round-trip random wire images (written here from genmsg's
field lists, not by genmros) under AddressSanitizer. Every refused one stops
both modes with one ``FILE:LINE: problem`` line and leaves the output as it
was. Deep, wide and long definitions finish in seconds.
"""

import os
import random
import shutil
import struct
import subprocess
import time
from concurrent.futures import ThreadPoolExecutor

import pytest

from genmsg import gentools, msg_loader
from genmsg.msgs import bare_msg_type, is_builtin, parse_type

from support.checkout import run_genmros
from support.file_trees import assert_one_line_error, package_xml, snapshot, write_tree
from testing.ros_paths import prefix_arguments, ros1_package_dir, ros1_prefixes

pytestmark = pytest.mark.slow

LANGUAGE_MODES = ['gnu++98', 'c++11', 'c++14', 'c++17']
STRICT = ['-Wall', '-Wextra', '-Wshadow', '-Werror', '-pedantic', '-fno-exceptions', '-fno-rtti']
SANITIZERS = ['-fsanitize=address,undefined', '-fno-sanitize-recover=all', '-g']


def _type_per_line(prefix, declarations):
    """One case per declaration: {case id: {msg/<Prefix><Index>.msg: declaration}}."""
    return [('%s-%s' % (prefix.lower(), declaration.split()[1].split('=')[0]),
             {'msg/%s%d.msg' % (prefix, index): declaration + '\n'})
            for index, declaration in enumerate(declarations)]


# Floating-point constants at the edges of their types: those that round to
# zero or to a subnormal compile without a warning and hold the value the
# type holds after the conversion (test_float_constants_hold_what_their_type_holds).
FLOAT_LIMITS_MSG = (
    'float32 F32_TO_ZERO=1e-50\nfloat32 F32_TO_MINUS_ZERO=-1e-50\nfloat32 F32_SUBNORMAL=1e-40\n'
    'float32 F32_SMALLEST=1.4e-45\nfloat32 F32_MAX=3.4028235e38\n'
    'float32 F32_ROUNDS_TO_MAX=3.40282356e38\n'
    'float32 F32_LOWEST=-3.4028235e38\nfloat32 F32_INF=inf\nfloat32 F32_TENTH=0.1\n'
    'float64 F64_TO_ZERO=1e-400\nfloat64 F64_SUBNORMAL=5e-324\n'
    'float64 F64_MAX=1.7976931348623157e308\n'
    'float64 F64_MINUS_INF=-Infinity\nint32 value\n')

# Accepted: (case id, {path in package hostile_ok: text}). A field or
# constant named like something C++ or the generated code owns is renamed
# with a trailing underscore; everything else keeps its name.
ACCEPTED = [
    ('field-length-beside-string',
     {'msg/FieldLength.msg': 'string length\nuint8[] data\nstring size\n'}),
    ('fields-in-out', {'msg/InOut.msg': 'string in\nstring out\nint32[] count\n'}),
    ('fields-like-generated-locals', {'msg/Locals.msg': (
        'uint32 message\nstring visitor\nuint32 value\nuint8[] buffer\nuint32 capacity\n'
        'uint32 cursor\nuint32 total\nuint32 pos\nuint32 remaining\nuint32 self\nuint32 body\n'
        'uint32 frame\nuint32 callback\nuint32 allocation_budget\n')}),
    ('fields-like-template-names', {'msg/TemplateNames.msg': (
        'uint32 T\nuint32 Message\nuint32 Fields\nuint32 Codec\nuint32 Reader\nuint32 Writer\n'
        'uint32 wire\nuint32 constants\nuint32 Time\n')}),
    ('fields-like-types-and-packages', {'msg/TypeNames.msg': (
        'std_msgs/Header Header\nstd_msgs/Header std_msgs\ngeometry_msgs/Point Point\n'
        'time time\nduration Duration\nstring string\nint32[] vector\nint32[2] array\n'
        'uint8 FILE\nuint8 hostile_ok\nEmpty Empty\n')}),
    ('field-named-like-its-type', {'msg/FieldSelf.msg': 'int32 FieldSelf\nint32 other\n'}),
    ('constant-named-like-its-type',
     {'msg/ConstantSelf.msg': 'uint8 ConstantSelf=1\nint32 value\n'}),
    ('constants-like-template-names', {'msg/ConstantNames.msg': (
        'int32 Unused=1\nint32 unused=2\nint32 T=3\nint32 Message=4\nstring text=a\n')}),
    ('constants-like-macros', {'msg/ConstantMacros.msg': (
        'int32 EOF=-1\nuint32 UINT32_MAX=4294967295\nint32 errno=5\nint32 assert=1\n'
        'uint64 SIZE_MAX=18446744073709551615\nint32 linux=1\nstring stdin=x\n'
        'float64 M_PI=3.14\n')}),
    ('constants-at-integer-limits', {'msg/Limits.msg': (
        'int64 I64_MIN=-9223372036854775808\nint64 I64_MAX=9223372036854775807\n'
        'uint64 U64_MAX=18446744073709551615\nint32 I32_MIN=-2147483648\nint8 I8_MIN=-128\n'
        'uint32 U32_MAX=4294967295\nint16 I16_MIN=-32768\nbyte B=-128\nchar C=255\n'
        'int32 value\n')}),
    ('float-constants-at-their-limits', {'msg/FloatLimits.msg': FLOAT_LIMITS_MSG}),
    ('string-constants-with-escapes', {'msg/Quotes.msg': (
        'string QUOTE="quoted" \\\\ back\nstring TRIGRAPH=??= ??/ ??\'\n'
        'string HASH=a # not a comment\nint32 value\n')}),
    ('zero-length-fixed-arrays',
     {'msg/ZeroArrays.msg': 'int32[0] none\nEmpty[0] empties\nstring[0] texts\n'}),
    ('empty-message', {'msg/Empty.msg': '# nothing\n'}),
    ('empty-nested-in-arrays',
     {'msg/Outer.msg': 'Inner[] inners\n', 'msg/Inner.msg': 'Empty[] es\n'}),
    ('type-named-like-c-function', {'msg/time.msg': 'int32 sec\n'}),
    ('type-named-like-support-types', {'msg/Codec.msg': 'int32 a\n', 'msg/Reader.msg': 'Codec c\n',
                                       'msg/Message.msg': 'Reader r\nCodec[] cs\n'}),
    ('type-named-like-c-type', {'msg/FILE.msg': 'int32 fd\n'}),
    ('types-named-like-support-namespaces',
     {'msg/constants.msg': 'int32 A=1\nint32 a\n',
      'msg/mros_constants.msg': 'int32 B=2\nconstants c\nwire w\n',
      'msg/wire.msg': 'int32 C=3\n'}),
    ('types-differing-in-case', {'msg/Thing.msg': 'int32 a\n', 'msg/THING.msg': 'string b\n'}),
    ('guard-of-package-and-type-underscores', {'msg/b_C.msg': 'int32 from_hostile_ok\n'}),
    ('service-with-hostile-fields',
     {'srv/Ask.srv': 'string length\nint32 EOF\n---\nstring in\nint32 class\n'}),
] + _type_per_line('MacroField', [
    'int32 EOF', 'int32 errno', 'int32 ERANGE', 'int32 EXIT_SUCCESS', 'int32 INT32_MAX',
    'uint32 UINT32_MAX', 'uint64 SIZE_MAX', 'int32 SEEK_SET', 'bool assert', 'string stdin',
    'int32 linux', 'int32 unix', 'int32 NULL', 'int32 offsetof', 'int32 va_arg', 'float64 M_PI',
]) + _type_per_line('TypedefField', [
    'uint32 uint32_t', 'int8 int8_t', 'uint64 size_t', 'string mros', 'string std',
]) + _type_per_line('KeywordField', [
    'int32 class', 'string new', 'int32 delete', 'bool and', 'bool not', 'int32 register',
    'int32 char8_t', 'int32 requires',
]) + _type_per_line('MemberField', [
    'int32 Ptr', 'int32 ConstPtr', 'int32 MROS_TYPE_ID', 'int32 MROS_MAX_SERIALIZED_SIZE',
    'int32 serialize', 'string deserialize', 'int32 memCopy', 'int32 dataSize',
])

# Refused: (case id, package, {path in the package: text}, the file the error
# names, ':LINE:' or ':', problem).
REFUSED = [
    ('package-keyword', 'class', {'msg/A.msg': 'int32 a\n'}, 'msg/A.msg', ':',
     "package name 'class' cannot be a C++ namespace: a C++ keyword"),
    ('package-with-dash', 'my-pkg', {'msg/A.msg': 'int32 a\n'}, 'msg/A.msg', ':',
     "package name 'my-pkg' cannot be a C++ namespace: not an ASCII identifier"),
    ('package-mros', 'mros', {'msg/Time.msg': 'uint32 sec\nuint32 nsec\n'}, 'msg/Time.msg', ':',
     "package name 'mros' cannot be a C++ namespace: a name the generated headers use"),
    ('package-std', 'std', {'msg/A.msg': 'int32 a\n'}, 'msg/A.msg', ':', "package name 'std'"),
    ('package-like-c-function', 'time', {'msg/A.msg': 'int32 a\n'}, 'msg/A.msg', ':',
     'a name the C/C++ standard headers declare in the global namespace'),
    ('package-like-support-template', 'array', {'msg/A.msg': 'int32 a\n'}, 'msg/A.msg', ':',
     "package name 'array' cannot be a C++ namespace: a name the generated headers use"),
    ('package-wire', 'wire', {'msg/A.msg': 'int32 a\n'}, 'msg/A.msg', ':', "package name 'wire'"),
    ('package-macro', 'linux', {'msg/A.msg': 'int32 a\n'}, 'msg/A.msg', ':',
     'a macro of the C/C++ standard headers'),
    ('package-trait', 'message_traits', {'msg/A.msg': 'int32 a\n'}, 'msg/A.msg', ':',
     "package name 'message_traits'"),
    ('type-keyword', 'hostile_bad', {'msg/int.msg': 'int32 a\n'}, 'msg/int.msg', ':',
     "type name 'hostile_bad/int' cannot be a C++ type: a C++ keyword"),
    ('type-keyword-class', 'hostile_bad', {'msg/class.msg': 'int32 a\n'}, 'msg/class.msg', ':',
     'a C++ keyword'),
    ('type-macro', 'hostile_bad', {'msg/EOF.msg': 'int32 a\n'}, 'msg/EOF.msg', ':',
     'a macro of the C/C++ standard headers'),
    ('type-gnu-macro', 'hostile_bad', {'msg/unix.msg': 'int32 a\n'}, 'msg/unix.msg', ':',
     'a macro of the C/C++ standard headers'),
    ('type-fixed-width-name', 'hostile_bad', {'msg/uint32_t.msg': 'int32 a\n'},
     'msg/uint32_t.msg', ':', 'a name the generated headers use'),
    ('type-mros', 'hostile_bad', {'msg/mros.msg': 'int32 a\n'}, 'msg/mros.msg', ':',
     'a name the generated headers use'),
    ('type-std', 'hostile_bad', {'msg/std.msg': 'int32 a\n'}, 'msg/std.msg', ':',
     'a name the generated headers use'),
    ('type-reserved-member', 'hostile_bad', {'msg/Ptr.msg': 'int32 a\n'}, 'msg/Ptr.msg', ':',
     'a name the generated headers use'),
    ('type-like-its-package', 'hostile_bad', {'msg/hostile_bad.msg': 'int32 a\n'},
     'msg/hostile_bad.msg', ':', 'the name of its package'),
    ('type-non-ascii', 'hostile_bad', {'msg/a\u00b2.msg': 'int32 a\n'}, 'msg/a\u00b2.msg', ':',
     "type name 'hostile_bad/a\u00b2' cannot be a C++ type: not an ASCII identifier"),
    ('type-like-used-package', 'hostile_bad',
     {'msg/std_msgs.msg': 'int32 a\n', 'msg/User.msg': 'int32 a\nstd_msgs/Header header\n'},
     'msg/User.msg', ':2:', "type 'hostile_bad/std_msgs' is named like package 'std_msgs'"),
    ('field-non-ascii', 'hostile_bad', {'msg/A.msg': 'int32 ok\nint32 a\u00b2\n'},
     'msg/A.msg', ':2:', "'a\u00b2' is not a legal field name for C++"),
    ('constant-non-ascii', 'hostile_bad', {'msg/A.msg': 'int32 \u00fc=1\n'}, 'msg/A.msg', ':1:',
     "'\u00fc' is not a legal constant name for C++"),
    ('escape-meets-field', 'hostile_bad', {'msg/A.msg': 'int32 EOF\nint32 EOF_\n'},
     'msg/A.msg', ':2:', "name 'EOF_' is already declared on line 1"),
    ('escape-meets-typedef-field', 'hostile_bad', {'msg/A.msg': 'int32 uint8_t_\nint32 uint8_t\n'},
     'msg/A.msg', ':2:', "name 'uint8_t' is already declared on line 1"),
    ('escape-meets-own-type', 'hostile_bad', {'msg/A.msg': 'int32 A_\nint32 A\n'},
     'msg/A.msg', ':2:', "name 'A' is already declared on line 1"),
    ('service-named-like-its-typedef', 'hostile_bad', {'srv/Request.srv': 'int32 a\n---\n'},
     'srv/Request.srv', ':',
     "service name 'hostile_bad/Request' cannot be a C++ type: a name the service header uses"),
    ('service-named-like-its-member', 'hostile_bad', {'srv/response.srv': 'int32 a\n---\n'},
     'srv/response.srv', ':', "service name 'hostile_bad/response'"),
    ('srv-meets-request-msg', 'hostile_bad',
     {'srv/Foo.srv': 'int32 a\n---\n', 'msg/FooRequest.msg': 'int32 a\n'},
     'msg/FooRequest.msg', ':', "'hostile_bad/FooRequest' would be defined twice"),
    ('srv-meets-response-msg', 'hostile_bad',
     {'srv/Foo.srv': 'int32 a\n---\n', 'msg/FooResponse.msg': 'int32 a\n'},
     'msg/FooResponse.msg', ':', "'hostile_bad/FooResponse' would be defined twice"),
    ('srv-meets-request-srv', 'hostile_bad',
     {'srv/Foo.srv': 'int32 a\n---\n', 'srv/FooRequest.srv': 'int32 a\n---\n'},
     'srv/Foo.srv', ':', "'hostile_bad/FooRequest' would be defined twice"),
    ('srv-meets-msg', 'hostile_bad',
     {'srv/Pair.srv': 'int32 a\n---\n', 'msg/Pair.msg': 'int32 a\n'},
     'msg/Pair.msg', ':', "'hostile_bad/Pair' would be defined twice"),
    ('fixed-array-beyond-int32', 'hostile_bad', {'msg/A.msg': 'int8 a\nuint8[2147483648] big\n'},
     'msg/A.msg', ':2:',
     'uint8[2147483648]: more elements than the 2147483647 a message can have'),
    ('empty-elements-beyond-int32', 'hostile_bad',
     {'msg/A.msg': 'Empty[4294967296] e\n', 'msg/Empty.msg': ''},
     'msg/A.msg', ':1:', 'more elements than the 2147483647'),
    ('fixed-size-2-to-31', 'hostile_bad', {'msg/A.msg': 'uint8[2147483647] a\nuint8 b\n'},
     'msg/A.msg', ':', 'hostile_bad/A takes at least 2147483648 bytes on the wire'),
    ('min-size-of-strings', 'hostile_bad', {'msg/A.msg': 'string[600000000] s\n'},
     'msg/A.msg', ':', 'takes at least 2400000000 bytes'),
    ('nested-fixed-size', 'hostile_bad',
     {'msg/Big.msg': 'uint8[1073741824] a\n', 'msg/Huge.msg': 'Big[2] b\n'},
     'msg/Huge.msg', ':', 'hostile_bad/Huge takes at least 2147483648 bytes'),
    ('int64-just-past-max', 'hostile_bad', {'msg/A.msg': 'int64 X=9223372036854775808\n'},
     'msg/A.msg', ':1:', 'cannot coerce [9223372036854775808] to int64 (out of bounds)'),
    ('uint64-just-past-max', 'hostile_bad',
     {'msg/A.msg': 'int8 a\nuint64 X=18446744073709551616\n'},
     'msg/A.msg', ':2:', 'cannot coerce [18446744073709551616] to uint64 (out of bounds)'),
    ('int64-just-past-min', 'hostile_bad', {'msg/A.msg': 'int64 X=-9223372036854775809\n'},
     'msg/A.msg', ':1:', 'out of bounds'),
    ('uint32-past-max', 'hostile_bad',
     {'msg/A.msg': 'uint32 X=4294967296\n'}, 'msg/A.msg', ':1:', 'out of bounds'),
    ('float32-beyond-max', 'hostile_bad', {'msg/A.msg': 'int8 a\nfloat32 X=1e39\n'},
     'msg/A.msg', ':2:',
     'float32 constant 1e39 is beyond the range of float32 '
     '(largest finite value 3.4028234663852886e+38)'),
    ('float32-just-beyond-max', 'hostile_bad', {'msg/A.msg': 'float32 X=3.4028236e38\n'},
     'msg/A.msg', ':1:', 'float32 constant 3.4028236e38 is beyond the range of float32'),
    ('float32-beyond-lowest', 'hostile_bad', {'msg/A.msg': 'float32 X=-1e39\n'},
     'msg/A.msg', ':1:', 'float32 constant -1e39 is beyond the range of float32'),
    ('float64-beyond-max', 'hostile_bad', {'msg/A.msg': 'float64 Y=1e400\n'},
     'msg/A.msg', ':1:',
     'float64 constant 1e400 is beyond the range of float64 '
     '(largest finite value 1.7976931348623157e+308)'),
    ('float64-beyond-lowest', 'hostile_bad', {'msg/A.msg': 'int8 a\nint8 b\nfloat64 Y=-2e308\n'},
     'msg/A.msg', ':3:', 'float64 constant -2e308 is beyond the range of float64'),
    ('srv-second-separator', 'hostile_bad',
     {'srv/A.srv': 'int32 a\n---\nint32 b\n---\nint32 c\nfloat32 1x\n'},
     'srv/A.srv', ':6:', '1x is not a legal message field name'),
    ('srv-second-separator-duplicate', 'hostile_bad',
     {'srv/A.srv': 'int32 a\n---\nint32 b\n---\nint32 b\n'},
     'srv/A.srv', ':5:', "duplicate field name 'b'"),
    ('srv-only-package-unknown-type', 'hostile_srv_only',
     {'srv/A.srv': 'int32 a\n---\nMissing m\n'}, 'srv/A.srv', ':3:',
     "unknown type 'hostile_srv_only/Missing' (package hostile_srv_only has no msg directory)"),
]


def _load_specs(search_path, full_names):
    context = msg_loader.MsgContext.create_default()
    for full_name in full_names:
        spec = msg_loader.load_msg_by_type(context, full_name, search_path)
        msg_loader.load_depends(context, spec, search_path)
    return context


class WireImages:
    """Random ROS 1 wire images of a type, written from genmsg's field list."""

    FORMATS = {'bool': '<B', 'int8': '<b', 'uint8': '<B', 'byte': '<b', 'char': '<B',
               'int16': '<h', 'uint16': '<H', 'int32': '<i', 'uint32': '<I', 'int64': '<q',
               'uint64': '<Q',
               'float32': '<I', 'float64': '<Q', 'time': '<II', 'duration': '<ii'}

    def __init__(self, context, seed):
        self.context = context
        self.random = random.Random(seed)

    def _scalar(self, base_type):
        if base_type == 'string':
            size = self.random.choice([0, 1, 7, 300])
            return struct.pack('<I', size) + bytes(self.random.getrandbits(8) for _ in range(size))
        if base_type == 'bool':
            return struct.pack('<B', self.random.randint(0, 1))
        fmt = self.FORMATS[base_type]
        values = []
        for code in fmt[1:]:
            size = struct.calcsize('<' + code)
            signed = code.islower()
            low, high = ((-(1 << (8 * size - 1)), (1 << (8 * size - 1)) - 1) if signed
                         else (0, (1 << (8 * size)) - 1))
            values.append(self.random.randint(low, high))
        return struct.pack(fmt, *values)

    def image(self, full_name):
        spec = self.context.get_registered(full_name)
        out = b''
        for field_type in spec.types:
            base_type, is_array, length = parse_type(field_type)
            count = 1
            if is_array:
                count = length if length is not None else self.random.randint(0, 3)
                if length is None:
                    out += struct.pack('<I', count)
            for _ in range(count):
                out += self._scalar(base_type) if is_builtin(
                    base_type) else self.image(bare_msg_type(base_type))
        return out


ROUND_TRIP = r'''
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vector>
%(includes)s

static int failures = 0;

// Decodes image into a reused (dirty) message, checks the length and the
// re-encoding, and that a buffer one byte short is refused.
template <class M> void roundTrip(M& message, const char* name, const std::vector<uint8_t>& image) {
  const uint32_t size = static_cast<uint32_t>(image.size());
  uint8_t* input = static_cast<uint8_t*>(calloc(size + 1, 1));
  if (size) memcpy(input, &image[0], size);
  const int32_t consumed = message.deserialize(input, size);
  free(input);
  uint8_t* output = static_cast<uint8_t*>(malloc(size + 1));
  if (consumed != static_cast<int32_t>(size) || message.serializedLength() != size ||
      message.serialize(output, size) != static_cast<int32_t>(size) ||
      (size && memcmp(output, &image[0], size) != 0)) {
    printf("FAIL %%s (%%u bytes)\n", name, size);
    ++failures;
  }
  free(output);
  if (size > 0) {
    uint8_t* short_output = static_cast<uint8_t*>(malloc(size - 1 + 1));
    if (message.serialize(short_output, size - 1) != -1) {
      printf("FAIL %%s: short buffer accepted\n", name);
      ++failures;
    }
    free(short_output);
  }
}

static std::vector<uint8_t> next(FILE* in, uint32_t& type) {
  uint32_t header[2];
  if (fread(header, 4, 2, in) != 2) return std::vector<uint8_t>(1, 0);
  type = header[0];
  std::vector<uint8_t> image(header[1]);
  if (header[1] && fread(&image[0], 1, header[1], in) != header[1]) exit(2);
  return image;
}

int main(int argc, char** argv) {
  FILE* in = fopen(argv[1], "rb");
  int images = 0;
  for (;;) {
    uint32_t type = 0xffffffffu;
    std::vector<uint8_t> image = next(in, type);
    if (type == 0xffffffffu) break;
    switch (type) {
%(cases)s
    }
    ++images;
  }
  (void)argc;
  printf("%%d images, %%d failures\n", images, failures);
  return failures != 0;
}
'''  # noqa: E501


def _accepted_files():
    files = {'package.xml': package_xml('hostile_ok')}
    for _, case_files in ACCEPTED:
        files.update(case_files)
    return files


# hostile_ok_b/C and hostile_ok/b_C: one guard if the package's length were not in it.
GUARD_TWIN = {'package.xml': package_xml(
    'hostile_ok_b'), 'msg/C.msg': 'string from_hostile_ok_b\n'}


@pytest.fixture(scope='module')
def accepted_export(tmp_path_factory):
    root = tmp_path_factory.mktemp('hostile_ok')
    package = root / 'ws' / 'src' / 'hostile_ok'
    write_tree(str(package), _accepted_files())
    write_tree(str(root / 'ws' / 'src' / 'hostile_ok_b'), GUARD_TWIN)
    output = str(root / 'out')
    run_genmros('mros-v1-export', '--workspace', str(root / 'ws'), '-o', output,
                *prefix_arguments(ros1_prefixes()))
    return str(root), str(package), output


def _accepted_types(package):
    names = []
    for _, case_files in ACCEPTED:
        for relative in case_files:
            base, extension = os.path.splitext(os.path.basename(relative))
            names.extend(['hostile_ok/' + base] if extension == '.msg'
                         else ['hostile_ok/%sRequest' % base, 'hostile_ok/%sResponse' % base])
    return names


def test_table_is_large_enough():
    assert len(ACCEPTED) + len(REFUSED) >= 60


def _run(command, **kwargs):
    result = subprocess.run(command, capture_output=True, text=True, **kwargs)
    assert result.returncode == 0, ' '.join(
        command[:6]) + '\n' + result.stdout[-3000:] + result.stderr[-6000:]
    return result


def test_accepted_headers_compile_together_and_alone(accepted_export, tmp_path):
    _, package, output = accepted_export
    headers = sorted(os.listdir(os.path.join(output, 'hostile_ok')))
    assert len(headers) >= len(ACCEPTED)
    together = tmp_path / 'together.cpp'
    together.write_text(''.join('#include <hostile_ok/%s>\n' %
                        h for h in headers) + 'int main() { return 0; }\n')
    alone = []
    for header in headers:
        source = tmp_path / ('alone_%s.cpp' % header[:-2])
        source.write_text('#include <hostile_ok/%s>\n' % header)
        alone.append(str(source))
    # The compiles are independent: two at a time, the machine's two cores; the headers
    # alone in two halves, so that the long part is shared.
    halves = [alone[:len(alone) // 2], alone[len(alone) // 2:]]
    commands = [['g++', '-std=' + mode, '-fsyntax-only', '-I' + output] + STRICT + sources
                for mode in LANGUAGE_MODES for sources in [[str(together)]] + halves]
    with ThreadPoolExecutor(max_workers=2) as pool:
        list(pool.map(_run, commands))


def test_header_guards_are_unique(accepted_export, tmp_path):
    _, _, output = accepted_export
    source = tmp_path / 'guards.cpp'
    source.write_text('#include <hostile_ok/b_C.h>\n#include <hostile_ok_b/C.h>\n'
                      '#include <hostile_ok/Thing.h>\n#include <hostile_ok/THING.h>\n'
                      'int main() { hostile_ok::b_C a; hostile_ok_b::C b; '
                      'hostile_ok::Thing c; hostile_ok::THING d;\n'
                      '  a.from_hostile_ok = 1; b.from_hostile_ok_b = "x"; '
                      'c.a = 2; d.b = "y";\n'
                      '  return a.serializedLength() + b.serializedLength() '
                      '+ c.serializedLength()\n'
                      '      + d.serializedLength() == 4 + 5 + 4 + 5 ? 0 : 1; }\n')
    _run(['g++', '-std=gnu++98', '-o', str(tmp_path / 'guards'), str(source), '-I' + output]
         + STRICT)
    _run([str(tmp_path / 'guards')])


def test_accepted_messages_round_trip_under_asan(accepted_export, tmp_path):
    _, package, output = accepted_export
    full_names = _accepted_types(package)
    search_path = {'hostile_ok': [os.path.join(package, 'msg')],
                   'std_msgs': [ros1_package_dir('std_msgs')],
                   'geometry_msgs': [ros1_package_dir('geometry_msgs')]}
    context = _load_specs(
        search_path, [n for n in full_names if not n.endswith(('Request', 'Response'))])
    service = msg_loader.load_srv_from_file(
        context, os.path.join(package, 'srv', 'Ask.srv'), 'hostile_ok/Ask')
    msg_loader.load_depends(context, service, search_path)
    images = WireImages(context, seed=10)
    with open(str(tmp_path / 'images.bin'), 'wb') as stream:
        for index, full_name in enumerate(full_names):
            for _ in range(6):
                image = images.image(full_name)
                stream.write(struct.pack('<II', index, len(image)) + image)
    cases = '\n'.join('      case %d: { static %s m; roundTrip(m, "%s", image); break; }'
                      % (i, n.replace('/', '::'), n) for i, n in enumerate(full_names))
    includes = '\n'.join('#include <%s.h>' % n for n in full_names)
    source = tmp_path / 'round_trip.cpp'
    source.write_text(ROUND_TRIP % {'includes': includes, 'cases': cases})
    program = str(tmp_path / 'round_trip')
    _run(['g++', '-std=gnu++98', '-O1', '-o', program,
         str(source), '-I' + output] + STRICT + SANITIZERS)
    result = _run([program, str(tmp_path / 'images.bin')])
    assert '%d images, 0 failures' % (6 * len(full_names)) in result.stdout


def test_float_constants_hold_what_their_type_holds(accepted_export, tmp_path):
    """Each constant's bits equal the definition's text converted to the type,
    as a C++ float or double holds it (and as struct packs it)."""
    _, _, output = accepted_export
    constants = [line.split(' ', 1) for line in FLOAT_LIMITS_MSG.splitlines() if '=' in line]
    prints = []
    for ros_type, declaration in constants:
        name = declaration.split('=')[0]
        cpp_type = 'float' if ros_type == 'float32' else 'double'
        prints.append('  { const %s v = hostile_ok::FloatLimits::%s; '
                      'printBytes("%s", &v, sizeof v); }' % (cpp_type, name, name))
    source = tmp_path / 'float_constants.cpp'
    source.write_text(
        '#include <stdio.h>\n#include <hostile_ok/FloatLimits.h>\n'
        'static void printBytes(const char* name, const void* value, size_t size) {\n'
        '  printf("%%s ", name);\n'
        '  for (size_t i = 0; i < size; ++i) '
        'printf("%%02x", static_cast<const unsigned char*>(value)[i]);\n'
        '  printf("\\n");\n}\nint main() {\n%s\n  return 0;\n}\n' % '\n'.join(prints))
    expected = []
    for ros_type, declaration in constants:
        name, text = declaration.split('=')
        packed = struct.pack('<f', float(
            text)) if ros_type == 'float32' else struct.pack('<d', float(text))
        expected.append('%s %s' % (name, packed.hex()))
    for mode in LANGUAGE_MODES:
        program = str(tmp_path / ('float_constants_' + mode))
        _run(['g++', '-std=' + mode, '-o', program, str(source), '-I' + output] + STRICT)
        assert _run([program]).stdout.splitlines() == expected, mode


def test_empty_elements_in_nested_arrays_stay_within_the_allocation_bound(accepted_export,
                                                                          tmp_path):
    """Outer{Inner[] inners}, Inner{Empty[] es}: 1,000 inners each claiming
    65,536 empties (4,004 bytes) once allocated 65,536,000 elements."""
    _, _, output = accepted_export
    source = tmp_path / 'bound.cpp'
    source.write_text(r'''
#include <stdio.h>
#include <hostile_ok/Outer.h>
#include <hostile_ok/Message.h>
int main() {
  std::vector<uint8_t> image(4);
  const uint32_t inners = 1000;
  memcpy(&image[0], &inners, 4);
  for (uint32_t i = 0; i < inners; ++i) {
    const uint8_t count[4] = {0x00, 0x00, 0x01, 0x00};  // 65,536 empties each
    image.insert(image.end(), count, count + 4);
  }
  hostile_ok::Outer outer;
  const int32_t refused = outer.deserialize(&image[0], static_cast<uint32_t>(image.size()));
  size_t elements = 0;
  for (size_t i = 0; i < outer.inners.size(); ++i) elements += outer.inners[i].es.capacity();
  // Within budget: 1,000 inners of 1 empty each.
  std::vector<uint8_t> small(4);
  memcpy(&small[0], &inners, 4);
  const uint8_t one[4] = {0x01, 0x00, 0x00, 0x00};
  for (uint32_t i = 0; i < inners; ++i) small.insert(small.end(), one, one + 4);
  hostile_ok::Outer ok;
  const int32_t accepted = ok.deserialize(&small[0], static_cast<uint32_t>(small.size()));
  printf("%d %zu %d\n", refused, elements, accepted);
  return 0;
}
''')
    program = str(tmp_path / 'bound')
    _run(['g++', '-std=c++11', '-O1', '-o', program,
         str(source), '-I' + output] + STRICT[:-1] + SANITIZERS)
    refused, elements, accepted = _run([program]).stdout.split()
    assert refused == '-1'
    assert int(elements) <= 65536  # the message's budget for elements that cost no wire bytes
    assert accepted == '4004'


@pytest.fixture(scope='module')
def good_export(tmp_path_factory):
    """An export of a good package, copied into every refused case's output."""
    root = tmp_path_factory.mktemp('hostile_good')
    write_tree(str(root / 'ws' / 'src' / 'hostile_good'),
               {'package.xml': package_xml('hostile_good'),
                'msg/Good.msg': 'std_msgs/Header header\nint32 a\n'})
    output = str(root / 'out')
    run_genmros('mros-v1-export', '--workspace', str(root / 'ws'), '-o', output,
                *prefix_arguments(ros1_prefixes()))
    return str(root / 'ws'), output


@pytest.mark.parametrize('package_name, files, target, line, problem', [c[1:] for c in REFUSED],
                         ids=[c[0] for c in REFUSED])
def test_refused_definition(good_export, tmp_path, package_name, files, target, line, problem):
    good_workspace, good_output = good_export
    workspace = tmp_path / 'ws'
    shutil.copytree(good_workspace, str(workspace))
    package = str(workspace / 'src' / 'case')
    write_tree(package, dict(files, **{'package.xml': package_xml(package_name)}))
    output = str(tmp_path / 'out')
    shutil.copytree(good_output, output)
    before = snapshot(output)
    location = os.path.join(package, target) + line
    result = run_genmros('mros-v1-export', '--workspace', str(workspace), '-o', output,
                         *prefix_arguments(ros1_prefixes()), check=False)
    assert_one_line_error(result, location, problem)
    assert snapshot(output) == before
    includes = ['-I', '%s:%s' % (package_name, os.path.join(package, 'msg')),
                '-I', 'std_msgs:' + ros1_package_dir('std_msgs')]
    if not os.path.isdir(os.path.join(package, 'msg')):
        includes = includes[2:]
    result = run_genmros('generate', os.path.join(package, target), '-p', package_name,
                         '-o', os.path.join(output, package_name), *includes, check=False)
    assert_one_line_error(result, location, problem)
    assert snapshot(output) == before


def test_non_ascii_package_in_generator_mode(tmp_path):
    """catkin_pkg already refuses such a package.xml in a workspace; catkin's
    generator mode takes the name from -p."""
    source = tmp_path / 'A.msg'
    source.write_text('int32 a\n')
    result = run_genmros('generate', str(source), '-p', 'paquete_\u00f1',
                         '-o', str(tmp_path / 'out' / 'x'), check=False)
    assert_one_line_error(result, str(source) + ':',
                          "package name 'paquete_\u00f1' cannot be a C++ namespace: "
                          "not an ASCII identifier")
    assert not (tmp_path / 'out').exists()


def _chain(depth):
    files = {'package.xml': package_xml('hostile_deep')}
    for level in range(depth):
        files['msg/D%d.msg' % level] = 'int32 level\n' + \
            ('D%d next\n' % (level + 1) if level + 1 < depth else '')
    return files


def test_nesting_as_deep_as_gencpp_handles(tmp_path):
    """250 levels (gencpp's limit): generated, compiled, and equal to genmsg."""
    package = str(tmp_path / 'ws' / 'src' / 'hostile_deep')
    write_tree(package, _chain(250))
    output = str(tmp_path / 'out')
    run_genmros('mros-v1-export', '--workspace', str(tmp_path / 'ws'), '-o', output,
                *prefix_arguments(ros1_prefixes()))
    source = tmp_path / 'deep.cpp'
    source.write_text('#include <hostile_deep/D0.h>\nint main() { hostile_deep::D0 d; '
                      'return d.serializedLength() == 1000 ? 0 : 1; }\n')
    # Each header includes the next, as gencpp's do: past g++'s default of 200.
    _run(['g++', '-std=gnu++98', '-fmax-include-depth=300', '-o', str(tmp_path / 'deep'),
          str(source), '-I' + output] + STRICT)
    _run([str(tmp_path / 'deep')])
    context = _load_specs({'hostile_deep': [os.path.join(package, 'msg')]}, ['hostile_deep/D0'])
    with open(os.path.join(output, 'hostile_deep', 'D0.h')) as stream:
        assert '"%s"' % gentools.compute_md5(
            context, context.get_registered('hostile_deep/D0')) in stream.read()


def test_nesting_beyond_the_limit_is_refused(tmp_path):
    package = str(tmp_path / 'ws' / 'src' / 'hostile_deep')
    write_tree(package, _chain(1002))
    result = run_genmros('mros-v1-export', '--workspace', str(tmp_path / 'ws'),
                         '-o', str(tmp_path / 'out'),
                         *prefix_arguments(ros1_prefixes()), check=False)
    assert_one_line_error(result, os.path.join(package, 'msg', 'D999.msg') + ':2:',
                          "field 'next' nests types more than 1000 levels deep")
    assert not os.path.exists(str(tmp_path / 'out'))


def _diamond(depth):
    files = {'package.xml': package_xml('hostile_wide')}
    for level in range(depth):
        files['msg/W%d.msg' % level] = ('W%d left\nW%d right\n' % (level + 1, level + 1)
                                        if level + 1 < depth
                                        else '# empty: the wire image stays small\n')
    return files


def test_diamond_nesting_takes_linear_time(tmp_path):
    """Each type holds the next twice: genmsg's own recursion takes 2**depth
    steps; genmros computes each type's identity once, with genmsg's result."""
    package = str(tmp_path / 'ws' / 'src' / 'hostile_wide')
    write_tree(package, _diamond(40))
    output = str(tmp_path / 'out')
    started = time.monotonic()
    run_genmros('mros-v1-export', '--workspace', str(tmp_path / 'ws'), '-o', output,
                *prefix_arguments(ros1_prefixes()))
    assert time.monotonic() - started < 30
    # genmsg itself, where it still finishes: the last 12 levels.
    context = _load_specs({'hostile_wide': [os.path.join(package, 'msg')]}, ['hostile_wide/W28'])
    spec = context.get_registered('hostile_wide/W28')
    with open(os.path.join(output, 'hostile_wide', 'W28.h')) as stream:
        header = stream.read()
    assert '"%s"' % gentools.compute_md5(context, spec) in header
    assert 'MSG: hostile_wide/W39' in header
    assert header.count(
        'MSG: hostile_wide/W') == len(gentools.compute_full_text(context, spec).split('MSG: ')) - 1


def test_error_on_the_last_line_of_a_long_file_is_found_quickly(tmp_path):
    package = str(tmp_path / 'ws' / 'src' / 'hostile_long')
    lines = ['int32 field%d' % i for i in range(19999)] + ['int32 1bad']
    write_tree(package, {'package.xml': package_xml('hostile_long'),
               'msg/Long.msg': '\n'.join(lines) + '\n'})
    started = time.monotonic()
    result = run_genmros('mros-v1-export', '--workspace', str(tmp_path / 'ws'),
                         '-o', str(tmp_path / 'out'),
                         *prefix_arguments(ros1_prefixes()), check=False)
    assert time.monotonic() - started < 20
    assert_one_line_error(result, os.path.join(package, 'msg', 'Long.msg') + ':20000:',
                          '1bad is not a legal message field name')
