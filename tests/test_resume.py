"""Interrupted runs: what a killed run leaves behind is cleared by the next one, and only that.

The end-to-end test (a real `snakemake --cores 2` killed with SIGKILL mid-render, then a plain
rerun) is in test_workflow_resume.py; these check the pieces on their own.
"""

import io
import json
import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

from reflectance.io.atomic import atomic_write, remove_stale_temporaries
from reflectance.resume import memory_kills, report_memory_kills, resume_after_kill

WORKFLOW = str(Path(__file__).resolve().parents[1] / "workflow")


def run_python(code, **kwargs):
    env = {**os.environ, "PYTHONPATH": WORKFLOW}
    return subprocess.run([sys.executable, "-c", code], env=env, check=True, **kwargs)


def fake_snakemake_state(state):
    """Locks and incomplete marks as Snakemake's file persistence writes them."""
    (state / "locks").mkdir(parents=True, exist_ok=True)
    (state / "locks" / "0.input.lock").write_text("spectra/Cu.csv\n")
    (state / "locks" / "0.output.lock").write_text("results/a.png\n")
    (state / "incomplete").mkdir(exist_ok=True)
    (state / "incomplete" / "cmVzdWx0cy9hLnBuZw==").write_text("{}")
    return state


def record_by_exited_process(state):
    """Let a process that has exited record itself as the run holding the locks."""
    run_python(f"from reflectance.resume import resume_after_kill; "
               f"resume_after_kill(state_dir={str(state)!r})")


def test_locks_of_a_dead_run_are_cleared(tmp_path):
    state = tmp_path / ".snakemake"
    record_by_exited_process(state)
    fake_snakemake_state(state)
    cleared = resume_after_kill(state_dir=state, stream=sys.stderr)
    assert cleared and "locks" in cleared[0]
    assert not list((state / "locks").glob("*.lock"))
    assert not [p for p in (state / "incomplete").rglob("*") if p.is_file()]
    # this run is now the one on record
    records = [json.loads(p.read_text()) for p in (state / "locks").glob("reflectance-run.*.json")]
    assert [r["pid"] for r in records] == [os.getpid()]


def test_locks_of_a_live_run_are_kept(tmp_path):
    state = tmp_path / ".snakemake"
    resume_after_kill(state_dir=state)  # this (live) process holds the locks
    fake_snakemake_state(state)
    run_python(f"from reflectance.resume import resume_after_kill; "
               f"assert resume_after_kill(state_dir={str(state)!r}) == []")
    assert len(list((state / "locks").glob("*.lock"))) == 2
    assert len(list((state / "incomplete").iterdir())) == 1


@pytest.fixture
def two_records(tmp_path):
    """Two runs on record before either locked: one still running (a child of this test, asleep
    after recording itself), one that recorded itself and exited; then Snakemake's locks."""
    state = tmp_path / ".snakemake"
    env = {**os.environ, "PYTHONPATH": WORKFLOW}
    alive = subprocess.Popen(
        [sys.executable, "-c", f"import time; from reflectance.resume import resume_after_kill; "
                               f"resume_after_kill(state_dir={str(state)!r}); print('on record', "
                               f"flush=True); time.sleep(120)"],
        env=env, stdout=subprocess.PIPE, text=True)
    try:
        assert alive.stdout.readline().strip() == "on record"
        record_by_exited_process(state)
        fake_snakemake_state(state)
        records = [json.loads(p.read_text())["pid"]
                   for p in (state / "locks").glob("reflectance-run.*.json")]
        assert len(records) == 2 and alive.pid in records
        yield state, alive
    finally:
        alive.kill()
        alive.wait()


def test_locks_are_kept_while_one_of_two_recorded_runs_is_alive(two_records):
    state, alive = two_records
    assert resume_after_kill(state_dir=state) == []
    assert len(list((state / "locks").glob("*.lock"))) == 2
    assert len(list((state / "incomplete").iterdir())) == 1


