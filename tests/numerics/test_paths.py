"""The kernels' numba cache follows their sources, not only the dates numba checks."""

from __future__ import annotations

from pathlib import Path

from app.numerics import paths


def _fill(folder: Path) -> list[Path]:
    folder.mkdir(parents=True, exist_ok=True)
    files = [folder / "vern8.run-60.py311.nbi", folder / "vern8.run-60.py311.1.nbc"]
    for f in files:
        f.write_bytes(b"old machine code")
    return files


def test_the_kernels_folder_is_the_one_numba_writes():
    from numba.core.caching import _CacheLocator  # numba's own rule, private: checked here, copied in paths

    expected = _CacheLocator.get_suitable_cache_subpath(str(paths.KERNELS / "vern8.py"))
    assert paths.kernels_cache(Path("/cache")) == Path("/cache") / expected


def test_a_cache_filled_from_other_sources_is_emptied(tmp_path):
    folder = paths.kernels_cache(tmp_path)
    files = _fill(folder)
    (folder / paths.STAMP).write_text("the hash of older sources")
    paths.drop_stale_kernels(tmp_path)
    assert not any(f.exists() for f in files)
    assert (folder / paths.STAMP).read_text() == paths.kernels_stamp()


def test_a_cache_without_a_stamp_is_emptied(tmp_path):
    files = _fill(paths.kernels_cache(tmp_path))
    paths.drop_stale_kernels(tmp_path)
    assert not any(f.exists() for f in files)


def test_a_cache_of_the_same_sources_is_kept(tmp_path):
    folder = paths.kernels_cache(tmp_path)
    files = _fill(folder)
    (folder / paths.STAMP).write_text(paths.kernels_stamp())
    paths.drop_stale_kernels(tmp_path)
    assert all(f.read_bytes() == b"old machine code" for f in files)


def test_the_stamp_changes_with_any_kernel_source(tmp_path):
    before = paths.kernels_stamp()
    copy = tmp_path / "kernels"
    copy.mkdir()
    for source in paths.KERNELS.glob("*.py"):
        (copy / source.name).write_bytes(source.read_bytes())
    assert paths.kernels_stamp(copy) == before
    stages = copy / "vern8_stages.py"
    stages.write_text(stages.read_text().replace("0.05 * h", "0.0500000001 * h", 1))
    assert paths.kernels_stamp(copy) != before
