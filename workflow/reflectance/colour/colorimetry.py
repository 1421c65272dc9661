"""Colorimetry on a wavelength grid: CMFs, illuminants, tristimulus weights, xy, CIELAB, dominant wavelength.

Everything tabulated (CIE colour matching functions, CIE illuminant SPDs) comes from colour-science
and is put onto the caller's grid exactly the way colour-science does it
(``colour.SpectralShape`` + ``.copy().align()``): its default interpolation (Sprague 1880 for
uniformly tabulated data, cubic spline otherwise) and constant extrapolation beyond the tabulated
range (CIE 15:2004 and CIE 167:2005 recommendations). Note that the CIE illuminants of
colour-science are tabulated from 300 nm to 780 nm only, so on a 360-830 nm grid their last value
(780 nm) is repeated up to 830 nm; the CMFs there are below 1e-4 of their peak, so this is
immaterial. The tables are computed by colour-science once and then read back from a cache
(:mod:`reflectance.colour.tables`), so this module itself needs numpy only; its formulas (xy,
CIELAB, dominant wavelength) reproduce colour-science's functions to float precision (checked by
the tests against colour-science).

This module knows nothing of BRDFs or displays: it turns spectra into CIE XYZ.

References
----------
-   CIE 15:2004 Colorimetry, 3rd edition, §7 (tristimulus values, normalisation k), §7.3
    (chromaticity coordinates), §8.2.1 (CIE 1976 L*a*b*) and §9.1 (dominant wavelength,
    complementary wavelength, excitation purity).
-   Cook, R. L., & Torrance, K. E. (1982). A Reflectance Model for Computer Graphics. ACM TOG 1(1),
    "Determining the RGB values".
"""

from __future__ import annotations

import functools

import numpy as np
import numpy.typing as npt

from reflectance.colour import tables

__all__ = [
    "OBSERVER_DEFAULT",
    "cmfs",
    "illuminant_sd",
    "illuminant_range_nm",
    "cmfs_wavelengths",
    "tristimulus_weights",
    "tristimulus_weights_spd",
    "white_XYZ",
    "spectrum_to_XYZ",
    "XYZ_to_xy",
    "XYZ_to_Lab",
    "dominant_wavelength",
]

OBSERVER_DEFAULT = "CIE 1931 2 Degree Standard Observer"
"""Cook & Torrance 1982 cite CIE 15 (1970), i.e. the CIE 1931 2 degree standard observer."""

_DOMINANT_WAVELENGTH_CHUNK = 2048
"""The dominant wavelength builds (n_colours, n_locus) intersection arrays; chunking bounds memory
(~2048 x 472 x 8 B per array) for whole images."""


_ACHROMATIC_XY = 1e-12
"""Distance in xy from the white below which a colour counts as achromatic (float rounding)."""


def _validate_observer(observer):
    """colour-science's key of ``observer`` (case, slug and canonical variants accepted)."""
    key = tables.resolve_observer(observer)
    if key is None:
        raise ValueError(
            f"observer: unknown standard observer {observer!r}; known: "
            f"{', '.join(tables.observer_names())}"
        )
    return key


def _validate_illuminant(name):
    """colour-science's key of illuminant ``name`` (case, slug and canonical variants accepted)."""
    key = tables.resolve_illuminant(name)
    if key is None:
        raise ValueError(
            f"illuminant: unknown illuminant {name!r}; known: {', '.join(tables.illuminant_names())}"
        )
    return key


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


@functools.lru_cache(maxsize=64)
def _cmfs_cached(observer, key):
    return tables.cmfs_aligned(_validate_observer(observer), key)


@functools.lru_cache(maxsize=64)
def _illuminant_cached(name, key):
    return tables.illuminant_aligned(_validate_illuminant(name), key)


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


def tristimulus_weights_spd(spd: npt.ArrayLike, wavelengths: npt.ArrayLike,
                            observer: str = OBSERVER_DEFAULT) -> npt.NDArray[np.float64]:
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


