"""The README stays a short door into the project: under 120 lines, its two commands first, a table cell a line."""

from __future__ import annotations

import re
from pathlib import Path

README = Path(__file__).resolve().parents[2] / "README.md"
CELL = 125  # characters: a cell longer than this wraps to several lines in a reader's window


def test_the_readme_is_under_120_lines():
    assert len(README.read_text().splitlines()) < 120


def test_the_readme_opens_with_the_two_commands():
    blocks = re.findall(r"```bash\n(.*?)\n```", README.read_text(), re.S)
    assert blocks[:2] == ["./scripts/run.sh", "./scripts/test.sh"]


def test_each_table_cell_is_one_short_line():
    long = [
        f"line {n}: {cell.strip()[:60]!r}… ({len(cell.strip())} characters)"
        for n, line in enumerate(README.read_text().splitlines(), 1)
        if line.startswith("|")
        for cell in line.strip("|").split("|")
        if len(cell.strip()) > CELL
    ]
    assert not long, "say it in the doc the cell links to:\n" + "\n".join(long)
