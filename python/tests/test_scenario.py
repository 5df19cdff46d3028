"""apprentice.Scenario: the world, its places, objects and task as Python objects."""
import pytest

import apprentice
from conftest import KITCHEN, SCENARIOS


def test_loads_the_kitchen_with_its_objects_places_and_task():
    scenario = apprentice.Scenario.load(KITCHEN)
    assert scenario.name == "tidy-kitchen"
    assert scenario.location == "kitchen"
    assert scenario.path.endswith("tidy-kitchen.yaml")
    # The file's header: 30 objects to tidy and 35 goal assertions.
    assert len(scenario.items) == 30
    assert len(scenario.goal_assertions) == 35
    assert len(scenario.objects) == len(scenario.items) + len(scenario.places)
    kinds = {o.id: o.kind for o in scenario.places}
    assert kinds["table1"] == "surface"
    assert kinds["fridge1"] == "receptacle"
    assert all(o.kind == "object" for o in scenario.items)
    ketchup = scenario.object("ketchup1")
    assert (ketchup.category, ketchup.kind) == ("ketchup", "object")
    assert scenario.where("ketchup1") == "table1"
    assert "(on ketchup1 table1)" in scenario.facts
    assert "(closed fridge1)" in scenario.facts
    assert "(in ketchup1 fridge1)" in scenario.goal_assertions


def test_the_task_names_its_subtasks_and_places():
    task = apprentice.Scenario.load(str(KITCHEN)).task
    assert task.name == "tidy kitchen"
    assert [(s.verb, s.place) for s in task.subtasks] == [("clear", "table1"), ("store", "counter1"),
                                                          ("unload", "dish-rack1")]


def test_objects_print_as_python_reprs():
    scenario = apprentice.Scenario.load(KITCHEN)
    assert repr(scenario.object("ketchup1")) == "Object('ketchup1', category='ketchup', kind='object')"
    assert repr(scenario).startswith("<Scenario tidy-kitchen: ")


def test_an_unknown_object_is_a_key_error():
    scenario = apprentice.Scenario.load(KITCHEN)
    with pytest.raises(KeyError, match="mustard"):
        scenario.object("mustard1")


def test_a_missing_file_raises_apprentice_error_not_found(tmp_path):
    with pytest.raises(apprentice.Error) as raised:
        apprentice.Scenario.load(tmp_path / "nowhere.yaml")
    assert raised.value.code == "not found"
    assert "nowhere.yaml" in str(raised.value)


def test_a_broken_file_raises_invalid_input_with_its_line(tmp_path):
    broken = tmp_path / "broken.yaml"
    broken.write_text("name: broken\ndomain: [unclosed\n")
    with pytest.raises(apprentice.Error) as raised:
        apprentice.Scenario.load(broken)
    assert raised.value.code == "invalid input"
    assert "broken.yaml:" in raised.value.message


def test_every_shipped_scenario_loads():
    for path in sorted(SCENARIOS.glob("*.yaml")):
        scenario = apprentice.Scenario.load(path)
        assert scenario.items, path
        assert scenario.task.subtasks, path


# A world written as JSON (YAML's subset), naming the shipped domain by name
# from a folder of its own: two shelves told apart by a property, a door.
JSON_WORLD = {
    "name": "json-laundry",
    "domain": "kitchen",
    "location": "laundry room",
    "places": [{"category": "folding-table", "kind": "surface"},
               {"category": "shelf", "kind": "surface", "properties": ["high"]},
               {"category": "shelf", "kind": "surface", "properties": ["low"]},
               {"category": "cupboard", "kind": "receptacle", "door": "closed"},
               {"category": "hamper", "kind": "receptacle"}],
    "objects": [{"category": "towel", "at": "folding-table1", "count": 2},
                {"category": "bleach", "at": "folding-table1"},
                {"category": "jeans", "at": "hamper1"}],
    "task": {"name": "do laundry", "subtasks": [{"verb": "clear", "place": "folding-table1"}]},
    "intent": [{"subtask": "clear", "category": "towel", "place": "cupboard1", "closed": True},
               {"subtask": "clear", "category": "bleach", "place": "shelf1"}],
}


def test_a_world_given_as_json_is_the_scenario_the_cli_reads(tmp_path):
    import json
    import subprocess
    from conftest import BINARY
    path = tmp_path / "laundry.json"
    path.write_text(json.dumps(JSON_WORLD, indent=2))
    cli = subprocess.run([str(BINARY), "world", str(path), "--json"], capture_output=True, text=True)
    assert cli.returncode == 0, cli.stderr
    world = json.loads(cli.stdout)
    scenario = apprentice.Scenario.load(path)
    assert (scenario.name, scenario.location) == (world["scenario"], world["location"]) == \
        ("json-laundry", "laundry room")
    assert scenario.domain_path.endswith("kitchen.pddl")

    def seen(o):
        return (o.id, o.category, o.kind, list(o.properties))

    assert [seen(o) for o in scenario.places] == \
        [(p["id"], p["category"], p["kind"], p["properties"]) for p in world["places"]]
    def location(item):
        place = scenario.where(item.id)
        return ("on " if scenario.object(place).kind == "surface" else "in ") + place

    assert [seen(o) + (location(o),) for o in scenario.items] == \
        [(o["id"], o["category"], o["kind"], o["properties"], o["location"]) for o in world["objects"]]
    assert [o["location"] for o in world["objects"]] == ["on folding-table1"] * 3 + ["in hamper1"]
    doors = {p["id"]: p["door"] for p in world["places"] if "door" in p}
    assert doors == {"cupboard1": "closed"} and "(closed cupboard1)" in scenario.facts
    assert [p["properties"] for p in world["places"] if p["category"] == "shelf"] == [["high"], ["low"]]
    assert [(s.verb, s.place) for s in scenario.task.subtasks] == [("clear", "folding-table1")]
    assert scenario.intended_goal("clear", "towel2") == "(and (in towel2 cupboard1) (closed cupboard1))"
