# SPDX-License-Identifier: BSD-3-Clause
"""The mros2 half of an export dir: what ``colcon build --mros-export DIR``
writes for the ROS 2 packages it built, and what a firmware's
``mros2_import_messages()`` reads::

    DIR/mros2/include/<pkg>/msg/<type>.hpp   the headers of every message and
    DIR/mros2/include/<pkg>/srv/<name>.hpp   service of the built packages and
                                             of every type they contain (heap
                                             storage), with the support headers
    DIR/mros2/share/<pkg>/package.xml        their definitions, as an installed
    DIR/mros2/share/<pkg>/msg|srv/...        ROS 2 prefix holds them, so that
    DIR/mros2/share/ament_index/...          genmros mros2-export --prefix
                                             DIR/mros2 reads them again
    DIR/mros2/COLCON_IGNORE                  so no tool takes share/<pkg> for packages

The headers are rendered from the definitions (the workspace's sources,
the prefixes' ``.msg``/``.srv``/``.idl``), never copied from the headers
rosidl_generator_mros2 installed, so the export does not depend on that
install's layout, nor on the generator having run for a package.

The include dir is switched in one step
(:func:`colcon_mros.core.output.write_tree`); the definitions are
written with :func:`colcon_mros.core.output.write_files`.
"""

import os

from colcon_mros.core.output import write_files
from colcon_mros.export.export_dir import IGNORE_MARKER
from colcon_mros.export.mros2_export import export_firmware
from colcon_mros.ros2.interfaces import AMENT_PACKAGE_INDEX

MROS2_DIR = 'mros2'
INCLUDE_DIR = 'include'
SHARE_DIR = 'share'


def _read(path):
    with open(path, encoding='utf-8') as stream:
        return stream.read()


def export_ros2_packages(export_dir, workspace, package_names, prefixes):
    """Export the interfaces of package_names (from workspace's sources, the
    types they contain from prefixes too) into export_dir's mros2 half."""
    root = os.path.join(export_dir, MROS2_DIR)
    result = export_firmware(os.path.join(root, INCLUDE_DIR), [workspace], prefixes,
                             package_names)
    definitions = {}
    packages = {}
    for model in result.messages + result.services:
        packages[model.package] = os.path.dirname(os.path.dirname(model.source))
        relative = os.path.join(SHARE_DIR, model.package, os.path.basename(
            os.path.dirname(model.source)), os.path.basename(model.source))
        definitions[relative] = _read(model.source)
    for package, package_root in packages.items():
        manifest = os.path.join(package_root, 'package.xml')
        if os.path.isfile(manifest):
            definitions[os.path.join(SHARE_DIR, package, 'package.xml')] = _read(manifest)
        definitions[os.path.join(SHARE_DIR, *AMENT_PACKAGE_INDEX, package)] = ''
    definitions[IGNORE_MARKER] = ''
    write_files(root, definitions)
    return result
