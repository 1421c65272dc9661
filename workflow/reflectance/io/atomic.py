"""Atomic file output: a failed or interrupted writer never leaves a partial file behind.

A writer fills a hidden temporary file beside its target and renames it onto the target only when
it has succeeded. A process killed outright (``kill -9``) cannot remove its temporary file; the
name says which process made it (``.<name>.tmp-<host>-<pid>-<random><suffix>``), so the next write
to the same folder removes every such file whose process is gone from this host.
"""

from __future__ import annotations

import contextlib
import os
import re
import socket
import tempfile
from collections.abc import Iterator
from pathlib import Path

__all__ = ["atomic_write", "write_text", "staged_folder", "remove_stale_temporaries",
           "process_alive", "process_start_time"]

#: a temporary file of :func:`atomic_write`: hidden, then target name, host, pid, mkstemp's 8 characters
_TEMPORARY = re.compile(r"^\.(?P<name>.+)\.tmp-(?P<host>[A-Za-z0-9-]*)-(?P<pid>\d+)-[a-z0-9_]{8}")


def _host():
    return re.sub(r"[^A-Za-z0-9-]", "-", socket.gethostname())


def process_start_time(pid: int) -> int | None:
    """A process's start time in clock ticks since boot (Linux /proc), or None where unknown."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return None
    # field 22 (starttime); the command name in field 2 may hold spaces, so split after its ')'
    return int(stat.rsplit(")", 1)[1].split()[19])


def process_alive(pid: int, start_time: int | None = None) -> bool:
    """Whether process ``pid`` exists on this host (and, if given, started at ``start_time``).

    >>> process_alive(os.getpid(), process_start_time(os.getpid()))
    True
    """
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        pass  # exists, owned by someone else
    if start_time is not None:
        now = process_start_time(pid)
        return now is None or now == start_time  # another start time: the pid was reused
    return True


def remove_stale_temporaries(folder: str | os.PathLike[str]) -> list[Path]:
    """Remove the temporary files that writers killed on this host left in ``folder``.

    A temporary file whose process is alive (another job writing to the same folder) or that was
    made on another host (a cluster node sharing the folder) is left alone.

    Parameters
    ----------
    folder : str or Path

    Returns
    -------
    list of Path
        The files removed.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> dead = folder / f".a.exr.tmp-{_host()}-999999999-abcd_123.exr"   # no such pid
    >>> live = folder / f".b.exr.tmp-{_host()}-{os.getpid()}-abcd_123.exr"
    >>> _ = dead.write_bytes(b"half"), live.write_bytes(b"half")
    >>> [p.name == dead.name for p in remove_stale_temporaries(folder)]
    [True]
    >>> sorted(p.name == live.name for p in folder.iterdir())
    [True]
    """
    host, removed = _host(), []
    with os.scandir(folder) as entries:
        for entry in entries:
            match = _TEMPORARY.match(entry.name)
            if (match and match["host"] == host and not process_alive(int(match["pid"]))
                    and entry.is_file(follow_symlinks=False)):
                with contextlib.suppress(FileNotFoundError):  # another writer was quicker
                    os.unlink(entry.path)
                    removed.append(Path(entry.path))
            elif (match and match["host"] == host and not process_alive(int(match["pid"]))
                  and entry.is_dir(follow_symlinks=False)):  # a staged_folder's
                import shutil

                shutil.rmtree(entry.path, ignore_errors=True)
                removed.append(Path(entry.path))
    return removed


@contextlib.contextmanager
def atomic_write(path: str | os.PathLike[str], suffix: str | None = None) -> Iterator[Path]:
    """Yield a temporary path beside ``path``; move it onto ``path`` only if the block succeeds.

    Stale temporary files that killed writers left in the same folder are removed first
    (:func:`remove_stale_temporaries`).

    Parameters
    ----------
    path : str or Path
        Final output file. Its parent folder is created if missing.
    suffix : str, optional
        Suffix of the temporary file (some writers choose the format by suffix); defaults to the
        suffix of ``path``.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> target = pathlib.Path(tempfile.mkdtemp()) / "a.txt"
    >>> with atomic_write(target) as tmp:
    ...     _ = pathlib.Path(tmp).write_text("done")
    >>> target.read_text()
    'done'
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    remove_stale_temporaries(path.parent)
    fd, tmp = tempfile.mkstemp(
        prefix=f".{path.name}.tmp-{_host()}-{os.getpid()}-",
        suffix=suffix if suffix is not None else path.suffix, dir=path.parent,
    )
    os.close(fd)
    umask = os.umask(0)
    os.umask(umask)
    try:
        yield Path(tmp)
        os.chmod(tmp, 0o666 & ~umask)  # mkstemp makes 0600; give the file ordinary permissions
        os.replace(tmp, path)
    except OSError as err:  # (a full disk: named by the file asked for, not the temporary)
        if err.errno is None or (err.filename is not None and Path(err.filename) != Path(tmp)):
            raise  # (a write on the open file names none: it is this one too)
        raise type(err)(err.errno, err.strerror, str(path)) from None
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def write_text(path: str | os.PathLike[str], text: str) -> None:
    """Write ``text`` to ``path`` (UTF-8, its line endings as they are) in one rename
    (:func:`atomic_write`).

    Examples
    --------
    >>> import pathlib, tempfile
    >>> target = pathlib.Path(tempfile.mkdtemp()) / "answer.rst"
    >>> write_text(target, "**Answer:** 42.\\n")
    >>> target.read_text()
    '**Answer:** 42.\\n'
    """
    with atomic_write(path) as tmp:
        Path(tmp).write_bytes(str(text).encode("utf-8"))


@contextlib.contextmanager
def staged_folder(folder: str | os.PathLike[str]) -> Iterator[Path]:
    """Yield a hidden folder beside ``folder`` to write several files into; only if the block
    succeeds are they moved into ``folder`` (all of them, or none: issue 25).

    A ``folder`` that does not exist yet is the staged folder renamed, in one step; into one that
    exists, each file is renamed onto its name (files of ``folder`` that the block did not write
    stay). A failed or interrupted block leaves nothing: its staged folder is removed then, or, if
    the process was killed, by the next write beside it (:func:`remove_stale_temporaries`).

    Examples
    --------
    >>> import pathlib, tempfile
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "out"
    >>> with staged_folder(out) as tmp:
    ...     _ = (tmp / "a.txt").write_text("a"), (tmp / "b.txt").write_text("b")
    >>> sorted(p.name for p in out.iterdir())
    ['a.txt', 'b.txt']
    >>> try:
    ...     with staged_folder(out) as tmp:
    ...         _ = (tmp / "a.txt").write_text("changed")
    ...         raise ValueError("a later file failed")
    ... except ValueError:
    ...     pass
    >>> (out / "a.txt").read_text(), sorted(p.name for p in out.parent.iterdir())
    ('a', ['out'])
    """
    import shutil

    folder = Path(folder)
    folder.parent.mkdir(parents=True, exist_ok=True)
    remove_stale_temporaries(folder.parent)
    tmp = Path(tempfile.mkdtemp(prefix=f".{folder.name}.tmp-{_host()}-{os.getpid()}-",
                                dir=folder.parent))
    umask = os.umask(0)
    os.umask(umask)
    try:
        yield tmp
        os.chmod(tmp, 0o777 & ~umask)  # mkdtemp makes 0700
        try:
            os.rename(tmp, folder)  # (a folder that does not exist: all files in one step)
        except OSError:
            if not folder.is_dir():
                raise
            for entry in sorted(tmp.iterdir()):
                os.replace(entry, folder / entry.name)
    finally:
        if tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)
