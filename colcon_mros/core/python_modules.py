# SPDX-License-Identifier: BSD-3-Clause
"""What a front end needs of this Python, checked with one clear line.

A front end's parser comes with its ROS (genmsg with ROS 1, rosidl with
ROS 2); without it the modules that generate cannot even be imported, so
each front end checks first and names the package that provides what is
missing instead of showing a traceback.
"""

import importlib.util
import sys

from colcon_mros.errors import GenmrosError


def importable(module):
    """Whether this interpreter finds module, without importing it."""
    try:
        return importlib.util.find_spec(module) is not None
    except (ImportError, ValueError):
        return False


def require_modules(modules, what):
    """Raise a one-line GenmrosError naming the first of modules this
    interpreter cannot import; what(module) says how to install it.
    A tuple in modules is satisfied by any one of its names."""
    for module in modules:
        names = module if isinstance(module, tuple) else (module,)
        if not any(importable(name) for name in names):
            raise GenmrosError('%s cannot import %s; install or source %s, or run genmros with '
                               'the Python that has it' % (sys.executable, ' or '.join(names),
                                                           what(names[0])))
