# SPDX-License-Identifier: BSD-3-Clause
"""The run record: the one rule that says whether genmros' output is up to date.

catkin's generator run for a package, ``colcon build --mros-export``, and
``genmros mros-v1-export --record`` (which the CMake module and the make fragment
run) each keep one record of their last run and ask it before running
again. The output is current when

- the record exists and was written by the same run: the same genmros
  version, templates and arguments (:meth:`Renderer.fingerprint
  <colcon_mros.mros_v1.render.Renderer.fingerprint>`);
- every input it names has the modification time and size it had when that
  run started: the .msg/.srv and options files the output comes from, and
  the msg/ and srv/ directories a run searched for them (so that a file
  added or removed there counts too; catkin names its files itself);
- every output it names exists.

Anything else makes the run again (catkin's runs again only the files whose
inputs changed). An input changed while the run was reading it is recorded
as unknown, so the next run makes it again.

The record is also a make rule, the record depending on every input, each
of which may vanish: make includes it and CMake reads the inputs from it, so
that build tools learn from the record when to call genmros, and genmros
decides.
"""

import os

from colcon_mros.core.output import GENERATED_MARKER, write_files

_UNKNOWN = (0, -1)  # the state of a missing file, or of one changed during the run
_RUN = '# run '
_INPUT = '# input '
_OUTPUT = '# output '


def file_state(path):
    """(modification time in ns, size) of path, or the unknown state."""
    try:
        status = os.stat(path)
    except OSError:
        return _UNKNOWN
    return status.st_mtime_ns, status.st_size


def snapshot(paths, started_ns=None):
    """{absolute path: state} of paths; a file modified after started_ns
    (time.time_ns() when the run began reading) gets the unknown state."""
    states = {}
    for path in paths:
        state = file_state(path)
        if started_ns is not None and state[0] >= started_ns:
            state = _UNKNOWN
        states[os.path.abspath(path)] = state
    return states


def definition_directories(sources):
    """The directories holding the definition files sources."""
    return sorted({os.path.dirname(os.path.abspath(source)) for source in sources})


def _make_path(path):
    return path.replace('$', '$$').replace('#', '\\#').replace(' ', '\\ ')


class RunRecord:
    """One run: its fingerprint, its inputs' states and its outputs."""

    def __init__(self, run, inputs=None, outputs=()):
        self.run = run.strip()
        self.inputs = dict(inputs or {})
        self.outputs = sorted(set(os.path.abspath(path) for path in outputs))

    @classmethod
    def read(cls, path):
        """The record at path, or None if there is none (or not one of ours)."""
        try:
            with open(path, encoding='utf-8') as stream:
                lines = stream.read().splitlines()
        except (OSError, UnicodeDecodeError):
            return None
        if not lines or GENERATED_MARKER not in lines[0]:
            return None
        run, inputs, outputs = None, {}, []
        for line in lines:
            if line.startswith(_RUN):
                run = line[len(_RUN):]
            elif line.startswith(_INPUT):
                fields = line[len(_INPUT):].split(' ', 2)
                if len(fields) == 3 and fields[0].isdigit() and fields[1].lstrip('-').isdigit():
                    inputs[fields[2]] = (int(fields[0]), int(fields[1]))
            elif line.startswith(_OUTPUT):
                outputs.append(line[len(_OUTPUT):])
        return cls(run, inputs, outputs) if run else None

    def changed(self, paths):
        """Whether any of paths is not recorded or differs from its record."""
        for path in paths:
            path = os.path.abspath(path)
            recorded = self.inputs.get(path)
            if recorded is None or recorded == _UNKNOWN or file_state(path) != recorded:
                return True
        return False

    def is_current(self, run):
        """Whether the run, made again, would make what is there."""
        return (self.run == run.strip() and not self.changed(self.inputs)
                and all(os.path.lexists(path) for path in self.outputs))

    def text(self, path):
        """The record as the file at path holds it: comments genmros reads,
        then the make rule, path depending on every input."""
        lines = ['# %s: the run record of genmros. The files below are remade when the run '
                 'or an input changes.' % GENERATED_MARKER,
                 _RUN + self.run]
        lines += ['%s%d %d %s' % ((_INPUT,) + self.inputs[input_path] + (input_path,))
                  for input_path in sorted(self.inputs)]
        lines += [_OUTPUT + output for output in self.outputs]
        inputs = [_make_path(input_path) for input_path in sorted(self.inputs)]
        lines.append('%s:%s' % (_make_path(path),
                                ''.join(' \\\n  ' + input_path for input_path in inputs)))
        lines += ['%s:' % input_path for input_path in inputs]
        return '\n'.join(lines) + '\n'

    def write(self, path, touch_ns=None):
        """Write the record to path (atomically). touch_ns: the time to give
        it, for make to compare with the inputs' (the time the run began
        reading them). The rule names path as given, as the makefile that
        includes the record names it."""
        text = self.text(path)
        path = os.path.abspath(path)
        write_files(os.path.dirname(path), {os.path.basename(path): text})
        if touch_ns is not None:
            os.utime(path, ns=(touch_ns, touch_ns))
