"""What one render holds while it runs (reflectance.render.session.RenderSession): one set of
the scene's primitives and one ID-buffer window for every band and refinement band, none for a
kept trace, and the window closed however the render ends."""

import dataclasses

import pytest
import yaml

import reflectance.render.integrator as integrator
import reflectance.render.session as session
import reflectance.render.tracing as tracing
from reflectance.io import cache
from reflectance.render.idbuffer import IdRenderer
from reflectance.render.pipeline import render
from reflectance.render.scene import scene_from_dict


@pytest.fixture
def windows(monkeypatch):
    """The ID-buffer windows the sessions open, each with whether it was closed."""
    opened = []

    class Counted(IdRenderer):
        def __init__(self, primitives):
            super().__init__(primitives)
            self.closed = False
            opened.append(self)

        def close(self):
            self.closed = True
            super().close()

    monkeypatch.setattr(session, "IdRenderer", Counted)
    return opened


@pytest.fixture(scope="module")
def hard(root):
    """The hard bench scene (a vase and spheres, three lights), small, with adaptive
    supersampling."""
    doc = yaml.safe_load((root / "workflow" / "scenes" / "bench_hard.yaml").read_text())
    doc["camera"].update(width=32, height=32)
    doc["camera"]["adaptive"] = {"enabled": True, "threshold": 2.0, "supersample": 4}
    return scene_from_dict(doc, spectra_dir=root / "spectra")


def test_one_window_for_every_band_and_refinement_band(hard, monkeypatch, windows):
    scene = hard
    monkeypatch.setattr(tracing, "SINGLE_TILE_SAMPLES", 0)
    monkeypatch.setattr(tracing, "TILE_SAMPLES", 32 * 2 * 2 * 8)  # bands of 8 pixel rows
    phases = []
    result = render(scene, progress=phases.append, threads=2)
    assert len(tracing.tiles(scene.camera)) == 4 and result.stats["refined"] > 0
    assert any(p.startswith("rows 8-16: ") for p in phases)
    assert any(p.startswith("refining rows ") for p in phases)
    assert len(windows) == 1 and windows[0].closed


def test_the_tally_counts_every_sample_traced_and_shaded(hard, monkeypatch):
    """render's tally: (done, total) samples, the first pass's in its bands, then the adaptive
    refinement's added when its pixels are picked; at the end done = total = the samples spent
    (its stats' samples per pixel times the pixels)."""
    scene = hard
    monkeypatch.setattr(tracing, "SINGLE_TILE_SAMPLES", 0)
    monkeypatch.setattr(tracing, "TILE_SAMPLES", 32 * 2 * 2 * 8)  # bands of 8 pixel rows
    counts = []
    result = render(scene, tally=lambda done, total: counts.append((done, total)), threads=1)
    first = 32 * 32 * 2 * 2
    band = 32 * 8 * 2 * 2
    assert counts[:5] == [(0, first), (band, first), (2 * band, first), (3 * band, first),
                          (first, first)]
    refined = round(result.stats["refined"] * 32 * 32)
    assert refined > 0 and counts[5] == (first, first + refined * 4 * 4)
    done, total = zip(*counts)
    assert list(done) == sorted(done) and counts[-1] == (total[-1], total[-1])
    assert total[-1] == round(result.stats["samples_per_pixel"] * 32 * 32)


def test_a_kept_trace_opens_no_window(hard, windows):
    scene = dataclasses.replace(hard, refinement=dataclasses.replace(hard.refinement,
                                                                    enabled=False))
    cache.clear()
    render(scene, keep_trace=True)
    render(scene, keep_trace=True)
    assert len(windows) == 1 and windows[0].closed and len(cache.TRACES) == 1


def test_the_window_is_closed_when_the_render_fails(hard, monkeypatch, windows):
    def fail(*args, **kwargs):
        raise RuntimeError("shading failed")

    monkeypatch.setattr(integrator, "shade_samples", fail)
    with pytest.raises(RuntimeError, match="shading failed"):
        render(hard, threads=2)
    assert len(windows) == 1 and windows[0].closed
