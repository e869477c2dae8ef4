"""Generator mode: one .msg or .srv file in, its headers out (as gencpp does).

This is what catkin calls per file, with gencpp's arguments. OUTDIR is the
package's directory under the include root (``<root>/<pkg>``); the support
headers go to the include root beside it.

With an export dir (catkin's MROS_EXPORT_DIR), the same run also fills that
dir for a firmware (:mod:`colcon_mros.export_dir`): the headers of the file's
types and of every type they contain, from whichever package, and the
definitions they come from.
"""

import os

from colcon_mros.definition import Definition
from colcon_mros.errors import GenmrosError
from colcon_mros.export_dir import ExportDir
from colcon_mros.installed_files import CMAKE_MODULE, installed_file
from colcon_mros.model import ModelBuilder
from colcon_mros.output import write_files
from colcon_mros.parse import SpecLoader
from colcon_mros.render import Renderer


def generate_file(path, package, output_dir, search_path, template_dir=None, export_dir=None):
    """Generate the headers of one definition file; returns the paths written."""
    definition = Definition(package, path)
    loader = SpecLoader(search_path)
    builder = ModelBuilder(loader)
    renderer = Renderer(template_dir)
    if definition.kind == 'msg':
        generated = builder.message(loader.load_message_file(path, package).full_name)
        headers = renderer.message(generated)
    elif definition.kind == 'srv':
        generated = builder.service(loader.load_service_file(path, package))
        headers = renderer.service(generated)
    else:
        raise GenmrosError('expected a .msg or .srv file', path)
    support = renderer.support_header()
    # Rendered in full before anything is written: a bad file changes nothing.
    if export_dir:
        contained = builder.closure(generated.dependencies)
        export_headers = dict(headers)
        export_headers.update(support)
        for message in contained:
            export_headers.update(renderer.message(message))
    package_files = {os.path.basename(relative): text for relative, text in headers.items()}
    include_root = os.path.dirname(os.path.abspath(output_dir))
    written = write_files(output_dir, package_files) + write_files(include_root, support)
    if export_dir:
        written += ExportDir(export_dir).add_generated(
            definition, export_headers, [message.definition_file for message in contained],
            installed_file(CMAKE_MODULE))
    return written
