"""The exported LaTeX document compiles with pdflatex (Debian's texlive-latex-base + -recommended)."""

import re
import shutil
import subprocess

import pytest

from tests.service.export.common import CASES, exported

pytestmark = pytest.mark.slow  # documents compiled by pdflatex


def compile_pdf(source: str, tmp_path) -> bytes:
    assert shutil.which("pdflatex"), "pdflatex is missing: scripts/test.sh installs texlive-latex-base"
    (tmp_path / "doc.tex").write_text(source)
    done = subprocess.run(
        ["pdflatex", "-no-shell-escape", "-interaction=nonstopmode", "-halt-on-error", "doc.tex"],
        capture_output=True,
        text=True,
        timeout=120,
        cwd=tmp_path,
    )
    assert done.returncode == 0, done.stdout[-3000:]
    return (tmp_path / "doc.pdf").read_bytes()


def test_a_whole_document_with_every_step_in_align():
    tex = exported("spherical-pendulum", "tex")
    assert tex.startswith("\\documentclass") and "\\usepackage{amsmath,amssymb}" in tex
    assert tex.count("\\begin{document}") == 1 and tex.rstrip().endswith("\\end{document}")
    assert tex.count("\\subsection*{") >= 20 and tex.count("\\begin{align*}") >= 24
    assert "\\section*{Errata: where the chapter goes wrong}" in tex


def test_the_prose_and_the_equations_print_the_azimuth_as_one_letter():
    # the spherical pendulum's azimuth φ: the equations print \varphi, and so must the prose around them
    tex = exported("spherical-pendulum", "tex")
    assert "\\varphi" in tex
    assert re.search(r"\\phi(?![A-Za-z])", tex) is None


def test_typed_prose_is_escaped():
    tex = exported("hostile", "tex")
    for text in ("\\input{", "\\write18", "\\def", "$$\\begin", "<script>"):
        assert text not in tex
    assert tex.count("\\begin{document}") == 1 and tex.count("\\end{document}") == 1
    assert r"\$\textbackslash{}input\{/etc/passwd\}\$" in tex


# how far a line may stick out of the text block (pdflatex's "Overfull \\hbox (NNpt too wide)")
OVERFULL_PT = 10.0


@pytest.mark.slow
@pytest.mark.parametrize("case", CASES)
def test_the_document_compiles_with_pdflatex_and_nothing_sticks_out(case, tmp_path):
    pdf = compile_pdf(exported(case, "tex"), tmp_path)
    assert pdf.startswith(b"%PDF")
    log = (tmp_path / "doc.log").read_text(errors="replace")
    overfull = [float(x) for x in re.findall(r"Overfull \\hbox \(([\d.]+)pt too wide\)", log)]
    assert max(overfull, default=0.0) <= OVERFULL_PT, sorted(overfull)[-5:]
