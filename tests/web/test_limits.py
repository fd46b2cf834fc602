"""The body limits: JSON nesting found by a scan that ignores brackets inside strings."""

import pytest

from app.web.limits import MAX_JSON_DEPTH, TooDeep, check_json_depth


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
