"""apprentice.KnowledgeStore: goals and rules as Python objects, read-only."""
import hashlib
import subprocess

import pytest

import apprentice
from conftest import BINARY, KITCHEN


@pytest.fixture(scope="module")
def kitchen_store(tmp_path_factory):
    """The stores `apprentice experiment --knowledge-out` keeps."""
    out = tmp_path_factory.mktemp("knowledge")
    subprocess.run([str(BINARY), "experiment", "--scenario", str(KITCHEN), "--conditions", "inst+search4",
                    "--knowledge-out", str(out)], check=True, capture_output=True)
    return out / "inst+search4.sqlite"


def test_reads_tasks_goals_and_rules(kitchen_store):
    store = apprentice.KnowledgeStore(kitchen_store)
    assert store.path == str(kitchen_store)
    assert [t.name for t in store.tasks] == ["tidy kitchen"]
    assert [(s.verb, s.relation, s.place) for s in store.tasks[0].subtasks] == [
        ("clear", "on", "table"), ("store", "on", "counter"), ("unload", "in", "dish-rack")]
    # One goal per (subtask, category): the paper's 26 goal types.
    assert len(store.goals) == 26
    plate = next(g for g in store.goals if g.category == "ceramic-plate" and g.subtask == "clear")
    assert sorted(plate.literals) == ["(closed dishwasher)", "(in ?o dishwasher)"]
    assert plate.text.startswith("If the task is tidy kitchen, the subtask is clear and the object is a ceramic-plate")
    assert plate.learned_on.startswith("ceramic-plate")
    assert plate.source.startswith("instructor")
    assert store.rules
    actions = {r.action for r in store.rules}
    assert {"open", "close"} <= actions
    assert all(r.signature.startswith(r.action + "(") for r in store.rules)
    assert all(r.text.startswith("If ") for r in store.rules)
    assert repr(store).endswith("1 tasks, 26 goals, %d rules>" % len(store.rules))


def test_the_same_as_the_knowledge_command(kitchen_store):
    import json
    cli = json.loads(subprocess.run([str(BINARY), "knowledge", "--knowledge", str(kitchen_store), "--json"],
                                    check=True, capture_output=True, text=True).stdout)
    store = apprentice.KnowledgeStore(kitchen_store)
    assert [g.text for g in store.goals] == [g["text"] for g in cli["goals"]]
    assert [r.signature for r in store.rules] == [r["signature"] for r in cli["rules"]]


def test_reading_never_writes_the_store(kitchen_store):
    before = hashlib.sha256(kitchen_store.read_bytes()).hexdigest()
    apprentice.KnowledgeStore(kitchen_store)
    assert hashlib.sha256(kitchen_store.read_bytes()).hexdigest() == before


def test_a_missing_store_is_not_created(tmp_path):
    missing = tmp_path / "none.sqlite"
    with pytest.raises(apprentice.Error) as raised:
        apprentice.KnowledgeStore(missing)
    assert raised.value.code == "not found"
    assert not missing.exists()


def test_a_file_that_is_not_a_store_is_refused(tmp_path):
    junk = tmp_path / "junk.sqlite"
    junk.write_bytes(b"this is not a database at all" * 10)
    with pytest.raises(apprentice.Error) as raised:
        apprentice.KnowledgeStore(junk)
    # Not a store at all: refused as such (the CLI's exit 2), never as damage.
    assert raised.value.code == "failed precondition"
    assert "not an apprentice knowledge store" in str(raised.value)
    empty = tmp_path / "empty.sqlite"
    empty.write_bytes(b"")
    with pytest.raises(apprentice.Error, match="empty"):
        apprentice.KnowledgeStore(empty)


