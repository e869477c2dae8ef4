# SPDX-License-Identifier: BSD-3-Clause
"""The export dir: the mROS headers of a ROS workspace, collected for firmware.

catkin fills one when ``MROS_EXPORT_DIR`` is set, ``colcon build
--mros-export DIR`` writes one, and a firmware's ``mros_import_messages()``
reads one. This module is the only code that knows its layout::

    DIR/mros_export.cmake          what a firmware include()s: the include dir,
                                   MROS_EXPORT_TYPES, the CMake module
    DIR/include/<pkg>/<Type>.h     the headers, and the support headers
    DIR/share/<pkg>/package.xml    the definitions the headers come from, as an
    DIR/share/<pkg>/msg|srv/...    installed prefix holds them (genmros mros-v1-export
                                   --underlay DIR reads them)
    DIR/COLCON_IGNORE              so no tool takes share/<pkg> for packages
    DIR/.genmros/                  private: which definition put which file here,
                                   the run records of catkin's packages and of
                                   colcon's export

Every type ``mros_export.cmake`` lists (messages, services and their
Request/Response halves) can be imported by name. The headers are in one
form, :data:`HEADER_FORM`: a firmware that asks for another has them
generated anew from the definitions beside them.

catkin's generator run for a package puts into the dir, for each definition
file it generates, the headers and definitions of every type the file
contains, from any package. When a file stops containing a type, no run
writes that type any more, yet it would stay. So each file's generation
records its claim, the paths it wrote, under
``.genmros/``, and files that were claimed once and are claimed by no
definition now leave the dir; files genmros never claimed are never removed.
Runs for packages built in parallel share the dir, so writing, claiming and
pruning happen under an exclusive lock.
"""

import fcntl
import os

from colcon_mros.core.defaults import DEFAULT_DEFINITION_TEXT, DEFAULT_STORAGE
from colcon_mros.core.output import check_writable, write_files
from colcon_mros.errors import GenmrosError
from colcon_mros.ros1.definition import KINDS, Definition, definitions_in

# (storage, definition text) of the headers catkin and colcon export.
HEADER_FORM = (DEFAULT_STORAGE, DEFAULT_DEFINITION_TEXT)
INCLUDE_DIR = 'include'
SHARE_DIR = 'share'
CMAKE_FILE = 'mros_export.cmake'
IGNORE_MARKER = 'COLCON_IGNORE'
MANIFEST = 'package.xml'
# mros_export.cmake's template.
TEMPLATE_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'templates')
_STATE_DIR = '.genmros'
_CLAIMS_DIR = 'claims'
_LEDGER = 'ledger'
_LOCK = 'lock'
_RECORDS_DIR = 'runs'
_COLCON_RECORD = '.colcon-export'


def _read(path):
    try:
        with open(path, encoding='utf-8') as stream:
            return stream.read()
    except (OSError, UnicodeDecodeError) as error:
        raise GenmrosError('cannot read file: %s' % getattr(error, 'strerror', error), path)


def _lines(paths):
    return ''.join(path + '\n' for path in sorted(paths))


def _remove_with_empty_parents(root, relative):
    """Remove root/relative, then its directories below root left empty."""
    path = os.path.join(root, relative)
    try:
        os.unlink(path)
    except FileNotFoundError:
        pass
    directory = os.path.dirname(path)
    while os.path.abspath(directory) != os.path.abspath(root):
        try:
            os.rmdir(directory)
        except OSError:  # not empty
            return
        directory = os.path.dirname(directory)


def _manifest_of(definition):
    """The package.xml beside a definition's msg/ or srv/ directory, if any."""
    package_root = os.path.dirname(os.path.dirname(os.path.abspath(definition.path)))
    path = os.path.join(package_root, MANIFEST)
    return path if os.path.isfile(path) else None


