"""A ROS definition file, named one way by every module.

A ``.msg`` file defines one message type; a ``.srv`` file defines a service
and its two message halves, ``<Srv>Request`` and ``<Srv>Response``, each with
a header of its own. Every place that needs the types a file gives, the
file's kind, or the key that stays the same on every machine
(``pkg/msg/Type.msg``, also the file's place in a package's and an export
dir's ``share/<pkg>/``) takes it from :class:`Definition`.
"""

import os

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
    return [Definition(package, os.path.join(directory, name)) for name in sorted(os.listdir(directory))
            if name.endswith('.' + kind)]
