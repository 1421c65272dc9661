"""Colorimetry on a wavelength grid: CMFs, illuminants, tristimulus weights, dominant wavelength.

Everything tabulated (CIE colour matching functions, CIE illuminant SPDs) comes from colour-science
and is put onto the caller's grid exactly the way colour-science does it
(``colour.SpectralShape`` + ``.copy().align()``): its default interpolation (Sprague 1880 for
uniformly tabulated data, cubic spline otherwise) and constant extrapolation beyond the tabulated
range (CIE 15:2004 and CIE 167:2005 recommendations). Note that the CIE illuminants of
colour-science are tabulated from 300 nm to 780 nm only, so on a 360-830 nm grid their last value
(780 nm) is repeated up to 830 nm; the CMFs there are below 1e-4 of their peak, so this is
immaterial.

This module knows nothing of BRDFs or displays: it turns spectra into CIE XYZ.

References
----------
-   CIE 15:2004 Colorimetry, 3rd edition, §7 (tristimulus values, normalisation k) and §9.1
    (dominant wavelength, complementary wavelength, excitation purity).
-   Cook, R. L., & Torrance, K. E. (1982). A Reflectance Model for Computer Graphics. ACM TOG 1(1),
    "Determining the RGB values".
"""

from __future__ import annotations

import functools

import colour
import numpy as np

__all__ = [
    "OBSERVER_DEFAULT",
    "cmfs",
    "illuminant_sd",
    "tristimulus_weights",
    "tristimulus_weights_spd",
    "white_XYZ",
    "spectrum_to_XYZ",
    "dominant_wavelength",
]

OBSERVER_DEFAULT = "CIE 1931 2 Degree Standard Observer"
"""Cook & Torrance 1982 cite CIE 15 (1970), i.e. the CIE 1931 2 degree standard observer."""

_DOMINANT_WAVELENGTH_CHUNK = 2048
"""colour.dominant_wavelength is vectorised but builds (n_colours, n_locus) intersection arrays;
chunking bounds memory (~2048 x 471 x 8 B per array) for whole images."""


_ACHROMATIC_XY = 1e-12
"""Distance in xy from the white below which a colour counts as achromatic (float rounding)."""


def _validate_observer(observer):
    known = colour.colorimetry.MSDS_CMFS_STANDARD_OBSERVER
    if not isinstance(observer, str) or observer not in known:
        raise ValueError(
            f"observer: unknown standard observer {observer!r}; known: {', '.join(known)}"
        )
    return known[observer]


def _validate_illuminant(name):
    known = colour.SDS_ILLUMINANTS
    if not isinstance(name, str) or name not in known:
        raise ValueError(f"illuminant: unknown illuminant {name!r}; known: {', '.join(known)}")
    return known[name]


def _grid_key(wavelengths):
    """Validate a uniform wavelength grid (nm) and return it as a hashable tuple."""
    wl = np.asarray(wavelengths, dtype=np.float64)
    if wl.ndim != 1 or wl.size < 2 or not np.all(np.isfinite(wl)):
        raise ValueError(
            f"wavelengths: expected a 1-D array of at least 2 finite values in nm, got shape "
            f"{wl.shape}"
        )
    step = np.diff(wl)
    if np.any(step <= 0):
        raise ValueError("wavelengths: must be strictly increasing")
    interval = (wl[-1] - wl[0]) / (wl.size - 1)
    if np.max(np.abs(step - interval)) > 1e-9 * max(1.0, abs(interval)):
        raise ValueError(
            "wavelengths: must be uniformly spaced (colour-science's SpectralShape and the "
            "rectangle-rule integration both assume a uniform interval)"
        )
    return tuple(wl.tolist())


def _align(spectral_data, key, what):
    """``spectral_data.copy().align(shape)`` with colour-science's errors named for the caller."""
    try:
        aligned = spectral_data.copy().align(_shape(key))
    except (AssertionError, ValueError) as error:
        raise ValueError(f"wavelengths: cannot align {what} onto the grid: {error}") from error
    return np.array(aligned.values, dtype=np.float64)


def _shape(key):
    shape = colour.SpectralShape(key[0], key[-1], (key[-1] - key[0]) / (len(key) - 1))
    if len(shape.wavelengths) != len(key):
        raise ValueError(
            f"wavelengths: colour.SpectralShape{(shape.start, shape.end, shape.interval)} gives "
            f"{len(shape.wavelengths)} samples, the grid has {len(key)}"
        )
    return shape


@functools.lru_cache(maxsize=64)
def _cmfs_cached(observer, key):
    msds = _validate_observer(observer)
    values = _align(msds, key, f"the {observer} CMFs")
    values.setflags(write=False)
    return values


