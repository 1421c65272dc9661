"""Deterministic image writers: display PNG (8 or 16 bit) and linear CIE XYZ OpenEXR.

Both writers produce byte-identical files for identical input (no timestamps, no text chunks, fixed
compression settings) and write atomically through :func:`reflectance.io.atomic.atomic_write`, so an
interrupted run never leaves a partial image that Snakemake would take for a finished one.

The PNG encoder is a few lines of numpy + zlib rather than Pillow: Pillow cannot write 16-bit RGB,
and one code path for both depths keeps the output independent of Pillow's encoder defaults.

References
----------
-   Portable Network Graphics (PNG) Specification (Second Edition), W3C Recommendation 2003 /
    ISO/IEC 15948:2003: §5.2 signature, §5.3 chunk layout and CRC-32, §9.2 filter types (type 0,
    None), §10 zlib deflate compression, §11.2.2 IHDR.
-   OpenEXR, "Standard Optional Attributes" (openexr.com): ``chromaticities`` gives the CIE (x, y)
    of the channel triples (1, 0, 0), (0, 1, 0), (0, 0, 1) and (1, 1, 1) (ImfChromaticities.h).
    For channels holding X, Y, Z those are (1, 0), (0, 1), (0, 0) and (1/3, 1/3). Channel names
    X, Y, Z follow pfstools (pfsinexr / pfsoutexr); note that some tools read a lone "Z" channel
    as depth, which the X and Y channels beside it disambiguate.
"""

from __future__ import annotations

import json
import struct
import zlib
from collections.abc import Mapping
from pathlib import Path

import numpy as np
import OpenEXR

from reflectance.io.atomic import atomic_write

__all__ = ["PNG_BIT_DEPTHS", "write_png", "XYZ_CHROMATICITIES", "write_exr_XYZ", "read_exr"]

PNG_BIT_DEPTHS = (8, 16)

_PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"  # PNG specification (2003) §5.2
_PNG_COLOUR_TYPES = {1: 0, 3: 2, 4: 6}  # channels -> PNG colour type (grey, RGB, RGBA), §11.2.2

XYZ_CHROMATICITIES = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0 / 3.0, 1.0 / 3.0)
"""``chromaticities`` attribute of an XYZ image: red (1, 0), green (0, 1), blue (0, 0), white
(1/3, 1/3): the xy of X = (1, 0, 0), Y = (0, 1, 0), Z = (0, 0, 1) and of the equal-energy white."""

# OpenEXR attributes the library writes or reserves itself; user attributes may not replace them.
_EXR_RESERVED = frozenset(
    {
        "channels", "compression", "dataWindow", "displayWindow", "lineOrder",
        "pixelAspectRatio", "screenWindowCenter", "screenWindowWidth", "chromaticities", "type",
        "name", "tiles", "version", "chunkCount", "view", "multiView",
    }
)


def _finite_array(array, name):
    try:
        array = np.asarray(array, dtype=np.float64)
    except (TypeError, ValueError) as error:
        raise ValueError(f"{name}: not a numeric array ({error})") from error
    if not np.all(np.isfinite(array)):
        bad = np.size(array) - np.count_nonzero(np.isfinite(array))
        raise ValueError(f"{name}: contains NaN or inf ({bad} non-finite values)")
    return array