class ExportDir:
    """One export dir. Methods that change it take its lock themselves."""

    def __init__(self, path):
        self.path = os.path.abspath(path)
        self.include_dir = os.path.join(self.path, INCLUDE_DIR)
        self.share_dir = os.path.join(self.path, SHARE_DIR)
        self.cmake_file = os.path.join(self.path, CMAKE_FILE)
        self._state_dir = os.path.join(self.path, _STATE_DIR)

    # Reading.

    def definitions(self):
        """Every definition the dir holds, by package."""
        found = []
        packages = sorted(os.listdir(self.share_dir)) if os.path.isdir(self.share_dir) else []
        for package in packages:
            for kind in KINDS:
                directory = os.path.join(self.share_dir, package, kind)
                found.extend(definitions_in(package, directory, kind))
        return found

    def types(self):
        """The name of every type the dir holds, each importable: messages
        and services' halves first, then the services."""
        messages, services = set(), set()
        for definition in self.definitions():
            if definition.is_service:
                services.add(definition.full_name)
                messages.update(definition.full_type_names[1:])
            else:
                messages.add(definition.full_name)
        return sorted(messages) + sorted(services)

    @property
    def records_dir(self):
        """Where catkin's run for a package leaves its run record, named after
        the package: when the dir is removed, the package is generated again."""
        return os.path.join(self._state_dir, _RECORDS_DIR)

    @property
    def colcon_record(self):
        """The run record of colcon build --mros-export's last export here."""
        return os.path.join(self._state_dir, _RECORDS_DIR, _COLCON_RECORD)

    def outputs_of(self, definition):
        """The paths generating definition for catkin writes here (its own
        headers and its copy; the types it contains vary with the build)."""
        headers = [os.path.join(self.include_dir, definition.package, name + '.h')
                   for name in definition.type_names]
        return headers + [os.path.join(self.share_dir, definition.key)]

    # Changing.

    def prepare(self, cmake_module):
        """Make the dir an export dir (before a build writes to it)."""
        check_writable(self.path)
        with self._locked():
            self._write_tables(cmake_module)

    def add_generated(self, definition, headers, contained, cmake_module):
        """What generating one definition file for catkin puts here: the
        headers rendered ({include-relative path: text}) and the definitions
        of the file and of every type contained (Definitions); the file's
        former claim is replaced, and what no definition claims any more
        leaves."""
        files = {os.path.join(INCLUDE_DIR, relative): text for relative, text in headers.items()}
        for source in [definition] + list(contained):
            files.update(self._definition_files(source))
        with self._locked():
            written = write_files(self.path, files)
            if self._claim(definition.key, files):
                self._prune()
            self._write_tables(cmake_module)
        return written

    def forget_other_definitions(self, package, keys, cmake_module):
        """A package now has the definitions keys (Definition.key) only: the
        claims of its others go, and what no definition claims any more
        leaves (a .msg removed from the package). Returns the removed paths."""
        prefix = os.path.join(self._state_dir, _CLAIMS_DIR, package)
        stale = []
        for kind in KINDS:
            directory = os.path.join(prefix, kind)
            for name in sorted(os.listdir(directory)) if os.path.isdir(directory) else ():
                key = '%s/%s/%s' % (package, kind, name)
                if name.endswith('.' + kind) and key not in keys:
                    stale.append(key)
        if not stale:
            return []
        with self._locked():
            for key in stale:
                os.unlink(os.path.join(self._state_dir, _CLAIMS_DIR, key))
            removed = self._prune()
            self._write_tables(cmake_module)
        return removed

    def prune(self, cmake_module=None):
        """Remove what no definition claims any more; returns the paths."""
        with self._locked():
            removed = self._prune()
            if cmake_module and removed:
                self._write_tables(cmake_module)
        return removed

    def replace_packages(self, packages, cmake_module):
        """The definitions colcon build --mros-export puts beside the headers
        it exported into include_dir: those of every package exported
        ({name: Package}); a package's removed definitions leave. Other
        packages stay: a build of some packages adds to an export, never
        shrinks it."""
        files = {}
        keep = set()
        for package in packages.values():
            for path in package.message_files() + package.service_files():
                definition = Definition(package.name, path)
                files.update(self._definition_files(definition))
                keep.add(definition.key)
        with self._locked():
            for old in self.definitions():
                if old.package in packages and old.key not in keep:
                    os.unlink(os.path.join(self.share_dir, old.key))
            write_files(self.path, files)
            self._write_tables(cmake_module)

    # Layout.

    def _definition_files(self, definition):
        """{dir-relative path: text}: a definition, and its package.xml."""
        files = {os.path.join(SHARE_DIR, definition.key): _read(definition.path)}
        manifest = _manifest_of(definition)
        if manifest:
            files[os.path.join(SHARE_DIR, definition.package, MANIFEST)] = _read(manifest)
        return files

    def _write_tables(self, cmake_module):
        """mros_export.cmake (with the types the dir holds now) and COLCON_IGNORE."""
        from colcon_mros.core.render import render_template  # empy, only when writing
        write_files(self.path, {
            CMAKE_FILE: render_template(TEMPLATE_DIR, CMAKE_FILE + '.em', include_dir=INCLUDE_DIR,
                                        types=self.types(), cmake_module=cmake_module),
            IGNORE_MARKER: '',
        })

    # Claims, under .genmros/: claims/<pkg>/<kind>/<file> (one path per line),
    # and the ledger, every path ever claimed and not yet removed.

    def _locked(self):
        return _Lock(os.path.join(self._state_dir, _LOCK))

    def _claim(self, key, paths):
        """Claim paths for the definition key, replacing its former claim;
        returns whether the former claim named a path the new one does not
        (only then can a file have lost its last claim)."""
        claim = os.path.join(_CLAIMS_DIR, key)
        dropped = self._read_lines(claim) - set(paths)
        ledger = self._read_lines(_LEDGER) | set(paths)
        write_files(self._state_dir, {_LEDGER: _lines(ledger), claim: _lines(paths)})
        return bool(dropped)

    def _prune(self):
        ledger = self._read_lines(_LEDGER)
        claimed = set()
        claims_dir = os.path.join(self._state_dir, _CLAIMS_DIR)
        for directory, _, names in os.walk(claims_dir):
            for name in names:
                # Else a killed writer's temporary.
                if not name.endswith(tuple('.' + kind for kind in KINDS)):
                    continue
                relative = os.path.relpath(os.path.join(directory, name), self._state_dir)
                claimed |= self._read_lines(relative)
        unclaimed = sorted(ledger - claimed)
        for relative in unclaimed:
            _remove_with_empty_parents(self.path, relative)
        if unclaimed:
            write_files(self._state_dir, {_LEDGER: _lines(ledger & claimed)})
        return unclaimed

    def _read_lines(self, relative):
        try:
            with open(os.path.join(self._state_dir, relative), encoding='utf-8') as stream:
                return {line for line in stream.read().splitlines() if line}
        except FileNotFoundError:
            return set()


class _Lock:
    """The export dir's exclusive lock (flock on .genmros/lock)."""

    def __init__(self, path):
        self._path = path
        self._file = None

    def __enter__(self):
        os.makedirs(os.path.dirname(self._path), exist_ok=True)
        self._file = open(self._path, 'a')
        fcntl.flock(self._file, fcntl.LOCK_EX)
        return self

    def __exit__(self, *exception):
        self._file.close()  # releases the lock
        self._file = None
