#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Regenerates colcon_mros/core/c_names.py: the names the C and C++
standard headers claim, which colcon_mros/mros_v1/names.py keeps ROS names
away from.

It asks the compilers this project supports (host g++ and clang++ with
glibc, arm-none-eabi-g++ with newlib), in every language mode from gnu++98
to c++17, about one translation unit that includes the support header,
<limits> and every C standard header a firmware may include before a
message header:

  MACROS        what `-E -dM` lists as defined at the end of that unit;
  GLOBAL_NAMES  the names declared at global scope (directly or inside
                extern "C"), read from clang's JSON syntax tree. A unit
                preprocessed by g++ or arm-none-eabi-g++ is parsed by
                clang++ too (for newlib with --target=arm-none-eabi), so
                every compiler's headers are read by the same parser.

Names that start with an underscore are left out: ROS names cannot start
with one. A compiler that is not installed is skipped with a note on
stderr, and the file's docstring names only the compilers that made it;
clang++ is needed as the parser. For a maintainer, after a compiler or C
library upgrade; it writes only that file.

  /usr/bin/python3 scripts/make-c-names.py
"""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import textwrap

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PACKAGE = os.path.join(REPO, 'colcon_mros')
# The mROS v1 support header and the containers header it includes.
SUPPORT_DIRS = [os.path.join(PACKAGE, 'mros_v1', 'support'),
                os.path.join(PACKAGE, 'core', 'support')]
OUTPUT = os.path.join(PACKAGE, 'core', 'c_names.py')

PARSER = 'clang++'
# (compiler, the clang target that parses its preprocessed output, the C
# library its headers come from, for the docstring). Target None: the host.
COMPILERS = [
    ('g++', None, 'glibc'),
    ('clang++', None, 'glibc'),
    ('arm-none-eabi-g++', 'arm-none-eabi', 'newlib'),
]
# mROS v1 builds with gnu++98; message headers compile in every later mode.
MODES = ['gnu++98', 'c++98', 'gnu++11', 'c++11', 'gnu++14', 'c++14', 'gnu++17', 'c++17']
C_HEADERS = ['assert.h', 'ctype.h', 'errno.h', 'float.h', 'limits.h', 'locale.h', 'math.h',
             'setjmp.h', 'signal.h', 'stdarg.h', 'stddef.h', 'stdio.h', 'stdlib.h', 'string.h',
             'time.h', 'wchar.h', 'wctype.h', 'inttypes.h', 'fenv.h']
CXX_HEADERS = ['mros_message_support.h', 'limits']

# genmros writes mros_message_support_version.h from a template beside the
# support headers; any version will do to compile them.
VERSION_HEADER = ('#ifndef MROS_MESSAGE_SUPPORT_VERSION_H\n'
                  '#define MROS_MESSAGE_SUPPORT_VERSION_H\n'
                  '#define MROS_MESSAGE_SUPPORT_VERSION 0\n'
                  '#endif\n')
# The support headers' own macros are mros_v1/names.py's SUPPORT_MACROS, held
# equal to the headers by tests/mros_v1/test_names.py, not the standard's.
SUPPORT_MACRO_PREFIX = 'MROS_'

LINE_WIDTH = 96
INDENT = '    '


def note(message):
    sys.stderr.write('make-c-names: %s\n' % message)


def run(command, check=True):
    """The command's stdout; its stderr is shown only when it fails."""
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            universal_newlines=True)
    if check and result.returncode != 0:
        sys.stderr.write(result.stderr)
        raise SystemExit('make-c-names: %s failed' % ' '.join(command))
    return result.stdout


def write_translation_unit(directory):
    with open(os.path.join(directory, 'mros_message_support_version.h'), 'w') as stream:
        stream.write(VERSION_HEADER)
    unit = os.path.join(directory, 'unit.cpp')
    with open(unit, 'w') as stream:
        for header in CXX_HEADERS + C_HEADERS:
            stream.write('#include <%s>\n' % header)
    return unit


def defined_macros(compiler, mode, include_flags, unit):
    names = set()
    for line in run([compiler, '-std=' + mode] + include_flags + ['-E', '-dM', unit]).splitlines():
        # "#define NAME value" or "#define NAME(args) value"
        name = line.split()[1].split('(')[0]
        names.add(name)
    return names


def global_declarations(tree):
    """The names of the declarations at global scope of clang's JSON tree,
    looking into extern "C" blocks, which do not open a scope."""
    names = set()
    pending = list(tree.get('inner', []))
    while pending:
        declaration = pending.pop()
        if declaration['kind'] == 'LinkageSpecDecl':
            pending.extend(declaration.get('inner', []))
        elif declaration.get('name'):
            names.add(declaration['name'])
    return names


