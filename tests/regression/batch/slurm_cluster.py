"""A single-node Slurm cluster run by a test as its own processes (no system services, nothing outside
its directory): munged with its own key and socket, slurmctld and slurmd in the foreground with a
generated slurm.conf, all in one temporary directory. Every daemon gets SIGTERM if the test process dies
(PR_SET_PDEATHSIG), and `with SlurmCluster(...)` stops them and removes the directory on any exit.
Every wait has a timeout.

    with SlurmCluster(cpus=4) as cluster:
        job = cluster.sbatch(["--time=1", "script.sh"], env=...)
        cluster.wait_gone(job, timeout=120)
"""
import ctypes
import os
import pwd
import shutil
import signal
import socket
import subprocess
import tempfile
import time

SLURM_BINARIES = ["munged", "slurmctld", "slurmd", "sbatch", "squeue", "scontrol", "srun"]
SBIN = ["/usr/sbin", "/usr/bin"]


def missing_binaries():
    """The Slurm and munge programs that cannot be found ([] when all are there)."""
    path = os.environ.get("PATH", "") + ":" + ":".join(SBIN)
    return [b for b in SLURM_BINARIES if shutil.which(b, path=path) is None]


def _die_with_parent():
    # PR_SET_PDEATHSIG = 1: the daemon gets SIGTERM when the test process ends, however it ends.
    ctypes.CDLL("libc.so.6", use_errno=True).prctl(1, signal.SIGTERM)
    os.setpgrp()  # its own process group: a ctest interrupt reaches the test, which stops the daemons


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class SlurmCluster:
    def __init__(self, cpus, keep=False):
        self.cpus = cpus
        self.user = pwd.getpwuid(os.getuid()).pw_name
        self.keep = keep
        self.dir = tempfile.mkdtemp(prefix="contessa-slurm-")
        os.chmod(self.dir, 0o700)  # munged refuses a key in a directory others may write
        self.daemons = []
        self.node = socket.gethostname().split(".")[0]
        self.env = dict(os.environ, SLURM_CONF=os.path.join(self.dir, "slurm.conf"))
        self.env["PATH"] = os.environ.get("PATH", "") + ":" + ":".join(SBIN)
        for var in [v for v in self.env if v.startswith(("SLURM_", "SBATCH_", "SRUN_", "SALLOC_"))]:
            if var != "SLURM_CONF":
                del self.env[var]  # a test run inside a job must not talk to that job's cluster

    # --- start and stop ---------------------------------------------------------------------------
    def __enter__(self):
        try:
            self._start_munge()
            self._write_conf()
            self._start("slurmctld", ["slurmctld", "-D", "-i", "-f", self.conf])
            self._wait(lambda: self._ok(["scontrol", "ping"]) and b"UP" in self._out(["scontrol", "ping"]),
                       30, "slurmctld to answer")
            self._start("slurmd", ["slurmd", "-D", "-f", self.conf, "-N", self.node])
            self._wait(lambda: b"idle" in self._out(["sinfo", "-h", "-o", "%t"]), 60, "the node to be idle")
        except BaseException:
            self.__exit__(None, None, None)
            raise
        return self

    def __exit__(self, *exc):
        # Jobs first (their steps outlive slurmd by design), then the daemons, then anything left that
        # belongs to this cluster.
        if any(name == "slurmctld" and proc.poll() is None for name, proc, _ in self.daemons):
            try:  # the cluster is this test's: all its jobs are
                subprocess.run(["scancel", "--user=" + self.user], env=self.env, capture_output=True, timeout=15)
            except (OSError, subprocess.TimeoutExpired):
                pass
        for name, proc, log in reversed(self.daemons):
            if proc.poll() is None:
                proc.terminate()
                try:
                    proc.wait(timeout=15)
                except subprocess.TimeoutExpired:
                    proc.kill()
                    proc.wait(timeout=5)
            log.close()
        self._kill_leftovers()
        if not self.keep:
            shutil.rmtree(self.dir, ignore_errors=True)
        return False

    def _kill_leftovers(self):
        """SIGKILL to every process of this cluster still there: slurmstepd, job scripts, srun and the
        job's tasks all carry this cluster's SLURM_CONF in their environment (no other process does)."""
        mark = ("SLURM_CONF=" + self.conf).encode() if hasattr(self, "conf") else None
        if mark is None:
            return
        for pid in os.listdir("/proc"):
            if not pid.isdigit() or int(pid) == os.getpid():
                continue
            try:
                with open(f"/proc/{pid}/environ", "rb") as f:
                    if mark in f.read().split(b"\0"):
                        os.kill(int(pid), signal.SIGKILL)
            except OSError:
                pass

    def _start(self, name, argv, env=None):
        log = open(os.path.join(self.dir, name + ".log"), "wb")
        proc = subprocess.Popen(argv, stdout=log, stderr=subprocess.STDOUT, env=env or self.env,
                                preexec_fn=_die_with_parent, cwd=self.dir)
        self.daemons.append((name, proc, log))
        return proc

    def _start_munge(self):
        d = self.dir
        self.munge_socket = os.path.join(d, "munge.socket")
        key = os.path.join(d, "munge.key")
        with open(key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(key, 0o400)
        self._start("munged", ["munged", "--foreground", "--force", "--socket=" + self.munge_socket,
                               "--key-file=" + key, "--pid-file=" + os.path.join(d, "munged.pid"),
                               "--log-file=" + os.path.join(d, "munged.log.internal"),
                               "--seed-file=" + os.path.join(d, "munged.seed")])
        self._wait(lambda: os.path.exists(self.munge_socket), 20, "munged's socket")

    def _write_conf(self):
        d = self.dir
        self.conf = os.path.join(d, "slurm.conf")
        for sub in ["state", "spool"]:
            os.makedirs(os.path.join(d, sub), exist_ok=True)
        self.user = user = pwd.getpwuid(os.getuid()).pw_name
        lines = f"""
ClusterName=contessa-test
SlurmctldHost={self.node}
SlurmctldPort={_free_port()}
SlurmdPort={_free_port()}
SlurmUser={user}
SlurmdUser={user}
AuthType=auth/munge
CredType=cred/munge
# A requeued job waits cred_expire seconds before it starts again (120 by default).
AuthInfo=socket={self.munge_socket},cred_expire=5
StateSaveLocation={d}/state
SlurmdSpoolDir={d}/spool
SlurmctldPidFile={d}/slurmctld.pid
SlurmdPidFile={d}/slurmd.pid
SlurmctldLogFile={d}/slurmctld.log.internal
SlurmdLogFile={d}/slurmd.log.internal
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
# The scheduler's periodic pass every 2 s (60 by default): a requeued job starts once its wait is over.
SchedulerParameters=sched_interval=2
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MailProg=/bin/true
ReturnToService=2
KillWait=10
MinJobAge=3600
InactiveLimit=0
SlurmdParameters=config_overrides
NodeName={self.node} CPUs={self.cpus} State=UNKNOWN
PartitionName=test Nodes={self.node} Default=YES MaxTime=INFINITE State=UP OverSubscribe=NO
"""
        with open(self.conf, "w") as f:
            f.write(lines.lstrip())

    # --- commands ---------------------------------------------------------------------------------
    def _out(self, argv, timeout=20):
        try:
            return subprocess.run(argv, capture_output=True, env=self.env, timeout=timeout).stdout
        except subprocess.TimeoutExpired:
            return b""

    def _ok(self, argv, timeout=20):
        try:
            return subprocess.run(argv, capture_output=True, env=self.env, timeout=timeout).returncode == 0
        except subprocess.TimeoutExpired:
            return False

    def _wait(self, ready, timeout, what):
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            for name, proc, _ in self.daemons:
                if proc.poll() is not None:
                    raise RuntimeError(f"{name} ended with status {proc.returncode} while waiting for {what}; "
                                       + self.daemon_logs())
            if ready():
                return
            time.sleep(0.5)
        raise RuntimeError(f"timed out after {timeout} s waiting for {what}; " + self.daemon_logs())

    def daemon_logs(self, tail=15):
        text = ""
        for name in ["munged", "slurmctld", "slurmd"]:
            for suffix in [".log", ".log.internal"]:
                path = os.path.join(self.dir, name + suffix)
                if os.path.exists(path):
                    lines = open(path, errors="replace").read().splitlines()[-tail:]
                    text += f"\n--- {name}{suffix} (last {len(lines)} lines)\n" + "\n".join(lines)
        return text

    def run(self, argv, timeout=30, env=None, cwd=None):
        """Runs a Slurm client command against this cluster; returns its CompletedProcess (text)."""
        return subprocess.run(argv, capture_output=True, text=True, env=dict(self.env, **(env or {})),
                              timeout=timeout, cwd=cwd)

    def sbatch(self, args, env=None, cwd=None):
        """Submits a batch job; returns its id."""
        r = self.run(["sbatch", "--parsable"] + args, env=env, cwd=cwd)
        if r.returncode != 0:
            raise RuntimeError(f"sbatch {' '.join(args)} failed: {r.stderr.strip()}")
        return r.stdout.strip().split(";")[0]

    def job(self, job_id):
        """The job's fields as scontrol shows them ({} once Slurm forgot it)."""
        r = self.run(["scontrol", "show", "job", "-o", job_id])
        fields = {}
        for word in r.stdout.split():
            if "=" in word:
                k, v = word.split("=", 1)
                fields.setdefault(k, v)
        return fields

    def wait(self, job_id, states, timeout):
        """Waits until the job is in one of `states` (e.g. {"RUNNING"}); returns its fields."""
        end = time.monotonic() + timeout
        fields = {}
        while time.monotonic() < end:
            fields = self.job(job_id)
            if fields.get("JobState") in states:
                return fields
            time.sleep(1)
        raise RuntimeError(f"timed out after {timeout} s waiting for job {job_id} to be {'/'.join(sorted(states))} "
                           f"(it is {fields.get('JobState')}, reason {fields.get('Reason')}); " + self.daemon_logs())
