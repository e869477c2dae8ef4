# SPDX-License-Identifier: BSD-3-Clause
"""Load .msg and .srv files through genmsg, reporting problems by file and line.

genmsg is the parser: it reads the declarations, resolves types, and later
computes MD5 sums and definition texts from the same context. genmsg's own
errors name neither the file nor the line, so this module finds the line of a
syntax error by handing genmsg the file's declarations one line at a time
(linear in the file's length), and loads dependencies itself, one field at a
time, so a missing or recursive type is reported at the field that names it.
It also refuses what genmsg accepts but C++ cannot take (see
:mod:`colcon_mros.core.cpp_names`, with the names the back end's headers
reserve), integer constants beyond their type, which
genmsg checks in floating point, and floating-point constants beyond their
type, which genmsg does not check.
"""

import math
import os

from genmsg import InvalidMsgSpec, MsgNotFound
from genmsg import msg_loader
from genmsg.msgs import BUILTIN_TYPES, HEADER, bare_msg_type, is_builtin, parse_type
from genmsg.names import is_legal_resource_base_name

from colcon_mros.core.cpp_names import (check_member_name, check_service_name, check_type_name,
                                        check_type_named_like_package)
from colcon_mros.core.floats import FLOAT_LIMITS, round_to_type
from colcon_mros.errors import GenmrosError, close_match
from colcon_mros.ros1.definition import Definition, check_unique_headers
from colcon_mros.ros1.identity import Identities
from colcon_mros.ros1.model import field_shape

SERVICE_SEPARATOR = '---'

# Types nest at most this deep (gencpp manages 250). Nothing recurses per
# level (the loader keeps its own stack), so any depth fits the interpreter.
MAX_NESTING_DEPTH = 1000
# The safe interface reports sizes as int32_t: no message has more bytes,
# and no fixed array more elements (even of empty messages).
MAX_ARRAY_LENGTH = (1 << 31) - 1


class Declarations:
    """Line numbers of the constants and fields of one message, in order, and
    their comments.

    genmsg keeps no line numbers; this follows genmsg's own rule for what a
    declaration is (a line that is not blank once its comment is removed; a
    constant when it contains '=') so index i of a spec's fields or constants
    maps to the line that declared it. A declaration's comment is the comment
    lines right above it (no blank line between) and the comment after it on
    its line; a string constant's value runs to the end of its line, '#'
    included, as genmsg reads it. The type's own comment is the first block of
    comment lines, where a blank line parts it from the first declaration.
    """

    def __init__(self, path, numbered_lines):
        self.path = path
        self.constant_lines = []
        self.field_lines = []
        self.comments = {}  # a declaration's line number: its comment, line by line
        self.type_comment = []
        above = []
        for number, line in numbered_lines:
            declaration = line.split('#')[0].strip()
            if not declaration:
                text = line.strip()
                if text.startswith('#'):
                    above = above + [text[1:].strip()]
                    continue
                if not self.comments and not self.type_comment:
                    self.type_comment = [comment for comment in above if comment]
                above = []
                continue
            is_string_constant = '=' in declaration and declaration.split()[0] == 'string'
            after = '' if is_string_constant else line.partition('#')[2].strip()
            self.comments[number] = [text for text in above + [after] if text]
            above = []
            if '=' in declaration:
                self.constant_lines.append(number)
            else:
                self.field_lines.append(number)


def _numbered_lines(text):
    return list(enumerate(text.split('\n'), 1))


def _service_halves(text):
    """Split a .srv text the way genmsg does: the numbered lines of the request
    and of the response. Every line starting with '---' is left out; the
    first one starts the response."""
    halves = ([], [])
    half = 0
    for number, line in _numbered_lines(text):
        if line.startswith(SERVICE_SEPARATOR):
            half = 1
        else:
            halves[half].append((number, line))
    return halves