def test_locks_are_cleared_once_both_recorded_runs_are_dead(two_records):
    state, alive = two_records
    alive.kill()
    alive.wait()
    cleared = resume_after_kill(state_dir=state)
    assert cleared and "locks" in cleared[0] and str(alive.pid) in cleared[0]
    assert not list((state / "locks").glob("*.lock"))


def test_locks_without_a_record_or_from_another_host_are_kept(tmp_path):
    state = fake_snakemake_state(tmp_path / ".snakemake")
    assert resume_after_kill(state_dir=state) == []  # no record: not ours to judge
    (state / "locks" / "reflectance-run.1.json").write_text(json.dumps(
        {"host": socket.gethostname() + "-elsewhere", "pid": 999999999, "start_time": None}))
    assert resume_after_kill(state_dir=state) == []
    assert len(list((state / "locks").glob("*.lock"))) == 2


def test_jobs_spawned_by_snakemake_leave_the_state_alone(tmp_path):
    state = tmp_path / ".snakemake"
    record_by_exited_process(state)
    fake_snakemake_state(state)
    assert resume_after_kill(main_process=False, state_dir=state) == []
    assert len(list((state / "locks").glob("*.lock"))) == 2


def test_marks_left_without_locks_are_cleared(tmp_path):
    """A run killed while running with --nolock, or after its locks were removed by hand."""
    state = fake_snakemake_state(tmp_path / ".snakemake")
    for lock in (state / "locks").glob("*.lock"):
        lock.unlink()
    assert resume_after_kill(state_dir=state) != []
    assert not list((state / "incomplete").iterdir())


WRITER = """
import sys, time
from reflectance.io.atomic import atomic_write
with atomic_write(sys.argv[1]) as tmp:
    tmp.write_bytes(b"half an EXR")
    print(tmp, flush=True)
    time.sleep(600)
"""


def test_sigkill_during_a_write_leaves_only_a_temporary_that_the_next_write_removes(tmp_path):
    target = tmp_path / "render.exr"
    target.write_bytes(b"the previous, whole render")
    env = {**os.environ, "PYTHONPATH": WORKFLOW}
    writer = subprocess.Popen([sys.executable, "-c", WRITER, str(target)], env=env,
                              stdout=subprocess.PIPE, text=True)
    tmp = Path(writer.stdout.readline().strip())
    writer.send_signal(signal.SIGKILL)
    writer.wait()
    assert tmp.exists() and tmp.parent == tmp_path and tmp.name.startswith(".render.exr.")
    assert target.read_bytes() == b"the previous, whole render"  # never a partial file

    # A live writer's temporary in the same folder is not touched by the cleaning.
    with atomic_write(tmp_path / "other.exr") as live:
        live.write_bytes(b"in progress")
        with atomic_write(tmp_path / "render.exr") as again:
            again.write_bytes(b"the new render")
            assert not tmp.exists()
            assert live.exists()
    assert target.read_bytes() == b"the new render"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["other.exr", "render.exr"]


def test_temporaries_of_other_names_or_hosts_are_kept(tmp_path):
    keep = [".render.exr.tmp-elsewhere-1-abcdefgh.exr",   # another host's writer
            ".hidden-by-the-user.exr", "notes.txt"]
    for name in keep:
        (tmp_path / name).write_text("x")
    assert remove_stale_temporaries(tmp_path) == []
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(keep)


