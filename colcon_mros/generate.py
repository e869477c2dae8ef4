"""Generator mode: one .msg or .srv file in, its headers out (as gencpp does).

This is what catkin calls per file, with gencpp's arguments. OUTDIR is the
package's directory under the include root (``<root>/<pkg>``); the support
header goes to the include root beside it.

With an export dir (catkin's MROS_EXPORT_DIR), the same run also fills that
dir for a firmware: ``include/<pkg>/<Type>.h`` for the file's types and every
type they contain, from whichever package, and ``share/<pkg>/`` with those
types' definitions and package.xml, which is what a firmware build reads to
write its aggregates. Files of the export dir that no definition needs any
more leave it (export_claims).
"""

import os

from colcon_mros.errors import GenmrosError
from colcon_mros.export_claims import ExportClaims, claim_key
from colcon_mros.model import ModelBuilder
from colcon_mros.output import write_files
from colcon_mros.parse import SpecLoader
from colcon_mros.render import Renderer


def _read(path):
    with open(path, encoding='utf-8') as stream:
        return stream.read()


def _add_definition(definitions, package, path):
    """Add one definition file, and its package's package.xml once, to
    {share-relative path: text}."""
    kind_dir = os.path.dirname(path)
    definitions['%s/%s/%s' % (package, os.path.basename(kind_dir), os.path.basename(path))] = _read(path)
    manifest = os.path.join(os.path.dirname(kind_dir), 'package.xml')
    key = '%s/package.xml' % package
    if key not in definitions and os.path.isfile(manifest):
        definitions[key] = _read(manifest)


def _export_files(renderer, builder, headers, support, package, path, dependencies):
    """What an export dir takes from one definition file: {relative path: text}."""
    files = {'include/' + relative: text for relative, text in headers.items()}
    files.update(('include/' + relative, text) for relative, text in support.items())
    definitions = {}
    _add_definition(definitions, package, path)
    for message in builder.closure(dependencies):
        files.update(('include/' + relative, text) for relative, text in renderer.message(message).items())
        _add_definition(definitions, message.package, message.source)
    files.update(('share/' + relative, text) for relative, text in definitions.items())
    return files


def generate_file(path, package, output_dir, search_path, template_dir=None, export_dir=None):
    """Generate the headers of one definition file; returns the paths written."""
    loader = SpecLoader(search_path)
    builder = ModelBuilder(loader)
    renderer = Renderer(template_dir)
    if path.endswith('.msg'):
        generated = builder.message(loader.load_message_file(path, package).full_name)
        headers = renderer.message(generated)
    elif path.endswith('.srv'):
        generated = builder.service(loader.load_service_file(path, package))
        headers = renderer.service(generated)
    else:
        raise GenmrosError('expected a .msg or .srv file', path)
    support = renderer.support_header()
    # Rendered in full before anything is written: a bad file changes nothing.
    export_files = (_export_files(renderer, builder, headers, support, package, path,
                                  generated.dependencies)
                    if export_dir else {})
    package_files = {os.path.basename(relative): text for relative, text in headers.items()}
    include_root = os.path.dirname(os.path.abspath(output_dir))
    written = write_files(output_dir, package_files) + write_files(include_root, support)
    if export_dir:
        with ExportClaims(export_dir) as claims:
            written += write_files(export_dir, export_files)
            if claims.record(claim_key(package, path), export_files):
                claims.prune()
    return written
