# SPDX-License-Identifier: BSD-3-Clause
"""Generate the C++ programs that hold genmros headers against roscpp.

The field lists come straight from genmsg (not from genmros' model), so the
harness does not share the code it checks. One ``fill`` function template per
type sets every field from a deterministic random stream; instantiated once
with roscpp's class and once with genmros' class, it gives both the same
values, and the harness compares their wire images.
"""

import glob
import os
import subprocess
import sys

from genmsg import msg_loader
from genmsg.msgs import bare_msg_type, is_builtin

from support.checkout import TESTS, TEST_WS
from testing import ros_paths

RANDOM_HEADER_DIR = os.path.join(TESTS, 'cpp')

ROSCPP_LIBRARIES = ['-lroscpp_serialization', '-lrostime', '-lcpp_common']


def mangle(full_name):
    return full_name.replace('/', '__')


def cpp_name(full_name):
    return full_name.replace('/', '::')


class TypeSet:
    """Messages (in dependency order) and services loaded with plain genmsg."""

    def __init__(self, search_path, message_names=(), service_files=()):
        self.context = msg_loader.MsgContext.create_default()
        self.search_path = search_path
        self.messages = []
        self.services = []
        for full_name in message_names:
            self._add_message(full_name)
        for package, path in service_files:
            name = '%s/%s' % (package, os.path.basename(path)[:-4])
            spec = msg_loader.load_srv_from_file(self.context, path, name)
            for half in (spec.request, spec.response):
                msg_loader.load_depends(self.context, half, search_path)
                self._add_message(half.full_name, half)
            self.services.append(name)

    def _add_message(self, full_name, spec=None):
        if full_name in self.messages:
            return
        if spec is None:
            spec = msg_loader.load_msg_by_type(self.context, full_name, self.search_path)
            msg_loader.load_depends(self.context, spec, self.search_path)
        for field in spec.parsed_fields():
            if not field.is_builtin:
                self._add_message(bare_msg_type(field.base_type))
        self.messages.append(full_name)

    def spec(self, full_name):
        return self.context.get_registered(full_name)


def _fill_element(target, base_type):
    if base_type == 'bool':
        return 'r.boolean(%s);' % target
    if base_type == 'string':
        return 'r.text(%s);' % target
    if base_type == 'time':
        return 'r.stamp(%s.sec, %s.nsec);' % (target, target)
    if base_type == 'duration':
        return 'r.span(%s.sec, %s.nsec);' % (target, target)
    if is_builtin(base_type):
        return 'r.value(%s);' % target
    return 'fill_%s(%s, r);' % (mangle(base_type), target)


def fill_functions(type_set):
    """C++ templates ``fill_<pkg>__<Type>(M&, harness::Random&)``, one per message."""
    lines = ['#include "harness_random.h"', '']
    for full_name in type_set.messages:
        lines.append('template <class M> void fill_%s(M& m, harness::Random& r);' %
                     mangle(full_name))
    lines.append('')
    for full_name in type_set.messages:
        spec = type_set.spec(full_name)
        lines.append(
            'template <class M> void fill_%s(M& m, harness::Random& r) {' % mangle(full_name))
        lines.append('  (void)m; (void)r;')
        for field in spec.parsed_fields():
            member = 'm.%s' % field.name
            base_type = bare_msg_type(field.base_type) if not field.is_builtin else field.base_type
            if not field.is_array:
                lines.append('  ' + _fill_element(member, base_type))
                continue
            if field.array_len is None:
                lines.append('  %s.resize(r.length());' % member)
            lines.append('  for (size_t i = 0; i < %s.size(); ++i) { %s }'
                         % (member, _fill_element('%s[i]' % member, base_type)))
        lines.append('}')
        lines.append('')
    return '\n'.join(lines)


def _includes(type_set):
    return ['#include <%s.h>' % name for name in type_set.messages + type_set.services]


def _dispatch(type_set, body):
    """A switch over type indexes; body(full_name) gives the case's statements."""
    lines = ['  switch (type) {']
    for index, full_name in enumerate(type_set.messages):
        lines.append('    case %d: { %s }' % (index, body(full_name)))
    lines.append('  }')
    return '\n'.join(lines)


COMMON_DECLARATIONS = '#include "harness_sides.h"'


