"""The exported notebook: valid nbformat, standalone, and it runs top to bottom with every check passing."""

import nbformat
import pytest
from jupyter_client.manager import AsyncKernelManager
from jupyter_client.utils import run_sync
from nbclient import NotebookClient

from tests.service.export.common import CASES, HOSTILE_TEXT, exported

pytestmark = pytest.mark.slow  # notebooks executed by a kernel

STEPS = ("## Symbols", "## Lagrangian", "## Euler–Lagrange equations", "## Accelerations", "## Generalized momenta")


def cells(case):
    book = nbformat.reads(exported(case, "ipynb"), as_version=4)
    nbformat.validate(book)
    return book


@pytest.mark.parametrize("case", CASES)
def test_the_notebook_has_the_problem_then_each_step_and_the_engines_result(case):
    book = cells(case)
    assert book.cells[0].cell_type == "markdown" and book.cells[0].source.startswith("# ")
    markdown = "\n".join(c.source for c in book.cells if c.cell_type == "markdown")
    for title in STEPS:
        assert title in markdown
    code = "\n".join(c.source for c in book.cells if c.cell_type == "code")
    for name in ("L", "EL", "acc", "p", "h"):
        assert f"{name}_engine = " in code
    assert "import app" not in code and "from app" not in code
    assert "solve_ivp(" in code and "plt.subplots" in code


def test_typed_prose_reaches_markdown_escaped_and_code_not_at_all():
    book = cells("hostile")
    code = "\n".join(c.source for c in book.cells if c.cell_type == "code")
    markdown = "\n".join(c.source for c in book.cells if c.cell_type == "markdown")
    for text in HOSTILE_TEXT:
        assert text not in code
    assert "\\$\\\\input\\{\\/etc\\/passwd\\}\\$" in markdown
    assert "$\\input" not in markdown and "<script>" not in markdown


@pytest.fixture(scope="module")
def kernel():
    """One IPython kernel for the module's notebooks (a new kernel per notebook re-imports numpy, scipy, sympy and
    matplotlib, most of a notebook's time)."""
    km = AsyncKernelManager(kernel_name="python3")
    run_sync(km.start_kernel)()
    yield km
    run_sync(km.shutdown_kernel)(now=True)


def run_in_a_clean_namespace(book, km) -> None:
    """Run every cell of the notebook in order, in the shared kernel emptied first by ``%reset -f``.

    The notebook sees no name a previous notebook defined, so it runs top to bottom on its own; only modules
    already imported (and their caches) are shared, as in any kernel after its first import.
    """
    reset = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("%reset -f")])
    for notebook in (reset, book):
        client = NotebookClient(notebook, km=km, timeout=180)
        try:
            client.execute()
        finally:
            if client.kc is not None:
                client.kc.stop_channels()


@pytest.mark.slow
@pytest.mark.parametrize("case", CASES)
def test_the_notebook_runs_top_to_bottom_and_agrees_with_the_engine(case, kernel):
    book = cells(case)
    run_in_a_clean_namespace(book, kernel)
    printed = [
        o.get("text", "") for c in book.cells if c.cell_type == "code" for o in c.outputs if o.output_type == "stream"
    ]
    checks = [line for text in printed for line in text.splitlines() if "the engine" in line]
    assert len(checks) >= 6 and all(line.endswith(": the same as the engine") for line in checks), checks
    plots = [o for c in book.cells if c.cell_type == "code" for o in c.outputs if "image/png" in o.get("data", {})]
    assert len(plots) == 1
    assert not [o for c in book.cells if c.cell_type == "code" for o in c.outputs if o.output_type == "error"]
