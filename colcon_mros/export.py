"""Export mode: the headers a firmware needs, collected into one include root.

Selects types from a workspace (and from installed packages), adds every
type they contain, renders each once, and writes them with the per-firmware
aggregates under the output directory::

    OUT/mros_message_support.h
    OUT/<pkg>/<Type>.h
    OUT/message_headers.h, OUT/message_class_specialization.h, OUT/msg_max_size.h

Everything is rendered before anything is written, so a bad definition
leaves OUT as it was. Headers left over from types that no longer exist in a
package the run exported are removed.
"""

import os

from colcon_mros.errors import GenmrosError
from colcon_mros.model import ModelBuilder
from colcon_mros.output import remove_stale, write_files
from colcon_mros.parse import SpecLoader
from colcon_mros.render import DEFAULT_VARIABLE_SIZE_BUDGET, Renderer
from colcon_mros.workspace import (installed_packages, msg_search_path, type_name_of,
                                   workspace_packages)


class ExportResult:
    """What an export wrote: the message models, the changed and removed paths."""

    def __init__(self, messages, services, changed, removed):
        self.messages = messages
        self.services = services
        self.changed = changed
        self.removed = removed


class Selection:
    """The message and service files a run exports, by package."""

    def __init__(self, packages, workspace_names, package_names, type_names):
        self.messages = []
        self.services = []
        self._packages = packages
        if not package_names and not type_names:
            package_names = sorted(workspace_names)
        for name in package_names:
            self._add_package(name)
        for full_name in type_names:
            self._add_type(full_name)

    def _package(self, name, what):
        if name not in self._packages:
            raise GenmrosError("unknown package '%s'%s (not in the workspace or the installed "
                               'ROS packages)' % (name, what))
        return self._packages[name]

    def _add_package(self, name):
        package = self._package(name, '')
        self.messages.extend((name, path) for path in package.message_files())
        self.services.extend((name, path) for path in package.service_files())

    def _add_type(self, full_name):
        package_name, _, type_name = full_name.partition('/')
        if not package_name or not type_name:
            raise GenmrosError("bad type name '%s' (expected PACKAGE/TYPE)" % full_name)
        package = self._package(package_name, " for type '%s'" % full_name)
        for files, target in ((package.message_files(), self.messages),
                              (package.service_files(), self.services)):
            for path in files:
                if type_name_of(path) == type_name:
                    target.append((package_name, path))
                    return
        raise GenmrosError("unknown type '%s' (package %s has no %s.msg or %s.srv)"
                           % (full_name, package_name, type_name, type_name))


def _check_type_ids(messages):
    owners = {}
    for message in messages:
        other = owners.setdefault(message.type_id, message.full_name)
        if other != message.full_name:
            raise GenmrosError('type ID %d is shared by %s and %s; rename one type'
                               % (message.type_id, other, message.full_name))


# What an export writes: everything, or one of its two halves (an export
# dir shared by many firmwares takes the headers, each firmware its aggregates).
EXPORT_PARTS = ('all', 'headers', 'aggregates')


def export(output_dir, prefixes, workspace=None, package_names=(), type_names=(),
           variable_budget=DEFAULT_VARIABLE_SIZE_BUDGET, template_dir=None, only='all'):
    packages = installed_packages(prefixes)
    local = workspace_packages(workspace) if workspace else {}
    packages.update(local)
    if workspace is None and not package_names and not type_names:
        raise GenmrosError('nothing to export: give --workspace, --package or --type')
    selection = Selection(packages, local.keys(), package_names, type_names)

    loader = SpecLoader(msg_search_path(packages))
    builder = ModelBuilder(loader)
    renderer = Renderer(template_dir)
    roots = [loader.load_message_file(path, package).full_name
             for package, path in selection.messages]
    services = [builder.service(loader.load_service_file(path, package))
                for package, path in selection.services]
    for service in services:
        roots.extend(service.dependencies)
    messages = builder.closure(roots)
    _check_type_ids(messages)

    writes_headers = only != 'aggregates'
    files = {}
    if writes_headers:
        files.update(renderer.support_header())
        for message in messages:
            files.update(renderer.message(message))
        for service in services:
            files.update(renderer.service(service))
    if only != 'headers':
        files.update(renderer.aggregates(messages, variable_budget))

    changed = write_files(output_dir, files)
    removed = []
    if writes_headers:
        exported_packages = {message.package for message in messages}
        exported_packages.update(service.package for service in services)
        for name in sorted(exported_packages):
            keep = {'%s.h' % type_name for type_name in packages[name].type_names()}
            removed.extend(remove_stale(os.path.join(output_dir, name), keep))
    return ExportResult(messages, services, changed, removed)
