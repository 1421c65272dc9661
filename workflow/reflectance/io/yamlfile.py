"""YAML read from data (config.yaml, scene files): bounded before it is built.

A YAML document can grow when it is read: an alias repeats the node its anchor names, so nine
levels of ten aliases each (the "billion laughs") are a few hundred bytes of text and 10^9 nodes
once built; a nesting thousands of levels deep exhausts Python's recursion while it is built.
:func:`read_yaml` therefore walks the parser's events first (a state machine: no recursion, no
node built) and refuses, in one line naming the file, a text larger than :data:`MAX_BYTES`, a
nesting deeper than :data:`MAX_DEPTH`, or a document whose aliases expand it to more than
:data:`MAX_NODES` nodes (each alias counted as the size of the node it repeats). Only then is the
document built, by a safe loader (data only) that refuses a key given twice in one mapping
(PyYAML keeps the last), naming both lines.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import yaml

__all__ = ["YAMLFileError", "MAX_BYTES", "MAX_DEPTH", "MAX_NODES", "read_yaml", "load_yaml_text"]

#: Largest YAML text read (bytes): config.yaml is about 47 kB, a scene file a few kB (meshes are
#: files of their own).
MAX_BYTES = 8 * 2**20

#: Deepest nesting of mappings and sequences: config.yaml nests 9 levels, scene files fewer.
MAX_DEPTH = 64

#: Most nodes of a document with its aliases expanded: config.yaml has about 10^4.
MAX_NODES = 10**6


class YAMLFileError(ValueError):
    """A YAML file that cannot be read as data; the message is one line naming the file."""


class _UniqueKeys:
    """A safe loader's mappings, refusing a key given twice in one mapping (PyYAML keeps the
    last)."""

    def construct_mapping(self, node, deep=False):
        seen = {}
        for key_node, _ in node.value:
            key = self.construct_object(key_node, deep=deep)
            mark = key_node.start_mark
            try:
                first = seen.setdefault(key, (mark.line, mark.column))
            except TypeError:  # an unhashable key: PyYAML's own error follows
                continue
            if first != (mark.line, mark.column):  # also twice on one line: {x: 1, x: 2}
                raise yaml.constructor.ConstructorError(
                    None, None, f"key {key!r} given twice (first on line {first[0] + 1})", mark)
        return super().construct_mapping(node, deep=deep)


class UniqueKeyLoader(_UniqueKeys, yaml.SafeLoader):
    """PyYAML's pure-Python safe loader: its syntax errors name the character found."""


#: libyaml's parser where PyYAML has it (ten times faster), with the same mappings and lines.
FastUniqueKeyLoader = (type("FastUniqueKeyLoader", (_UniqueKeys, yaml.CSafeLoader), {})
                       if hasattr(yaml, "CSafeLoader") else UniqueKeyLoader)


def _bounds(text, loader_class):
    """None if the document of ``text`` stays within :data:`MAX_DEPTH` and :data:`MAX_NODES`,
    else what it exceeds (one phrase). Reads the parser's events only; yaml.YAMLError on a
    syntax error."""
    loader = loader_class(text)
    anchors = {}  # anchor -> expanded size of its node
    stack = []  # per open collection: [anchor, expanded size so far]
    total = 0
    try:
        while True:
            event = loader.get_event()
            if event is None or isinstance(event, yaml.StreamEndEvent):
                break
            if isinstance(event, (yaml.MappingStartEvent, yaml.SequenceStartEvent)):
                if len(stack) >= MAX_DEPTH:
                    return (f"line {event.start_mark.line + 1}: nested more than {MAX_DEPTH} "
                            f"levels deep")
                stack.append([event.anchor, 1])
                continue
            if isinstance(event, (yaml.MappingEndEvent, yaml.SequenceEndEvent)):
                anchor, size = stack.pop()
                if anchor is not None:
                    anchors[anchor] = size
            elif isinstance(event, yaml.AliasEvent):
                size = anchors.get(event.anchor, 1)  # an unknown anchor: the loader says so
            elif isinstance(event, yaml.ScalarEvent):
                size = 1
                if event.anchor is not None:
                    anchors[event.anchor] = 1
            else:  # stream and document start and end
                continue
            if stack:
                stack[-1][1] += size
            total += size
            if total > MAX_NODES or (stack and stack[-1][1] > MAX_NODES):
                return (f"line {event.start_mark.line + 1}: its aliases expand it to more than "
                        f"{MAX_NODES:,} nodes")
    finally:
        loader.dispose()
    return None


