"""An app's message types against the mROS v1 settings its build includes:
the fit check ``genmros mros-v1-pc`` runs before it builds, and the data of
``genmros mros-v1-fit``'s report (:mod:`colcon_mros.export.library_fit`)."""

from colcon_mros.export.firmware_export import ExportRequest, FirmwareTypes
from colcon_mros.export.library_fit import Fit, read_settings
from colcon_mros.generator.library_needs import LibraryNeeds
from colcon_mros.generator.workspace import split_msg_paths


def types_fit(type_names, msg_paths, settings_files, storage_kind, option_files):
    """The Fit of the types (found on msg_paths: source trees and installed
    prefixes; none: the ROS environment) to the settings headers."""
    prefixes, workspaces = split_msg_paths(msg_paths)
    request = ExportRequest(output_dir=None, prefixes=prefixes or None, workspaces=workspaces,
                            type_names=type_names, storage_kind=storage_kind,
                            option_files=option_files)
    return Fit(LibraryNeeds(FirmwareTypes(request).firmware_messages),
               read_settings(settings_files))

