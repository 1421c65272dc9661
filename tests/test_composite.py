"""reflectance.render.composite: the object mask of :func:`appearance` against scipy's erosion."""

import numpy as np
import pytest
from scipy import ndimage

from reflectance.render.composite import _erode


@pytest.mark.parametrize("shape", [(1, 1), (1, 7), (6, 1), (2, 2), (40, 55)])
@pytest.mark.parametrize("fill", [0.3, 0.8, 1.0])
def test_rim_removal_is_scipy_binary_erosion(shape, fill):
    mask = np.random.default_rng(2).random(shape) < fill
    np.testing.assert_array_equal(_erode(mask), ndimage.binary_erosion(mask))
