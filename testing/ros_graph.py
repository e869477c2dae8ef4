# SPDX-License-Identifier: BSD-3-Clause
"""A ROS graph on this machine for apps the PC target built: run an mROS v1
app beside real ROS nodes, as it will run on the board beside them.

- :class:`RosGraph`: a rosmaster on a free 127.0.0.1 port and the processes
  started against it, each in its own process group with its output kept
  line by line; leaving the context stops every one (SIGINT, then SIGKILL to
  the whole group), also when the code using it fails.
- :class:`Board`: an app of the PC target in that graph, at its own loopback
  address with free slave and publisher ports (the library ignores
  publishers at its own address, and roscpp with a loopback ROS_IP takes
  TCPROS connections on 127.0.0.1 only), its pins in files (the mbed
  stand-in's ``MROS_PC_INPUTS`` and ``MROS_PC_OUTPUT_LOG``).
- :class:`CatkinWorkspace`: the ROS nodes of a catkin workspace, built with
  catkin_make.

The paper's evaluation, the tests and the benchmarks run apps this way;
only the standard library and ROS' own programs are used.
"""

import os
import re
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
import xmlrpc.client

BOARD_IP = '127.0.0.2'
# The task stack report the arm target prints when stopped and on SIGUSR1
# (asp/task_stacks.c): its heading, then a line per task.
_STACK_REPORT = 'mROS PC target: task stacks'
_STACK_LINE = re.compile(r'^  (\w+) +(\d+|-) of +(\d+) bytes +(?:\d+%|\(never ran\))$')
PEER_IP = '127.0.0.1'
# How long a message may take through qemu, the library's 100 ms polling
# and a loaded machine.
DELIVERY_TIMEOUT = 30
# The Python of the ROS environment: the one running the tests, the bench or
# the main job (their scripts run them with the Python that has rospy).
PYTHON = sys.executable


def let_children_stop_on_sigint():
    """A shell that starts a command in the background (`cmd &`, as some CI
    runners and nohup do) makes it ignore SIGINT, and its children inherit
    that: every node would then sit out stop()'s grace period before SIGKILL,
    and a genmros stopped as a user's Ctrl-C stops it would go on. A handled
    signal is reset to the default in a child."""
    if (signal.getsignal(signal.SIGINT) == signal.SIG_IGN
            and threading.current_thread() is threading.main_thread()):
        signal.signal(signal.SIGINT, signal.default_int_handler)


