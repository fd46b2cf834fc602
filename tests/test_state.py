"""State on the app, not in modules: every module-level cache, lock, mutable container, memoized function or
``global`` in app/ is one docs/state.md lists as staying, with its reason (a pure memo, a process resource, a
worker process's own); the rest is held by the app's services and given to routes through ``Depends``."""

import ast
import re
from pathlib import Path

import pytest

from app.settings import ROOT

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

APP = ROOT / "app"
DOC = ROOT / "docs" / "state.md"

# constructors whose result is state: a container filled at run time, a cache, a lock, a context
STATEFUL = {
    "dict", "list", "set", "OrderedDict", "defaultdict", "Counter", "deque", "LRUCache", "TTLCache", "Recent",
    "JsonCache", "BytesCache", "local", "Lock", "RLock", "Semaphore", "BoundedSemaphore", "Event", "Condition",
    "ThreadPoolExecutor", "ContextVar", "WeakValueDictionary", "WeakKeyDictionary", "count",
}  # fmt: skip
MEMOIZERS = {"cache", "lru_cache"}


def _name(node: ast.expr) -> str:
    """The last name of a callee or decorator: ``threading.Lock`` -> Lock, ``lru_cache(maxsize=4)`` -> lru_cache."""
    if isinstance(node, ast.Call):
        node = node.func
    if isinstance(node, ast.Attribute):
        return node.attr
    return node.id if isinstance(node, ast.Name) else ""


def _frozen(cls: ast.ClassDef) -> bool:
    """A class whose instances cannot change: a frozen dataclass, a NamedTuple, an Enum."""
    for decorator in cls.decorator_list:
        if isinstance(decorator, ast.Call) and _name(decorator) == "dataclass":
            if any(k.arg == "frozen" and getattr(k.value, "value", False) is True for k in decorator.keywords):
                return True
    return any(_name(base) in {"NamedTuple", "Enum", "IntEnum", "StrEnum"} for base in cls.bases)


def state_of(source: str) -> set[str]:
    """The names of a module's module-level state (see the module's docstring)."""
    tree = ast.parse(source)
    own = {n.name for n in tree.body if isinstance(n, ast.ClassDef) and not _frozen(n)}
    found = set()
    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and any(_name(d) in MEMOIZERS for d in node.decorator_list):
            found.add(node.name)
        if isinstance(node, ast.Assign | ast.AnnAssign) and node.value is not None:
            value = node.value
            empty = isinstance(value, ast.Dict | ast.List | ast.Set) and not (
                value.keys if isinstance(value, ast.Dict) else value.elts
            )
            # dict(zip(...)) or set(names) builds a table once; dict() or Lock() makes something to fill or hold
            made = isinstance(value, ast.Call) and (
                (_name(value) in STATEFUL and not (_name(value) in {"dict", "list", "set"} and value.args))
                or _name(value) in own
            )
            if empty or made:
                targets = node.targets if isinstance(node, ast.Assign) else [node.target]
                found.update(t.id for t in targets if isinstance(t, ast.Name))
    for node in ast.walk(tree):
        if isinstance(node, ast.Global):
            found.update(node.names)
    return found


def documented() -> dict[str, set[str]]:
    """docs/state.md's rows that stay: module -> names."""
    staying: dict[str, set[str]] = {}
    for line in DOC.read_text().splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 4 and cells[0].startswith("`app/") and "**stays**" in cells[3]:
            for module in re.findall(r"`([^`]+\.py)`", cells[0]):
                staying.setdefault(module, set()).update(re.findall(r"`(\w+)`", cells[1]))
    return staying


def test_module_state_is_only_what_the_inventory_keeps():
    staying = documented()
    undocumented = {}
    for path in sorted(APP.rglob("*.py")):
        module = path.relative_to(ROOT).as_posix()
        extra = state_of(path.read_text()) - staying.get(module, set())
        if extra:
            undocumented[module] = sorted(extra)
    assert not undocumented, f"module-level state not in docs/state.md (move it to the app's services): {undocumented}"