def cmfs(observer: str = OBSERVER_DEFAULT,
         wavelengths: npt.ArrayLike | None = None) -> npt.NDArray[np.float64]:
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
    >>> cmfs("CIE 1931 2 Degree Standard Observer", np.arange(360, 831, 5.0))[39].round(4).tolist()
    [0.5121, 1.0, 0.0057]
    """
    if wavelengths is None:
        return np.array(tables.cmfs_tabulated(_validate_observer(observer))[1])
    return _cmfs_cached(observer, _grid_key(wavelengths)).copy()


def illuminant_sd(name: str = "D65",
                  wavelengths: npt.ArrayLike | None = None) -> npt.NDArray[np.float64]:
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
        return np.array(tables.illuminant_tabulated(_validate_illuminant(name))[1])
    return _illuminant_cached(name, _grid_key(wavelengths)).copy()


def cmfs_wavelengths(observer: str = OBSERVER_DEFAULT) -> npt.NDArray[np.float64]:
    """The wavelengths (nm) of a CIE standard observer's own tabulation in colour-science.

    That is ``colour.MSDS_CMFS[observer].wavelengths``, read from the table cache
    (:mod:`reflectance.colour.tables`), so a caller that needs no other colour-science function
    does not import it.

    Examples
    --------
    >>> w = cmfs_wavelengths("CIE 1931 2 Degree Standard Observer")
    >>> float(w[0]), float(w[-1]), len(w)
    (360.0, 830.0, 471)
    """
    return tables.cmfs_tabulated(_validate_observer(observer))[0]


def illuminant_range_nm(name: str = "D65") -> tuple[float, float]:
    """First and last wavelength (nm) of colour-science's own tabulation of a CIE illuminant.

    That is ``colour.SDS_ILLUMINANTS[name].shape``'s start and end, read from the table cache
    (:mod:`reflectance.colour.tables`), so a caller that needs no other colour-science function
    does not import it. Beyond these, :func:`illuminant_sd` holds the end values constant.

    Examples
    --------
    >>> illuminant_range_nm("D65")
    (300.0, 780.0)
    """
    wavelengths = tables.illuminant_tabulated(_validate_illuminant(name))[0]
    return float(wavelengths[0]), float(wavelengths[-1])


def tristimulus_weights(wavelengths: npt.ArrayLike, illuminant: str = "D65",
                        observer: str = OBSERVER_DEFAULT) -> npt.NDArray[np.float64]:
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
    illuminant : str or colour.SpectralDistribution
        A key of ``colour.SDS_ILLUMINANTS``, or an illuminant's spectral distribution (nm),
        interpolated linearly onto the grid (:func:`tristimulus_weights_spd`).
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
    if not isinstance(illuminant, str) and type(illuminant).__module__.startswith("colour."):
        # a colour-science SpectralDistribution: its power interpolated linearly onto the grid,
        # as an SPD file's is (reflectance.audit.shortcuts.audit_weights)
        grid = np.asarray(wavelengths, dtype=np.float64)
        w = np.asarray(illuminant.wavelengths, dtype=np.float64)
        if grid.min() < w[0] or grid.max() > w[-1]:
            raise ValueError(f"illuminant {illuminant.name!r}: covers {w[0]:g}-{w[-1]:g} nm, the "
                             f"grid needs {grid.min():g}-{grid.max():g} nm")
        return tristimulus_weights_spd(np.interp(grid, w, np.asarray(illuminant.values,
                                                                      dtype=np.float64)),
                                       wavelengths, observer)
    key = _grid_key(wavelengths)
    _validate_illuminant(illuminant)
    _validate_observer(observer)
    return _weights_cached(key, illuminant, observer).copy()


def spectrum_to_XYZ(S: npt.ArrayLike, W: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """CIE XYZ of spectra ``S[..., n_wl]`` with tristimulus weights ``W`` (n_wl, 3): ``S @ W``.

    Examples
    --------
    >>> W = tristimulus_weights(np.arange(360, 831, 5.0))
    >>> spectrum_to_XYZ(np.full((2, 95), 0.5), W)[:, 1].round(12).tolist()
    [0.5, 0.5]
    """
    S = np.asarray(S, dtype=np.float64)
    W = np.asarray(W, dtype=np.float64)
    if W.ndim != 2 or W.shape[1] != 3:
        raise ValueError(f"W: expected shape (n_wl, 3), got {W.shape}")
    if S.ndim == 0 or S.shape[-1] != W.shape[0]:
        raise ValueError(f"S: last axis must have {W.shape[0]} wavelengths, got shape {S.shape}")
    return S @ W


def white_XYZ(illuminant: str = "D65", observer: str = OBSERVER_DEFAULT,
              wavelengths: npt.ArrayLike | None = None) -> npt.NDArray[np.float64]:
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
    >>> white_XYZ("D65").round(4).tolist()
    [0.9505, 1.0, 1.0888]
    """
    if wavelengths is None:
        wavelengths = tables.cmfs_tabulated(_validate_observer(observer))[0]
    W = tristimulus_weights(wavelengths, illuminant, observer)
    return spectrum_to_XYZ(np.ones(W.shape[0]), W)