@functools.lru_cache(maxsize=64)
def _illuminant_cached(name, key):
    sd = _validate_illuminant(name)
    values = _align(sd, key, f"illuminant {name}")
    values.setflags(write=False)
    return values


@functools.lru_cache(maxsize=64)
def _weights_cached(key, illuminant, observer):
    W = _weights(_illuminant_cached(illuminant, key), _cmfs_cached(observer, key))
    W.setflags(write=False)
    return W


def _weights(S, xyz_bar):
    # CIE 15:2004 §7.1: X = k sum S(l) R(l) x_bar(l) dl with k = 1 / sum S(l) y_bar(l) dl (the
    # interval dl cancels). Same sum, in the same order of operations, as colour-science's
    # sd_to_XYZ_integration.
    return S[:, None] * xyz_bar / np.sum(xyz_bar[:, 1] * S)


def tristimulus_weights_spd(spd, wavelengths, observer=OBSERVER_DEFAULT):
    """:func:`tristimulus_weights` for an illuminant given by its SPD values on the grid.

    Parameters
    ----------
    spd : array_like
        Relative spectral power at each wavelength of ``wavelengths`` (>= 0, not all 0).
    wavelengths : array_like
        Uniform grid in nm.
    observer : str
        A key of ``colour.colorimetry.MSDS_CMFS_STANDARD_OBSERVER``.

    Returns
    -------
    numpy.ndarray
        Shape ``(len(wavelengths), 3)``; ``spd`` of a CIE illuminant gives the same weights as its
        name does in :func:`tristimulus_weights`.

    Examples
    --------
    >>> wl = np.arange(360, 831, 5.0)
    >>> bool(np.allclose(tristimulus_weights_spd(illuminant_sd("A", wl), wl),
    ...                  tristimulus_weights(wl, "A")))
    True
    """
    key = _grid_key(wavelengths)
    S = np.asarray(spd, dtype=np.float64)
    if S.shape != (len(key),) or not np.all(np.isfinite(S)) or np.any(S < 0):
        raise ValueError(f"illuminant SPD: expected {len(key)} finite values >= 0 on the grid, "
                         f"got shape {S.shape}")
    _validate_observer(observer)
    xyz_bar = _cmfs_cached(observer, key)
    if not np.sum(xyz_bar[:, 1] * S) > 0:
        raise ValueError("illuminant SPD: no power where the observer's y_bar is non-zero")
    return _weights(S, xyz_bar)


def cmfs(observer=OBSERVER_DEFAULT, wavelengths=None):
    """Colour matching functions of a CIE standard observer on a wavelength grid.

    Parameters
    ----------
    observer : str
        A key of ``colour.colorimetry.MSDS_CMFS_STANDARD_OBSERVER``.
    wavelengths : array_like or None
        Uniform grid in nm; ``None`` returns the observer's own tabulation (1 nm for the CIE ones).

    Returns
    -------
    numpy.ndarray
        Shape ``(len(wavelengths), 3)``: x_bar, y_bar, z_bar.

    References
    ----------
    CIE 15:2004, Table T.4 (via colour-science ``MSDS_CMFS``).

    Examples
    --------
    >>> cmfs("CIE 1931 2 Degree Standard Observer", np.arange(360, 831, 5.0))[39].round(4)
    array([ 0.5121,  1.    ,  0.0057])
    """
    if wavelengths is None:
        return np.array(_validate_observer(observer).values, dtype=np.float64)
    return _cmfs_cached(observer, _grid_key(wavelengths)).copy()


def illuminant_sd(name="D65", wavelengths=None):
    """Relative spectral power distribution of a CIE illuminant on a wavelength grid.

    Parameters
    ----------
    name : str
        A key of ``colour.SDS_ILLUMINANTS`` (``"D65"``, ``"A"``, ``"C"``, ``"FL2"``, ...).
    wavelengths : array_like or None
        Uniform grid in nm; ``None`` returns colour-science's own tabulation.

    Returns
    -------
    numpy.ndarray
        Shape ``(len(wavelengths),)``, relative units (D65 is 100 at 560 nm).

    References
    ----------
    CIE 15:2004, Table T.1 (via colour-science ``SDS_ILLUMINANTS``).

    Examples
    --------
    >>> float(illuminant_sd("D65", np.arange(360, 831, 5.0))[40])
    100.0
    """
    if wavelengths is None:
        return np.array(_validate_illuminant(name).values, dtype=np.float64)
    return _illuminant_cached(name, _grid_key(wavelengths)).copy()


