import os
import subprocess
from pathlib import Path
from types import SimpleNamespace

import pytest
from hypothesis import settings

# Property tests: no wall-clock deadline (a shared 2-core machine is not a benchmark), and in CI
# (CI=true) a fixed example sequence, so a submission's result does not depend on the draw.
settings.register_profile("dev", deadline=None)
settings.register_profile("ci", deadline=None, derandomize=True, print_blob=True)
settings.load_profile("ci" if os.environ.get("CI") else "dev")

ROOT = Path(__file__).resolve().parents[1]

# pyvista renders off-screen (EGL); never try to open a window in tests.
os.environ.setdefault("PYVISTA_OFF_SCREEN", "true")


@pytest.fixture(scope="session")
def root():
    return ROOT


def pytest_collection_modifyitems(items):
    """The modules that read the session's build (`built`) run last, each whole and in its place
    among them: the build starts with the session (fixture ``early``) and runs while everything
    else is tested, instead of holding up the first of them to come alphabetically. Likewise,
    the other modules with runs of their own started with the session come just before them."""
    late = {item.path for item in items if "built" in getattr(item, "fixturenames", ())}
    # before them, the modules whose own runs start with the session (``start_with_session``,
    # e.g. tests/test_archive.py): their runs then overlap the other tests instead of being
    # waited for
    background = {item.path for item in items
                  if hasattr(getattr(item, "module", None), "start_with_session")}
    items.sort(key=lambda item: (item.path in late, item.path in background))  # stable


# {id of an error: (the error, kept so that its id stays its own; the test that reported it)}
_REPORTED = pytest.StashKey[dict]()


class _Text:
    """A test report's ``longrepr`` that is a text: shown whole with the test's failure, and its
    first line alone in the short summary (which on CI would repeat a whole message)."""

    def __init__(self, text):
        self.text = text
        self.reprcrash = SimpleNamespace(message=text.splitlines()[0])  # what the summary reads

    def toterminal(self, tw):
        tw.line(self.text)

    def __str__(self):
        return self.text


@pytest.hookimpl(wrapper=True)
def pytest_runtest_makereport(item, call):
    """An error is reported once. A session or module fixture that raised gives every test that
    uses it the same exception (the session's build failing: a dozen tests read it): the first
    test it fails reports it, and every later one is skipped with one line naming that test.
    The build's own failure (``BuildFailed``) is reported as its text alone, its first line in
    the short summary: it says what the traceback would, and its frames are pytest's and the
    pool's."""
    from build_report import BuildFailed

    report = yield
    if not report.failed or call.excinfo is None or call.when == "teardown":
        return report
    error = call.excinfo.value
    reported = item.session.stash.setdefault(_REPORTED, {})
    if id(error) not in reported:
        reported[id(error)] = (error, item.nodeid)
        if isinstance(error, BuildFailed):
            report.longrepr = _Text(str(error))
        return report
    first = reported[id(error)][1]
    headline = (str(error).splitlines() or [type(error).__name__])[0][:160]
    path, line = item.reportinfo()[:2]
    report.outcome = "skipped"
    report.longrepr = (os.fspath(path), line + 1, f"the same error as {first}: {headline}")
    return report


@pytest.fixture(scope="session", autouse=True)
def early(request, root, tmp_path_factory):
    """Runs that only wait on subprocesses, started in background threads when the session does
    (tests/side_by_side.py), if a selected test needs them: the session's build, the SLURM
    daemons and runs of tests/test_slurm.py, the failing runs of tests/test_workflow_resume.py,
    the clone, archive and builds of tests/test_archive.py, the lint of tests/test_workflow.py,
    the Sphinx build of tests/test_docs.py, the installed wheel of tests/test_audit_cli.py, the
    refused runs of tests/test_config_corpus.py, the broken builds of tests/test_build_failure.py;
    once the build is done, the runs that read it (``after_build``: the kill -9 resume, the
    generic-cluster run, the dry runs and the report). The tests that need them take their results (or their failure) when they come to them; at
    the end of the session, whatever is still running is killed and the daemons are stopped."""
    from side_by_side import SideBySide, workers

    items = request.session.items
    # one run more than the cores (side_by_side.workers: at most 4): the build and the SLURM
    # runs (mostly waiting) take two for most of the session; the short runs get the third
    with SideBySide(workers() + 1) as runs:
        if any("built" in getattr(item, "fixturenames", ()) for item in items):
            runs.start_once("built", _build, runs, tmp_path_factory.mktemp("workflow"), root)
        # a test module's own background runs: its function start_with_session(runs, root,
        # tmp_path_factory, its selected tests) starts those they need
        modules = _modules_with(items, "start_with_session")
        # the modules that read the build first (the SLURM runs are long, mostly waiting; the
        # others short), then the others in the order their tests come
        late = {module for module, selected in modules.items()
                if any("built" in getattr(item, "fixturenames", ()) for item in selected)}
        for module, selected in sorted(modules.items(), key=lambda m: m[0] not in late):
            module.start_with_session(runs, root, tmp_path_factory, selected)
        # the runs that read the finished build (a module's function after_build(runs, built,
        # tmp_path_factory, its selected tests)): started the moment the build ends, instead of
        # one after another when the last modules' tests come to them
        readers = _modules_with(items, "after_build")
        if readers and runs.started("built"):
            runs.after("built", "after build", _after_build, runs, readers, tmp_path_factory)
        yield runs


