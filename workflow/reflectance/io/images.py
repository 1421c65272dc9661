"""Deterministic image writers: display PNG (8 or 16 bit, tagged with its colour space) and linear
OpenEXR (CIE XYZ, or display-referred linear RGB).

Both writers produce byte-identical files for identical input (no timestamps, no text chunks, fixed
compression settings) and write atomically through :func:`reflectance.io.atomic.atomic_write`, so an
interrupted run never leaves a partial image that Snakemake would take for a finished one.

The PNG encoder is a few lines of numpy + zlib rather than Pillow: Pillow cannot write 16-bit RGB,
and one code path for both depths keeps the output independent of Pillow's encoder defaults.

A display PNG is tagged with its colour space (:class:`ColourTag`): sRGB by its own chunk, any other
space (SMPTE-C) by an ICC profile written here (:func:`icc_profile_v2`: a 128-byte header and
nine tags). Pillow's ImageCms, the one littlecms binding at hand, builds only its fixed
sRGB, Lab and XYZ profiles (``ImageCms.createProfile``), not one of given primaries; it does read
this one, and the tests convert through it with littlecms against colour-science.

References
----------
-   Portable Network Graphics (PNG) Specification (Second Edition), W3C Recommendation 2003 /
    ISO/IEC 15948:2003: §5.2 signature, §5.3 chunk layout and CRC-32, §9.2 filter types (type 0,
    None), §10 zlib deflate compression, §11.2.2 IHDR.
-   PNG specification §11.3.3: cHRM (chromaticities x 100000), gAMA (100000 / gamma), iCCP
    (name, 0, zlib-compressed ICC profile), sRGB (rendering intent); §11.3.3.5: an sRGB image
    should carry gAMA 45455 and cHRM with the sRGB values beside the sRGB chunk, for decoders
    that do not know it; iCCP and sRGB are never both present.
-   International Color Consortium, ICC.1:2001-04 (profile version 2.4): §6.1 header, §6.2 tag
    table, §6.5 tags of a three-component matrix-based display profile (rXYZ, gXYZ, bXYZ, rTRC,
    gTRC, bTRC, wtpt), §6.3.4.2 desc, cprt; colorants relative to the D50 PCS through a
    chromatic adaptation (Bradford, Annex A of ICC.1:2010 recommends it), media white point the
    display's own white.
-   OpenEXR, "Standard Optional Attributes" (openexr.com): ``chromaticities`` gives the CIE (x, y)
    of the channel triples (1, 0, 0), (0, 1, 0), (0, 0, 1) and (1, 1, 1) (ImfChromaticities.h).
    For channels holding X, Y, Z those are (1, 0), (0, 1), (0, 0) and (1/3, 1/3). Channel names
    X, Y, Z follow pfstools (pfsinexr / pfsoutexr); note that some tools read a lone "Z" channel
    as depth, which the X and Y channels beside it disambiguate.
"""

from __future__ import annotations

import dataclasses
import json
import os
import struct
import zlib
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
import OpenEXR

from reflectance.io.atomic import atomic_write

__all__ = [
    "PNG_BIT_DEPTHS",
    "ColourTag",
    "SRGB_TAG",
    "icc_profile_v2",
    "write_png",
    "tag_png",
    "XYZ_CHROMATICITIES",
    "write_exr_XYZ",
    "write_exr_RGB",
    "tag_chromaticities",
    "read_exr",
]

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


@dataclasses.dataclass(frozen=True)
class ColourTag:
    """The colour space a PNG declares: what a viewer needs to show the intended colours.

    Attributes
    ----------
    name : str
        Printable name (ASCII; the ICC profile's description and the iCCP chunk's name).
    primaries : tuple
        CIE 1931 ``((x_R, y_R), (x_G, y_G), (x_B, y_B))`` of the display primaries.
    whitepoint : tuple
        ``(x, y)`` of the display white (R = G = B = 1).
    transfer : str or float
        ``"sRGB"`` (IEC 61966-2-1: the PNG gets the sRGB chunk) or a pure power ``gamma``
        (linear = encoded^gamma: the PNG gets an ICC profile whose curves are that power).
    """

    name: str
    primaries: tuple
    whitepoint: tuple
    transfer: object


SRGB_TAG = ColourTag("sRGB", ((0.64, 0.33), (0.30, 0.60), (0.15, 0.06)), (0.3127, 0.3290), "sRGB")
"""The sRGB display (IEC 61966-2-1:1999 §5.1: its primaries and D65 white), the colour space
of whatever matplotlib and VTK draw: their colours are sRGB values, written as they are."""

# ICC.1:2001-04 §6.1: the PCS illuminant D50 as stored in every profile (s15Fixed16 of these).
_ICC_D50 = (0.9642, 1.0, 0.8249)
_ICC_DATE = (2000, 1, 1, 0, 0, 0)  # a fixed creation date: identical tags, identical bytes


