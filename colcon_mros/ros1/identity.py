# SPDX-License-Identifier: BSD-3-Clause
"""MD5 sums and full definition texts, each computed once per type.

genmsg's ``compute_md5`` and ``compute_full_text`` give the values the ROS
master and the TCPROS handshake compare, but recompute every nested type
wherever it occurs: a type whose fields hold the next type twice, twenty
levels deep, costs 2**20 recomputations. :class:`Identities` computes the
same values (the tests hold them equal to genmsg's for every Debian type)
from the same genmsg context, once per type, without recursion, so neither
time nor the stack grows with how often a type is reached.
"""

import hashlib

from genmsg.msgs import bare_msg_type, is_builtin

_SEPARATOR = '=' * 80 + '\n'
_COMMENT = '#'
_CONSTANT = '='


def _tokens(declaration):
    """The words of a declaration, split as genmsg splits them (on spaces)."""
    return [word for word in (piece.strip() for piece in declaration.split(' ')) if word]


def _compact_line(line):
    """One line of a .msg text as genmsg reads it, in the fewest bytes; None
    for a line without a declaration."""
    declaration = line.split(_COMMENT)[0].strip()
    if not declaration:
        return None
    tokens = _tokens(declaration)
    if _CONSTANT not in declaration:
        return ' '.join(tokens)
    if tokens[0] == 'string':
        # A string constant's value is the rest of the line, '#' and all.
        return line
    name, _, value = ' '.join(tokens[1:]).partition(_CONSTANT)
    return '%s %s=%s' % (tokens[0], name.strip(), value.strip())


def compact_text(text):
    """A .msg text without its comments, blank lines and repeated blanks:
    the declarations genmsg reads from text, unchanged."""
    lines = (_compact_line(line) for line in text.split('\n'))
    return '\n'.join(line for line in lines if line is not None)


def _nested_types(spec):
    """The message types spec's fields name, in field order, with repeats."""
    return [bare_msg_type(t) for t in spec.types if not is_builtin(bare_msg_type(t))]


class Identities:
    """MD5 sums and full texts of the types registered in one genmsg context."""

    def __init__(self, context):
        self._context = context
        self._md5 = {}
        self._closure = {}

    def contained_first(self, full_name, done):
        """full_name and every type it contains, each after those it contains,
        leaving out those in done (without recursion: types nest deeply)."""
        order = []
        stack = [(full_name, False)]
        pending = set()
        while stack:
            name, expanded = stack.pop()
            if name in done:
                continue
            if expanded:
                order.append(name)
                continue
            if name in pending:
                continue
            pending.add(name)
            stack.append((name, True))
            spec = self._context.get_registered(name)
            stack.extend((nested, False) for nested in reversed(_nested_types(spec)))
        return order

    def _md5_text(self, spec):
        lines = ['%s %s=%s' % (c.type, c.name, c.val_text) for c in spec.constants]
        for field_type, name in zip(spec.types, spec.names):
            base = bare_msg_type(field_type)
            if is_builtin(base):
                lines.append('%s %s' % (field_type, name))
            else:
                lines.append('%s %s' % (self.md5_of(base), name))
        return '\n'.join(lines).strip()

    def md5_of(self, full_name):
        """The MD5 sum of a registered message type, as genmsg computes it."""
        if full_name not in self._md5:
            for name in self.contained_first(full_name, self._md5):
                self._md5[name] = hashlib.md5(
                    self._md5_text(self._context.get_registered(name)).encode()).hexdigest()
        return self._md5[full_name]

    def service_md5(self, spec):
        """The MD5 sum of a service, as genmsg computes it."""
        digest = hashlib.md5()
        digest.update(self._md5_text(spec.request).encode())
        digest.update(self._md5_text(spec.response).encode())
        return digest.hexdigest()

    def _contained(self, full_name):
        """Every type full_name contains, in genmsg's order: depth first,
        each at its first occurrence."""
        if full_name not in self._closure:
            for name in self.contained_first(full_name, self._closure):
                contained = {}
                for nested in _nested_types(self._context.get_registered(name)):
                    contained.setdefault(nested)
                    for deeper in self._closure[nested]:
                        contained.setdefault(deeper)
                self._closure[name] = list(contained)
        return self._closure[full_name]

    def full_text(self, full_name, compact=False):
        """The definition text with those of the types it contains, as
        genmsg's compute_full_text gives it; compact: each type's text
        without comments, blank lines and repeated blanks."""
        def text_of(name):
            text = self._context.get_registered(name).text
            return compact_text(text) if compact else text
        pieces = [text_of(full_name), '\n']
        for nested in self._contained(full_name):
            pieces.extend([_SEPARATOR, 'MSG: %s\n' % nested, text_of(nested), '\n'])
        return ''.join(pieces)[:-1]
