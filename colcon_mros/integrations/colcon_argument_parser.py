# SPDX-License-Identifier: BSD-3-Clause
"""The colcon hook of ``colcon build --mros-export DIR``.

Implements colcon-core's ``colcon_core.argument_parser`` extension point
(``ArgumentParserDecoratorExtensionPoint``), registered in setup.cfg. No
documented extension point both adds an argument to one verb and runs code
after that verb, so this module holds the one place that leans on how
colcon-core builds its command line: colcon-core sets each verb's parser
defaults with ``verb_extension`` and ``main`` (colcon_core.command); the
decorator sees that call for the ``build`` verb, adds ``--mros-export`` and
wraps the verb's ``main`` to export after a successful build, so a failed
export fails ``colcon build`` (one line, exit code 1). Without the flag,
colcon runs exactly as before. tests/integrations/test_colcon_versions.py holds this
against Debian's colcon-core and the newest on PyPI.

What the export does is :mod:`colcon_mros.integrations.colcon_export`'s job; it is imported
only when the flag is used, so colcon loads this module without genmsg.
"""

import os

from colcon_core.argument_parser import ArgumentParserDecorator
from colcon_core.argument_parser import ArgumentParserDecoratorExtensionPoint
from colcon_core.plugin_system import satisfies_version

from colcon_mros.errors import GenmrosError

FLAG_HELP = ('After the build, write the mROS headers (genmros) of every message and service '
             'of the built packages and their dependencies to the export dir DIR '
             '(DIR/mros_export.cmake for a firmware build)')


class MrosExportArgumentParserDecorator(ArgumentParserDecoratorExtensionPoint):
    """Adds --mros-export DIR to colcon build."""

    def __init__(self):  # noqa: D107
        super().__init__()
        satisfies_version(ArgumentParserDecoratorExtensionPoint.EXTENSION_POINT_VERSION, '^1.0')

    def decorate_argument_parser(self, *, parser):  # noqa: D102
        return _BuildVerbDecorator(parser)


class _BuildVerbDecorator(ArgumentParserDecorator):
    """Catches the build verb's parser when colcon sets the verb's main on it."""

    def set_defaults(self, **kwargs):  # noqa: D102
        extension = kwargs.get('verb_extension')
        if getattr(extension, 'VERB_NAME', None) == 'build' and 'main' in kwargs:
            self._parser.add_argument('--mros-export', metavar='DIR', help=FLAG_HELP)
            kwargs['main'] = _exporting(kwargs['main'])
        return self._parser.set_defaults(**kwargs)


def _exporting(build_main):
    """The build verb's main, checking DIR before and exporting after the build."""
    def main(*, context):
        export_dir = context.args.mros_export
        if export_dir:
            from colcon_mros.core.output import check_writable
            _fail_as_colcon_error(check_writable, os.path.abspath(export_dir))
        rc = build_main(context=context)
        if rc or not export_dir:
            return rc
        from colcon_mros.integrations.colcon_export import export_built_packages
        _fail_as_colcon_error(export_built_packages, context.args, os.path.abspath(export_dir))
        return 0
    return main


def _fail_as_colcon_error(function, *arguments):
    # colcon reports a RuntimeError from a verb as one line and exits with 1.
    try:
        function(*arguments)
    except GenmrosError as error:
        raise RuntimeError('genmros: error: %s' % error)