ROSCPP_TEMPLATES = '''
template <class M> std::vector<uint8_t> encode(const M& m) {
  const uint32_t size = ros::serialization::serializationLength(m);
  std::vector<uint8_t> bytes(size);
  ros::serialization::OStream stream(bytes.data(), size);
  ros::serialization::serialize(stream, m);
  return bytes;
}

template <class M> Identity identity() {
  return Identity{ros::message_traits::MD5Sum<M>::value(), ros::message_traits::DataType<M>::value(),
                  ros::message_traits::Definition<M>::value()};
}

template <class S> Identity service_identity() {
  return Identity{ros::service_traits::MD5Sum<S>::value(), ros::service_traits::DataType<S>::value(), ""};
}
'''  # noqa: E501

MROS_TEMPLATES = '''
template <class M> std::vector<uint8_t> encode(const M& m) {
  std::vector<uint8_t> bytes(m.serializedLength());
  const int32_t written = m.serialize(bytes.data(), static_cast<uint32_t>(bytes.size()));
  if (written != static_cast<int32_t>(bytes.size())) bytes.clear();
  return bytes;
}

// Parses input; on success returns the bytes consumed and re-encodes into out.
template <class M> int32_t reencode(const uint8_t* input, uint32_t size, std::vector<uint8_t>& out) {
  M m;
  const int32_t consumed = m.deserialize(input, size);
  if (consumed >= 0) out = encode(m);
  return consumed;
}

template <class M> Identity identity() {
  return Identity{message_traits::MD5Sum<M::MROS_TYPE_ID>::value(), message_traits::DataType<M*>::value(),
                  message_traits::Definition<M*>::value()};
}

template <class S> Identity service_identity() {
  return Identity{service_traits::MD5Sum<S*>::value(), service_traits::DataType<S*>::value(), ""};
}
'''  # noqa: E501


def _side(type_set, namespace, prelude, templates, parses):
    """One translation unit: the types' headers, fill functions, and the
    functions of harness_sides.h for this side, dispatched by type index."""
    lines = prelude + _includes(type_set) + [
        COMMON_DECLARATIONS, fill_functions(type_set), 'namespace %s {' % namespace, templates,
        'std::vector<uint8_t> sample(int type, uint64_t seed, int mode) {',
        _dispatch(type_set, lambda n: '%s m; harness::Random r(seed, mode); '
                                      'fill_%s(m, r); return encode(m);'
                                      % (cpp_name(n), mangle(n))),
        '  return {};', '}', '']
    if parses:
        lines += ['int32_t reencode(int type, const uint8_t* input, uint32_t size, '
                  'std::vector<uint8_t>& out) {',
                  _dispatch(type_set, lambda n: 'return reencode<%s>(input, size, out);' %
                            cpp_name(n)),
                  '  return -2;', '}', '']
    lines += ['Identity identity(int type) {',
              _dispatch(type_set, lambda n: 'return identity<%s>();' % cpp_name(n)),
              '  return {};', '}', '',
              'Identity service_identity(int service) {', '  switch (service) {']
    lines += ['    case %d: return service_identity<%s>();' % (i, cpp_name(s))
              for i, s in enumerate(type_set.services)]
    lines += ['  }', '  return {};', '}', '}  // namespace %s' % namespace, '']
    return '\n'.join(lines)


def roscpp_side(type_set):
    """Translation unit that fills and serializes roscpp's classes."""
    return _side(type_set, 'roscpp_side', ['#include <ros/serialization.h>'], ROSCPP_TEMPLATES,
                 parses=False)


def mros_side(type_set):
    """Translation unit that fills, serializes and parses genmros' classes."""
    return _side(type_set, 'mros_side', [], MROS_TEMPLATES, parses=True)


def target_side(type_set):
    """Translation unit for the target CPUs (C++98 and later): fills genmros'
    classes and runs the checks of targets/target_check.h on them, through
    checkType(type index, seed, mode, report)."""
    lines = _includes(type_set) + [
        '#include <mros_v1_delivery.h>  // memCopy, which the checks call',
        '#include "target_check.h"', '#include "harness_types.inc"', fill_functions(type_set),
        'void checkType(int type, uint32_t seed, int mode, target::Report& report) {',
        _dispatch(type_set, lambda n: 'target::checkInstance<%s>(fill_%s<%s>, kTypes[type], '
                                      'seed, mode, report); return;'
                                      % (cpp_name(n), mangle(n), cpp_name(n))),
        '}', '']
    return '\n'.join(lines)


