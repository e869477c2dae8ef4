# SPDX-License-Identifier: BSD-3-Clause
"""TOPPERS/ASP's configurator for the PC target: app.cfg to kernel tables.

On the board, ASP's ``cfg`` tool turns the static API of an app's
``app.cfg`` (and the ``mros.cfg`` it includes) into ``kernel_cfg.h`` (one
ID macro per object) and ``kernel_cfg.c`` (the kernel's tables). This does
the same for ``asp/kernel*.c``: the IDs in order of creation, as
ASP numbers them, and tables whose fields are the cfg's own C expressions,
compiled with the app's headers (the cfg's ``#include`` lines). Board-only
files the cfg includes (the timer, serial and log services, mbed's
start-up) are replaced by the PC target's versions in its ``cfg/``
directory, found after the including file's own directory.

Supported: ``INCLUDE``, ``CRE_TSK``, ``CRE_SEM``, ``CRE_CYC``, ``ATT_INI``;
``DEF_KMM`` and ``AID_TSK`` (memory for objects created at run time) are
accepted and have no effect. Anything else, and conditional directives
(``#if``), stop with ``FILE:LINE: problem``.
"""

import os
import re

from colcon_mros.core.output import write_files
from colcon_mros.errors import GenmrosError

IGNORED_APIS = ('DEF_KMM', 'AID_TSK')
# Static API -> the fields of its {...} block, in order.
OBJECT_FIELDS = {
    'CRE_TSK': ('attr', 'exinf', 'task', 'priority', 'stack_size', 'stack'),
    'CRE_SEM': ('attr', 'initial_count', 'max_count'),
    'CRE_CYC': ('attr', 'exinf', 'handler', 'period', 'phase'),
}
INITIALIZER_FIELDS = ('attr', 'exinf', 'routine')
_API_CALL = re.compile(r'([A-Z][A-Z_]*)\s*\(')
IDENTIFIER = re.compile(r'[A-Za-z_]\w*\Z')


class KernelObject:
    """One object of the static API: its ID name, fields and where it is."""

    def __init__(self, api, name, fields, path, line):
        self.api = api
        self.name = name
        self.fields = fields
        self.path = path
        self.line = line


class KernelConfig:
    """Everything app.cfg creates, in order, with the C lines it includes
    and the headers those name that sit next to the including cfg."""

    def __init__(self, cfg_path):
        self.cfg_dir = os.path.dirname(os.path.abspath(cfg_path))
        self.objects = []
        self.initializers = []
        self.c_directives = []
        self.headers = []

    def of_api(self, api):
        return [kernel_object for kernel_object in self.objects if kernel_object.api == api]

    def shown(self, path):
        """path as a message shows it: relative to the app's cfg where it is below it."""
        relative = os.path.relpath(path, self.cfg_dir)
        return path if relative.startswith(os.pardir) else relative

    def stack_origin(self, task):
        """Where a CRE_TSK's stack size is set: the macro it names and the
        header line that defines it (where a header the cfg includes does),
        and the CRE_TSK line."""
        expression = task.fields['stack_size'].strip()
        site = 'CRE_TSK at %s:%d' % (self.shown(task.path), task.line)
        if not IDENTIFIER.match(expression):
            return site
        definition = re.compile(r'\s*#\s*define\s+%s\b' % re.escape(expression))
        for header in self.headers:
            with open(header, encoding='utf-8', errors='replace') as stream:
                for number, line in enumerate(stream, 1):
                    if definition.match(line):
                        return '%s at %s:%d; %s' % (expression, self.shown(header), number, site)
        return '%s; %s' % (expression, site)


def _without_comments(text):
    """text with comments blanked, line breaks kept (for line numbers)."""
    def blank(match):
        return re.sub(r'[^\n]', ' ', match.group(0))
    return re.sub(r'/\*.*?\*/|//[^\n]*|"(?:\\.|[^"\\\n])*"',
                  lambda m: m.group(0) if m.group(0).startswith('"') else blank(m), text,
                  flags=re.S)


_OPENING = '({['
_CLOSING = ')}]'


def _outside_quotes(text, start=0):
    """(index, char) of each character of text from start outside quoted
    strings, then (len(text), None) unless a quote is left open."""
    quote = None
    for index in range(start, len(text)):
        char = text[index]
        if quote:
            if char == quote and text[index - 1] != '\\':
                quote = None
        elif char in '"\'':
            quote = char
        else:
            yield index, char
    if not quote:
        yield len(text), None


