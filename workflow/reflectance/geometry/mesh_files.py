"""Mesh files checked before VTK reads them (issue 25, "native crashes").

VTK's readers trust a file: a PLY face index past the last vertex, or a binary PLY cut short,
crashes the process (segmentation fault, no message); a header that claims two billion
vertices allocates them; OBJ, legacy VTK and VTP readers keep an index out of range, which a
later filter or the renderer then follows into foreign memory. :func:`check_mesh_file` reads
each format the scene schema accepts (OBJ, PLY, STL, VTK, VTP) with numpy first: every count
its header declares against the bytes the file holds, every index against the vertex count,
every coordinate finite. :func:`check_read_mesh` repeats the last two on what VTK read (the
formats whose binary payload is not parsed here: legacy VTK's and VTP's). Each problem is a
``ValueError`` of one line that starts with the file's path.
"""

from __future__ import annotations

import os
import re
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pyvista as pv

__all__ = ["check_mesh_file", "check_read_mesh"]

_HEADER_LIMIT = 1 << 16
"""Bytes a PLY header or a legacy VTK section line may take."""

_PLY_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2",
              "int16": "i2", "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4",
              "uint": "u4", "uint32": "u4", "float": "f4", "float32": "f4", "double": "f8",
              "float64": "f8"}

_VTK_TYPES = {"bit": None, "unsigned_char": "u1", "char": "i1", "unsigned_short": "u2",
              "short": "i2", "unsigned_int": "u4", "int": "i4", "unsigned_long": "u8",
              "long": "i8", "float": "f4", "double": "f8", "vtktypeint64": "i8",
              "vtktypeuint64": "u8", "vtkidtype": "i8", "vtktypeint32": "i4"}

_ZLIB_RATIO = 1032
"""zlib's largest compression ratio (deflate's limit): a compressed VTP array holds at most
this many bytes per stored byte (RFC 1951's longest match, 258 bytes in a 2-bit code)."""


class _Bad(ValueError):
    pass


def _indices(path, what, index, count):
    index = np.asarray(index)
    if index.size and (index.min() < 0 or index.max() >= count):
        bad = index[(index < 0) | (index >= count)].ravel()[0]
        raise _Bad(f"{what} index {int(bad)} is out of range: the file has {count} vertices")


def _finite(path, points):
    points = np.asarray(points)
    if points.size and not np.isfinite(points).all():
        row = int(np.flatnonzero(~np.isfinite(points).all(axis=-1))[0])
        raise _Bad(f"vertex {row} has a coordinate that is not finite "
                   f"({', '.join(str(v) for v in points[row])})")


# --- PLY --------------------------------------------------------------------------------------

def _ply_header(data):
    end = data.find(b"end_header", 0, _HEADER_LIMIT)
    if not data.startswith(b"ply") or end < 0:
        raise _Bad("not a PLY file (no 'ply' ... 'end_header' header in its first 64 KiB)")
    body = data.index(b"\n", end) + 1 if b"\n" in data[end:end + 64] else len(data)
    fmt, elements = None, []
    for line in data[:end].decode("ascii", "replace").splitlines()[1:]:
        words = line.split()
        if not words or words[0] in ("comment", "obj_info"):
            continue
        if words[0] == "format" and len(words) == 3:
            fmt = words[1]
        elif words[0] == "element" and len(words) == 3 and words[2].isdigit():
            elements.append((words[1], int(words[2]), []))
        elif words[0] == "property" and elements and len(words) == 3 and words[1] in _PLY_TYPES:
            elements[-1][2].append((words[2], None, _PLY_TYPES[words[1]]))
        elif (words[0] == "property" and elements and len(words) == 5 and words[1] == "list"
              and words[2] in _PLY_TYPES and words[3] in _PLY_TYPES):
            elements[-1][2].append((words[4], _PLY_TYPES[words[2]], _PLY_TYPES[words[3]]))
        else:
            raise _Bad(f"header line {line.strip()!r} is not PLY")
    if fmt not in ("ascii", "binary_little_endian", "binary_big_endian"):
        raise _Bad(f"PLY format {fmt!r}; known: ascii, binary_little_endian, binary_big_endian")
    names = [e[0] for e in elements]
    if "vertex" not in names:
        raise _Bad("the PLY header declares no vertex element")
    vertex = elements[names.index("vertex")]
    if not {"x", "y", "z"} <= {p[0] for p in vertex[2]} or any(p[1] for p in vertex[2]):
        raise _Bad("the PLY vertex element needs scalar properties x, y, z")
    return fmt, elements, body