def _load(text, loader_class):
    problem = _bounds(text, loader_class)
    if problem is not None:
        raise YAMLFileError(problem)
    loader = loader_class(text)  # a safe loader: data only
    try:
        return loader.get_single_data()
    finally:
        loader.dispose()


def _syntax_message(err):
    """', line L, column C: not valid YAML: what' of a PyYAML error (one line)."""
    mark = getattr(err, "problem_mark", None) or getattr(err, "context_mark", None)
    where = f", line {mark.line + 1}, column {mark.column + 1}" if mark else ""
    what = getattr(err, "problem", None) or " ".join(str(err).split())
    context, start = getattr(err, "context", None), getattr(err, "context_mark", None)
    if context and start is not None and start is not mark:
        what += f" ({context} that starts on line {start.line + 1}, column {start.column + 1})"
    elif context:
        what += f" ({context})"
    return f"{where}: not valid YAML: {what}"


def load_yaml_text(text: str, source: str = "<yaml>") -> Any:
    """The document of ``text`` (see :func:`read_yaml`); YAMLFileError naming ``source``.

    Examples
    --------
    >>> load_yaml_text("a: 1\\nb: [2, 3]\\n")
    {'a': 1, 'b': [2, 3]}
    >>> load_yaml_text("a: 1\\na: 2\\n", "s.yaml")
    Traceback (most recent call last):
    ...
    reflectance.io.yamlfile.YAMLFileError: s.yaml, line 2, column 1: not valid YAML: key 'a' given twice (first on line 1)
    >>> load_yaml_text("a: " + "[" * 100 + "]" * 100, "s.yaml")
    Traceback (most recent call last):
    ...
    reflectance.io.yamlfile.YAMLFileError: s.yaml: line 1: nested more than 64 levels deep
    """
    if len(text) > MAX_BYTES:
        raise YAMLFileError(f"{source}: {len(text):,} characters; a YAML file read here holds at "
                            f"most {MAX_BYTES:,}")
    try:
        try:
            return _load(text, FastUniqueKeyLoader)
        except yaml.YAMLError as err:
            mark = getattr(err, "problem_mark", None)
            if "maximum nesting depth" in str(getattr(err, "problem", "")) and mark:
                # libyaml's own bound (1000 levels), met while scanning a flow: said at once (the
                # pure-Python scanner looks ahead over the whole flow first, in quadratic time)
                raise YAMLFileError(f"line {mark.line + 1}: nested more than {MAX_DEPTH} "
                                    f"levels deep") from None
            # the pure-Python parser decides (as Snakemake reads the file); its message names
            # what it found ('\t', the alias)
            return _load(text, UniqueKeyLoader)
    except yaml.YAMLError as err:
        raise YAMLFileError(f"{source}{_syntax_message(err)}") from None
    except YAMLFileError as err:
        raise YAMLFileError(f"{source}: {err}") from None


def read_yaml(path: str | os.PathLike[str], encoding: str = "utf-8") -> Any:
    """The document of the YAML file ``path``, built only if it stays within the bounds
    (:data:`MAX_BYTES`, :data:`MAX_DEPTH`, :data:`MAX_NODES`) and gives no key twice;
    YAMLFileError, one line naming the file (and the line), otherwise. ``encoding``: "utf-8",
    or "utf-8-sig" to allow a byte-order mark."""
    path = Path(path)
    try:
        size = path.stat().st_size
        if size > MAX_BYTES:
            raise YAMLFileError(f"{path}: {size:,} bytes; a YAML file read here holds at most "
                                f"{MAX_BYTES:,}")
        text = path.read_text(encoding=encoding)
    except UnicodeDecodeError as err:
        raise YAMLFileError(f"{path}: not UTF-8 text ({err.reason} at byte {err.start})") \
            from None
    except OSError as err:
        raise YAMLFileError(f"{path}: cannot read: {err.strerror or err}") from None
    return load_yaml_text(text, str(path))