def _read_text(path):
    try:
        with open(path, 'rb') as handle:
            raw = handle.read()
    except OSError as error:
        raise GenmrosError('cannot read file: %s' % (error.strerror or error), path)
    try:
        return raw.decode('utf-8')
    except UnicodeDecodeError as error:
        line = raw[:error.start].count(b'\n') + 1
        raise GenmrosError('not UTF-8 text', path, line)


def _locate_syntax_error(halves, path):
    """The first line genmsg rejects, found by parsing each line on its own
    (a declaration is one line; only a repeated field name needs the others)."""
    context = msg_loader.MsgContext.create_default()
    for numbered_lines in halves:
        seen = set()
        for number, line in numbered_lines:
            try:
                spec = msg_loader.load_msg_from_string(context, line, 'genmros/Line')
            except (InvalidMsgSpec, ValueError) as error:
                return GenmrosError(str(error), path, number)
            for name in spec.names:
                if name in seen:
                    return GenmrosError("duplicate field name '%s'" % name, path, number)
                seen.add(name)
    return None


def _check_integer_constants(spec, declarations):
    """genmsg compares integer constants with their bounds in floating point,
    so 2**63 passes as an int64 and 2**64 as a uint64: check them exactly."""
    for constant, line in zip(spec.constants, declarations.constant_lines):
        bits = _INTEGER_BITS.get(constant.type)
        if bits is None:
            continue
        if constant.type.startswith('u') or constant.type == 'char':
            lower, upper = 0, (1 << bits) - 1
        else:
            lower, upper = -(1 << (bits - 1)), (1 << (bits - 1)) - 1
        if not lower <= constant.val <= upper:
            raise GenmrosError('cannot coerce [%s] to %s (out of bounds)'
                               % (constant.val, constant.type), declarations.path, line)


def _is_infinity_text(text):
    return text.strip().lstrip('+-').lower() in ('inf', 'infinity')


def _check_float_constants(spec, declarations):
    """genmsg takes any float() text, so float32 X=1e39 and float64 Y=1e400
    pass, and C++ would not compile them: a finite value beyond the type's
    range is refused (infinity is spelled 'inf')."""
    for constant, line in zip(spec.constants, declarations.constant_lines):
        cpp_type = _FLOAT_TYPES.get(constant.type)
        if cpp_type is None or _is_infinity_text(constant.val_text):
            continue
        largest = FLOAT_LIMITS[cpp_type]
        too_large = (not math.isnan(constant.val) and abs(constant.val) > largest
                     and math.isinf(round_to_type(cpp_type, constant.val)))
        if math.isinf(constant.val) or too_large:
            raise GenmrosError('%s constant %s is beyond the range of %s (largest finite value %r)'
                               % (constant.type, constant.val_text, constant.type, largest),
                               declarations.path, line)


# A .msg float type as C++ holds it.
_FLOAT_TYPES = {'float32': 'float', 'float64': 'double'}
_INTEGER_BITS = {'int8': 8, 'uint8': 8, 'byte': 8, 'char': 8, 'int16': 16, 'uint16': 16,
                 'int32': 32, 'uint32': 32, 'int64': 64, 'uint64': 64}


def _check_member_names(spec, declarations):
    for name, line in zip(spec.names, declarations.field_lines):
        check_member_name(name, 'field', declarations.path, line)
    for constant, line in zip(spec.constants, declarations.constant_lines):
        check_member_name(constant.name, 'constant', declarations.path, line)