def free_port():
    """A TCP port that is free on 127.0.0.1 right now."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as probe:
        probe.bind(('127.0.0.1', 0))
        return probe.getsockname()[1]


def sourced_environment(setup_bash):
    """The environment after `source setup_bash` (a catkin devel space)."""
    output = subprocess.run(['bash', '-c', 'source "$0" && env -0', setup_bash],
                            check=True, capture_output=True).stdout
    return dict(item.split('=', 1) for item in output.decode().split('\0') if '=' in item)


class Process:
    """A started process whose merged stdout/stderr is collected as lines."""

    def __init__(self, name, argv, env, interactive=False):
        self.name = name
        self.argv = argv
        self._lines = []
        self._changed = threading.Condition()
        self.popen = subprocess.Popen(argv, env=env, stdout=subprocess.PIPE,
                                      stderr=subprocess.STDOUT,
                                      stdin=subprocess.PIPE if interactive else subprocess.DEVNULL,
                                      start_new_session=True)
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self):
        for raw in self.popen.stdout:
            with self._changed:
                self._lines.append(raw.decode(errors='replace').rstrip('\n'))
                self._changed.notify_all()
        with self._changed:
            self._changed.notify_all()

    def type(self, text):
        """Writes text to the standard input of an interactive process."""
        self.popen.stdin.write(text.encode())
        self.popen.stdin.flush()

    def lines(self):
        with self._changed:
            return list(self._lines)

    def output(self):
        return '\n'.join(self.lines())

    def wait_for(self, pattern, timeout=15.0, start=0, count=1):
        """The first `count` matches of regex pattern in lines[start:]; raises
        AssertionError with the output if they do not appear in time."""
        regex = re.compile(pattern)
        deadline = time.monotonic() + timeout
        with self._changed:
            while True:
                matches = [m for m in map(regex.search, self._lines[start:]) if m]
                if len(matches) >= count:
                    return matches[:count]
                remaining = deadline - time.monotonic()
                if remaining <= 0 or (self.popen.poll() is not None
                                      and not self._reader.is_alive()):
                    raise AssertionError('%s: no %d line(s) matching %r within %.0f s; output:\n%s'
                                         % (self.name, count, pattern, timeout, self.output()))
                self._changed.wait(min(remaining, 0.1))

    def alive(self):
        return self.popen.poll() is None

    def stop(self, sig=signal.SIGINT, timeout=5.0):
        """Signals the process group and waits; kills it if it lingers.
        Returns the exit status."""
        if self.popen.poll() is None:
            try:
                os.killpg(self.popen.pid, sig)
                self.popen.wait(timeout)
            except subprocess.TimeoutExpired:
                pass
        if self.popen.poll() is None:
            self.kill()
        self._reader.join(2)
        return self.popen.returncode

    def kill(self):
        try:
            os.killpg(self.popen.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        self.popen.wait()


class RosGraph:
    """A rosmaster on a free loopback port and the nodes started against it.

    with RosGraph(base_env) as graph:
        node = graph.start('talker', [...])
    """

    def __init__(self, base_env=None):
        let_children_stop_on_sigint()
        self.port = free_port()
        self.uri = 'http://127.0.0.1:%d/' % self.port
        self._home = tempfile.TemporaryDirectory(prefix='ros_home_')
        env = dict(base_env if base_env is not None else os.environ)
        env.update(ROS_MASTER_URI=self.uri, ROS_IP=PEER_IP, ROS_HOME=self._home.name,
                   ROS_LOG_DIR=os.path.join(self._home.name, 'log'), PYTHONUNBUFFERED='1')
        env.pop('ROS_HOSTNAME', None)
        self.env = env
        self.processes = []
        self.master = None

    def __enter__(self):
        try:
            self.master = self.start('rosmaster', ['rosmaster', '--core', '-p', str(self.port)])
            self._wait_for_master()
        except BaseException:
            self.stop_all()
            raise
        return self

    def __exit__(self, *exc_info):
        self.stop_all()

    def start(self, name, argv, extra_env=None, interactive=False):
        """Starts argv as node `name`, with extra_env added to the graph's
        environment (and a standard input to type into if interactive)."""
        process = Process(name, argv, dict(self.env, **(extra_env or {})), interactive)
        self.processes.append(process)
        return process

    def stop_all(self):
        for process in reversed(self.processes):
            process.stop()
        self._home.cleanup()

    def master_proxy(self):
        return xmlrpc.client.ServerProxy(self.uri)

    def _wait_for_master(self, timeout=15.0):
        deadline = time.monotonic() + timeout
        while True:
            try:
                code, _, _ = self.master_proxy().getSystemState('/test')
                if code == 1:
                    return
            except OSError:
                pass
            if time.monotonic() > deadline or not self.master.alive():
                raise AssertionError('rosmaster did not come up:\n' + self.master.output())
            time.sleep(0.1)

    def system_state(self):
        """(publishers, subscribers) as {topic: set(node names)}."""
        code, message, (publishers, subscribers, _) = self.master_proxy().getSystemState('/test')
        assert code == 1, message
        return ({topic: set(nodes) for topic, nodes in publishers},
                {topic: set(nodes) for topic, nodes in subscribers})

    def wait_for_graph(self, publishers=None, subscribers=None, timeout=15.0):
        """Waits until every (topic, node) pair given is registered."""
        deadline = time.monotonic() + timeout
        while True:
            current = self.system_state()
            missing = [(topic, node) for wanted, have in zip((publishers, subscribers), current)
                       for topic, node in (wanted or [])
                       if node not in have.get(topic, set())]
            if not missing:
                return
            if time.monotonic() > deadline:
                raise AssertionError('not registered at the master: %r' % missing)
            time.sleep(0.1)


def board_environment():
    """The environment of an app on the PC target beside this machine's ROS
    nodes: its own address and free slave and publisher ports."""
    return {'ROS_IP': BOARD_IP, 'MROS_V1_SLAVE_PORT': str(free_port()),
            'MROS_V1_PUBLISHER_PORT': str(free_port())}


class Board:
    """An app on the PC target in a ROS graph: its log, its pins.

    runner: what runs the program (qemu-arm for the arm target, nothing for
    native); inputs: the pins' levels at start."""

    def __init__(self, graph, program, directory, runner=('qemu-arm',), inputs=None):
        self.inputs = os.path.join(directory, 'inputs')
        self.outputs = os.path.join(directory, 'outputs')
        self.set_inputs(**(inputs or {'P6_0': 1}))
        environment = board_environment()
        self.slave_port = int(environment['MROS_V1_SLAVE_PORT'])
        self.publisher_port = int(environment['MROS_V1_PUBLISHER_PORT'])
        environment.update(MROS_PC_INPUTS=self.inputs, MROS_PC_OUTPUT_LOG=self.outputs)
        self.process = graph.start(os.path.basename(program), list(runner) + [program],
                                   environment)

    def set_inputs(self, **pins):
        with open(self.inputs + '.new', 'w') as stream:
            stream.writelines('%s %d\n' % item for item in sorted(pins.items()))
        os.replace(self.inputs + '.new', self.inputs)

    def output_lines(self):
        if not os.path.exists(self.outputs):
            return []
        with open(self.outputs) as stream:
            return stream.read().splitlines()

    def wait_for_output(self, line, timeout=DELIVERY_TIMEOUT):
        """Waits until the app writes line to an output pin; raises
        AssertionError with its outputs and log if it does not in time."""
        deadline = time.monotonic() + timeout
        while line not in self.output_lines():
            if time.monotonic() > deadline:
                raise AssertionError('no output %r; outputs: %s; log:\n%s' % (
                    line, self.output_lines()[-20:], self.process.output()))
            time.sleep(0.1)

    @property
    def slave_uri(self):
        return 'http://%s:%d/' % (BOARD_IP, self.slave_port)

    def stack_reports(self):
        """Every task stack report in the app's log so far, in order: each
        {task: (peak bytes, or None if it never ran; size)}."""
        reports = []
        for line in self.process.lines():
            if line.startswith(_STACK_REPORT):
                reports.append({})
                continue
            match = _STACK_LINE.match(line) if reports else None
            if match:
                peak = None if match.group(2) == '-' else int(match.group(2))
                reports[-1][match.group(1)] = (peak, int(match.group(3)))
        return reports


