# SPDX-License-Identifier: BSD-3-Clause
"""Export mode: the headers a firmware needs, collected into one include root.

Selects types from a workspace (and from installed packages), adds every
type they contain, renders each once, and writes them with the per-firmware
aggregates, which cover the selected types only, under the output directory::

    OUT/mros_message_support.h and the support headers it includes
    OUT/<pkg>/<Type>.h
    OUT/message_headers.h, OUT/message_class_specialization.h, OUT/msg_max_size.h,
    OUT/mros_v1_delivery.h, OUT/mros_v1_fit_check.h (which message_headers.h includes)

With the mROS v1 library's settings headers, the types are checked against
them first (:mod:`colcon_mros.mros_v1.fit`); mros_v1_fit_check.h checks
them again where the library compiles.

Everything is rendered before anything is written, so a bad definition
leaves OUT as it was, and OUT is switched to the new export in one step
(:func:`colcon_mros.core.output.write_tree`). Headers left over from types that
no longer exist in a package the run exported are removed. With a run
record (:mod:`colcon_mros.export.run_record`), a run whose inputs, arguments
and genmros are those of the last one does nothing.
"""

import os
import time

from colcon_mros.core.defaults import DEFAULT_DEFINITION_TEXT, DEFAULT_STORAGE, EXPORT_PARTS
from colcon_mros.core.output import is_generated, write_tree
from colcon_mros.core.settings import read_settings
from colcon_mros.core.storage import storage_for
from colcon_mros.errors import GenmrosError, close_match
from colcon_mros.export.export_dir import HEADER_FORM
from colcon_mros.export.run_record import RunRecord, definition_directories, snapshot
from colcon_mros.mros_v1.aggregates import SOURCE_DIRS, firmware_files
from colcon_mros.mros_v1.defaults import DEFAULT_VARIABLE_SIZE_BUDGET
from colcon_mros.mros_v1.fit import Fit
from colcon_mros.mros_v1.names import RESERVED_NAMES
from colcon_mros.mros_v1.render import Renderer
from colcon_mros.ros1.model import ModelBuilder
from colcon_mros.ros1.parse import SpecLoader
from colcon_mros.ros1.workspace import (environment_packages, installed_packages,
                                        msg_search_path, split_msg_paths,
                                        workspace_packages)


class ExportResult:
    """What an export wrote: the message models, the changed and removed
    paths; up_to_date when its run record said there was nothing to do;
    warnings of the fit check (types that only might not fit)."""

    def __init__(self, messages, services, changed, removed, up_to_date=False, warnings=()):
        self.messages = messages
        self.services = services
        self.changed = changed
        self.removed = removed
        self.up_to_date = up_to_date
        self.warnings = list(warnings)


class Selection:
    """The definitions a run exports: whole packages, or single types (a
    message, a service, or one half of a service, which brings its service)."""

    def __init__(self, packages, workspace_names, package_names, type_names):
        self.messages = []
        self.services = []
        # Service halves named as types: the firmware uses the half's message.
        self.service_halves = []
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
                               'ROS packages%s)' % (name, what, close_match(name, self._packages)))
        return self._packages[name]

    def _add_package(self, name):
        for definition in self._package(name, '').definitions():
            (self.services if definition.is_service else self.messages).append(definition)

    def _add_type(self, full_name):
        package_name, _, type_name = full_name.partition('/')
        if not package_name or not type_name:
            raise GenmrosError("bad type name '%s' (expected PACKAGE/TYPE)" % full_name)
        package = self._package(package_name, " for type '%s'" % full_name)
        for definition in package.definitions():
            if definition.name == type_name:
                (self.services if definition.is_service else self.messages).append(definition)
                return
            if definition.half_of(type_name):
                self.service_halves.append((definition, full_name))
                return
        raise GenmrosError("unknown type '%s' (package %s has no %s.msg or %s.srv%s)"
                           % (full_name, package_name, type_name, type_name,
                              close_match(type_name, package.type_names())))


class ExportRequest:
    """What one export run is asked for: the command line's ``genmros mros-v1-export``
    and ``colcon build --mros-export`` both make one.

    prefixes=None searches the ROS environment for packages; only is 'all',
    'headers' or 'aggregates' (colcon_mros.core.defaults.EXPORT_PARTS);
    export_dir: an export dir the types come from, whose headers serve
    where they have the form asked for; record: the run record's path;
    library_settings: the mROS v1 library's and app's settings headers to
    check the firmware's types against (:mod:`colcon_mros.mros_v1.fit`),
    fit_strict: a type that only might not fit is refused too."""

    def __init__(self, *, output_dir, prefixes=None, workspaces=(), package_names=(),
                 type_names=(), variable_budget=DEFAULT_VARIABLE_SIZE_BUDGET, template_dir=None,
                 only=EXPORT_PARTS[0], record=None, storage_kind=DEFAULT_STORAGE,
                 option_files=(), definition_text=DEFAULT_DEFINITION_TEXT, export_dir=None,
                 library_settings=(), fit_strict=False):
        self.output_dir = output_dir
        # An export dir is an installed prefix of its definitions.
        self.prefixes = (list(prefixes or []) + [export_dir] if export_dir else prefixes)
        self.workspaces = list(workspaces)
        self.package_names = list(package_names)
        self.type_names = list(type_names)
        self.variable_budget = variable_budget
        self.template_dir = template_dir
        self.only = only
        self.record = record
        self.storage_kind = storage_kind
        self.option_files = list(option_files)
        self.definition_text = definition_text
        self.export_dir = export_dir
        self.library_settings = [os.path.abspath(path) for path in library_settings]
        self.fit_strict = fit_strict

    @property
    def parts(self):
        """What the run writes (EXPORT_PARTS): with an export dir whose
        headers have the form asked for, the aggregates only."""
        if self.export_dir and (self.storage_kind, self.definition_text) == HEADER_FORM:
            return 'aggregates'
        return self.only

    def run_arguments(self):
        """Everything but the definitions that decides what the run writes:
        its arguments, and where the ROS environment finds packages."""
        variables = ('ROS_PACKAGE_PATH', 'CMAKE_PREFIX_PATH')
        environment = (None if self.prefixes is not None else
                       [os.environ.get(name) for name in variables])
        return (os.path.abspath(self.output_dir), self.prefixes, environment,
                [os.path.abspath(path) for path in self.workspaces], self.package_names,
                self.type_names, self.variable_budget, self.parts, self.storage_kind,
                [os.path.abspath(path) for path in self.option_files], self.definition_text,
                self.library_settings, self.fit_strict)