def tristimulus_weights(wavelengths, illuminant="D65", observer=OBSERVER_DEFAULT):
    """Weights ``W`` such that ``XYZ = S @ W`` for a spectral reflectance factor ``S``.

    ``W[i] = S_illum(l_i) * xyz_bar(l_i) / sum_j S_illum(l_j) y_bar(l_j)``, so that ``S = 1`` gives
    the illuminant's white with ``Y = 1``. This is the same rectangle-rule sum, on the same uniform
    grid, as colour-science's ``sd_to_XYZ(sd, cmfs, illuminant, method="Integration") / 100``
    (CIE 15:2004 §7.1, with its normalisation constant k); the interval cancels.

    Results are cached per (grid, illuminant, observer) since many callers ask for the same grid;
    a fresh copy is returned each time.

    Parameters
    ----------
    wavelengths : array_like
        Uniform grid in nm.
    illuminant : str
        A key of ``colour.SDS_ILLUMINANTS``.
    observer : str
        A key of ``colour.colorimetry.MSDS_CMFS_STANDARD_OBSERVER``.

    Returns
    -------
    numpy.ndarray
        Shape ``(len(wavelengths), 3)``.

    References
    ----------
    CIE 15:2004 §7.1; Cook & Torrance 1982, "Determining the RGB values" (multiply the reflected
    spectrum by the XYZ matching functions and integrate).

    Examples
    --------
    >>> W = tristimulus_weights(np.arange(360, 831, 5.0))
    >>> W.shape, round(float(W[:, 1].sum()), 12)
    ((95, 3), 1.0)
    """
    key = _grid_key(wavelengths)
    _validate_illuminant(illuminant)
    _validate_observer(observer)
    return _weights_cached(key, illuminant, observer).copy()


def spectrum_to_XYZ(S, W):
    """CIE XYZ of spectra ``S[..., n_wl]`` with tristimulus weights ``W`` (n_wl, 3): ``S @ W``.

    Examples
    --------
    >>> W = tristimulus_weights(np.arange(360, 831, 5.0))
    >>> spectrum_to_XYZ(np.full((2, 95), 0.5), W)[:, 1].round(12)
    array([ 0.5,  0.5])
    """
    S = np.asarray(S, dtype=np.float64)
    W = np.asarray(W, dtype=np.float64)
    if W.ndim != 2 or W.shape[1] != 3:
        raise ValueError(f"W: expected shape (n_wl, 3), got {W.shape}")
    if S.ndim == 0 or S.shape[-1] != W.shape[0]:
        raise ValueError(f"S: last axis must have {W.shape[0]} wavelengths, got shape {S.shape}")
    return S @ W


def white_XYZ(illuminant="D65", observer=OBSERVER_DEFAULT, wavelengths=None):
    """CIE XYZ (Y = 1) of an illuminant's white, i.e. of ``S = 1``, for an observer.

    Parameters
    ----------
    illuminant : str
        A key of ``colour.SDS_ILLUMINANTS``.
    observer : str
        A key of ``colour.colorimetry.MSDS_CMFS_STANDARD_OBSERVER``.
    wavelengths : array_like or None
        Grid of the sum. ``None`` uses the observer's own tabulation (1 nm, 360-830 nm for the CIE
        observers). A renderer summing on a coarser grid should pass that grid so that its white
        (``ones @ W``) is reproduced to float precision: the 5 nm and 1 nm whites of D65 differ by
        ~1e-4 in Z.

    Returns
    -------
    numpy.ndarray
        Shape (3,).

    References
    ----------
    CIE 15:2004 §7.1 (k chosen so that Y = 100 for the perfect reflecting diffuser; here 1).

    Examples
    --------
    >>> white_XYZ("D65").round(4)
    array([ 0.9505,  1.    ,  1.0888])
    """
    if wavelengths is None:
        wavelengths = _validate_observer(observer).wavelengths
    W = tristimulus_weights(wavelengths, illuminant, observer)
    return spectrum_to_XYZ(np.ones(W.shape[0]), W)