class CatkinWorkspace:
    """A catkin workspace at root (its packages in root/src) and the
    commands of the nodes of one of its packages."""

    def __init__(self, root, package):
        self.root = root
        self.setup_bash = os.path.join(root, 'devel', 'setup.bash')
        self.mros_export = os.path.join(root, 'mros_export')
        self.lib = os.path.join(root, 'devel', 'lib', package)
        self.scripts = os.path.join(root, 'src', package, 'scripts')

    def build(self, log_path, *cmake_arguments, environment=None):
        """catkin_make with Debian's Python and genmros' export into
        mros_export/, in environment (default: this process's); raises
        RuntimeError with the log's end if it fails."""
        argv = ['catkin_make', '-C', self.root, '-DPYTHON_EXECUTABLE=' + PYTHON,
                '-DMROS_EXPORT_DIR=' + self.mros_export] + list(cmake_arguments)
        with open(log_path, 'w') as log:
            result = subprocess.run(argv, stdout=log, stderr=subprocess.STDOUT, cwd=self.root,
                                    env=environment)
        if result.returncode != 0:
            with open(log_path) as log:
                raise RuntimeError('%s failed:\n%s' % (' '.join(argv), log.read()[-6000:]))
        return self

    def environment(self):
        """The environment after sourcing the devel space's setup.bash."""
        return sourced_environment(self.setup_bash)

    def roscpp(self, node, *arguments):
        return [os.path.join(self.lib, node)] + list(arguments)

    def rospy(self, script, *arguments):
        return [PYTHON, os.path.join(self.scripts, script)] + list(arguments)
