// apprentice.Scenario and the plain objects it is made of.
#include <pybind11/pytypes.h>

#include "face/apprentice.h"
#include "bindings.h"
#include "world/goal.h"

namespace apprentice::python {

namespace {

// A subtask as Python sees it: the verb and the place's id.
struct SubtaskView {
  std::string verb;                 // "clear"
  std::string place;                // "table1", or a kind ("bag") for every place of it, as in the file
  std::vector<std::string> places;  // every place it empties: "table1"; "bag1", "bag2" for `place: bag`
};

struct TaskView {
  std::string name;  // "tidy kitchen"
  std::vector<SubtaskView> subtasks;
};

std::string kind_name(ObjectKind kind) { return std::string(to_string(kind)); }

std::vector<ObjectInfo> objects_where(const Scenario& scenario, bool (*keep)(const ObjectInfo&)) {
  std::vector<ObjectInfo> out;
  for (const ObjectInfo& info : scenario.world.universe->objects())
    if (keep(info)) out.push_back(info);
  return out;
}

// The object's id; KeyError for an id the scenario lacks.
ObjectId object_id(const ScenarioHandle& h, const std::string& id) {
  auto found = h.scenario->world.universe->find(id);
  if (!found) throw py::key_error("no object " + id + " in scenario " + h.scenario->name);
  return *found;
}

std::string object_repr(const ObjectInfo& o) {
  std::string text = "Object('" + o.id + "', category='" + o.category + "', kind='" + kind_name(o.kind) + "'";
  if (!o.properties.empty()) {
    text += ", properties=[";
    for (std::size_t i = 0; i < o.properties.size(); ++i) text += (i ? ", '" : "'") + o.properties[i] + "'";
    text += "]";
  }
  return text + ")";
}

}  // namespace

std::vector<std::string> facts_of(const World& world) {
  std::vector<std::string> facts;
  for (const Fact& f : world.state.facts()) facts.push_back(format_fact(*world.domain, *world.universe, f));
  return facts;
}

std::optional<std::string> place_of(const World& world, ObjectId object) {
  for (const Fact& f : world.state.facts())
    if ((f.predicate == world.vocabulary.on || f.predicate == world.vocabulary.in) && f.args[0] == object)
      return world.universe->name(f.args[1]);
  return std::nullopt;
}

ScenarioHandle scenario_from(const py::object& scenario_or_path) {
  if (py::isinstance<ScenarioHandle>(scenario_or_path)) return scenario_or_path.cast<ScenarioHandle>();
  std::filesystem::path path = py::str(py::module_::import("os").attr("fspath")(scenario_or_path)).cast<std::string>();
  Result<Scenario> loaded;
  {
    py::gil_scoped_release release;
    loaded = load_world(path);
  }
  return ScenarioHandle{std::make_shared<const Scenario>(unwrap(std::move(loaded)))};
}

void bind_scenario(py::module_& m) {
  py::class_<ObjectInfo>(m, "Object", "An object of a world: an item, a receptacle or a surface.")
      .def_readonly("id", &ObjectInfo::id, "Its id, e.g. 'ketchup1'.")
      .def_readonly("category", &ObjectInfo::category, "Its category, e.g. 'ketchup'.")
      .def_property_readonly("kind", [](const ObjectInfo& o) { return kind_name(o.kind); },
                             "'object' (an item the robot carries), 'receptacle' or 'surface'.")
      .def_readonly("properties", &ObjectInfo::properties,
                    "Words that tell it from look-alikes, e.g. ['top'].")
      .def("__repr__", &object_repr);

  py::class_<SubtaskView>(m, "Subtask", "A subtask of the task: a verb and the place it empties.")
      .def_readonly("verb", &SubtaskView::verb)
      .def_readonly("place", &SubtaskView::place)
      .def_readonly("places", &SubtaskView::places)
      .def("__repr__", [](const SubtaskView& s) { return "Subtask('" + s.verb + "', place='" + s.place + "')"; });

  py::class_<TaskView>(m, "Task", "The task the instructor teaches: its name and subtasks, in order.")
      .def_readonly("name", &TaskView::name)
      .def_readonly("subtasks", &TaskView::subtasks)
      .def("__repr__", [](const TaskView& t) {
        return "Task('" + t.name + "', " + std::to_string(t.subtasks.size()) + " subtasks)";
      });

  py::class_<ScenarioHandle>(m, "Scenario",
                             "A world and the task an instructor teaches in it, read from a scenario file (YAML).")
      .def_static("load", [](const py::object& path) { return scenario_from(path); }, py::arg("path"),
                  "Loads a scenario file. Raises apprentice.Error ('not found', 'invalid input' with file:line).")
      .def_property_readonly("name", [](const ScenarioHandle& h) { return h.scenario->name; })
      .def_property_readonly("path", [](const ScenarioHandle& h) { return h.scenario->source.string(); })
      .def_property_readonly("domain_path", [](const ScenarioHandle& h) { return h.scenario->domain_path.string(); })
      .def_property_readonly("location", [](const ScenarioHandle& h) { return h.scenario->world.location; })
      .def_property_readonly(
          "objects", [](const ScenarioHandle& h) { return h.scenario->world.universe->objects(); },
          "Every object, places included, in id order.")
      .def_property_readonly(
          "places",
          [](const ScenarioHandle& h) {
            return objects_where(*h.scenario, [](const ObjectInfo& o) { return o.kind != ObjectKind::kItem; });
          },
          "The receptacles and surfaces.")
      .def_property_readonly(
          "items",
          [](const ScenarioHandle& h) {
            return objects_where(*h.scenario, [](const ObjectInfo& o) { return o.kind == ObjectKind::kItem; });
          },
          "The objects the robot can carry.")
      .def_property_readonly(
          "facts",
          [](const ScenarioHandle& h) { return facts_of(h.scenario->world); },
          "The initial state, as PDDL atoms such as '(on ketchup1 table1)'.")
      .def_property_readonly(
          "task",
          [](const ScenarioHandle& h) {
            TaskView task{h.scenario->task.name, {}};
            for (const Subtask& s : h.scenario->task.subtasks) {
              const Universe& universe = *h.scenario->world.universe;
              SubtaskView view{s.verb, "", {}};
              for (ObjectId place : s.places) view.places.push_back(universe.name(place));
              if (!s.places.empty())
                view.place = s.places.size() == 1 ? universe.name(s.places.front())
                                                  : universe.info(s.places.front()).category;
              task.subtasks.push_back(std::move(view));
            }
            return task;
          },
          "The task the instructor will teach (the agent learns it from the instructor's words).")
      .def_property_readonly(
          "goal_assertions",
          [](const ScenarioHandle& h) {
            const World& world = h.scenario->world;
            std::vector<std::string> out;
            for (const Literal& l : h.scenario->goal_assertions())
              out.push_back(format_literal(*world.domain, *world.universe, l));
            return out;
          },
          "What the instructor wants to hold at the end; completion is measured against these.")
      .def(
          "object",
          [](const ScenarioHandle& h, const std::string& id) {
            return h.scenario->world.universe->info(object_id(h, id));
          },
          py::arg("id"), "The object with this id; KeyError if there is none.")
      .def(
          "intended_goal",
          [](const ScenarioHandle& h, const std::string& subtask, const std::string& id) -> std::optional<std::string> {
            const World& world = h.scenario->world;
            auto goal = h.scenario->intended_goal(subtask, object_id(h, id));
            if (!goal) return std::nullopt;
            return format_goal(*world.domain, *world.universe, *goal);
          },
          py::arg("subtask"), py::arg("object"),
          "What the scenario's author wants for the object in the subtask, as PDDL, or None. For an instructor\n"
          "program and for measuring; the agent never sees it.")
      .def(
          "where",
          [](const ScenarioHandle& h, const std::string& id) -> std::optional<std::string> {
            return place_of(h.scenario->world, object_id(h, id));
          },
          py::arg("id"), "The id of the place the object starts on or in, or None.")
      .def("__repr__", [](const ScenarioHandle& h) {
        const Scenario& s = *h.scenario;
        return "<Scenario " + s.name + ": " + std::to_string(s.world.universe->size()) + " objects, task '" +
               s.task.name + "'>";
      });
}

}  // namespace apprentice::python
