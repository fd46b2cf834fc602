"""The bounded cache of recent answers (app/service/runtime/cache.py's ``Recent``) that the action, the Poincaré
sections and the modes at given parameters keep."""

from app.service.runtime.cache import Recent


def test_an_answer_is_computed_once_and_the_least_recently_used_goes_first():
    calls = []
    recent = Recent(2)

    def answer(key):
        return recent.get(key, lambda: calls.append(key) or key.upper())

    assert [answer("a"), answer("b"), answer("a")] == ["A", "B", "A"]
    assert calls == ["a", "b"]  # "a" came from the cache the second time
    answer("c")  # full: "b", used least recently, goes
    answer("a")
    answer("b")
    assert calls == ["a", "b", "c", "b"]


def test_a_failed_computation_is_not_remembered():
    recent = Recent(4)
    attempts = []

    def flaky():
        attempts.append(1)
        if len(attempts) == 1:
            raise ValueError("first try fails")
        return 42

    try:
        recent.get("k", flaky)
    except ValueError:
        pass
    assert recent.get("k", flaky) == 42 and len(attempts) == 2
