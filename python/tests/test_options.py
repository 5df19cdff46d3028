"""Every option of the CLI's teach, run and experiment, in Python: each gives
what the CLI gives with the flag of the same name (issue 24). The LLM's
options are seen where they land: in the requests a recording server gets.
"""
import json
import os
import subprocess

import pytest

import apprentice
from conftest import BINARY, SOURCE_DIR
from fake_llm import RecordingLlmServer

TWO_OBJECTS = SOURCE_DIR / "tests" / "agent" / "data" / "two-objects.yaml"


def cli_experiment(*flags, conditions="inst+search4", scenario=TWO_OBJECTS, check=True):
    run = subprocess.run([str(BINARY), "experiment", "--scenario", str(scenario), "--conditions", conditions,
                          "--json", *flags], capture_output=True, text=True,
                         env={**os.environ, "APPRENTICE_LLM": ""})
    if check:
        assert run.returncode == 0, run.stderr
    return run


def figures(results):
    """What a run measured, without its wall-clock time."""
    return [{k: v for k, v in r.items() if k != "wall_ms"} for r in results]


def same_as_cli(flags, conditions="inst+search4", **options):
    ours = apprentice.experiment(str(TWO_OBJECTS), conditions=conditions.split(","), **options)
    cli = json.loads(cli_experiment(*flags, conditions=conditions).stdout)
    assert figures(ours) == figures(cli)
    return ours


@pytest.fixture(autouse=True)
def no_llm_from_the_environment(monkeypatch):
    monkeypatch.setenv("APPRENTICE_LLM", "")


def test_conditions():
    ours = same_as_cli([], conditions="instruction,inst+search4")
    assert [r["condition"] for r in ours] == ["instruction", "inst+search4"]


def test_generalization():
    same_as_cli(["--generalization", "paper"], conditions="instruction", generalization="paper")


def test_no_rules():
    ours = same_as_cli(["--no-rules"], conditions="instruction", use_rules=False)
    assert ours[0]["completion_rate"] == 100.0


def test_knowledge_out_and_knowledge_in(tmp_path):
    same_as_cli(["--knowledge-out", str(tmp_path / "cli")], knowledge_out=tmp_path / "py")
    assert (tmp_path / "cli" / "inst+search4.sqlite").exists() and (tmp_path / "py" / "inst+search4.sqlite").exists()
    ours = same_as_cli(["--knowledge-in", str(tmp_path / "cli" / "inst+search4.sqlite")],
                       knowledge_in=tmp_path / "py" / "inst+search4.sqlite")
    assert ours[0]["instructions"] < 10  # the task and goals were known


def test_transcript(tmp_path):
    same_as_cli(["--transcript", str(tmp_path / "cli")], transcript_dir=tmp_path / "py")
    cli = (tmp_path / "cli" / "inst+search4.txt").read_text()
    assert cli.startswith("Agent: What task should I learn?")
    assert (tmp_path / "py" / "inst+search4.txt").read_text() == cli


def llm_requests(flags, **options):
    """The LLM requests of inst+llm on the two-object kitchen, made by the CLI
    with `flags` and by Python with `options`: (cli's, ours, their results)."""
    seen = []
    for side in ("cli", "python"):
        with RecordingLlmServer() as server:
            if side == "cli":
                run = cli_experiment("--llm", "openai:" + server.url, *flags, conditions="inst+llm", check=False)
                result = (run.returncode, figures(json.loads(run.stdout)) if run.returncode == 0 else run.stderr)
            else:
                try:
                    result = (0, figures(apprentice.experiment(str(TWO_OBJECTS), conditions=["inst+llm"],
                                                               llm="openai:" + server.url, **options)))
                except apprentice.Error as error:
                    result = (error.code, str(error))
            seen.append((list(server.requests), result))
    (cli_requests, cli_result), (our_requests, our_result) = seen
    assert len(cli_requests) == len(our_requests) > 0
    assert [r["body"] for r in cli_requests] == [r["body"] for r in our_requests]
    assert [r["authorization"] for r in cli_requests] == [r["authorization"] for r in our_requests]
    if cli_result[0] == 0:
        assert our_result == cli_result
    return cli_requests, our_result


def test_llm_model():
    requests, _ = llm_requests(["--llm-model", "tiny-model"], llm_model="tiny-model")
    assert all(r["body"].get("model") == "tiny-model" for r in requests)


def test_llm_api_key():
    requests, _ = llm_requests(["--llm-api-key", "sesame"], llm_api_key="sesame")
    assert all(r["authorization"] == "Bearer sesame" for r in requests)


def test_llm_seed():
    requests, _ = llm_requests(["--llm-seed", "7"], llm_seed=7)
    assert all(r["body"].get("seed") == 7 for r in requests)


