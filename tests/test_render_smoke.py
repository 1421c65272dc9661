"""Smoke tests of the command line's renderer paths that the figures do not take, and the
per-angle Fresnel table of a dielectric at the renderer's default size against brute force."""

import inspect
import json

import colour
import numpy as np
import pytest

from reflectance.cli import main
from reflectance.io.images import read_exr
from reflectance.optics.spectra import load_material
from reflectance.render.shading import Ambient, ShadingMaterial, shade

from test_shading import lights_at, random_geometry


def test_bench_runs_on_a_tiny_size(root, capsys):
    """`reflectance bench` with one tiny size and one run of each kind: the report's numbers are
    there and sane (brute-force shading agrees with the table, grids compared)."""
    assert main(["bench", "--sizes", "24", "--runs", "1", "--brute-force-runs", "1",
                 "--grids", "5", "--grid-size", "24", "--spectra-dir", str(root / "spectra"),
                 "--json"]) == 0
    out = capsys.readouterr().out
    results = json.loads(out)
    # the grid comparison runs at --grid-size when it is among --sizes (24: it is)
    (grid,) = results[0]["grids"]
    assert grid["step_nm"] == 5.0 and grid["wavelengths"] == 95
    assert grid["table_s"] > 0 and grid["brute-force_s"] > 0
    text = json.dumps(results)
    assert "24" in text
    numbers = [v for v in _leaves(results) if isinstance(v, (int, float))
               and not isinstance(v, bool)]
    assert numbers and all(np.isfinite(numbers))
    # the table-vs-brute CIEDE2000 the rendering guide quotes is reported and imperceptible
    dE = [v for k, v in _items(results) if "de2000" in k.lower() and isinstance(v, (int, float))]
    assert dE and max(dE) < 0.01, results


def test_bench_report_prints(root, capsys):
    assert main(["bench", "--sizes", "16", "--runs", "1", "--brute-force-runs", "0",
                 "--grids", "--spectra-dir", str(root / "spectra")]) == 0
    assert "16" in capsys.readouterr().out


def _items(node, key=""):
    if isinstance(node, dict):
        for k, v in node.items():
            yield from _items(v, str(k))
    elif isinstance(node, list):
        for v in node:
            yield from _items(v, key)
    else:
        yield key, node


def _leaves(node):
    return [v for _, v in _items(node)]


def test_render_brute_force_agrees_with_the_table(root, tmp_path):
    """`reflectance render --spectral brute-force` on the example scene: same image as the
    default per-angle table, to far below a just-noticeable difference."""
    scene = root / "workflow" / "scenes" / "example_spheres.yaml"
    images = {}
    for spectral in ("table", "brute-force"):
        exr = tmp_path / f"{spectral}.exr"
        assert main(["render", str(scene), "-o", str(exr), "--width", "32", "--height", "20",
                     "--spectral", spectral, "--spectra-dir", str(root / "spectra"),
                     "--quiet"]) == 0
        images[spectral], _ = read_exr(exr)
    brute, table = images["brute-force"], images["table"]
    assert brute.shape == (20, 32, 3) and brute[..., 1].max() > 0
    scale = 1.0 / brute[..., 1].max()
    white = colour.XYZ_to_xy([0.95047, 1.0, 1.08883])
    dE = colour.delta_E(colour.XYZ_to_Lab(table * scale, white),
                        colour.XYZ_to_Lab(brute * scale, white), method="CIE 2000")
    assert np.nanmax(dE) < 0.01


def test_dielectric_table_at_the_default_size_equals_brute_force(root, grid):
    """A dielectric's F climbs from 0.04 to 1 in the last degrees before grazing, where a
    table in c = V.H is coarsest relative to the change: the default table must still agree."""
    default_size = inspect.signature(shade).parameters["table_size"].default
    vinyl = load_material("Vinyl", grid, spectra_dir=root / "spectra")
    assert np.all(vinyl.k == 0) or np.max(vinyl.k) < 1e-3  # a dielectric
    N, V, L = random_geometry(11, 2000)  # V.H over (0, 1], grazing included
    material = ShadingMaterial(model="CookTorrance1982", s=1.0, d=0.0, n=vinyl.n, k=vinyl.k,
                               albedo=vinyl.F0, roughness=0.3, shadowing="v-cavity")
    lights = lights_at([L[0], L[1]], spectrum="D65")
    ambient = Ambient(0.0, "intensity", "D65")
    args = (np.zeros_like(N), N, V, np.zeros((len(N), 2)), material, lights)
    table = shade(*args, ambient=ambient, wavelengths=grid)
    brute = shade(*args, ambient=ambient, wavelengths=grid, spectral="brute-force")
    assert table[:, 1].max() > 0
    white = colour.XYZ_to_xy([0.95047, 1.0, 1.08883])
    scale = 1.0 / brute[:, 1].max()
    dE = colour.delta_E(colour.XYZ_to_Lab(table * scale, white),
                        colour.XYZ_to_Lab(brute * scale, white), method="CIE 2000")
    assert np.nanmax(dE) < 0.01, (default_size, np.nanmax(dE))
    np.testing.assert_allclose(table, brute, rtol=1e-4, atol=1e-6 * brute[:, 1].max())  # 65 entries: 9e-4


def test_bench_error_against_the_reference_vanishes_at_the_reference_sampling(root):
    """The bench's converged-reference error is 0 when the image is the reference itself, and
    positive (CIEDE2000 mean <= p95) with fewer samples."""
    from reflectance.cli import _default_bench_scene
    from reflectance.bench.measure import bench_size

    doc = _default_bench_scene()
    same = bench_size(doc, 16, supersample=2, runs=1, brute_force_runs=0,
                      spectra_dir=root / "spectra", reference_supersample=2)
    assert same["spp"] == 4 and same["dE_reference_mean"] == same["dE_reference_p95"] == 0.0
    fewer = bench_size(doc, 16, supersample=1, runs=1, brute_force_runs=0,
                       spectra_dir=root / "spectra", reference_supersample=4)
    assert 0.0 < fewer["dE_reference_mean"] and fewer["dE_reference_p95"] > 0.0
    from reflectance.bench.run import crosscheck_status
    assert "Mitsuba" in crosscheck_status()
