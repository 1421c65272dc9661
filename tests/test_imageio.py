"""Tests of reflectance.io.images: PNG and OpenEXR round trips, determinism, bad input."""

import io
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


# --- colour tags: sRGB chunk, ICC profile ---------------------------------------------------


def _colourspace(name):
    import colour

    return colour.RGB_COLOURSPACES[{"sRGB": "sRGB", "SMPTE-C": "SMPTE C"}[name]]


def _icc_tags(profile):
    """{signature: bytes} of an ICC profile, parsed with struct (ICC.1:2001-04 §6.1, §6.2)."""
    (size,) = struct.unpack(">I", profile[:4])
    assert size == len(profile) and profile[36:40] == b"acsp"
    (count,) = struct.unpack(">I", profile[128:132])
    tags = {}
    for i in range(count):
        signature, offset, length = struct.unpack(">4sII", profile[132 + 12 * i: 144 + 12 * i])
        tags[signature.decode()] = profile[offset: offset + length]
    return tags


def _icc_XYZ(block):
    assert block[:4] == b"XYZ "
    return np.array(struct.unpack(">3i", block[8:20])) / 65536.0


@pytest.mark.parametrize("bit_depth", [8, 16])
def test_srgb_png_carries_srgb_gama_chrm_matching_colour_science(tmp_path, bit_depth):
    from reflectance.colour.display import display_tag

    write_png(tmp_path / "a.png", image((3, 4, 3), 9), bit_depth, tag=display_tag("sRGB"))
    chunks = dict(read_png_chunks((tmp_path / "a.png").read_bytes()))
    assert chunks[b"sRGB"] == bytes([1]) and b"iCCP" not in chunks  # never both (PNG §11.3.3)
    assert struct.unpack(">I", chunks[b"gAMA"]) == (45455,)  # §11.3.3.5
    chrm = np.array(struct.unpack(">8I", chunks[b"cHRM"])) / 100000
    cs = _colourspace("sRGB")
    np.testing.assert_allclose(chrm[:2], cs.whitepoint, atol=1e-5)
    np.testing.assert_allclose(chrm[2:].reshape(3, 2), cs.primaries, atol=1e-5)
    with Image.open(tmp_path / "a.png") as im:  # Pillow reads the same chunks
        assert im.info["srgb"] == 1 and "icc_profile" not in im.info


def test_smpte_c_png_carries_an_icc_profile_with_colour_science_primaries(tmp_path):
    import colour

    from reflectance.colour.display import display_tag

    write_png(tmp_path / "a.png", image((3, 4, 3), 10), tag=display_tag("SMPTE-C"))
    chunks = dict(read_png_chunks((tmp_path / "a.png").read_bytes()))
    assert b"sRGB" not in chunks
    assert struct.unpack(">I", chunks[b"gAMA"]) == (round(100000 / 2.4),)
    name, rest = chunks[b"iCCP"].split(b"\0", 1)
    assert name == b"SMPTE-C" and rest[0] == 0  # compression method 0 (zlib)
    tags = _icc_tags(zlib.decompress(rest[1:]))
    assert {"desc", "cprt", "wtpt", "rXYZ", "gXYZ", "bXYZ", "rTRC", "gTRC", "bTRC"} <= set(tags)
    cs = _colourspace("SMPTE-C")
    white = _icc_XYZ(tags["wtpt"])
    np.testing.assert_allclose(colour.XYZ_to_xy(white), cs.whitepoint, atol=1e-4)
    # colorants are D50-adapted (Bradford); undo it with colour-science and compare the xy
    for signature, xy in zip(("rXYZ", "gXYZ", "bXYZ"), cs.primaries):
        XYZ = colour.chromatic_adaptation(_icc_XYZ(tags[signature]), np.array([0.9642, 1, 0.8249]),
                                          white, method="Von Kries", transform="Bradford")
        np.testing.assert_allclose(colour.XYZ_to_xy(XYZ), xy, atol=1e-4)
    # the tone curve: encoded^2.4 (the BT.1886 reference EOTF, L_B = 0)
    curve = tags["rTRC"]
    (n,) = struct.unpack(">I", curve[8:12])
    table = np.frombuffer(curve[12:12 + 2 * n], ">u2") / 65535
    np.testing.assert_allclose(table, np.linspace(0, 1, n) ** 2.4, atol=1e-5)


