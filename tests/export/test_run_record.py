# SPDX-License-Identifier: BSD-3-Clause
"""colcon_mros.export.run_record: the one rule for "up to date", the record
read back, and the same record as make reads it; genmros mros-v1-export --record,
which the CMake module and the make fragment run."""

import os
import subprocess
import sys
import time

from colcon_mros.export.run_record import RunRecord, snapshot
from support.checkout import REPO

RUN = 'genmros 0.1.0 0123abcd'


def _write(path, text):
    os.makedirs(os.path.dirname(str(path)), exist_ok=True)
    with open(str(path), 'w') as stream:
        stream.write(text)
    return str(path)


def _recorded(tmp_path, started_ns=None):
    source = _write(tmp_path / 'my pkg' / 'msg' / 'Lamp.msg', 'uint8 on\n')
    output = _write(tmp_path / 'out' / 'Lamp.h', '// header\n')
    record_path = str(tmp_path / 'out.d')
    RunRecord(RUN, snapshot([source, os.path.dirname(source)], started_ns), [output]).write(
        record_path)
    return source, output, record_path


def test_a_record_reads_back_as_written(tmp_path):
    source, output, record_path = _recorded(tmp_path)
    record = RunRecord.read(record_path)
    assert record.run == RUN
    assert record.outputs == [output]
    status = os.stat(source)
    assert record.inputs[source] == (status.st_mtime_ns, status.st_size)
    assert sorted(record.inputs) == [os.path.dirname(source), source]
    assert record.is_current(RUN)


def test_each_change_the_rule_names_makes_the_run_again(tmp_path):
    source, output, record_path = _recorded(tmp_path)
    assert not RunRecord.read(record_path).is_current('genmros 0.1.0 other')

    os.remove(output)
    assert not RunRecord.read(record_path).is_current(RUN)
    _write(output, '// header\n')
    assert RunRecord.read(record_path).is_current(RUN)

    with open(source, 'a') as stream:
        stream.write('uint8 brightness\n')
    assert not RunRecord.read(record_path).is_current(RUN)


def test_a_file_added_beside_a_definition_makes_the_run_again(tmp_path):
    source, _, record_path = _recorded(tmp_path)
    time.sleep(0.01)
    _write(os.path.join(os.path.dirname(source), 'Switch.msg'), 'bool on\n')
    record = RunRecord.read(record_path)
    assert not record.is_current(RUN)
    assert record.changed([os.path.dirname(source)])
    assert not record.changed([source])


def test_an_input_changed_during_the_run_is_unknown_to_the_next(tmp_path):
    _, _, record_path = _recorded(tmp_path, started_ns=time.time_ns() - 10 ** 9)
    record = RunRecord.read(record_path)
    assert not record.is_current(RUN)
    assert set(record.inputs.values()) == {(0, -1)}


def test_a_file_not_written_by_genmros_is_no_record(tmp_path):
    path = _write(tmp_path / 'other.d', 'out.d: in.msg\n# run %s\n' % RUN)
    assert RunRecord.read(path) is None
    assert RunRecord.read(str(tmp_path / 'missing.d')) is None


def _make_would_remake(tmp_path, record_path):
    recipe = _write(tmp_path / 'recipe.mk', '%s:\n\t@echo remade\n' %
                    os.path.basename(record_path))
    result = subprocess.run(['make', '-n', '-f', os.path.basename(record_path), '-f', recipe,
                             os.path.basename(record_path)], cwd=str(tmp_path),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True)
    assert result.returncode == 0, result.stdout
    return 'echo remade' in result.stdout


def test_make_reads_the_record_as_its_rule(tmp_path, monkeypatch):
    # The rule names the record as its writer did (relative here, as the make
    # fragment names it); the input's path has a space, escaped as make wants.
    monkeypatch.chdir(str(tmp_path))
    source, _, _ = _recorded(tmp_path)
    record = RunRecord.read('out.d')
    record.write('out.d')
    record_path = str(tmp_path / 'out.d')
    assert not _make_would_remake(tmp_path, record_path)
    an_hour_ago = time.time() - 3600
    os.utime(record_path, (an_hour_ago, an_hour_ago))
    assert _make_would_remake(tmp_path, record_path)
    os.utime(source, (an_hour_ago - 60, an_hour_ago - 60))
    os.utime(os.path.dirname(source), (an_hour_ago - 60, an_hour_ago - 60))
    assert not _make_would_remake(tmp_path, record_path)
    os.remove(source)  # a vanished input is no error, as in a depfile
    assert _make_would_remake(tmp_path, record_path)


def _export(*arguments, cwd):
    """genmros mros-v1-export from this checkout, run in cwd."""
    return subprocess.run([sys.executable, '-m', 'colcon_mros', 'mros-v1-export']
                          + list(arguments),
                          cwd=cwd, env=dict(os.environ, PYTHONPATH=REPO), stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True)


def test_export_with_a_record_does_nothing_until_something_changes(tmp_path):
    _write(tmp_path / 'ws' / 'demo' / 'package.xml',
           '<package format="2"><name>demo</name><version>1.0.0</version>'
           '<description>d</description><maintainer email="dev@example.com">a</maintainer>'
           '<license>BSD</license></package>\n')
    lamp = _write(tmp_path / 'ws' / 'demo' / 'msg' / 'Lamp.msg', 'uint8 on\n')
    arguments = ['--workspace', 'ws', '--type', 'demo/Lamp', '-o', 'out', '--record', 'out.d']
    cwd = str(tmp_path)
    first = _export(*arguments, cwd=cwd)
    assert first.stdout == (
        'genmros: exported 1 message type and 0 service types to out\n'), first.stdout
    header = str(tmp_path / 'out' / 'demo' / 'Lamp.h')
    written = os.stat(header).st_mtime_ns

    again = _export(*arguments, cwd=cwd)
    assert again.stdout == 'genmros: the headers in out are up to date\n'
    assert os.stat(header).st_mtime_ns == written

    compact = _export(*(arguments + ['--definition-text', 'compact']), cwd=cwd)
    assert compact.stdout.startswith('genmros: exported 1 message'), compact.stdout

    with open(lamp, 'a') as stream:
        stream.write('# a comment only the full text carries\n')
    assert _export(*arguments, cwd=cwd).stdout.startswith('genmros: exported 1 message')
    with open(header) as stream:
        assert 'a comment only the full text carries' in stream.read()

    os.remove(header)
    assert _export(*arguments, cwd=cwd).stdout.startswith('genmros: exported 1 message')
    assert os.path.isfile(header)
