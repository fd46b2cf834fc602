"""The written-out stages match the tableau they were generated from."""

from app.numerics.kernels import unroll


def test_generated_stages_are_current():
    """Re-run ``python -m app.numerics.kernels.unroll`` after a change to the tableau or the generator."""
    assert unroll.TARGET.read_text() == unroll.source()


def test_every_nonzero_coefficient_is_written_once():
    from app.numerics.kernels import vern8_tableau as tab

    text = unroll.source()
    stage_rows = [*range(1, tab.N_STEP), *range(tab.N_STEP + 1, tab.N_ALL)]
    expected = sum(int((tab.A[s] != 0).sum()) for s in stage_rows) + int((tab.B != 0).sum() + (tab.E != 0).sum())
    assert text.count(" * K[") + text.count(" * ks[i]") == expected