def _s15f16(values):
    return b"".join(struct.pack(">i", int(round(v * 65536))) for v in values)


def _icc_text_description(text):
    # ICC.1:2001-04 §6.5.17 textDescriptionType: ASCII (with NUL), empty Unicode and ScriptCode
    ascii_ = text.encode("ascii") + b"\0"
    return (b"desc" + bytes(4) + struct.pack(">I", len(ascii_)) + ascii_
            + struct.pack(">II", 0, 0) + struct.pack(">HB", 0, 0) + bytes(67))


def icc_profile_v2(tag: ColourTag, copyright: str = "No copyright, use freely") -> bytes:
    """An ICC version 2.4 RGB display profile (matrix/TRC) for a :class:`ColourTag` with a power
    transfer, as bytes; identical input gives identical bytes.

    The colorants (rXYZ, gXYZ, bXYZ) are the columns of the normalised primary matrix of the
    tag's primaries and white (``colour.normalised_primary_matrix``) adapted to the D50 PCS with
    the Bradford transform (``colour.adaptation.matrix_chromatic_adaptation_VonKries``); wtpt is
    the display white (Y = 1); the three curves share one 1024-entry table of
    ``encoded^gamma``.

    Examples
    --------
    >>> tag = ColourTag("test", ((0.64, 0.33), (0.3, 0.6), (0.15, 0.06)), (0.3127, 0.329), 2.4)
    >>> profile = icc_profile_v2(tag)
    >>> profile[36:40], profile[12:20], len(profile) == int.from_bytes(profile[:4], "big")
    (b'acsp', b'mntrRGB ', True)
    """
    import colour

    gamma = tag.transfer
    if isinstance(gamma, bool) or not isinstance(gamma, (int, float)) or not 0 < gamma < 10:
        raise ValueError(f"tag.transfer: an ICC profile needs a power 0 < gamma < 10, got "
                         f"{gamma!r}")
    primaries = np.asarray(tag.primaries, dtype=np.float64).reshape(3, 2)
    white_xy = np.asarray(tag.whitepoint, dtype=np.float64).reshape(2)
    M = colour.normalised_primary_matrix(primaries, white_xy)
    white = colour.xy_to_XYZ(white_xy)
    adapt = colour.adaptation.matrix_chromatic_adaptation_VonKries(
        white, np.array(_ICC_D50), transform="Bradford")
    colorants = adapt @ M  # columns: the primaries in the D50 PCS
    curve = np.rint(65535 * np.linspace(0.0, 1.0, 1024) ** float(gamma)).astype(">u2")
    xyz = lambda v: b"XYZ " + bytes(4) + _s15f16(v)  # noqa: E731 - §6.5.26 XYZType
    blocks = [  # (signatures sharing the data, data)
        ((b"desc",), _icc_text_description(tag.name)),
        ((b"cprt",), b"text" + bytes(4) + copyright.encode("ascii") + b"\0"),
        ((b"wtpt",), xyz(white)),
        ((b"rXYZ",), xyz(colorants[:, 0])),
        ((b"gXYZ",), xyz(colorants[:, 1])),
        ((b"bXYZ",), xyz(colorants[:, 2])),
        ((b"rTRC", b"gTRC", b"bTRC"),  # §6.5.3 curveType
         b"curv" + bytes(4) + struct.pack(">I", len(curve)) + curve.tobytes()),
    ]
    count = sum(len(signatures) for signatures, _ in blocks)
    offset = 128 + 4 + 12 * count
    table, data = [], b""
    for signatures, block in blocks:
        for signature in signatures:
            table.append(struct.pack(">4sII", signature, offset + len(data), len(block)))
        data += block + bytes(-len(block) % 4)  # each tag starts on a 4-byte boundary
    body = struct.pack(">I", count) + b"".join(table) + data
    size = 128 + len(body)
    header = (struct.pack(">I", size) + bytes(4) + bytes([2, 0x40, 0, 0])  # version 2.4.0
              + b"mntr" + b"RGB " + b"XYZ " + struct.pack(">6H", *_ICC_DATE) + b"acsp"
              + bytes(4 + 4 + 4 + 4 + 8) + struct.pack(">I", 0)  # platform ... intent 0
              + _s15f16(_ICC_D50) + bytes(4) + bytes(44))
    assert len(header) == 128
    return header + body


