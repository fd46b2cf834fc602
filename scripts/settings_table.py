"""The table of settings in docs/deployment.md, generated from ``app.settings.Settings``.

Usage: python scripts/settings_table.py           print the table
       python scripts/settings_table.py --write   rewrite it in docs/deployment.md (between the markers)
       python scripts/settings_table.py --check   fail if docs/deployment.md's table differs (scripts/lint.sh)
"""

from __future__ import annotations

import sys
from pathlib import Path

from app.settings import ROOT, Settings

DOC = ROOT / "docs" / "deployment.md"
BEGIN, END = "<!-- settings:begin -->", "<!-- settings:end -->"


def _shown(value: object) -> str:
    if value is None:
        return "none"
    if isinstance(value, Path) and value.is_relative_to(ROOT):
        return f"`{value.relative_to(ROOT)}`"
    if isinstance(value, bool):
        return "1" if value else "0"
    return f"`{value}`"


def table() -> str:
    prefix = Settings.model_config.get("env_prefix", "")
    lines = ["| variable | default | meaning |", "|---|---|---|"]
    for name, field in Settings.model_fields.items():
        lines.append(f"| `{prefix}{name.upper()}` | {_shown(field.default)} | {field.description} |")
    return "\n".join(lines)


def with_table(readme: str) -> str:
    head, _, rest = readme.partition(BEGIN)
    _, _, tail = rest.partition(END)
    if not rest or not tail:
        raise SystemExit(f"docs/deployment.md has no {BEGIN} ... {END} block")
    return f"{head}{BEGIN}\n{table()}\n{END}{tail}"


def main(argv: list[str]) -> int:
    readme = DOC.read_text()
    if "--write" in argv:
        DOC.write_text(with_table(readme))
    elif "--check" in argv:
        if with_table(readme) != readme:
            print("docs/deployment.md's settings table differs from app/settings.py: run python scripts/settings_table.py --write")
            return 1
    else:
        print(table())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
