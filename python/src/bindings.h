// Shared by the binding files of the Python module apprentice._apprentice.
//
// Conventions: every C++ Result error becomes apprentice.Error (with .code,
// e.g. "not found"); long C++ work runs with the GIL released, and any call
// back into Python (an instructor callback) takes it again first.
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>
#include <string>

#include "face/apprentice.h"
#include "knowledge/concepts.h"
#include "knowledge/store.h"
#include "util/result.h"
#include "world/scenario.h"

namespace apprentice::python {

namespace py = pybind11;

// Sets apprentice.Error for `error` and throws, so that pybind11 raises it
// in the caller. Needs the GIL.
[[noreturn]] void raise_error(const Error& error);

template <typename T>
T unwrap(Result<T> result) {
  if (!result) raise_error(result.error());
  return std::move(*result);
}

// A keyword argument checked as the CLI checks its flag, named `name` in
// the error: a whole number in [low, high], True or False, a str. Another
// value raises apprentice.Error ("invalid input").
long whole_number(const py::handle& value, const char* name, long low, long high);
bool flag(const py::handle& value, const char* name);
std::string text(const py::handle& value, const char* name);

// The keyword options the Agent and experiment() take besides their named
// arguments, as the CLI's flags of the same names (--no-rules is
// use_rules=False): use_rules, max_reprompts, goal_repair, offer_ungrounded,
// llm_model, llm_api_key, llm_timeout_ms, llm_connect_timeout_ms, llm_seed,
// llm_optional, llm_goal_responses. An unknown one or a bad value raises
// apprentice.Error ("invalid input"), as the CLI refuses the flag.
void apply_agent_options(const py::kwargs& options, AgentSpec& spec);

// A loaded scenario, shared by the Python Scenario object and the agents
// made from it.
struct ScenarioHandle {
  std::shared_ptr<const Scenario> scenario;
};

// A world's state as PDDL atoms: "(on ketchup1 table1)", ...
std::vector<std::string> facts_of(const World& world);
// The id of the place `object` is on or in now, if any.
std::optional<std::string> place_of(const World& world, ObjectId object);

// Loads a scenario from a path (str or os.PathLike) or takes a Scenario.
ScenarioHandle scenario_from(const py::object& scenario_or_path);

// What an agent knows, as Python sees it (apprentice.Knowledge): plain
// copies, so that it stays valid whatever becomes of the agent or store.
struct GoalView {
  std::string task, subtask, category, place;
  std::vector<std::string> literals;  // "(in ?o dishwasher)", "(closed dishwasher)"
  std::string text;                   // format_goal_knowledge
  std::string learned_on, source;
};
struct RuleView {
  std::string action;  // "open"
  std::optional<std::string> subtask;
  int steps_to_goal = 1;
  std::string text;       // format_rule: the paper's If/Then
  std::string signature;  // rule_signature: one line
  std::string learned_on, source;
};
// A class rule (apprentice.ClassRule): what it is about, where it sends
// things, and why (agent/class_rule_knowledge.h).
struct ClassRuleView {
  std::string text;         // say_class_rule: the English of `apprentice knowledge`
  std::string subject;      // "edible fruit", "other clothes"
  std::string destination;  // "on the coffee table"
  std::vector<std::string> evidence, exceptions;
  std::string source;  // "induced", "person", "llm", "fleet"
  std::string said;    // the sentence it was read from; "" when induced
  double confidence = 0;
  std::string task;  // where it holds; "" for any task
};
struct SubtaskKnowledgeView {
  std::string verb, relation, place;
};
struct TaskKnowledgeView {
  std::string name;
  std::vector<SubtaskKnowledgeView> subtasks;
};
struct KnowledgeView {
  std::vector<TaskKnowledgeView> tasks;
  std::vector<GoalView> goals;
  std::vector<RuleView> rules;
  // The class rules in use (a person's, and those the goals induce, when
  // `concepts` is given; else those stored), and those forgotten.
  std::vector<ClassRuleView> class_rules, forgotten_rules;
};
KnowledgeView view_of(const Knowledge& knowledge, const Domain& domain, const ConceptSource* concepts = nullptr);

void bind_errors(py::module_& m);
void bind_scenario(py::module_& m);
void bind_knowledge(py::module_& m);
void bind_agent(py::module_& m);
void bind_experiment(py::module_& m);
void bind_plan_and_interpret(py::module_& m);

}  // namespace apprentice::python