def parsed_names(source, mode, target, include_flags):
    """Global names of a C++ source as clang++ parses it in this mode.

    g++'s headers hold a few things clang reads differently: glibc's
    __malloc__ attribute with arguments, which clang drops while keeping
    the declaration, and libstdc++'s __integer_pack builtin (c++14 on), in
    std::make_integer_sequence, not at global scope. So errors do not stop
    the dump, and none of them loses a global name.
    """
    command = [PARSER, '-std=' + mode, '-x', 'c++'] + include_flags + [
        '-fsyntax-only', '-ferror-limit=0', '-w', '-Xclang', '-ast-dump=json', source]
    if target:
        command[1:1] = ['--target=' + target]
    output = run(command, check=False)
    if not output.strip():
        raise SystemExit('make-c-names: %s gave no syntax tree' % ' '.join(command))
    return global_declarations(json.loads(output))


def words(names):
    """Each name split into words, without those starting with '_'.

    clang names an operator "operator new[]" and a using-declaration by the
    name it brings in, "std::abort"; names.py only looks up identifiers, so
    the extra words never match and are kept as clang spells them.
    """
    return {word for name in names for word in name.split() if not word.startswith('_')}


def collect(compilers, directory):
    unit = write_translation_unit(directory)
    include_flags = ['-I', directory]
    for support in SUPPORT_DIRS:
        include_flags += ['-I', support]
    macros, global_names = set(), set()
    for compiler, target, _ in compilers:
        for mode in MODES:
            note('%s -std=%s' % (compiler, mode))
            macros |= defined_macros(compiler, mode, include_flags, unit)
            if compiler == PARSER:
                global_names |= parsed_names(unit, mode, target, include_flags)
                continue
            # Another compiler's headers: its preprocessed unit, whose line
            # markers keep them system headers for the parser too.
            preprocessed = os.path.join(directory, 'preprocessed.ii')
            with open(preprocessed, 'w') as stream:
                stream.write(run([compiler, '-std=' + mode] + include_flags + ['-E', unit]))
            global_names |= parsed_names(preprocessed, mode, target, [])
    macros = {name for name in macros
              if not name.startswith('_') and not name.startswith(SUPPORT_MACRO_PREFIX)}
    return macros, words(global_names)


def compiler_phrase(compilers):
    """'host g++ and clang++ with glibc, arm-none-eabi-g++ with newlib', or
    less: the docstring names only the compilers that ran."""
    groups = []  # [(target, library, [compiler, ...])], in COMPILERS' order
    for compiler, target, library in compilers:
        if groups and groups[-1][:2] == (target, library):
            groups[-1][2].append(compiler)
        else:
            groups.append((target, library, [compiler]))
    return ', '.join('%s%s with %s' % ('' if target else 'host ', ' and '.join(names), library)
                     for target, library, names in groups)


def wrapped(names):
    return textwrap.fill(' '.join(sorted(names)), width=LINE_WIDTH, initial_indent=INDENT,
                         subsequent_indent=INDENT, break_long_words=False,
                         break_on_hyphens=False)


def docstring(compilers):
    c_headers = ', '.join(C_HEADERS)
    text = ('Names the C and C++ standard headers claim, which ROS names can meet.\n\n'
            'Made by scripts/make-c-names.py; do not edit by hand. Collected from '
            'the compilers this project supports (%s) in every language mode from '
            'gnu++98 to c++17, preprocessing and parsing the support header, <limits> '
            'and every C standard header (%s), which a firmware may include before a '
            'message header. Names that start with an underscore are left out: ROS '
            'names cannot start with one.' % (compiler_phrase(compilers), c_headers))
    paragraphs = [textwrap.fill(paragraph, width=76, break_on_hyphens=False)
                  for paragraph in text.split('\n\n')]
    return '"""%s\n"""\n' % '\n\n'.join(paragraphs)


def render(compilers, macros, global_names):
    return ('# SPDX-License-Identifier: BSD-3-Clause\n' + docstring(compilers) + '\n'
            "# Object- and function-like macros (EOF, errno, INT32_MAX, assert, and the\n"
            "# gnu modes' linux and unix): a field or constant named like one would be\n"
            '# rewritten by the preprocessor.\n'
            "MACROS = frozenset('''\n%s\n'''.split())\n\n"
            '# What those headers declare in the global namespace (functions, types,\n'
            "# variables, namespaces): a package's namespace cannot share a name with one.\n"
            "GLOBAL_NAMES = frozenset('''\n%s\n'''.split())\n"
            % (wrapped(macros), wrapped(global_names)))


def write_atomically(path, text):
    """Replace the file in one step, so a failed run leaves the old table."""
    handle, temporary = tempfile.mkstemp(dir=os.path.dirname(path), prefix='.c_names.')
    try:
        with os.fdopen(handle, 'w') as stream:
            stream.write(text)
        os.chmod(temporary, 0o644)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise


def main():
    if not shutil.which(PARSER):
        raise SystemExit('make-c-names: %s is needed to parse the headers' % PARSER)
    compilers = []
    for entry in COMPILERS:
        if shutil.which(entry[0]):
            compilers.append(entry)
        else:
            note('%s not found, skipped' % entry[0])
    with tempfile.TemporaryDirectory(prefix='make-c-names.') as directory:
        macros, global_names = collect(compilers, directory)
    write_atomically(OUTPUT, render(compilers, macros, global_names))
    note('wrote %s: %d macros, %d global names' % (OUTPUT, len(macros), len(global_names)))


if __name__ == '__main__':
    main()
