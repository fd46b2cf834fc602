"""The document model (app/engine/document/model.py): every printed document has exactly the model's shape, and the
model's JSON is the document's, byte for byte."""

import orjson
import pytest
from pydantic import ValidationError

from app.engine.document.model import Document
from app.scenes import SCENES
from app.service.chapter.derivations import derivation_document
from app.web.api.examples_user import DERIVE_RESPONSE


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_every_chapter_document_has_the_models_shape_and_bytes(scene_id):
    served = derivation_document(scene_id)
    # extra="forbid" throughout: a key the model does not name, or one it names and misses, fails here
    document = Document.model_validate(served)
    assert document.id == scene_id
    assert orjson.dumps(document.as_json()) == orjson.dumps(served)


def test_the_documented_user_answer_has_the_models_shape_and_bytes():
    document = Document.model_validate(DERIVE_RESPONSE)
    assert document.id is None and document.scene is None
    # a system of your own has no id: the key is absent, not null
    assert orjson.dumps(document.as_json()) == orjson.dumps(DERIVE_RESPONSE)


def test_a_document_that_changes_shape_is_refused():
    served = derivation_document("simple-pendulum")
    with pytest.raises(ValidationError, match="surprise"):
        Document.model_validate({**served, "surprise": 1})
    with pytest.raises(ValidationError, match="title"):
        Document.model_validate({**served, "steps": [{k: v for k, v in served["steps"][0].items() if k != "title"}]})
    with pytest.raises(ValidationError, match="note"):
        Document.model_validate({**served, "steps": [{**served["steps"][0], "note": ""}]})


def test_a_first_stage_has_the_models_shape_and_bytes():
    from app.engine.document.contract import first_stage
    from app.engine.document.model import FirstStage
    from app.service.users.user_checks import checked
    from app.service.users.user_jobs import derive_checked
    from app.web.api.examples_user import SPINNING_HOOP

    printed = first_stage(derive_checked(checked(SPINNING_HOOP)))
    stage = FirstStage.model_validate(printed)
    assert stage.stage == "equations" and stage.notation is not None
    assert orjson.dumps(stage.as_json()) == orjson.dumps(printed)
    with pytest.raises(ValidationError, match="steps"):
        FirstStage.model_validate({**printed, "steps": []})  # a member of the whole document only