class SpecLoader:
    """Loads message and service specs and their dependencies into one genmsg context.

    ``search_path`` maps a package name to the list of its msg directories,
    as genmsg expects; ``reserved_names`` are the C++ names the back end's
    headers own (:class:`colcon_mros.core.cpp_names.ReservedNames`), which no
    package or type may take.
    """

    def __init__(self, search_path, reserved_names):
        self.reserved_names = reserved_names
        self.context = msg_loader.MsgContext.create_default()
        self.search_path = search_path
        self._declarations = {}
        self._in_progress = []
        # Packages known to exist although they may have no msg directory
        # (only srv/): a missing type there is not a missing package.
        self._packages = set(search_path)
        self._files_of_package = {}
        self.identities = Identities(self.context)

    def declarations(self, full_name):
        """The :class:`Declarations` of a loaded message (or service half)."""
        return self._declarations[full_name]

    def load_message_file(self, path, package):
        definition = _definition(package, path, 'msg')
        if self.context.is_registered(definition.full_name):
            return self.context.get_registered(definition.full_name)
        spec = self._parse_message_file(definition)
        self._load_dependencies(spec)
        return spec

    def _parse_message_file(self, definition):
        """Parse and register one message, without the types it contains."""
        self._check_file_names(definition)
        text = _read_text(definition.path)
        numbered_lines = _numbered_lines(text)
        spec = self._parse(
            text, definition.path, [numbered_lines],
            lambda context, source: msg_loader.load_msg_from_string(context, source,
                                                                    definition.full_name))
        self.context.set_file(definition.full_name, definition.path)
        self._declarations[definition.full_name] = Declarations(definition.path, numbered_lines)
        return spec

    def load_service_file(self, path, package):
        definition = _definition(package, path, 'srv')
        self._packages.add(package)
        self._check_file_names(definition)
        text = _read_text(path)
        halves = _service_halves(text)
        spec = self._parse(
            text, path, halves,
            lambda context, source: msg_loader.load_srv_from_string(context, source,
                                                                    definition.full_name))
        for half, numbered_lines in zip((spec.request, spec.response), halves):
            self.context.set_file(half.full_name, path)
            self._declarations[half.full_name] = Declarations(path, numbered_lines)
            self._load_dependencies(half)
        return spec

    def load_message_type(self, full_name):
        """Load a message by its type name from the search path."""
        if self.context.is_registered(full_name):
            return self.context.get_registered(full_name)
        package, name = full_name.split('/', 1)
        return self.load_message_file(self._find_message_file(package, name), package)

    def field_shape(self, full_name, field):
        """The storage's FieldShape of a field of a message type, None if the
        type has no such field (an unknown type raises GenmrosError)."""
        spec = self.load_message_type(full_name)
        if field not in spec.names:
            return None
        return field_shape(spec.types[spec.names.index(field)])

    def _parse(self, text, path, halves, parse):
        try:
            return parse(self.context, text)
        except (InvalidMsgSpec, ValueError) as error:
            located = _locate_syntax_error(halves, path)
            raise located or GenmrosError(str(error), path)

    def _package_files(self, package, path):
        """Every definition file of package: in its msg directories, the srv
        directories beside them, and the directory of path."""
        if package not in self._files_of_package:
            directories = list(self.search_path.get(package, []))
            directories += [os.path.join(os.path.dirname(d), 'srv') for d in directories]
            directories.append(os.path.dirname(os.path.abspath(path)))
            files = set()
            for directory in directories:
                if os.path.isdir(directory):
                    files.update(os.path.join(directory, name) for name in os.listdir(directory)
                                 if name.endswith(('.msg', '.srv')))
            self._files_of_package[package] = sorted(files)
        return self._files_of_package[package]

    def _check_file_names(self, definition):
        for name in definition.type_names:
            check_type_name(definition.package, name, self.reserved_names, definition.path)
        if definition.is_service:
            check_service_name(definition.package, definition.name, self.reserved_names,
                               definition.path)
        check_unique_headers(definition, self._package_files(definition.package, definition.path))

    def _find_message_file(self, package, name, path=None, line=None):
        if package not in self.search_path and package in self._packages:
            raise GenmrosError("unknown type '%s/%s' (package %s has no msg directory)"
                               % (package, name, package), path, line)
        if package not in self.search_path:
            raise GenmrosError(
                "unknown package '%s' for type '%s/%s' (not in the workspace or the "
                'installed ROS packages%s)' % (package, package, name,
                                               close_match(package, self.search_path)),
                path, line)
        try:
            return msg_loader.get_msg_file(package, name, self.search_path)
        except MsgNotFound:
            # A misspelt built-in type reaches here as a message of the package.
            known = [os.path.splitext(entry)[0] for directory in self.search_path[package]
                     if os.path.isdir(directory) for entry in os.listdir(directory)
                     if entry.endswith('.msg')] + list(BUILTIN_TYPES) + [HEADER]
            raise GenmrosError(
                "unknown type '%s/%s' (no %s.msg in %s%s)"
                % (package, name, name, ', '.join(self.search_path[package]),
                   close_match(name, known)), path, line)

    def _load_dependencies(self, root):
        """Load every type root contains, depth first, each before the type
        that contains it; a missing, recursive or too deep type is reported
        at the field that names it. The stack is this loop's own, so the
        depth of the nesting does not meet the interpreter's recursion limit."""
        stack = [_Visit(root, self._declarations[root.full_name])]
        self._check_declarations(stack[-1])
        while stack:
            visit = stack[-1]
            if visit.next_field == len(visit.spec.types):
                stack.pop()
                msg_loader.load_depends(self.context, visit.spec, self.search_path)
                continue
            index = visit.next_field
            visit.next_field += 1
            dependency_spec = self._field_dependency(
                visit, index, [v.spec.full_name for v in stack])
            if dependency_spec is not None:
                stack.append(
                    _Visit(dependency_spec, self._declarations[dependency_spec.full_name]))
                self._check_declarations(stack[-1])

    def _check_declarations(self, visit):
        _check_member_names(visit.spec, visit.declarations)
        _check_integer_constants(visit.spec, visit.declarations)
        _check_float_constants(visit.spec, visit.declarations)

    def _field_dependency(self, visit, index, in_progress):
        """Check field index of a visited spec; returns the spec of the
        message type it names when that still needs its dependencies loaded."""
        spec, declarations = visit.spec, visit.declarations
        field_type = spec.types[index]
        line = declarations.field_lines[index]
        array_length = parse_type(field_type)[2]
        if array_length is not None and array_length > MAX_ARRAY_LENGTH:
            raise GenmrosError('%s: more elements than the %d a message can have'
                               % (field_type, MAX_ARRAY_LENGTH), declarations.path, line)
        dependency = bare_msg_type(field_type)
        if is_builtin(dependency):
            return None
        if visit.own_types is None:
            visit.own_types = {
                type_name for path in self._package_files(spec.package, declarations.path)
                for type_name in Definition(spec.package, path).type_names}
        check_type_named_like_package(spec.package, visit.own_types, dependency.split('/')[0],
                                      declarations.path, line)
        if dependency in in_progress:
            raise GenmrosError(
                "type '%s' contains itself through field '%s'"
                % (dependency, spec.names[index]), declarations.path, line)
        if len(in_progress) >= MAX_NESTING_DEPTH:
            raise GenmrosError("field '%s' nests types more than %d levels deep"
                               % (spec.names[index], MAX_NESTING_DEPTH), declarations.path, line)
        if self.context.is_registered(dependency):
            return None
        package, name = dependency.split('/', 1)
        dependency_path = self._find_message_file(package, name, declarations.path, line)
        return self._parse_message_file(_definition(package, dependency_path, 'msg'))


class _Visit:
    """A spec whose fields the loader is going through."""

    def __init__(self, spec, declarations):
        self.spec = spec
        self.declarations = declarations
        self.next_field = 0
        self.own_types = None  # the type names of the spec's package, when needed


def _definition(package, path, kind):
    """The Definition of path, which must be a legal file of kind."""
    definition = Definition(package, path)
    if definition.kind != kind:
        raise GenmrosError('expected a .%s file' % kind, path)
    if not is_legal_resource_base_name(definition.name):
        raise GenmrosError("'%s' is not a legal ROS type name" % definition.name, path)
    return definition
