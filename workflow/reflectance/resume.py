"""A plain ``snakemake`` resumes a run that was killed.

A run killed outright (``kill -9``, a lost terminal, a power cut) cannot clean up after itself: it
leaves Snakemake's locks in ``.snakemake/locks/`` and an "incomplete" mark on each output of the
jobs it was running. The next plain ``snakemake`` then stops, first with IncompleteFilesException
and, once that is cleared, with LockException. Snakemake's own answers are command-line options
(``--rerun-incomplete``, ``--unlock``), and a workflow profile that sets them is read only from
``profiles/default/`` beside the Snakefile or in the working folder (snakemake/cli.py,
``parse_args``), a top-level folder this project leaves to the user. So the Snakefile calls
:func:`resume_after_kill` instead, which does what those options would, and only when the run that
holds the locks is known to be dead:

- the Snakefile, parsed by Snakemake's main process, records that process (host, pid and start
  time) in ``.snakemake/locks/reflectance-run.<pid>.json`` whenever no run holds the locks
  (Snakemake removes that folder when a run ends normally);
- when locks are found and every recorded process is gone from this host, they are removed, as
  ``snakemake --unlock`` would;
- when no run holds the locks, every incomplete mark is stale and is removed. Every writer of this
  project replaces its file in one rename (:mod:`reflectance.io.atomic`), and Snakemake deletes a
  job's outputs before the job starts, so an output that exists is whole and a killed job always
  misses at least one output: it reruns, and nothing half-written is ever taken for a result.

Locks recorded by a live process, by a process on another host, or by a run that left no record
are left alone (Snakemake reports them as before). Only Snakemake's default file-based persistence
(``.snakemake/``) is handled. On a cluster, a job that outlived its killed Snakemake is submitted
again rather than waited for (its mark, which held the cluster's job id, is cleared with the
rest); both write the same bytes, each in one rename.
"""

from __future__ import annotations

import json
import os
import re
import socket
import sys
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any, TextIO

from reflectance.io.atomic import process_alive, process_start_time

__all__ = ["resume_after_kill", "memory_kills", "report_memory_kills"]

#: records of the runs that may hold Snakemake's locks, inside Snakemake's lock folder
RUN_RECORDS = "reflectance-run.*.json"


def _this_run():
    pid = os.getpid()
    return {"host": socket.gethostname(), "pid": pid, "start_time": process_start_time(pid)}


def _read_record(path):
    try:
        record = json.loads(path.read_text())
        return {"host": str(record["host"]), "pid": int(record["pid"]),
                "start_time": record.get("start_time")}
    except (OSError, ValueError, KeyError, TypeError):
        return None


def _dead(record):
    return (record is not None and record["host"] == socket.gethostname()
            and not process_alive(record["pid"], record["start_time"]))


def resume_after_kill(main_process: bool = True, state_dir: str | os.PathLike[str] = ".snakemake",
                      stream: TextIO = sys.stderr) -> list[str]:
    """Clear what a killed run of this workflow left in ``state_dir``; record this run.

    Parameters
    ----------
    main_process : bool
        True in Snakemake's main process (``workflow.exec_mode`` DEFAULT); jobs that Snakemake
        spawns, locally or on a cluster node, parse the Snakefile too and must leave the state alone.
    state_dir : str or Path
        Snakemake's state folder in the working folder.
    stream : file
        Where to say what was cleared.

    Returns
    -------
    list of str
        What was cleared (empty when nothing was).
    """
    if not main_process:
        return []
    state = Path(state_dir)
    lock_dir, incomplete_dir = state / "locks", state / "incomplete"
    cleared: list[str] = []
    locks = sorted(lock_dir.glob("*.lock")) if lock_dir.is_dir() else []
    records = {p: _read_record(p) for p in lock_dir.glob(RUN_RECORDS)} if locks else {}
    if locks:
        # Two runs may have started before either locked; the locks are stale only if all are gone.
        if not records or not all(_dead(r) for r in records.values()):
            return cleared  # a live run, another host's run, or a run that left no record
        for lock in locks:
            lock.unlink(missing_ok=True)
        pids = ", ".join(str(r["pid"]) for r in records.values())
        cleared.append(f"the locks of the killed run (pid {pids})")
    # No run holds the locks now: every record of a dead run and every incomplete mark is stale.
    for path in lock_dir.glob(RUN_RECORDS) if lock_dir.is_dir() else []:
        record = _read_record(path)
        if record is None or _dead(record):
            path.unlink(missing_ok=True)
    marks = [p for p in incomplete_dir.rglob("*") if p.is_file()] if incomplete_dir.is_dir() else []
    for mark in marks:
        mark.unlink(missing_ok=True)
    if marks:
        cleared.append(f"{len(marks)} incomplete mark(s) (its unfinished jobs run again)")
    lock_dir.mkdir(parents=True, exist_ok=True)
    this = _this_run()
    record_path = lock_dir / RUN_RECORDS.replace("*", str(this["pid"]))
    tmp = lock_dir / f".{record_path.name}"
    tmp.write_text(json.dumps(this))
    os.replace(tmp, record_path)
    if cleared:
        print(f"reflectance: resuming; cleared {' and '.join(cleared)}.", file=stream)
    return cleared


