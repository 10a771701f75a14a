"""A study as a job array on a real Slurm (Debian's slurm-wlm 22.05 with munge).

The test starts its own cluster on localhost from files it writes into a
temporary folder: munged on a private socket and key, one slurmctld and one
slurmd (NodeName=localhost, 2 CPUs) on two free ports, state and spool in the
folder, no cgroups (proctrack/linuxproc, task/none). For a study of each mode
it submits examples/slurm/study_array.sh -- the script docs/studies.md shows --
as an array of 3 tasks, each running one slice with `--shard slurm`, waits for
them, runs `proxsim study merge` and compares every file (the answers and the
report drawn from them) byte for byte with a single-process run's. The
daemons are stopped at the end, whatever happened.
If they cannot start, the test fails and says why: it is never skipped.
"""
import os
import signal
import socket
import subprocess
import tempfile
import time

import pytest

SOURCE_DIR = os.environ.get("PROXSIM_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("PROXSIM_BINARY", os.path.join(SOURCE_DIR, "build", "release", "proxsim"))
SCRIPT = os.path.join(SOURCE_DIR, "examples", "slurm", "study_array.sh")
DAEMONS = ("munged", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo", "scontrol")
START_TIMEOUT_S = 30
JOBS_TIMEOUT_S = 60


def free_ports(count):
    """`count` distinct ports free now (held open together, so none is given twice): the controller's and
    the node's, never the default 6817/6818 another Slurm on the machine may hold."""
    sockets = [socket.socket() for _ in range(count)]
    try:
        for s in sockets:
            s.bind(("127.0.0.1", 0))
        return [s.getsockname()[1] for s in sockets]
    finally:
        for s in sockets:
            s.close()


def tail(path, lines=15):
    try:
        with open(path, errors="replace") as f:
            return "".join(f.readlines()[-lines:])
    except OSError as error:
        return f"({error})"


class LocalSlurm:
    """munged + slurmctld + slurmd on localhost, all files in `root`."""

    def __init__(self, root):
        self.root = root
        self.pid_files = []
        self.logs = {}
        self.env = dict(os.environ, SLURM_CONF=os.path.join(root, "slurm.conf"))

    def _path(self, *parts):
        path = os.path.join(self.root, *parts)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        return path

    def fail(self, why):
        logs = "\n".join(f"--- {name} ({path}):\n{tail(path)}" for name, path in self.logs.items())
        pytest.fail(f"the local Slurm could not start: {why}\n{logs}", pytrace=False)

    def run(self, *command, check=True):
        result = subprocess.run(command, env=self.env, capture_output=True, text=True, timeout=30)
        if check and result.returncode != 0:
            self.fail(f"`{' '.join(command)}` exited {result.returncode}: {result.stderr.strip()}")
        return result

    def start(self):
        missing = [d for d in DAEMONS if subprocess.run(["sh", "-c", f"command -v {d} || test -x /usr/sbin/{d}"],
                                                          capture_output=True).returncode != 0]
        if missing:
            self.fail(f"{', '.join(missing)} not installed (scripts/install-deps.sh installs slurm-wlm and munge)")
        # munge: a key of our own, a private socket (root runs it: no other user to trust)
        key = self._path("munge", "munge.key")
        with open(key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(key, 0o400)
        socket_path = self._path("munge", "munge.socket")
        self.logs["munged"] = self._path("munge", "munged.log")
        self.pid_files.append(self._path("munge", "munged.pid"))
        self.run("/usr/sbin/munged", "--force", f"--socket={socket_path}", f"--key-file={key}",
                 f"--log-file={self.logs['munged']}", f"--pid-file={self.pid_files[-1]}",
                 f"--seed-file={self._path('munge', 'munged.seed')}")

        # slurm.conf: this host as the controller, localhost as the one node
        host = socket.gethostname().split(".")[0]
        self.logs["slurmctld"] = self._path("log", "slurmctld.log")
        self.logs["slurmd"] = self._path("log", "slurmd.log")
        controller_port, node_port = free_ports(2)
        config = {
            "ClusterName": "proxsimtest",
            "SlurmctldHost": f"{host}(127.0.0.1)",
            "SlurmUser": "root",
            "SlurmdUser": "root",
            "SlurmctldPort": controller_port,
            "SlurmdPort": node_port,
            "AuthType": "auth/munge",
            "CredType": "cred/munge",
            "AuthInfo": f"socket={socket_path}",
            "StateSaveLocation": os.path.dirname(self._path("state", "x")),
            "SlurmdSpoolDir": os.path.dirname(self._path("spool", "x")),
            "SlurmctldPidFile": self._path("slurmctld.pid"),
            "SlurmdPidFile": self._path("slurmd.pid"),
            "SlurmctldLogFile": self.logs["slurmctld"],
            "SlurmdLogFile": self.logs["slurmd"],
            "ProctrackType": "proctrack/linuxproc",
            "TaskPlugin": "task/none",
            "SelectType": "select/cons_tres",
            "SelectTypeParameters": "CR_Core",
            "SchedulerType": "sched/builtin",
            "JobCompType": "jobcomp/none",
            "AccountingStorageType": "accounting_storage/none",
            "MpiDefault": "none",
            "ReturnToService": 2,
        }
        lines = [f"{k}={v}" for k, v in config.items()]
        lines.append(f"NodeName=localhost NodeHostname={socket.gethostname()} NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN")
        lines.append("PartitionName=proxsim Nodes=localhost Default=YES MaxTime=INFINITE State=UP")
        with open(self.env["SLURM_CONF"], "w") as f:
            f.write("\n".join(lines) + "\n")

        conf = self.env["SLURM_CONF"]
        self.pid_files.append(config["SlurmctldPidFile"])
        self.run("/usr/sbin/slurmctld", "-f", conf)
        self.pid_files.append(config["SlurmdPidFile"])
        self.run("/usr/sbin/slurmd", "-f", conf, "-N", "localhost")

        # ready when the node is idle
        deadline = time.monotonic() + START_TIMEOUT_S
        state = ""
        while time.monotonic() < deadline:
            result = self.run("sinfo", "-h", "-N", "-o", "%t", check=False)
            state = (result.stdout or result.stderr).strip()
            if state == "idle":
                return
            time.sleep(0.5)
        self.fail(f"the node localhost was not idle within {START_TIMEOUT_S} s (sinfo: {state!r})")

    def stop(self):
        pids = []
        for pid_file in reversed(self.pid_files):  # slurmd, slurmctld, then munged
            try:
                with open(pid_file) as f:
                    pids.append(int(f.read().split()[0]))
            except (OSError, ValueError, IndexError):
                continue
        for pid in pids:
            try:
                os.kill(pid, signal.SIGTERM)
            except ProcessLookupError:
                pass
        deadline = time.monotonic() + 10
        for pid in pids:
            while time.monotonic() < deadline:
                try:
                    os.kill(pid, 0)
                except ProcessLookupError:
                    break
                time.sleep(0.1)
            else:
                try:
                    os.kill(pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass


@pytest.fixture(scope="module")
def slurm():
    root = tempfile.mkdtemp(prefix="proxsim_slurm_")
    cluster = LocalSlurm(root)
    try:
        cluster.start()
        yield cluster
    finally:
        cluster.stop()
        subprocess.run(["rm", "-rf", root])


# Small studies of both modes (seconds): 6 placement jobs (2 scenes x 3 seeds),
# 5 outcome worlds (an obstacle room with no way through, small generated rooms).
STUDIES = {
    "placement": """proxsim_study: 1
base: {scenarios}/paper_dining_room.yaml
candidates:
  axes: {{type: [laser, ultrasonic], link: left_tibia, along_m: [-0.35, -0.25], forward_m: 0.06, pitch_deg: 10}}
scenes:
  - {{name: obstacle_15cm, builtin: dining_room}}
  - {{name: obstacle_30cm, builtin: dining_room, obstacle: {{height_m: 0.30, x_m: 2.0}}}}
seeds: [1, 2, 3]
hazards: [obstacle]
select: {{sensors: 2}}
""",
    "outcomes": """proxsim_study: 1
mode: outcomes
base: {scenarios}/outcome_walker.yaml
sets:
  - {{name: upward, sensors: [{{name: up, type: laser, link: left_tibia, pose: {{xyz_m: [0.06, 0, -0.35], rpy_deg: [0, -80, 0]}}}}]}}
  - {{name: ahead, sensors: [{{name: ahead, type: laser, link: left_tibia, pose: {{xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 8, 0]}}}}]}}
prices: {{laser: {{price_usd: 10}}}}
strategies: [{{name: stop}}]
worlds:
  - {{name: obstacle_room, scenario: {scenarios}/circumvent_obstacle.yaml, seeds: [1, 2]}}
  - {{generate: {{kind: room, difficulty: 0.3, size_m: [4, 4]}}, seeds: [1, 2, 3]}}
""",
}
EXPECTED = {
    "placement": {"results.csv", "ranking.csv", "selection.json", "pareto.svg", "index.html"},
    "outcomes": {"results.csv", "ranking.csv", "pairs.csv", "selection.json", "failures.csv", "episodes.jsonl",
                 "success_by_set.svg", "index.html"},
}


def answers(folder):
    """{relative path: bytes} of a study's files but its journal (a single run's lines come in the order
    its jobs finished) and the lock."""
    files = {}
    for parent, _, names in os.walk(folder):
        for name in names:
            if name in ("journal.jsonl", ".proxsim.lock"):
                continue
            path = os.path.join(parent, name)
            with open(path, "rb") as f:
                files[os.path.relpath(path, folder)] = f.read()
    return files


@pytest.mark.parametrize("mode", ["placement", "outcomes"])
def test_a_job_array_of_three_slices_merges_to_the_single_runs_bytes(slurm, mode):
    started = time.monotonic()
    work = os.path.join(slurm.root, mode)
    os.makedirs(work)
    study = os.path.join(work, "study.yaml")
    with open(study, "w") as f:
        f.write(STUDIES[mode].format(scenarios=os.path.join(os.path.abspath(SOURCE_DIR), "data", "scenarios")))

    # the array: the script as docs/studies.md gives it, its tasks' environment carrying PROXSIM
    env = dict(slurm.env, PROXSIM=os.path.abspath(BINARY))
    submit = subprocess.run(["sbatch", "--parsable", "--array=1-3", f"--chdir={work}", SCRIPT, study, "slices"],
                            env=env, capture_output=True, text=True, timeout=30)
    assert submit.returncode == 0, submit.stderr
    array_id = submit.stdout.strip().split(";")[0]

    # waits until no task is pending or running
    deadline = time.monotonic() + JOBS_TIMEOUT_S
    while True:
        queue = slurm.run("squeue", "-h", "-j", array_id, "-o", "%i %T", check=False)
        if queue.returncode == 0 and not queue.stdout.strip():
            break
        assert time.monotonic() < deadline, f"the array was not done within {JOBS_TIMEOUT_S} s:\n{queue.stdout}"
        time.sleep(0.5)
    # every task completed with exit 0, as the controller saw it
    shown = slurm.run("scontrol", "-o", "show", "job", array_id).stdout.strip().splitlines()
    assert len(shown) == 3, shown
    for line in shown:
        fields = dict(item.split("=", 1) for item in line.split() if "=" in item)
        log = os.path.join(work, f"slurm-{array_id}_{fields['ArrayTaskId']}.out")
        assert fields["JobState"] == "COMPLETED" and fields["ExitCode"] == "0:0", f"{line}\n{tail(log)}"
        assert f"slice {fields['ArrayTaskId']}/3 done" in open(log).read(), tail(log)

    merged = os.path.join(work, "merged")
    slices = sorted(os.path.join(work, "slices", d) for d in os.listdir(os.path.join(work, "slices")))
    assert [os.path.basename(s) for s in slices] == ["slice-1", "slice-2", "slice-3"]
    merge = subprocess.run([BINARY, "study", "merge", *slices, "--out", merged],
                           capture_output=True, text=True, timeout=60)
    assert merge.returncode == 0, merge.stdout + merge.stderr

    single = os.path.join(work, "single")
    one = subprocess.run([BINARY, "study", study, "--out", single], capture_output=True, text=True, timeout=60)
    assert one.returncode == 0, one.stdout + one.stderr

    # the answers and the report drawn from them
    single_files, merged_files = answers(single), answers(merged)
    assert EXPECTED[mode] <= set(single_files), sorted(single_files)
    assert sorted(merged_files) == sorted(single_files)
    for name, content in single_files.items():
        assert merged_files[name] == content, f"{name} differs from the single run's"
    print(f"\n{mode} study, slurm job array {array_id}: 3 slices merged, {len(single_files)} files byte-identical "
          f"to one process's, {time.monotonic() - started:.1f} s")


def test_the_docs_show_the_script_the_array_runs():
    with open(SCRIPT) as f:
        script = f.read()
    with open(os.path.join(SOURCE_DIR, "docs", "studies.md")) as f:
        docs = f.read()
    assert script in docs, "docs/studies.md must show examples/slurm/study_array.sh as it is"
