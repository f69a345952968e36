"""A single-host SLURM cluster for tests and measurements: munged, slurmctld and slurmd on
this machine, started without systemd, every file (config, key, sockets, state, logs) in
one temporary directory, ports picked free. Needs root (slurmd runs jobs as their user)
and Debian's `slurm-wlm` and `munge` packages (scripts/setup.sh installs them).

    cluster = SingleHostCluster().start()     # raises ClusterUnavailable with the reason
    env = cluster.env()                       # SLURM_CONF for sbatch/squeue/scancel/sacct
    ...
    cluster.stop()

From a shell (for docs/cluster.md's measurements):
    /usr/bin/python3 tests/server/slurm_cluster.py up DIR     # prints export SLURM_CONF=...
    /usr/bin/python3 tests/server/slurm_cluster.py down DIR
"""

import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

DAEMONS = ("munged", "slurmctld", "slurmd")


class ClusterUnavailable(RuntimeError):
    """The daemons cannot run here; the message says why."""


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _memory_mb():
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith("MemTotal:"):
                return int(line.split()[1]) // 1024
    raise ClusterUnavailable("cannot read MemTotal from /proc/meminfo")


class SingleHostCluster:
    def __init__(self, directory=None, cpus=None, memory_mb=None):
        self.own_dir = directory is None
        self.dir = directory or tempfile.mkdtemp(prefix="slipfront-slurm-")
        self.cpus = cpus or os.cpu_count() or 1
        # What slurmd may hand out: most of the machine, leaving room for the OS.
        self.memory_mb = memory_mb or max(256, int(_memory_mb() * 0.8))
        self.node = socket.gethostname().split(".")[0]
        self.conf = os.path.join(self.dir, "slurm.conf")
        self.munge_socket = os.path.join(self.dir, "munge", "munge.socket")
        self.procs = {}
        self.logs = []

    # -- paths --------------------------------------------------------------------------
    def path(self, *parts):
        return os.path.join(self.dir, *parts)

    def env(self, base=None):
        env = dict(os.environ if base is None else base)
        env["SLURM_CONF"] = self.conf
        return env

    def log_tail(self, lines=30):
        out = []
        for name in DAEMONS:
            p = self.path("log", name + ".log")
            try:
                with open(p, errors="replace") as f:
                    tail = f.read().splitlines()[-lines:]
            except OSError:
                continue
            out.append(f"--- {name} ---\n" + "\n".join(tail))
        return "\n".join(out)

    # -- start / stop -------------------------------------------------------------------
    def start(self, timeout=30.0):
        try:
            self._check_tools()
        except ClusterUnavailable:
            self.stop()  # removes the temporary directory
            raise
        for sub in ("munge", "log", "state", "spool", "run"):
            os.makedirs(self.path(sub), exist_ok=True)
        os.chmod(self.path("munge"), 0o700)
        try:
            self._start_munge()
            self._write_config()
            self._start_slurm(timeout)
        except Exception:
            self.stop()
            raise
        return self

    def _check_tools(self):
        if os.geteuid() != 0:
            raise ClusterUnavailable("a single-host SLURM needs root (slurmd runs jobs as "
                                     "their user); run the tests as root")
        for tool in ("munged", "slurmctld", "slurmd", "sbatch", "squeue", "scancel", "scontrol"):
            if shutil.which(tool) is None and not os.path.exists("/usr/sbin/" + tool):
                raise ClusterUnavailable(f"{tool} not found: install Debian's slurm-wlm and "
                                         "munge (bash scripts/setup.sh)")

    def _sbin(self, name):
        return shutil.which(name) or "/usr/sbin/" + name

    def _start_munge(self):
        key = self.path("munge", "munge.key")
        with open(key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(key, 0o400)
        cmd = [self._sbin("munged"), "--foreground", "--force",
               f"--socket={self.munge_socket}", f"--key-file={key}",
               f"--pid-file={self.path('munge', 'munged.pid')}",
               f"--seed-file={self.path('munge', 'munged.seed')}",
               f"--log-file={self.path('log', 'munged.log')}"]
        self._spawn("munged", cmd)
        deadline = time.monotonic() + 10
        while not os.path.exists(self.munge_socket):
            if self.procs["munged"].poll() is not None or time.monotonic() > deadline:
                raise ClusterUnavailable("munged did not start:\n" + self.log_tail())
            time.sleep(0.05)

    def _write_config(self):
        ctld_port, slurmd_port = _free_port(), _free_port()
        conf = f"""# Generated by tests/server/slurm_cluster.py: a single-host cluster for tests.
ClusterName=slipfront-test
SlurmctldHost={self.node}(127.0.0.1)
SlurmctldPort={ctld_port}
SlurmdPort={slurmd_port}
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket={self.munge_socket}
StateSaveLocation={self.path('state')}
SlurmdSpoolDir={self.path('spool')}
SlurmctldPidFile={self.path('run', 'slurmctld.pid')}
SlurmdPidFile={self.path('run', 'slurmd.pid')}
SlurmctldLogFile={self.path('log', 'slurmctld.log')}
SlurmdLogFile={self.path('log', 'slurmd.log')}
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU_Memory
SchedulerType=sched/backfill
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
ReturnToService=2
MpiDefault=none
# The node may be declared with more CPUs than the machine has (tests: tiny jobs).
SlurmdParameters=config_overrides
DefMemPerCPU=256
SwitchType=switch/none
LaunchParameters=use_interactive_step
# Short cycles: a test waits seconds, not minutes.
SchedulerParameters=sched_interval=1,bf_interval=1
MinJobAge=600
KillWait=2
InactiveLimit=0
SlurmctldTimeout=30
SlurmdTimeout=30
MessageTimeout=10
NodeName={self.node} NodeAddr=127.0.0.1 CPUs={self.cpus} RealMemory={self.memory_mb} State=UNKNOWN
PartitionName=debug Nodes={self.node} Default=YES MaxTime=INFINITE State=UP
"""
        with open(self.conf, "w") as f:
            f.write(conf)

    def _spawn(self, name, cmd):
        log = open(self.path("log", name + ".out"), "ab")
        self.logs.append(log)
        self.procs[name] = subprocess.Popen(cmd, stdout=log, stderr=log, env=self.env(),
                                            start_new_session=True)

    def _start_slurm(self, timeout):
        self._spawn("slurmctld", [self._sbin("slurmctld"), "-D", "-i", "-f", self.conf])
        self._spawn("slurmd", [self._sbin("slurmd"), "-D", "-f", self.conf, "-N", self.node])
        self._wait_idle(timeout)

    def restart_controller(self, clear_state=False, timeout=30.0):
        """Stops slurmctld and starts it again; with `clear_state` it forgets every job
        (slurmctld -c): how a test makes SLURM lose a job."""
        proc = self.procs.pop("slurmctld")
        proc.send_signal(signal.SIGTERM)
        proc.wait(timeout=20)
        self._spawn("slurmctld", [self._sbin("slurmctld"), "-D", "-f", self.conf] +
                    (["-c"] if clear_state else ["-R"]))
        self._wait_idle(timeout)

    def _wait_idle(self, timeout):
        deadline = time.monotonic() + timeout
        last = ""
        while time.monotonic() < deadline:
            for name in ("slurmctld", "slurmd"):
                if self.procs[name].poll() is not None:
                    raise ClusterUnavailable(f"{name} exited with {self.procs[name].returncode}:"
                                             f"\n{self._daemon_output(name)}\n{self.log_tail()}")
            r = subprocess.run(["sinfo", "-h", "-N", "-o", "%T"], env=self.env(),
                               capture_output=True, text=True, timeout=10)
            last = (r.stdout + r.stderr).strip()
            if r.returncode == 0 and last in ("idle", "mixed", "allocated"):
                return
            time.sleep(0.3)
        raise ClusterUnavailable(f"the node did not become idle within {timeout} s (sinfo: "
                                 f"{last!r}):\n{self.log_tail()}")

    def _daemon_output(self, name):
        try:
            with open(self.path("log", name + ".out"), errors="replace") as f:
                return f.read()[-2000:]
        except OSError:
            return ""

    def stop(self):
        # Jobs first, so that no step outlives its slurmd.
        if "slurmctld" in self.procs and self.procs["slurmctld"].poll() is None:
            subprocess.run(["scancel", "--full", "--user", "root"], env=self.env(),
                           capture_output=True, timeout=10)
        for name in reversed(DAEMONS):
            proc = self.procs.get(name)
            if proc is None or proc.poll() is not None:
                continue
            proc.send_signal(signal.SIGTERM)
            try:
                proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait(timeout=5)
        self.procs.clear()
        for log in self.logs:
            log.close()
        self.logs.clear()
        if self.own_dir:
            shutil.rmtree(self.dir, ignore_errors=True)


def _main(argv):
    if len(argv) != 3 or argv[1] not in ("up", "down"):
        print(__doc__, file=sys.stderr)
        return 2
    directory = os.path.abspath(argv[2])
    if argv[1] == "up":
        os.makedirs(directory, exist_ok=True)
        cluster = SingleHostCluster(directory).start()
        for name, proc in cluster.procs.items():
            with open(cluster.path("run", name + ".pgid"), "w") as f:
                f.write(str(proc.pid))
        print(f"export SLURM_CONF={cluster.conf}")
        return 0
    for name in reversed(DAEMONS):
        try:
            with open(os.path.join(directory, "run", name + ".pgid")) as f:
                os.killpg(int(f.read()), signal.SIGTERM)
        except (OSError, ValueError):
            pass
    return 0


if __name__ == "__main__":
    sys.exit(_main(sys.argv))
