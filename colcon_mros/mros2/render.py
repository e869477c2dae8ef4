# SPDX-License-Identifier: BSD-3-Clause
"""Render mros2 headers from the ROS 2 type model: ``{relative path: text}``.

One header per message (``pkg/msg/type_name.hpp``) and per service
(``pkg/srv/name.hpp``, both halves), the static support headers, a
firmware's ``templates.hpp``, and the Fast DDS profile of the ROS nodes
that talk to a board. Nothing is written here.
"""

import os

from colcon_mros import __version__
from colcon_mros.core.render import render_template, static_text
from colcon_mros.mros2.cpp import (SUPPORT_HEADERS, WIRE_HEADER, WIRE_VERSION, CppMessage,
                                   CppMessageName, CppService)
from colcon_mros.mros2.endpoints import CALL, PUBLISH, SERVE, SUBSCRIBE, messages, services
from colcon_mros.mros2.rules import (GRAPH_MACRO, GRAPH_PATCH, QOS_MACRO, QOS_PATCH,
                                     READER_STACK_MARGIN, READER_STACK_MARGIN_MACRO,
                                     SERVICES_MACRO, SERVICES_PATCH, graph_writer_requirements,
                                     requirements)

TEMPLATE_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'templates')
# The wire header; the containers header is the core's.
SUPPORT_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'support')
TEMPLATES_HEADER = 'templates.hpp'


def _render(name, **context):
    return render_template(TEMPLATE_DIR, name, genmros_version=__version__,
                           wire_header=WIRE_HEADER, wire_version=WIRE_VERSION, **context)


def support_headers():
    return {name: static_text(SUPPORT_DIR, name) for name in SUPPORT_HEADERS}


def message_header(message):
    view = CppMessage(message)
    return {view.header: _render(
        'header.hpp.em', file=view, body_text=_render('message_class.hpp.em', msg=view),
        traits_text=_render('type_name.hpp.em', messages=[view]))}


def service_header(service):
    view = CppService(service)
    body = _render('service_types.hpp.em', srv=view,
                   request_text=_render('message_class.hpp.em', msg=view.request),
                   response_text=_render('message_class.hpp.em', msg=view.response))
    return {view.header: _render(
        'header.hpp.em', file=view, body_text=body,
        traits_text=_render('type_name.hpp.em', messages=[view.request, view.response]))}


def templates_header(endpoints, board_requirements=()):
    """mros2's templates.hpp: the explicit instantiations of its publish and
    subscribe calls for the message types a firmware's endpoints use, and
    the rules' static_asserts on the board's rtps::Config, with
    board_requirements (those of the fit check's board: its mros2 and the
    ROS side), and those of the writer of the patch node-in-the-ros-graph
    where its mros2.h says it is in. It compiles against mros2 with the
    patch reliable-where-asked and without; a firmware with reliable
    endpoints stops with an #error without it, and one with services without
    the patch services-both-ways."""
    publish = [CppMessageName(m) for m in messages(endpoints, PUBLISH, of_services=False)]
    subscribe = [CppMessageName(m) for m in messages(endpoints, SUBSCRIBE, of_services=False)]
    serve = [CppService(s) for s in services(endpoints, SERVE)]
    call = [CppService(s) for s in services(endpoints, CALL)]
    reliable = sorted(e.describe() for e in endpoints if e.reliable and e.service is None)
    return {TEMPLATES_HEADER: _render(
        'templates.hpp.em',
        headers=sorted({name.header for name in publish + subscribe + serve + call}),
        services_macro=SERVICES_MACRO, services_patch=SERVICES_PATCH,
        services=', '.join(sorted({e.service.describe() for e in endpoints if e.service})),
        serve=serve, call=call,
        requirements=requirements(endpoints) + list(board_requirements),
        graph_macro=GRAPH_MACRO, graph_patch=GRAPH_PATCH,
        graph_requirements=graph_writer_requirements(endpoints),
        stack_margin_macro=READER_STACK_MARGIN_MACRO, stack_margin=READER_STACK_MARGIN,
        qos_macro=QOS_MACRO, qos_patch=QOS_PATCH, reliable=', '.join(reliable),
        publish=publish, subscribe=subscribe)}


def peer_profile(max_message, receive_buffer):
    """The Fast DDS profile (XML) of a ROS 2 node whose datagrams stay within max_message
    bytes, the board's receive limit, and whose sockets take receive_buffer bytes."""
    return _render('fast_dds_profile.xml.em', max_message=max_message,
                   receive_buffer=receive_buffer)
