# SPDX-License-Identifier: BSD-3-Clause
"""Generator mode: a package's .msg and .srv files in, their headers out.

catkin runs it once per package, with gencpp's arguments and every file of
the package (``genmros generate FILE... -p PKG -o OUTDIR -I ...``); one file at a time
works as well. OUTDIR is the package's directory under the include root
(``<root>/<pkg>``); the support headers go to the include root beside it.

With an export dir (catkin's MROS_EXPORT_DIR), the same run also fills that
dir for a firmware (:mod:`colcon_mros.export.export_dir`): the headers of the files'
types and of every type they contain, from whichever package, and the
definitions they come from.

Every file is loaded and every header rendered before anything is written,
so one bad file leaves the package's headers as they were. With run records
(:mod:`colcon_mros.export.run_record`; the outputs make knows the run by),
only the files whose definition, or the definition of a type they contain,
changed since the records were written are generated again: their headers
are rewritten where their text changed and touched otherwise, as a per-file
rule would; the other headers keep their modification times, so nothing
downstream rebuilds for nothing.
"""

import os
import time

from colcon_mros.core.output import is_generated, write_files
from colcon_mros.errors import GenmrosError
from colcon_mros.export.run_record import RunRecord, snapshot
from colcon_mros.integrations.installed_files import CMAKE_MODULE, installed_file
from colcon_mros.mros_v1.names import RESERVED_NAMES
from colcon_mros.mros_v1.render import Renderer
from colcon_mros.ros1.definition import Definition
from colcon_mros.ros1.model import ModelBuilder
from colcon_mros.ros1.parse import SpecLoader

GENERATED_LOG = 'Generating mROS headers from %s/%s'
REMOVED_LOG = 'genmros: removed %s'


class _Generated:
    """One definition file, loaded and (when stale) rendered."""

    def __init__(self, definition, model, contained):
        self.definition = definition
        self.model = model
        self.contained = contained  # the messages its types contain
        self.headers = None  # {include-relative path: text}, once rendered
        self.export_headers = None  # the same, with the contained types' and the support headers

    def sources(self):
        return [self.definition.path] + [message.source for message in self.contained]

    def outputs(self, output_dir, exports):
        paths = [os.path.join(output_dir, name + '.h') for name in self.definition.type_names]
        return paths + (exports.outputs_of(self.definition) if exports else [])


def _load(loader, builder, definition):
    if definition.kind == 'msg':
        model = builder.message(loader.load_message_file(
            definition.path, definition.package).full_name)
    elif definition.kind == 'srv':
        model = builder.service(loader.load_service_file(definition.path, definition.package))
    else:
        raise GenmrosError('expected a .msg or .srv file', definition.path)
    return _Generated(definition, model, builder.closure(model.dependencies))


def _last_runs(records, run):
    """The records of the last run, or None when one is missing or another
    run's (a different genmros, template or argument)."""
    last = [RunRecord.read(path) for path in records]
    if not last or any(record is None or record.run != run.strip() for record in last):
        return None
    return last


def _is_stale(generated, last_runs, outputs):
    """Whether a file needs generating: no records of the same run, an output
    missing, or a definition it reads changed since the records."""
    if last_runs is None or not all(os.path.exists(path) for path in outputs):
        return True
    return any(record.changed(generated.sources()) for record in last_runs)


def _touch(paths, moment):
    for path in paths:
        if os.path.exists(path):
            os.utime(path, (moment, moment))


def _remove_stale_headers(output_dir, definitions):
    """Headers genmros wrote into output_dir for definitions other than these."""
    keep = {name + '.h' for definition in definitions for name in definition.type_names}
    removed = []
    for name in sorted(os.listdir(output_dir)) if os.path.isdir(output_dir) else ():
        path = os.path.join(output_dir, name)
        if name.endswith('.h') and name not in keep and is_generated(path):
            os.unlink(path)
            removed.append(path)
    return removed


def generate_files(paths, package, output_dir, search_path, template_dir=None, export_dir=None,
                   records=(), cmake_module=None, all_of_package=False, log=print):
    """Generate the headers of a package's definition files; returns the
    paths written. log receives one line per file generated or removed.
    all_of_package: paths are all the package has, so the headers and export
    claims of its other (removed) definitions go."""
    started_ns = time.time_ns()
    loader = SpecLoader(search_path, RESERVED_NAMES)
    builder = ModelBuilder(loader)
    renderer = Renderer(template_dir)
    loaded = [_load(loader, builder, Definition(package, path)) for path in paths]
    run = renderer.fingerprint((package, sorted(paths), sorted(search_path.items()), export_dir))
    last_runs = _last_runs(records, run)
    exports = None
    if export_dir:
        from colcon_mros.export.export_dir import ExportDir  # most runs have no export dir
        exports = ExportDir(export_dir)
    stale = [generated for generated in loaded
             if _is_stale(generated, last_runs, generated.outputs(output_dir, exports))]
    # Rendered in full before anything is written: a bad file changes nothing.
    support = renderer.support_headers()
    rendered = {}  # full name: headers, as many files contain the same types

    def message_headers(message):
        if message.full_name not in rendered:
            rendered[message.full_name] = renderer.message(message)
        return rendered[message.full_name]

    for generated in stale:
        if generated.definition.is_service:
            generated.headers = renderer.service(generated.model)
        else:
            generated.headers = message_headers(generated.model)
        if export_dir:
            generated.export_headers = dict(generated.headers)
            generated.export_headers.update(support)
            for message in generated.contained:
                generated.export_headers.update(message_headers(message))

    include_root = os.path.dirname(os.path.abspath(output_dir))
    if exports and cmake_module is None:
        cmake_module = installed_file(CMAKE_MODULE)
    if all_of_package:
        definitions = [generated.definition for generated in loaded]
        removed = _remove_stale_headers(output_dir, definitions)
        if exports:
            removed += [os.path.join(exports.path, relative) for relative in
                        exports.forget_other_definitions(
                            package, {definition.key for definition in definitions}, cmake_module)]
        for path in removed:
            log(REMOVED_LOG % path)
    written = []
    for generated in stale:
        log(GENERATED_LOG % (package, generated.definition.file_name))
        written += write_files(output_dir, {os.path.basename(relative): text
                                            for relative, text in generated.headers.items()})
    if stale:
        written += write_files(include_root, support)
    if exports:
        for generated in stale:
            written += exports.add_generated(
                generated.definition, generated.export_headers,
                [message.definition_file for message in generated.contained], cmake_module)
    # As a per-file rule's touch: the outputs of a regenerated file are newer than its inputs.
    for generated in stale:
        _touch(generated.outputs(output_dir, exports), time.time())
    sources = {source for generated in loaded for source in generated.sources()}
    record = RunRecord(run, snapshot(sorted(sources), started_ns),
                       [path for generated in loaded
                        for path in generated.outputs(output_dir, exports)])
    for path in records:
        record.write(path, touch_ns=started_ns)
    return written
