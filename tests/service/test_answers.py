"""What an app remembers is its own: each ``Answers`` (held by the app's services) starts empty, and the
service functions fill the one they are given, never a module's."""

import pytest

from app.service.answers import Answers
from app.service.chapter.derivations import PROCESS_SCENES, scene_document
from app.service.export import exporting
from app.service.services import Services
from app.settings import Settings


def test_each_app_remembers_its_own_answers(tmp_path):
    config = Settings(cache_dir=tmp_path, warm=False)
    first, second = Services.start(config, PROCESS_SCENES), Services.start(config, PROCESS_SCENES)
    try:
        assert first.answers is not second.answers
        exported = exporting.scene_export("simple-pendulum", "py", scene_document, first.answers.exports)
        assert (
            exporting.scene_export("simple-pendulum", "py", scene_document, first.answers.exports) is exported
        )  # remembered
        again = exporting.scene_export("simple-pendulum", "py", scene_document, second.answers.exports)
        assert again is not exported and again == exported  # the other app made its own, the same file
    finally:
        first.stop()
        second.stop()


def test_without_an_apps_memory_nothing_is_kept():
    exported = exporting.scene_export("simple-pendulum", "tex", scene_document)
    assert exporting.scene_export("simple-pendulum", "tex", scene_document) is not exported


def test_a_refused_format_is_refused_before_any_memory_is_touched(tmp_path):
    answers = Answers.start(tmp_path)
    with pytest.raises(ValueError, match="unknown export format"):
        exporting.scene_export("simple-pendulum", "docx", scene_document, answers.exports)


def test_the_disk_caches_are_under_the_folder_given(tmp_path):
    answers = Answers.start(tmp_path)
    for cache in (answers.work_precision, answers.measured_modes, answers.examples, answers.lyapunov):
        assert cache.folder == tmp_path
    answers.work_precision.get("probe", lambda: {"runs": []})
    assert [p.name.startswith("probe-") for p in (tmp_path / "work-precision").iterdir()] == [True]
