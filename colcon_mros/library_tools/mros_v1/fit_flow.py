# SPDX-License-Identifier: BSD-3-Clause
"""The fit flow: which types, against which settings headers, for an app or
an export dir; the one flow ``genmros mros-v1-pc`` (before it builds) and
``genmros mros-v1-fit`` (its report, :mod:`.report`) both run.

For an app (``mros_ws/<app>``) the settings are those its build includes
(:func:`.app.app_settings_headers`) and the types those of its app.json or
``--type``; for an export dir, the types it holds (or ``--type``) against
the settings headers given. Reading the types' definitions needs genmsg.
"""

from colcon_mros.core.settings import read_settings
from colcon_mros.errors import GenmrosError
from colcon_mros.export.export_dir import ExportDir
from colcon_mros.export.firmware_export import firmware_messages
from colcon_mros.mros_v1.app import app_settings_headers, passes_frame_size
from colcon_mros.mros_v1.fit import Fit


def app_fit(app, types, msg_paths, settings_files, storage_kind, option_files, hardened=False):
    """The Fit of an App's types (those given, else its app.json's) to its
    settings (those given, else the headers its build includes), and the
    settings headers read: the one fit flow of genmros mros-v1-pc and
    genmros mros-v1-fit. hardened: the library will have genmros' patch set."""
    types, msg_paths = app.message_types(types, msg_paths)
    settings_files = list(settings_files) or app_settings_headers(app)
    messages = firmware_messages(types, msg_paths, storage_kind, option_files)
    frame_table = not (hardened or passes_frame_size(app.mros_root))
    return Fit(messages, read_settings(settings_files), frame_table), settings_files


def export_dir_fit(export_dir, types, settings_files, storage_kind, option_files):
    """The Fit of an export dir's types (those given, else all it holds) to
    the settings headers given, and those headers."""
    if not settings_files:
        raise GenmrosError('with --export-dir, give the settings headers: --mros-v1-settings '
                           "the app's mros_usr_config.h --mros-v1-settings the library's "
                           'mros_packet_config.h')
    exports = ExportDir(export_dir)
    messages = firmware_messages(list(types) or exports.types(), [exports.path], storage_kind,
                                 option_files)
    return Fit(messages, read_settings(settings_files)), list(settings_files)
