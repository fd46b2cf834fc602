"""The disk cache of users' systems stays under its bound; least recently used modules go first."""

import os
import time

from app.service.runtime import disk


def make_module(generated, compiled, key, size, used):
    module = generated / f"rhs_{key}.py"
    module.write_bytes(b"#" * size)
    os.utime(module, (used, used))
    for name in (f"rhs_{key}.rhs-10.py311.nbi", f"rhs_{key}.rhs-10.py311.1.nbc"):
        (compiled / name).write_bytes(b"0" * size)


def test_pruning_keeps_the_most_recently_used_modules_within_the_bound(tmp_path):
    generated = tmp_path / "generated-user"
    compiled = tmp_path / "numba" / "generated-user_abc123"
    chapter = tmp_path / "numba" / "generated_def456"
    for folder in (generated, compiled, chapter):
        folder.mkdir(parents=True)
    (chapter / "rhs_scene.rhs-10.py311.nbi").write_bytes(b"0" * 50_000)  # the chapter's: never touched
    now = time.time()
    for i in range(10):
        make_module(generated, compiled, f"k{i}", 10_000, now - 100 + i)  # k9 used last
    assert disk.total_bytes(generated, tmp_path / "numba") == 300_000
    freed = disk.prune(100_000, generated, tmp_path / "numba")
    assert freed == 210_000 and disk.total_bytes(generated, tmp_path / "numba") <= 100_000
    assert sorted(p.stem for p in generated.glob("*.py")) == ["rhs_k7", "rhs_k8", "rhs_k9"]
    assert sorted(p.name.split(".")[0] for p in compiled.iterdir()) == ["rhs_k7"] * 2 + ["rhs_k8"] * 2 + ["rhs_k9"] * 2
    assert (chapter / "rhs_scene.rhs-10.py311.nbi").exists()


def test_compiled_files_left_without_their_module_go_first(tmp_path):
    generated = tmp_path / "generated-user"
    compiled = tmp_path / "numba" / "generated-user_abc"
    generated.mkdir()
    compiled.mkdir(parents=True)
    make_module(generated, compiled, "kept", 1000, time.time())
    (compiled / "rhs_orphan.rhs-10.py311.nbi").write_bytes(b"0" * 1000)
    disk.prune(3000, generated, tmp_path / "numba")
    assert not (compiled / "rhs_orphan.rhs-10.py311.nbi").exists()
    assert (generated / "rhs_kept.py").exists()