def test_smpte_c_profile_converts_like_colour_science_through_littlecms(tmp_path):
    """littlecms (Pillow's ImageCms) reads the profile and converts SMPTE-C codes to sRGB as
    colour-science's RGB_to_RGB does."""
    import io

    import colour
    from PIL import ImageCms

    from reflectance.colour.display import display_tag

    codes = np.array([[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.5, 0.5, 0.5],
                       [0.8, 0.6, 0.3], [0.2, 0.7, 0.9]]])
    write_png(tmp_path / "a.png", codes, tag=display_tag("SMPTE-C"))
    with Image.open(tmp_path / "a.png") as im:
        source = ImageCms.ImageCmsProfile(io.BytesIO(im.info["icc_profile"]))
        converted = ImageCms.profileToProfile(
            im, source, ImageCms.createProfile("sRGB"),
            renderingIntent=ImageCms.Intent.RELATIVE_COLORIMETRIC, outputMode="RGB")
    got = np.asarray(converted, dtype=np.float64) / 255
    linear = colour.RGB_to_RGB((np.round(codes * 255) / 255) ** 2.4, _colourspace("SMPTE-C"),
                               _colourspace("sRGB"))
    expected = colour.cctf_encoding(np.clip(linear, 0, 1), function="sRGB")
    np.testing.assert_allclose(got, expected, atol=2.5 / 255)


def test_tagged_png_is_deterministic(tmp_path):
    from reflectance.colour.display import display_tag

    rgb = image((5, 6, 3), 11)
    for name in ("a", "b"):
        write_png(tmp_path / f"{name}.png", rgb, tag=display_tag("SMPTE-C"))
    assert (tmp_path / "a.png").read_bytes() == (tmp_path / "b.png").read_bytes()


def test_bad_tag_raises_and_writes_nothing(tmp_path):
    from reflectance.io.images import ColourTag

    with pytest.raises(ValueError, match="tag"):
        write_png(tmp_path / "a.png", image((2, 2, 3), 1), tag="sRGB")
    with pytest.raises(ValueError, match="gamma"):
        write_png(tmp_path / "a.png", image((2, 2, 3), 1),
                  tag=ColourTag("x", ((0.6, 0.3), (0.3, 0.6), (0.15, 0.06)), (0.3, 0.3), -1.0))
    assert list(tmp_path.iterdir()) == []


# --- display-referred linear RGB EXR -----------------------------------------------------------


@pytest.mark.parametrize("space", ["sRGB", "SMPTE-C"])
def test_rgb_exr_round_trip_with_colour_science_chromaticities(tmp_path, space):
    from reflectance.colour.display import display_tag
    from reflectance.io.images import write_exr_RGB

    RGB = np.random.default_rng(12).uniform(0, 1, (6, 5, 3)).astype(np.float32)
    write_exr_RGB(tmp_path / "a.exr", RGB, display_tag(space), {"note": "x"})
    with OpenEXR.File(str(tmp_path / "a.exr"), separate_channels=True) as exr:
        header = dict(exr.header())
        channels = exr.channels()
        assert sorted(channels) == ["B", "G", "R"]
        for i, name in enumerate("RGB"):
            np.testing.assert_array_equal(channels[name].pixels, RGB[..., i])
    cs = _colourspace(space)
    chroma = np.array(header["chromaticities"])
    np.testing.assert_allclose(chroma[:6].reshape(3, 2), cs.primaries, atol=1e-6)
    np.testing.assert_allclose(chroma[6:], cs.whitepoint, atol=1e-6)
    assert header["note"] == "x"
    read, _ = read_exr(tmp_path / "a.exr", channels="RGB")
    np.testing.assert_array_equal(read, RGB)


# --- figures: matplotlib and pyvista PNGs carry their colour space ------------------------------


def _colour_chunks(data):
    """{type: body} of the colour chunks, checking they come before the image data (PNG §5.6)."""
    kinds = [kind for kind, _ in read_png_chunks(data)]
    first_data = kinds.index(b"IDAT")
    found = {kind: body for kind, body in read_png_chunks(data)
             if kind in (b"cHRM", b"gAMA", b"sRGB", b"iCCP", b"cICP")}
    assert all(kinds.index(kind) < first_data for kind in found)
    assert all(kinds.count(kind) == 1 for kind in found)
    return found


def _srgb_chunks_as_colour_science_says(found):
    """sRGB chunk, gAMA 1/2.2 and cHRM with colour-science's sRGB primaries and white."""
    assert found[b"sRGB"] == bytes([1]) and b"iCCP" not in found
    assert struct.unpack(">I", found[b"gAMA"]) == (45455,)
    cs = _colourspace("sRGB")
    chrm = np.array(struct.unpack(">8I", found[b"cHRM"])) / 100000
    np.testing.assert_allclose(chrm, [*cs.whitepoint, *cs.primaries.ravel()], atol=1e-5)


def _plot():
    from matplotlib.patches import Rectangle

    from reflectance.io.figures import new_figure

    fig = new_figure(2.0, 1.5)
    ax = fig.add_subplot()
    ax.plot([0, 1, 2], [0, 1, 0])
    ax.add_patch(Rectangle((0.2, 0.2), 0.5, 0.3, color="#d55e00"))
    return fig


