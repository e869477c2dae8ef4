"""Real ROS processes for the mROS v1 tests, the evaluation and the benchmark:
a rosmaster on a free 127.0.0.1 port, nodes started in their own process
groups with their output captured line by line, and a RosGraph context that
stops every process it started (SIGINT, then SIGKILL to the whole group),
also when the code using it fails."""

import os
import re
import signal
import socket
import subprocess
import tempfile
import threading
import time
import xmlrpc.client

# A shell that starts a command in the background (`cmd &`, as some CI
# runners and nohup do) makes it ignore SIGINT, and its children inherit
# that: every node would then sit out stop()'s grace period before SIGKILL
# (the suite takes half again as long) and no node would stop the way it does
# for a user's Ctrl-C. A handled signal is reset to the default in a child.
if signal.getsignal(signal.SIGINT) == signal.SIG_IGN:
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
                if remaining <= 0 or (self.popen.poll() is not None and not self._reader.is_alive()):
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
        self.port = free_port()
        self.uri = 'http://127.0.0.1:%d/' % self.port
        self._home = tempfile.TemporaryDirectory(prefix='ros_home_')
        env = dict(base_env if base_env is not None else os.environ)
        env.update(ROS_MASTER_URI=self.uri, ROS_IP='127.0.0.1', ROS_HOME=self._home.name,
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