def dominant_wavelength(XYZ, illuminant="D65", observer=OBSERVER_DEFAULT, wavelengths=None):
    """Dominant wavelength and excitation purity of CIE XYZ colours relative to a white.

    Thin wrapper over ``colour.dominant_wavelength`` (which needs scipy): purples, which have no
    dominant wavelength, get their complementary wavelength as a negative number, as colour-science
    returns it. colour-science's function is vectorised but allocates (n_colours, n_locus) arrays,
    so colours are processed in chunks; any input shape ``(..., 3)`` is accepted. Its wavelength is
    the locus sample closest to the intersection, i.e. it is quantised to the CMF tabulation (1 nm).

    Parameters
    ----------
    XYZ : array_like
        Shape ``(..., 3)``.
    illuminant : str or array_like
        Name of the white's illuminant (see :func:`white_XYZ`) or its XYZ directly.
    observer : str
        Observer of the spectral locus and of the white.
    wavelengths : array_like or None
        Grid of the white, see :func:`white_XYZ`.

    Returns
    -------
    tuple of numpy.ndarray
        ``(wavelength_nm, purity)``, each of shape ``XYZ.shape[:-1]``. ``purity`` is the CIE
        excitation purity ``|xy - xy_n| / |xy_b - xy_n|`` with ``xy_b`` the boundary point (spectral
        locus or purple line). Colours without a chromaticity (X + Y + Z <= 0, or non-finite) and
        colours at the white point (within 1e-12 in xy) have an undefined wavelength, returned as
        NaN, and purity 0 (NaN for non-finite input).

    References
    ----------
    CIE 15:2004 §9.1; Judd & Wyszecki (1975) pp. 170-172, cited by Cook & Torrance 1982.

    Examples
    --------
    >>> wl, p = dominant_wavelength(colour.xyY_to_XYZ([0.54369557, 0.32107944, 0.2]))
    >>> float(wl), round(float(p), 2)
    (616.0, 0.62)
    """
    XYZ = np.asarray(XYZ, dtype=np.float64)
    if XYZ.ndim == 0 or XYZ.shape[-1] != 3:
        raise ValueError(f"XYZ: expected shape (..., 3), got {XYZ.shape}")
    if isinstance(illuminant, str):
        XYZ_n = white_XYZ(illuminant, observer, wavelengths)
    else:
        XYZ_n = np.asarray(illuminant, dtype=np.float64)
        if XYZ_n.shape != (3,) or not np.all(np.isfinite(XYZ_n)) or XYZ_n.sum() <= 0:
            raise ValueError(f"illuminant: expected a name or a finite XYZ white, got {XYZ_n!r}")
    xy_n = XYZ_n[:2] / XYZ_n.sum()
    msds = _validate_observer(observer)

    flat = XYZ.reshape(-1, 3)
    total = flat.sum(axis=-1)
    finite = np.all(np.isfinite(flat), axis=-1)
    has_xy = finite & (total > 0)
    xy = np.zeros((flat.shape[0], 2))
    xy[has_xy] = flat[has_xy, :2] / total[has_xy, None]
    # At the white point (to rounding) the direction, hence the wavelength, is undefined.
    chromatic = has_xy & (np.hypot(*(xy - xy_n).T) > _ACHROMATIC_XY)

    wl = np.full(flat.shape[0], np.nan)
    purity = np.where(finite, 0.0, np.nan)
    index = np.flatnonzero(chromatic)
    for start in range(0, index.size, _DOMINANT_WAVELENGTH_CHUNK):
        i = index[start : start + _DOMINANT_WAVELENGTH_CHUNK]
        wl_i, xy_b = _dominant_wavelength_colour(xy[i], xy_n, msds)
        wl[i] = wl_i
        # CIE 15:2004 §9.1 excitation purity; colour's xy_b lies on the purple line for purples.
        purity[i] = np.hypot(*(xy[i] - xy_n).T) / np.hypot(*(xy_b - xy_n).T)
    shape = XYZ.shape[:-1]
    return wl.reshape(shape), purity.reshape(shape)


def _dominant_wavelength_colour(xy, xy_n, msds):
    """colour.dominant_wavelength for (n, 2) chromaticities, robust to lines through a locus vertex.

    When the line from the white through ``xy`` passes exactly through a tabulated locus point
    (e.g. a monochromatic stimulus), rounding can make colour-science's segment test miss both
    adjoining locus segments: it then returns a NaN intersection and the first tabulated
    wavelength. Those rows are recomputed with the direction from the white rotated by +-1e-9 rad,
    which moves the intersection by ~1e-9 in xy and so cannot change the nearest locus sample.
    """
    wl, xy_b, _xy_c = colour.dominant_wavelength(xy, xy_n, msds)
    wl, xy_b = np.array(wl, dtype=np.float64).reshape(-1), np.reshape(xy_b, (-1, 2)).copy()
    for angle in (1e-9, -1e-9):
        failed = np.flatnonzero(np.any(np.isnan(xy_b), axis=-1))
        if failed.size == 0:
            break
        c, s = np.cos(angle), np.sin(angle)
        d = xy[failed] - xy_n
        xy_rotated = xy_n + np.stack([c * d[:, 0] - s * d[:, 1], s * d[:, 0] + c * d[:, 1]], -1)
        wl_f, xy_b_f, _ = colour.dominant_wavelength(xy_rotated, xy_n, msds)
        wl[failed] = wl_f
        xy_b[failed] = np.reshape(xy_b_f, (-1, 2))
    wl[np.any(np.isnan(xy_b), axis=-1)] = np.nan
    return wl, xy_b