def XYZ_to_xy(XYZ: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """CIE xy chromaticity coordinates of CIE XYZ: ``x = X / (X + Y + Z)``, ``y = Y / (X + Y + Z)``.

    As colour-science's ``colour.XYZ_to_xy`` (to the bit): where ``X + Y + Z`` is 0 or a quotient
    is not finite, the coordinate is 0 (colour-science's default "Ignore Zero Conversion" division).

    Parameters
    ----------
    XYZ : array_like
        Shape ``(..., 3)``.

    Returns
    -------
    numpy.ndarray
        Shape ``(..., 2)``.

    References
    ----------
    CIE 15:2004 §7.3, equations 7.3-7.4.

    Examples
    --------
    >>> XYZ_to_xy([0.20654008, 0.12197225, 0.05136952]).round(8).tolist()
    [0.54369557, 0.32107944]
    """
    XYZ = np.asarray(XYZ, dtype=np.float64)
    X, Y, Z = XYZ[..., 0], XYZ[..., 1], XYZ[..., 2]
    total = X + Y + Z
    with np.errstate(divide="ignore", invalid="ignore"):
        xy = np.stack([X / total, Y / total], axis=-1)
    return np.nan_to_num(xy, nan=0.0, posinf=0.0, neginf=0.0)


def _lightness_function_CIE1976(t):
    """CIE 15:2004 §8.2.1: f(t) = t^(1/3) for t > (24/116)^3, else (841/108) t + 16/116."""
    # |t|^(1/3) only where t > 0 is used; abs keeps np.where's other branch free of warnings.
    return np.where(t > (24 / 116) ** 3, np.abs(t) ** (1 / 3), (841 / 108) * t + 16 / 116)


def XYZ_to_Lab(XYZ: npt.ArrayLike, illuminant_xy: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """CIE 1976 L*a*b* of CIE XYZ (Y = 1 scale) relative to the white of chromaticity ``illuminant_xy``.

    The white is ``X_n = x / y``, ``Y_n = 1``, ``Z_n = (1 - x - y) / y``; then ``L* = 116 f(Y/Y_n)
    - 16``, ``a* = 500 (f(X/X_n) - f(Y/Y_n))``, ``b* = 200 (f(Y/Y_n) - f(Z/Z_n))``, in colour-science's
    order of operations, so that the result equals ``colour.XYZ_to_Lab(XYZ, illuminant_xy)`` to the
    bit. L* is 0-100.

    Parameters
    ----------
    XYZ : array_like
        Shape ``(..., 3)``, relative to the white at Y = 1.
    illuminant_xy : array_like
        Chromaticity (x, y) of the reference white.

    Returns
    -------
    numpy.ndarray
        Shape ``(..., 3)``: L*, a*, b*.

    References
    ----------
    CIE 15:2004 §8.2.1, equations 8.3-8.11.

    Examples
    --------
    >>> XYZ_to_Lab([0.20654008, 0.12197225, 0.05136952], [0.3127, 0.3290]).round(3).tolist()
    [41.528, 52.639, 26.923]
    """
    XYZ = np.asarray(XYZ, dtype=np.float64)
    x_n, y_n = np.asarray(illuminant_xy, dtype=np.float64)[..., :2].T
    with np.errstate(divide="ignore", invalid="ignore"):
        Y_y = np.nan_to_num(1.0 / y_n, nan=0.0, posinf=0.0, neginf=0.0)
    X_n, Y_n, Z_n = x_n * Y_y, 1.0, (1 - (x_n + y_n)) * Y_y
    f_X = _lightness_function_CIE1976(XYZ[..., 0] / X_n)
    f_Y = _lightness_function_CIE1976(XYZ[..., 1] / Y_n)
    f_Z = _lightness_function_CIE1976(XYZ[..., 2] / Z_n)
    return np.stack([116 * f_Y - 16, 500 * (f_X - f_Y), 200 * (f_Y - f_Z)], axis=-1)


def dominant_wavelength(XYZ: npt.ArrayLike, illuminant: str = "D65",
                        observer: str = OBSERVER_DEFAULT,
                        wavelengths: npt.ArrayLike | None = None
                       ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """Dominant wavelength and excitation purity of CIE XYZ colours relative to a white.

    Purples, which have no dominant wavelength, get their complementary wavelength as a negative
    number. The wavelength is colour-science's (``colour.dominant_wavelength``, reproduced to the
    bit by :func:`_dominant_wavelength_locus`): the locus sample closest to the intersection of the
    ray from the white through the colour with the spectral locus, i.e. it is quantised to the
    CMF tabulation (1 nm). The locus is the observer's CMFs in xy, on their own tabulation. Colours
    are processed in chunks of (n_colours, n_locus) arrays; any input shape ``(..., 3)`` is
    accepted.

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
    >>> wl, p = dominant_wavelength([0.20654008, 0.12197225, 0.05136952])
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
    locus_wavelengths, locus_xy = _spectral_locus(_validate_observer(observer))

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
        wl_i, xy_b = _dominant_wavelength_robust(xy[i], xy_n, locus_wavelengths, locus_xy)
        wl[i] = wl_i
        # CIE 15:2004 §9.1 excitation purity; xy_b lies on the purple line for purples.
        purity[i] = np.hypot(*(xy[i] - xy_n).T) / np.hypot(*(xy_b - xy_n).T)
    shape = XYZ.shape[:-1]
    return wl.reshape(shape), purity.reshape(shape)


@functools.lru_cache(maxsize=None)
def _spectral_locus(observer_key):
    """(wavelengths, xy) of an observer's spectral locus, on the CMFs' own tabulation."""
    wavelengths, xyz_bar = tables.cmfs_tabulated(observer_key)
    xy = XYZ_to_xy(xyz_bar)
    xy.setflags(write=False)
    return wavelengths, xy


def _extend_line_segment(a, b, distance=1.0):
    """The point ``distance`` beyond ``b`` on the line from ``a`` through ``b`` (colour-science's
    ``colour.geometry.extend_line_segment``, zero-division giving 0)."""
    d = np.linalg.norm(a - b, axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        step = np.nan_to_num((b - a) / d[..., None], nan=0.0, posinf=0.0, neginf=0.0)
    return b + step * distance


def _intersect_line_segments(l_1, l_2):
    """Intersections of every segment of ``l_1`` (n, 4) with every segment of ``l_2`` (m, 4).

    Returns ``(xy (n, m, 2), intersect (n, m))``, NaN where they do not intersect: the pairs of
    :func:`_intersect_line_segments_pairs`, broadcast.
    """
    xy, intersect = _intersect_line_segments_pairs(l_1[:, None, :], l_2[None, :, :])
    xy[~intersect] = np.nan
    return xy, intersect


_LOCUS_MARGIN = 1e-12
"""Rounding allowance of the shortlists of :func:`_closest_locus_sample`: a cross product or a
squared distance computed in another order is within ~1e-15 of the exact formula's (xy below 1),
so a margin of 1e-12 leaves out nothing the exact test or the exact nearest sample would pick."""


def _closest_locus_sample(xy, xy_n, locus_xy, inverse):
    """Index of the locus sample nearest to where the ray from the white meets the closed locus.

    The ray runs from the white ``xy_n`` through ``xy`` (away from ``xy``'s side if ``inverse``),
    one unit long; the locus is closed by the purple line. As colour-science's
    ``closest_spectral_locus_wavelength``, including its choice among several intersections (the
    smallest x and the smallest y, sorted separately) and its nearest sample by Euclidean
    distance (first on ties; a ray that meets nothing gives index 0 and a NaN point).

    colour-science tests every ray against every locus segment and measures the distance to every
    locus sample. Here both are first shortlisted with one matrix product each (a segment whose
    ends lie strictly on one side of the ray's line cannot meet it; a sample farther than the
    nearest by more than the rounding allowance :data:`_LOCUS_MARGIN` cannot be the nearest), and
    only the shortlisted pairs, a few per ray, are computed with colour-science's formulas (the same
    operations on the same numbers): the same intersections and the same index, to the bit.
    """
    xy_e = _extend_line_segment(xy, xy_n) if inverse else _extend_line_segment(xy_n, xy)
    closed = np.vstack([locus_xy, locus_xy[0]])
    segments = np.hstack([closed, np.roll(closed, 1, axis=0)])
    rays = np.concatenate([xy_n, xy_e], axis=-1)
    # the side of each vertex P of the ray's line: (x_2 - x_1)(y_1 - P_y) - (y_2 - y_1)(x_1 - P_x)
    dx, dy = rays[:, 2] - rays[:, 0], rays[:, 3] - rays[:, 1]
    line = np.stack([dy, -dx, dx * rays[:, 1] - dy * rays[:, 0]], axis=-1)
    side = line @ np.column_stack([closed, np.ones(len(closed))]).T
    above, below = side > _LOCUS_MARGIN, side < -_LOCUS_MARGIN
    # segment k runs from vertex k to vertex k - 1
    apart = ~((above & np.roll(above, 1, axis=1)) | (below & np.roll(below, 1, axis=1)))
    ray, segment = np.nonzero(apart)
    points, hit = _intersect_line_segments_pairs(rays[ray], segments[segment])
    # colour sorts x and y of the intersections separately and keeps the first (NaN sort last)
    xy_wl = np.full((len(xy), 2), np.inf)
    np.minimum.at(xy_wl, ray[hit], points[hit])
    xy_wl[np.isinf(xy_wl[:, 0])] = np.nan
    index = np.zeros(len(xy), dtype=np.intp)  # colour's argmin over NaN distances: 0
    found = np.flatnonzero(~np.isnan(xy_wl[:, 0]))
    if found.size:
        p = xy_wl[found]
        squared = (np.sum(p * p, axis=1)[:, None] - 2.0 * p @ closed.T
                   + np.sum(closed * closed, axis=1)[None, :])
        row, sample = np.nonzero(squared <= squared.min(axis=1, keepdims=True) + _LOCUS_MARGIN)
        d = p[row] - closed[sample]
        distance = np.sqrt(d[:, 0] * d[:, 0] + d[:, 1] * d[:, 1])  # colour's, per pair
        order = np.lexsort((sample, distance, row))  # per ray: nearest first, then first index
        first = order[np.r_[True, row[order][1:] != row[order][:-1]]]
        index[found[row[first]]] = sample[first]
    return index, xy_wl


def _intersect_line_segments_pairs(l_1, l_2):
    """Intersections of the segments ``l_1[..., :]`` and ``l_2[..., :]`` (``(x_1, y_1, x_2, y_2)``
    in the last axis, broadcast against each other): ``(xy (..., 2), intersect (...))``. The
    standard parametric solution, in the order of operations of colour-science's
    ``colour.geometry.intersect_line_segments``."""
    x_1, y_1, x_2, y_2 = np.moveaxis(l_1, -1, 0)
    x_3, y_3, x_4, y_4 = np.moveaxis(l_2, -1, 0)
    x_4_x_3 = x_4 - x_3
    y_1_y_3 = y_1 - y_3
    y_4_y_3 = y_4 - y_3
    x_1_x_3 = x_1 - x_3
    x_2_x_1 = x_2 - x_1
    y_2_y_1 = y_2 - y_1
    numerator_a = x_4_x_3 * y_1_y_3 - y_4_y_3 * x_1_x_3
    numerator_b = x_2_x_1 * y_1_y_3 - y_2_y_1 * x_1_x_3
    denominator = y_4_y_3 * x_2_x_1 - x_4_x_3 * y_2_y_1
    with np.errstate(divide="ignore", invalid="ignore"):
        u_a = numerator_a / denominator
        u_b = numerator_b / denominator
    intersect = (u_a >= 0) & (u_a <= 1) & (u_b >= 0) & (u_b <= 1)
    xy = np.stack([x_1 + x_2_x_1 * u_a, y_1 + y_2_y_1 * u_a], axis=-1)
    return xy, intersect


def _dominant_wavelength_locus(xy, xy_n, locus_wavelengths, locus_xy):
    """Dominant (or, for purples, negative complementary) wavelength of (n, 2) chromaticities.

    CIE 15:2004 §9.1: the dominant wavelength is where the straight line from the white through
    the colour, extended, meets the spectral locus; if it meets the purple line instead, the
    complementary wavelength is where the line meets the locus on the opposite side of the white.
    Reproduces ``colour.dominant_wavelength(xy, xy_n, cmfs)[:2]`` (colour-science 0.4) to the bit:
    the wavelength is the nearest tabulated locus sample to the intersection.

    Returns ``(wavelength (n,), boundary point xy_b (n, 2))``.
    """
    xy_n = np.resize(xy_n, xy.shape)
    i_wl, xy_wl = _closest_locus_sample(xy, xy_n, locus_xy, inverse=False)
    wl = np.asarray(locus_wavelengths)[i_wl]
    xy_e = _extend_line_segment(xy_n, xy)
    purple_line = np.hstack([locus_xy[0], locus_xy[-1]])[None, :]
    _, purple = _intersect_line_segments(np.concatenate([xy_n, xy_e], axis=-1), purple_line)
    purple = purple[:, 0]
    if np.any(purple):
        i_wl_c, _ = _closest_locus_sample(xy[purple], xy_n[purple], locus_xy, inverse=True)
        wl[purple] = -np.asarray(locus_wavelengths)[i_wl_c]
    return wl, xy_wl


def _dominant_wavelength_robust(xy, xy_n, locus_wavelengths, locus_xy):
    """:func:`_dominant_wavelength_locus`, robust to lines through a locus vertex.

    When the line from the white through ``xy`` passes exactly through a tabulated locus point
    (e.g. a monochromatic stimulus), rounding can make the segment test miss both adjoining locus
    segments: colour-science then returns a NaN intersection and the first tabulated wavelength.
    Those rows are recomputed with the direction from the white rotated by +-1e-9 rad, which moves
    the intersection by ~1e-9 in xy and so cannot change the nearest locus sample.
    """
    wl, xy_b = _dominant_wavelength_locus(xy, xy_n, locus_wavelengths, locus_xy)
    wl, xy_b = np.array(wl, dtype=np.float64).reshape(-1), np.reshape(xy_b, (-1, 2)).copy()
    for angle in (1e-9, -1e-9):
        failed = np.flatnonzero(np.any(np.isnan(xy_b), axis=-1))
        if failed.size == 0:
            break
        c, s = np.cos(angle), np.sin(angle)
        d = xy[failed] - xy_n
        xy_rotated = xy_n + np.stack([c * d[:, 0] - s * d[:, 1], s * d[:, 0] + c * d[:, 1]], -1)
        wl_f, xy_b_f = _dominant_wavelength_locus(xy_rotated, xy_n, locus_wavelengths, locus_xy)
        wl[failed] = wl_f
        xy_b[failed] = np.reshape(xy_b_f, (-1, 2))
    wl[np.any(np.isnan(xy_b), axis=-1)] = np.nan
    return wl, xy_b