def _unguarded_writes(source):
    """Calls in a script that write a file other than through reflectance.io's atomic writers:
    ``x.to_csv(path)``, ``fig.savefig(path)``, ``open(path, "w")``, ``p.write_text(...)``,
    ``p.write_bytes(...)``, ``plotter.screenshot(path)``, ``image.save(path)``, unless the path is
    the temporary of an enclosing ``with atomic_write(...) as tmp``."""
    import ast

    tree = ast.parse(source)
    temporaries = {item.optional_vars.id for node in ast.walk(tree) if isinstance(node, ast.With)
                   for item in node.items
                   if isinstance(item.context_expr, ast.Call)
                   and getattr(item.context_expr.func, "id", getattr(item.context_expr.func, "attr",
                                                                     None)) == "atomic_write"
                   and isinstance(item.optional_vars, ast.Name)}
    found = []
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call):
            continue
        name = getattr(node.func, "attr", getattr(node.func, "id", None))
        first = node.args[0] if node.args else None
        to_temporary = isinstance(first, ast.Name) and first.id in temporaries
        if name in ("to_csv", "savefig", "screenshot", "save") and isinstance(node.func, ast.Attribute):
            if first is not None and not to_temporary and ast.unparse(first) != "sys.stdout":
                found.append(ast.unparse(node))
        elif name in ("write_text", "write_bytes") and isinstance(node.func, ast.Attribute):
            target = node.func.value
            if (isinstance(target, ast.Call) and getattr(target.func, "id", None) == "Path"
                    and target.args):  # Path(tmp).write_text(...)
                target = target.args[0]
            if not (isinstance(target, ast.Name) and target.id in temporaries):
                found.append(ast.unparse(node))
        elif name == "open" and isinstance(node.func, ast.Name):
            modes = [a.value for a in node.args[1:2] + [k.value for k in node.keywords
                                                        if k.arg == "mode"]
                     if isinstance(a, ast.Constant)]
            if any(set(m) & set("wax+") for m in modes):
                found.append(ast.unparse(node))
    return found


def test_every_script_writes_its_outputs_atomically(root):
    """Resuming relies on it: a file at an output's path is always whole. The rendered
    figures' scripts call their drawings (reflectance.papers.draw), checked as scripts."""
    drawings = root / "workflow" / "reflectance" / "papers" / "draw"
    offenders = {p.name: _unguarded_writes(p.read_text())
                 for p in sorted((root / "workflow" / "scripts").glob("*.py"))
                 + sorted(drawings.glob("*.py"))}
    assert {k: v for k, v in offenders.items() if v} == {}
    # the check itself sees the writes it is meant to catch
    assert _unguarded_writes("t.to_csv(snakemake.output.csv)\nfig.savefig('a.png')\n"
                             "open('x', 'w')\n") == ["t.to_csv(snakemake.output.csv)",
                                                      "fig.savefig('a.png')", "open('x', 'w')"]
    assert _unguarded_writes("with atomic_write(p) as tmp:\n    im.save(tmp)\n") == []
    assert _unguarded_writes("with atomic_write(p) as tmp:\n    Path(tmp).write_text(s)\n") == []
    assert _unguarded_writes("Path(out).write_text(s)\n") == ["Path(out).write_text(s)"]


# --- jobs a cluster killed for their memory (the Snakefile's onerror) ------------------------------