def _png_chunk(kind, data):
    # PNG specification (2003) §5.3: length, type, data, CRC-32 over type and data.
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def write_png(path, rgb01, bit_depth=8):
    """Write display RGB in [0, 1] as a PNG, 8 or 16 bits per channel, deterministically.

    Values are quantised to the nearest code ``round(v * (2^b - 1))`` (ties to even). Rows use
    filter type 0 and the whole image is one zlib stream at level 9, in one IDAT chunk; the file
    holds only IHDR, IDAT and IEND (no time or text chunks), so identical input gives identical
    bytes.

    Parameters
    ----------
    path : str or Path
        Output file (written atomically; its folder is created).
    rgb01 : array_like
        Shape ``(H, W, 3)`` RGB, ``(H, W, 4)`` RGBA or ``(H, W)`` grey; finite values in [0, 1]
        (encoded, i.e. after the transfer function: see :func:`reflectance.colour.display.XYZ_to_display`).
    bit_depth : int
        8 or 16.

    Raises
    ------
    ValueError
        Naming ``rgb01`` (shape, NaN / inf, values outside [0, 1]) or ``bit_depth``.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> target = pathlib.Path(tempfile.mkdtemp()) / "grey.png"
    >>> write_png(target, np.full((2, 3, 3), 0.5))
    >>> target.read_bytes()[:8] == b"\\x89PNG\\r\\n\\x1a\\n"
    True
    """
    if isinstance(bit_depth, bool) or bit_depth not in PNG_BIT_DEPTHS:
        raise ValueError(f"bit_depth: must be one of {PNG_BIT_DEPTHS}, got {bit_depth!r}")
    image = _finite_array(rgb01, "rgb01")
    if image.ndim == 2:
        image = image[..., None]
    if image.ndim != 3 or image.shape[-1] not in _PNG_COLOUR_TYPES or 0 in image.shape[:2]:
        raise ValueError(
            f"rgb01: expected shape (H, W), (H, W, 3) or (H, W, 4) with H, W >= 1, got "
            f"{np.shape(rgb01)}"
        )
    if image.min() < 0 or image.max() > 1:
        raise ValueError(
            f"rgb01: values must lie in [0, 1], got min {image.min():.6g}, max {image.max():.6g}"
        )
    height, width, channels = image.shape
    samples = np.empty(image.shape, ">u2" if bit_depth == 16 else np.uint8)
    step = max(1, (1 << 20) // (width * channels))  # rows quantised at once: small temporaries
    for start in range(0, height, step):
        codes = image[start:start + step] * (2**bit_depth - 1)
        samples[start:start + step] = np.rint(codes, out=codes)
    rows = samples.reshape(height, width * channels).view(np.uint8).reshape(height, -1)
    # PNG specification (2003) §9.2: each scanline starts with its filter type byte (0 = None).
    raw = np.concatenate([np.zeros((height, 1), dtype=np.uint8), rows], axis=1).tobytes()
    header = struct.pack(
        ">IIBBBBB", width, height, bit_depth, _PNG_COLOUR_TYPES[channels], 0, 0, 0
    )  # §11.2.2 IHDR: compression 0, filter method 0, no interlace
    data = (
        _PNG_SIGNATURE
        + _png_chunk(b"IHDR", header)
        + _png_chunk(b"IDAT", zlib.compress(raw, 9))
        + _png_chunk(b"IEND", b"")
    )
    with atomic_write(path) as tmp:
        Path(tmp).write_bytes(data)


def _attribute_text(key, value):
    if not isinstance(key, str) or not key or key in _EXR_RESERVED:
        raise ValueError(
            f"attributes: key {key!r} must be a non-empty string and not one of OpenEXR's own "
            f"attributes ({', '.join(sorted(_EXR_RESERVED))})"
        )
    if isinstance(value, str):
        return value
    try:
        return json.dumps(value, sort_keys=True, allow_nan=False)
    except (TypeError, ValueError) as error:
        raise ValueError(
            f"attributes[{key!r}]: value {value!r} is neither a string nor JSON-serialisable "
            f"({error})"
        ) from error


def write_exr_XYZ(path, XYZ, attributes=None):
    """Write a linear CIE XYZ image as a float32 OpenEXR file, deterministically.

    Channels ``X``, ``Y``, ``Z`` (FLOAT), ZIP compression, scanline image, ``chromaticities`` set
    to :data:`XYZ_CHROMATICITIES`, and every entry of ``attributes`` as a string attribute (strings
    as given, other values as JSON), e.g. the render parameters. OpenEXR writes no timestamp, so
    identical input gives identical bytes.

    Parameters
    ----------
    path : str or Path
        Output file (written atomically; its folder is created).
    XYZ : array_like
        Shape ``(H, W, 3)``, finite, representable in float32.
    attributes : mapping, optional
        ``{name: value}``; names may not shadow OpenEXR's own attributes.

    Raises
    ------
    ValueError
        Naming ``XYZ`` (shape, NaN / inf, float32 overflow) or ``attributes`` (bad key or value).

    Examples
    --------
    >>> import pathlib, tempfile
    >>> target = pathlib.Path(tempfile.mkdtemp()) / "xyz.exr"
    >>> write_exr_XYZ(target, np.ones((2, 3, 3)), {"material": "copper"})
    >>> XYZ, header = read_exr(target)
    >>> XYZ.shape, header["material"]
    ((2, 3, 3), 'copper')
    """
    XYZ = _finite_array(XYZ, "XYZ")
    if XYZ.ndim != 3 or XYZ.shape[-1] != 3 or 0 in XYZ.shape[:2]:
        raise ValueError(f"XYZ: expected shape (H, W, 3) with H, W >= 1, got {XYZ.shape}")
    if max(XYZ.max(), -XYZ.min()) > np.finfo(np.float32).max:  # (no temporary of |XYZ|)
        raise ValueError("XYZ: values exceed the float32 range of the EXR file")
    if attributes is not None and not isinstance(attributes, Mapping):
        raise ValueError(f"attributes: expected a mapping, got {type(attributes).__name__}")
    texts = {key: _attribute_text(key, value) for key, value in (attributes or {}).items()}
    header = {
        "compression": OpenEXR.ZIP_COMPRESSION,
        "type": OpenEXR.scanlineimage,
        "chromaticities": XYZ_CHROMATICITIES,
        **dict(sorted(texts.items())),
    }
    channels = {
        name: np.ascontiguousarray(XYZ[..., i], dtype=np.float32) for i, name in enumerate("XYZ")
    }
    with atomic_write(path) as tmp:
        with OpenEXR.File(header, channels) as exr:
            exr.write(str(tmp))


def read_exr(path):
    """Read an XYZ OpenEXR image written by :func:`write_exr_XYZ` (or any file with X, Y, Z).

    Parameters
    ----------
    path : str or Path

    Returns
    -------
    tuple
        ``(XYZ, header)``: float32 array ``(H, W, 3)`` and the header as a dict (OpenEXR's Python
        values: string attributes are ``str``, ``chromaticities`` a tuple of 8 floats).

    Raises
    ------
    FileNotFoundError
        If ``path`` does not exist.
    ValueError
        If the file is not OpenEXR or lacks an X, Y or Z channel (naming the file).
    """
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"path: no such file {path}")
    if not OpenEXR.isOpenExrFile(str(path)):
        raise ValueError(f"path: {path} is not an OpenEXR file")
    with OpenEXR.File(str(path), separate_channels=True) as exr:
        header = dict(exr.header())
        found = exr.channels()
        missing = [name for name in "XYZ" if name not in found]
        if missing:
            raise ValueError(
                f"path: {path} has no channel(s) {', '.join(missing)}; channels: "
                f"{', '.join(found)}"
            )
        XYZ = np.stack([np.asarray(found[name].pixels, dtype=np.float32) for name in "XYZ"], -1)
    return XYZ, header