def _modules_with(items, function):
    """{test module that defines ``function``: its tests among ``items``}, in the items' order."""
    modules = {}
    for item in items:
        module = getattr(item, "module", None)
        if module is not None and hasattr(module, function):
            modules.setdefault(module, []).append(item)
    return modules


def _after_build(built, runs, readers, tmp_path_factory):
    """Each reading module's copies of the finished build first (no run has touched it yet),
    then all their runs, the longest first (each module's ``after_build`` returns
    ``(estimated seconds, key, function, args)`` per run and makes its copies itself)."""
    starts = []
    for module, selected in readers.items():
        starts += module.after_build(runs, built, tmp_path_factory, selected)
    for _, key, function, args in sorted(starts, key=lambda start: -start[0]):
        runs.start(key, function, *args)
    return built


#: The session's build is killed after this many seconds (default BUILD_TIMEOUT_S).
BUILD_TIMEOUT = "REFLECTANCE_TEST_BUILD_TIMEOUT"
# about twenty times the whole build on an idle machine (workflow/docs/guides/testing.rst):
# room for a loaded one, and an end to a hung job before CI's own limit
BUILD_TIMEOUT_S = 1200


def _build(runs, cwd, root):
    """The whole workflow, `snakemake --cores 2`, in a temporary copy of the project, from
    nothing: the copy starts without the committed spectra, so the build exports and derives
    every one again (whether Snakemake would rerun them beside a checkout depends on the files'
    times). Killed, its whole process group, after BUILD_TIMEOUT seconds; a failure, or the
    timeout, raises ``BuildFailed`` with the failing (or still running) rules, the end of
    their logs and of Snakemake's output (tests/build_report.py)."""
    from build_report import BuildFailed, report
    from test_workflow import SNAKEMAKE, copy_project

    copy_project(root, cwd)
    for spectrum in (cwd / "spectra").glob("*.csv"):
        spectrum.unlink()
    args = ["--cores", "2"]
    command = " ".join(["snakemake", *args])
    timeout = float(runs.environ.get(BUILD_TIMEOUT, BUILD_TIMEOUT_S))
    try:
        proc = runs.run(SNAKEMAKE + args, cwd=cwd, timeout=timeout)
    except subprocess.TimeoutExpired as expired:
        output = (expired.stdout or "") + (expired.stderr or "")
        raise BuildFailed(report(
            f"the session's build, {command}, ran past {timeout:g} s ({BUILD_TIMEOUT}) and was "
            "killed", cwd, output, failed=False)) from None
    if proc.returncode != 0:
        output = proc.stdout + proc.stderr
        raise BuildFailed(report(
            f"the session's build failed: {command} exited with {proc.returncode}",
            cwd, output, failed=True))
    return cwd


@pytest.fixture(scope="session")
def built(early, root, tmp_path_factory):
    """The whole workflow, `snakemake --cores 2`, run once per test session in a temporary copy
    of the project (``_build``); shared by every end-to-end test that reads (never changes) its
    results. Started with the session (``early``), taken here."""
    if not early.started("built"):  # (``early`` starts it whenever a selected test needs it)
        early.start("built", _build, early, tmp_path_factory.mktemp("workflow"), root)
    return early.result("built")


@pytest.fixture(scope="session")
def after_build(early, built):
    """The runs the modules' ``after_build`` started once the session's build was done
    (``early``): ``after_build(key)`` waits for that one and gives its result (or raises what
    it raised)."""
    early.result("after build")
    return early.result


@pytest.fixture(scope="session")
def grid():
    from reflectance.optics.spectra import wavelength_grid

    return wavelength_grid(360, 830, 5)