def test_llm_goal_responses():
    few, _ = llm_requests(["--llm-goal-responses", "1"], llm_goal_responses=1)
    many, _ = llm_requests([])
    assert len(few) < len(many)


def test_goal_repair():
    _, ours = llm_requests(["--goal-repair", "none"], goal_repair="none")
    assert ours[0] == 0


def test_offer_ungrounded():
    _, ours = llm_requests(["--offer-ungrounded"], offer_ungrounded=True)
    assert ours[0] == 0


def test_llm_timeouts():
    _, ours = llm_requests(["--llm-timeout-ms", "20000", "--llm-connect-timeout-ms", "3000"],
                           llm_timeout_ms=20000, llm_connect_timeout_ms=3000)
    assert ours[0] == 0


def test_llm_optional_and_a_server_that_does_not_answer():
    # Nothing listens on the port of a server that was closed.
    with RecordingLlmServer() as server:
        url = server.url
    run = cli_experiment("--llm", "openai:" + url, "--llm-optional", "--llm-connect-timeout-ms", "500",
                         conditions="inst+llm")
    cli = figures(json.loads(run.stdout))
    ours = figures(apprentice.experiment(str(TWO_OBJECTS), conditions=["inst+llm"], llm="openai:" + url,
                                         llm_optional=True, llm_connect_timeout_ms=500))
    assert ours == cli and ours[0]["degraded"]
    refused = cli_experiment("--llm", "openai:" + url, "--llm-connect-timeout-ms", "500", conditions="inst+llm",
                             check=False)
    assert refused.returncode == 4
    with pytest.raises(apprentice.Error) as raised:
        apprentice.experiment(str(TWO_OBJECTS), conditions=["inst+llm"], llm="openai:" + url,
                              llm_connect_timeout_ms=500)
    assert raised.value.code == "unavailable"


def test_a_bad_option_value_is_refused_as_the_cli_refuses_the_flag():
    assert cli_experiment("--llm-goal-responses", "11", check=False).returncode == 2
    with pytest.raises(apprentice.Error, match="llm_goal_responses: 11 is out of range"):
        apprentice.experiment(str(TWO_OBJECTS), conditions=["inst+search4"], llm_goal_responses=11)
    with pytest.raises(apprentice.Error, match="unknown option llm_sed"):
        apprentice.Agent(TWO_OBJECTS, llm_sed=3)


# The Agent: teach's and run's options.

def scripted_teacher(replies):
    replies = list(replies)
    return lambda question: replies.pop(0) if replies else None


TEACHING = ["Tidy kitchen.", "Repeat the following tasks while an object is on the table.",
            "Clear an object that is on the table.",
            "If the object is a ketchup then the goal is that the object is in the fridge and the fridge is closed.",
            "You are done.", "Repeat.",
            "If the object is a paper-plate then the goal is that the object is in the garbage.",
            "You are done.", "You are done."]


def cli_teach(*flags):
    return subprocess.run([str(BINARY), "teach", "--scenario", str(TWO_OBJECTS), "-q", *flags],
                          input="\n".join(TEACHING) + "\n", capture_output=True, text=True,
                          env={**os.environ, "APPRENTICE_LLM": ""})


@pytest.mark.parametrize("condition", ["inst+search4", "inst+search"])
def test_agent_condition_and_knowledge_teach_and_run_as_the_cli(tmp_path, condition):
    cli = cli_teach("--condition", condition, "--knowledge", str(tmp_path / "cli.sqlite"))
    assert cli.returncode == 0, cli.stderr
    agent = apprentice.Agent(TWO_OBJECTS, knowledge=tmp_path / "py.sqlite", condition=condition)
    report = agent.learn(scripted_teacher(TEACHING))
    # The same end-of-session summary, but for where the store is.
    assert report["summary"].replace(str(tmp_path / "py.sqlite"), "STORE") == \
        cli.stdout[cli.stdout.index("The task is learned"):].replace(str(tmp_path / "cli.sqlite"), "STORE")
    run = subprocess.run([str(BINARY), "run", "--scenario", str(TWO_OBJECTS), "--knowledge",
                          str(tmp_path / "cli.sqlite"), "--json"], capture_output=True, text=True, check=True)
    cli_run = json.loads(run.stdout)
    ours = apprentice.Agent(TWO_OBJECTS, knowledge=tmp_path / "py.sqlite").perform()
    for key in cli_run:
        assert ours[key] == cli_run[key], key


def test_agent_generalization_as_the_cli(tmp_path):
    cli = cli_teach("--generalization", "paper", "--knowledge", str(tmp_path / "cli.sqlite"))
    assert cli.returncode == 0, cli.stderr
    agent = apprentice.Agent(TWO_OBJECTS, knowledge=tmp_path / "py.sqlite", generalization="paper")
    agent.learn(scripted_teacher(TEACHING))
    knowledge = subprocess.run([str(BINARY), "knowledge", "--knowledge", str(tmp_path / "cli.sqlite"), "--json"],
                               capture_output=True, text=True, check=True)
    cli_rules = sorted(r["signature"] for r in json.loads(knowledge.stdout)["rules"])
    assert sorted(r.signature for r in agent.knowledge.rules) == cli_rules


