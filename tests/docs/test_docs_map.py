"""The docs say what is: no issue numbers, commit hashes, sessions or dates, and every relative link resolves.

History lives in git and dated figures in docs/benchmarks.md, which is the one file not scanned here.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOCS = sorted(
    [ROOT / "README.md", ROOT / "ARCHITECTURE.md"]
    + [p for p in (ROOT / "docs").glob("*.md") if p.name != "benchmarks.md"]
)
IDS = [p.relative_to(ROOT).as_posix() for p in DOCS]

# "issue 35", "(issue 30, item 2)", "issues 34 and 35", "issue #12"
ISSUE = re.compile(r"\bissues?\s+#?\d+", re.I)
# a commit's short or full hash: 7 to 40 hex digits standing as a word, with at least one digit. Not part of a
# number (a digit group after a decimal point or a thousands comma, or before one), not a colour (#rrggbbaa),
# not a longer run of hex digits (a SHA-256 checksum has 64).
HASH = re.compile(r"(?<![\w#.,-])(?=[0-9a-f]*\d)[0-9a-f]{7,40}(?![\w]|[.,]\d)")
# "stop" as a session of work: "the fourth stop", "this stop's final code", "the stop before", "two stops"
ORDINAL = r"first|second|third|fourth|fifth|sixth|seventh|eighth|ninth|tenth|this|that|last|next|previous|earlier"
STOP = re.compile(
    rf"\b(?:{ORDINAL})\s+stop(?:'s)?\b|\bstop(?:'s)?\s+(?:before|after)\b|\b(?:two|three|four|five|six)\s+stops\b",
    re.I,
)
# a calendar date, YYYY-MM-DD
DATE = re.compile(r"\b(?:19|20)\d\d-(?:0[1-9]|1[0-2])-(?:0[1-9]|[12]\d|3[01])\b")
# [text](target) and ![alt](target); the target up to a space (a title) or the closing parenthesis
LINK = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")


def offending(path: Path, pattern: re.Pattern[str]) -> list[str]:
    return [
        f"{path.relative_to(ROOT).as_posix()}:{number}: {match.group(0)!r} in {line.strip()[:120]!r}"
        for number, line in enumerate(path.read_text().splitlines(), 1)
        for match in pattern.finditer(line)
    ]


@pytest.mark.parametrize("path", DOCS, ids=IDS)
def test_no_issue_numbers(path: Path):
    found = offending(path, ISSUE)
    assert not found, "history belongs in git, not in the docs:\n" + "\n".join(found)


@pytest.mark.parametrize("path", DOCS, ids=IDS)
def test_no_commit_hashes(path: Path):
    found = offending(path, HASH)
    assert not found, "a commit hash dates the text; say what is:\n" + "\n".join(found)


@pytest.mark.parametrize("path", DOCS, ids=IDS)
def test_no_sessions_of_work(path: Path):
    found = offending(path, STOP)
    assert not found, "'this stop', 'the fourth stop' mean nothing to a reader:\n" + "\n".join(found)


@pytest.mark.parametrize("path", DOCS, ids=IDS)
def test_no_dates(path: Path):
    found = offending(path, DATE)
    assert not found, "a dated figure belongs in docs/benchmarks.md, under its benchmark:\n" + "\n".join(found)


def relative_targets(path: Path) -> list[str]:
    targets = [m.group(1) for m in LINK.finditer(path.read_text())]
    return [t for t in targets if not re.match(r"^(?:[a-z][a-z0-9+.-]*:|#|//)", t, re.I)]


@pytest.mark.parametrize("path", DOCS + [ROOT / "docs" / "benchmarks.md"], ids=IDS + ["docs/benchmarks.md"])
def test_relative_links_resolve(path: Path):
    missing = [t for t in relative_targets(path) if not (path.parent / t.split("#")[0]).exists()]
    assert not missing, f"{path.relative_to(ROOT)} links to files that do not exist: {missing}"


@pytest.mark.parametrize(
    ("pattern", "text"),
    [
        (ISSUE, "(issue 30, item 2)"),
        (ISSUE, "Issue 34 measured"),
        (HASH, "base 7506999 and after"),
        (HASH, "(`git log` 685aae5)"),
        (HASH, "at 9f79bd1."),
        (STOP, "the fourth stop's final code"),
        (STOP, "The stop before:"),
        (STOP, "this stop"),
        (DATE, "one run, 2026-11-28)"),
    ],
)
def test_each_rule_catches_what_it_is_for(pattern: re.Pattern[str], text: str):
    assert pattern.search(text)


@pytest.mark.parametrize(
    ("pattern", "text"),
    [
        (HASH, "rtol 1e-3 and 6.5e-13"),
        (HASH, "0.1771, 1, 2.8229"),
        (HASH, "348,726 steps and 1,800 s"),
        (HASH, "3.1415926 rad"),
        (HASH, "a colour #1f77b4ff"),
        (HASH, "sha256 " + "0123456789abcdef" * 4),
        (HASH, "a decade of effaced text"),
        (HASH, "2·10⁷ steps, 10⁻¹⁰ of the largest"),
        (STOP, "the run stops at t_end; press Stop"),
        (ISSUE, "a known issue with the fonts"),
        (DATE, "1e-3 to 2026-13-40"),
    ],
)
def test_no_false_alarms(pattern: re.Pattern[str], text: str):
    assert not pattern.search(text)