def _png_colour_chunks(tag):
    """cHRM, gAMA and sRGB or iCCP chunks declaring ``tag`` (PNG specification §11.3.3)."""
    if not isinstance(tag, ColourTag):
        raise ValueError(f"tag: expected a ColourTag or None, got {type(tag).__name__}")
    points = [*np.asarray(tag.whitepoint, np.float64).reshape(2),
              *np.asarray(tag.primaries, np.float64).reshape(6)]
    chrm = _png_chunk(b"cHRM", struct.pack(">8I", *(int(round(v * 100000)) for v in points)))
    if tag.transfer == "sRGB":
        # §11.3.3.5: sRGB (rendering intent 1, relative colorimetric: the colours as computed),
        # with gAMA and cHRM for decoders that do not read sRGB
        return (chrm + _png_chunk(b"gAMA", struct.pack(">I", 45455))
                + _png_chunk(b"sRGB", bytes([1])))
    profile = icc_profile_v2(tag)
    name = tag.name.encode("latin-1")[:79]
    return (chrm + _png_chunk(b"gAMA", struct.pack(">I", int(round(100000 / tag.transfer))))
            + _png_chunk(b"iCCP", name + b"\0\0" + zlib.compress(profile, 9)))


def write_png(path: str | os.PathLike[str], rgb01: npt.ArrayLike, bit_depth: int = 8,
              tag: ColourTag | None = None) -> None:
    """Write display RGB in [0, 1] as a PNG, 8 or 16 bits per channel, deterministically.

    Values are quantised to the nearest code ``round(v * (2^b - 1))`` (ties to even). Rows use
    filter type 0 and the whole image is one zlib stream at level 9, in one IDAT chunk; the file
    holds only IHDR, the colour chunks of ``tag``, IDAT and IEND (no time or text chunks), so
    identical input gives identical bytes.

    Parameters
    ----------
    path : str or Path
        Output file (written atomically; its folder is created).
    rgb01 : array_like
        Shape ``(H, W, 3)`` RGB, ``(H, W, 4)`` RGBA or ``(H, W)`` grey; finite values in [0, 1]
        (encoded, i.e. after the transfer function: see :func:`reflectance.colour.display.XYZ_to_display`).
    bit_depth : int
        8 or 16.
    tag : ColourTag, optional
        The colour space of the encoded values: with ``transfer="sRGB"`` the file carries the
        sRGB, gAMA and cHRM chunks; with a power transfer, cHRM, gAMA and an ICC profile (iCCP,
        :func:`icc_profile_v2`). Without it the file is untagged (viewers assume sRGB).

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
    colour_chunks = b"" if tag is None else _png_colour_chunks(tag)
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
        + colour_chunks  # §5.6: before IDAT
        + _png_chunk(b"IDAT", zlib.compress(raw, 9))
        + _png_chunk(b"IEND", b"")
    )
    with atomic_write(path) as tmp:
        Path(tmp).write_bytes(data)


_PNG_COLOUR_CHUNK_TYPES = (b"cHRM", b"gAMA", b"iCCP", b"sRGB", b"cICP")


def tag_png(data: bytes, tag: ColourTag) -> bytes:
    """The PNG ``data`` (bytes) with the colour chunks of ``tag`` added: the same cHRM, gAMA and
    sRGB or iCCP chunks :func:`write_png` writes, placed right after IHDR (PNG specification
    §5.6: before PLTE and IDAT). The pixels and every other chunk are kept byte for byte, so
    identical input gives identical bytes. This tags a PNG another encoder made (matplotlib's,
    through Pillow) without decoding it.

    Raises
    ------
    ValueError
        If ``data`` is not a PNG starting with IHDR, or already declares a colour space (a cHRM,
        gAMA, iCCP, sRGB or cICP chunk: a second declaration would contradict the first).

    Examples
    --------
    >>> import pathlib, tempfile
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "grey.png"
    >>> write_png(path, np.full((2, 3), 0.5))
    >>> tagged = tag_png(path.read_bytes(), SRGB_TAG)
    >>> b"sRGB" in tagged, tagged[:8] == _PNG_SIGNATURE
    (True, True)
    """
    data = bytes(data)
    if data[:8] != _PNG_SIGNATURE or data[12:16] != b"IHDR":
        raise ValueError("data: not a PNG file (no signature and IHDR chunk)")
    position = 8
    while position + 8 <= len(data):  # walk the chunk list (§5.3: length, type, data, CRC)
        (length,) = struct.unpack(">I", data[position:position + 4])
        kind = data[position + 4:position + 8]
        if kind in _PNG_COLOUR_CHUNK_TYPES:
            raise ValueError(f"data: the PNG already declares its colour space ({kind.decode()} "
                             f"chunk)")
        position += 12 + length
    end_of_IHDR = 8 + 12 + struct.unpack(">I", data[8:12])[0]
    return data[:end_of_IHDR] + _png_colour_chunks(tag) + data[end_of_IHDR:]


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


def write_exr_XYZ(path: str | os.PathLike[str], XYZ: npt.ArrayLike,
                  attributes: Mapping[str, Any] | None = None) -> None:
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
    _write_exr(path, XYZ, "XYZ", XYZ_CHROMATICITIES, attributes)


def _write_exr(path, image, names, chromaticities, attributes):
    label = names
    image = _finite_array(image, label)
    if image.ndim != 3 or image.shape[-1] != 3 or 0 in image.shape[:2]:
        raise ValueError(f"{label}: expected shape (H, W, 3) with H, W >= 1, got {image.shape}")
    if max(image.max(), -image.min()) > np.finfo(np.float32).max:  # (no temporary of |image|)
        raise ValueError(f"{label}: values exceed the float32 range of the EXR file")
    if attributes is not None and not isinstance(attributes, Mapping):
        raise ValueError(f"attributes: expected a mapping, got {type(attributes).__name__}")
    texts = {key: _attribute_text(key, value) for key, value in (attributes or {}).items()}
    header = {
        "compression": OpenEXR.ZIP_COMPRESSION,
        "type": OpenEXR.scanlineimage,
        "chromaticities": tuple(float(v) for v in chromaticities),
        **dict(sorted(texts.items())),
    }
    channels = {
        name: np.ascontiguousarray(image[..., i], dtype=np.float32) for i, name in enumerate(names)
    }
    with atomic_write(path) as tmp:
        with OpenEXR.File(header, channels) as exr:
            try:
                exr.write(str(tmp))
            except RuntimeError as err:  # OpenEXR says only that it failed (issue 25)
                raise _write_error(tmp, err) from None


def _write_error(path, err):
    """An OSError naming ``path`` for a writer's RuntimeError: a full disk said as such."""
    import errno
    import os

    try:
        full = os.statvfs(Path(path).parent).f_bavail == 0
    except OSError:
        full = False
    if full:
        return OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(path))
    first = (str(err).strip().splitlines() or ["failed"])[0].replace(f' "{path}"', "")
    return OSError(errno.EIO, f"the writer failed ({first[:200]})", str(path))


