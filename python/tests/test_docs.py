"""docs/python.md runs as written: its examples are doctests."""
import doctest

from conftest import SOURCE_DIR


def test_python_md_runs_as_written(tmp_path, monkeypatch):
    (tmp_path / "data").symlink_to(SOURCE_DIR / "data")
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("APPRENTICE_LLM", raising=False)
    result = doctest.testfile(str(SOURCE_DIR / "docs" / "python.md"), module_relative=False,
                              optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.attempted >= 25
    assert result.failed == 0, "docs/python.md: %d of %d examples differ (above)" % (result.failed, result.attempted)
    assert (tmp_path / "experiment.svg").exists()
