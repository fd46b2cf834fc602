"""The example notebook (docs/notebook.ipynb) runs top to bottom in a kernel, its own checks passing."""

from __future__ import annotations

from pathlib import Path

import nbformat
import pytest
from nbclient import NotebookClient

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]


def test_the_example_notebook_runs():
    book = nbformat.read(ROOT / "docs" / "notebook.ipynb", as_version=4)
    nbformat.validate(book)
    NotebookClient(book, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(ROOT)}}).execute()
    outputs = [o for c in book.cells if c.cell_type == "code" for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    shown = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    assert "T + U changes by at most" in shown and "potential: unknown name" in shown
    latex = [o["data"]["text/latex"] for o in outputs if "text/latex" in o.get("data", {})]
    assert any("\\ddot{\\theta} + \\frac{g}{l} \\sin {\\theta} &= 0" in t for t in latex)
    assert any("image/png" in o.get("data", {}) for o in outputs)  # the double pendulum's plot
