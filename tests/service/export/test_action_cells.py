"""The notebook's action cells run after the rest and agree with the app: S(ε) − S(0) > 0 on both sides for a
short T, dS/dε ≈ 0 at the true path."""

import re

import nbformat
import pytest
from nbclient import NotebookClient

from tests.service.export.common import exported

pytestmark = pytest.mark.slow  # notebooks executed by a kernel


@pytest.mark.parametrize("case", ["simple-pendulum", "hostile"])
def test_the_action_cells_compute_S_of_epsilon(case):
    book = nbformat.reads(exported(case, "ipynb"), as_version=4)
    assert any(c.cell_type == "markdown" and c.source.startswith("## The action") for c in book.cells)
    NotebookClient(book, timeout=240, kernel_name="python3").execute()
    printed = "".join(
        o.get("text", "") for c in book.cells if c.cell_type == "code" for o in c.outputs if o.output_type == "stream"
    )
    slope = float(re.search(r"dS/dε at 0 ≈ (\S+)", printed).group(1))
    changes = [float(x) for x in re.findall(r"S\(ε\) − S\(0\) = (\S+)", printed)]
    assert abs(slope) < 1e-6 and len(changes) == 7
    assert changes[3] == 0 and all(x > 0 for i, x in enumerate(changes) if i != 3)
