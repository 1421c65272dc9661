"""Run a workflow script as Snakemake would, with a stand-in for its ``snakemake`` object (test
helper shared by the figure tests that check a script's drawing without a build)."""

import runpy
from pathlib import Path
from types import SimpleNamespace

SCRIPTS = Path(__file__).resolve().parents[1] / "workflow" / "scripts"


def run_script(name, tmp_path, outputs, inputs=None, **params):
    """Run workflow/scripts/<name>.py with ``outputs`` ({key: file name}) in ``tmp_path``,
    ``inputs`` and ``params`` as the rule would give them; return the script's globals."""
    snakemake = SimpleNamespace(
        input=SimpleNamespace(**(inputs or {})),
        output=SimpleNamespace(**{key: str(tmp_path / file) for key, file in outputs.items()}),
        params=SimpleNamespace(**params),
        log=[str(tmp_path / f"{name}.log")],
        rule=name,
    )
    return runpy.run_path(str(SCRIPTS / f"{name}.py"), init_globals={"snakemake": snakemake})