def type_table(type_set):
    """Names of the types and services, indexed as the dispatch switches are."""
    return '\n'.join(
        ['static const char* const kTypes[] = {'] +
        ['  "%s",' % name for name in type_set.messages] +
        ['};', 'static const int kTypeCount = %d;' % len(type_set.messages),
         'static const char* const kServices[] = {'] +
        ['  "%s",' % name for name in type_set.services] +
        ['  0', '};', 'static const int kServiceCount = %d;' % len(type_set.services), ''])


def compile_object(source, build_dir, include_dirs, strict=True, flags=()):
    """Compile one translation unit into build_dir; strict adds -Werror (not for
    roscpp's own headers)."""
    output = os.path.join(build_dir, os.path.basename(source)[:-len('.cpp')] + '.o')
    warnings = ['-Wall', '-Wextra', '-pedantic'] + (['-Werror'] if strict else [])
    command = (['g++', '-std=c++11', '-O1', '-c', '-o', output, source] + warnings + list(flags)
               + ['-I' + d for d in list(include_dirs) + [RANDOM_HEADER_DIR]])
    _run(command)
    return output


def link_program(objects, output, flags=(), libraries=()):
    _run(['g++', '-o', output] + list(objects) + list(flags) + list(libraries))
    return output


def _run(command):
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        raise AssertionError('%s\nfailed:\n%s' % (' '.join(command), result.stderr[-6000:]))


def write_sources(directory, type_set, with_roscpp=True, for_targets=False):
    """Write the generated translation units; returns their paths."""
    sources = {'mros_side.cpp': mros_side(type_set), 'harness_types.inc': type_table(type_set)}
    if with_roscpp:
        sources['roscpp_side.cpp'] = roscpp_side(type_set)
    if for_targets:
        sources['target_side.cpp'] = target_side(type_set)
    paths = {}
    for name, text in sources.items():
        paths[name] = os.path.join(directory, name)
        with open(paths[name], 'w') as stream:
            stream.write(text)
    return paths


# The roscpp side's reference program, shared by the target-CPU and compact
# definition tests.
TARGETS_DIR = os.path.join(TESTS, 'cpp', 'targets')
TEST_WS_PACKAGES = ['mros_test', 'mros_test_base']
BINARY, TEXT, COMPACT = 0, 1, 2  # harness::Mode


def search_path(with_test_ws=True):
    """genmsg's search path: the installed ROS message packages
    (testing.ros_paths) and, with_test_ws, test_ws's."""
    search_path = ros_paths.ros1_search_path()
    for package in TEST_WS_PACKAGES if with_test_ws else ():
        search_path[package] = [os.path.join(TEST_WS, 'src', package, 'msg')]
    return search_path


def test_ws_definitions(kind):
    """(package, path) of every test_ws definition of kind (msg or srv)."""
    for package in TEST_WS_PACKAGES:
        for path in sorted(glob.glob(os.path.join(TEST_WS, 'src', package, kind, '*.' + kind))):
            yield package, path


def gencpp_headers(search_path, output_root):
    """roscpp's headers of the test_ws types, from the installed real gencpp."""
    gencpp, templates = ros_paths.gencpp()
    includes = []
    for package, directories in sorted(search_path.items()):
        includes += ['-I', '%s:%s' % (package, directories[0])]
    for kind in ('msg', 'srv'):
        for package, path in test_ws_definitions(kind):
            subprocess.run([sys.executable, gencpp, path, '-p', package,
                            '-o', os.path.join(output_root, package), '-e', templates] + includes,
                           check=True, capture_output=True)
    return output_root


def expected_bytes_program(type_set, search_path, root, for_targets=False):
    """The harness's sources for type_set under root/sources, and the host
    program that prints roscpp's wire images of their instances (gencpp's
    headers of the test_ws types, Debian's of the others)."""
    gencpp = gencpp_headers(search_path, str(root / 'gencpp'))
    directory = str(root / 'sources')
    os.makedirs(directory)
    sources = write_sources(directory, type_set, for_targets=for_targets)
    objects = [
        compile_object(sources['roscpp_side.cpp'], directory, [gencpp, directory], strict=False),
        compile_object(os.path.join(TARGETS_DIR, 'expected_bytes.cpp'), directory,
                       [directory, TARGETS_DIR]),
    ]
    program = link_program(objects, os.path.join(directory, 'expected_bytes'),
                           libraries=ROSCPP_LIBRARIES)
    return sources, program
