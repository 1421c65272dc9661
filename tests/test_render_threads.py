"""The renderer's threads (reflectance.render.parallel): the same image, bit for bit, at any
thread count; the thread count's sources."""

import numpy as np
import pytest
import yaml

import reflectance.render.tracing as tracing
from reflectance.render.parallel import THREADS_VARIABLE, pieces, render_threads
from reflectance.render.pipeline import render
from reflectance.render.scene import scene_from_dict


def hard_scene(root, size=48, adaptive=True):
    """The hard bench scene (a vase and spheres; two point lights and a sun: one perspective
    light map, a cube map, an orthographic one), small."""
    doc = yaml.safe_load((root / "workflow" / "scenes" / "bench_hard.yaml").read_text())
    doc["camera"].update(width=size, height=size)
    doc["camera"]["adaptive"] = {"enabled": adaptive, "threshold": 2.0, "supersample": 4}
    return scene_from_dict(doc, spectra_dir=root / "spectra")


def same_bits(a, b):
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


@pytest.fixture(scope="module")
def serial_render(root):
    """The hard scene and its serial render (threads=1): the one reference of both thread
    counts below, computed once."""
    scene = hard_scene(root)
    return scene, render(scene, components=True, threads=1)


@pytest.mark.parametrize("threads", [2, 3])
def test_threads_render_the_serial_images_bit_for_bit(serial_render, threads):
    scene, serial = serial_render
    parallel = render(scene, components=True, threads=threads)
    assert serial.stats["refined"] > 0 and 0 < min(serial.stats["shadowed"])
    assert same_bits(parallel.XYZ, serial.XYZ)
    assert all(same_bits(parallel.components[k], serial.components[k])
               for k in serial.components)
    assert parallel.stats == serial.stats
    assert np.array_equal(parallel.refined, serial.refined)


def test_threads_render_bands_bit_for_bit(root, monkeypatch):
    import reflectance.render.shading as shading
    import reflectance.render.shadows as shadows

    scene = hard_scene(root, size=40, adaptive=False)
    monkeypatch.setattr(tracing, "SINGLE_TILE_SAMPLES", 0)
    monkeypatch.setattr(tracing, "TILE_SAMPLES", 40 * 2 * 2 * 7)  # bands of 7 pixel rows
    assert len(tracing.tiles(scene.camera)) == 6
    # a band here holds 1,120 samples, fewer than pieces' least (4,096): split them anyway, into
    # pieces of at least 16, so that each band's shadows and shading are shared between threads
    split = []

    def small_pieces(n, threads, most, least=None):
        out = pieces(n, threads, most, 16)
        split.append((threads, len(out)))
        return out

    for module in (shading, shadows):
        monkeypatch.setattr(module, "pieces", small_pieces)
    serial = render(scene, threads=1)
    assert serial.stats["hit"] > 0
    assert same_bits(render(scene, threads=2).XYZ, serial.XYZ)
    assert max(count for threads, count in split if threads == 2) > 1


def test_thread_count_from_argument_environment_or_cores(monkeypatch):
    import os

    monkeypatch.delenv(THREADS_VARIABLE, raising=False)
    monkeypatch.delenv("OMP_NUM_THREADS", raising=False)
    assert render_threads() == len(os.sched_getaffinity(0))
    monkeypatch.setenv("OMP_NUM_THREADS", "5")  # a scheduler's grant (Snakemake: the rule's)
    assert render_threads() == 5
    monkeypatch.setenv(THREADS_VARIABLE, "3")
    assert render_threads() == 3
    assert render_threads(1) == 1
    for bad in ("0", "two", "1.5", "-2"):
        monkeypatch.setenv(THREADS_VARIABLE, bad)
        with pytest.raises(ValueError, match=THREADS_VARIABLE):
            render_threads()
    with pytest.raises(ValueError, match="threads"):
        render_threads(True)
    monkeypatch.delenv(THREADS_VARIABLE)
    monkeypatch.setenv("OMP_NUM_THREADS", "4,2")  # OpenMP's list per nesting level: the first
    assert render_threads() == 4
    for theirs in ("x", "0", ""):  # OpenMP's business, not a reason to refuse a render
        monkeypatch.setenv("OMP_NUM_THREADS", theirs)
        assert render_threads() == len(os.sched_getaffinity(0))


def test_a_forked_child_gets_pools_of_its_own():
    """A pool made before a fork has no threads in the child: work queued there would wait
    forever (the child here gives up after 20 s and exits 3)."""
    import os
    import signal

    from reflectance.render.parallel import Tasks

    import time

    # the parent's pool of 2, both of its threads started (each busy when the next call came)
    assert Tasks(2).map(time.sleep, [0.2] * 4) == [None] * 4
    pid = os.fork()
    if pid == 0:  # the child
        signal.signal(signal.SIGALRM, lambda *_: os._exit(3))
        signal.alarm(20)
        os._exit(0 if Tasks(2).map(abs, [-3, -4]) == [3, 4] else 4)
    _, status = os.waitpid(pid, 0)
    assert os.waitstatus_to_exitcode(status) == 0


@pytest.mark.parametrize("n, threads, most", [(10, 1, 4), (10, 2, 4), (3, 4, 100), (0, 2, 8),
                                              (1000, 2, 64), (50000, 2, 1 << 15), (5000, 3, 1 << 15)])
def test_pieces_cover_the_range_in_order_once(n, threads, most):
    got = pieces(n, threads, most, least=1000)
    assert np.array_equal(np.concatenate([np.arange(n)[s] for s in got] or [[]]), np.arange(n))
    assert all(0 < s.stop - s.start <= most for s in got)
    if threads == 1:  # the serial path's chunks
        assert [s.start for s in got] == list(range(0, n, most))
    elif n >= 2 * threads * 1000:  # two per thread, when each can hold 1000
        assert len(got) >= 2 * threads
    elif 0 < n < 1000 and n <= most:  # too little to split
        assert len(got) == 1
