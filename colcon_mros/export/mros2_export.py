# SPDX-License-Identifier: BSD-3-Clause
"""What one mros2 firmware needs, and what one ROS 2 package's build writes.

:func:`export_firmware` (``genmros mros2-export``, the CMake module's
``mros2_import_messages()``): the named types of a ROS 2 workspace and the
installed packages, every type they contain, the support headers and, for
the types the firmware publishes and subscribes to, mros2's templates.hpp,
switched into the output directory in one step
(:func:`colcon_mros.core.output.write_tree`): a bad definition leaves it
as it was, and headers of types no longer exported leave it. Given the
board (:class:`Board`: its rtps/config.h, receive limit, mros2 checkout),
the fit check (:mod:`colcon_mros.mros2.fit`) runs first and a misfit writes
nothing; :func:`firmware_fit` (``genmros mros2-fit``) runs it alone.
:func:`render_types` also serves the rosidl generator
(:mod:`colcon_mros.integrations.rosidl_generator`).
"""

import os

from colcon_mros.core.output import is_generated, write_tree
from colcon_mros.core.settings import read_settings
from colcon_mros.core.storage import storage_for
from colcon_mros.errors import GenmrosError, close_match
from colcon_mros.mros2 import render
from colcon_mros.mros2.endpoints import parse_endpoints
from colcon_mros.mros2.fit import Fit, Mros2Checkout, receive_limit
from colcon_mros.mros2.rules import PEER_MAX_MESSAGE
from colcon_mros.ros2.interfaces import all_packages, where_packages_come_from
from colcon_mros.ros2.model import ModelBuilder


class Mros2Export:
    """What an export wrote: its messages and services, changed and removed
    paths, the fit check's Fit where the board was given, and the notes on
    the endpoints' names."""

    def __init__(self, messages, services, changed, removed, fit=None, notes=()):
        self.messages = messages
        self.services = services
        self.changed = changed
        self.removed = removed
        self.fit = fit
        self.notes = list(notes)


def _builder(packages, storage, option_files):
    # A package's own bounds: msg/genmros.options, as on the ROS 1 side.
    msg_dirs = {name: [os.path.join(package.root, 'msg')] for name, package in packages.items()}
    return ModelBuilder(packages, storage_for(storage, option_files, msg_dirs))


def _select(builder, package_names, type_names):
    """The messages and services named: whole packages, or single types
    ('pkg/msg/Type', 'pkg/Type', 'pkg/srv/Service' or a service's half)."""
    messages, services = [], []
    for name in package_names:
        if name not in builder.packages:
            raise GenmrosError("unknown ROS 2 package '%s' (not in the workspace or the installed "
                               'ROS 2 packages%s; %s)'
                               % (name, close_match(name, builder.packages),
                                  where_packages_come_from(name)))
        for kind, type_name in sorted(builder.packages[name].interfaces):
            if kind == 'msg':
                messages.append(builder.message('%s/msg/%s' % (name, type_name)))
            else:
                services.append(builder.service('%s/srv/%s' % (name, type_name)))
    for full_name in type_names:
        parts = full_name.split('/')
        if len(parts) == 3 and parts[1] == 'srv' and not parts[2].endswith(('_Request',
                                                                            '_Response')):
            services.append(builder.service(full_name))
        else:
            messages.append(builder.message(full_name))
    return messages, services


def render_types(messages, services):
    """{path: text} of the headers of messages (service halves among them
    are their services') and of services."""
    files = {}
    for message in messages:
        if message.kind == 'msg':
            files.update(render.message_header(message))
    for service in services:
        files.update(render.service_header(service))
    return files


def _within(path, directory):
    return os.path.commonpath([os.path.abspath(path), os.path.abspath(directory)]) == \
        os.path.abspath(directory)


class Board:
    """What the fit check reads of the board: its rtps/config.h (None: no
    check), the receive limit as given (--receive-limit: bytes or
    FILE:NAME), the user's mros2 checkout (or None), and the largest
    datagram the ROS side sends (--peer-max-message)."""

    def __init__(self, rtps_config=None, receive_limit_text=None, mros2_root=None,
                 peer_max_message=PEER_MAX_MESSAGE):
        self.rtps_config = rtps_config
        self.receive_limit_text = receive_limit_text
        self.mros2_root = mros2_root
        self.peer_max_message = peer_max_message

    def fit(self, endpoints, notes=()):
        """The Fit of endpoints to this board, with notes on their names."""
        settings = read_settings(
            [self.rtps_config], "the board's rtps/config.h (--rtps-config, RTPS_CONFIG)",
            "give the rtps/config.h the firmware compiles with (the mros2 port's "
            'include/rtps/config.h, or its own)')
        return Fit(endpoints, settings,
                   receive_limit(self.receive_limit_text),
                   Mros2Checkout(self.mros2_root) if self.mros2_root else None, notes,
                   self.peer_max_message)


def firmware_fit(board, workspaces=(), prefixes=None, publish=(), subscribe=(), storage='heap',
                 option_files=(), serve=(), call=()):
    """The Fit of a firmware's endpoints (TOPIC:TYPE or TYPE texts; services NAME:TYPE) to a
    Board."""
    builder = _builder(all_packages(workspaces, prefixes), storage, option_files)
    return board.fit(*parse_endpoints(publish, subscribe, builder.message, serve, call,
                                      builder.service))


def export_firmware(output_dir, workspaces=(), prefixes=None, package_names=(), type_names=(),
                    publish=(), subscribe=(), storage='heap', option_files=(), board=None,
                    serve=(), call=()):
    """Write one firmware's mros2 headers under output_dir (see the module);
    with a Board whose rtps_config is given, refuse the misfits first."""
    packages = all_packages(workspaces, prefixes)
    builder = _builder(packages, storage, option_files)
    endpoints, notes = parse_endpoints(publish, subscribe, builder.message, serve, call,
                                       builder.service)
    fit = board.fit(endpoints, notes) if board and board.rtps_config else None
    if fit:
        fit.refuse()
    if not package_names and not type_names and not endpoints:
        if not workspaces:
            raise GenmrosError('name the types to export (--type, --package, --publish, '
                               '--subscribe) or a --workspace')
        # A workspace's packages hide installed ones of the same name.
        package_names = sorted(name for name, package in packages.items()
                               if any(_within(package.root, w) for w in workspaces))
    messages, services = _select(builder, package_names, type_names)
    for endpoint in endpoints:
        if endpoint.service and endpoint.service.service not in services:
            services.append(endpoint.service.service)
    contained = builder.closure(messages + [e.message for e in endpoints] +
                                [half for service in services for half in service.dependencies])
    files = render.support_headers()
    files.update(render_types(contained, services))
    if endpoints:
        files.update(render.templates_header(endpoints, fit.board_requirements if fit else ()))
    changed, removed = write_tree(
        output_dir, files, drop=lambda relative: is_generated(os.path.join(output_dir, relative)))
    return Mros2Export([m for m in contained if m.kind == 'msg'], services, changed, removed,
                       fit, notes)
