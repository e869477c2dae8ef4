"""Load .msg and .srv files through genmsg, reporting problems by file and line.

genmsg is the parser: it reads the declarations, resolves types, and later
computes MD5 sums and definition texts from the same context. genmsg's own
errors name neither the file nor the line, so this module finds the line of a
syntax error by handing genmsg growing prefixes of the file, and loads
dependencies itself, one field at a time, so a missing or recursive type is
reported at the field that names it.
"""

import os

from genmsg import InvalidMsgSpec, MsgNotFound
from genmsg import msg_loader
from genmsg.msgs import bare_msg_type, is_builtin
from genmsg.names import is_legal_resource_base_name

from colcon_mros.errors import GenmrosError

SERVICE_SEPARATOR = '---'


class Declarations:
    """Line numbers of the constants and fields of one message, in order.

    genmsg keeps no line numbers; this follows genmsg's own rule for what a
    declaration is (a line that is not blank once its comment is removed; a
    constant when it contains '=') so index i of a spec's fields or constants
    maps to the line that declared it.
    """

    def __init__(self, path, lines, first_line):
        self.path = path
        self.constant_lines = []
        self.field_lines = []
        for number, line in enumerate(lines, first_line):
            declaration = line.split('#')[0].strip()
            if not declaration:
                continue
            if '=' in declaration:
                self.constant_lines.append(number)
            else:
                self.field_lines.append(number)


def _service_halves(text):
    """Split a .srv text the way genmsg does: (request lines, response lines, response first line)."""
    lines = text.split('\n')
    for index, line in enumerate(lines):
        if line.startswith(SERVICE_SEPARATOR):
            return lines[:index], lines[index + 1:], index + 2
    return lines, [], len(lines) + 1


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


def _describe_genmsg_error(error, line_text):
    """genmsg's message, reworded where genmsg's wording does not point at the problem."""
    message = str(error)
    if message.startswith('Duplicate field names'):
        words = line_text.split('#')[0].split()
        return "duplicate field name '%s'" % (words[-1] if words else '')
    return message


def _locate_syntax_error(text, parse, path):
    """Re-parse growing prefixes of text to find the line genmsg rejects."""
    lines = text.split('\n')
    for count in range(1, len(lines) + 1):
        try:
            parse(msg_loader.MsgContext.create_default(), '\n'.join(lines[:count]))
        except (InvalidMsgSpec, ValueError) as error:
            return GenmrosError(_describe_genmsg_error(error, lines[count - 1]), path, count)
    return None


class SpecLoader:
    """Loads message and service specs and their dependencies into one genmsg context.

    ``search_path`` maps a package name to the list of its msg directories,
    as genmsg expects.
    """

    def __init__(self, search_path):
        self.context = msg_loader.MsgContext.create_default()
        self.search_path = search_path
        self._declarations = {}
        self._in_progress = []

    def declarations(self, full_name):
        """The :class:`Declarations` of a loaded message (or service half)."""
        return self._declarations[full_name]

    def load_message_file(self, path, package):
        full_name = '%s/%s' % (package, _type_name_from_path(path, '.msg'))
        if self.context.is_registered(full_name):
            return self.context.get_registered(full_name)
        text = _read_text(path)
        spec = self._parse(
            text, path,
            lambda context, source: msg_loader.load_msg_from_string(context, source, full_name))
        self.context.set_file(full_name, path)
        self._declarations[full_name] = Declarations(path, text.split('\n'), 1)
        self._load_dependencies(spec)
        return spec

    def load_service_file(self, path, package):
        full_name = '%s/%s' % (package, _type_name_from_path(path, '.srv'))
        text = _read_text(path)
        spec = self._parse(
            text, path,
            lambda context, source: msg_loader.load_srv_from_string(context, source, full_name))
        request_lines, response_lines, response_first_line = _service_halves(text)
        for half, lines, first_line in ((spec.request, request_lines, 1),
                                        (spec.response, response_lines, response_first_line)):
            self.context.set_file(half.full_name, path)
            self._declarations[half.full_name] = Declarations(path, lines, first_line)
            self._load_dependencies(half)
        return spec

    def load_message_type(self, full_name):
        """Load a message by its type name from the search path."""
        if self.context.is_registered(full_name):
            return self.context.get_registered(full_name)
        package, name = full_name.split('/', 1)
        return self.load_message_file(self._find_message_file(package, name), package)

    def _parse(self, text, path, parse):
        try:
            return parse(self.context, text)
        except (InvalidMsgSpec, ValueError) as error:
            located = _locate_syntax_error(text, parse, path)
            raise located or GenmrosError(str(error), path)

    def _find_message_file(self, package, name, path=None, line=None):
        if package not in self.search_path:
            raise GenmrosError(
                "unknown package '%s' for type '%s/%s' (not in the workspace or the "
                'installed ROS packages)' % (package, package, name), path, line)
        try:
            return msg_loader.get_msg_file(package, name, self.search_path)
        except MsgNotFound:
            raise GenmrosError(
                "unknown type '%s/%s' (no %s.msg in %s)"
                % (package, name, name, ', '.join(self.search_path[package])), path, line)

    def _load_dependencies(self, spec):
        declarations = self._declarations[spec.full_name]
        self._in_progress.append(spec.full_name)
        for index, field_type in enumerate(spec.types):
            dependency = bare_msg_type(field_type)
            if is_builtin(dependency):
                continue
            line = declarations.field_lines[index]
            if dependency in self._in_progress:
                raise GenmrosError(
                    "type '%s' contains itself through field '%s'"
                    % (dependency, spec.names[index]), declarations.path, line)
            if not self.context.is_registered(dependency):
                package, name = dependency.split('/', 1)
                dependency_path = self._find_message_file(package, name, declarations.path, line)
                self.load_message_file(dependency_path, package)
        self._in_progress.pop()
        msg_loader.load_depends(self.context, spec, self.search_path)


def _type_name_from_path(path, extension):
    base = os.path.basename(path)
    if not base.endswith(extension):
        raise GenmrosError('expected a %s file' % extension, path)
    name = base[:-len(extension)]
    if not is_legal_resource_base_name(name):
        raise GenmrosError("'%s' is not a legal ROS type name" % name, path)
    return name