def _ply_binary(data, order, elements, at):
    size, n_vertices, points = len(data), None, None
    for name, count, props in elements:
        if all(p[1] is None for p in props):
            dtype = np.dtype([(p[0], order + p[2]) for p in props])
            need = count * dtype.itemsize
            if need > size - at:
                raise _Bad(f"the header declares {count} {name} elements ({need} bytes) but only "
                           f"{size - at} bytes follow it: the file is truncated or its header wrong")
            table = np.frombuffer(data, dtype, count, at)
            at += need
            if name == "vertex":
                n_vertices = count
                points = np.column_stack([table[c].astype(np.float64) for c in "xyz"])
            continue
        if len(props) != 1:
            raise _Bad(f"PLY element {name!r} mixes a list with other properties")
        _, count_type, index_type = props[0]
        cdt, idt = np.dtype(order + count_type), np.dtype(order + index_type)
        if count * cdt.itemsize > size - at:
            raise _Bad(f"the header declares {count} {name} elements but only {size - at} bytes "
                       f"follow: the file is truncated or its header wrong")
        lists = []
        if count:  # most files hold lists of one length: read them in one view, else walk
            first = int(np.frombuffer(data, cdt, 1, at)[0])
            stride = cdt.itemsize + first * idt.itemsize
            if count * stride <= size - at:
                rows = np.frombuffer(data, np.dtype([("n", cdt), ("i", idt, (first,))]), count, at)
                if (rows["n"] == first).all():
                    lists.append(rows["i"].ravel())
                    at += count * stride
                    count = 0
        for _ in range(count):
            if at + cdt.itemsize > size:
                raise _Bad(f"the {name} lists run past the end of the file: it is truncated")
            n = int(np.frombuffer(data, cdt, 1, at)[0])
            at += cdt.itemsize
            if n < 0 or at + n * idt.itemsize > size:
                raise _Bad(f"the {name} lists run past the end of the file: it is truncated")
            lists.append(np.frombuffer(data, idt, n, at))
            at += n * idt.itemsize
        if name in ("face", "edge", "tristrips") and lists and n_vertices is not None:
            _indices(None, f"{name}", np.concatenate(lists).astype(np.int64), n_vertices)
    return points


def _ply_ascii(data, elements, at):
    lines = data[at:].decode("ascii", "replace").split("\n")
    total = sum(count for _, count, _ in elements)
    if total > len(lines):
        raise _Bad(f"the header declares {total} element lines but the file holds {len(lines)}"
                   ": it is truncated or its header wrong")
    row, n_vertices, points = 0, None, None
    for name, count, props in elements:
        chunk = lines[row:row + count]
        row += count
        if name == "vertex":
            columns = [p[0] for p in props]
            try:
                table = np.array([line.split()[:len(columns)] for line in chunk], np.float64)
            except ValueError:
                raise _Bad("a vertex line does not hold its properties' numbers") from None
            if table.shape != (count, len(columns)):
                raise _Bad("a vertex line does not hold its properties' numbers")
            n_vertices = count
            points = table[:, [columns.index(c) for c in "xyz"]]
        elif len(props) == 1 and props[0][1] is not None and n_vertices is not None:
            for i, line in enumerate(chunk):
                words = line.split()
                try:
                    n, index = int(words[0]), np.array(words[1:], np.int64)
                except (ValueError, IndexError):
                    raise _Bad(f"{name} {i}: not a count and indices") from None
                if n != len(index):
                    raise _Bad(f"{name} {i}: says {n} indices, holds {len(index)}")
                _indices(None, f"{name} {i}'s", index, n_vertices)
    return points


