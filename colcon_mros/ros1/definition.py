# SPDX-License-Identifier: BSD-3-Clause
"""A ROS definition file, named one way by every module.

A ``.msg`` file defines one message type; a ``.srv`` file defines a service
and its two message halves, ``<Srv>Request`` and ``<Srv>Response``, each with
a header of its own. Every place that needs the types a file gives, the
file's kind, or the key that stays the same on every machine
(``pkg/msg/Type.msg``, also the file's place in a package's and an export
dir's ``share/<pkg>/``) takes it from :class:`Definition`.
"""

import os

from colcon_mros.errors import GenmrosError

KINDS = ('msg', 'srv')
SERVICE_HALVES = ('Request', 'Response')


class Definition:
    """One .msg or .srv file of a package."""

    def __init__(self, package, path):
        self.package = package
        self.path = path
        self.file_name = os.path.basename(path)
        self.name, extension = os.path.splitext(self.file_name)
        self.kind = extension[1:]
        self.is_service = self.kind == 'srv'
        self.full_name = '%s/%s' % (package, self.name)
        halves = [self.name + half for half in SERVICE_HALVES] if self.is_service else []
        # The names of the types the file defines: one header each.
        self.type_names = [self.name] + halves
        self.full_type_names = ['%s/%s' % (package, name) for name in self.type_names]
        self.key = '%s/%s/%s' % (package, self.kind, self.file_name)

    def __repr__(self):
        return 'Definition(%r)' % self.key

    def half_of(self, type_name):
        """'Request' or 'Response' when type_name is one of this service's
        halves, else None."""
        for half in SERVICE_HALVES if self.is_service else ():
            if type_name == self.name + half:
                return half
        return None


def definitions_in(package, directory, kind):
    """The definitions of one kind in directory, by file name."""
    if not os.path.isdir(directory):
        return []
    return [Definition(package, os.path.join(directory, name))
            for name in sorted(os.listdir(directory)) if name.endswith('.' + kind)]


def check_unique_headers(definition, sibling_paths):
    """Refuse a definition file that would write a header another file of
    its package writes too (Foo.srv and FooRequest.msg, Pair.srv and Pair.msg)."""
    mine = set(definition.type_names)
    for other in sorted(sibling_paths):
        # The same file, or the same definition found in another directory.
        if os.path.basename(other) == definition.file_name:
            continue
        shared = mine.intersection(Definition(definition.package, other).type_names)
        if shared:
            raise GenmrosError("'%s/%s' would be defined twice, by %s and by %s; rename one"
                               % (definition.package, sorted(shared)[0], definition.file_name,
                                  other),
                               definition.path)
