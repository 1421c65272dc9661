"""The workflow on a real one-node SLURM: Debian's slurm-wlm and munge, started here, torn down after.

munged, slurmctld and slurmd run on localhost from a slurm.conf written below (this machine's
CPUs and memory as `slurmd -C` reports them). No cgroups are needed: processes are tracked by
proctrack/linuxproc, and a job's memory request is enforced by jobacct_gather/linux sampling every
second with OverMemoryKill. There is no accounting database (sacct needs slurmdbd): the profile
asks the SLURM executor to follow jobs with squeue (MinJobAge keeps finished jobs visible), and
jobcomp/filetxt writes one line per finished job, which is what the tests read back.

The executor plugin's jobstep strips SLURM_CONF from the environment of the `srun` it runs inside
each job, so the configuration lives where SLURM looks by default, /etc/slurm/slurm.conf; the test
skips rather than overwrite one that is already there, and removes its own afterwards.

Needs root (slurmd starts jobs as their user), the Debian packages and the `cluster` extra;
skips with the reason otherwise.
"""

import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

pytestmark = [pytest.mark.slurm, pytest.mark.workflow]

SLURM_CONF = Path("/etc/slurm/slurm.conf")
PROFILE = "workflow/profiles/slurm"
#: A subset with every kind of rule: a measured spectrum exported (Cu, which Fig. 4 reads), one
#: derived from a Munsell notation (RedPigment, which the spheres read), an analytic figure and a
#: render. The copies start without those two spectra, so all four rules run.
REMOVED_SPECTRA = ["spectra/Cu.csv", "spectra/RedPigment.csv"]
TARGETS = ["results/cook_torrance_1982/fig4.csv", "results/article/spheres.png"]
RULES = {"export_spectrum", "derive_spectrum", "ct82_fig4", "article_spheres"}


