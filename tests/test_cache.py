"""The library's caches (reflectance.io.cache): each memo named and bounded, one way to clear
them all, and the disk folders it clears named as their users name them."""

import numpy as np
import pytest

from reflectance.io import cache


@pytest.fixture
def memo():
    made = cache.Memo("a memo of this test", 2)
    yield made
    del cache.MEMOS[made.name]


def test_a_memo_keeps_its_limit_and_drops_the_least_recently_used(memo):
    calls = []

    def make(n):
        return lambda: calls.append(n) or n * n

    assert [memo.get(n, make(n)) for n in (1, 2, 1)] == [1, 4, 1] and calls == [1, 2]
    memo.get(3, make(3))  # 2 was used longest ago: dropped, 1 kept
    assert 1 in memo and 2 not in memo and 3 in memo and len(memo) == 2
    assert memo.get(2, make(2)) == 4 and calls == [1, 2, 3, 2]  # made again


def test_a_value_that_cannot_be_made_is_not_kept(memo):
    def fail():
        raise ValueError("no")

    with pytest.raises(ValueError):
        memo.get("k", fail)
    assert "k" not in memo and len(memo) == 0


def test_memos_are_one_per_name_and_hold_at_least_one(memo):
    with pytest.raises(ValueError, match="exists"):
        cache.Memo(memo.name, 3)
    with pytest.raises(ValueError, match="at least 1"):
        cache.Memo("another memo of this test", 0)
    assert "another memo of this test" not in cache.MEMOS


def test_the_librarys_memos_are_registered_and_bounded():
    for memo in (cache.BUILT_MESHES, cache.COMPOSED_MESHES, cache.TRACES):
        assert cache.MEMOS[memo.name] is memo and memo.limit >= 1


def test_clear_empties_every_memo(memo, root):
    from reflectance.render.scene import scene_from_dict

    memo.get("k", lambda: 1)
    scene_from_dict({"camera": {"position": [0, -5, 0], "look_at": [0, 0, 0], "up": [0, 0, 1],
                                "fov_deg": 30.0, "width": 8, "height": 8},
                     "objects": [{"geometry": {"type": "sphere", "radius": 1.0},
                                  "material": {"model": "Lambert", "convention": "physical",
                                               "albedo": 0.5}}],
                     "lights": [{"type": "directional", "direction": [0, -1, 0]}]},
                    spectra_dir=root / "spectra")
    assert len(cache.BUILT_MESHES) and len(cache.COMPOSED_MESHES) and len(memo)
    cache.clear()
    assert all(len(m) == 0 for m in cache.MEMOS.values())


def test_the_disk_folders_are_named_as_their_users_name_them():
    """clear and prune find a user's folder by DISK_FOLDERS: each pattern matches the name its
    user gives its folder."""
    import re

    from reflectance.colour import tables
    from reflectance.geometry import shapes

    assert re.fullmatch(cache.DISK_FOLDERS["colour tables"], tables.cache_directory().name)
    assert re.fullmatch(cache.DISK_FOLDERS["meshes"], shapes._mesh_cache_name())


def test_clear_disk_removes_the_caches_folders_and_nothing_else(tmp_path, monkeypatch):
    from reflectance.geometry.shapes import vase

    profile = [(0.35, 0.0), (0.55, 0.15), (0.75, 0.45), (0.7, 0.75), (0.4, 1.05)]
    root = tmp_path / "cache"
    monkeypatch.setenv(cache.CACHE_ENVIRONMENT_VARIABLE, str(root))
    first = vase(profile, 16, 10, 0.03)
    tables = root / "colour-science-0.0"
    tables.mkdir()
    (tables / "cmfs-x.npy").write_bytes(b"x")
    others = [root / "meshes-of-my-own", root / "notes.txt"]  # not names of the cache's
    others[0].mkdir()
    others[1].write_text("mine")
    (meshes,) = root.glob("meshes-*-numpy-*")
    cache.clear(disk=True)
    assert not meshes.exists() and not tables.exists() and all(p.exists() for p in others)
    again = vase(profile, 16, 10, 0.03)  # built again, into a new folder
    assert np.array_equal(np.asarray(again.points), np.asarray(first.points))
    assert meshes.is_dir()
    cache.clear(disk=True)  # nothing to remove but the meshes: fine
    monkeypatch.setenv(cache.CACHE_ENVIRONMENT_VARIABLE, str(tmp_path / "none"))
    cache.clear(disk=True)  # no cache folder at all: nothing to do


# --- a changed cache file is computed again, never used (issue 25) -------------------------------

def _tamper(path, old, new):
    """Change bytes of a cached file inside what it holds, keeping it a readable file of its
    kind: what a reader without a checksum would take as it is."""
    data = path.read_bytes()
    assert old in data
    path.write_bytes(data.replace(old, new, 1))


def test_a_changed_colour_table_is_computed_again(tmp_path, monkeypatch):
    """A CIE 1931 CMF table (.npy) whose numbers changed after it was written: colour-science's
    own values come back, and the file is rewritten."""
    import colour

    from reflectance.colour import tables

    monkeypatch.setenv(cache.CACHE_ENVIRONMENT_VARIABLE, str(tmp_path))
    key = "CIE 1931 2 Degree Standard Observer"
    grid = tuple(float(w) for w in range(400, 701, 10))
    tables.cmfs_aligned(key, grid)
    (path,) = tables.cache_directory().glob("observers-aligned-*.npy")
    stored = np.load(io_bytes(cache.load(path)))
    # the table's first float64 (x_bar at 400 nm) set to 0.5 in the file itself
    _tamper(path, stored[0, 0].tobytes(), np.float64(0.5).tobytes())
    truth = (colour.colorimetry.MSDS_CMFS_STANDARD_OBSERVER[key].copy()
             .align(colour.SpectralShape(400, 700, 10)).values)
    np.testing.assert_array_equal(tables.cmfs_aligned(key, grid), truth)
    np.testing.assert_array_equal(np.load(io_bytes(cache.load(path))), truth)  # rewritten


def test_a_changed_mesh_is_built_again(tmp_path, monkeypatch):
    """A cached vase (.npz) with a vertex moved: the built vertices come back, not the moved one."""
    from reflectance.geometry.shapes import vase

    monkeypatch.setenv(cache.CACHE_ENVIRONMENT_VARIABLE, str(tmp_path))
    profile = [(0.35, 0.0), (0.55, 0.15), (0.75, 0.45), (0.7, 0.75), (0.4, 1.05)]
    first = np.array(vase(profile, 16, 10, 0.03).points)
    (path,) = tmp_path.glob("meshes-*/*.npz")
    # stored uncompressed (np.savez): the points' bytes sit in the file as they are
    _tamper(path, first[:4].tobytes(), (first[:4] + 0.25).tobytes())
    with pytest.raises(ValueError, match="does not match its checksum"):
        cache.load(path)
    cache.clear()
    np.testing.assert_array_equal(np.array(vase(profile, 16, 10, 0.03).points), first)
    cache.load(path)  # rewritten with its checksum


def test_a_cache_file_without_its_checksum_is_not_used(tmp_path):
    path = tmp_path / "old.npy"
    np.save(path, np.arange(3.0))  # as an earlier version wrote it: no checksum
    with pytest.raises(ValueError, match="checksum"):
        cache.load(path)
    path.write_bytes(b"x")  # shorter than any checksum
    with pytest.raises(ValueError, match="checksum"):
        cache.load(path)


def io_bytes(data):
    import io

    return io.BytesIO(data)