def _ply(data):
    fmt, elements, at = _ply_header(data)
    if fmt == "ascii":
        return _ply_ascii(data, elements, at)
    return _ply_binary(data, "<" if fmt == "binary_little_endian" else ">", elements, at)


# --- STL, OBJ ------------------------------------------------------------------------------

def _stl(data):
    if len(data) >= 84:
        count = int(np.frombuffer(data, "<u4", 1, 80)[0])
        if len(data) == 84 + 50 * count:
            rows = np.frombuffer(data, np.dtype([("normal", "<f4", 3), ("v", "<f4", (3, 3)),
                                                 ("attribute", "<u2")]), count, 84)
            return rows["v"].reshape(-1, 3).astype(np.float64)
    if not data.lstrip().startswith(b"solid"):
        count = int(np.frombuffer(data, "<u4", 1, 80)[0]) if len(data) >= 84 else 0
        raise _Bad(f"a binary STL of {count} triangles has {84 + 50 * count} bytes, this file "
                   f"{len(data)}: it is truncated or its header wrong")
    text = data.decode("ascii", "replace")
    try:
        points = np.array([line.split()[1:4] for line in text.splitlines()
                           if line.strip().startswith("vertex")], np.float64).reshape(-1, 3)
    except ValueError:
        raise _Bad("an ASCII STL 'vertex' line does not hold three numbers") from None
    if len(points) == 0 or len(points) % 3:
        raise _Bad(f"an ASCII STL holds {len(points)} vertices, not three per facet")
    return points


def _obj(data):
    counts = {"v": 0, "vt": 0, "vn": 0}
    highest = dict.fromkeys(counts, 0)
    points = []
    for number, line in enumerate(data.decode("utf-8", "replace").splitlines(), 1):
        words = line.split()
        if not words:
            continue
        key = words[0]
        if key in counts:
            counts[key] += 1
            if key == "v":
                try:
                    points.append([float(w) for w in words[1:4]])
                except ValueError:
                    raise _Bad(f"line {number}: 'v' needs three numbers") from None
                if len(points[-1]) != 3:
                    raise _Bad(f"line {number}: 'v' needs three numbers")
        elif key in ("f", "l", "p"):
            for word in words[1:]:
                for slot, part in zip(("v", "vt", "vn"), word.split("/")):
                    if not part:
                        continue
                    try:
                        i = int(part)
                    except ValueError:
                        raise _Bad(f"line {number}: {word!r} is not an index") from None
                    n = counts[slot]  # negative: relative to the ones given so far
                    if i == 0 or i < -n:
                        raise _Bad(f"line {number}: {slot} index {i} is out of range "
                                   f"({n} given before it)")
                    if i > 0:  # positive: checked against the file's total below
                        highest[slot] = max(highest[slot], i)
    for slot in ("v", "vt", "vn"):
        if highest[slot] > counts[slot]:
            raise _Bad(f"{slot} index {highest[slot]} is out of range: the file has "
                       f"{counts[slot]}")
    return np.array(points, np.float64).reshape(-1, 3)


# --- legacy VTK, VTP -------------------------------------------------------------------------

def _vtk(data):
    head = data[:_HEADER_LIMIT].split(b"\n", 4)
    if len(head) < 5 or not head[0].startswith(b"# vtk DataFile Version"):
        raise _Bad("not a legacy VTK file (no '# vtk DataFile Version' line)")
    binary = head[2].strip().upper() == b"BINARY"
    if not binary and head[2].strip().upper() != b"ASCII":
        raise _Bad(f"the third line must say ASCII or BINARY, not {head[2][:40]!r}")
    # every count a section line declares, against what the rest of the file can hold
    for match in re.finditer(rb"^(POINTS|POLYGONS|TRIANGLE_STRIPS|LINES|VERTICES|CELLS)"
                             rb"[ \t]+(\d+)[ \t]*(\w*)", data, flags=re.M):
        key, count, kind = match.group(1).decode(), int(match.group(2)), match.group(3).decode()
        values = 3 * count if key == "POINTS" else count
        width = np.dtype(_VTK_TYPES.get(kind.lower()) or "u1").itemsize if key == "POINTS" else 1
        need = values * width if binary else 2 * values - 1  # (text: a digit and a space)
        left = len(data) - match.end()
        if need > left:
            raise _Bad(f"{key} declares {count} entries ({need} bytes at least) but only {left} "
                       f"bytes follow: the file is truncated or its header wrong")
    return None