def _why_not():
    """Why SLURM cannot be started here, or None."""
    missing = [b for b in ("munged", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo")
               if shutil.which(b) is None]
    if missing:
        return f"SLURM binaries absent ({', '.join(missing)}): apt-get install slurm-wlm munge"
    try:
        import snakemake_executor_plugin_slurm  # noqa: F401
    except ImportError:
        return "snakemake-executor-plugin-slurm absent: pip install -e '.[cluster]'"
    if os.geteuid() != 0:
        return "slurmd must run as root to start jobs"
    if SLURM_CONF.exists():
        return f"{SLURM_CONF} exists (a real SLURM installation?); not overwritten"
    return None


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _node_line():
    """`slurmd -C`'s NodeName line (this machine's CPUs, sockets, cores and RealMemory)."""
    out = subprocess.run(["slurmd", "-C"], capture_output=True, text=True, check=True).stdout
    return next(line for line in out.splitlines() if line.startswith("NodeName="))


def _slurm_conf(d, host, node):
    return f"""\
# Written by tests/test_slurm.py: a one-node SLURM on localhost, state under {d}
ClusterName=reflectance
SlurmctldHost={host}(127.0.0.1)
SlurmctldPort={_free_port()}
SlurmdPort={_free_port()}
SlurmUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket={d}/munge/munge.sock
StateSaveLocation={d}/state
SlurmdSpoolDir={d}/spool
SlurmctldPidFile={d}/slurmctld.pid
SlurmdPidFile={d}/slurmd.pid
SlurmctldLogFile={d}/log/slurmctld.log
SlurmdLogFile={d}/log/slurmd.log
MailProg=/bin/true
# no cgroups: processes tracked by their parentage; memory enforced by sampling the step's RSS
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
JobAcctGatherType=jobacct_gather/linux
JobAcctGatherFrequency=task=1
JobAcctGatherParams=OverMemoryKill
# no slurmdbd: squeue follows the jobs (finished ones stay 10 min), jobcomp records them
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc={d}/log/jobcomp.txt
MinJobAge=600
ReturnToService=2
MpiDefault=none
{node} NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
"""


def _run(*cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=60, **kw)


@pytest.fixture(scope="module")
def slurm(tmp_path_factory):
    """Start munged, slurmctld and slurmd; yield the jobcomp file; stop them all and clean up."""
    reason = _why_not()
    if reason:
        pytest.skip(reason)
    d = tmp_path_factory.mktemp("slurm")
    for sub in ("state", "spool", "log", "munge"):
        (d / sub).mkdir()
    (d / "munge").chmod(0o711)
    key = d / "munge" / "munge.key"
    key.write_bytes(os.urandom(128))
    key.chmod(0o600)
    SLURM_CONF.parent.mkdir(parents=True, exist_ok=True)
    SLURM_CONF.write_text(_slurm_conf(d, socket.gethostname().split(".")[0], _node_line()))
    daemons = []

    def start(*cmd):
        log = open(d / "log" / f"{Path(cmd[0]).name}.out", "w")
        daemons.append(subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT,
                                        start_new_session=True))

    try:
        start("munged", "-F", "-f", f"--key-file={key}", f"--socket={d}/munge/munge.sock",
              f"--pid-file={d}/munge/munged.pid", f"--log-file={d}/munge/munged.log",
              f"--seed-file={d}/munge/munged.seed")
        for _ in range(50):
            if (d / "munge" / "munge.sock").exists():
                break
            time.sleep(0.2)
        start("slurmctld", "-D", "-f", str(SLURM_CONF))
        start("slurmd", "-D", "-f", str(SLURM_CONF))
        state = ""
        for _ in range(120):
            state = _run("sinfo", "-h", "-N", "-o", "%T").stdout.strip()
            if state == "idle":
                break
            if any(p.poll() is not None for p in daemons):
                break
            time.sleep(0.5)
        if state != "idle":
            logs = "\n".join(f.read_text()[-2000:] for f in sorted((d / "log").glob("*")))
            pytest.fail(f"SLURM did not come up (node state {state!r}):\n{logs}")
        yield d / "log" / "jobcomp.txt"
    finally:
        _run("scancel", "--user", "root")
        for proc in reversed(daemons):  # slurmd, slurmctld, munged: each in its own session
            if proc.poll() is None:
                os.killpg(proc.pid, signal.SIGTERM)
                try:
                    proc.wait(timeout=30)
                except subprocess.TimeoutExpired:
                    os.killpg(proc.pid, signal.SIGKILL)
                    proc.wait(timeout=10)
        SLURM_CONF.unlink(missing_ok=True)
        left = [p.pid for p in daemons if _session_alive(p.pid)]
        assert not left, f"SLURM daemons still running after teardown: {left}"


def _session_alive(sid):
    """Whether any process is left in the session a daemon started."""
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                if os.getsid(int(entry.name)) == sid:
                    return True
            except ProcessLookupError:
                continue
    return False


def _workdir(root, path, removed=()):
    path.mkdir()
    for name in ("Snakefile", "config.yaml"):
        shutil.copy(root / name, path / name)
    # Fresh modification times, the spectra newest: Snakemake would otherwise rebuild every
    # spectrum whose script is newer than the committed CSV (as on a fresh checkout).
    for name in ("workflow", "spectra"):
        shutil.copytree(root / name, path / name, ignore=shutil.ignore_patterns("__pycache__"),
                        copy_function=shutil.copy)
    for name in removed:
        (path / name).unlink()
    return path


def _snakemake(cwd, *args, ok=True):
    proc = subprocess.run([sys.executable, "-m", "snakemake", *args], cwd=cwd,
                          capture_output=True, text=True, timeout=1500)
    out = proc.stdout + proc.stderr
    assert (proc.returncode == 0) == ok, out
    return out


def _jobcomp(path):
    """jobcomp/filetxt's records: {job id: {field: value}}."""
    records = {}
    for line in path.read_text().splitlines():
        fields = dict(re.findall(r"(\w+)=(\S*)", line))
        records[fields["JobId"]] = fields
    return records


