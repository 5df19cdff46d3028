"""apprentice.experiment(): the same results as `apprentice experiment --json`."""
import json
import subprocess

import pytest

import apprentice
from conftest import BINARY, KITCHEN


def test_inst_search4_takes_the_papers_40_instructions_and_603_words():
    results = apprentice.experiment(str(KITCHEN), conditions=["inst+search4"])
    assert len(results) == 1
    result = results[0]
    assert result["condition"] == "inst+search4"
    assert (result["instructions"], result["words"], result["yes_no"]) == (40, 603, 0)
    assert result["completion_rate"] == 100.0
    assert result["relevance"] is None


def test_instruction_with_both_generalizations():
    ours = apprentice.experiment(KITCHEN, conditions=["instruction"])[0]
    paper = apprentice.experiment(KITCHEN, conditions="instruction", generalization="paper")[0]
    assert (ours["instructions"], ours["words"]) == (48, 636)
    assert (paper["instructions"], paper["words"]) == (76, 757)


def test_same_keys_and_figures_as_the_cli_json():
    conditions = ["instruction", "inst+search4"]
    ours = apprentice.experiment(str(KITCHEN), conditions=conditions)
    cli = json.loads(subprocess.run([str(BINARY), "experiment", "--scenario", str(KITCHEN), "--conditions",
                                     ",".join(conditions), "--json"], check=True, capture_output=True,
                                    text=True).stdout)
    assert [sorted(r) for r in ours] == [sorted(r) for r in cli]
    for a, b in zip(ours, cli):
        for key in a:
            if key != "wall_ms":
                assert a[key] == b[key], key


def test_without_an_llm_every_condition_that_can_run(monkeypatch):
    monkeypatch.delenv("APPRENTICE_LLM", raising=False)
    results = apprentice.experiment(KITCHEN)
    assert [r["condition"] for r in results] == ["instruction", "inst+search4"]


def test_errors_are_apprentice_errors(monkeypatch):
    monkeypatch.delenv("APPRENTICE_LLM", raising=False)
    with pytest.raises(apprentice.Error) as raised:
        apprentice.experiment(KITCHEN, conditions=["inst+search9000x"])
    assert raised.value.code == "invalid input"
    with pytest.raises(apprentice.Error, match="LLM"):
        apprentice.experiment(KITCHEN, conditions=["inst+llm"])
    with pytest.raises(apprentice.Error, match="generalization must be full or paper"):
        apprentice.experiment(KITCHEN, conditions=["instruction"], generalization="some")


def test_paper_rows_are_table_3():
    assert apprentice.condition_names()[:2] == ["instruction", "inst+search4"]
    row = apprentice.paper_row("inst+search4+llm")
    assert (row["instructions"], row["words"], row["yes_no"], row["relevance"]) == (70, 360, 43, 30.2)
    assert apprentice.paper_row("inst+search3") is None


def test_knowledge_in_starts_every_condition_from_a_store(tmp_path):
    # The CLI keeps what inst+search4 learned; starting from it, the same
    # condition needs fewer instructions and still tidies everything.
    subprocess.run([str(BINARY), "experiment", "--scenario", str(KITCHEN), "--conditions", "inst+search4",
                    "--knowledge-out", str(tmp_path), "--quiet"], check=True, capture_output=True)
    store = tmp_path / "inst+search4.sqlite"
    fresh = apprentice.experiment(KITCHEN, conditions=["inst+search4"])[0]
    taught = apprentice.experiment(KITCHEN, conditions=["inst+search4"], knowledge_in=store)[0]
    assert taught["completion_rate"] == 100.0
    assert taught["instructions"] < fresh["instructions"]
    cli = json.loads(subprocess.run([str(BINARY), "experiment", "--scenario", str(KITCHEN), "--conditions",
                                     "inst+search4", "--knowledge-in", str(store), "--json"], check=True,
                                    capture_output=True, text=True).stdout)[0]
    assert (taught["instructions"], taught["words"]) == (cli["instructions"], cli["words"])


def test_knowledge_in_that_is_not_a_store_raises_apprentice_error(tmp_path):
    broken = tmp_path / "not-a-store.sqlite"
    broken.write_text("this is not a knowledge store\n")
    with pytest.raises(apprentice.Error):
        apprentice.experiment(KITCHEN, conditions=["inst+search4"], knowledge_in=broken)
