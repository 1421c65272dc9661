"""Run a command with its standard error on a pseudo-terminal (as a user's shell gives it) or on a
pipe (as a Snakemake job's log or CI), and read what it wrote there."""

import fcntl
import os
import pty
import struct
import subprocess
import termios


def stderr_of(command, terminal, columns=100, until=None, **popen):
    """``(process, text)``: run ``command`` (a list, as for :class:`subprocess.Popen`) with its
    standard error on a pseudo-terminal of ``columns`` columns (``terminal``) or a pipe, and
    read it to the end. ``until(text so far)``: return the running process as soon as it is
    true, the rest unread (the caller reads it with :func:`read_rest`)."""
    if not terminal:
        proc = subprocess.Popen(command, stderr=subprocess.PIPE, **popen)
        if until is None:
            _, err = proc.communicate(timeout=300)
            return proc, err.decode()
        proc.reader, text = proc.stderr.fileno(), ""
    else:
        reader, writer = pty.openpty()
        # a terminal's size, as a window gives it (an unset one reads 0 x 0)
        fcntl.ioctl(writer, termios.TIOCSWINSZ, struct.pack("HHHH", 24, columns, 0, 0))
        proc = subprocess.Popen(command, stderr=writer, **popen)
        os.close(writer)  # the child holds it: reading ends when the child has ended
        proc.reader, text = reader, ""
    while until is None or not until(text):
        chunk = _read(proc.reader)
        if not chunk:
            break
        text += chunk
    if until is not None:
        return proc, text
    proc.wait(timeout=300)
    os.close(proc.reader)
    return proc, text


def read_rest(proc):
    """What ``proc`` (of :func:`stderr_of` with ``until``) writes on standard error from now to
    its end; it has ended when this returns."""
    text = ""
    while chunk := _read(proc.reader):
        text += chunk
    proc.wait(timeout=300)
    if proc.stderr is None:  # the terminal's end (a pipe's closes with its file)
        os.close(proc.reader)
    return text


def _read(fd):
    try:
        return os.read(fd, 65536).decode(errors="replace")
    except OSError:  # EIO: the terminal's other end is closed (Linux)
        return ""
