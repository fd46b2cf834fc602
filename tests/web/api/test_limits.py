"""The body limits: JSON nesting found by a scan that ignores brackets inside strings."""

import pytest

from app.web.api.limits import MAX_JSON_DEPTH, TooDeep, check_json_depth


def test_depth_of_ordinary_requests_passes():
    check_json_depth(b'{"coordinates": ["x"], "forces": {"x": "[[[[["}}')
    check_json_depth("[" * MAX_JSON_DEPTH + "]" * MAX_JSON_DEPTH)
    check_json_depth("[[]]" * 1000)  # many brackets, shallow


def test_brackets_inside_strings_do_not_count():
    text = '{"a": "' + "[" * 1000 + '\\"' + "{" * 1000 + '"}'
    check_json_depth(text)


@pytest.mark.parametrize("text", ["[" * (MAX_JSON_DEPTH + 1), '{"a": ' * (MAX_JSON_DEPTH + 1), "[{" * 10000])
def test_deep_text_is_refused_before_parsing(text):
    with pytest.raises(TooDeep, match=str(MAX_JSON_DEPTH)):
        check_json_depth(text)


@pytest.mark.parametrize("encoding", ["utf-16", "utf-16-le", "utf-16-be", "utf-32", "utf-32-le", "utf-8-sig"])
def test_the_depth_is_that_of_the_decoded_document_whatever_its_encoding(encoding):
    # U+2200 is 00 22 in UTF-16-BE (22 00 in -LE): a quote's byte, which a byte scan takes for a string's end
    deep = '{"\u2200": ' + "[" * 900 + "]" * 900 + "}"
    with pytest.raises(TooDeep):
        check_json_depth(deep.encode(encoding))
    shallow = '{"coordinates": ["x"], "lagrangian": "[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[x"}'
    check_json_depth(shallow.encode(encoding))  # brackets in a string still do not count


@pytest.mark.parametrize("levels", [900, 5000])
def test_a_utf16_body_cannot_hide_its_nesting_from_the_api(client, levels):
    body = ('{"\u2200": 1, "coordinates": ' + "[" * levels + "]" * levels + "}").encode("utf-16")
    response = client.post("/api/derive", content=body, headers={"content-type": "application/json"})
    assert response.status_code == 400 and "nested deeper" in response.json()["detail"]