def test_agent_llm_options_send_what_teach_sends(tmp_path):
    flags = ["--llm-model", "tiny-model", "--llm-seed", "3", "--llm-api-key", "sesame", "--llm-goal-responses", "2"]
    seen = []
    for side in ("cli", "python"):
        with RecordingLlmServer() as server:
            if side == "cli":
                cli_teach("--condition", "inst+llm", "--llm", "openai:" + server.url, *flags)
            else:
                agent = apprentice.Agent(TWO_OBJECTS, condition="inst+llm", llm="openai:" + server.url,
                                         llm_model="tiny-model", llm_seed=3, llm_api_key="sesame",
                                         llm_goal_responses=2)
                agent.learn(scripted_teacher(TEACHING))
            seen.append(list(server.requests))
    cli, ours = seen
    # The check before the run, then the first goal query: the same. (What
    # follows depends on how each teacher answers the LLM's goals.)
    assert len(ours) > 1 and len(cli) > 1
    assert [r["body"] for r in ours[:2]] == [r["body"] for r in cli[:2]]
    assert all(r["authorization"] == "Bearer sesame" and r["body"]["seed"] == 3 for r in ours + cli)
    assert ours[1]["body"]["model"] == "tiny-model"


def knowledge_json(store, household):
    run = subprocess.run([str(BINARY), "knowledge", "--knowledge", str(store), "--household", household, "--json"],
                         capture_output=True, text=True, check=True)
    document = json.loads(run.stdout)
    return sorted(g["text"] for g in document["goals"]), sorted(t["name"] for t in document["tasks"])


def test_agent_household_and_run_task_as_the_cli(tmp_path):
    cli = cli_teach("--household", "smiths", "--knowledge", str(tmp_path / "cli.sqlite"))
    assert cli.returncode == 0, cli.stderr
    apprentice.Agent(TWO_OBJECTS, knowledge=tmp_path / "py.sqlite", household="smiths").learn(
        scripted_teacher(TEACHING))
    # The same goals and task, in the smiths' household and not in the default one.
    smiths = knowledge_json(tmp_path / "cli.sqlite", "smiths")
    assert smiths == knowledge_json(tmp_path / "py.sqlite", "smiths") and len(smiths[0]) == 2
    assert knowledge_json(tmp_path / "py.sqlite", "default") == ([], [])
    # run --household smiths --task "tidy kitchen" performs what perform() does.
    run = subprocess.run([str(BINARY), "run", str(TWO_OBJECTS), "--knowledge", str(tmp_path / "cli.sqlite"),
                          "--household", "smiths", "--task", "tidy kitchen", "--json"],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    ours = apprentice.Agent(TWO_OBJECTS, knowledge=tmp_path / "py.sqlite", household="smiths").perform(task="tidy kitchen")
    cli_run = json.loads(run.stdout)
    for key in cli_run:
        assert ours[key] == cli_run[key], key
    assert ours["assertions_achieved"] == ours["assertions_total"] == 3


def robots_of(store):
    """Who learned what in a store: (household, robot) per goal, and the
    robots that saved its rules."""
    import sqlite3
    with sqlite3.connect(store) as db:
        return (sorted(db.execute("SELECT household, robot FROM goals").fetchall()),
                sorted({robot for (robot,) in db.execute("SELECT robot FROM rules")}))


def test_agent_robot_as_the_cli(tmp_path):
    cli = cli_teach("--robot", "kitchen-2", "--knowledge", str(tmp_path / "cli.sqlite"))
    assert cli.returncode == 0, cli.stderr
    apprentice.Agent(TWO_OBJECTS, knowledge=tmp_path / "py.sqlite", robot="kitchen-2").learn(
        scripted_teacher(TEACHING))
    ours = robots_of(tmp_path / "py.sqlite")
    assert ours == robots_of(tmp_path / "cli.sqlite")
    # Both goals and every rule name the robot given, not the host.
    assert ours == ([("default", "kitchen-2")] * 2, ["kitchen-2"])
    # A name the CLI refuses (exit 2, one line) Python refuses in the same words.
    refused = cli_teach("--robot", "kitchen/2", "--knowledge", str(tmp_path / "cli.sqlite"))
    assert refused.returncode == 2
    with pytest.raises(apprentice.Error) as raised:
        apprentice.Agent(TWO_OBJECTS, knowledge=tmp_path / "py.sqlite", robot="kitchen/2")
    assert raised.value.code == "invalid input"
    assert refused.stderr.strip() == "apprentice: " + str(raised.value)