def _submitted(out):
    """Snakemake's own account of a run: [(rule, its resources and threads, SLURM job id)]."""
    blocks = {}
    for rule, body in re.findall(r"^rule (\w+):\n((?:    .*\n)+)", out, flags=re.M):
        info = dict(re.findall(r"^    (\w+): (.*)$", body, flags=re.M))
        resources = dict(re.findall(r"(\w+)=([^,]+)", info["resources"]))
        blocks[info["jobid"]] = (rule, resources, int(info.get("threads", 1)))
    return [blocks[job] + (slurm_id,) for job, slurm_id in
            re.findall(r"^Job (\d+) has been submitted with SLURM jobid (\d+)", out, flags=re.M)]


def _outputs(cwd):
    files = [cwd / name for name in REMOVED_SPECTRA] + sorted((cwd / "results").rglob("*"))
    return {str(f.relative_to(cwd)): f.read_bytes() for f in files if f.is_file()}


def test_every_job_is_a_slurm_job_with_the_rules_resources_and_the_local_result(
        slurm, root, tmp_path):
    local = _workdir(root, tmp_path / "local", REMOVED_SPECTRA)
    cluster = _workdir(root, tmp_path / "cluster", REMOVED_SPECTRA)
    _snakemake(local, "--cores", "2", *TARGETS)
    out = _snakemake(cluster, "--profile", PROFILE, *TARGETS)

    jobs = _submitted(out)
    assert {rule for rule, *_ in jobs} == RULES, out
    assert len(jobs) == 4, out
    records = _jobcomp(slurm)
    default_mem = "2000"  # the profile's default-resources: every rule here declares its own
    for rule, resources, threads, slurm_id in jobs:
        record = records[slurm_id]
        assert record["JobState"] == "COMPLETED", (rule, record)
        assert resources["mem_mb"] != default_mem, (rule, resources)
        assert f"mem={resources['mem_mb']}M" in record["Tres"].split(","), (rule, record)
        assert record["TimeLimit"] == resources["runtime"], (rule, record)
        assert record["ProcCnt"] == str(threads), (rule, record)
        assert record["Partition"] == "debug", record  # slurm.conf's default partition

    local_files, cluster_files = _outputs(local), _outputs(cluster)
    assert set(local_files) == set(cluster_files)
    assert len(local_files) >= 2 + 3 + 5  # two spectra, Fig. 4 (csv, png, pdf), the spheres
    assert [f for f in local_files if local_files[f] != cluster_files[f]] == []


def test_a_job_over_its_memory_request_is_killed_and_a_larger_request_completes(
        slurm, root, tmp_path):
    cwd = _workdir(root, tmp_path / "memory")
    target = "results/cook_torrance_1982/fig4.csv"
    # 200 MB: less than the Snakemake process that runs the job inside it needs (~450 MB)
    out = _snakemake(cwd, target, "--profile", PROFILE, "--set-resources", "ct82_fig4:mem_mb=200",
                     ok=False)
    jobs = _submitted(out)
    assert len(jobs) == 1, out
    (rule, resources, _, slurm_id), = jobs
    assert rule == "ct82_fig4" and resources["mem_mb"] == "200", out
    assert "Error in rule ct82_fig4" in out
    assert f"SLURM-job '{slurm_id}' failed" in out
    log = re.search(rf"(\S+/{slurm_id}\.log)", out).group(1)
    assert re.search(r"exceeded memory limit \(\d+ > 209715200\)", Path(cwd, log).read_text())
    assert _jobcomp(slurm)[slurm_id]["JobState"] in ("FAILED", "OUT_OF_MEMORY", "CANCELLED")
    assert not (cwd / target).exists()

    out = _snakemake(cwd, "--profile", PROFILE, target)  # the rule's own mem_mb
    jobs = _submitted(out)
    assert len(jobs) == 1, out
    (rule, resources, _, slurm_id), = jobs
    assert rule == "ct82_fig4" and int(resources["mem_mb"]) > 200
    assert _jobcomp(slurm)[slurm_id]["JobState"] == "COMPLETED"
    assert (cwd / target).exists()
