# SPDX-License-Identifier: BSD-3-Clause
"""SIGKILL during an export: the output is the complete old or the complete
new export, and the next run leaves no temporary behind.

Kills land at random times across many runs, and at fixed phases through a
launcher that wraps genmros' own functions in this test's process (nothing
in the product waits for or looks at a test): while rendering, while the new
tree is written beside the old, just before and just after the exchange,
and, in generator mode, between writing temporaries and renaming them.
"""

import os
import random
import shutil
import signal
import subprocess
import sys
import time

import pytest

from support.checkout import REPO, run_genmros
from support.file_trees import package_xml, snapshot, write_tree
from testing.ros_paths import prefix_arguments, ros1_prefixes

TYPES = 40
KILLS = 30

LAUNCHER = '''
import os, signal, sys
import colcon_mros.core.output as output
import colcon_mros.mros_v1.render as render
from colcon_mros.cli import main

def die():
    os.kill(os.getpid(), signal.SIGKILL)

def on_call(count, function, after=False):
    calls = [0]
    def wrapper(*arguments, **keywords):
        calls[0] += 1
        if calls[0] == count and not after:
            die()
        result = function(*arguments, **keywords)
        if calls[0] == count:
            die()
        return result
    return wrapper

phase = sys.argv[1]
if phase == 'rendering':
    render.Renderer.message = on_call(5, render.Renderer.message)
elif phase == 'linking-unchanged':
    os.link = on_call(3, os.link)
elif phase == 'writing-changed':
    os.chmod = on_call(6, os.chmod)
elif phase == 'before-exchange':
    output._exchange = on_call(1, output._exchange)
elif phase == 'after-exchange':
    output._exchange = on_call(1, output._exchange, after=True)
elif phase == 'between-renames':
    os.replace = on_call(2, os.replace)
sys.exit(main(sys.argv[2:]))
'''


def _sources(version):
    """Package kill_ws at a version: every type changes, one goes, one comes."""
    files = {'package.xml': package_xml('kill_ws')}
    for index in range(TYPES):
        if version == 'new' and index == 0:
            continue
        files['msg/T%d.msg' % index] = ('std_msgs/Header header\ngeometry_msgs/Pose pose\n'
                                        'int32 %s%d\n' % (version, index))
    if version == 'new':
        files['msg/Added.msg'] = 'T1 t\n'
    return files


def _contents(root):
    return {relative: content for relative, (content, _) in snapshot(root).items()}


def _temporaries(root):
    found = []
    for directory, subdirectories, names in os.walk(root):
        found.extend(os.path.join(directory, n)
                     for n in names + subdirectories if '.genmros-' in n)
    return found


@pytest.fixture(scope='module')
def exports(tmp_path_factory):
    """The old and new exports of kill_ws, and a workspace holding the new sources."""
    root = tmp_path_factory.mktemp('kill')
    states = {}
    for version in ('old', 'new'):
        workspace = root / version / 'ws'
        write_tree(str(workspace / 'src' / 'kill_ws'), _sources(version))
        output = str(root / version / 'out')
        run_genmros('mros-v1-export', '--workspace', str(workspace), '-o', output,
                    *prefix_arguments(ros1_prefixes()))
        states[version] = output
    return str(root / 'new' / 'ws'), states['old'], states['new']


def _export_arguments(workspace, output):
    return ['mros-v1-export', '--workspace', workspace, '-o', output,
            *prefix_arguments(ros1_prefixes())]


def _median_duration(workspace, old, tmp_path):
    """Seconds one export of the new sources over the old export takes here, median of three."""
    durations = []
    for run in range(3):
        started = time.monotonic()
        run_genmros(*_export_arguments(workspace,
                    shutil.copytree(old, str(tmp_path / ('timing%d' % run)))))
        durations.append(time.monotonic() - started)
    return sorted(durations)[1]


def test_random_kills_leave_old_or_new(exports, tmp_path):
    workspace, old, new = exports
    old_state, new_state = _contents(old), _contents(new)
    assert old_state != new_state
    duration = _median_duration(workspace, old, tmp_path)
    randomness = random.Random(10)
    outcomes = {'old': 0, 'new': 0}
    killed_while_running = 0
    for attempt in range(KILLS):
        output = shutil.copytree(old, str(tmp_path / ('out%d' % attempt)))
        process = subprocess.Popen([sys.executable, '-m', 'colcon_mros']
                                   + _export_arguments(workspace, output),
                                   cwd=REPO, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        # A sweep from early in the run to past its usual end, so that one slow
        # or fast timing run cannot put every kill on one side of the exchange.
        time.sleep((0.3 + 0.9 * attempt / (KILLS - 1)) * duration * randomness.uniform(0.95, 1.05))
        killed_while_running += process.poll() is None
        process.send_signal(signal.SIGKILL)
        process.wait()
        state = _contents(output)
        assert state in (old_state, new_state), 'mixed export after a kill at attempt %d' % attempt
        outcomes['old' if state == old_state else 'new'] += 1
        run_genmros(*_export_arguments(workspace, output))
        assert _contents(output) == new_state
        assert _temporaries(str(tmp_path)) == []
        shutil.rmtree(output)
    assert outcomes['old'] > 0 and outcomes['new'] > 0, outcomes
    # Most kills hit a running export (the rest make sure of a "new").
    assert killed_while_running >= KILLS // 3, killed_while_running


@pytest.mark.parametrize('phase, expected', [
    ('rendering', 'old'), ('linking-unchanged',
                           'old'), ('writing-changed', 'old'), ('before-exchange', 'old'),
    ('after-exchange', 'new')])
def test_kill_at_each_phase_of_an_export(exports, tmp_path, phase, expected):
    workspace, old, new = exports
    output = shutil.copytree(old, str(tmp_path / 'out'))
    result = subprocess.run([sys.executable, '-c', LAUNCHER, phase]
                            + _export_arguments(workspace, output),
                            cwd=REPO, capture_output=True, text=True)
    assert result.returncode == -signal.SIGKILL, result.stderr
    assert _contents(output) == _contents(old if expected == 'old' else new)
    if phase != 'rendering':
        # The kill left the tree it was building (or the old one) beside the output.
        assert _temporaries(str(tmp_path)) != []
    run_genmros(*_export_arguments(workspace, output))
    assert _contents(output) == _contents(new)
    assert _temporaries(str(tmp_path)) == []


def test_generator_mode_kill_between_renames_leaves_no_temporary(tmp_path):
    package = str(tmp_path / 'src' / 'kill_ws')
    write_tree(package, {'package.xml': package_xml('kill_ws'),
               'srv/Ask.srv': 'int32 a\n---\nint32 b\n'})
    output = str(tmp_path / 'include' / 'kill_ws')
    arguments = ['generate', os.path.join(
        package, 'srv', 'Ask.srv'), '-p', 'kill_ws', '-o', output]
    result = subprocess.run([sys.executable, '-c', LAUNCHER, 'between-renames'] + arguments,
                            cwd=REPO, capture_output=True, text=True)
    assert result.returncode == -signal.SIGKILL, result.stderr
    assert len(_temporaries(output)) == 2  # the first of three headers was renamed
    run_genmros(*arguments)
    assert _temporaries(str(tmp_path)) == []
    assert sorted(os.listdir(output)) == ['Ask.h', 'AskRequest.h', 'AskResponse.h']
