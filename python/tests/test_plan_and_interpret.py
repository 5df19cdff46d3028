"""apprentice.plan() and apprentice.interpret() give what `apprentice plan`
and `apprentice interpret` print on the same input (issue 24), and the
question kinds are one vocabulary: question_kinds, `interpret --asked`, and
Question.asked of a Python teacher's questions."""
import json
import os
import re
import subprocess

import pytest

import apprentice
from conftest import BINARY, KITCHEN, SOURCE_DIR

KETCHUP_AWAY = "(and (in ketchup1 fridge1) (closed fridge1))"
CORPUS = SOURCE_DIR / "tests" / "llm" / "data" / "goal_corpus.jsonl"


def cli(*args):
    return subprocess.run([str(BINARY), *args], capture_output=True, text=True,
                          env={**os.environ, "APPRENTICE_LLM": ""})


def untimed(text):
    """A search's output without its times, which differ from run to run."""
    return re.sub(r"\d+(\.\d+)?(e-?\d+)? ms", "<t> ms", text)


def untimed_json(document):
    return {k: v for k, v in document.items() if k not in ("elapsed_ms", "grounding_ms")}


@pytest.mark.parametrize("flags,options", [([], {}), (["--depth", "4"], {"depth": 4}),
                                           (["--no-pruning"], {"pruning": False}),
                                           (["--node-limit", "100000"], {"node_limit": 100000})])
def test_plan_prints_what_the_cli_prints(flags, options):
    ours = apprentice.plan(KITCHEN, KETCHUP_AWAY, **options)
    text = cli("plan", "--scenario", str(KITCHEN), "--goal", KETCHUP_AWAY, *flags)
    assert text.returncode == 0, text.stderr
    assert untimed(ours["text"]) == untimed(text.stdout)
    assert ours["text"].startswith("1. ")  # numbered English sentences, not PDDL
    pddl = cli("plan", "--scenario", str(KITCHEN), "--goal", KETCHUP_AWAY, "--pddl", *flags)
    assert untimed(ours["pddl"]) == untimed(pddl.stdout)
    assert ours["pddl"].splitlines()[0].startswith("(")
    document = json.loads(cli("plan", "--scenario", str(KITCHEN), "--goal", KETCHUP_AWAY, "--json", *flags).stdout)
    assert untimed_json({k: v for k, v in ours.items() if k not in ("text", "pddl", "why_not")}) == untimed_json(document)
    assert ours["status"] == "solved" and ours["why_not"] is None and len(ours["plan"]) > 0


def test_plan_without_a_plan_says_why_as_the_cli_does():
    ours = apprentice.plan(KITCHEN, "intent", depth=1)
    run = cli("plan", "--scenario", str(KITCHEN), "--goal", "intent", "--depth", "1")
    assert run.returncode == 1
    assert ours["status"] != "solved"
    assert "apprentice: " + ours["why_not"] in run.stderr
    assert untimed(ours["text"]) == untimed(run.stdout)


def test_plan_refuses_what_the_cli_refuses():
    with pytest.raises(apprentice.Error) as refused:
        apprentice.plan(KITCHEN, "put the ketchup in the fridge")
    run = cli("plan", "--scenario", str(KITCHEN), "--goal", "put the ketchup in the fridge")
    assert run.returncode == 2
    assert refused.value.code == "invalid input"
    assert refused.value.message in run.stderr
    with pytest.raises(apprentice.Error):
        apprentice.plan(KITCHEN, KETCHUP_AWAY, depth=65)  # --depth takes 0 to 64


@pytest.mark.parametrize("reply,asked,flags", [
    ("put it in the fridge and close it", "goal", ["--object", "ketchup1"]),
    ("the milk goes in the fridge", "goal", ["--object", "ketchup1"]),
    ("the one on the counter", "which", ["--choices", "mug1,mug2"]),
    ("yes", "yes-no", []),
    ("tidy the kitchen", "task", []),
])
def test_interpret_reads_a_reply_as_the_cli_does(reply, asked, flags):
    options = {"object": flags[1]} if flags[:1] == ["--object"] else {}
    if flags[:1] == ["--choices"]:
        options["choices"] = flags[1].split(",")
    ours = apprentice.interpret(KITCHEN, reply, asked=asked, **options)
    text = cli("interpret", "--scenario", str(KITCHEN), "--asked", asked, *flags, reply)
    assert ours["text"] == text.stdout
    assert ours["usable"] == (text.returncode == 0)
    document = json.loads(cli("interpret", "--scenario", str(KITCHEN), "--asked", asked, "--json", *flags, reply).stdout)
    assert {k: v for k, v in ours.items() if k not in ("text", "usable")} == document


def test_interpret_reads_a_sentence_and_a_corpus_as_the_cli_does():
    ours = apprentice.interpret(KITCHEN, "put the ketchup in the fridge", object="ketchup1")
    text = cli("interpret", "--scenario", str(KITCHEN), "--object", "ketchup1", "put the ketchup in the fridge")
    assert ours["text"] == text.stdout and ours["grounded"] == (text.returncode == 0) and ours["grounded"]
    document = json.loads(cli("interpret", "--scenario", str(KITCHEN), "--object", "ketchup1", "--json",
                              "put the ketchup in the fridge").stdout)
    assert {k: v for k, v in ours.items() if k not in ("text", "grounded")} == document
    report = apprentice.interpret(KITCHEN, corpus=CORPUS)
    assert report == json.loads(cli("interpret", "--scenario", str(KITCHEN), "--corpus", str(CORPUS), "--json").stdout)


def test_the_question_kinds_are_one_vocabulary():
    help_text = cli("interpret", "--help").stdout
    assert ", ".join(apprentice.question_kinds) in help_text
    with pytest.raises(apprentice.Error) as refused:
        apprentice.interpret(KITCHEN, "yes", asked="what")
    run = cli("interpret", "--scenario", str(KITCHEN), "--asked", "what", "yes")
    assert run.returncode == 2 and refused.value.message in run.stderr
    # Every question a teacher hears says its kind in that vocabulary, and
    # the reply the agent got reads at it as the agent read it.
    heard = []

    def teacher(question):
        heard.append(question)
        if question.asked == "task":
            return "Tidy kitchen."
        return None

    apprentice.Agent(KITCHEN).learn(teacher)
    assert [q.asked for q in heard][:2] == ["task", "task-step"]
    assert all(q.asked in apprentice.question_kinds for q in heard)
    assert apprentice.interpret(KITCHEN, "Tidy kitchen.", asked=heard[0].asked)["usable"]