def _check_type_ids(messages):
    owners = {}
    for message in messages:
        other = owners.setdefault(message.type_id, message.full_name)
        if other != message.full_name:
            raise GenmrosError('type ID %d is shared by %s and %s; rename one type'
                               % (message.type_id, other, message.full_name))


class FirmwareTypes:
    """The types one export request selects, loaded: the packages searched,
    every message (the selected ones and all they contain), the services,
    and the firmware's own messages (those it publishes and subscribes: the
    ones it names, not the ones nested in them)."""

    def __init__(self, request):
        packages = (environment_packages() if request.prefixes is None
                    else installed_packages(request.prefixes))
        local = {}
        for workspace in request.workspaces:
            local.update(workspace_packages(workspace))
        packages.update(local)
        if not request.workspaces and not request.package_names and not request.type_names:
            raise GenmrosError('nothing to export: give --workspace, --package or --type')
        selection = Selection(packages, local.keys(), request.package_names, request.type_names)

        search_path = msg_search_path(packages)
        self.storage = storage_for(request.storage_kind, request.option_files, search_path)
        loader = SpecLoader(search_path, RESERVED_NAMES)
        self.storage.check(loader.field_shape)
        builder = ModelBuilder(loader, self.storage, request.definition_text)
        roots = [loader.load_message_file(d.path, d.package).full_name for d in selection.messages]
        services = [builder.service(loader.load_service_file(d.path, d.package))
                    for d in selection.services]
        for service in services:
            roots.extend(service.dependencies)
        for definition, half in selection.service_halves:
            services.append(builder.service(loader.load_service_file(definition.path,
                                                                     definition.package)))
            roots.append(half)
        self.packages = packages
        self.messages = builder.closure(roots)
        _check_type_ids(self.messages)
        self.services = services
        # Only the types the firmware names get API instantiations and callback cases.
        self.firmware_messages = [builder.message(name) for name in dict.fromkeys(roots)]


def firmware_messages(type_names, msg_paths, storage_kind, option_files):
    """The models of the named types, as an export of them has them (found
    on msg_paths: source trees and installed prefixes; none: the ROS
    environment)."""
    prefixes, workspaces = split_msg_paths(msg_paths)
    request = ExportRequest(output_dir=None, prefixes=prefixes or None, workspaces=workspaces,
                            type_names=type_names, storage_kind=storage_kind,
                            option_files=option_files)
    return FirmwareTypes(request).firmware_messages


def export(request):
    """Run one :class:`ExportRequest`; returns an :class:`ExportResult`."""
    output_dir = request.output_dir
    renderer = Renderer(request.template_dir)
    if request.record:
        run = renderer.fingerprint(request.run_arguments(), SOURCE_DIRS)
        last = RunRecord.read(request.record)
        if last and last.is_current(run):
            return ExportResult([], [], [], [], up_to_date=True)
    started_ns = time.time_ns()
    types = FirmwareTypes(request)
    warnings = []
    if request.library_settings:
        fit = Fit(types.firmware_messages, read_settings(request.library_settings))
        fit.refuse(request.fit_strict)
        warnings = fit.warnings
    packages, messages, services = types.packages, types.messages, types.services
    firmware_messages = types.firmware_messages

    parts = request.parts
    writes_headers = parts != 'aggregates'
    files = {}
    if writes_headers:
        files.update(renderer.support_headers())
        for message in messages:
            files.update(renderer.message(message))
        for service in services:
            files.update(renderer.service(service))
    if parts != 'headers':
        files.update(firmware_files(firmware_messages, request.variable_budget))

    # Headers left over from types that no longer exist in an exported package.
    keep = {}
    if writes_headers:
        for name in {m.package for m in messages} | {s.package for s in services}:
            keep[name] = {'%s.h' % type_name for type_name in packages[name].type_names()}

    def stale(relative):
        """A header of a type gone from its package or, when the export
        dir's headers serve, one this dir held in another form."""
        if request.export_dir and not writes_headers:
            return (relative.endswith('.h') and relative not in files
                    and is_generated(os.path.join(output_dir, relative)))
        package, _, header = relative.partition('/')
        return (package in keep and header.endswith('.h') and header not in keep[package]
                and is_generated(os.path.join(output_dir, relative)))

    changed, removed = write_tree(output_dir, files, stale)
    if request.record:
        sources = sorted({model.source for model in messages + services})
        inputs = (sources + definition_directories(sources) + list(types.storage.option_files)
                  + list(request.library_settings))
        RunRecord(run, snapshot(inputs, started_ns),
                  [os.path.join(output_dir, relative) for relative in files]
                  ).write(request.record)
    return ExportResult(messages, services, changed, removed, warnings=warnings)