def test_the_scan_sees_each_kind_of_state():
    source = """
import threading
from functools import cache, lru_cache

class Guard:
    pass

TABLE = {"a": 1}
EMPTY = {}
LOCK = threading.Lock()
GUARD = Guard()

@lru_cache(maxsize=4)
def remembered(x): return x

@cache
def once(): return 1

def plain(): return 2

def setter():
    global _flag
    _flag = True
"""
    assert state_of(source) == {"EMPTY", "LOCK", "GUARD", "remembered", "once", "_flag"}


def test_what_moved_is_no_longer_in_its_module():
    """The caches docs/state.md says moved to the app are gone from their modules."""
    for module, name in [
        ("app/web/pages/chapter.py", "_models"),
        ("app/web/pages/chapter.py", "_pages"),
        ("app/web/rendering/templating.py", "_gzipped"),
        ("app/web/pages/playground.py", "_EXAMPLES_CACHE"),
        ("app/service/simulations/modes.py", "_at_cache"),
        ("app/service/simulations/poincare.py", "_sections"),
        ("app/service/simulations/action.py", "_answers"),
        ("app/service/simulations/work_precision.py", "_cache"),
        ("app/service/chapter/derivations.py", "_json_cache"),
        ("app/service/chapter/derivations.py", "_derivation"),
        ("app/service/chapter/derivations.py", "_locks"),
        ("app/service/chapter/compiled.py", "COMPILED"),
        ("app/service/chapter/compiled.py", "_SOURCES"),
        ("app/service/chapter/compiled.py", "_EVENTS"),
        ("app/service/runtime/gates.py", "IN_FLIGHT"),
    ]:
        assert name not in state_of((ROOT / module).read_text()), (module, name)
    assert "scene_export" not in state_of((ROOT / "app/service/export/exporting.py").read_text())
    assert Path(DOC).is_file()


def _resolves_to(node: ast.expr | None, state: set[str]) -> str | None:
    """The module state a default names: ``GATES``, ``derivations.PROCESS_SCENES``, ``PROCESS_SCENES.compiled``,
    or ``X if p is None else p`` choosing it when nothing is given."""
    while isinstance(node, ast.Attribute):  # derivations.PROCESS_SCENES, PROCESS_SCENES.compiled
        if node.attr in state:
            return node.attr
        node = node.value
    if isinstance(node, ast.Name) and node.id in state:
        return node.id
    if isinstance(node, ast.IfExp):
        return _resolves_to(node.body, state) or _resolves_to(node.orelse, state)
    return None


def test_no_function_takes_module_state_as_its_default():
    """Module state (a process's scenes, gates, cores) is passed explicitly: the app's services give theirs, a
    worker's job or a script its own; no parameter or dataclass field falls back to it when not given."""
    modules = {path: ast.parse(path.read_text()) for path in sorted(APP.rglob("*.py"))}
    state = set().union(*(state_of(path.read_text()) for path in modules))
    found = []
    for path, tree in modules.items():
        for node in ast.walk(tree):
            where = f"{path.relative_to(ROOT)}:{getattr(node, 'lineno', 0)}"
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
                defaults = [*node.args.defaults, *node.args.kw_defaults]
                found += [f"{where} {node.name}: {name}" for d in defaults if (name := _resolves_to(d, state))]
            # a parameter resolved in the body: ``chapter = PROCESS_SCENES if chapter is None else chapter``
            if isinstance(node, ast.IfExp) and isinstance(node.test, ast.Compare):
                given = node.test.comparators[0] if node.test.comparators else None
                if isinstance(given, ast.Constant) and given.value is None and (name := _resolves_to(node, state)):
                    found.append(f"{where} {name} when None")
            if isinstance(node, ast.ClassDef):
                fields = [n for n in node.body if isinstance(n, ast.AnnAssign)]
                found += [f"{where} {node.name}: {name}" for f in fields if (name := _resolves_to(f.value, state))]
    assert found == []