# What Snakemake 9.27 with snakemake-executor-plugin-slurm 2.8 printed for a job killed by
# SLURM 22.05 (tests/test_slurm.py's run; ids and paths shortened), and SLURM's log of that job.
RUN_LOG = """\
[Tue Dec  1 22:49:00 2026]
rule ct82_fig4:
    input: spectra/Cu.csv
    output: results/cook_torrance_1982/fig4.png, results/cook_torrance_1982/fig4.csv
    log: logs/cook_torrance_1982/fig4.log
    jobid: 3
    reason: Missing output files: results/cook_torrance_1982/fig4.csv
    resources: tmpdir=<TBD>, mem_mb=200, mem=200 MB, mem_mib=191, disk_mb=1000, runtime=10
Job 3 has been submitted with SLURM jobid 17 (log: {slurm_log}).
[Tue Dec  1 22:49:00 2026]
rule ct82_fig2:
    output: results/cook_torrance_1982/fig2.png
    log: logs/cook_torrance_1982/fig2.log
    jobid: 4
    resources: tmpdir=<TBD>, mem_mb=1000, mem=1000 MB, runtime=10
Job 4 has been submitted with SLURM jobid 18 (log: {other_log}).
[Tue Dec  1 22:49:30 2026]
Error in rule ct82_fig4:
    message: SLURM-job '17' failed, SLURM status is: 'FAILED'. Detailed failure reason unavailable (status command is not 'sacct').
    jobid: 3
    input: spectra/Cu.csv
    log: logs/cook_torrance_1982/fig4.log, {slurm_log} (check log file(s) for error details)
    external_jobid: 17
[Tue Dec  1 22:49:31 2026]
Error in rule ct82_fig2:
    message: SLURM-job '18' failed, SLURM status is: 'FAILED'. Detailed failure reason unavailable (status command is not 'sacct').
    jobid: 4
    log: logs/cook_torrance_1982/fig2.log, {other_log} (check log file(s) for error details)
    external_jobid: 18
Exiting because a job execution failed. Look above for error messages
"""
SLURM_LOG = """\
host: vm
slurmstepd-vm: error: StepId=17.batch exceeded memory limit (229134336 > 209715200), being killed
slurmstepd-vm: error: Exceeded job memory limit
slurmstepd-vm: error: *** JOB 17 ON vm CANCELLED AT 2026-12-01T22:49:18 ***
"""


#: SLURM's lines in the other order it writes them in (seen on a loaded machine)
SLURM_LOG_JOB_LINE_FIRST = """\
host: vm
slurmstepd-vm: error: Exceeded job memory limit
slurmstepd-vm: error: StepId=17.batch exceeded memory limit (229134336 > 209715200), being killed
slurmstepd-vm: error: *** JOB 17 ON vm CANCELLED AT 2026-12-01T22:49:18 ***
"""


@pytest.mark.parametrize("slurm_text", [SLURM_LOG, SLURM_LOG_JOB_LINE_FIRST],
                         ids=["step-line-first", "job-line-first"])
def test_a_job_killed_for_memory_is_named_with_its_rule_and_request(tmp_path, slurm_text):
    slurm_log, other_log = tmp_path / "17.log", tmp_path / "18.log"
    slurm_log.write_text(slurm_text)
    other_log.write_text("Traceback (most recent call last):\nValueError: not memory\n")
    run_log = tmp_path / "run.snakemake.log"
    run_log.write_text(RUN_LOG.format(slurm_log=slurm_log, other_log=other_log))

    # ct82_fig2 failed too, but not for memory: only ct82_fig4 is named
    (kill,) = memory_kills(run_log.read_text())
    assert (kill["rule"], kill["jobid"], kill["external_jobid"], kill["mem_mb"]) == (
        "ct82_fig4", "3", "17", 200)
    assert "exceeded memory limit (229134336 > 209715200)" in kill["evidence"]
    stream = io.StringIO()
    # Snakemake 9 hands onerror the list of its log files
    (line,) = report_memory_kills([run_log], stream=stream)
    assert report_memory_kills(run_log, stream=io.StringIO()) == [line]
    assert stream.getvalue() == line + "\n"
    assert line.startswith("reflectance: rule ct82_fig4 (SLURM job 17) was killed for exceeding "
                           "its memory request, mem_mb=200 (")
    assert line.endswith("; rerun with more: --set-resources ct82_fig4:mem_mb=400")


def test_out_of_memory_status_alone_names_the_job_and_a_missing_log_is_no_error(tmp_path):
    text = RUN_LOG.format(slurm_log=tmp_path / "gone.log", other_log=tmp_path / "gone2.log")
    assert memory_kills(text) == []  # FAILED and no log to read: nothing claimed
    text = text.replace("SLURM status is: 'FAILED'", "SLURM status is: 'OUT_OF_MEMORY'", 1)
    (kill,) = memory_kills(text)
    assert kill["rule"] == "ct82_fig4" and kill["evidence"] == "SLURM status OUT_OF_MEMORY"
    assert report_memory_kills(tmp_path / "no-such.log") == []