def _split_top_level(text, path, line):
    """The comma-separated parts of text, commas inside brackets kept."""
    parts, depth, start = [], 0, 0
    for index, char in _outside_quotes(text):
        if char is None:
            if depth == 0:
                parts.append(text[start:].strip())
                return [' '.join(part.split()) for part in parts]
        elif char in _OPENING:
            depth += 1
        elif char in _CLOSING:
            depth -= 1
        elif char == ',' and depth == 0:
            parts.append(text[start:index].strip())
            start = index + 1
    raise GenmrosError('unbalanced brackets or quotes', path, line)


def _block(text, path, line, api):
    text = text.strip()
    if not (text.startswith('{') and text.endswith('}')):
        raise GenmrosError('%s: expected { ... } after the ID' % api, path, line)
    return _split_top_level(text[1:-1], path, line)


def _call_end(text, start, path, line):
    """The index just past the ')' that closes the '(' before start."""
    depth = 1
    for index, char in _outside_quotes(text, start):
        if char == '(':
            depth += 1
        elif char == ')':
            depth -= 1
            if depth == 0:
                return index + 1
    raise GenmrosError('static API call without its closing ")"', path, line)


class _Reader:
    """Reads a cfg file and the files it includes into a KernelConfig."""

    def __init__(self, cfg_path, search_dirs):
        self.search_dirs = search_dirs
        self.config = KernelConfig(cfg_path)
        self.reading = []

    def read(self, path):
        path = os.path.abspath(path)
        if path in self.reading:
            raise GenmrosError('INCLUDE of itself (through %s)' % ' -> '.join(self.reading), path)
        try:
            with open(path, encoding='utf-8', errors='replace') as stream:
                text = _without_comments(stream.read())
        except OSError as error:
            raise GenmrosError('cannot read: %s' % error.strerror, path)
        self.reading.append(path)
        statements = []
        for number, line in enumerate(text.splitlines(), 1):
            stripped = line.strip()
            if stripped.startswith('#'):
                self._directive(stripped, path, number)
                statements.append((number, ''))
            else:
                statements.append((number, line))
        self._statements(statements, path)
        self.reading.pop()

    def _directive(self, directive, path, line):
        keyword = directive[1:].strip().split(None, 1)[0] if directive[1:].strip() else ''
        if keyword in ('if', 'ifdef', 'ifndef', 'elif', 'else', 'endif'):
            raise GenmrosError('#%s: the PC target\'s configurator has no conditionals; put the '
                               'condition into the included header' % keyword, path, line)
        if keyword == 'include':
            match = re.match(r'#\s*include\s*"([^"]+)"', directive)
            if match:
                candidate = os.path.join(os.path.dirname(path), match.group(1))
                if os.path.isfile(candidate):
                    directive = '#include "%s"' % os.path.abspath(candidate)
                    self.config.headers.append(os.path.abspath(candidate))
        self.config.c_directives.append(directive)

    def _statements(self, numbered_lines, path):
        text = '\n'.join(line for _, line in numbered_lines)
        position = 0
        while True:
            match = _API_CALL.search(text, position)
            leftover = text[position:match.start() if match else len(text)]
            if leftover.strip(' \t\n;'):
                line = text.count('\n', 0, position + len(leftover) - len(leftover.lstrip())) + 1
                raise GenmrosError('expected a static API call, found %r'
                                   % leftover.strip().split('\n')[0][:40], path, line)
            if not match:
                return
            line = text.count('\n', 0, match.start()) + 1
            end = _call_end(text, match.end(), path, line)
            self._api(match.group(1), text[match.end():end - 1], path, line)
            position = end

    def _api(self, api, arguments, path, line):
        if api == 'INCLUDE':
            self.read(self._resolve(arguments.strip(), path, line))
        elif api in OBJECT_FIELDS:
            parts = _split_top_level(arguments, path, line)
            if len(parts) != 2 or not IDENTIFIER.match(parts[0]):
                raise GenmrosError('%s(ID, { ... }) expected' % api, path, line)
            values = _block(parts[1], path, line, api)
            if len(values) != len(OBJECT_FIELDS[api]):
                raise GenmrosError('%s: %d fields in { ... }, expected %d (%s)'
                                   % (api, len(values), len(OBJECT_FIELDS[api]),
                                      ', '.join(OBJECT_FIELDS[api])), path, line)
            for earlier in self.config.objects:
                if earlier.name == parts[0]:
                    raise GenmrosError('%s is created twice (first at %s:%d)'
                                       % (parts[0], earlier.path, earlier.line), path, line)
            self.config.objects.append(
                KernelObject(api, parts[0], dict(zip(OBJECT_FIELDS[api], values)), path, line))
        elif api == 'ATT_INI':
            values = _block(arguments, path, line, api)
            if len(values) != len(INITIALIZER_FIELDS):
                raise GenmrosError('ATT_INI({ attr, exinf, routine }) expected', path, line)
            self.config.initializers.append(
                KernelObject(api, None, dict(zip(INITIALIZER_FIELDS, values)), path, line))
        elif api not in IGNORED_APIS:
            raise GenmrosError('%s is not supported by the PC target (it has %s)'
                               % (api, ', '.join(['INCLUDE', 'ATT_INI'] + sorted(OBJECT_FIELDS)
                                                 + list(IGNORED_APIS))), path, line)

    def _resolve(self, argument, path, line):
        match = re.match(r'"([^"]+)"\Z', argument)
        if not match:
            raise GenmrosError('INCLUDE("file.cfg") expected', path, line)
        name = match.group(1)
        directories = [os.path.dirname(path)] + list(self.search_dirs)
        for directory in directories:
            candidate = os.path.normpath(os.path.join(directory, name))
            if os.path.isfile(candidate):
                return candidate
        raise GenmrosError('INCLUDE: %s not found (looked in %s)' % (name, ', '.join(directories)),
                           path, line)


