"""Adaptive supersampling: more samples in the pixels whose samples disagree.

A render first samples every pixel on the camera's regular n x n grid
(:meth:`reflectance.render.camera.Camera.sample_coordinates`). A pixel is then *refined* when

- a silhouette crosses it: the object seen (or the background) is not the same at every sample
  of its window; or
- the shading curves across it: the mean linear XYZ over its window differs from the mean
  over its own samples by more than ``threshold`` CIELAB units, the difference of each of
  t = X, Y, Z taken through the slope of CIELAB's f at the pixel's exposed value (CIE 15:2004
  Eq. 8.3-8.5; :func:`refine_mask`), on the display's exposure.

The window is the pixel's own n x n samples and the ring of samples around them (one fine-grid
sample of each neighbour, (n + 2)^2 in all), so that a highlight or an edge lying between two
pixels' samples still shows. A shading that varies linearly across the window (the flank of a
broad highlight) leaves the two means equal and needs no refinement: the pixel's regular grid
integrates it exactly; a highlight's peak, a narrow highlight and a shadow edge do not. (A first
design refined where the window's samples *spread* by more than the threshold: on the Fig. 6b
vase it refined 12 % of the pixels, the whole flanks of its highlights, where 2 x 2 is already
0.006 CIEDE2000 from 8 x 8. A second took the difference of the cube roots, not of the linear
values the box filter averages: the flank of a Gaussian highlight is nearly linear in the cube
root, and its worst pixel went unrefined.) The exposure is the one the display will apply,
measured on the first pass's image, so the threshold is in the units of the colour difference
the reader sees.

A refined pixel is sampled again on a regular N x N grid (``supersample``, N > n, the sample
positions of a camera with supersampling N: deterministic) by the same exact machinery (the ID
buffer of the pixel's band of rows at the finer spacing chooses each sample's triangle, the
float64 ray and the cast-shadow rays decide, :func:`reflectance.render.visibility.visibility`
with ``select``), and its value is the box-filter mean of those N x N samples: the same numbers
as the whole image rendered at N x N in that pixel. The pixels are refined in bands of rows
(:func:`refinement_bands`) so that memory stays bounded, and the cost grows with the number of
refined pixels, not with the number of wavelengths (the shading is the table path's).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

if TYPE_CHECKING:
    from reflectance.render.samples import SurfaceSamples

__all__ = ["Refinement", "pixel_spread", "refine_mask", "refinement_bands",
           "REFINE_BAND_SAMPLES", "REFINE_BAND_ID_PIXELS"]

#: refined samples traced at once (bounds the per-sample arrays of a refinement band)
REFINE_BAND_SAMPLES = 1 << 19
#: ID-buffer pixels drawn at once for a refinement band (rows of the finer grid x its columns)
REFINE_BAND_ID_PIXELS = 1 << 23


@dataclass(frozen=True)
class Refinement:
    """How a scene's pixels are refined (the scene's ``camera.adaptive``).

    Attributes
    ----------
    enabled : bool
    threshold : float
        Largest difference, in CIELAB units on the display's exposure, between the mean of a
        pixel's window and of its own samples that leaves it unrefined (see the module's
        description).
    supersample : int
        N: a refined pixel gets N x N samples (more than the camera's n x n).
    """

    enabled: bool = False
    threshold: float = 2.0
    supersample: int = 8

    def __post_init__(self):
        if not (np.isfinite(self.threshold) and self.threshold > 0):
            raise ValueError(f"adaptive threshold must be a positive number, got "
                             f"{self.threshold!r}")
        if isinstance(self.supersample, bool) or not isinstance(self.supersample,
                                                                (int, np.integer)) \
                or not 1 <= self.supersample <= 64:
            raise ValueError(f"adaptive supersample must be an integer in 1 .. 64, got "
                             f"{self.supersample!r}")


def _window_range(values, n):
    """(min, max) per pixel of a fine-grid array (rows, cols) over each pixel's window: its
    n x n samples and the ring of samples around them (edge samples repeated at the band's
    border)."""
    from scipy.ndimage import maximum_filter, minimum_filter

    hi = maximum_filter(values, size=3, mode="nearest")
    lo = minimum_filter(values, size=3, mode="nearest")
    rows, cols = values.shape
    shape = (rows // n, n, cols // n, n)
    return lo.reshape(shape).min(axis=(1, 3)), hi.reshape(shape).max(axis=(1, 3))


def _window_minus_pixel_mean(values, n):
    """Per pixel of a fine-grid array (rows, cols, k): the mean over its window ((n + 2)^2
    samples, edge samples repeated at the band's border) minus the mean of its own n x n."""
    rows, cols = values.shape[:2]
    padded = np.pad(values, ((1, 1), (1, 1), (0, 0)), mode="edge")
    total = np.zeros((rows + 3, cols + 3, values.shape[2]))
    np.cumsum(np.cumsum(padded, axis=0), axis=1, out=total[1:, 1:])  # summed-area table
    r0, c0 = np.arange(0, rows, n), np.arange(0, cols, n)
    r1, c1 = r0 + n + 2, c0 + n + 2
    window = (total[r1][:, c1] - total[r0][:, c1] - total[r1][:, c0] + total[r0][:, c0])
    own = values.reshape(rows // n, n, cols // n, n, -1).mean(axis=(1, 3))
    return window / (n + 2) ** 2 - own


def pixel_spread(samples: SurfaceSamples,
                 XYZ: npt.NDArray[np.float64]
                ) -> tuple[npt.NDArray[np.float32], npt.NDArray[np.bool_]]:
    """Per pixel of a band: the window's mean minus the pixel's own mean, and its silhouettes.

    For shading that varies linearly across the window the two means agree (the midpoint rule
    integrates a linear function exactly, and the window is centred on the pixel); curvature (a
    highlight's peak, an edge, a feature between the samples) makes them differ: for a quadratic
    variation by 12 times the 2 x 2 grid's error of the pixel mean.

    Parameters
    ----------
    samples : SurfaceSamples
        A band of the regular grid (:func:`reflectance.render.visibility.visibility`).
    XYZ : ndarray, shape (N, 3)
        The samples' shaded linear XYZ.

    Returns
    -------
    difference : ndarray of float32, shape (rows // n, cols // n, 3)
        Mean linear XYZ over each pixel's window minus the mean over its own n x n samples.
    silhouette : ndarray of bool, shape (rows // n, cols // n)
        The window's samples do not all see the same object (or all the background).
    """
    n = samples.supersample
    difference = _window_minus_pixel_mean(samples.image(XYZ), n).astype(np.float32)
    lo, hi = _window_range(samples.image(samples.object_id), n)
    return difference, lo != hi


#: CIELAB's f(t) is t^(1/3) above this t and linear below (CIE 15:2004 Eq. 8.5: (6/29)^3)
_TOE = (6.0 / 29.0) ** 3


def refine_mask(difference: npt.NDArray[np.floating], silhouette: npt.NDArray[np.bool_],
                XYZ: npt.NDArray[np.float64], scale: float, threshold: float,
                white: npt.ArrayLike) -> npt.NDArray[np.bool_]:
    """Pixels to refine: a silhouette, or a window-minus-pixel difference (:func:`pixel_spread`)
    worth more than ``threshold`` CIELAB units on the exposure ``scale`` (a factor on XYZ).

    The difference of each of t = X, Y, Z is taken through the slope of CIELAB's f at the
    pixel's own exposed value (CIE 15:2004 Eq. 8.3-8.5: L* = 116 f(Y / Y_n) - 16, a* and b* from
    f(X / X_n), f(Y / Y_n), f(Z / Z_n); f(u) = u^(1/3), or its linear toe below (6/29)^3):
    116 f'(s t / t_n) s abs(difference) / t_n, the largest of the three against the threshold.

    Parameters
    ----------
    difference : ndarray, shape (H, W, 3)
    silhouette : ndarray of bool, shape (H, W)
    XYZ : ndarray, shape (H, W, 3)
        The first pass's image (each pixel's own mean).
    scale : float
        The display's exposure factor on XYZ.
    threshold : float
    white : array_like, shape (3,)
        XYZ of the display white (Y = 1).
    """
    white = np.asarray(white, np.float64)
    s = max(float(scale), 0.0)
    mask = silhouette.copy()
    for c in range(3):  # channel by channel: temporaries of one image plane
        u = np.maximum(XYZ[..., c], 0.0) * (s / white[c])
        slope = 1.0 / (3.0 * np.cbrt(np.maximum(u, _TOE)) ** 2)  # f'(u); the toe's below
        mask |= 116.0 * slope * (s / white[c]) * np.abs(difference[..., c]) > threshold
    return mask


def refinement_bands(mask: npt.NDArray[np.bool_], supersample: int, max_samples: int | None = None,
                     max_id_pixels: int | None = None
                    ) -> list[tuple[tuple[int, int], npt.NDArray[np.intp], npt.NDArray[np.intp]]]:
    """The refinement's bands: ``[(rows, select, pixels)]`` where ``rows`` (start, stop) is a
    band of rows of the N x N fine grid, ``select`` its refined samples (row-major indices in the
    band; pixel by pixel, N x N each, in the order of ``pixels``) and ``pixels`` the flat indices
    (row * width + col) of its refined pixels, increasing.

    A band spans whole pixel rows from the first refined one on; it ends before the row that
    would take it beyond ``max_samples`` refined samples (default :data:`REFINE_BAND_SAMPLES`)
    or ``max_id_pixels`` ID-buffer pixels (default :data:`REFINE_BAND_ID_PIXELS`), and always
    holds at least one pixel row. Rows without refined pixels between bands are skipped.
    """
    mask = np.asarray(mask, bool)
    N = int(supersample)
    max_samples = REFINE_BAND_SAMPLES if max_samples is None else int(max_samples)
    max_id = REFINE_BAND_ID_PIXELS if max_id_pixels is None else int(max_id_pixels)
    height, width = mask.shape
    per_row = np.count_nonzero(mask, axis=1) * N * N
    cols = width * N
    block = (np.arange(N)[:, None] * cols + np.arange(N)[None, :]).ravel()  # a pixel's samples
    bands, row = [], 0
    while row < height:
        if per_row[row] == 0:
            row += 1
            continue
        stop, count = row + 1, per_row[row]
        while (stop < height and count + per_row[stop] <= max_samples
               and (stop + 1 - row) * N * cols <= max_id):
            count += per_row[stop]
            stop += 1
        r, c = np.nonzero(mask[row:stop])
        select = (((r * N) * cols + c * N)[:, None] + block[None, :]).ravel()
        bands.append(((row * N, stop * N), select, (r + row) * width + c))
        row = stop
    return bands
