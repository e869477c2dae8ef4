"""Which ROS names C++ can take, and how the generated code spells them.

genmsg accepts names C++ cannot take as they are: keywords (``class``),
macros of the standard headers (``EOF``, ``errno``, ``linux`` in the gnu
modes), names the generated code itself uses (``uint32_t``, ``Ptr``,
``mros``), non-ASCII letters. A field or constant is a member, so it can be
renamed: it gets a trailing underscore (``class_``). A package or type name
is the header's path and the C++ type's name, so it cannot: it is refused
with the file and line that declare it. So are two files of one package
that would write the same header (``Foo.srv`` gives ``FooRequest.h``, as
``FooRequest.msg`` does).
"""

import os
import re

from colcon_mros.generator.c_names import GLOBAL_NAMES, MACROS
from colcon_mros.generator.definition import Definition
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

# Members every generated message has (from mros::Message<T> and msg.h.em).
RESERVED_MEMBERS = frozenset('''
    serializedLength serialize deserialize dataSize memCopy Ptr ConstPtr
    MROS_TYPE_ID MROS_MIN_SERIALIZED_SIZE MROS_MAX_SERIALIZED_SIZE
'''.split())

# Names a message header uses unqualified inside the package's namespace
# and inside the message's struct: a member named like one would change
# what the next declaration means; a type named like one would hide it.
UNQUALIFIED_NAMES = frozenset('''
    int8_t uint8_t int16_t uint16_t int32_t uint32_t int64_t uint64_t size_t
    mros std
'''.split())

# Namespaces the generated headers (and the mROS v1 library) open, and the
# trait templates specialized there, looked up from inside them.
SUPPORT_NAMESPACES = frozenset('''
    mros std constants wire message_traits subtask_methods service_traits
    MD5Sum DataType DataTypeId Definition CallCallbackFuncs
'''.split())

# What the support header, and the static header an export of mROS v1
# aggregates puts beside it (colcon_mros.mros_v1.aggregates), declare in
# namespaces mros and mros::wire (types, templates, namespaces): message
# headers name packages from inside those namespaces, where these would be
# found first. tests/generator/test_names.py holds this list equal to the headers'.
SUPPORT_HEADER_NAMES = frozenset('''
    CallCallbackFuncs Codec DataType DataTypeId Definition DeliveryStorage Duration ElementRun
    Fields FloatCodec IntegerCodec LengthCounter MD5Sum Message OnBoardFrames Reader
    RawStorage SequenceCodec Slots StampCodec TextCodec Time UnsignedWord Writer array
    bounded_string bounded_vector
    message_traits mros service_traits subtask_methods wire
'''.split())

# The macros the support headers define or read; a member so named is
# escaped like one of the standard headers' macros.
SUPPORT_MACROS = frozenset('''
    MROS_BOUNDED_OVERFLOW MROS_MESSAGE_CONTAINERS_H MROS_MESSAGE_SUPPORT_H
    MROS_MESSAGE_SUPPORT_VERSION MROS_MESSAGE_SUPPORT_VERSION_H MROS_MESSAGE_WIRE_H
    MROS_LIBRARY_PASSES_FRAME_SIZE MROS_ONBOARD_FRAME_SLOTS MROS_V1_DELIVERY_H MROS_WIRE_PORTABLE
'''.split())

_ASCII_IDENTIFIER = re.compile(r'[A-Za-z][A-Za-z0-9_]*\Z')


def member_identifier(name, type_name):
    """The C++ spelling of a field or constant of type ``type_name``."""
    spelling = name
    while (spelling in CPP_KEYWORDS or spelling in MACROS or spelling in SUPPORT_MACROS
           or spelling in RESERVED_MEMBERS
           or spelling in UNQUALIFIED_NAMES or spelling == type_name):
        spelling += '_'
    return spelling


def is_ascii_identifier(name):
    return bool(_ASCII_IDENTIFIER.match(name))


def check_member_name(name, kind, path, line):
    """Refuse a field or constant name no C++ spelling can keep (non-ASCII)."""
    if not is_ascii_identifier(name):
        raise GenmrosError("'%s' is not a legal %s name for C++ (ASCII letters, digits and '_', "
                           'starting with a letter)' % (name, kind), path, line)


_NOT_ASCII = "not an ASCII identifier (letters, digits and '_', starting with a letter)"
_TYPE_NAME_RULES = [
    ('a C++ keyword', CPP_KEYWORDS),
    ('a macro of the C/C++ standard headers', MACROS),
    ('a name the generated headers use', UNQUALIFIED_NAMES | RESERVED_MEMBERS),
]
_PACKAGE_NAME_RULES = [
    ('a C++ keyword', CPP_KEYWORDS),
    ('a macro of the C/C++ standard headers', MACROS),
    ('a name the generated headers use', SUPPORT_NAMESPACES | SUPPORT_HEADER_NAMES),
    ('a name the C/C++ standard headers declare in the global namespace', GLOBAL_NAMES),
]


def _problem(name, rules):
    if not is_ascii_identifier(name):
        return _NOT_ASCII
    for reason, names in rules:
        if name in names:
            return reason
    return None


def check_type_name(package, name, path, line=None):
    """Refuse a package or type name that cannot be a C++ namespace or struct."""
    problem = _problem(package, _PACKAGE_NAME_RULES)
    if problem:
        raise GenmrosError("package name '%s' cannot be a C++ namespace: %s" % (package, problem),
                           path, line)
    problem = _problem(name, _TYPE_NAME_RULES)
    if not problem and name == package:
        problem = 'the name of its package, whose namespace it would hide'
    if problem:
        raise GenmrosError("type name '%s/%s' cannot be a C++ type: %s" % (package, name, problem),
                           path, line)


# Members of a service's struct: a service cannot be named like one.
SERVICE_MEMBERS = frozenset(['Request', 'Response', 'request', 'response'])


def check_service_name(package, name, path):
    if name in SERVICE_MEMBERS:
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


def check_unique_headers(definition, sibling_paths):
    """Refuse a definition file that would write a header another file of
    its package writes too (Foo.srv and FooRequest.msg, Pair.srv and Pair.msg)."""
    mine = set(definition.type_names)
    for other in sorted(sibling_paths):
        # The same file, or the same definition found in another directory.
        if os.path.basename(other) == definition.file_name:
            continue
        shared = mine.intersection(Definition(definition.package, other).type_names)
        if shared:
            raise GenmrosError("'%s/%s' would be defined twice, by %s and by %s; rename one"
                               % (definition.package, sorted(shared)[0], definition.file_name,
                                  other),
                               definition.path)
