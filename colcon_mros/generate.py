"""Generator mode: one .msg or .srv file in, its headers out (as gencpp does).

This is what catkin calls per file, with gencpp's arguments. OUTDIR is the
package's directory under the include root (``<root>/<pkg>``); the support
header goes to the include root beside it.
"""

import os

from colcon_mros.errors import GenmrosError
from colcon_mros.model import ModelBuilder
from colcon_mros.output import write_files
from colcon_mros.parse import SpecLoader
from colcon_mros.render import Renderer


def generate_file(path, package, output_dir, search_path, template_dir=None):
    """Generate the headers of one definition file; returns the paths written."""
    loader = SpecLoader(search_path)
    builder = ModelBuilder(loader)
    renderer = Renderer(template_dir)
    if path.endswith('.msg'):
        spec = loader.load_message_file(path, package)
        files = renderer.message(builder.message(spec.full_name))
    elif path.endswith('.srv'):
        files = renderer.service(builder.service(loader.load_service_file(path, package)))
    else:
        raise GenmrosError('expected a .msg or .srv file', path)
    package_files = {os.path.basename(relative): text for relative, text in files.items()}
    include_root = os.path.dirname(os.path.abspath(output_dir))
    return (write_files(output_dir, package_files) +
            write_files(include_root, renderer.support_header()))
