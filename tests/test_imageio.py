"""Tests of reflectance.io.images: PNG and OpenEXR round trips, determinism, bad input."""

import struct
import zlib

import numpy as np
import OpenEXR
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp
from PIL import Image

from reflectance.io.images import XYZ_CHROMATICITIES, read_exr, write_exr_XYZ, write_png


def read_png_chunks(data):
    """Independent minimal PNG parser: chunk list with CRCs checked (PNG spec 2003 §5.3)."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    chunks, i = [], 8
    while i < len(data):
        (length,) = struct.unpack(">I", data[i : i + 4])
        kind, body = data[i + 4 : i + 8], data[i + 8 : i + 8 + length]
        (crc,) = struct.unpack(">I", data[i + 8 + length : i + 12 + length])
        assert crc == zlib.crc32(kind + body), f"bad CRC in {kind}"
        chunks.append((kind, body))
        i += 12 + length
    return chunks


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else (b if pb <= pc else c)


def read_png(path):
    """Decode a non-interlaced grey / RGB / RGBA PNG of depth 8 or 16, all five filter types."""
    chunks = read_png_chunks(path.read_bytes())
    width, height, depth, colour_type, _, _, interlace = struct.unpack(">IIBBBBB", chunks[0][1])
    assert interlace == 0
    channels = {0: 1, 2: 3, 6: 4}[colour_type]
    bpp = channels * depth // 8
    raw = zlib.decompress(b"".join(body for kind, body in chunks if kind == b"IDAT"))
    stride = width * bpp
    previous, rows = bytearray(stride), []
    for y in range(height):
        line = raw[y * (stride + 1) : (y + 1) * (stride + 1)]
        f, row = line[0], bytearray(line[1:])
        for x in range(stride):
            a = row[x - bpp] if x >= bpp else 0
            b = previous[x]
            c = previous[x - bpp] if x >= bpp else 0
            row[x] = (row[x] + [0, a, b, (a + b) // 2, paeth(a, b, c)][f]) & 0xFF
        rows.append(bytes(row))
        previous = row
    dtype = ">u2" if depth == 16 else np.uint8
    return np.frombuffer(b"".join(rows), dtype=dtype).reshape(height, width, channels)


def image(shape, seed):
    return np.random.default_rng(seed).uniform(0, 1, shape)


# --- PNG ----------------------------------------------------------------------------------


@pytest.mark.parametrize("shape", [(5, 7, 3), (4, 6), (3, 5, 4)])
def test_png_8_bit_round_trip_with_pillow(tmp_path, shape):
    rgb = image(shape, seed=1)
    write_png(tmp_path / "a.png", rgb)
    with Image.open(tmp_path / "a.png") as im:
        assert im.mode == {1: "L", 3: "RGB", 4: "RGBA"}[1 if len(shape) == 2 else shape[-1]]
        decoded = np.array(im)
    np.testing.assert_array_equal(decoded, np.rint(rgb * 255).astype(np.uint8))
    np.testing.assert_array_equal(read_png(tmp_path / "a.png").reshape(decoded.shape), decoded)


@pytest.mark.parametrize("shape", [(5, 7, 3), (4, 6), (3, 5, 4)])
def test_png_16_bit_round_trip(tmp_path, shape):
    rgb = image(shape, seed=2)
    write_png(tmp_path / "a.png", rgb, bit_depth=16)
    codes = np.rint(rgb * 65535).astype(np.uint16)
    np.testing.assert_array_equal(read_png(tmp_path / "a.png").reshape(shape), codes)
    with Image.open(tmp_path / "a.png") as im:
        im.verify()
    with Image.open(tmp_path / "a.png") as im:
        decoded = np.array(im)
    if len(shape) == 2:  # Pillow keeps 16-bit grey ('I;16') ...
        np.testing.assert_array_equal(decoded, codes)
    elif shape[-1] == 3:  # ... but reduces 16-bit RGB to its high bytes.
        np.testing.assert_array_equal(decoded, codes >> 8)


@settings(max_examples=20, deadline=None)
@given(
    hnp.arrays(np.float64, st.tuples(st.integers(1, 6), st.integers(1, 6), st.just(3)),
               elements=st.floats(0, 1)),
    st.sampled_from([8, 16]),
)
def test_png_round_trip_property(tmp_path_factory, rgb, bit_depth):
    path = tmp_path_factory.mktemp("png") / "p.png"
    write_png(path, rgb, bit_depth)
    decoded = read_png(path).astype(np.float64) / (2**bit_depth - 1)
    # Round to nearest: within half a code of the input.
    assert np.max(np.abs(decoded - rgb)) <= 0.5 / (2**bit_depth - 1) + 1e-12


def test_png_rounds_to_nearest_code(tmp_path):
    rgb = np.array([[[0.4 / 255, 0.6 / 255, 1.0], [254.4 / 255, 254.6 / 255, 0.0]]])
    write_png(tmp_path / "r.png", rgb)
    np.testing.assert_array_equal(read_png(tmp_path / "r.png"), [[[0, 1, 255], [254, 255, 0]]])


@pytest.mark.parametrize("bit_depth", [8, 16])
def test_png_is_deterministic_and_has_no_extra_chunks(tmp_path, bit_depth):
    rgb = image((16, 9, 3), seed=3)
    write_png(tmp_path / "a.png", rgb, bit_depth)
    write_png(tmp_path / "sub" / "b.png", rgb.copy(), bit_depth)
    data = (tmp_path / "a.png").read_bytes()
    assert data == (tmp_path / "sub" / "b.png").read_bytes()
    assert [kind for kind, _ in read_png_chunks(data)] == [b"IHDR", b"IDAT", b"IEND"]
    write_png(tmp_path / "a.png", rgb, bit_depth)  # overwrite in place
    assert (tmp_path / "a.png").read_bytes() == data
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.png", "sub"]  # no temp files left


@pytest.mark.parametrize(
    "rgb, bit_depth, message",
    [
        (np.full((2, 2, 3), np.nan), 8, "rgb01.*NaN"),
        (np.array([[[0.1, np.inf, 0.2]]]), 16, "rgb01.*inf"),
        (np.full((2, 2, 3), 1.01), 8, r"rgb01.*\[0, 1\]"),
        (np.full((2, 2, 3), -0.01), 8, r"rgb01.*\[0, 1\]"),
        (np.full((2, 2, 2), 0.5), 8, "rgb01.*shape"),
        (np.full((0, 2, 3), 0.5), 8, "rgb01.*shape"),
        (np.full((2, 2, 3), 0.5), 12, "bit_depth"),
        (np.full((2, 2, 3), 0.5), True, "bit_depth"),
        ([["a"]], 8, "rgb01"),
    ],
)
def test_png_bad_input_raises_and_writes_nothing(tmp_path, rgb, bit_depth, message):
    with pytest.raises(ValueError, match=message):
        write_png(tmp_path / "bad.png", rgb, bit_depth)
    assert list(tmp_path.iterdir()) == []


# --- OpenEXR ------------------------------------------------------------------------------


def xyz_image(seed, shape=(7, 5)):
    rng = np.random.default_rng(seed)
    XYZ = rng.lognormal(0, 3, (*shape, 3)).astype(np.float32)
    XYZ[0, 0] = [0.0, -1.5, 1e-30]  # zero, negative, denormal-ish values survive too
    return XYZ


def test_exr_round_trip_is_float32_exact_with_header(tmp_path):
    XYZ = xyz_image(4)
    attributes = {
        "material": "copper", "m": 0.15, "lights": [1, 2], "paper": "Cook & Torrance 1982"
    }
    write_exr_XYZ(tmp_path / "a.exr", XYZ, attributes)
    read, header = read_exr(tmp_path / "a.exr")
    assert read.dtype == np.float32 and read.shape == (7, 5, 3)
    np.testing.assert_array_equal(read, XYZ)
    assert header["material"] == "copper"
    assert header["m"] == "0.15" and header["lights"] == "[1, 2]"
    assert header["paper"] == "Cook & Torrance 1982"
    np.testing.assert_allclose(header["chromaticities"], XYZ_CHROMATICITIES, rtol=1e-7)
    assert header["compression"] == OpenEXR.ZIP_COMPRESSION
    assert [c.name for c in header["channels"]] == ["X", "Y", "Z"]
    # Read independently of read_exr, channel by channel, through OpenEXR itself.
    with OpenEXR.File(str(tmp_path / "a.exr"), separate_channels=True) as exr:
        for i, name in enumerate("XYZ"):
            np.testing.assert_array_equal(exr.channels()[name].pixels, XYZ[..., i])


def test_exr_float64_input_is_stored_as_float32(tmp_path):
    XYZ = np.random.default_rng(5).uniform(0, 2, (3, 4, 3))
    write_exr_XYZ(tmp_path / "a.exr", XYZ)
    np.testing.assert_array_equal(read_exr(tmp_path / "a.exr")[0], XYZ.astype(np.float32))


def test_exr_rewrite_is_byte_identical(tmp_path):
    XYZ = xyz_image(6, shape=(40, 33))
    attributes = {"b": "2", "a": "1"}
    write_exr_XYZ(tmp_path / "a.exr", XYZ, attributes)
    first = (tmp_path / "a.exr").read_bytes()
    write_exr_XYZ(tmp_path / "a.exr", XYZ.copy(), dict(reversed(list(attributes.items()))))
    write_exr_XYZ(tmp_path / "b.exr", XYZ, attributes)
    assert (tmp_path / "a.exr").read_bytes() == first == (tmp_path / "b.exr").read_bytes()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.exr", "b.exr"]


@pytest.mark.parametrize(
    "XYZ, attributes, message",
    [
        (np.full((2, 2, 3), np.nan), None, "XYZ.*NaN"),
        (np.array([[[1.0, -np.inf, 0.0]]]), None, "XYZ.*inf"),
        (np.full((2, 2, 3), 1e39), None, "XYZ.*float32"),
        (np.ones((2, 2)), None, "XYZ.*shape"),
        (np.ones((2, 2, 3)), {"compression": "none"}, "attributes.*compression"),
        (np.ones((2, 2, 3)), {"": "x"}, "attributes"),
        (np.ones((2, 2, 3)), {"f": object()}, r"attributes\['f'\]"),
        (np.ones((2, 2, 3)), {"f": float("nan")}, r"attributes\['f'\]"),
        (np.ones((2, 2, 3)), ["a"], "attributes.*mapping"),
    ],
)
def test_exr_bad_input_raises_and_writes_nothing(tmp_path, XYZ, attributes, message):
    with pytest.raises(ValueError, match=message):
        write_exr_XYZ(tmp_path / "bad.exr", XYZ, attributes)
    assert list(tmp_path.iterdir()) == []


def test_read_exr_errors(tmp_path):
    with pytest.raises(FileNotFoundError):
        read_exr(tmp_path / "missing.exr")
    (tmp_path / "text.exr").write_text("not an image")
    with pytest.raises(ValueError, match="text.exr.*OpenEXR"):
        read_exr(tmp_path / "text.exr")
    rgb = {name: np.zeros((2, 2), np.float32) for name in "RGB"}
    with OpenEXR.File({"compression": OpenEXR.ZIP_COMPRESSION}, rgb) as exr:
        exr.write(str(tmp_path / "rgb.exr"))
    with pytest.raises(ValueError, match="rgb.exr.*X, Y, Z"):
        read_exr(tmp_path / "rgb.exr")