def _vtp(data):
    text = data.decode("utf-8", "replace")
    appended = text.find("<AppendedData")
    head = text if appended < 0 else text[:appended]
    for key, count in re.findall(r'Number(?:Of)?(Points|Polys|Strips|Lines|Verts|Cells)="(\d+)"',
                                 head):
        need = int(count) * (12 if key == "Points" else 4)
        ratio = _ZLIB_RATIO if "compressor=" in head else 1
        if need > ratio * len(data):
            raise _Bad(f"it declares {count} {key.lower()} ({need} bytes at least) in a file of "
                       f"{len(data)} bytes: its header is wrong")
    if appended >= 0:
        if not data.rstrip().endswith(b"</VTKFile>"):
            raise _Bad("it ends before '</VTKFile>': the file is truncated")
        return None
    try:
        root = ET.fromstring(data)
    except ET.ParseError as err:
        raise _Bad(f"not well-formed XML ({err}): the file is truncated or not VTP") from None
    piece = root.find(".//Piece")
    if piece is None:
        raise _Bad("no <Piece> in it: not a VTP file")
    n_points = int(piece.get("NumberOfPoints", "0"))
    points = None
    for array in root.iter("DataArray"):
        if array.get("format") != "ascii":
            continue
        values = np.array((array.text or "").split(), np.float64)
        if array.get("Name") == "connectivity":
            _indices(None, "connectivity", values.astype(np.int64), n_points)
        parent_points = root.find(".//Points/DataArray")
        if array is parent_points:
            points = values.reshape(-1, 3)
    return points


_CHECKS = {".ply": _ply, ".stl": _stl, ".obj": _obj, ".vtk": _vtk, ".vtp": _vtp}


def check_mesh_file(path: str | os.PathLike[str]) -> None:
    """Refuse a mesh file whose header, indices or coordinates VTK would not survive.

    Parameters
    ----------
    path : str or Path
        An OBJ, PLY, STL, VTK (legacy) or VTP file.

    Raises
    ------
    ValueError
        One line: the path, then what is wrong (a declared count the file cannot hold, an index
        past the vertices, a coordinate that is not finite).
    """
    path = Path(path)
    check = _CHECKS.get(path.suffix.lower())
    if check is None:
        return
    data = path.read_bytes()
    try:
        points = check(data)
        if points is not None:
            _finite(path, points)
    except _Bad as err:
        raise ValueError(f"{path}: {err}") from None
    except (ValueError, IndexError, TypeError) as err:  # a malformed number or structure
        raise ValueError(f"{path}: not a readable {path.suffix[1:].upper()} file ({err})") from None


def check_read_mesh(mesh: pv.PolyData, path: str | os.PathLike[str]) -> None:
    """What VTK read from ``path``: every cell's vertex index in range, every point finite.

    Raises
    ------
    ValueError
        One line starting with the path.
    """
    from vtkmodules.util.numpy_support import vtk_to_numpy

    try:
        n_points = mesh.n_points
        _finite(path, np.asarray(mesh.points, np.float64).reshape(-1, 3))
        if hasattr(mesh, "GetPolys"):
            arrays = [mesh.GetVerts(), mesh.GetLines(), mesh.GetPolys(), mesh.GetStrips()]
        else:
            arrays = [mesh.GetCells()] if hasattr(mesh, "GetCells") else []
        for cells in arrays:
            if cells is not None and cells.GetNumberOfCells():
                _indices(path, "a cell's vertex",
                         vtk_to_numpy(cells.GetConnectivityArray()).astype(np.int64), n_points)
    except _Bad as err:
        raise ValueError(f"{path}: {err}") from None