# --- jobs a cluster killed for their memory --------------------------------------------------------

#: What SLURM writes into a job's log when it kills the job for its memory: jobacct_gather's
#: OverMemoryKill ("StepId=12.batch exceeded memory limit (229134336 > 209715200), being killed")
#: and the cgroup plugin's ("Detected 1 oom_kill event in StepId=12.0").
MEMORY_KILL = re.compile(r"^.*(?:exceeded (?:job )?memory limit|oom[-_]kill event).*$",
                         re.IGNORECASE | re.MULTILINE)
#: the line of those that says by how much: "(229134336 > 209715200)", used bytes over the limit
_MEMORY_FIGURES = re.compile(r"\(\d+ > \d+\)")
_BLOCK = r"^{head}:\n((?:    .*\n?)+)"


def _fields(body):
    return dict(re.findall(r"^    (\w+): (.*)$", body, flags=re.MULTILINE))


def memory_kills(log_text: str,
                 read_text: Callable[[str], str] = lambda path: Path(path).read_text(errors="replace")
                ) -> list[dict[str, Any]]:
    """The jobs of a Snakemake run that the cluster killed for exceeding their memory request.

    Snakemake's SLURM executor reports such a job only as failed ("SLURM status is: 'FAILED'",
    or 'OUT_OF_MEMORY' where its status command can tell), and names neither the memory nor the
    request. This reads the run's log (what Snakemake printed): each failed job's rule, its
    ``mem_mb`` as submitted, and the memory line of the cluster's log of the job.

    Parameters
    ----------
    log_text : str
        Snakemake's log of the run (``.snakemake/log/*.snakemake.log``).
    read_text : callable
        Reads a log file named by the run (SLURM's log of the job); may raise OSError.

    Returns
    -------
    list of dict
        One per job killed for memory: ``rule``, ``jobid`` (Snakemake's), ``external_jobid``,
        ``mem_mb`` (None if the run did not print it) and ``evidence`` (the cluster's line).
    """
    submitted = {}
    for rule, body in re.findall(_BLOCK.format(head=r"(?:local)?rule (\w+)"), log_text,
                                 flags=re.MULTILINE):
        fields = _fields(body)
        mem = re.search(r"(?:^|, )mem_mb=(\d+)", fields.get("resources", ""))
        submitted[fields.get("jobid")] = int(mem.group(1)) if mem else None
    kills = []
    for rule, body in re.findall(_BLOCK.format(head=r"Error in rule (\w+)"), log_text,
                                 flags=re.MULTILINE):
        fields = _fields(body)
        evidence = None
        if "OUT_OF_MEMORY" in fields.get("message", ""):
            evidence = "SLURM status OUT_OF_MEMORY"
        logs = re.sub(r"\s*\(check log file\(s\) for error details\)$", "", fields.get("log", ""))
        for path in (p.strip() for p in logs.split(", ") if p.strip()):
            try:
                found = [m.group(0).strip() for m in MEMORY_KILL.finditer(read_text(path))]
            except OSError:
                continue
            if found:
                # SLURM writes its lines in no fixed order ("Exceeded job memory limit" may come
                # first): the one with the step's used and allowed bytes, else the first
                evidence = next((line for line in found if _MEMORY_FIGURES.search(line)),
                                found[0])
                break
        if evidence:
            kills.append({"rule": rule, "jobid": fields.get("jobid"),
                          "external_jobid": fields.get("external_jobid"),
                          "mem_mb": submitted.get(fields.get("jobid")), "evidence": evidence})
    return kills


def report_memory_kills(log_path: str | os.PathLike[str] | Sequence[str | os.PathLike[str]],
                        stream: TextIO = sys.stderr) -> list[str]:
    """Say, for each job of the run in ``log_path`` killed for its memory, which rule and request.

    ``log_path`` is one log file or a list of them (what Snakemake hands ``onerror:``).

    Called by the Snakefile's ``onerror:`` (Snakemake's main process, once a run has failed), so
    the run ends with e.g. "rule ct82_fig4 (SLURM job 12) was killed for exceeding its memory
    request, mem_mb=200 (...); rerun with more: --set-resources ct82_fig4:mem_mb=400".

    Returns
    -------
    list of str
        The lines written (none when no job was killed for memory, or the log cannot be read).
    """
    paths = [log_path] if isinstance(log_path, (str, os.PathLike)) else list(log_path or [])
    text = ""
    for path in paths:  # Snakemake 9 passes the list of its log files
        try:
            text += Path(path).read_text(errors="replace")
        except (OSError, TypeError):
            continue
    lines = []
    for kill in memory_kills(text):
        rule, mem = kill["rule"], kill["mem_mb"]
        job = f" (SLURM job {kill['external_jobid']})" if kill["external_jobid"] else ""
        request = f"mem_mb={mem}" if mem is not None else "mem_mb"
        more = f"{rule}:mem_mb={2 * mem}" if mem is not None else f"{rule}:mem_mb=<more>"
        lines.append(f"reflectance: rule {rule}{job} was killed for exceeding its memory request, "
                     f"{request} ({kill['evidence']}); rerun with more: --set-resources {more}")
    for line in lines:
        print(line, file=stream)
    return lines