def read_config(cfg_path, search_dirs):
    """The KernelConfig of cfg_path, INCLUDEs resolved next to the including
    file first, then in search_dirs."""
    reader = _Reader(cfg_path, search_dirs)
    reader.read(cfg_path)
    return reader.config


def _header(config):
    lines = ['/* Generated by genmros from the app\'s kernel configuration: the ID of',
             ' * each kernel object, numbered in order of creation as ASP\'s cfg does. */',
             '#ifndef TOPPERS_KERNEL_CFG_H', '#define TOPPERS_KERNEL_CFG_H', '']
    for api, count_name in (('CRE_TSK', 'TNUM_TSKID'), ('CRE_SEM', 'TNUM_SEMID'),
                            ('CRE_CYC', 'TNUM_CYCID')):
        objects = config.of_api(api)
        lines.append('#define %s %d' % (count_name, len(objects)))
        lines.extend('#define %s %d' % (kernel_object.name, number)
                     for number, kernel_object in enumerate(objects, 1))
        lines.append('')
    lines.append('#endif /* TOPPERS_KERNEL_CFG_H */')
    return '\n'.join(lines) + '\n'


def _table(type_name, array, count_name, rows):
    lines = ['const struct %s %s[%d + 1] = {' % (type_name, array, len(rows))]
    lines.extend('    {%s},' % row for row in rows)
    lines.append('    {0}};')
    lines.append('const uint_t %s = %d;' % (count_name, len(rows)))
    return lines + ['']


def _c_string(text):
    return '"%s"' % text.replace('\\', '\\\\').replace('"', '\\"')


def _source(config):
    lines = ['/* Generated by genmros from the app\'s kernel configuration: the tables',
             ' * the PC target\'s kernel runs the app with. */',
             '#include "kernel.h"', '#include "pc_target.h"', '#include "kernel_cfg.h"']
    lines.extend(config.c_directives)
    lines.append('')
    tasks = ['"%s", %s, (intptr_t)(%s), (TASK)(%s), %s, %s, %s'
             % (task.name, f['attr'], f['exinf'], f['task'], f['priority'], f['stack_size'],
                _c_string(config.stack_origin(task)))
             for task in config.of_api('CRE_TSK') for f in [task.fields]]
    semaphores = ['"%s", %s, %s, %s' % (semaphore.name, f['attr'], f['initial_count'],
                                        f['max_count'])
                  for semaphore in config.of_api('CRE_SEM') for f in [semaphore.fields]]
    cyclics = ['"%s", %s, (intptr_t)(%s), (CYCHDR)(%s), %s, %s'
               % (cyclic.name, f['attr'], f['exinf'], f['handler'], f['period'], f['phase'])
               for cyclic in config.of_api('CRE_CYC') for f in [cyclic.fields]]
    initializers = ['%s, (intptr_t)(%s), (INIRTN)(%s)' % (f['attr'], f['exinf'], f['routine'])
                    for initializer in config.initializers for f in [initializer.fields]]
    lines += _table('pc_task_config', 'pc_task_configs', 'pc_task_count', tasks)
    lines += _table('pc_semaphore_config', 'pc_semaphore_configs', 'pc_semaphore_count',
                    semaphores)
    lines += _table('pc_cyclic_config', 'pc_cyclic_configs', 'pc_cyclic_count', cyclics)
    lines += _table('pc_initializer_config', 'pc_initializer_configs', 'pc_initializer_count',
                    initializers)
    return '\n'.join(lines)


def write_kernel_config(config, output_dir):
    """Writes kernel_cfg.h and kernel_cfg.c (only what changed) into output_dir."""
    return write_files(output_dir, {'kernel_cfg.h': _header(config),
                                    'kernel_cfg.c': _source(config)})
