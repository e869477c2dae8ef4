"""Which definition file put which file into a catkin export dir.

catkin runs genmros once per .msg/.srv file, and each run also puts into the
export dir (MROS_EXPORT_DIR) the headers and definitions of every type the
file contains, from any package. When a file stops containing a type, no
run writes that type any more, yet its header would stay, and a firmware's
``mros_import_messages()`` without TYPES would take it in. So every run
records its claim, the export-relative paths it wrote, and files that were
claimed once and are claimed by no definition now leave the dir.

Under ``<export dir>/.genmros/``:

- ``claims/<pkg>/<msg|srv>/<file>``: one claim per definition file, one path
  per line. A run whose new claim drops a path prunes the dir; the CMake side
  removes the claim of a definition removed from its package, then runs
  ``genmros prune-export``. Prunes read every claim, so the runs that drop
  nothing (nearly all of them) skip it.
- ``ledger``: every path ever claimed and not yet removed; only these are
  ever removed, so files that genmros did not put there stay.
- ``lock``: runs for packages built in parallel share the dir, so writing,
  claiming and pruning happen under an exclusive lock.
"""

import fcntl
import os

from colcon_mros.output import write_files

STATE_DIR = '.genmros'


def claim_key(package, definition_path):
    """The claim name of a definition file: <pkg>/<msg|srv>/<file>."""
    kind = os.path.basename(os.path.dirname(definition_path))
    return '/'.join((package, kind, os.path.basename(definition_path)))


class ExportClaims:
    """The claims of one export dir, held under its lock (a context manager)."""

    def __init__(self, export_dir):
        self._export_dir = export_dir
        self._state_dir = os.path.join(export_dir, STATE_DIR)
        self._lock = None

    def __enter__(self):
        os.makedirs(self._state_dir, exist_ok=True)
        self._lock = open(os.path.join(self._state_dir, 'lock'), 'a')
        fcntl.flock(self._lock, fcntl.LOCK_EX)
        return self

    def __exit__(self, *exception):
        self._lock.close()  # releases the lock
        self._lock = None

    def record(self, key, paths):
        """Claim paths for the definition key, replacing its former claim;
        returns whether the former claim named a path the new one does not
        (only then can a file have lost its last claim)."""
        claim = 'claims/' + key
        dropped = self._read_lines(claim) - set(paths)
        ledger = self._read_lines('ledger') | set(paths)
        write_files(self._state_dir, {'ledger': _lines(ledger), claim: _lines(paths)})
        return bool(dropped)

    def prune(self):
        """Remove the files of the ledger that no claim names; returns them."""
        ledger = self._read_lines('ledger')
        claimed = set()
        claims_dir = os.path.join(self._state_dir, 'claims')
        for directory, _, names in os.walk(claims_dir):
            for name in names:
                if not name.endswith(('.msg', '.srv')):  # a killed writer's temporary
                    continue
                relative = os.path.relpath(os.path.join(directory, name), self._state_dir)
                claimed |= self._read_lines(relative)
        unclaimed = sorted(ledger - claimed)
        for relative in unclaimed:
            _remove_with_empty_parents(self._export_dir, relative)
        if unclaimed:
            write_files(self._state_dir, {'ledger': _lines(ledger & claimed)})
        return unclaimed

    def _read_lines(self, relative):
        try:
            with open(os.path.join(self._state_dir, relative), encoding='utf-8') as stream:
                return {line for line in stream.read().splitlines() if line}
        except FileNotFoundError:
            return set()


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
