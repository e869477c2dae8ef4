# SPDX-License-Identifier: BSD-3-Clause
"""Which names C++ can take, and how generated code spells them.

A front end accepts names C++ cannot take as they are: keywords
(``class``), macros of the standard headers (``EOF``, ``errno``, ``linux``
in the gnu modes), names a back end's headers use themselves, non-ASCII
letters. A back end describes its own names in :class:`ReservedNames`; the
rules here are the same for every back end:

- a field or constant is a member, so it can be renamed: it gets a trailing
  underscore (``class_``);
- a package or type name is a header's path and a C++ name, so it cannot:
  it is refused with the file and line that declare it.
"""

import re

from colcon_mros.core.c_names import GLOBAL_NAMES, MACROS
from colcon_mros.errors import GenmrosError

# The language's keywords and alternative tokens up to C++20, and NULL.
CPP_KEYWORDS = frozenset('''
    alignas alignof and and_eq asm auto bitand bitor bool break case catch char
    char8_t char16_t char32_t class co_await co_return co_yield compl concept const
    consteval constexpr constinit const_cast continue decltype default delete do
    double dynamic_cast else enum explicit export extern false float for friend
    goto if inline int long mutable namespace new noexcept not not_eq nullptr
    operator or or_eq private protected public register reinterpret_cast requires
    return short signed sizeof static static_assert static_cast struct switch
    template this thread_local throw true try typedef typeid typename union
    unsigned using virtual void volatile wchar_t while xor xor_eq NULL
'''.split())


class ReservedNames:
    """The names a back end's generated headers own.

    members: what every generated struct declares or uses unqualified
    inside it; a member so named is escaped, and a type cannot be so named.
    macros: the macros its support headers define; a member so named is
    escaped. namespaces: what its headers declare where message headers
    name packages; a package cannot be so named. service_members: the
    members of a service's struct; a service cannot be so named.
    """

    def __init__(self, members=frozenset(), macros=frozenset(), namespaces=frozenset(),
                 service_members=frozenset()):
        self.members = frozenset(members)
        self.macros = frozenset(macros)
        self.namespaces = frozenset(namespaces)
        self.service_members = frozenset(service_members)


_ASCII_IDENTIFIER = re.compile(r'[A-Za-z][A-Za-z0-9_]*\Z')
_NOT_ASCII = "not an ASCII identifier (letters, digits and '_', starting with a letter)"


def member_identifier(name, type_name, reserved):
    """The C++ spelling of a field or constant of type ``type_name``."""
    spelling = name
    while (spelling in CPP_KEYWORDS or spelling in MACROS or spelling in reserved.macros
           or spelling in reserved.members or spelling == type_name):
        spelling += '_'
    return spelling


def is_ascii_identifier(name):
    return bool(_ASCII_IDENTIFIER.match(name))


def check_member_name(name, kind, path, line):
    """Refuse a field or constant name no C++ spelling can keep (non-ASCII)."""
    if not is_ascii_identifier(name):
        raise GenmrosError("'%s' is not a legal %s name for C++ (ASCII letters, digits and '_', "
                           'starting with a letter)' % (name, kind), path, line)


def _problem(name, rules):
    if not is_ascii_identifier(name):
        return _NOT_ASCII
    for reason, names in rules:
        if name in names:
            return reason
    return None


def check_type_name(package, name, reserved, path, line=None):
    """Refuse a package or type name that cannot be a C++ namespace or struct."""
    problem = _problem(package, [
        ('a C++ keyword', CPP_KEYWORDS),
        ('a macro of the C/C++ standard headers', MACROS),
        ('a name the generated headers use', reserved.namespaces),
        ('a name the C/C++ standard headers declare in the global namespace', GLOBAL_NAMES),
    ])
    if problem:
        raise GenmrosError("package name '%s' cannot be a C++ namespace: %s" % (package, problem),
                           path, line)
    problem = _problem(name, [
        ('a C++ keyword', CPP_KEYWORDS),
        ('a macro of the C/C++ standard headers', MACROS),
        ('a name the generated headers use', reserved.members),
    ])
    if not problem and name == package:
        problem = 'the name of its package, whose namespace it would hide'
    if problem:
        raise GenmrosError("type name '%s/%s' cannot be a C++ type: %s" % (package, name, problem),
                           path, line)


def check_service_name(package, name, reserved, path):
    if name in reserved.service_members:
        raise GenmrosError("service name '%s/%s' cannot be a C++ type: a name the service header "
                           'uses' % (package, name), path)


def check_type_named_like_package(package, type_names, dependency_package, path, line):
    """Refuse a field of a type from a package that one of its own package's
    types is named after: inside namespace package, that type would hide the
    other package's namespace."""
    if dependency_package != package and dependency_package in type_names:
        raise GenmrosError(
            "type '%s/%s' is named like package '%s', whose types %s uses: C++ cannot tell "
            'them apart; rename one' % (package, dependency_package, dependency_package, package),
            path, line)