def test_class_rules_as_the_knowledge_command_says_them_and_forgetting_one(kitchen_store, tmp_path):
    import json
    import shutil
    store_path = tmp_path / "copy.sqlite"
    shutil.copy(kitchen_store, store_path)
    store = apprentice.KnowledgeStore(store_path)
    cli = json.loads(subprocess.run([str(BINARY), "knowledge", "--knowledge", str(store_path), "--json"],
                                    check=True, capture_output=True, text=True).stdout)
    assert [r.text for r in store.class_rules] == [r["text"] for r in cli["class_rules"]]
    assert store.class_rules and not store.forgotten_rules
    induced = [r for r in store.class_rules if r.source == "induced" and len(r.evidence) >= 2]
    assert induced
    rule = max(induced, key=lambda r: r.confidence)
    assert 0 < rule.confidence <= 1
    assert rule.text.startswith(rule.subject + " go")
    assert rule.destination in rule.text
    assert rule.said == "" and rule.task == "tidy kitchen"
    assert repr(rule) == "ClassRule(%s %s, induced)" % (rule.subject, rule.destination)

    forgotten = apprentice.forget_rule(store_path, rule.subject + " " + rule.destination)
    assert [r.text for r in forgotten] == [rule.text]
    again = apprentice.KnowledgeStore(store_path)
    assert [r.text for r in again.forgotten_rules] == [rule.text]
    assert rule.text not in [r.text for r in again.class_rules]
    assert len(again.class_rules) == len(store.class_rules) - 1
    cli = json.loads(subprocess.run([str(BINARY), "knowledge", "--knowledge", str(store_path), "--json"],
                                    check=True, capture_output=True, text=True).stdout)
    assert [r.text for r in again.class_rules] == [r["text"] for r in cli["class_rules"]]

    with pytest.raises(apprentice.Error) as raised:
        apprentice.forget_rule(store_path, "unicorns")
    assert raised.value.code == "invalid input"
    assert 'I hold no rule about "unicorns"' in str(raised.value)
    with pytest.raises(apprentice.Error) as raised:
        apprentice.forget_rule(tmp_path / "none.sqlite", "fruit")
    assert raised.value.code == "not found"
    assert not (tmp_path / "none.sqlite").exists()


def test_a_household_and_a_domain_give_what_the_knowledge_command_gives(tmp_path):
    """The stacking kitchen's store, kept for the smiths: read with its own
    domain, Python and `knowledge --household --domain` agree; with the
    kitchen's, whose actions its rules lack, both refuse it alike."""
    import json
    from conftest import SCENARIOS, SOURCE_DIR
    stacking = SOURCE_DIR / "data" / "domains" / "kitchen-stacking.pddl"
    kitchen = SOURCE_DIR / "data" / "domains" / "kitchen.pddl"
    subprocess.run([str(BINARY), "experiment", str(SCENARIOS / "dish-tower.yaml"), "--conditions", "inst+search4",
                    "--household", "smiths", "--knowledge-out", str(tmp_path)], check=True, capture_output=True)
    store_path = tmp_path / "inst+search4.sqlite"

    def cli(household, domain):
        return subprocess.run([str(BINARY), "knowledge", "--knowledge", str(store_path), "--household", household,
                               "--domain", str(domain), "--json"], capture_output=True, text=True)

    run = cli("smiths", stacking)
    assert run.returncode == 0, run.stderr
    theirs = json.loads(run.stdout)
    store = apprentice.KnowledgeStore(store_path, domain=stacking, household="smiths")
    assert store.household == theirs["household"] == "smiths"
    assert [(t.name, [(s.verb, s.relation, s.place) for s in t.subtasks]) for t in store.tasks] == \
        [(t["name"], [(s["verb"], s["relation"], s["place"]) for s in t["subtasks"]]) for t in theirs["tasks"]]
    assert [(g.text, g.learned_on, g.source) for g in store.goals] == \
        [(g["text"], g["object"], g["source"]) for g in theirs["goals"]]
    assert [(r.signature, r.learned_on, r.source) for r in store.rules] == \
        [(r["signature"], r["object"], r["source"]) for r in theirs["rules"]]
    assert [r.text for r in store.class_rules] == [r["text"] for r in theirs["class_rules"]]
    assert store.goals and store.rules and store.tasks[0].name == "put away dishes"
    # The default household holds none of the smiths' goals, in both.
    default = json.loads(cli("default", stacking).stdout)
    assert apprentice.KnowledgeStore(store_path, domain=stacking).goals == [] == default["goals"]
    # The plain kitchen's domain has no action to stack with.
    refused = cli("smiths", kitchen)
    assert refused.returncode == 2
    with pytest.raises(apprentice.Error) as raised:
        apprentice.KnowledgeStore(store_path, domain=kitchen, household="smiths")
    assert raised.value.code == "failed precondition"  # the CLI's exit 2
    assert refused.stderr.strip() == "apprentice: " + str(raised.value)