def tag_chromaticities(tag: ColourTag) -> tuple[float, ...]:
    """OpenEXR ``chromaticities`` of a :class:`ColourTag`: red, green, blue and white (x, y)."""
    return (*np.asarray(tag.primaries, np.float64).reshape(6).tolist(),
            *np.asarray(tag.whitepoint, np.float64).reshape(2).tolist())


def write_exr_RGB(path: str | os.PathLike[str], RGB: npt.ArrayLike, tag: ColourTag,
                  attributes: Mapping[str, Any] | None = None) -> None:
    """Write display-referred linear RGB as a float32 OpenEXR file, deterministically.

    As :func:`write_exr_XYZ`, with channels ``R``, ``G``, ``B`` and ``chromaticities`` the
    primaries and white of ``tag`` (a :class:`ColourTag`), the file most image viewers show as
    intended: linear light of the display (no transfer function).

    Examples
    --------
    >>> import pathlib, tempfile
    >>> target = pathlib.Path(tempfile.mkdtemp()) / "rgb.exr"
    >>> tag = ColourTag("sRGB", ((0.64, 0.33), (0.3, 0.6), (0.15, 0.06)), (0.3127, 0.329), "sRGB")
    >>> write_exr_RGB(target, np.ones((2, 3, 3)), tag)
    >>> RGB, header = read_exr(target, channels="RGB")
    >>> RGB.shape, [round(v, 4) for v in header["chromaticities"][:2]]
    ((2, 3, 3), [0.64, 0.33])
    """
    if not isinstance(tag, ColourTag):
        raise ValueError(f"tag: expected a ColourTag, got {type(tag).__name__}")
    _write_exr(path, RGB, "RGB", tag_chromaticities(tag), attributes)


def read_exr(path: str | os.PathLike[str],
             channels: str = "XYZ") -> tuple[npt.NDArray[np.float32], dict[str, Any]]:
    """Read an XYZ OpenEXR image written by :func:`write_exr_XYZ` (or any file with X, Y, Z;
    ``channels="RGB"``: R, G, B, as :func:`write_exr_RGB` writes them).

    Parameters
    ----------
    path : str or Path
    channels : str
        ``"XYZ"`` or ``"RGB"``: the three channels read, in that order.

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
    if channels not in ("XYZ", "RGB"):
        raise ValueError(f"channels: must be 'XYZ' or 'RGB', got {channels!r}")
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"path: no such file {path}")
    if not OpenEXR.isOpenExrFile(str(path)):
        raise ValueError(f"path: {path} is not an OpenEXR file")
    with OpenEXR.File(str(path), separate_channels=True) as exr:
        header = dict(exr.header())
        found = exr.channels()
        missing = [name for name in channels if name not in found]
        if missing:
            raise ValueError(
                f"path: {path} has no channel(s) {', '.join(missing)}; channels: "
                f"{', '.join(found)}"
            )
        XYZ = np.stack([np.asarray(found[name].pixels, dtype=np.float32) for name in channels],
                       -1)
    return XYZ, header