def test_matplotlib_figure_png_is_tagged_srgb_with_its_pixels_untouched(tmp_path):
    """savefig: the sRGB chunk (matplotlib's colours are sRGB values); the pixels equal the ones
    matplotlib writes untagged; the PDF beside it is still written; a rerun is byte-identical."""
    from reflectance.io.figures import savefig

    savefig(_plot(), tmp_path / "a.png", tmp_path / "a.pdf", dpi=50)
    savefig(_plot(), tmp_path / "b.png", dpi=50)
    fig = _plot()
    fig.savefig(tmp_path / "plain.png", dpi=50, bbox_inches="tight")
    data = (tmp_path / "a.png").read_bytes()
    _srgb_chunks_as_colour_science_says(_colour_chunks(data))
    assert data == (tmp_path / "b.png").read_bytes()
    assert (tmp_path / "a.pdf").read_bytes()[:5] == b"%PDF-"
    assert b"tIME" not in [kind for kind, _ in read_png_chunks(data)]
    with Image.open(tmp_path / "a.png") as im, Image.open(tmp_path / "plain.png") as plain:
        assert im.info["srgb"] == 1 and "icc_profile" not in im.info  # Pillow reads it too
        assert "srgb" not in plain.info and "icc_profile" not in plain.info  # (what tags it)
        np.testing.assert_array_equal(np.asarray(im), np.asarray(plain))


def test_figure_of_smpte_c_pixels_carries_the_displays_icc_profile(tmp_path):
    """A figure showing SMPTE-C-encoded pixels (tag=display_tag): iCCP, no sRGB chunk; the profile
    is the one write_png gives a render of that display, and littlecms reads it."""
    from PIL import ImageCms

    from reflectance.colour.display import display_tag
    from reflectance.io.figures import savefig

    savefig(_plot(), tmp_path / "a.png", dpi=50, tag=display_tag("SMPTE-C"))
    write_png(tmp_path / "render.png", image((2, 2, 3), 3), tag=display_tag("SMPTE-C"))
    found = _colour_chunks((tmp_path / "a.png").read_bytes())
    assert b"sRGB" not in found
    assert found == _colour_chunks((tmp_path / "render.png").read_bytes())
    with Image.open(tmp_path / "a.png") as im:
        profile = ImageCms.ImageCmsProfile(io.BytesIO(im.info["icc_profile"]))
    assert ImageCms.getProfileDescription(profile).strip() == "SMPTE-C"


def test_pyvista_screenshot_is_tagged_srgb(tmp_path):
    import pyvista as pv

    from reflectance.io.figures import off_screen_plotter, save_plotter

    for name in ("a", "b"):
        plotter = off_screen_plotter(48, 32)
        plotter.add_mesh(pv.Sphere(), color="#0072b2")
        save_plotter(plotter, tmp_path / f"{name}.png")
    data = (tmp_path / "a.png").read_bytes()
    _srgb_chunks_as_colour_science_says(_colour_chunks(data))
    assert data == (tmp_path / "b.png").read_bytes()
    with Image.open(tmp_path / "a.png") as im:
        assert im.size == (48, 32) and im.info["srgb"] == 1


def test_the_fixed_srgb_tag_writes_what_colour_sciences_srgb_writes(tmp_path):
    """SRGB_TAG (IEC 61966-2-1's numbers, for io, which may not import colour) and
    display_tag("sRGB") (colour-science's) give the same chunks."""
    from reflectance.colour.display import display_tag
    from reflectance.io.images import SRGB_TAG

    rgb = image((2, 3, 3), 5)
    write_png(tmp_path / "a.png", rgb, tag=SRGB_TAG)
    write_png(tmp_path / "b.png", rgb, tag=display_tag("sRGB"))
    assert (tmp_path / "a.png").read_bytes() == (tmp_path / "b.png").read_bytes()


def test_tag_png_refuses_a_second_colour_space_and_non_png():
    from reflectance.io.images import SRGB_TAG, tag_png

    buffer = io.BytesIO()
    Image.new("RGB", (2, 2)).save(buffer, format="PNG")
    tagged = tag_png(buffer.getvalue(), SRGB_TAG)
    with pytest.raises(ValueError, match="already declares its colour space"):
        tag_png(tagged, SRGB_TAG)
    with pytest.raises(ValueError, match="not a PNG"):
        tag_png(b"GIF89a....", SRGB_TAG)
    with Image.open(io.BytesIO(tagged)) as im:  # still a valid PNG, same pixels
        assert im.info["srgb"] == 1 and np.asarray(im).sum() == 0
