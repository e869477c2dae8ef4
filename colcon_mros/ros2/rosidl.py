# SPDX-License-Identifier: BSD-3-Clause
"""rosidl's Python helpers, from whichever rosidl line is installed.

rosidl 3.3 and later (Debian 12's 3.3.1, the ROS 2 wheels' 4.x) keep them
in ``rosidl_pycommon``; Humble's rosidl 3.1 keeps the same functions in
``rosidl_cmake``. Everything the package takes from them goes through here.
"""

import importlib

# The helpers' module, newest first.
HELPER_MODULES = ('rosidl_pycommon', 'rosidl_cmake')


def _helpers():
    newest, humbles = HELPER_MODULES
    try:
        return importlib.import_module(newest)
    except ImportError:
        return importlib.import_module(humbles)


def type_file_stem(name):
    """rosidl's file name of a type: 'TypeName' -> 'type_name', 'UInt16' -> 'u_int16'."""
    return _helpers().convert_camel_case_to_lower_case_underscore(name)


def read_generator_arguments(path):
    """The arguments file rosidl_write_generator_arguments() wrote, as a dict."""
    return _helpers().read_generator_arguments(path)
