"""The session's build, when it fails, told in a few KB (test helper of tests/conftest.py).

Snakemake's output of the whole build runs to hundreds of KB, and a test that printed it would
bury the cause: what says why the build failed is the rules that failed (Snakemake's ``Error in
rule X:`` blocks, each naming the rule's log), the end of each one's log (where a figure script
writes its traceback) and the last lines of Snakemake's output. A build that ran out of time has
no failed rule: the jobs still running when it was killed take their place.
"""

import re
from pathlib import Path

#: lines kept from the end of each rule's log and of Snakemake's output
TAIL_LINES = 25
#: a longer line is cut (Snakemake prints a job's whole list of outputs on one line)
LINE_CHARS = 240

# a job's block: its header, then its fields, one per line, indented by four spaces
_HEADER = re.compile(r"^(Error in rule|rule|localrule|checkpoint|localcheckpoint) (\S+):$")
_FIELD = re.compile(r"^ {4}(\w+): (.*)$")
_FINISHED = re.compile(r"^Finished job(?:id:)? (\d+)")


class BuildFailed(Exception):
    """The session's build failed or ran out of time; ``str()`` is its report (``report``)."""


def _blocks(text):
    """Snakemake's job blocks in ``text``, its output: ``[(header, rule, {field: text})]`` in
    order, ``header`` being ``"Error in rule"`` for a failed job and the block's own word
    (``rule``, ``localrule``, ...) for a started one.

    Examples
    --------
    >>> _blocks("localrule a:\\n    log: x.log\\n    jobid: 1\\nother\\n    jobid: 2\\n")
    [('localrule', 'a', {'log': 'x.log', 'jobid': '1'})]
    """
    blocks, fields = [], None
    for line in text.splitlines():
        header, field = _HEADER.match(line), _FIELD.match(line)
        if header:
            fields = {}
            blocks.append((header[1], header[2], fields))
        elif field and fields is not None:
            fields[field[1]] = field[2]
        else:
            fields = None
    return blocks


def jobs(text, failed):
    """The jobs that failed (Snakemake's ``Error in rule X:`` blocks), or those started and
    neither finished nor failed: what a killed build was running.

    Parameters
    ----------
    text : str
        Snakemake's output.
    failed : bool
        The failed jobs, or the running ones.

    Returns
    -------
    list of tuple
        ``(rule, log files)`` per job, in the order of ``text``.

    Examples
    --------
    >>> text = ("rule a:\\n    jobid: 1\\nrule b:\\n    log: b.log\\n    jobid: 2\\n"
    ...         "rule c:\\n    jobid: 3\\nFinished jobid: 1 (Rule: a)\\nError in rule c:\\n"
    ...         "    jobid: 3\\n    log: c.log, d.log (check log file(s) for error details)\\n")
    >>> jobs(text, failed=True)
    [('c', ['c.log', 'd.log'])]
    >>> jobs(text, failed=False)
    [('b', ['b.log'])]
    """
    blocks = _blocks(text)
    errors = [(rule, fields) for header, rule, fields in blocks if header == "Error in rule"]
    if failed:
        return [(rule, _logs(fields)) for rule, fields in errors]
    ended = {fields.get("jobid") for _, fields in errors}
    ended |= {found[1] for line in text.splitlines() if (found := _FINISHED.match(line))}
    return [(rule, _logs(fields)) for header, rule, fields in blocks
            if header != "Error in rule" and fields.get("jobid") not in ended]


def _logs(fields):
    """The log files a job block names (none if the rule has no log)."""
    text = fields.get("log", "").split(" (check log file")[0].strip()
    return [name for name in text.split(", ") if name]


def tail(text, lines=TAIL_LINES):
    """The last ``lines`` lines of ``text``, each cut to LINE_CHARS, indented by four spaces.

    Examples
    --------
    >>> tail("a\\nb\\nc\\n", 2)
    '    b\\n    c'
    """
    return "\n".join("    " + (line if len(line) <= LINE_CHARS else line[:LINE_CHARS] + " [...]")
                     for line in text.splitlines()[-lines:])


def report(headline, cwd, output, failed):
    """The build's failure in a few KB.

    Parameters
    ----------
    headline : str
        What happened, one line.
    cwd : path-like
        The folder the build ran in (its logs' paths are relative to it).
    output : str
        Snakemake's output.
    failed : bool
        Show the jobs that failed (the build failed), or those still running (it was killed).

    Returns
    -------
    str
        ``headline``, then each of those jobs' rule with the tail of each of its logs, then the
        tail of ``output``.
    """
    rules, state = jobs(output, failed), "failed" if failed else "still running"
    parts = [headline, f"in {cwd} (Snakemake's whole log: {Path(cwd, '.snakemake', 'log')})"]
    for rule, logs in rules:
        if not logs:
            parts.append(f"rule {rule} ({state}): it has no log")
        for name in logs:
            path = Path(cwd, name)
            if path.is_file():
                parts.append(f"rule {rule} ({state}), the end of its log {name}:\n"
                             + tail(path.read_text(errors="replace")))
            else:
                parts.append(f"rule {rule} ({state}): its log {name} was not written")
    if not rules:
        parts.append(f"no job {state} in Snakemake's output")
    parts.append("the end of Snakemake's output:\n" + tail(output))
    return "\n".join(parts)
